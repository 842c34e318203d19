/*
 * k nearest neighbours over a uniform grid, for evenly spread points (the
 * samplers' Poisson disks and lattices): about one point per cell, each
 * query scans rings of cells outward until the next ring lies beyond its
 * k-th distance. The same lists as the box tree (knn.c), the k nearest by
 * (squared distance, index), at a third of its cost: the tree scans about
 * 100 points per query for k = 9, the grid about 30. Declines when the
 * points crowd a few cells (clustered inputs: TSPLIB's drilling
 * instances), or when isolated points make the rings too many, and the
 * tree takes over.
 */
#include <string.h>

#include "tour_internal.h"

/* Points per cell on average over the bounding box. */
#define PER_CELL 1
/* Declines when the squared cell counts sum above this many times m: about
 * 1 + PER_CELL for uniform random points, less for Poisson disks. */
#define CROWD_LIMIT (PER_CELL + 2)
/* Gives up when the queries have visited CELL_BUDGET + CELL_BUDGET_K * k
 * cells per point (k = 9 on evenly spread points: about 25). */
#define CELL_BUDGET 16
#define CELL_BUDGET_K 8
/* Cell bounds are widened by this fraction of a cell: a point's cell comes
 * from a rounded product, and a ring is skipped only when surely too far. */
#define CELL_MARGIN 1e-6

typedef struct grid {
    const qc_vec2 *q;
    double x0, y0, h, inv; /* cell (i, j) spans x0 + [i, i+1) h, likewise y */
    uint32_t gx, gy;
    uint32_t *start;  /* gx * gy + 1: cell c holds id[start[c] .. start[c+1]) */
    uint32_t *id;
    size_t visits, budget;
} grid;

static uint32_t cell_of(double v, double lo, double inv, uint32_t cells)
{
    double f = (v - lo) * inv;

    if (!(f > 0.0))
        return 0;
    return f >= (double)(cells - 1) ? cells - 1 : (uint32_t)f;
}

/* The side of a cell: about one point per cell over the bounding box,
 * never so small that a thin box gets more cells than 3m. */
static double cell_side(double w, double ht, size_t m)
{
    double h = sqrt(PER_CELL * w * ht / (double)m), line = (w > ht ? w : ht) / (double)m;

    return h > line ? h : line;
}

/* Lays the points into cells (a counting sort); 1 when they crowd. */
static int build(qc_ctx *ctx, grid *g, size_t m)
{
    const qc_vec2 *q = g->q;
    double x1 = q[0].x, y1 = q[0].y;
    size_t i, cells;
    uint64_t crowd = 0;

    g->x0 = q[0].x, g->y0 = q[0].y;
    for (i = 1; i < m; i++) {
        g->x0 = q[i].x < g->x0 ? q[i].x : g->x0;
        g->y0 = q[i].y < g->y0 ? q[i].y : g->y0;
        x1 = q[i].x > x1 ? q[i].x : x1;
        y1 = q[i].y > y1 ? q[i].y : y1;
    }
    g->h = cell_side(x1 - g->x0, y1 - g->y0, m);
    if (!(g->h > 0.0))
        return 1;
    g->inv = 1.0 / g->h;
    g->gx = (uint32_t)((x1 - g->x0) * g->inv) + 1;
    g->gy = (uint32_t)((y1 - g->y0) * g->inv) + 1;
    cells = (size_t)g->gx * g->gy;
    g->start = qc__alloc_array(ctx, cells + 1, sizeof *g->start);
    g->id = qc__alloc_array(ctx, m, sizeof *g->id);
    if (g->start == NULL || g->id == NULL)
        return qc__fail(ctx, QC_ENOMEM, "tsp: out of memory for a grid of %lu points",
                        (unsigned long)m);
    memset(g->start, 0, (cells + 1) * sizeof *g->start);
    for (i = 0; i < m; i++)
        g->start[(size_t)cell_of(q[i].y, g->y0, g->inv, g->gy) * g->gx +
                 cell_of(q[i].x, g->x0, g->inv, g->gx) + 1]++;
    for (i = 1; i <= cells; i++) {
        crowd += (uint64_t)g->start[i] * g->start[i];
        g->start[i] += g->start[i - 1];
    }
    if (crowd > (uint64_t)CROWD_LIMIT * m)
        return 1;
    for (i = 0; i < m; i++) { /* start[c] runs on to c's end, then is put back */
        size_t c = (size_t)cell_of(q[i].y, g->y0, g->inv, g->gy) * g->gx +
                   cell_of(q[i].x, g->x0, g->inv, g->gx);
        g->id[g->start[c]++] = (uint32_t)i;
    }
    memmove(g->start + 1, g->start, cells * sizeof *g->start);
    g->start[0] = 0;
    return QC_OK;
}

