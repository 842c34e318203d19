/*
 * quiltc job quilt.json: a whole quilt of blocks, each with its region,
 * place, rotation, family and parameters, generated and joined into one
 * file in serpentine row order, with a jump and tie-offs between blocks.
 *
 * {"units": "in", "tie": 3, "output": ["quilt.pat"],
 *  "blocks": [{"region": "rect:8x8", "at": [0, 0], "rotate": 0,
 *              "family": "stipple", "motif": "leaf", "params": {"spacing": 0.5}}]}
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "job.h"

/* Generates block b in its own frame, then rotates it about its box's
 * lower-left corner and moves that corner to `at`. */
static int make_block(qc_ctx *ctx, block *b)
{
    qc_region region = {0};
    qc_points given = {0};
    qc_motif_set motifs = {0};
    qc_result res = {0};
    double mm, c, s;
    size_t i;
    int rc = cli_pattern_load(ctx, &b->pat, &region, &given); /* params: cli_job_budget */

    if (rc == CLI_OK && b->pat.motifs != NULL)
        rc = cli_load_motifs(ctx, b->pat.motifs, &motifs);
    if (rc == CLI_OK && qc_generate(ctx, &region, &b->pat.params, &given,
                                    motifs.n ? &motifs : NULL, &res) < 0)
        rc = cli_fail(ctx, b->label, ctx->status);
    if (rc == CLI_OK) {
        mm = b->pat.mm_per_unit;
        c = qc_cos(b->rotate * QC_PI / 180);
        s = qc_sin(b->rotate * QC_PI / 180);
        for (i = 0; i < res.path.npt; i++) {
            qc_vec2 p = res.path.pt[i];
            res.path.pt[i].x = b->at[0] * mm + c * p.x - s * p.y;
            res.path.pt[i].y = b->at[1] * mm + s * p.x + c * p.y;
        }
        b->lo.x = b->at[0] * mm;
        b->lo.y = b->at[1] * mm;
        b->path = res.path; /* keep the path, free the rest */
        memset(&res.path, 0, sizeof res.path);
    }
    qc_result_free(ctx, &res);
    qc_motif_set_free(ctx, &motifs);
    qc_points_free(ctx, &given);
    qc_region_free(ctx, &region);
    return rc;
}

static int by_row_then_x(const void *pa, const void *pb)
{
    const block *a = *(const block *const *)pa, *b = *(const block *const *)pb;

    if (a->lo.y != b->lo.y)
        return a->lo.y < b->lo.y ? -1 : 1;
    return (a->lo.x > b->lo.x) - (a->lo.x < b->lo.x);
}

/* Serpentine rows: the bottom row left to right, the next right to left, ... */
static void sewing_order(block **order, size_t n)
{
    size_t i = 0, row = 0;

    qsort(order, n, sizeof *order, by_row_then_x);
    while (i < n) {
        size_t end = i;
        while (end < n && fabs(order[end]->lo.y - order[i]->lo.y) < 1.0)
            end++;
        if (row++ % 2 == 1) {
            size_t a = i, b = end - 1;
            for (; a < b; a++, b--) {
                block *t = order[a];
                order[a] = order[b];
                order[b] = t;
            }
        }
        i = end;
    }
}

/* One path, a piece per block; moved so nothing is negative (PAT needs that). */
static int join_blocks(qc_ctx *ctx, block **order, size_t n, qc_path *out)
{
    double minx = 0, miny = 0;
    size_t i;

    for (i = 0; i < n; i++)
        if (qc_path_append(ctx, out, &order[i]->path, 0) < 0)
            return cli_fail(ctx, "job", ctx->status);
    for (i = 0; i < out->npt; i++) {
        minx = fmin(minx, out->pt[i].x);
        miny = fmin(miny, out->pt[i].y);
    }
    for (i = 0; i < out->npt; i++) {
        out->pt[i].x -= minx;
        out->pt[i].y -= miny;
    }
    return CLI_OK;
}

