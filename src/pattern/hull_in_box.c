/*
 * Every point of the path inside the region's box, control points too: a
 * curve lies in the hull of its control points, so a path whose points
 * all do stays in the box, and whoever checks the points alone (`quiltc
 * job`'s guard, a viewer sizing its page) sees the block's box. Keeping
 * inside (src/curve/keep_inside.c) lets a cubic's control point lie past
 * the seam when the curve itself is inside (a leaf or a pebble along the
 * seam), and an end point stray by its tolerance.
 */
#include "pattern_internal.h"

static qc_vec2 clamp_point(qc_vec2 p, qc_bbox b)
{
    p.x = p.x < b.min.x ? b.min.x : (p.x > b.max.x ? b.max.x : p.x);
    p.y = p.y < b.min.y ? b.min.y : (p.y > b.max.y ? b.max.y : p.y);
    return p;
}

/* The largest share t <= 1 of the way from a (inside b) towards c that
 * stays in b along one axis. */
static double reach(double a, double c, double lo, double hi)
{
    if (c < lo)
        return (a - lo) / (a - c);
    if (c > hi)
        return (hi - a) / (c - a);
    return 1.0;
}

/* Control point c of end a pulled towards a until inside b: its tangent
 * keeps its direction, so the curve stays smooth. */
static qc_vec2 pull(qc_vec2 a, qc_vec2 c, qc_bbox b)
{
    double tx = reach(a.x, c.x, b.min.x, b.max.x), ty = reach(a.y, c.y, b.min.y, b.max.y);
    double t = tx < ty ? tx : ty;

    if (t >= 1.0)
        return c;
    t = t > 0.0 ? t : 0.0;
    c.x = a.x + (c.x - a.x) * t;
    c.y = a.y + (c.y - a.y) * t;
    return clamp_point(c, b); /* the last rounding */
}

void qc__path_hull_in_box(qc_path *path, qc_bbox box)
{
    size_t k, at = 0;

    for (k = 0; k < path->ncmd; k++) { /* the points on the curve first */
        at += qc_path_cmd_points(path->cmd[k]);
        path->pt[at - 1] = clamp_point(path->pt[at - 1], box);
    }
    at = 0;
    for (k = 0; k < path->ncmd; k++) {
        if (path->cmd[k] == QC_PATH_CUBIC && at > 0) {
            path->pt[at] = pull(path->pt[at - 1], path->pt[at], box);
            path->pt[at + 1] = pull(path->pt[at + 2], path->pt[at + 1], box);
        }
        at += qc_path_cmd_points(path->cmd[k]);
    }
}
