/*
 * Proper self-crossings of a polyline: segments binned in a uniform grid,
 * each candidate pair decided by exact orientation tests and counted only
 * in the first grid cell both bounding boxes share.
 */
#include <math.h>

#include "internal.h"

/* The polyline's segments for the grid: k to k + 1, wrapping when closed;
 * an open polyline's last point is a segment of no length (it crosses
 * nothing) so that every point is in the grid's box. */
typedef struct polyline {
    size_t n;
    int closed;
} polyline;

static uint32_t next_point(const void *ud, uint32_t k)
{
    const polyline *l = ud;

    return k + 1 < l->n ? k + 1 : l->closed ? 0 : k;
}

static int cross_proper(qc_vec2 a, qc_vec2 b, qc_vec2 c, qc_vec2 d)
{
    double o1 = qc_orient2d(a, b, c), o2 = qc_orient2d(a, b, d);
    double o3, o4;

    if (!((o1 > 0.0 && o2 < 0.0) || (o1 < 0.0 && o2 > 0.0)))
        return 0;
    o3 = qc_orient2d(c, d, a);
    o4 = qc_orient2d(c, d, b);
    return (o3 > 0.0 && o4 < 0.0) || (o3 < 0.0 && o4 > 0.0);
}

/* Proper crossings among the segments of cell i, each pair counted in the
 * first cell both their boxes meet. */
static size_t cell_crossings(const qc__seg_grid *g, const qc_vec2 *pts, size_t n, int closed,
                             size_t nseg, size_t i)
{
    size_t b = g->start[i], e = g->start[i + 1], p, q, found = 0;
    size_t cx = i % g->gx, cy = i / g->gx;

    for (p = b; p < e; p++) {
        size_t sa = g->seg[p], ra[4];
        qc_vec2 a0 = pts[sa], a1 = pts[(sa + 1) % n];

        qc__seg_grid_cells(g, a0, a1, ra);
        for (q = p + 1; q < e; q++) {
            size_t sb = g->seg[q], rb[4];
            qc_vec2 b0 = pts[sb], b1 = pts[(sb + 1) % n];
            size_t lo = sa < sb ? sa : sb, hi = sa < sb ? sb : sa;

            if (hi >= nseg || hi == lo + 1 || (closed && lo == 0 && hi == nseg - 1))
                continue; /* neighbours share a vertex */
            qc__seg_grid_cells(g, b0, b1, rb);
            if ((ra[0] > rb[0] ? ra[0] : rb[0]) != cx || (ra[1] > rb[1] ? ra[1] : rb[1]) != cy)
                continue; /* counted in the first common cell */
            if (cross_proper(a0, a1, b0, b1))
                found++;
        }
    }
    return found;
}

int qc_path_self_crossings(qc_ctx *ctx, const qc_vec2 *pts, size_t n, int closed,
                           size_t *count)
{
    qc__seg_grid g;
    polyline line;
    size_t nseg, s, i, found = 0;
    double len = 0.0;

    if (pts == NULL || count == NULL)
        return qc__fail(ctx, QC_EINVAL, "self crossings: pts or count is NULL");
    *count = 0;
    nseg = n < 2 ? 0 : (closed && n > 2 ? n : n - 1);
    if (nseg < 2)
        return QC_OK;
    for (s = 0; s < nseg; s++) {
        qc_vec2 a = pts[s], b = pts[(s + 1) % n];
        len += fabs(b.x - a.x) + fabs(b.y - a.y);
    }
    line.n = n;
    line.closed = nseg == n;
    QC__TRY(qc__seg_grid_build(ctx, &g, pts, n, next_point, &line,
                               fmax(2.0 * len / (double)nseg, 1e-9), 4.0));
    for (i = 0; i < g.gx * g.gy; i++)
        found += cell_crossings(&g, pts, n, closed, nseg, i);
    qc__seg_grid_free(ctx, &g);
    *count = found;
    return QC_OK;
}
