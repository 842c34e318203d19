/*
 * qc_region_normalize: validate a region (finite, bounded, no zero-area or
 * crossing rings) and orient its rings by nesting depth.
 */
#include <math.h>
#include <string.h>

#include "region_index.h"

#define MAX_COORD 1e6
/* Edge pairs the crossing check may test: about 64 per edge in the worst
 * cells of a real outline; beyond that the outline is refused. */
#define PAIRS_PER_EDGE 64.0
#define PAIRS_FLOOR 4.0e6

static size_t ring_start(const qc_region *r, size_t k)
{
    return k ? r->ring_end[k - 1] : 0;
}

static int check_finite(qc_ctx *ctx, const qc_region *r)
{
    size_t i;

    for (i = 0; i < r->nv; i++) {
        qc_vec2 p = r->v[i];
        size_t ring = qc__region_ring_of(r, i);
        if (!(fabs(p.x) <= MAX_COORD) || !(fabs(p.y) <= MAX_COORD))
            return qc__fail(ctx, QC_ERANGE,
                            "ring %lu vertex %lu is (%g, %g): coordinates must be finite "
                            "and within %g mm",
                            (unsigned long)ring + 1, (unsigned long)(i - ring_start(r, ring)) + 1,
                            p.x, p.y, MAX_COORD);
    }
    return QC_OK;
}

/* Drops repeated consecutive vertices (and a last equal to the first) in place. */
static int drop_repeats(qc_ctx *ctx, qc_region *r)
{
    size_t k, out = 0, start = 0;

    for (k = 0; k < r->nrings; k++) {
        size_t end = r->ring_end[k], first = out, i;

        for (i = start; i < end; i++) {
            qc_vec2 p = r->v[i];
            if (out > first && p.x == r->v[out - 1].x && p.y == r->v[out - 1].y)
                continue;
            r->v[out++] = p;
        }
        while (out - first > 1 && r->v[out - 1].x == r->v[first].x &&
               r->v[out - 1].y == r->v[first].y)
            out--;
        if (out - first < 3)
            return qc__fail(ctx, QC_EDEGENERATE,
                            "ring %lu has %lu distinct vertices; a ring needs 3",
                            (unsigned long)k + 1, (unsigned long)(out - first));
        start = end;
        r->ring_end[k] = (uint32_t)out;
    }
    r->nv = out;
    return QC_OK;
}

static double ring_area(const qc_region *r, size_t k)
{
    size_t s = ring_start(r, k), e = r->ring_end[k], i, j = e - 1;
    double a = 0.0;

    for (i = s; i < e; j = i++)
        a += (r->v[j].x - r->v[s].x) * (r->v[i].y - r->v[s].y) -
             (r->v[i].x - r->v[s].x) * (r->v[j].y - r->v[s].y);
    return a * 0.5;
}

static int on_segment(qc_vec2 a, qc_vec2 b, qc_vec2 p)
{
    return p.x >= fmin(a.x, b.x) && p.x <= fmax(a.x, b.x) && p.y >= fmin(a.y, b.y) &&
           p.y <= fmax(a.y, b.y);
}

/* Exact: closed segments ab and cd share a point. */
static int segments_meet(qc_vec2 a, qc_vec2 b, qc_vec2 c, qc_vec2 d)
{
    double o1 = qc_orient2d(a, b, c), o2 = qc_orient2d(a, b, d);
    double o3 = qc_orient2d(c, d, a), o4 = qc_orient2d(c, d, b);

    if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0)))
        return 1;
    return (o1 == 0 && on_segment(a, b, c)) || (o2 == 0 && on_segment(a, b, d)) ||
           (o3 == 0 && on_segment(c, d, a)) || (o4 == 0 && on_segment(c, d, b));
}

/* Edges e (a->b) and f (c->d) that share only the vertex b == c meet elsewhere
 * only when they fold back onto each other. */
static int adjacent_fold(qc_vec2 a, qc_vec2 b, qc_vec2 d)
{
    return qc_orient2d(a, b, d) == 0 &&
           (d.x - b.x) * (a.x - b.x) + (d.y - b.y) * (a.y - b.y) > 0;
}

static int report_crossing(qc_ctx *ctx, const qc_region *r, uint32_t e, uint32_t f)
{
    size_t re = qc__region_ring_of(r, e), rf = qc__region_ring_of(r, f);
    qc_vec2 at = r->v[e];

    if (re == rf)
        return qc__fail(ctx, QC_EINTERSECT, "ring %lu crosses itself near (%.3f, %.3f) mm",
                        (unsigned long)re + 1, at.x, at.y);
    return qc__fail(ctx, QC_EINTERSECT, "ring %lu touches or crosses ring %lu near (%.3f, %.3f) mm",
                    (unsigned long)re + 1, (unsigned long)rf + 1, at.x, at.y);
}

