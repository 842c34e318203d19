/*
 * The JavaScript boundary (see quiltc_wasm.h): flat qcw_* functions over the
 * unchanged library. The steps mirror the CLI's generate exactly (region
 * normalized and moved to the origin, qc_generate, qc_stitch_plan with the
 * tie-off count, qc_io_write with the region and svg_inches), so downloads
 * are byte-identical to quiltc's. The same file is compiled natively for the
 * tests. Only this layer has a clock: it times the core's stages through
 * the context's trace hook.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "quiltc.h"
#include "quiltc_wasm.h"
#include "qcw_internal.h"

static double now_ms(void)
{
    struct timespec ts;

    if (clock_gettime(CLOCK_MONOTONIC, &ts) != 0)
        return 0.0;
    return (double)ts.tv_sec * 1000.0 + (double)ts.tv_nsec / 1e6;
}

static void on_stage(void *ud, const char *stage)
{
    qcw_job *job = ud;

    if (job->nstages < MAX_STAGES) {
        job->stage[job->nstages] = stage;
        job->stage_ms[job->nstages] = now_ms();
        job->nstages++;
    }
}

qcw_job *qcw_new(void)
{
    qcw_job *job = calloc(1, sizeof *job);

    if (job != NULL) {
        qc_ctx_init(&job->ctx, NULL, NULL);
        job->ctx.trace = on_stage;
        job->ctx.trace_ud = job;
    }
    return job;
}

void qcw__drop_result(qcw_job *job)
{
    qc_result_free(&job->ctx, &job->result);
    qc_quilt_result_free(&job->ctx, &job->quilt);
    job->sewn = 0;
    qc_plan_free(&job->ctx, &job->plan);
    job->nstages = 0;
    job->plan_ms = job->total_ms = 0.0;
}

void qcw_free(qcw_job *job)
{
    if (job == NULL)
        return;
    qcw__drop_result(job);
    qcw__drop_top(job);
    qc_region_free(&job->ctx, &job->region);
    qc_motif_set_free(&job->ctx, &job->motifs);
    free(job->bytes);
    free(job->json);
    if (job->warnings != NULL)
        free(job->warnings->s);
    free(job->warnings);
    free(job);
}

const char *qcw_error(const qcw_job *job)
{
    return job != NULL ? qc_errmsg(&job->ctx) : "no job";
}

const char *qcw_version(void)
{
    return qc_version();
}


const char *qcw_params_json(qcw_job *job)
{
    static const char *const types[] = {"int", "enum", "real", "length", "seed"};
    size_t n, i;
    const qc_param_info *t = qc_param_table(&n);
    qcw_text out = {0};

    qcw__add(&out, "[");
    for (i = 0; i < n; i++) {
        qcw__add(&out, "%s{\"name\":", i ? "," : "");
        qcw__add_str(&out, t[i].name);
        qcw__add(&out, ",\"help\":");
        qcw__add_str(&out, t[i].help);
        qcw__add(&out, ",\"unit\":");
        qcw__add_str(&out, t[i].unit);
        qcw__add(&out, ",\"type\":\"%s\",\"choices\":", types[t[i].type]);
        qcw__add_str(&out, t[i].choices != NULL ? t[i].choices : "");
        qcw__add(&out, ",\"min\":%.17g,\"max\":%.17g,\"def\":%.17g,\"def_per_spacing\":%.17g,"
                  "\"families\":%lu}",
            t[i].min, t[i].max, t[i].def, t[i].def_per_spacing,
            (unsigned long)qc_param_families(&t[i]));
    }
    qcw__add(&out, "]");
    return qcw__finish_json(job, &out);
}

/* Enum row value k (1-based) as its choice name. */
static void add_choice(qcw_text *t, const char *choices, int k)
{
    const char *s = choices;

    while (--k > 0 && s != NULL)
        s = strchr(s, '|') != NULL ? strchr(s, '|') + 1 : NULL;
    if (s == NULL) {
        qcw__add(t, "null");
        return;
    }
    qcw__add(t, "\"%.*s\"", (int)(strchr(s, '|') != NULL ? (size_t)(strchr(s, '|') - s) : strlen(s)), s);
}

