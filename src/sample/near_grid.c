/*
 * "Is a point of this set within r of p?" for the seeding passes (corner,
 * medial and contour points): a uniform grid of chains over a growing
 * qc_points, so each query looks at the 3 x 3 cells round p.
 */
#include <math.h>
#include <string.h>

#include "sample_internal.h"

#define NEAR_MAX_CELLS 4194304.0 /* 2^22 */

int qc__near_grid_init(qc_ctx *ctx, qc__near_grid *g, qc_bbox box, double cell)
{
    size_t k;

    memset(g, 0, sizeof *g);
    g->x0 = box.min.x;
    g->y0 = box.min.y;
    for (;;) { /* a sparse region's box: coarser cells, not gigabytes */
        double fx = floor((box.max.x - box.min.x) / cell) + 1;
        double fy = floor((box.max.y - box.min.y) / cell) + 1;
        if (fx * fy <= NEAR_MAX_CELLS) {
            g->gx = (size_t)fx;
            g->gy = (size_t)fy;
            break;
        }
        cell *= 1.25;
    }
    g->cell = cell;
    g->head = qc__alloc_array(ctx, g->gx * g->gy, sizeof *g->head);
    if (g->head == NULL)
        return QC_ENOMEM;
    for (k = 0; k < g->gx * g->gy; k++)
        g->head[k] = SIZE_MAX;
    return QC_OK;
}

void qc__near_grid_free(qc_ctx *ctx, qc__near_grid *g)
{
    qc__free(ctx, g->head, g->gx * g->gy * sizeof *g->head);
    qc__free(ctx, g->next, g->cap * sizeof *g->next);
    memset(g, 0, sizeof *g);
}

/* Cell coordinate floor(f) clamped to [0, n): truncation is floor from 1 up
 * (no libm call on the query path). */
static size_t clamp_cell(double f, size_t n)
{
    return f >= 1.0 ? (f < (double)n ? (size_t)f : n - 1) : 0;
}

/* The cell of p, clamped to the grid (points outside the box go to its rim). */
static size_t cell_of(const qc__near_grid *g, qc_vec2 p, size_t *cx, size_t *cy)
{
    *cx = clamp_cell((p.x - g->x0) / g->cell, g->gx);
    *cy = clamp_cell((p.y - g->y0) / g->cell, g->gy);
    return *cy * g->gx + *cx;
}

int qc__near_grid_add(qc_ctx *ctx, qc__near_grid *g, const qc_points *pts, size_t i)
{
    size_t cx, cy, c = cell_of(g, pts->v[i], &cx, &cy);

    if (i >= g->cap) {
        size_t nc = g->cap * 2 + 64;
        size_t *t;

        while (nc <= i)
            nc *= 2;
        t = qc__realloc(ctx, g->next, g->cap * sizeof *t, nc * sizeof *t);
        if (t == NULL)
            return QC_ENOMEM;
        g->next = t;
        g->cap = nc;
    }
    g->next[i] = g->head[c];
    g->head[c] = i;
    return QC_OK;
}

int qc__near_grid_near(const qc__near_grid *g, const qc_points *pts, qc_vec2 p, double r)
{
    size_t cx, cy, x, y;

    cell_of(g, p, &cx, &cy);
    for (y = cy ? cy - 1 : 0; y <= cy + 1 && y < g->gy; y++)
        for (x = cx ? cx - 1 : 0; x <= cx + 1 && x < g->gx; x++) {
            size_t i;
            for (i = g->head[y * g->gx + x]; i != SIZE_MAX; i = g->next[i])
                if (qc_hypot(pts->v[i].x - p.x, pts->v[i].y - p.y) < r)
                    return 1;
        }
    return 0;
}

int qc__points_append_clear(qc_ctx *ctx, qc_points *out, size_t ref0, const qc_points *cand,
                            double r)
{
    qc__near_grid g;
    qc_bbox box;
    size_t i;
    int rc = QC_OK;

    if (ref0 >= out->n || !(r > 0)) {
        for (i = 0; i < cand->n; i++)
            QC__TRY(qc_points_push(ctx, out, cand->v[i]));
        return QC_OK;
    }
    box.min = box.max = out->v[ref0];
    for (i = ref0 + 1; i < out->n; i++) {
        box.min.x = fmin(box.min.x, out->v[i].x);
        box.min.y = fmin(box.min.y, out->v[i].y);
        box.max.x = fmax(box.max.x, out->v[i].x);
        box.max.y = fmax(box.max.y, out->v[i].y);
    }
    QC__TRY(qc__near_grid_init(ctx, &g, box, r));
    for (i = ref0; i < out->n && rc == QC_OK; i++)
        rc = qc__near_grid_add(ctx, &g, out, i);
    for (i = 0; i < cand->n && rc == QC_OK; i++) /* the refs end where the grid's chains do */
        if (!qc__near_grid_near(&g, out, cand->v[i], r))
            rc = qc_points_push(ctx, out, cand->v[i]);
    qc__near_grid_free(ctx, &g);
    return rc;
}

int qc__near_grid_push_clear(qc_ctx *ctx, qc__near_grid *g, qc_points *out,
                             const qc__rindex *ix, qc_vec2 p, double r, double margin)
{
    if (qc__near_grid_near(g, out, p, r) || !qc__rindex_admits(ix, p, margin))
        return QC_OK;
    QC__TRY(qc_points_push(ctx, out, p));
    return qc__near_grid_add(ctx, g, out, out->n - 1);
}
