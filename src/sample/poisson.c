/*
 * Bridson's Poisson-disk sampling (2007) over a background grid of cell
 * d / sqrt 2 (at most one point per cell). Every empty cell whose centre is
 * admissible seeds a new run, so islands and the far side of holes fill too.
 */
#include <math.h>
#include <string.h>

#include "sample_internal.h"

typedef struct pgrid {
    double x0, y0, cell, d2;
    size_t nx, ny;
    qc_vec2 *at; /* the cell's point, or {HUGE_VAL, HUGE_VAL} when empty */
} pgrid;

static size_t cell_index(const pgrid *g, qc_vec2 p)
{
    size_t cx = (size_t)((p.x - g->x0) / g->cell), cy = (size_t)((p.y - g->y0) / g->cell);
    return (cy < g->ny ? cy : g->ny - 1) * g->nx + (cx < g->nx ? cx : g->nx - 1);
}

static int is_empty(const pgrid *g, size_t c)
{
    return g->at[c].x == HUGE_VAL;
}

/* Whether the point q (an empty cell's is infinitely far) is nearer p than d. */
static int near(const pgrid *g, qc_vec2 q, qc_vec2 p)
{
    double dx = q.x - p.x, dy = q.y - p.y;
    return dx * dx + dy * dy < g->d2;
}

/* No point closer than d to p. Cells are d / sqrt 2 wide, so only the 5x5
 * cells round p's can hold one, less the corners (at least d away). The
 * cells hold their point's coordinates, so a cell is tested without a
 * branch on whether it is empty: p's own cell first (the likeliest
 * conflict), the rest of the 3x3 block (a near conflict ends the search),
 * then the ring of 12; written out, the offsets constant. */
static int is_far(const pgrid *g, qc_vec2 p)
{
    static const signed char off[21][2] = {
        {0, 0},   {1, 0},   {-1, 0}, {0, 1},  {0, -1}, {1, 1},   {-1, 1},
        {1, -1},  {-1, -1}, {2, 0},  {-2, 0}, {0, 2},  {0, -2},  {2, 1},
        {2, -1},  {-2, 1},  {-2, -1}, {1, 2}, {-1, 2}, {1, -2},  {-1, -2}};
    long cx = (long)((p.x - g->x0) / g->cell), cy = (long)((p.y - g->y0) / g->cell);
    size_t i;

    if (cx >= 2 && cy >= 2 && cx + 2 < (long)g->nx && cy + 2 < (long)g->ny) {
        /* away from the grid's sides: the same cells, no bounds to check */
        const qc_vec2 *a = g->at + (size_t)cy * g->nx + (size_t)cx;
        const qc_vec2 *u = a - g->nx, *v = a + g->nx, *uu = u - g->nx, *vv = v + g->nx;
        if (near(g, a[0], p))
            return 0;
        if (near(g, a[1], p) | near(g, a[-1], p) | near(g, u[0], p) | near(g, v[0], p) |
            near(g, u[1], p) | near(g, u[-1], p) | near(g, v[1], p) | near(g, v[-1], p))
            return 0;
        return !(near(g, a[2], p) | near(g, a[-2], p) | near(g, uu[0], p) |
                 near(g, vv[0], p) | near(g, u[2], p) | near(g, u[-2], p) |
                 near(g, v[2], p) | near(g, v[-2], p) | near(g, uu[1], p) |
                 near(g, uu[-1], p) | near(g, vv[1], p) | near(g, vv[-1], p));
    }
    for (i = 0; i < 21; i++) {
        long x = cx + off[i][0], y = cy + off[i][1];
        if (x < 0 || y < 0 || x >= (long)g->nx || y >= (long)g->ny)
            continue;
        if (near(g, g->at[(size_t)y * g->nx + (size_t)x], p))
            return 0;
    }
    return 1;
}

static int inside_box(const qc__rindex *ix, qc_vec2 p)
{
    return p.x >= ix->box.min.x && p.x <= ix->box.max.x && p.y >= ix->box.min.y &&
           p.y <= ix->box.max.y;
}

