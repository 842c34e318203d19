/*
 * Fuzz target: the whole pipeline driven by fuzzed choices on a small
 * region. The bytes choose a region (a built-in shape up to 60 mm, or up to
 * three rings of quantized vertices, so degenerate, touching and crossing
 * outlines are common), parameters within and beyond the table's ranges
 * (NaN, infinities, negatives, raw bits), a seed, stitch-plan settings and
 * writer options; then qc_generate -> qc_stitch_plan -> every writer into a
 * null sink (and one failing sink). Requests that would be legal but slow
 * (more than about 50 points, tiles, long perturbation, tiny tolerances)
 * are scaled down or skipped, and a plan of more than 150 points goes
 * through one chosen writer, so each run stays well under a millisecond. Sometimes the k-th allocation fails.
 *
 * Checks: statuses in range with one-line messages, a failed qc_generate or
 * qc_stitch_plan leaves its output zeroed, a result is one path starting
 * with MOVE, every writer succeeds on a plan (or refuses with ERANGE for
 * PAT's negative coordinates), nothing leaks.
 */
#include "fuzz_common.h"

#define MAX_EST_POINTS 50.0  /* points the sampler may make */
#define MAX_REGION_MM 60.0
#define ALL_WRITERS_MAX 150  /* bigger plans go through one chosen writer */

static const char *const shapes[] = {"rect", "square", "circle", "hexagon", "star", "heart"};

static int make_region(qc_ctx *ctx, fuzz_in *in, qc_region *r)
{
    unsigned kind = fuzz_u8(in);
    double w = fuzz_range(in, 0.2, MAX_REGION_MM);

    if (kind % 4 != 0) {
        char spec[64];
        const char *name = shapes[(kind >> 2) % 6];
        double h = fuzz_range(in, 0.2, MAX_REGION_MM);

        if (kind % 4 == 1)
            snprintf(spec, sizeof spec, "%s:%.17gx%.17g", name, w, h);
        else if (kind % 4 == 2)
            snprintf(spec, sizeof spec, "%s:%.17g", name, w);
        else /* hostile spec text */
            snprintf(spec, sizeof spec, "%s:%.17gx%.17g", name, fuzz_hostile(in, 0.2, 80),
                     fuzz_hostile(in, 0.2, 80));
        return qc_region_shape(ctx, spec, 1.0, r);
    } else {
        unsigned rings = 1 + fuzz_u8(in) % 3, k;
        for (k = 0; k < rings; k++) {
            qc_vec2 v[12];
            size_t n = 3 + fuzz_u8(in) % 10, i;
            int rc;
            for (i = 0; i < n; i++) {
                v[i].x = (double)(fuzz_u8(in) % 17) * w / 16.0;
                v[i].y = (double)(fuzz_u8(in) % 17) * w / 16.0;
            }
            if (getenv("QC_FUZZ_VERBOSE") != NULL) {
                fprintf(stderr, "  input ring %u:", k);
                for (i = 0; i < n; i++)
                    fprintf(stderr, " (%.17g, %.17g)", v[i].x, v[i].y);
                fputc('\n', stderr);
            }
            rc = qc_region_add_ring(ctx, r, v, n);
            if (rc < 0)
                return rc;
        }
        return qc_region_normalize(ctx, r);
    }
}

/* Writes row's field directly (the table's ranges are not checked here:
 * qc_generate must refuse what is out of range). */
static void set_field(qc_ctx *ctx, qc_params *p, const qc_param_info *info, fuzz_in *in)
{
    char *base = (char *)p + info->offset;
    unsigned how = fuzz_u8(in);

    if (how % 8 == 7) { /* through the public setter, any double */
        double v = fuzz_hostile(in, info->min, info->max);
        int rc;
        rc = qc_params_set(ctx, p, info->name, v);
        fuzz_check_status(ctx, rc, "qc_params_set status");
        return;
    }
    if (info->type == QC_PARAM_ENUM) {
        int v = how % 4 == 0 ? (int)(int32_t)fuzz_u64(in) : (int)(fuzz_u8(in) % 12) - 1;
        memcpy(base, &v, sizeof v);
    } else if (info->type == QC_PARAM_SEED) {
        uint64_t v = fuzz_u64(in);
        memcpy(base, &v, sizeof v);
    } else {
        double v = how % 3 == 0 ? fuzz_hostile(in, info->min, info->max)
                                : fuzz_range(in, info->min, info->max < 200 ? info->max : 200);
        if (info->type == QC_PARAM_INT && how % 3 != 0)
            v = floor(v);
        memcpy(base, &v, sizeof v);
    }
    p->given |= QC_PARAM_BIT(info->id);
}