/* Every pair of edges sharing a grid cell is tested exactly. */
static int check_crossings(qc_ctx *ctx, const qc_region *r, const qc__rindex *ix)
{
    size_t c, ncell = ix->nx * ix->ny;
    double pairs = 0.0, budget = PAIRS_PER_EDGE * (double)r->nv + PAIRS_FLOOR;

    /* Many long edges crowding the same cells (a comb of thin teeth) would
     * make this quadratic: refuse such outlines in bounded time. */
    for (c = 0; c < ncell; c++) {
        double m = (double)(ix->cell_start[c + 1] - ix->cell_start[c]);
        pairs += m * (m - 1) / 2;
    }
    if (pairs > budget)
        return qc__fail(ctx, QC_ELIMIT,
                        "the outline is too dense to check for crossings (%lu edges, %.3g edge "
                        "pairs sharing cells); simplify it", (unsigned long)r->nv, pairs);
    for (c = 0; c < ncell; c++) {
        size_t i, j, lo = ix->cell_start[c], hi = ix->cell_start[c + 1];
        for (i = lo; i < hi; i++) {
            uint32_t e = ix->cell_edge[i], en = ix->next[e];
            for (j = i + 1; j < hi; j++) {
                uint32_t f = ix->cell_edge[j], fn = ix->next[f];
                int meet;

                if (en == f)
                    meet = adjacent_fold(r->v[e], r->v[en], r->v[fn]);
                else if (fn == e)
                    meet = adjacent_fold(r->v[f], r->v[fn], r->v[en]);
                else
                    meet = segments_meet(r->v[e], r->v[en], r->v[f], r->v[fn]);
                if (meet)
                    return report_crossing(ctx, r, e, f);
            }
        }
    }
    return QC_OK;
}

static void reverse_ring(qc_region *r, size_t k)
{
    size_t i = ring_start(r, k), j = r->ring_end[k] - 1;

    for (; i < j; i++, j--) {
        qc_vec2 t = r->v[i];
        r->v[i] = r->v[j];
        r->v[j] = t;
    }
}

/* Rings do not cross, so the parity of the rings round a ring's first
 * vertex is the parity of the other rings' edges a ray from it crosses:
 * the index's band holds them all. */
static int depth_is_odd(const qc_region *r, const qc__rindex *ix, size_t k)
{
    qc_vec2 p = r->v[ring_start(r, k)];
    size_t lo = ring_start(r, k), hi = r->ring_end[k], b, i;
    int odd = 0;

    b = (size_t)((p.y - ix->box.min.y) / ix->band);
    if (b >= ix->nband)
        b = ix->nband - 1;
    for (i = ix->band_start[b]; i < ix->band_start[b + 1]; i++) {
        uint32_t e = ix->band_edge[i];
        qc_vec2 a = r->v[e], c = r->v[ix->next[e]];

        if (e >= lo && e < hi)
            continue;
        if ((a.y > p.y) != (c.y > p.y) && p.x < a.x + (p.y - a.y) * (c.x - a.x) / (c.y - a.y))
            odd = !odd;
    }
    return odd;
}

/* Every ring's depth is read from the index first: reversing a ring moves
 * its vertices under the index's edge numbers, so later queries would meet
 * stale bands. */
static int orient_rings(qc_ctx *ctx, qc_region *r, const qc__rindex *ix)
{
    unsigned char *flip = qc__alloc(ctx, r->nrings);
    size_t k;

    if (flip == NULL)
        return QC_ENOMEM;
    for (k = 0; k < r->nrings; k++)
        flip[k] = (ring_area(r, k) > 0) != !depth_is_odd(r, ix, k);
    for (k = 0; k < r->nrings; k++)
        if (flip[k])
            reverse_ring(r, k);
    qc__free(ctx, flip, r->nrings);
    return QC_OK;
}

int qc_region_normalize(qc_ctx *ctx, qc_region *r)
{
    qc__rindex ix;
    size_t k;
    int rc;

    if (r == NULL || r->nrings == 0)
        return qc__fail(ctx, QC_EEMPTY, "the region has no outline");
    QC__TRY(check_finite(ctx, r));
    QC__TRY(drop_repeats(ctx, r));
    for (k = 0; k < r->nrings; k++) {
        qc_bbox b = {{0, 0}, {0, 0}};
        size_t i;
        double a = fabs(ring_area(r, k)), size;

        b.min = b.max = r->v[ring_start(r, k)];
        for (i = ring_start(r, k); i < r->ring_end[k]; i++) {
            b.min.x = fmin(b.min.x, r->v[i].x);
            b.min.y = fmin(b.min.y, r->v[i].y);
            b.max.x = fmax(b.max.x, r->v[i].x);
            b.max.y = fmax(b.max.y, r->v[i].y);
        }
        size = fmax(b.max.x - b.min.x, b.max.y - b.min.y);
        if (!(a > 1e-12 * size * size) || a < 1e-12)
            return qc__fail(ctx, QC_EDEGENERATE, "ring %lu has zero area (%g mm^2)",
                            (unsigned long)k + 1, a);
    }
    rc = qc__rindex_build(ctx, r, &ix);
    if (rc < 0)
        return rc;
    rc = check_crossings(ctx, r, &ix);
    if (rc == QC_OK)
        rc = orient_rings(ctx, r, &ix);
    qc__rindex_free(ctx, &ix);
    if (rc < 0)
        return rc;
    return QC_OK;
}
