/*
 * Every point of the path inside the region's box, control points too,
 * where the curve itself is: a curve lies in the hull of its control
 * points, so whoever checks the points alone (`quiltc job`'s guard, a
 * viewer sizing its page) sees the block's box. Keeping inside
 * (src/curve/keep_inside.c) leaves a cubic's control point past the seam
 * when the curve is inside (a leaf or a pebble along the seam), and an end
 * point astray by up to its tolerance. A curve that strays further (a
 * family at margin 0) is left for the guards to refuse.
 */
#include <math.h>

#include "pattern_internal.h"
#include "../curve/keep_inside.h"

/* Whether v lies in [lo - tol, hi + tol]. */
static int near_range(double v, double lo, double hi)
{
    return v >= lo - QC__INSIDE_TOL_MM && v <= hi + QC__INSIDE_TOL_MM;
}

static double clamp(double v, double lo, double hi)
{
    return v < lo ? lo : (v > hi ? hi : v);
}

/* The cubic a, b, c, d (one axis) at t. */
static double cubic_at(double a, double b, double c, double d, double t)
{
    double u = 1.0 - t;
    return u * u * u * a + 3.0 * u * u * t * b + 3.0 * u * t * t * c + t * t * t * d;
}

/* Whether the cubic a, b, c, d (one axis) stays within tol of [lo, hi]: its
 * ends and its turning points (the roots of its derivative in (0, 1)). */
static int cubic_near(double a, double b, double c, double d, double lo, double hi)
{
    double qa = -a + 3.0 * b - 3.0 * c + d, qb = 2.0 * (a - 2.0 * b + c), qc = b - a;
    double t[2];
    int n = 0, k;

    if (!near_range(a, lo, hi) || !near_range(d, lo, hi))
        return 0;
    if (qa > -1e-12 && qa < 1e-12) { /* the derivative is linear */
        if (qb != 0.0)
            t[n++] = -qc / qb;
    } else {
        double disc = qb * qb - 4.0 * qa * qc;
        if (disc >= 0.0) {
            double r = sqrt(disc);
            t[n++] = (-qb - r) / (2.0 * qa);
            t[n++] = (-qb + r) / (2.0 * qa);
        }
    }
    for (k = 0; k < n; k++)
        if (t[k] > 0.0 && t[k] < 1.0 && !near_range(cubic_at(a, b, c, d, t[k]), lo, hi))
            return 0;
    return 1;
}

/* The largest share s <= 1 of the way from a (inside) towards c that stays
 * in [lo, hi]. */
static double reach(double a, double c, double lo, double hi)
{
    if (c < lo)
        return a > lo ? (a - lo) / (a - c) : 0.0;
    if (c > hi)
        return a < hi ? (hi - a) / (c - a) : 0.0;
    return 1.0;
}

/* Control point c of end a pulled towards a until inside b: its tangent
 * keeps its direction, so the curve stays smooth. */
static qc_vec2 pull(qc_vec2 a, qc_vec2 c, qc_bbox b)
{
    double sx = reach(a.x, c.x, b.min.x, b.max.x), sy = reach(a.y, c.y, b.min.y, b.max.y);
    double s = sx < sy ? sx : sy;

    if (s >= 1.0)
        return c;
    c.x = clamp(a.x + (c.x - a.x) * s, b.min.x, b.max.x); /* clamp: the last rounding */
    c.y = clamp(a.y + (c.y - a.y) * s, b.min.y, b.max.y);
    return c;
}

void qc__path_hull_in_box(qc_path *path, qc_bbox box)
{
    size_t k, at = 0;

    for (k = 0; k < path->ncmd; k++) { /* ends astray by the tolerance at most */
        qc_vec2 *p;
        at += qc_path_cmd_points(path->cmd[k]);
        p = &path->pt[at - 1];
        if (near_range(p->x, box.min.x, box.max.x) && near_range(p->y, box.min.y, box.max.y)) {
            p->x = clamp(p->x, box.min.x, box.max.x);
            p->y = clamp(p->y, box.min.y, box.max.y);
        }
    }
    at = 0;
    for (k = 0; k < path->ncmd; k++) {
        if (path->cmd[k] == QC_PATH_CUBIC && at > 0) {
            qc_vec2 *q = &path->pt[at - 1]; /* start, control 1, control 2, end */
            if (cubic_near(q[0].x, q[1].x, q[2].x, q[3].x, box.min.x, box.max.x) &&
                cubic_near(q[0].y, q[1].y, q[2].y, q[3].y, box.min.y, box.max.y)) {
                q[1] = pull(q[0], q[1], box);
                q[2] = pull(q[3], q[2], box);
            }
        }
        at += qc_path_cmd_points(path->cmd[k]);
    }
}