static int fuzz_given(const qc_params *p, const char *name)
{
    const qc_param_info *row = qc_param_find(name);

    return row != NULL && qc_params_given(p, (int)row->id);
}

/* Legal but slow requests scaled down; 0 when the run should stop here. */
static int affordable(const qc_region *r, qc_params *p, qc_params *resolved)
{
    double area = fabs(qc_region_area(r));
    qc_bbox b = qc_region_bbox(r);
    double box = (b.max.x - b.min.x + 2 * resolved->spacing) *
                 (b.max.y - b.min.y + 2 * resolved->spacing);
    double cell = 0.8 * resolved->spacing * resolved->spacing;

    if (area / cell > MAX_EST_POINTS || box / cell > 8 * MAX_EST_POINTS)
        return 0;
    /* open finding: a spiral started off the region sorts a NULL array */
    if (fuzz_known("spiral-miss") && resolved->family == QC_FAMILY_SPIRAL &&
        (fuzz_given(p, "start-x") || fuzz_given(p, "start-y")))
        return 0;
    if (resolved->repeat_cols * resolved->repeat_rows > 6) {
        p->repeat_cols = p->repeat_rows = 1;
        resolved->repeat_cols = resolved->repeat_rows = 1;
    }
    if (resolved->tsp_time_ms > 2) {
        p->tsp_time_ms = 2;
        resolved->tsp_time_ms = 2;
    }
    return 1;
}

static void given_points(fuzz_in *in, const qc_region *r, qc_points *g, qc_ctx *ctx)
{
    qc_bbox b = qc_region_bbox(r);
    size_t n = fuzz_u8(in) % 64, i;

    for (i = 0; i < n; i++) {
        qc_vec2 v;
        v.x = b.min.x + (b.max.x - b.min.x) * (double)(fuzz_u8(in) % 33) / 32.0;
        v.y = b.min.y + (b.max.y - b.min.y) * (double)(fuzz_u8(in) % 33) / 32.0;
        if (qc_points_push(ctx, g, v) < 0)
            return;
    }
}

static void stitch_params(fuzz_in *in, qc_stitch_params *sp, double length)
{
    unsigned how = fuzz_u8(in);

    memset(sp, 0, sizeof *sp);
    sp->tolerance = how & 1 ? fuzz_hostile(in, 0, 1000) : fuzz_range(in, 0.01, 5);
    sp->min_segment = how & 2 ? fuzz_hostile(in, 0, 1000) : fuzz_range(in, -1, 5);
    sp->max_segment = how & 4 ? fuzz_hostile(in, 0.01, 1000) : fuzz_range(in, 0, 20);
    sp->tie_stitches = how & 8 ? (int)(int8_t)fuzz_u8(in) * 3 : (int)(fuzz_u8(in) % 8);
    sp->tie_length = how & 16 ? fuzz_hostile(in, 0, 100) : fuzz_range(in, 0, 5);
    sp->clip = (how & 32) != 0;
    /* legal but slow: a tolerance far below a micron, millions of splits */
    if (sp->tolerance > 0 && sp->tolerance < 0.001)
        sp->tolerance = 0.001;
    if (sp->max_segment > 0 && isfinite(sp->max_segment) && length / sp->max_segment > 2e4)
        sp->max_segment = length / 2e4;
}