/* Every row of resolved r as "name":value (enums by choice name, the seed
 * as a decimal string), in a JSON object. */
static void add_resolved(qcw_text *out, const qc_params *r)
{
    size_t n, i;
    const qc_param_info *t = qc_param_table(&n);

    qcw__add(out, "{");
    for (i = 0; i < n; i++) {
        qcw__add(out, "%s\"%s\":", i ? "," : "", t[i].name);
        if (t[i].type == QC_PARAM_ENUM)
            add_choice(out, t[i].choices, (int)qc_params_get(r, &t[i]));
        else if (t[i].type == QC_PARAM_SEED)
            qcw__add(out, "\"%llu\"", (unsigned long long)r->seed);
        else
            qcw__add(out, "%.17g", qc_params_get(r, &t[i]));
    }
    qcw__add(out, "}");
}

const char *qcw_resolved_json(qcw_job *job)
{
    qc_params r;
    qcw_text out = {0};

    qc_clear_error(&job->ctx);
    if (qc_params_resolve(&job->ctx, &job->params, &r) < 0)
        return NULL;
    add_resolved(&out, &r);
    return qcw__finish_json(job, &out);
}

const char *qcw_families_json(qcw_job *job)
{
    const qc_family_desc *f;
    size_t i;
    qcw_text out = {0};

    qcw__add(&out, "[");
    for (i = 0; (f = qc_family_info(i)) != NULL; i++) {
        qc_params p, r;

        memset(&p, 0, sizeof p);
        p.family = (int)f->id;
        if (qc_params_resolve(&job->ctx, &p, &r) < 0) {
            free(out.s);
            return NULL;
        }
        qcw__add(&out, "%s{\"name\":", i ? "," : "");
        qcw__add_str(&out, f->name);
        qcw__add(&out, ",\"summary\":");
        qcw__add_str(&out, f->summary);
        qcw__add(&out, ",\"id\":%d,\"points\":%s,\"tree\":%s,\"motifs\":%s", (int)f->id,
            f->needs & QC_FAMILY_NEEDS_POINTS ? "true" : "false",
            f->needs & QC_FAMILY_NEEDS_TREE ? "true" : "false",
            f->needs & QC_FAMILY_NEEDS_MOTIFS ? "true" : "false");
        qcw__add(&out, ",\"defaults\":");
        add_resolved(&out, &r);
        qcw__add(&out, "}");
    }
    qcw__add(&out, "]");
    return qcw__finish_json(job, &out);
}

const char *qcw_motifs_json(qcw_job *job)
{
    size_t n = qc_motif_builtin_count(), i;
    qcw_text out = {0};

    qcw__add(&out, "[");
    for (i = 0; i < n; i++) {
        qcw__add(&out, "%s", i ? "," : "");
        qcw__add_str(&out, qc_motif_builtin_name(i));
    }
    qcw__add(&out, "]");
    return qcw__finish_json(job, &out);
}

/* ---- region ---- */

/* As the CLI does: normalized, moved so the bounding box starts at (0, 0). */
static int place_region(qcw_job *job, int rc)
{
    qc_bbox box;

    if (rc == QC_OK)
        rc = qc_region_normalize(&job->ctx, &job->region);
    if (rc < 0) {
        qc_region_free(&job->ctx, &job->region);
        return rc;
    }
    box = qc_region_bbox(&job->region);
    qc_region_translate(&job->region, -box.min.x, -box.min.y);
    return QC_OK;
}

static void keep_warning(void *ud, const char *text)
{
    qcw_text *t = (qcw_text *)ud;

    if (t->n)
        qcw__add(t, ",");
    qcw__add_str(t, text);
}

/* Forgets the last SVG's warnings (a new outline is on its way). */
static void forget_warnings(qcw_job *job)
{
    if (job->warnings == NULL)
        return;
    free(job->warnings->s);
    memset(job->warnings, 0, sizeof *job->warnings);
}

void qcw__svg_opts(qcw_job *job, qc_svg_opts *opts)
{
    memset(opts, 0, sizeof *opts);
    forget_warnings(job);
    if (job->warnings == NULL)
        job->warnings = (qcw_text *)calloc(1, sizeof *job->warnings);
    if (job->warnings == NULL)
        return; /* warnings dropped, the reading goes on */
    opts->warn = keep_warning;
    opts->warn_ud = job->warnings;
}