static int add_point(qc_ctx *ctx, pgrid *g, qc_points *pts, qc_order *active, qc_vec2 p)
{
    g->at[cell_index(g, p)] = p;
    QC__TRY(qc_order_push(ctx, active, (uint32_t)pts->n));
    return qc_points_push(ctx, pts, p);
}

/* A uniformly random unit vector: a point of the unit disk by rejection,
 * normalised (no sine or cosine: a third of the sampler's time). */
static qc_vec2 random_direction(qc_rng *rng)
{
    qc_vec2 u;
    double s, k;

    do {
        u.x = 2.0 * qc__rng_unit(rng) - 1.0;
        u.y = 2.0 * qc__rng_unit(rng) - 1.0;
        s = u.x * u.x + u.y * u.y;
    } while (s > 1.0 || s < 1e-6);
    k = 1.0 / sqrt(s);
    u.x *= k;
    u.y *= k;
    return u;
}

/* Grows the sample from the active list until it empties. */
static int grow(qc_ctx *ctx, const qc__rindex *ix, pgrid *g, double d, double margin, int k,
                qc_rng *rng, qc_points *pts, qc_order *active)
{
    while (active->n > 0) {
        size_t at = (size_t)qc_rng_below(rng, active->n);
        qc_vec2 c = pts->v[active->i[at]];
        int t, placed = 0;

        for (t = 0; t < k && !placed; t++) {
            qc_vec2 u = random_direction(rng), p;
            double r = d * sqrt(1.0 + 3.0 * qc__rng_unit(rng)); /* area-uniform in [d, 2d) */

            p.x = c.x + r * u.x;
            p.y = c.y + r * u.y;
            if (inside_box(ix, p) && is_far(g, p) && qc__rindex_admits(ix, p, margin)) {
                QC__TRY(add_point(ctx, g, pts, active, p));
                placed = 1;
            }
        }
        if (!placed)
            active->i[at] = active->i[--active->n];
    }
    return QC_OK;
}

int qc__sample_poisson(qc_ctx *ctx, const qc__rindex *ix, double d, double margin,
                       uint64_t seed, int k, qc_points *out)
{
    pgrid g;
    qc_order active = {0};
    qc_points pts = {0};
    qc_rng rng;
    size_t c, i;
    int rc = QC_OK;

    memset(&g, 0, sizeof g);
    g.x0 = ix->box.min.x;
    g.y0 = ix->box.min.y;
    g.cell = d / 1.4142135623730951;
    g.d2 = d * d;
    g.nx = (size_t)((ix->box.max.x - g.x0) / g.cell) + 1;
    g.ny = (size_t)((ix->box.max.y - g.y0) / g.cell) + 1;
    g.at = qc__alloc_array(ctx, g.nx * g.ny, sizeof *g.at);
    if (g.at == NULL)
        return QC_ENOMEM;
    for (c = 0; c < g.nx * g.ny; c++)
        g.at[c] = QC__V2(HUGE_VAL, HUGE_VAL);
    qc_rng_seed(&rng, seed);
    for (c = 0; c < g.nx * g.ny && rc == QC_OK; c++) {
        qc_vec2 p;
        if (!is_empty(&g, c))
            continue;
        p.x = g.x0 + ((double)(c % g.nx) + 0.5) * g.cell;
        p.y = g.y0 + ((double)(c / g.nx) + 0.5) * g.cell;
        if (inside_box(ix, p) && is_far(&g, p) && qc__rindex_admits(ix, p, margin)) {
            rc = add_point(ctx, &g, &pts, &active, p);
            if (rc == QC_OK)
                rc = grow(ctx, ix, &g, d, margin, k, &rng, &pts, &active);
        }
    }
    for (i = 0; i < pts.n && rc == QC_OK; i++)
        rc = qc_points_push(ctx, out, pts.v[i]);
    qc_points_free(ctx, &pts);
    qc_order_free(ctx, &active);
    qc__free(ctx, g.at, g.nx * g.ny * sizeof *g.at);
    return rc;
}
