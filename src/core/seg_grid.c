/*
 * Segments binned in a uniform grid (compressed rows), for the "which
 * segments lie near here" questions of echo joins, spirals, ring repair
 * and the self-crossing count: each segment goes into every cell its box
 * meets.
 */
#include <string.h>

#include "internal.h"

static size_t clamp_cell(double v, double lo, double cell, size_t count)
{
    return qc__grid_cell((v - lo) / cell, count);
}

void qc__seg_grid_cells(const qc__seg_grid *g, qc_vec2 a, qc_vec2 b, size_t c[4])
{
    c[0] = clamp_cell(a.x < b.x ? a.x : b.x, g->x0, g->cell, g->gx);
    c[1] = clamp_cell(a.y < b.y ? a.y : b.y, g->y0, g->cell, g->gy);
    c[2] = clamp_cell(a.x > b.x ? a.x : b.x, g->x0, g->cell, g->gx);
    c[3] = clamp_cell(a.y > b.y ? a.y : b.y, g->y0, g->cell, g->gy);
}

/* Pass 0 counts each segment's cells into start[cell + 1], pass 1 fills. */
static void bin(qc__seg_grid *g, const qc_vec2 *p, size_t n, qc__seg_next next, const void *ud,
                int fill)
{
    size_t k, x, y, c[4];

    for (k = 0; k < n; k++) {
        qc__seg_grid_cells(g, p[k], p[next(ud, (uint32_t)k)], c);
        for (y = c[1]; y <= c[3]; y++)
            for (x = c[0]; x <= c[2]; x++) {
                if (fill)
                    g->seg[g->start[y * g->gx + x]++] = (uint32_t)k;
                else
                    g->start[y * g->gx + x + 1]++;
            }
    }
}

int qc__seg_grid_build(qc_ctx *ctx, qc__seg_grid *g, const qc_vec2 *p, size_t n,
                       qc__seg_next next, const void *ud, double cell, double cells_per_seg)
{
    qc_bbox box = qc__points_bbox(p, n);
    size_t ncell, k;

    memset(g, 0, sizeof *g);
    g->cell = qc__fit_cell(box, cell, cells_per_seg * (double)n + 64.0);
    g->x0 = box.min.x;
    g->y0 = box.min.y;
    g->gx = (size_t)((box.max.x - box.min.x) / g->cell) + 1;
    g->gy = (size_t)((box.max.y - box.min.y) / g->cell) + 1;
    ncell = g->gx * g->gy;
    g->start = qc__alloc_array(ctx, ncell + 1, sizeof *g->start);
    if (g->start == NULL)
        return QC_ENOMEM;
    memset(g->start, 0, (ncell + 1) * sizeof *g->start);
    bin(g, p, n, next, ud, 0);
    for (k = 0; k < ncell; k++)
        g->start[k + 1] += g->start[k];
    g->nseg = g->start[ncell] ? g->start[ncell] : 1;
    g->seg = qc__alloc_array(ctx, g->nseg, sizeof *g->seg);
    if (g->seg == NULL) {
        qc__seg_grid_free(ctx, g);
        return QC_ENOMEM;
    }
    bin(g, p, n, next, ud, 1);
    for (k = ncell; k > 0; k--) /* back to starts */
        g->start[k] = g->start[k - 1];
    g->start[0] = 0;
    return QC_OK;
}

void qc__seg_grid_free(qc_ctx *ctx, qc__seg_grid *g)
{
    if (g->start != NULL)
        qc__free(ctx, g->start, (g->gx * g->gy + 1) * sizeof *g->start);
    qc__free(ctx, g->seg, g->seg != NULL ? g->nseg * sizeof *g->seg : 0);
    memset(g, 0, sizeof *g);
}
