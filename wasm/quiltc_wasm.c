/*
 * The JavaScript boundary: flat qcw_* wrappers over the unchanged library.
 * A job holds one region, parameters and the last result; every call returns
 * a status (QC_OK or a negative QC_E*) and qcw_error() tells why. The steps
 * mirror the CLI's exactly, so downloads are byte-identical to quiltc's.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "quiltc.h"

typedef struct qcw_job {
    qc_ctx ctx;
    qc_region region;
    qc_params params;
    qc_motif_set motifs;
    qc_result result;
    qc_plan plan;
    int svg_inches;
    double *xy;          /* plan points as x,y pairs (mm) for drawing */
    unsigned char *flags;
    unsigned char *bytes; /* last export */
    size_t nbytes, bytes_cap;
    char *json;           /* last JSON answer */
} qcw_job;

qcw_job *qcw_new(void);
void qcw_free(qcw_job *job);
const char *qcw_error(const qcw_job *job);
const char *qcw_version(void);
const char *qcw_params_json(qcw_job *job);
int qcw_region_shape(qcw_job *job, const char *spec, double mm_per_unit);
int qcw_region_svg(qcw_job *job, const char *svg, size_t len);
const double *qcw_region_xy(const qcw_job *job);
size_t qcw_region_vertices(const qcw_job *job);
const uint32_t *qcw_region_ring_ends(const qcw_job *job);
size_t qcw_region_rings(const qcw_job *job);
void qcw_params_reset(qcw_job *job, int svg_inches);
int qcw_param(qcw_job *job, const char *name, double value);
int qcw_seed(qcw_job *job, double hi, double lo);
int qcw_motifs(qcw_job *job, const char *names);
int qcw_motif_svg(qcw_job *job, const char *svg, size_t len, const char *name);
int qcw_run(qcw_job *job, int tie_stitches);
size_t qcw_points(const qcw_job *job);
const double *qcw_xy(const qcw_job *job);
const unsigned char *qcw_flags(const qcw_job *job);
const char *qcw_stats_json(qcw_job *job);
int qcw_export(qcw_job *job, const char *format);
const unsigned char *qcw_export_data(const qcw_job *job);
size_t qcw_export_size(const qcw_job *job);

qcw_job *qcw_new(void)
{
    qcw_job *job = calloc(1, sizeof *job);

    if (job != NULL)
        qc_ctx_init(&job->ctx, NULL, NULL);
    return job;
}

static void drop_result(qcw_job *job)
{
    qc_result_free(&job->ctx, &job->result);
    qc_plan_free(&job->ctx, &job->plan);
    free(job->xy);
    free(job->flags);
    job->xy = NULL;
    job->flags = NULL;
}