static void write_all(qc_ctx *ctx, fuzz_in *in, const qc_plan *plan, const qc_region *r)
{
    qc_io_opts io;
    fuzz_sink sink;
    unsigned how = fuzz_u8(in);
    int fmt, rc;

    memset(&io, 0, sizeof io);
    io.region = how & 1 ? r : NULL;
    io.svg_inches = (how & 2) != 0;
    io.feed_mm_min = how & 4 ? fuzz_hostile(in, 0, 1e5) : fuzz_range(in, 0, 1e4);
    for (fmt = 0; fmt <= QC_FORMAT_COUNT; fmt++) {
        if (plan->n > ALL_WRITERS_MAX && fmt != (int)(how >> 3) % (QC_FORMAT_COUNT + 1))
            continue;
        memset(&sink, 0, sizeof sink);
        rc = qc_io_write(ctx, fmt, plan, &io, fuzz_sink_fn, &sink);
        fuzz_check_status(ctx, rc, "writer status");
        if (fmt == 0 || fmt == QC_FORMAT_COUNT)
            FUZZ_CHECK(rc == QC_EINVAL, "an unknown format refused");
        else if (rc == QC_EIO)
            FUZZ_CHECK(0, "a writer failed on a sink that never fails");
    }
    /* the chosen writer into a sink that fails after a few chunks */
    memset(&sink, 0, sizeof sink);
    sink.fail_after = 1 + fuzz_u8(in) % 4;
    fmt = 1 + (int)(fuzz_u8(in) % (QC_FORMAT_COUNT - 1));
    rc = qc_io_write(ctx, fmt, plan, &io, fuzz_sink_fn, &sink);
    fuzz_check_status(ctx, rc, "writer status, failing sink");
    if (sink.calls >= sink.fail_after)
        FUZZ_CHECK(rc == QC_EIO, "a failed write reported as success");
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_alloc a;
    qc_ctx ctx;
    qc_region region = {0};
    qc_points given = {0};
    qc_params p, resolved;
    qc_result res;
    qc_plan plan;
    qc_stitch_params sp;
    fuzz_in in;
    size_t nrows, k, nset;
    const qc_param_info *table = qc_param_table(&nrows);
    unsigned oom;
    int rc;

    in.p = data;
    in.n = size;
    in.at = 0;
    fuzz_ctx_init(&ctx, &a);
    oom = fuzz_u8(&in);
    rc = make_region(&ctx, &in, &region);
    fuzz_check_status(&ctx, rc, "region status");
    if (rc < 0)
        goto out;
    memset(&p, 0, sizeof p);
    p.family = 1 + (int)(fuzz_u8(&in) % (QC_FAMILY_COUNT - 1));
    p.given = QC_PARAM_BIT(QC_PARAM_ID_FAMILY);
    nset = fuzz_u8(&in) % 8;
    for (k = 0; k < nset; k++) {
        size_t row = fuzz_u8(&in) % nrows;
        set_field(&ctx, &p, &table[row], &in);
    }
    if (qc_params_resolve(&ctx, &p, &resolved) == QC_OK) {
        if (!affordable(&region, &p, &resolved))
            goto out;
        if (resolved.points == QC_POINTS_GIVEN)
            given_points(&in, &region, &given, &ctx);
    }
    if (oom < 24) /* now and then the k-th allocation from here on fails */
        a.t.fail_at = a.t.allocs + 1 + fuzz_u8(&in);
    if (getenv("QC_FUZZ_VERBOSE") != NULL) { /* what a reproducer asks for */
        fprintf(stderr, "region: %lu rings, %lu vertices, area %g mm2\n",
                (unsigned long)region.nrings, (unsigned long)region.nv, qc_region_area(&region));
        for (k = 0; k < region.nrings; k++) {
            size_t v;
            fprintf(stderr, "  ring %lu:", (unsigned long)k);
            for (v = k ? region.ring_end[k - 1] : 0; v < region.ring_end[k]; v++)
                fprintf(stderr, " (%.17g, %.17g)", region.v[v].x, region.v[v].y);
            fputc('\n', stderr);
        }
        for (k = 0; k < nrows; k++)
            if (qc_params_given(&p, (int)table[k].id))
                fprintf(stderr, "  %s = %.17g\n", table[k].name, qc_params_get(&p, &table[k]));
        fprintf(stderr, "given points %lu, fail_at %lu\n", (unsigned long)given.n,
                (unsigned long)a.t.fail_at);
    }
    rc = qc_generate(&ctx, &region, &p, &given, NULL, &res);
    fuzz_check_status(&ctx, rc, "generate status");
    if (getenv("QC_FUZZ_VERBOSE") != NULL)
        fprintf(stderr, "qc_generate: %d %s; live blocks %lu\n", rc, qc_errmsg(&ctx),
                (unsigned long)a.t.live_blocks);
    if (rc < 0) {
        FUZZ_CHECK(fuzz_all_zero(&res, sizeof res), "a failed qc_generate left its result");
        goto out;
    }
    FUZZ_CHECK(res.path.ncmd > 0 && res.path.cmd[0] == QC_PATH_MOVE, "a pattern starts with MOVE");
    stitch_params(&in, &sp, res.stats.length_mm);
    rc = qc_stitch_plan(&ctx, &res.path, &region, &sp, &plan);
    fuzz_check_status(&ctx, rc, "stitch plan status");
    if (rc < 0) {
        FUZZ_CHECK(plan.n == 0 && plan.p == NULL, "a failed plan is empty");
    } else {
        qc_plan_estimate est;
        FUZZ_CHECK(plan.n > 0 && (plan.flags[0] & QC_ST_JUMP), "p[0] is a jump");
        qc_plan_estimate_get(&plan, fuzz_hostile(&in, 0, 100), fuzz_hostile(&in, 0, 100), &est);
        FUZZ_CHECK(est.points == plan.n, "the estimate counts the points");
        write_all(&ctx, &in, &plan, &region);
    }
    qc_plan_free(&ctx, &plan);
    qc_result_free(&ctx, &res);
out:
    qc_points_free(&ctx, &given);
    qc_region_free(&ctx, &region);
    fuzz_check_clean(&a, "generate leaked");
    return 0;
}
