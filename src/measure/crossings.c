/*
 * Proper self-crossings of a polyline: segments binned in a uniform grid,
 * each candidate pair decided by exact orientation tests and counted only
 * in the first grid cell both bounding boxes share.
 */
#include <math.h>
#include <string.h>

#include "internal.h"

#define MAX_CELLS ((size_t)1 << 20)

typedef struct xgrid {
    double x0, y0, cell;
    size_t nx, ny;
    size_t *start; /* nx * ny + 1: CSR over seg */
    uint32_t *seg;
    size_t nseg;
} xgrid;


static void cell_range(const xgrid *g, qc_vec2 a, qc_vec2 b, size_t r[4])
{
    double lx = (qc__lesser(a.x, b.x) - g->x0) / g->cell, hx = (qc__greater(a.x, b.x) - g->x0) / g->cell;
    double ly = (qc__lesser(a.y, b.y) - g->y0) / g->cell, hy = (qc__greater(a.y, b.y) - g->y0) / g->cell;
    double mx = (double)(g->nx - 1), my = (double)(g->ny - 1);

    r[0] = (size_t)qc__lesser(qc__greater(floor(lx), 0.0), mx);
    r[1] = (size_t)qc__lesser(qc__greater(floor(ly), 0.0), my);
    r[2] = (size_t)qc__lesser(qc__greater(floor(hx), 0.0), mx);
    r[3] = (size_t)qc__lesser(qc__greater(floor(hy), 0.0), my);
}

/* Whether the bounding boxes of ab and cd are strictly apart (then the
 * segments cannot cross properly). */
static int apart(qc_vec2 a, qc_vec2 b, qc_vec2 c, qc_vec2 d)
{
    double abx0 = a.x < b.x ? a.x : b.x, abx1 = a.x < b.x ? b.x : a.x;
    double aby0 = a.y < b.y ? a.y : b.y, aby1 = a.y < b.y ? b.y : a.y;
    double cdx0 = c.x < d.x ? c.x : d.x, cdx1 = c.x < d.x ? d.x : c.x;
    double cdy0 = c.y < d.y ? c.y : d.y, cdy1 = c.y < d.y ? d.y : c.y;

    return abx1 < cdx0 || cdx1 < abx0 || aby1 < cdy0 || cdy1 < aby0;
}

/* A zero-length segment crosses nothing properly: not binned, so stitches
 * repeated on one spot cost nothing. */
static int zero_length(const qc_vec2 *pts, size_t n, size_t s)
{
    qc_vec2 a = pts[s], b = pts[(s + 1) % n];

    return a.x == b.x && a.y == b.y;
}

int qc_path_self_crossings(qc_ctx *ctx, const qc_vec2 *pts, size_t n, int closed,
                           size_t *count)
{
    xgrid g;
    size_t nseg, s, i, total = 0, found = 0;
    double len = 0.0, w, h, pairs = 0.0;
    qc_bbox box;
    int rc = QC_OK;

    if (pts == NULL || count == NULL)
        return qc__fail(ctx, QC_EINVAL, "self crossings: pts or count is NULL");
    *count = 0;
    nseg = n < 2 ? 0 : (closed && n > 2 ? n : n - 1);
    if (nseg < 2)
        return QC_OK;
    box = qc__points_bbox(pts, n);
    for (s = 0; s < nseg; s++) {
        qc_vec2 a = pts[s], b = pts[(s + 1) % n];
        len += fabs(b.x - a.x) + fabs(b.y - a.y);
    }
    w = box.max.x - box.min.x;
    h = box.max.y - box.min.y;
    g.cell = fmax(2.0 * len / (double)nseg, 1e-9);
    while (((w / g.cell) + 1.0) * ((h / g.cell) + 1.0) > (double)MAX_CELLS)
        g.cell *= 2.0;
    g.nx = (size_t)(w / g.cell) + 1;
    g.ny = (size_t)(h / g.cell) + 1;
    g.x0 = box.min.x;
    g.y0 = box.min.y;
    g.start = qc__alloc_array(ctx, g.nx * g.ny + 1, sizeof *g.start);
    if (g.start == NULL)
        return QC_ENOMEM;
    memset(g.start, 0, (g.nx * g.ny + 1) * sizeof *g.start);
    for (s = 0; s < nseg; s++) {
        size_t r[4], x, y;
        if (zero_length(pts, n, s))
            continue;
        cell_range(&g, pts[s], pts[(s + 1) % n], r);
        for (y = r[1]; y <= r[3]; y++)
            for (x = r[0]; x <= r[2]; x++)
                g.start[y * g.nx + x + 1]++;
    }
    for (i = 0; i < g.nx * g.ny; i++) {
        double k = (double)g.start[i + 1];
        pairs += k * (k - 1) / 2;
        g.start[i + 1] += g.start[i];
    }
    if (pairs > (double)QC_MAX_CROSSING_PAIRS) {
        rc = qc__fail(ctx, QC_ELIMIT,
                      "self crossings: %.0f segment pairs share grid cells (stitches piled in one "
                      "spot), over the limit of %u",
                      pairs, QC_MAX_CROSSING_PAIRS);
        total = 0;
        g.seg = NULL;
        goto out;
    }
    total = g.start[g.nx * g.ny];
    g.seg = qc__alloc_array(ctx, total ? total : 1, sizeof *g.seg);
    if (g.seg == NULL) {
        rc = QC_ENOMEM;
        goto out;
    }
    for (s = 0; s < nseg; s++) {
        size_t r[4], x, y;
        if (zero_length(pts, n, s))
            continue;
        cell_range(&g, pts[s], pts[(s + 1) % n], r);
        for (y = r[1]; y <= r[3]; y++)
            for (x = r[0]; x <= r[2]; x++)
                g.seg[g.start[y * g.nx + x]++] = (uint32_t)s;
    }
    /* start[c] now ends cell c */
    for (i = 0; i < g.nx * g.ny; i++) {
        size_t b = i ? g.start[i - 1] : 0, e = g.start[i], p, q;
        size_t cx = i % g.nx, cy = i / g.nx;

        for (p = b; p < e; p++) {
            size_t sa = g.seg[p], ra[4];
            qc_vec2 a0 = pts[sa], a1 = pts[(sa + 1) % n];

            cell_range(&g, a0, a1, ra);
            for (q = p + 1; q < e; q++) {
                size_t sb = g.seg[q], rb[4];
                qc_vec2 b0 = pts[sb], b1 = pts[(sb + 1) % n];
                size_t lo = sa < sb ? sa : sb, hi = sa < sb ? sb : sa;

                if (hi == lo + 1 || (closed && lo == 0 && hi == nseg - 1))
                    continue; /* neighbours share a vertex */
                if (apart(a0, a1, b0, b1))
                    continue; /* boxes apart: no crossing, and cell_range is dear */
                cell_range(&g, b0, b1, rb);
                if ((ra[0] > rb[0] ? ra[0] : rb[0]) != cx || (ra[1] > rb[1] ? ra[1] : rb[1]) != cy)
                    continue; /* counted in the first common cell */
                if (qc__segs_cross_proper(a0, a1, b0, b1))
                    found++;
            }
        }
    }
    *count = found;
out:
    qc__free(ctx, g.seg, (total ? total : 1) * sizeof *g.seg);
    qc__free(ctx, g.start, (g.nx * g.ny + 1) * sizeof *g.start);
    return rc;
}