const char *qcw_svg_warnings_json(qcw_job *job)
{
    qcw_text t = {0};

    qcw__add(&t, "[");
    if (job->warnings != NULL && job->warnings->n > 0 && !job->warnings->failed)
        qcw__add(&t, "%s", job->warnings->s);
    qcw__add(&t, "]");
    return qcw__finish_json(job, &t);
}

int qcw_region_shape(qcw_job *job, const char *spec, double mm_per_unit)
{
    forget_warnings(job);
    qcw__drop_top(job);
    qc_region_free(&job->ctx, &job->region);
    qc_clear_error(&job->ctx);
    return place_region(job, qc_region_shape(&job->ctx, spec, mm_per_unit, &job->region));
}

int qcw_region_svg(qcw_job *job, const char *svg, size_t len)
{
    qc_svg_opts opts;

    qcw__svg_opts(job, &opts);
    qcw__drop_top(job);
    qc_region_free(&job->ctx, &job->region);
    qc_clear_error(&job->ctx);
    return place_region(job, qc_io_read_svg_region(&job->ctx, svg, len, &opts, &job->region));
}

const double *qcw_region_xy(const qcw_job *job)
{
    return job->region.nv ? &job->region.v[0].x : NULL;
}

size_t qcw_region_vertices(const qcw_job *job)
{
    return job->region.nv;
}

const uint32_t *qcw_region_ring_ends(const qcw_job *job)
{
    return job->region.ring_end;
}

size_t qcw_region_rings(const qcw_job *job)
{
    return job->region.nrings;
}

/* ---- parameters and motifs ---- */

void qcw_params_reset(qcw_job *job, int svg_inches)
{
    memset(&job->params, 0, sizeof job->params);
    job->svg_inches = svg_inches;
    qc_motif_set_free(&job->ctx, &job->motifs);
}

int qcw_param(qcw_job *job, const char *name, double value)
{
    qc_clear_error(&job->ctx);
    return qc_params_set(&job->ctx, &job->params, name, value);
}

int qcw_seed(qcw_job *job, double hi, double lo)
{
    qc_clear_error(&job->ctx);
    if (!(hi >= 0.0 && hi <= 4294967295.0 && lo >= 0.0 && lo <= 4294967295.0))
        return qcw__fail(job, QC_ERANGE, "seed halves out of range%s", "");
    qc_params_set_seed(&job->params, ((uint64_t)hi << 32) | (uint64_t)lo);
    return QC_OK;
}

int qcw_motifs(qcw_job *job, const char *names)
{
    qc_clear_error(&job->ctx);
    return qc_motif_builtin(&job->ctx, names, &job->motifs);
}

int qcw_motif_svg(qcw_job *job, const char *svg, size_t len, const char *name)
{
    qc_clear_error(&job->ctx);
    return qc_motif_from_svg(&job->ctx, svg, len, name, &job->motifs);
}

/* ---- generation ---- */

int qcw_run(qcw_job *job, int tie_stitches)
{
    qc_stitch_params sp;
    double t0 = now_ms(), t1;
    int rc;

    qcw__drop_result(job);
    qc_clear_error(&job->ctx);
    job->params.skip_gap_stat = 1; /* a live preview: the path is the same without it */
    rc = qc_generate(&job->ctx, &job->region, &job->params, NULL,
                     job->motifs.n ? &job->motifs : NULL, &job->result);
    if (rc == QC_OK) /* the same figure as --stats and `quiltc check` */
        rc = qc_result_measure(&job->ctx, &job->region, &job->result);
    if (rc < 0) {
        qcw__drop_result(job);
        return rc;
    }
    t1 = now_ms();
    memset(&sp, 0, sizeof sp);
    sp.tie_stitches = tie_stitches;
    /* nothing reads the path once planned: it goes as it is flattened (the
     * peak of a large preview) */
    rc = qc_stitch_plan_taking(&job->ctx, &job->result.path, NULL, &sp, &job->plan);
    job->plan_ms = now_ms() - t1;
    job->total_ms = now_ms() - t0;
    if (rc < 0)
        qcw__drop_result(job);
    return rc;
}

