/* Pieced shapes: triangles, star points, diamonds, strips, curves, holes. */
#include <math.h>
#include <string.h>

#include "pieced.h"

#define IN 25.4
#define PI 3.14159265358979323846
#define MAXV 400

static const pieced_shape shapes[] = {
    {"half-square triangle", 1}, {"flying geese", 1}, {"star point 30", 1},
    {"star point 45", 1},        {"5-point star", 1}, {"LeMoyne diamond", 1},
    {"sashing 1.5x20", 0},       {"border 0.75x30", 0}, {"crescent", 1},
    {"ring", 0},                 {"block with holes", 0}, {"C-shape", 0},
    {"heart", 0},
};

const pieced_shape *pieced_shapes(size_t *count)
{
    *count = sizeof shapes / sizeof shapes[0];
    return shapes;
}

static qc_vec2 P(double x, double y)
{
    qc_vec2 p;
    p.x = x * IN;
    p.y = y * IN;
    return p;
}

static int ring(qc_ctx *ctx, qc_region *r, const qc_vec2 *v, size_t n)
{
    return qc_region_add_ring(ctx, r, v, n);
}

/* A circle of n vertices, centre (cx, cy), radius rr (inches). */
static int circle(qc_ctx *ctx, qc_region *r, double cx, double cy, double rr, size_t n)
{
    qc_vec2 v[MAXV];
    size_t i;

    for (i = 0; i < n; i++)
        v[i] = P(cx + rr * cos(2 * PI * (double)i / (double)n),
                 cy + rr * sin(2 * PI * (double)i / (double)n));
    return ring(ctx, r, v, n);
}

static int rect(qc_ctx *ctx, qc_region *r, double x0, double y0, double w, double h)
{
    qc_vec2 v[4];
    v[0] = P(x0, y0);
    v[1] = P(x0 + w, y0);
    v[2] = P(x0 + w, y0 + h);
    v[3] = P(x0, y0 + h);
    return ring(ctx, r, v, 4);
}

static int build(qc_ctx *ctx, size_t k, qc_region *r)
{
    qc_vec2 v[MAXV];
    size_t i, n = 0;
    int rc;

    switch (k) {
    case 0: /* 6 in half-square triangle: 90, 45, 45 */
        v[0] = P(0, 0), v[1] = P(6, 0), v[2] = P(0, 6);
        return ring(ctx, r, v, 3);
    case 1: /* flying geese goose, 6 x 3 in: 45, 45, 90 */
        v[0] = P(0, 0), v[1] = P(6, 0), v[2] = P(3, 3);
        return ring(ctx, r, v, 3);
    case 2: /* sawtooth star point, 30 deg apex */
        v[0] = P(0, 0), v[1] = P(3, 0), v[2] = P(1.5, 1.5 / tan(15 * PI / 180));
        return ring(ctx, r, v, 3);
    case 3: /* star point, 45 deg apex */
        v[0] = P(0, 0), v[1] = P(3, 0), v[2] = P(1.5, 1.5 / tan(22.5 * PI / 180));
        return ring(ctx, r, v, 3);
    case 4: /* 5-point star, 8 in across: 36 deg tips */
        for (i = 0; i < 10; i++) {
            double a = PI / 2 + PI * (double)i / 5, rr = i % 2 ? 4 * 0.381966 : 4;
            v[n++] = P(4 + rr * cos(a), 4 + rr * sin(a));
        }
        return ring(ctx, r, v, n);
    case 5: /* LeMoyne star diamond: 45 / 135 deg, 4 in sides */
        v[0] = P(0, 0), v[1] = P(4, 0), v[2] = P(4 + 4 * cos(PI / 4), 4 * sin(PI / 4));
        v[3] = P(4 * cos(PI / 4), 4 * sin(PI / 4));
        return ring(ctx, r, v, 4);
    case 6:
        return rect(ctx, r, 0, 0, 20, 1.5);
    case 7:
        return rect(ctx, r, 0, 0, 30, 0.75);
    case 8: { /* crescent: a 3 in circle less a 2.6 in circle shifted 1.2 in */
        double R = 3, rr = 2.6, c = 1.2, x = (R * R - rr * rr + c * c) / (2 * c);
        double t1 = atan2(sqrt(R * R - x * x), x), p1 = atan2(sqrt(R * R - x * x), x - c);
        for (i = 0; i <= 60; i++) { /* outer arc t1 .. 2 pi - t1 */
            double a = t1 + (2 * PI - 2 * t1) * (double)i / 60;
            v[n++] = P(3 + R * cos(a), 3 + R * sin(a));
        }
        for (i = 59; i >= 1; i--) { /* inner arc back, p1 .. 2 pi - p1 */
            double a = p1 + (2 * PI - 2 * p1) * (double)i / 60;
            v[n++] = P(3 + c + rr * cos(a), 3 + rr * sin(a));
        }
        return ring(ctx, r, v, n);
    }
    case 9: /* ring: 6 in across, 3 in hole */
        rc = circle(ctx, r, 3, 3, 3, 96);
        return rc < 0 ? rc : circle(ctx, r, 3, 3, 1.5, 64);
    case 10: /* 8 in block, two square holes and a round one */
        rc = rect(ctx, r, 0, 0, 8, 8);
        if (rc == QC_OK)
            rc = rect(ctx, r, 1, 1, 2, 2);
        if (rc == QC_OK)
            rc = rect(ctx, r, 5, 1.5, 1.5, 3);
        return rc < 0 ? rc : circle(ctx, r, 3, 6, 1, 48);
    case 11: /* C: 6 in square, a 4 x 2 in notch from the right */
        v[0] = P(0, 0), v[1] = P(6, 0), v[2] = P(6, 2), v[3] = P(2, 2);
        v[4] = P(2, 4), v[5] = P(6, 4), v[6] = P(6, 6), v[7] = P(0, 6);
        return ring(ctx, r, v, 8);
    case 12:
        return qc_region_shape(ctx, "heart:6", IN, r);
    default:
        return QC_EINVAL;
    }
}

int pieced_build(qc_ctx *ctx, size_t k, qc_region *out)
{
    int rc;

    memset(out, 0, sizeof *out);
    rc = build(ctx, k, out);
    if (rc == QC_OK)
        rc = qc_region_normalize(ctx, out);
    if (rc == QC_OK) {
        qc_bbox b = qc_region_bbox(out);
        qc_region_translate(out, -b.min.x, -b.min.y);
    }
    if (rc < 0)
        qc_region_free(ctx, out);
    return rc;
}