void qcw_free(qcw_job *job)
{
    if (job == NULL)
        return;
    drop_result(job);
    qc_region_free(&job->ctx, &job->region);
    qc_motif_set_free(&job->ctx, &job->motifs);
    free(job->bytes);
    free(job->json);
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

/* JSON text builder over a growing heap string. */
typedef struct text {
    char *s;
    size_t n, cap;
    int failed;
} text;

static void add(text *t, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

#include <stdarg.h>
static void add(text *t, const char *fmt, ...)
{
    va_list ap;
    int k;

    for (;;) {
        size_t room = t->cap - t->n;

        va_start(ap, fmt);
        k = vsnprintf(t->s ? t->s + t->n : NULL, t->s ? room : 0, fmt, ap);
        va_end(ap);
        if (k < 0) {
            t->failed = 1;
            return;
        }
        if (t->s != NULL && (size_t)k < room) {
            t->n += (size_t)k;
            return;
        }
        {
            size_t cap = (t->cap ? t->cap * 2 : 1024) + (size_t)k;
            char *s = realloc(t->s, cap);

            if (s == NULL) {
                t->failed = 1;
                return;
            }
            t->s = s;
            t->cap = cap;
        }
    }
}

static const char *finish_json(qcw_job *job, text *t)
{
    free(job->json);
    job->json = t->failed ? NULL : t->s;
    if (t->failed)
        free(t->s);
    return job->json != NULL ? job->json : "null";
}

const char *qcw_params_json(qcw_job *job)
{
    static const char *const types[] = {"int", "enum", "real", "length", "seed"};
    size_t n, i;
    const qc_param_info *t = qc_param_table(&n);
    text out = {0};

    add(&out, "[");
    for (i = 0; i < n; i++) {
        add(&out, "%s{\"name\":\"%s\",\"help\":\"%s\",\"unit\":\"%s\",\"type\":\"%s\","
                  "\"choices\":\"%s\",\"min\":%.17g,\"max\":%.17g,\"def\":%.17g,"
                  "\"def_per_spacing\":%.17g,\"families\":%u}",
            i ? "," : "", t[i].name, t[i].help, t[i].unit, types[t[i].type],
            t[i].choices ? t[i].choices : "", t[i].min, t[i].max, t[i].def,
            t[i].def_per_spacing, (unsigned)t[i].families);
    }
    add(&out, "]");
    return finish_json(job, &out);
}

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

int qcw_region_shape(qcw_job *job, const char *spec, double mm_per_unit)
{
    qc_region_free(&job->ctx, &job->region);
    qc_clear_error(&job->ctx);
    return place_region(job, qc_region_shape(&job->ctx, spec, mm_per_unit, &job->region));
}

int qcw_region_svg(qcw_job *job, const char *svg, size_t len)
{
    qc_svg_opts opts;

    memset(&opts, 0, sizeof opts);
    qc_region_free(&job->ctx, &job->region);
    qc_clear_error(&job->ctx);
    return place_region(job, qc_io_read_svg_region(&job->ctx, svg, len, &opts, &job->region));
}

const double *qcw_region_xy(const qcw_job *job)
{
    return (const double *)job->region.v;
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

void qcw_params_reset(qcw_job *job, int svg_inches)
{
    memset(&job->params, 0, sizeof job->params);
    job->svg_inches = svg_inches;
    qc_motif_set_free(&job->ctx, &job->motifs);
}

/* Lengths arrive in mm: the page converts from its units, as the CLI does. */
int qcw_param(qcw_job *job, const char *name, double value)
{
    qc_clear_error(&job->ctx);
    return qc_params_set(&job->ctx, &job->params, name, value);
}

/* JS numbers hold 53 bits: the seed comes as two 32-bit halves. */
int qcw_seed(qcw_job *job, double hi, double lo)
{
    int rc = qc_params_set(&job->ctx, &job->params, "seed", 0.0);

    job->params.seed = ((uint64_t)hi << 32) | (uint64_t)lo;
    return rc;
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

int qcw_run(qcw_job *job, int tie_stitches)
{
    qc_stitch_params sp;
    size_t i;
    int rc;

    drop_result(job);
    qc_clear_error(&job->ctx);
    rc = qc_generate(&job->ctx, &job->region, &job->params, NULL,
                     job->motifs.n ? &job->motifs : NULL, &job->result);
    if (rc < 0)
        return rc;
    memset(&sp, 0, sizeof sp);
    sp.tie_stitches = tie_stitches;
    rc = qc_stitch_plan(&job->ctx, &job->result.path, NULL, &sp, &job->plan);
    if (rc < 0)
        return rc;
    job->xy = malloc(job->plan.n * 2 * sizeof *job->xy + 1);
    job->flags = malloc(job->plan.n + 1);
    if (job->xy == NULL || job->flags == NULL)
        return QC_ENOMEM;
    for (i = 0; i < job->plan.n; i++) {
        job->xy[2 * i] = job->plan.p[i].x;
        job->xy[2 * i + 1] = job->plan.p[i].y;
        job->flags[i] = job->plan.flags[i];
    }
    return QC_OK;
}

size_t qcw_points(const qcw_job *job)
{
    return job->plan.n;
}

const double *qcw_xy(const qcw_job *job)
{
    return job->xy;
}

const unsigned char *qcw_flags(const qcw_job *job)
{
    return job->flags;
}

const char *qcw_stats_json(qcw_job *job)
{
    const qc_stats *s = &job->result.stats;
    qc_plan_estimate est;
    text out = {0};

    qc_plan_estimate_get(&job->plan, 0, 0, &est);
    add(&out, "{\"family\":\"%s\",\"points\":%lu,\"pieces\":%lu,\"path_length_mm\":%.3f,"
              "\"stitches\":%lu,\"thread_mm\":%.1f,\"sew_seconds\":%.1f,\"jumps\":%lu,"
              "\"motifs_placed\":%lu,\"motifs_skipped\":%lu,\"pebbles\":%lu,"
              "\"largest_gap_mm\":%.3f}",
        qc_family_name(job->result.params.family), (unsigned long)s->points,
        (unsigned long)s->pieces, s->length_mm, (unsigned long)est.stitches,
        est.thread_mm, est.seconds, (unsigned long)est.jumps,
        (unsigned long)s->motifs_placed, (unsigned long)s->motifs_skipped,
        (unsigned long)s->pebbles, s->largest_gap_mm);
    return finish_json(job, &out);
}

static int collect(void *ud, const void *data, size_t len)
{
    qcw_job *job = ud;

    if (job->nbytes + len > job->bytes_cap) {
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
    if (f < 0) {
        snprintf(job->ctx.msg, sizeof job->ctx.msg, "unknown format '%s'", format);
        return QC_EINVAL;
    }
    memset(&io, 0, sizeof io);
    io.region = &job->region;
    io.svg_inches = job->svg_inches;
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