size_t qcw_points(const qcw_job *job)
{
    return job->plan.n;
}

const double *qcw_xy(const qcw_job *job)
{
    return job->plan.n ? &job->plan.p[0].x : NULL;
}

const unsigned char *qcw_flags(const qcw_job *job)
{
    return job->plan.flags;
}

const char *qcw_stats_json(qcw_job *job)
{
    const qc_stats *s = &job->result.stats;
    qc_plan_estimate est;
    qcw_text out = {0};
    size_t i;

    qc_plan_estimate_get(&job->plan, 0, 0, &est);
    qcw__add(&out, "{\"family\":");
    qcw__add_str(&out, qc_family_name(job->result.params.family));
    qcw__add(&out, ",\"points\":%lu,\"plan_points\":%lu,\"pieces\":%lu,\"path_length_mm\":%.3f,"
              "\"stitches\":%lu,\"thread_mm\":%.1f,\"sew_seconds\":%.1f,\"jumps\":%lu,"
              "\"ties\":%lu,\"width_mm\":%.3f,\"height_mm\":%.3f,"
              "\"motifs_placed\":%lu,\"motifs_shrunk\":%lu,\"motifs_skipped\":%lu,"
              "\"pebbles\":%lu,\"largest_gap_mm\":%.3f,\"farthest_fabric_mm\":%.3f,"
              "\"seam_bare\":%.4f,\"spacing_mm\":%.6g,\"stages_ms\":{",
        (unsigned long)s->points, (unsigned long)job->plan.n, (unsigned long)s->pieces,
        s->length_mm, (unsigned long)est.stitches, est.thread_mm, est.seconds,
        (unsigned long)est.jumps, (unsigned long)est.ties, est.bbox.max.x - est.bbox.min.x,
        est.bbox.max.y - est.bbox.min.y, (unsigned long)s->motifs_placed,
        (unsigned long)s->motifs_shrunk, (unsigned long)s->motifs_skipped,
        (unsigned long)s->pebbles, s->largest_gap_mm, s->farthest_fabric_mm, s->seam_bare,
        job->result.params.spacing);
    for (i = 0; i + 1 < job->nstages; i++) {
        qcw__add(&out, "%s", i ? "," : "");
        qcw__add_str(&out, job->stage[i]);
        qcw__add(&out, ":%.3f", job->stage_ms[i + 1] - job->stage_ms[i]);
    }
    qcw__add(&out, "%s\"plan\":%.3f},\"total_ms\":%.3f}", i ? "," : "", job->plan_ms, job->total_ms);
    return qcw__finish_json(job, &out);
}

/* ---- export ---- */

static int collect(void *ud, const void *data, size_t len)
{
    qcw_job *job = ud;

    if (len > job->bytes_cap - job->nbytes) {
        size_t cap = (job->bytes_cap ? job->bytes_cap * 2 : 65536) + len;
        unsigned char *b = realloc(job->bytes, cap);

        if (b == NULL)
            return -1;
        job->bytes = b;
        job->bytes_cap = cap;
    }
    memcpy(job->bytes + job->nbytes, data, len);
    job->nbytes += len;
    return 0;
}

int qcw_export(qcw_job *job, const char *format)
{
    qc_io_opts io;
    int f = qc_format_from_name(format);

    qc_clear_error(&job->ctx);
    job->nbytes = 0;
    if (f < 0)
        return qcw__fail(job, QC_EINVAL, "unknown format '%s'", format);
    if (job->plan.n == 0)
        return qcw__fail(job, QC_EEMPTY, "nothing to export: generate a pattern first%s", "");
    memset(&io, 0, sizeof io);
    io.region = &job->region;
    io.svg_inches = job->svg_inches;
    if (job->sewn) { /* a top: as quiltc quilt writes it */
        io.travel = &job->quilt.ditch;
        io.dxf_outlines = 1;
    }
    return qc_io_write(&job->ctx, f, &job->plan, &io, collect, job);
}

const unsigned char *qcw_export_data(const qcw_job *job)
{
    return job->bytes;
}

size_t qcw_export_size(const qcw_job *job)
{
    return job->nbytes;
}
