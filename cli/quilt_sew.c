/* A top quilted by its plan: read, checked for overlaps, a rule per patch, sewn. */
#include <stdlib.h>
#include <string.h>

#include "quilt_plan.h"

#define MAX_TOP_BYTES ((size_t)16 << 20)

/* How messages name a patch: its id, else its element number and line. */
static void patch_name(const qc_patch *p, char *buf, size_t size)
{
    if (p->id[0] != '\0')
        snprintf(buf, size, "id \"%s\" (line %lu)", p->id, p->line);
    else
        snprintf(buf, size, "shape %lu (line %lu)", (unsigned long)p->element, p->line);
}

static int load_top(qc_ctx *ctx, const char *top, const cli_pattern_opts *base, qc_patches *ps)
{
    char *buf = NULL, an[160], bn[160];
    qc_svg_opts opts;
    size_t len, a, b;
    qc_vec2 at;
    double u = base->mm_per_unit;
    int rc = CLI_OK;

    if (cli_read_file(top, MAX_TOP_BYTES, &buf, &len) != 0)
        return CLI_RUNTIME;
    cli_svg_opts(&opts, top, MAX_TOP_BYTES);
    if (qc_io_read_svg_patches(ctx, buf, len, &opts, ps) < 0)
        rc = cli_fail(ctx, top, ctx->status);
    free(buf);
    if (rc == CLI_OK && qc_patches_overlap(ps, 0, &a, &b, &at)) {
        patch_name(&ps->p[a], an, sizeof an);
        patch_name(&ps->p[b], bn, sizeof bn);
        cli_error("%s: patches %s and %s overlap near (%.3f, %.3f) %s", top, an, bn, at.x / u,
                  at.y / u, base->units);
        rc = CLI_USAGE;
    }
    return rc;
}

/* The job of every patch: its rule's options, or the base's. */
static int make_jobs(qc_ctx *ctx, cli_quilt *q, const char *top, quilt_plan *plan,
                     cli_pattern_opts *base)
{
    const qc_patches *ps = &q->ps;
    size_t i;
    int rc = CLI_OK;

    if (base->motifs != NULL)
        rc = cli_load_motifs(ctx, base->motifs, &q->base_motifs);
    for (i = 0; i < plan->n && rc == CLI_OK; i++) {
        plan_rule *r = &plan->rule[i];
        rc = cli_pattern_finish(ctx, &r->pat);
        if (rc == CLI_OK && r->pat.motifs != NULL && !r->none)
            rc = cli_load_motifs(ctx, r->pat.motifs, &r->motifs);
    }
    for (i = 0; i < ps->n && rc == CLI_OK; i++) {
        plan_rule *r = cli_quilt_plan_match(plan, &ps->p[i]);

        q->chosen[i] = r;
        if (r != NULL) {
            r->matched++;
            q->jobs[i].params = r->none ? NULL : &r->pat.params;
            q->jobs[i].motifs = r->motifs.n ? &r->motifs : NULL;
        } else {
            q->jobs[i].params = &base->params;
            q->jobs[i].motifs = q->base_motifs.n ? &q->base_motifs : NULL;
        }
    }
    for (i = 0; i < plan->n && rc == CLI_OK; i++)
        if (plan->rule[i].matched == 0) {
            cli_error("%s matches no patch of %s", plan->rule[i].where, top);
            rc = CLI_USAGE;
        }
    return rc;
}

/* One line per patch too small for its pattern, which qc_quilt sewed round
 * in the ditch instead: the quilter may want a smaller spacing there. */
static void report_ditch_only(qc_ctx *ctx, const cli_quilt *q, const char *top, double u)
{
    char name[160];
    size_t i;

    for (i = 0; i < q->res.npatch; i++) {
        qc_params p;

        if (!q->res.patch[i].ditch_only || qc_params_resolve(ctx, q->jobs[i].params, &p) < 0)
            continue;
        patch_name(&q->ps.p[i], name, sizeof name);
        fprintf(stderr, "quiltc: %s: patch %s is too small for %s at spacing %g %s; "
                "sewn round in the ditch only\n", top, name, qc_family_name(p.family),
                p.spacing / u, cli_units_name(u));
    }
}

int cli_quilt_sew(qc_ctx *ctx, cli_quilt *q, const char *top, quilt_plan *plan,
                  cli_pattern_opts *base, const qc_quilt_params *qp, const char *where)
{
    int rc;

    memset(q, 0, sizeof *q);
    rc = load_top(ctx, top, base, &q->ps);
    if (rc == CLI_OK) {
        q->jobs = calloc(q->ps.n, sizeof *q->jobs);
        q->chosen = calloc(q->ps.n, sizeof *q->chosen);
        if (q->jobs == NULL || q->chosen == NULL) {
            cli_error("out of memory");
            rc = CLI_RUNTIME;
        }
    }
    if (rc == CLI_OK)
        rc = make_jobs(ctx, q, top, plan, base);
    if (rc == CLI_OK && qc_quilt(ctx, &q->ps, q->jobs, qp, &q->res) < 0)
        rc = cli_fail(ctx, where, ctx->status);
    if (rc == CLI_OK)
        report_ditch_only(ctx, q, top, base->mm_per_unit);
    return rc;
}

void cli_quilt_free(qc_ctx *ctx, cli_quilt *q)
{
    qc_quilt_result_free(ctx, &q->res);
    free(q->jobs);
    free(q->chosen);
    qc_motif_set_free(ctx, &q->base_motifs);
    qc_patches_free(ctx, &q->ps);
    memset(q, 0, sizeof *q);
}

int cli_quilt_outlines(qc_ctx *ctx, const qc_patches *ps, qc_region *out)
{
    if (qc_patches_outlines(ctx, ps, out) < 0)
        return cli_fail(ctx, "quilt", ctx->status);
    return CLI_OK;
}
