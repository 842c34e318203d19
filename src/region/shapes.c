/*
 * Built-in block outlines: "rect:WxH", "square:S", "circle:D", "hexagon:D",
 * "star:D", "heart:D", in the caller's unit.
 */
#include <math.h>
#include <string.h>

#include "internal.h"

#define MAX_SIZE_MM 1e5
#define CHORD_TOL_MM 0.01 /* a circle's polygon stays this close to the circle */
#define MAX_SEGMENTS 4096

typedef int (*shape_fn)(qc_ctx *ctx, const double *size, qc_region *out);

/* Segments so a circle of radius r deviates from its polygon by at most about
 * CHORD_TOL_MM: the sagitta of angle a is r a^2 / 8 for small a. */
static size_t circle_segments(double r)
{
    double n = QC_PI * sqrt(r / (2.0 * CHORD_TOL_MM));
    /* a multiple of 4, so the polygon touches its circle's box on all sides */
    return n < 64.0 ? 64 : n > MAX_SEGMENTS ? MAX_SEGMENTS : (size_t)ceil(n / 4) * 4;
}

static int add_points(qc_ctx *ctx, qc_region *out, qc_vec2 *v, size_t n)
{
    int rc = qc_region_add_ring(ctx, out, v, n);
    qc__free(ctx, v, n * sizeof *v);
    return rc;
}

static int rect(qc_ctx *ctx, const double *s, qc_region *out)
{
    qc_vec2 v[4];

    v[0].x = 0;    v[0].y = 0;
    v[1].x = s[0]; v[1].y = 0;
    v[2].x = s[0]; v[2].y = s[1];
    v[3].x = 0;    v[3].y = s[1];
    return qc_region_add_ring(ctx, out, v, 4);
}

/* n points on a circle of radius r round (r, r), first at angle a0. */
static int polygon(qc_ctx *ctx, double r, size_t n, double a0, qc_region *out)
{
    qc_vec2 *v = qc__alloc_array(ctx, n, sizeof *v);
    size_t i;

    if (v == NULL)
        return QC_ENOMEM;
    for (i = 0; i < n; i++) {
        double a = a0 + 2.0 * QC_PI * (double)i / (double)n;
        v[i].x = r + r * qc_cos(a);
        v[i].y = r + r * qc_sin(a);
    }
    return add_points(ctx, out, v, n);
}

static int circle(qc_ctx *ctx, const double *s, qc_region *out)
{
    return polygon(ctx, s[0] / 2, circle_segments(s[0] / 2), 0.0, out);
}

/* Flat-topped: D is the distance across corners. */
static int hexagon(qc_ctx *ctx, const double *s, qc_region *out)
{
    return polygon(ctx, s[0] / 2, 6, 0.0, out);
}

/* Five points, the inner radius of a regular pentagram. */
static int star(qc_ctx *ctx, const double *s, qc_region *out)
{
    double r = s[0] / 2, inner = r * 0.381966011250105; /* (3 - sqrt 5) / 2 */
    qc_vec2 v[10];
    size_t i;

    for (i = 0; i < 10; i++) {
        double a = QC_PI / 2 + QC_PI * (double)i / 5.0, rad = i % 2 ? inner : r;
        v[i].x = r + rad * qc_cos(a);
        v[i].y = r + rad * qc_sin(a);
    }
    return qc_region_add_ring(ctx, out, v, 10);
}

/* The classic heart curve x = 16 sin^3 t, y = 13 cos t - 5 cos 2t - 2 cos 3t - cos 4t,
 * scaled to D wide. */
static int heart(qc_ctx *ctx, const double *s, qc_region *out)
{
    size_t n = circle_segments(s[0] / 2) * 2, i;
    double k = s[0] / 32.0;
    qc_vec2 *v = qc__alloc_array(ctx, n, sizeof *v);

    if (v == NULL)
        return QC_ENOMEM;
    for (i = 0; i < n; i++) {
        double t = 2.0 * QC_PI * (double)i / (double)n, st = qc_sin(t);
        v[i].x = k * 16.0 * st * st * st;
        v[i].y = k * (13.0 * qc_cos(t) - 5.0 * qc_cos(2 * t) - 2.0 * qc_cos(3 * t) -
                      qc_cos(4 * t));
    }
    return add_points(ctx, out, v, n);
}

static const struct shape {
    const char *name;
    int nsize; /* 1: "D", 2: "WxH" */
    shape_fn fn;
} shapes[] = {
    {"rect", 2, rect},       {"square", 1, rect},  {"circle", 1, circle},
    {"hexagon", 1, hexagon}, {"star", 1, star},    {"heart", 1, heart},
};

/* Parses one size at *s (advancing it; qc__scan_number: no hex, nan, inf or
 * locale), checks its range in mm. */
static int parse_size(qc_ctx *ctx, const char *spec, const char **s, double mm, double *out)
{
    size_t n = 0;
    double v;

    if (!qc__scan_number(*s, strlen(*s), &n, &v))
        return qc__fail(ctx, QC_EINVAL, "shape '%s': expected a number at '%s'", spec, *s);
    *s += n;
    v *= mm;
    if (!(v > 0.0) || !(v <= MAX_SIZE_MM))
        return qc__fail(ctx, QC_ERANGE, "shape '%s': size %g mm is outside (0, %g]", spec, v,
                        MAX_SIZE_MM);
    *out = v;
    return QC_OK;
}

static int parse(qc_ctx *ctx, const char *spec, double mm, const struct shape **shape,
                 double size[2])
{
    const char *colon = strchr(spec, ':'), *s;
    size_t i, len = colon ? (size_t)(colon - spec) : strlen(spec);

    *shape = NULL;
    for (i = 0; i < sizeof shapes / sizeof shapes[0]; i++)
        if (strlen(shapes[i].name) == len && strncmp(spec, shapes[i].name, len) == 0)
            *shape = &shapes[i];
    if (*shape == NULL || colon == NULL)
        return qc__fail(ctx, QC_EINVAL,
                        "unknown shape '%s' (rect:WxH, square:S, circle:D, hexagon:D, star:D, "
                        "heart:D)", spec);
    s = colon + 1;
    QC__TRY(parse_size(ctx, spec, &s, mm, &size[0]));
    size[1] = size[0];
    if ((*shape)->nsize == 2) {
        if (*s != 'x' && *s != 'X')
            return qc__fail(ctx, QC_EINVAL, "shape '%s': expected WxH", spec);
        s++;
        QC__TRY(parse_size(ctx, spec, &s, mm, &size[1]));
    }
    if (*s != '\0')
        return qc__fail(ctx, QC_EINVAL, "shape '%s': unexpected '%s'", spec, s);
    return QC_OK;
}

int qc_region_shape(qc_ctx *ctx, const char *spec, double mm_per_unit, qc_region *out)
{
    const struct shape *shape;
    double size[2];
    qc_bbox box;
    int rc;

    memset(out, 0, sizeof *out);
    if (spec == NULL)
        return qc__fail(ctx, QC_EINVAL, "no shape given");
    if (!(mm_per_unit > 0.0) || !(mm_per_unit <= 1e4))
        return qc__fail(ctx, QC_ERANGE, "unit of %g mm is not a length unit", mm_per_unit);
    QC__TRY(parse(ctx, spec, mm_per_unit, &shape, size));
    rc = shape->fn(ctx, size, out);
    if (rc == QC_OK) {
        box = qc_region_bbox(out);
        qc_region_translate(out, -box.min.x, -box.min.y);
        rc = qc_region_normalize(ctx, out);
    }
    if (rc < 0)
        qc_region_free(ctx, out);
    return rc;
}