static int run_job(qc_ctx *ctx, job *j, const char *const *outputs, const int *formats,
                   size_t nout)
{
    block **order = calloc(j->n, sizeof *order);
    qc_path all = {0};
    qc_plan plan = {0};
    qc_stitch_params sp;
    qc_io_opts io;
    size_t i;
    int rc = order == NULL ? CLI_RUNTIME : CLI_OK;

    if (rc == CLI_OK)
        rc = cli_job_budget(ctx, j);
    for (i = 0; i < j->n && rc == CLI_OK; i++) {
        order[i] = &j->blocks[i];
        rc = make_block(ctx, &j->blocks[i]);
    }
    if (rc == CLI_OK) {
        sewing_order(order, j->n);
        rc = join_blocks(ctx, order, j->n, &all);
    }
    memset(&sp, 0, sizeof sp);
    sp.tie_stitches = j->tie;
    if (rc == CLI_OK && qc_stitch_plan(ctx, &all, NULL, &sp, &plan) < 0)
        rc = cli_fail(ctx, "job", ctx->status);
    memset(&io, 0, sizeof io);
    io.svg_inches = strcmp(j->units, "in") == 0;
    if (rc == CLI_OK) /* all outputs or none */
        rc = cli_write_plans(ctx, outputs, formats, nout, &plan, &io);
    qc_plan_free(ctx, &plan);
    qc_path_free(ctx, &all);
    free(order);
    return rc;
}

/* The format of each output, from its extension, before any work. */
static int output_formats(const char *const *outputs, size_t nout, int *formats)
{
    size_t i;

    for (i = 0; i < nout; i++) {
        formats[i] = qc_format_from_name(outputs[i]);
        if (formats[i] < 0) {
            cli_error("job: output '%s': unknown format (pat, qli, dxf, plt, qcc, iqp, bqm, "
                      "gcode, svg)", outputs[i]);
            return CLI_USAGE;
        }
    }
    return cli_outputs_distinct(outputs, nout);
}

int cmd_job(int argc, char **argv)
{
    const char *outputs[MAX_JOB_OUTPUTS];
    int formats[MAX_JOB_OUTPUTS];
    size_t nout = 0, i;
    const char *file = NULL;
    char *buf = NULL;
    size_t len;
    cJSON *root = NULL;
    cli_job_names names = {NULL, 0, 0};
    job j;
    qc_ctx ctx;
    int rc = CLI_OK, a, allow_outside = 0;

    for (a = 1; a < argc && rc == CLI_OK; a++) {
        if (strcmp(argv[a], "--help") == 0) {
            puts("usage: quiltc job QUILT.json [-o FILE]... [--allow-outside]\n"
                 "Generates every block of a quilt and joins them into one file (see README).\n"
                 "The job's files (regions, motifs, points, outputs) must stay inside its\n"
                 "folder; --allow-outside lets them be anywhere. -o is never limited.");
            return CLI_OK;
        } else if (strcmp(argv[a], "--allow-outside") == 0) {
            allow_outside = 1;
        } else if (strcmp(argv[a], "-o") == 0 && a + 1 < argc) {
            if (nout == MAX_JOB_OUTPUTS) {
                cli_error("job: at most %d outputs", MAX_JOB_OUTPUTS);
                rc = CLI_USAGE;
            } else
                outputs[nout++] = argv[++a];
        } else if (file == NULL && argv[a][0] != '-')
            file = argv[a];
        else {
            cli_bad_option("job", argv[a], '?');
            rc = CLI_USAGE;
        }
    }
    if (rc == CLI_OK && file == NULL) {
        cli_error("job: expected a QUILT.json file");
        rc = CLI_USAGE;
    }
    if (rc != CLI_OK)
        return rc;
    if (cli_read_file(file, MAX_JOB_BYTES, &buf, &len) != 0)
        return CLI_RUNTIME;
    memset(&j, 0, sizeof j);
    root = cli_json_parse(buf, len, file);
    rc = root == NULL ? CLI_USAGE : cli_job_parse(&j, root);
    if (rc == CLI_OK && nout > 0)
        j.nout = 0; /* -o replaces the job's outputs: they are not checked */
    if (rc == CLI_OK)
        rc = cli_job_resolve_names(&j, file, allow_outside, &names);
    if (rc == CLI_OK && nout == 0) {
        for (i = 0; i < j.nout; i++)
            outputs[nout++] = j.outputs[i];
        if (nout == 0)
            outputs[nout++] = "quilt.pat";
    }
    if (rc == CLI_OK)
        rc = output_formats(outputs, nout, formats);
    if (rc == CLI_OK) {
        qc_ctx_init(&ctx, NULL, NULL);
        rc = run_job(&ctx, &j, outputs, formats, nout);
        for (i = 0; i < j.n; i++)
            qc_path_free(&ctx, &j.blocks[i].path);
    }
    free(j.blocks);
    cJSON_Delete(root);
    free(buf);
    cli_job_names_free(&names);
    return rc;
}
