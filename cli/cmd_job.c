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
#include "stats_json.h"
#include "quilt_plan.h"

/* Moves n points from the block's frame (lower-left corner `lo`) to `at`,
 * turned by rotate degrees about that corner. */
static void place_points(const block *b, qc_vec2 *v, size_t n, qc_vec2 lo)
{
    double mm = b->pat.mm_per_unit, c = qc_cos(b->rotate * QC_PI / 180);
    double s = qc_sin(b->rotate * QC_PI / 180);
    size_t i;

    for (i = 0; i < n; i++) {
        qc_vec2 p = v[i];
        p.x -= lo.x;
        p.y -= lo.y;
        v[i].x = b->at[0] * mm + c * p.x - s * p.y;
        v[i].y = b->at[1] * mm + s * p.x + c * p.y;
    }
}

/* The path and the outline (taken over from *outline) go to the quilt's frame. */
static void place(block *b, qc_path *path, qc_region *outline, qc_vec2 lo)
{
    place_points(b, path->pt, path->npt, lo);
    place_points(b, outline->v, outline->nv, lo);
    b->outline = *outline;
    memset(outline, 0, sizeof *outline);
    b->lo.x = b->at[0] * b->pat.mm_per_unit;
    b->lo.y = b->at[1] * b->pat.mm_per_unit;
}

/* Blocks may touch but not overlap: one line naming both and where. */
static int check_overlaps(const job *j)
{
    qc_patches ps;
    size_t i, a, b;
    qc_vec2 at;
    double mm = cli_units_mm(j->units);
    int found;

    ps.n = ps.cap = j->n;
    ps.p = calloc(j->n, sizeof *ps.p);
    if (ps.p == NULL) {
        cli_error("job: out of memory");
        return CLI_RUNTIME;
    }
    for (i = 0; i < j->n; i++)
        ps.p[i].region = j->blocks[i].outline; /* borrowed */
    found = qc_patches_overlap(&ps, 0, &a, &b, &at);
    free(ps.p);
    if (!found)
        return CLI_OK;
    cli_error("job: %s and %s overlap near (%.3f, %.3f) %s", j->blocks[a].where,
              j->blocks[b].where, at.x / mm, at.y / mm, j->units);
    return CLI_USAGE;
}

/* A pieced top as a block: quilted as one line in the ditch (its plan's
 * rules named "job: blocks[i].plan[k]"), its lower-left corner at "at". */
static int make_top(qc_ctx *ctx, block *b)
{
    quilt_plan plan;
    cli_quilt q;
    char prefix[48];
    qc_region drawn = {0};
    int rc = CLI_OK; /* params: cli_job_budget */

    memset(&plan, 0, sizeof plan);
    memset(&q, 0, sizeof q);
    snprintf(prefix, sizeof prefix, "job: %s.plan", b->where);
    if (rc == CLI_OK && b->plan != NULL)
        rc = cli_quilt_plan_parse(&plan, b->plan, &b->pat, prefix);
    if (rc == CLI_OK)
        rc = cli_quilt_sew(ctx, &q, b->top, &plan, &b->pat, NULL, b->label);
    if (rc == CLI_OK)
        rc = cli_quilt_outlines(ctx, &q.ps, &drawn);
    if (rc == CLI_OK) {
        place(b, &q.res.path, &drawn, qc_region_bbox(&drawn).min);
        b->path = q.res.path; /* keep the line, free the rest */
        memset(&q.res.path, 0, sizeof q.res.path);
    }
    qc_region_free(ctx, &drawn);
    cli_quilt_free(ctx, &q);
    cli_quilt_plan_free(ctx, &plan);
    return rc;
}

/* Generates block b in its own frame, then rotates it about its box's
 * lower-left corner and moves that corner to `at`. */
