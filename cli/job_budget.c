/*
 * A job's total budget, checked before any block is generated: each block
 * is within the one-pattern limits, but 1,024 of them are not (57 KB of
 * JSON ran past 120 s and 2.85 GB; 1,024 tsp-time maxima add up to a
 * week). The blocks' points together stay within QC_MAX_POINTS and their
 * tsp-time within one block's maximum, as if the quilt were one pattern.
 */
#include <stdlib.h>
#include <string.h>

#include "job.h"

/* Points block b asks for: its given points, else the region's area over
 * the densest lattice's cell at its spacing (an upper estimate). */
static int block_points(qc_ctx *ctx, block *b, const qc_params *r, double *n)
{
    qc_region region = {0};
    qc_points given = {0};
    qc_sample_params sp;
    int rc = b->top != NULL ? cli_load_top(ctx, b->top, b->pat.mm_per_unit, &region)
                            : cli_pattern_load(ctx, &b->pat, &region, &given);

    if (rc != CLI_OK)
        return rc;
    memset(&sp, 0, sizeof sp);
    sp.kind = QC_SAMPLE_TRIANGLE;
    sp.spacing = r->spacing;
    sp.margin = r->margin;
    *n = r->points == QC_POINTS_GIVEN ? (double)given.n : qc_sample_estimate(&region, &sp);
    qc_points_free(ctx, &given);
    qc_region_free(ctx, &region);
    return CLI_OK;
}

int cli_job_budget(qc_ctx *ctx, job *j)
{
    double points = 0, tsp_ms = 0, n;
    size_t i;
    int rc;

    for (i = 0; i < j->n; i++) {
        block *b = &j->blocks[i];
        qc_params r;
        if ((rc = cli_pattern_finish(ctx, &b->pat)) != CLI_OK)
            return rc;
        if (b->top == NULL) /* a top's rules choose the family per patch */
            cli_pattern_warn_ignored(&b->pat);
        if (qc_params_resolve(ctx, &b->pat.params, &r) < 0)
            return cli_fail(ctx, b->label, ctx->status);
        tsp_ms += r.tsp_time_ms;
        if (tsp_ms > JOB_MAX_TSP_MS) {
            cli_error("job: %s: the blocks' tsp-time adds up to %.0f ms, over the job's budget "
                      "of %.0f ms", b->where, tsp_ms, JOB_MAX_TSP_MS);
            return CLI_USAGE;
        }
        if ((rc = block_points(ctx, b, &r, &n)) != CLI_OK)
            return rc;
        points += n;
        if (points > (double)QC_MAX_POINTS) {
            cli_error("job: %s: the blocks ask for about %.0f points together, over the job's "
                      "budget of %u; raise the spacing or split the job",
                      b->where, points, QC_MAX_POINTS);
            return CLI_RUNTIME;
        }
    }
    return CLI_OK;
}
