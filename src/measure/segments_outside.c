/*
 * qc_plan_segments_outside: points inside the region are not enough; a
 * stitched segment between two inside points may cross a gap (between
 * the pieces of a region, or the notch of a concave outline). A segment
 * no boundary edge comes near lies wholly on one side (its midpoint
 * decides); one near the boundary is sampled every tol.
 */
#include <math.h>

#include "internal.h"

static size_t ring_start(const qc_region *r, size_t k)
{
    return k ? r->ring_end[k - 1] : 0;
}

/* Whether segments ab and cd come within tol (bounding boxes first). */
static int near(qc_vec2 a, qc_vec2 b, qc_vec2 c, qc_vec2 d, double tol)
{
    double t2 = tol * tol;
    double o1, o2, o3, o4;

    if (fmax(c.x, d.x) < fmin(a.x, b.x) - tol || fmin(c.x, d.x) > fmax(a.x, b.x) + tol ||
        fmax(c.y, d.y) < fmin(a.y, b.y) - tol || fmin(c.y, d.y) > fmax(a.y, b.y) + tol)
        return 0;
    o1 = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    o2 = (b.x - a.x) * (d.y - a.y) - (b.y - a.y) * (d.x - a.x);
    o3 = (d.x - c.x) * (a.y - c.y) - (d.y - c.y) * (a.x - c.x);
    o4 = (d.x - c.x) * (b.y - c.y) - (d.y - c.y) * (b.x - c.x);
    if (((o1 < 0 && o2 > 0) || (o1 > 0 && o2 < 0)) && ((o3 < 0 && o4 > 0) || (o3 > 0 && o4 < 0)))
        return 1;
    return qc__seg_dist2(c, a, b) <= t2 || qc__seg_dist2(d, a, b) <= t2 ||
           qc__seg_dist2(a, c, d) <= t2 || qc__seg_dist2(b, c, d) <= t2;
}

static int near_boundary(const qc_region *r, qc_vec2 a, qc_vec2 b, double tol)
{
    size_t k, i;

    for (k = 0; k < r->nrings; k++) {
        size_t s = ring_start(r, k), e = r->ring_end[k], j = e - 1;
        for (i = s; i < e; j = i++)
            if (near(a, b, r->v[j], r->v[i], tol))
                return 1;
    }
    return 0;
}

static int outside(const qc_region *r, qc_vec2 q, double tol)
{
    return !qc_region_contains(r, q) && qc_region_boundary_distance(r, q) > tol;
}

/* A point of segment ab more than tol outside r, if any. */
static int leaves(const qc_region *r, qc_vec2 a, qc_vec2 b, double tol, qc_vec2 *at)
{
    double len = qc_hypot(b.x - a.x, b.y - a.y);
    size_t steps, s;

    if (!near_boundary(r, a, b, tol)) {
        at->x = (a.x + b.x) / 2;
        at->y = (a.y + b.y) / 2;
        return !qc_region_contains(r, *at);
    }
    steps = (size_t)fmin(len / tol, 1e7) + 1;
    for (s = 0; s <= steps; s++) {
        double t = (double)s / (double)steps;
        at->x = a.x + t * (b.x - a.x);
        at->y = a.y + t * (b.y - a.y);
        if (outside(r, *at, tol))
            return 1;
    }
    return 0;
}

int qc_plan_segments_outside(const qc_region *r, const qc_plan *plan, double tol,
                             size_t *count, qc_vec2 *first)
{
    size_t i, n = 0;
    qc_vec2 at;

    if (r == NULL || plan == NULL || count == NULL || r->nrings == 0 || !(tol > 0))
        return QC_EINVAL;
    for (i = 1; i < plan->n; i++) {
        if (plan->flags[i] & QC_ST_JUMP)
            continue;
        if (leaves(r, plan->p[i - 1], plan->p[i], tol, &at)) {
            if (n == 0 && first != NULL)
                *first = at;
            n++;
        }
    }
    *count = n;
    return QC_OK;
}