static int make_block(qc_ctx *ctx, block *b)
{
    qc_region region = {0};
    qc_points given = {0};
    qc_motif_set motifs = {0};
    qc_result res = {0};
    qc_vec2 origin = {0, 0};
    int rc;

    if (b->top != NULL)
        return make_top(ctx, b);
    rc = cli_pattern_load(ctx, &b->pat, &region, &given); /* params: cli_job_budget */
    if (rc == CLI_OK && b->pat.motifs != NULL)
        rc = cli_load_motifs(ctx, b->pat.motifs, &motifs);
    if (rc == CLI_OK && qc_generate(ctx, &region, &b->pat.params, &given,
                                    motifs.n ? &motifs : NULL, &res) < 0)
        rc = cli_fail(ctx, b->label, ctx->status);
    if (rc == CLI_OK)
        rc = cli_check_path_inside(ctx, &res.path, &res.params, &region,
                                   b->pat.region != NULL ? b->pat.region : "rect:8x8", b->label);
    if (rc == CLI_OK) {
        place(b, &res.path, &region, origin);
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

/* One path, a piece per block; moved so nothing sewn is negative (PAT needs
 * that), by *moved. The box is the flattened path's: control points of
 * curves lie outside the curve and would move the whole quilt. */
static int join_blocks(qc_ctx *ctx, block **order, size_t n, qc_path *out, qc_vec2 *moved)
{
    double len;
    qc_bbox box;
    size_t i;

    for (i = 0; i < n; i++)
        if (qc_path_append(ctx, out, &order[i]->path, 0) < 0)
            return cli_fail(ctx, "job", ctx->status);
    qc_curve_measure(out, 0.01, &len, &box);
    moved->x = -fmin(0, box.min.x);
    moved->y = -fmin(0, box.min.y);
    for (i = 0; i < out->npt; i++) {
        out->pt[i].x += moved->x;
        out->pt[i].y += moved->y;
    }
    return CLI_OK;
}

/* Every block's outline (a top's patches), moved with the path: drawn in
 * the SVG and on the DXF's layer OUTLINES. */
static int job_outlines(qc_ctx *ctx, const job *j, qc_vec2 moved, qc_region *out)
{
    size_t i, k, at;

    for (i = 0; i < j->n; i++) {
        const qc_region *r = &j->blocks[i].outline;
        size_t first = out->nv;
        for (k = 0, at = 0; k < r->nrings; at = r->ring_end[k++])
            if (qc_region_add_ring(ctx, out, r->v + at, r->ring_end[k] - at) < 0)
                return cli_fail(ctx, "job", ctx->status);
        for (k = first; k < out->nv; k++) {
            out->v[k].x += moved.x;
            out->v[k].y += moved.y;
        }
    }
    return CLI_OK;
}

static int run_job(qc_ctx *ctx, job *j, const char *const *outputs, const int *formats,
                   size_t nout, int quiet)
{
    cli_sewing sew = {12, 25.4, 0}; /* generate's defaults */
    block **order = calloc(j->n, sizeof *order);
    qc_path all = {0};
    qc_region outlines = {0};
    qc_vec2 moved = {0, 0};
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
    if (rc == CLI_OK)
        rc = check_overlaps(j);
    if (rc == CLI_OK) {
        sewing_order(order, j->n);
        rc = join_blocks(ctx, order, j->n, &all, &moved);
    }
    if (rc == CLI_OK)
        rc = job_outlines(ctx, j, moved, &outlines);
    memset(&sp, 0, sizeof sp);
    sp.tie_stitches = j->tie;
    if (rc == CLI_OK && qc_stitch_plan_taking(ctx, &all, NULL, &sp, &plan) < 0)
        rc = cli_fail(ctx, "job", ctx->status);
    memset(&io, 0, sizeof io);
    io.svg_inches = strcmp(j->units, "in") == 0;
    io.region = &outlines;
    if (rc == CLI_OK) /* all outputs or none */
        rc = cli_write_plans(ctx, outputs, formats, nout, &plan, &io);
    if (rc == CLI_OK && !quiet)
        cli_say_written(outputs, formats, nout, &plan, &sew, io.svg_inches);
    qc_plan_free(ctx, &plan);
    qc_region_free(ctx, &outlines);
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
    int rc = CLI_OK, a, allow_outside = 0, quiet = 0;

    for (a = 1; a < argc && rc == CLI_OK; a++) {
        if (strcmp(argv[a], "--help") == 0) {
            puts("usage: quiltc job QUILT.json [-o FILE]... [--allow-outside] [-q]\n"
                 "Generates every block of a quilt and joins them into one file (see README),\n"
                 "then prints a line per file written (-q, --quiet: none).\n"
                 "The job's files (regions, motifs, points, outputs) must stay inside its\n"
                 "folder; --allow-outside lets them be anywhere. -o is never limited.");
            return CLI_OK;
        } else if (strcmp(argv[a], "--allow-outside") == 0) {
            allow_outside = 1;
        } else if (strcmp(argv[a], "-q") == 0 || strcmp(argv[a], "--quiet") == 0) {
            quiet = 1;
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
        rc = run_job(&ctx, &j, outputs, formats, nout, quiet);
        for (i = 0; i < j.n; i++) {
            qc_path_free(&ctx, &j.blocks[i].path);
            qc_region_free(&ctx, &j.blocks[i].outline);
        }
    }
    free(j.blocks);
    cJSON_Delete(root);
    free(buf);
    cli_job_names_free(&names);
    return rc;
}