/* The squared distance from a to the cells x0 .. x1 of row y, widened by
 * the margin. */
static double span_d2(const grid *g, qc_vec2 a, uint32_t x0, uint32_t x1, uint32_t y)
{
    double e = CELL_MARGIN * g->h;
    double lx = g->x0 + x0 * g->h - e, hx = g->x0 + (x1 + 1) * g->h + e;
    double ly = g->y0 + y * g->h - e, hy = g->y0 + (y + 1) * g->h + e;
    double dx = a.x < lx ? lx - a.x : a.x > hx ? a.x - hx : 0.0;
    double dy = a.y < ly ? ly - a.y : a.y > hy ? a.y - hy : 0.0;

    return dx * dx + dy * dy;
}

/* Offers the points of cells x0 .. x1 of row y: one run of id, as the
 * cells go row by row. */
static void scan_span(grid *g, qc__knn_best *b, uint32_t self, uint32_t x0, uint32_t x1, uint32_t y)
{
    qc_vec2 a = g->q[self];
    size_t c = (size_t)y * g->gx, i, end = g->start[c + x1 + 1];

    g->visits += x1 - x0 + 1;
    if (b->have == b->k && span_d2(g, a, x0, x1, y) > b->d2[b->k - 1])
        return;
    for (i = g->start[c + x0]; i < end; i++) {
        uint32_t j = g->id[i];
        double dx = g->q[j].x - a.x, dy = g->q[j].y - a.y;

        if (j != self)
            qc__knn_offer(b, dx * dx + dy * dy, j);
    }
}

/* Ring r around (cx, cy): the cells at Chebyshev distance r, clipped. */
static void scan_ring(grid *g, qc__knn_best *b, uint32_t self, uint32_t cx, uint32_t cy, uint32_t r)
{
    long x0 = (long)cx - (long)r, x1 = (long)cx + (long)r;
    long y0 = (long)cy - (long)r, y1 = (long)cy + (long)r, y;
    uint32_t lx = x0 < 0 ? 0 : (uint32_t)x0;
    uint32_t hx = x1 >= (long)g->gx ? g->gx - 1 : (uint32_t)x1;
    long ly = y0 + 1 < 0 ? 0 : y0 + 1, hy = y1 - 1 >= (long)g->gy ? (long)g->gy - 1 : y1 - 1;

    if (y0 >= 0) /* the bottom and top rows whole */
        scan_span(g, b, self, lx, hx, (uint32_t)y0);
    if (r > 0 && y1 < (long)g->gy)
        scan_span(g, b, self, lx, hx, (uint32_t)y1);
    for (y = ly; y <= hy; y++) { /* the sides */
        if (x0 >= 0)
            scan_span(g, b, self, (uint32_t)x0, (uint32_t)x0, (uint32_t)y);
        if (x1 < (long)g->gx)
            scan_span(g, b, self, (uint32_t)x1, (uint32_t)x1, (uint32_t)y);
    }
}

/* The k nearest to point i into out; 1 when the budget ran out. */
static int nearest(grid *g, uint32_t i, unsigned k, uint32_t *out)
{
    qc_vec2 a = g->q[i];
    uint32_t cx = cell_of(a.x, g->x0, g->inv, g->gx), cy = cell_of(a.y, g->y0, g->inv, g->gy);
    uint32_t r, rmax = g->gx > g->gy ? g->gx : g->gy;
    qc__knn_best b;

    b.k = k;
    b.have = 0;
    for (r = 0; r < rmax; r++) {
        /* every cell of ring r is at least r - 1 cells (less the margin) away */
        double lo = r > 1 ? ((double)r - 1.0 - CELL_MARGIN) * g->h : 0.0;

        if (b.have == k && lo * lo > b.d2[k - 1])
            break;
        scan_ring(g, &b, i, cx, cy, r);
        if (g->visits > g->budget)
            return 1;
    }
    memcpy(out, b.id, k * sizeof *out);
    return 0;
}

int qc__knn_grid(qc_ctx *ctx, const qc_vec2 *q, size_t m, unsigned k, uint32_t *nb)
{
    grid g;
    size_t i;
    int rc;

    memset(&g, 0, sizeof g);
    g.q = q;
    g.budget = (CELL_BUDGET + CELL_BUDGET_K * (size_t)k) * m;
    rc = build(ctx, &g, m);
    for (i = 0; i < m && rc == QC_OK; i++)
        rc = nearest(&g, (uint32_t)i, k, nb + i * k);
    if (g.start != NULL)
        qc__free(ctx, g.start, ((size_t)g.gx * g.gy + 1) * sizeof *g.start);
    qc__free(ctx, g.id, m * sizeof *g.id);
    return rc;
}
