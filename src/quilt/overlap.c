/*
 * qc_patches_overlap: two patches of a top may share seams and corners but
 * not fabric. Two tests, each within the seam tolerance: an edge of one
 * properly crossing an edge of the other away from both ends (two patches
 * laid across each other), and a point just inside one patch, beside the
 * middle of one of its edges, lying well inside the other (a patch on top
 * of or within another, or two drawn twice).
 */
#include <math.h>

#include "internal.h"
#include "quiltc.h"

#define DEFAULT_TOL 0.05 /* the SVG reader's flattening tolerance */

static size_t ring_start(const qc_region *r, size_t k)
{
    return k ? r->ring_end[k - 1] : 0;
}

static double orient(qc_vec2 a, qc_vec2 b, qc_vec2 c)
{
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

static int boxes_meet(qc_bbox a, qc_bbox b, double tol)
{
    return a.min.x < b.max.x - tol && b.min.x < a.max.x - tol && a.min.y < b.max.y - tol &&
           b.min.y < a.max.y - tol;
}

/* Edges a0a1 and b0b1 cross at one point well away from all four ends. */
static int cross(qc_vec2 a0, qc_vec2 a1, qc_vec2 b0, qc_vec2 b1, double tol2, qc_vec2 *at)
{
    double d0 = orient(b0, b1, a0), d1 = orient(b0, b1, a1);
    double d2 = orient(a0, a1, b0), d3 = orient(a0, a1, b1), t;

    if (!((d0 < 0 && d1 > 0) || (d0 > 0 && d1 < 0)) || !((d2 < 0 && d3 > 0) || (d2 > 0 && d3 < 0)))
        return 0;
    if (qc__seg_dist2(a0, b0, b1) <= tol2 || qc__seg_dist2(a1, b0, b1) <= tol2 ||
        qc__seg_dist2(b0, a0, a1) <= tol2 || qc__seg_dist2(b1, a0, a1) <= tol2)
        return 0;
    t = d0 / (d0 - d1);
    at->x = a0.x + t * (a1.x - a0.x);
    at->y = a0.y + t * (a1.y - a0.y);
    return 1;
}

static int edges_cross(const qc_region *a, const qc_region *b, double tol, qc_vec2 *at)
{
    size_t ka, kb, i, j;

    for (ka = 0; ka < a->nrings; ka++) {
        size_t sa = ring_start(a, ka), ea = a->ring_end[ka], pi = ea - 1;

        for (i = sa; i < ea; pi = i++) {
            qc_bbox e = qc__points_bbox(a->v + pi, 1);

            e.min.x = fmin(e.min.x, a->v[i].x);
            e.min.y = fmin(e.min.y, a->v[i].y);
            e.max.x = fmax(e.max.x, a->v[i].x);
            e.max.y = fmax(e.max.y, a->v[i].y);
            for (kb = 0; kb < b->nrings; kb++) {
                size_t sb = ring_start(b, kb), eb = b->ring_end[kb], pj = eb - 1;

                for (j = sb; j < eb; pj = j++) {
                    qc_vec2 b0 = b->v[pj], b1 = b->v[j];

                    if (fmax(b0.x, b1.x) < e.min.x || fmin(b0.x, b1.x) > e.max.x ||
                        fmax(b0.y, b1.y) < e.min.y || fmin(b0.y, b1.y) > e.max.y)
                        continue;
                    if (cross(a->v[pi], a->v[i], b0, b1, tol * tol, at))
                        return 1;
                }
            }
        }
    }
    return 0;
}

/* A point just inside a, beside the middle of one of its edges (the inside
 * is on the left of every normalized ring), lying well inside b. */
static int inside_point_in(const qc_region *a, const qc_region *b, double tol, qc_vec2 *at)
{
    double step = 10 * tol;
    size_t k, i;

    for (k = 0; k < a->nrings; k++) {
        size_t s = ring_start(a, k), e = a->ring_end[k], j = e - 1;

        for (i = s; i < e; j = i++) {
            qc_vec2 p0 = a->v[j], p1 = a->v[i], m;
            double dx = p1.x - p0.x, dy = p1.y - p0.y, len = qc_hypot(dx, dy);

            if (!(len > 2 * step))
                continue;
            m.x = (p0.x + p1.x) / 2 - dy / len * step;
            m.y = (p0.y + p1.y) / 2 + dx / len * step;
            if (!qc_region_contains(a, m) || qc_region_boundary_distance(a, m) < step / 2)
                continue;
            if (qc_region_contains(b, m) && qc_region_boundary_distance(b, m) > 2 * tol) {
                *at = m;
                return 1;
            }
        }
    }
    return 0;
}

int qc_patches_overlap(const qc_patches *ps, double tol, size_t *a, size_t *b, qc_vec2 *where)
{
    size_t i, j;
    qc_vec2 at = {0, 0};

    if (ps == NULL)
        return 0;
    if (!(tol > 0))
        tol = DEFAULT_TOL;
    for (i = 0; i < ps->n; i++) {
        const qc_region *ri = &ps->p[i].region;
        qc_bbox bi = qc_region_bbox(ri);

        for (j = i + 1; j < ps->n; j++) {
            const qc_region *rj = &ps->p[j].region;

            if (!boxes_meet(bi, qc_region_bbox(rj), tol))
                continue;
            if (edges_cross(ri, rj, tol, &at) || inside_point_in(ri, rj, tol, &at) ||
                inside_point_in(rj, ri, tol, &at)) {
                if (a != NULL)
                    *a = i;
                if (b != NULL)
                    *b = j;
                if (where != NULL)
                    *where = at;
                return 1;
            }
        }
    }
    return 0;
}
