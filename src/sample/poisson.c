/*
 * Bridson's Poisson-disk sampling (2007) over a background grid of cell
 * d / sqrt 2 (at most one point per cell). Every empty cell whose centre is
 * admissible seeds a new run, so islands and the far side of holes fill too.
 */
#include <math.h>
#include <string.h>

#include "sample_internal.h"

#define PAD 2 /* empty cells round the grid: is_far's 5x5 block always exists */
#define COVER_SUB 2.0

typedef struct pgrid {
    double x0, y0, cell, d2, reach; /* reach: 2 d and a slack (inner) */
    size_t nx, ny, w; /* cells across and down, and a row's length with the pad */
    qc_vec2 *cells;   /* (nx + 2 PAD) by (ny + 2 PAD), PAD rows and columns first */
    qc_vec2 *at;      /* cell (0, 0); a cell's point, or {HUGE_VAL, HUGE_VAL} when empty */
    qc__cover cover;  /* squares of a COVER_SUB-th of a cell no candidate can take */
} pgrid;

/* The offset from at of cell (cx, cy) of the grid's nx by ny. */
static size_t cell_at(const pgrid *g, size_t cx, size_t cy)
{
    return cy * g->w + cx;
}

static size_t cell_index(const pgrid *g, qc_vec2 p)
{
    size_t cx = (size_t)((p.x - g->x0) / g->cell), cy = (size_t)((p.y - g->y0) / g->cell);
    return cell_at(g, cx < g->nx ? cx : g->nx - 1, cy < g->ny ? cy : g->ny - 1);
}

/* Whether the point q (an empty cell's is infinitely far) is nearer p than d. */
static int near(const pgrid *g, qc_vec2 q, qc_vec2 p)
{
    double dx = q.x - p.x, dy = q.y - p.y;
    return dx * dx + dy * dy < g->d2;
}

/* No point closer than d to p. Cells are d / sqrt 2 wide, so only the 5x5
 * cells round p's can hold one, less the corners (at least d away). The
 * grid has a border of PAD empty cells, so those cells always exist; they
 * hold their point's coordinates, so a cell is tested without a branch on
 * whether it is empty: p's own cell first (the likeliest conflict), the rest
 * of the 3x3 block (a near conflict ends the search), then the ring of 12. */
static int is_far(const pgrid *g, qc_vec2 p)
{
    const qc_vec2 *a = g->at + cell_index(g, p);
    const qc_vec2 *u = a - g->w, *v = a + g->w, *uu = u - g->w, *vv = v + g->w;

    if (near(g, a[0], p))
        return 0;
    if (near(g, a[1], p) | near(g, a[-1], p) | near(g, u[0], p) | near(g, v[0], p) |
        near(g, u[1], p) | near(g, u[-1], p) | near(g, v[1], p) | near(g, v[-1], p))
        return 0;
    return !(near(g, a[2], p) | near(g, a[-2], p) | near(g, uu[0], p) | near(g, vv[0], p) |
             near(g, u[2], p) | near(g, u[-2], p) | near(g, v[2], p) | near(g, v[-2], p) |
             near(g, uu[1], p) | near(g, uu[-1], p) | near(g, vv[1], p) | near(g, vv[-1], p));
}

static int inside_box(const qc__rindex *ix, qc_vec2 p)
{
    return p.x >= ix->box.min.x && p.x <= ix->box.max.x && p.y >= ix->box.min.y &&
           p.y <= ix->box.max.y;
}

/* Whether p may join the sample: in the box, on no marked square (the
 * cheap look that turns most candidates down), d from every point, and
 * admitted by the region at margin. */
static inline int takes(const qc__rindex *ix, const pgrid *g, qc_vec2 p, double margin,
                        int inner)
{
    return (inner || inside_box(ix, p)) && !qc__cover_holds(&g->cover, p) && is_far(g, p) &&
           qc__rindex_admits(ix, p, margin);
}

/* Whether every candidate round c (nearer than 2 d, give or take a slack
 * far above rounding) lies in the box: then takes need not look. */
static int inner(const qc__rindex *ix, const pgrid *g, qc_vec2 c)
{
    return c.x - g->reach > ix->box.min.x && c.x + g->reach < ix->box.max.x &&
           c.y - g->reach > ix->box.min.y && c.y + g->reach < ix->box.max.y;
}

static int add_point(qc_ctx *ctx, pgrid *g, qc_points *pts, qc_order *active, qc_vec2 p)
{
    g->at[cell_index(g, p)] = p;
    qc__cover_mark(&g->cover, p);
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
        int t, placed = 0, in = inner(ix, g, c), rc = QC_OK;
        qc_rng lr = *rng; /* a local copy: its state stays in registers */

        for (t = 0; t < k && !placed; t++) {
            qc_vec2 u = random_direction(&lr), p;
            double r = d * sqrt(1.0 + 3.0 * qc__rng_unit(&lr)); /* area-uniform in [d, 2d) */

            p.x = c.x + r * u.x;
            p.y = c.y + r * u.y;
            if (takes(ix, g, p, margin, in)) {
                rc = add_point(ctx, g, pts, active, p);
                placed = 1;
            }
        }
        *rng = lr;
        QC__TRY(rc);
        if (!placed)
            active->i[at] = active->i[--active->n];
    }
    return QC_OK;
}

/* The grid over the index's box, every cell empty. */
static int pgrid_init(qc_ctx *ctx, pgrid *g, const qc__rindex *ix, double d)
{
    size_t c, total;

    memset(g, 0, sizeof *g);
    g->x0 = ix->box.min.x;
    g->y0 = ix->box.min.y;
    g->cell = d / 1.4142135623730951;
    g->d2 = d * d;
    g->reach = 2.0 * d + 1e-9 * d +
               1e-12 * (fabs(ix->box.min.x) + fabs(ix->box.min.y) + fabs(ix->box.max.x) +
                        fabs(ix->box.max.y));
    g->nx = (size_t)((ix->box.max.x - g->x0) / g->cell) + 1;
    g->ny = (size_t)((ix->box.max.y - g->y0) / g->cell) + 1;
    g->w = g->nx + 2 * PAD;
    total = g->w * (g->ny + 2 * PAD);
    g->cells = qc__alloc_array(ctx, total, sizeof *g->cells);
    if (g->cells == NULL)
        return QC_ENOMEM;
    for (c = 0; c < total; c++)
        g->cells[c] = QC__V2(HUGE_VAL, HUGE_VAL);
    g->at = g->cells + cell_at(g, PAD, PAD);
    if (qc__cover_init(ctx, &g->cover, ix->box, d, g->cell / COVER_SUB) < 0) {
        qc__free(ctx, g->cells, total * sizeof *g->cells);
        return QC_ENOMEM;
    }
    return QC_OK;
}

static void pgrid_free(qc_ctx *ctx, pgrid *g)
{
    qc__cover_free(ctx, &g->cover);
    qc__free(ctx, g->cells, g->w * (g->ny + 2 * PAD) * sizeof *g->cells);
}

int qc__sample_poisson(qc_ctx *ctx, const qc__rindex *ix, double d, double margin,
                       uint64_t seed, int k, qc_points *out)
{
    pgrid g;
    qc_order active = {0};
    qc_points pts = {0};
    qc_rng rng;
    size_t cx, cy, i;
    int rc;

    QC__TRY(pgrid_init(ctx, &g, ix, d));
    qc_rng_seed(&rng, seed);
    /* every empty cell whose centre is admissible seeds a run, row by row */
    for (cy = 0, rc = QC_OK; cy < g.ny && rc == QC_OK; cy++)
        for (cx = 0; cx < g.nx && rc == QC_OK; cx++) {
            qc_vec2 p;
            if (g.at[cell_at(&g, cx, cy)].x != HUGE_VAL)
                continue;
            p.x = g.x0 + ((double)cx + 0.5) * g.cell;
            p.y = g.y0 + ((double)cy + 0.5) * g.cell;
            if (takes(ix, &g, p, margin, 0)) {
                rc = add_point(ctx, &g, &pts, &active, p);
                if (rc == QC_OK)
                    rc = grow(ctx, ix, &g, d, margin, k, &rng, &pts, &active);
            }
        }
    for (i = 0; i < pts.n && rc == QC_OK; i++)
        rc = qc_points_push(ctx, out, pts.v[i]);
    qc_points_free(ctx, &pts);
    qc_order_free(ctx, &active);
    pgrid_free(ctx, &g);
    return rc;
}
