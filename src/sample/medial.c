/*
 * Seeds on the medial axis: a lattice or Poisson fill stops a spacing or
 * more short of a star point and can miss a narrow strip altogether. The
 * ridge of the boundary distance runs down every strip and into every
 * corner along its bisector, so points are added on it, the ones deepest
 * in a corner first (where the margin is just kept from both seams: the
 * floor a margin allows), wherever no point lies within SEED_GAP * d.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sample_internal.h"
#include "../measure/measure_internal.h"

#define CELLS_PER_D 4.0 /* raster: d / 4 */
#define SEED_GAP 0.8    /* no seed nearer an existing point than this * d */
#define CORNER_MAX 150.0 /* corners sharper than this, degrees, get a point */
#define CORNER_GAP 0.6   /* a corner point drops fill points nearer than this * d */
#define CORNER_SLACK 1.01 /* just inside the margin, for the admission test */
#define CORNER_TRIES 80   /* steps down the bisector looking for room */
#define CORNER_TRY_STEP 0.05 /* times d */
#define CORNER_REACH 3.0  /* else the nearest room within this * d of the tip */
#define CORNER_SCAN 8.0   /* on a d / 8 lattice */
#define CORNER_SCANS 64   /* tips scanned so, at most (a serrated outline has thousands) */

typedef struct ridge {
    float f; /* squared boundary distance, cells */
    uint32_t at;
} ridge;

static int cmp_ridge(const void *pa, const void *pb)
{
    const ridge *a = pa, *b = pb;

    if (a->f != b->f)
        return a->f < b->f ? -1 : 1;
    return (a->at > b->at) - (a->at < b->at);
}

/* Whether the cells at offsets -o and +o of c are both inside, and c is no
 * lower than either and strictly above one (the heights compared first:
 * most cells are on a slope; floats compare as the doubles they widen to). */
static inline int ridge_across(const float *f, const unsigned char *mask, size_t c, size_t o)
{
    float v = f[c], a = f[c + o], b = f[c - o];

    return v >= a && v >= b && (v > a || v > b) && mask[c + o] && mask[c - o];
}

/* Whether cell k is a ridge: no lower than both neighbours across it in
 * some direction, and strictly above one of them. */
static int is_ridge(const qc__gap_grid *g, const unsigned char *mask, size_t i, size_t j)
{
    static const int dx[4] = {1, 0, 1, 1}, dy[4] = {0, 1, 1, -1};
    double c = (double)g->f[j * g->nx + i];
    int k;

    if (i > 0 && j > 0 && i + 1 < g->nx && j + 1 < g->ny) {
        /* inside the raster's border: every neighbour exists */
        size_t at = j * g->nx + i, w = g->nx;
        return ridge_across(g->f, mask, at, 1) || ridge_across(g->f, mask, at, w) ||
               ridge_across(g->f, mask, at, w + 1) || ridge_across(g->f, mask, at, w - 1);
    }
    for (k = 0; k < 4; k++) {
        long ax = (long)i + dx[k], ay = (long)j + dy[k], bx = (long)i - dx[k], by = (long)j - dy[k];
        double a, b;
        if (ax < 0 || ay < 0 || bx < 0 || by < 0 || ax >= (long)g->nx || bx >= (long)g->nx ||
            ay >= (long)g->ny || by >= (long)g->ny)
            continue;
        if (!mask[ay * (long)g->nx + ax] || !mask[by * (long)g->nx + bx])
            continue;
        a = (double)g->f[ay * (long)g->nx + ax];
        b = (double)g->f[by * (long)g->nx + bx];
        if (c >= a && c >= b && (c > a || c > b))
            return 1;
    }
    return 0;
}

/* The point nearest v (on a d / 8 lattice within CORNER_REACH * d) that
 * keeps the margin: where the bisector leaves a tip that curves away from
 * it (a crescent's horn). 0 when there is none. */
static int nearest_room(const qc__rindex *ix, qc_vec2 v, double d, double margin, qc_vec2 *at)
{
    long n = (long)(CORNER_REACH * CORNER_SCAN), i, j;
    double h = d / CORNER_SCAN, best = HUGE_VAL;

    for (j = -n; j <= n; j++)
        for (i = -n; i <= n; i++) {
            qc_vec2 p = QC__V2(v.x + (double)i * h, v.y + (double)j * h);
            double r = qc_hypot(p.x - v.x, p.y - v.y);
            if (r < best && qc__rindex_admits(ix, p, margin)) {
                best = r;
                *at = p;
            }
        }
    return best < HUGE_VAL;
}

/* A point on each convex corner's bisector where the margin is just kept
 * from both seams (m / sin(theta / 2) from the corner), the points of out
 * nearer than CORNER_GAP * d to it dropped: the fill's nearest point can lie
 * 1.5 d or more from a corner, and the floor point is what a margin allows. */
static int corner_seeds(qc_ctx *ctx, const qc_region *region, const qc__rindex *ix, double d,
                        double margin, qc_points *out)
{
    size_t q, rs = 0, i, k, w, scans = 0;

    for (q = 0; q < region->nrings; q++) {
        size_t end = region->ring_end[q];
        for (i = rs; i < end; i++) {
            qc_vec2 pv = region->v[i == rs ? end - 1 : i - 1], v = region->v[i];
            qc_vec2 nx = region->v[i + 1 == end ? rs : i + 1], c;
            double th = qc_region_corner_angle(region, i) * (QC_PI / 180.0);
            double l1 = qc_hypot(v.x - pv.x, v.y - pv.y), l2 = qc_hypot(nx.x - v.x, nx.y - v.y);
            double bx, by, bl, far;

            if (!(th < CORNER_MAX * (QC_PI / 180.0)) || !(l1 > 0) || !(l2 > 0))
                continue;
            /* the bisector points inside: the sum of the unit vectors along both edges */
            bx = (pv.x - v.x) / l1 + (nx.x - v.x) / l2;
            by = (pv.y - v.y) / l1 + (nx.y - v.y) / l2;
            bl = qc_hypot(bx, by);
            if (!(bl > 1e-12))
                continue;
            far = CORNER_SLACK * fmax(margin, 1e-3) / qc_sin(0.5 * th);
            c = QC__V2(v.x + far * bx / bl, v.y + far * by / bl);
            /* flanks that curve in (a heart's cusp) leave the floor point
             * too near a seam, or beyond the shape: the first point down
             * the bisector that keeps the margin */
            far = CORNER_SLACK * fmax(margin, 1e-3);
            for (k = 0; !qc__rindex_admits(ix, c, margin) && k < CORNER_TRIES; k++) {
                c = QC__V2(v.x + far * bx / bl, v.y + far * by / bl);
                far += CORNER_TRY_STEP * d;
            }
            if (!qc__rindex_admits(ix, c, margin) &&
                (scans++ >= CORNER_SCANS || !nearest_room(ix, v, d, margin, &c)))
                continue;
            for (k = w = 0; k < out->n; k++) /* drop the points crowding it */
                if (qc_hypot(out->v[k].x - c.x, out->v[k].y - c.y) >= CORNER_GAP * d)
                    out->v[w++] = out->v[k];
            out->n = w;
            QC__TRY(qc_points_push(ctx, out, c));
        }
        rs = end;
    }
    return QC_OK;
}

/* The cells whose centre lies nearer than SEED_GAP * d (less a slack far
 * above rounding) to a point of pts get 1 in blocked: no seed can go there,
 * whatever is added meanwhile (points are only ever added). */
static void block_near(const qc__gap_grid *g, const qc_points *pts, double d,
                       unsigned char *blocked)
{
    double slack = 1e-9 * d + 1e-12 * (fabs(g->x0) + fabs(g->y0) + (double)g->nx * g->h +
                                       (double)g->ny * g->h);
    double reach = SEED_GAP * d - slack, r2 = reach * reach;
    size_t n;

    if (!(reach > 0.0))
        return;
    for (n = 0; n < pts->n; n++) {
        qc_vec2 q = pts->v[n];
        long j = qc__ceil_from0((q.y - reach - g->y0) / g->h - 0.5);
        long jend = qc__floor_below((q.y + reach - g->y0) / g->h - 0.5, g->ny);

        for (; j <= jend; j++) {
            double dy = g->y0 + ((double)j + 0.5) * g->h - q.y, rest = r2 - dy * dy, r;
            long i0, i1;
            if (!(rest > 0.0))
                continue;
            r = sqrt(rest);
            i0 = qc__ceil_from0((q.x - r - g->x0) / g->h - 0.5);
            i1 = qc__floor_below((q.x + r - g->x0) / g->h - 0.5, g->nx);
            if (i0 <= i1)
                memset(blocked + (size_t)j * g->nx + (size_t)i0, 1, (size_t)(i1 - i0 + 1));
        }
    }
}

/* The next free cell (a 0 in shut: inside, no point near) from k on, or
 * cells: memchr skips the shut raster far faster than a loop. */
static size_t next_free(const unsigned char *shut, size_t k, size_t cells)
{
    const unsigned char *at = k < cells ? memchr(shut + k, 0, cells - k) : NULL;

    return at != NULL ? (size_t)(at - shut) : cells;
}

/* Flags in rows (ny bytes) the rows holding a free cell (0 in shut), and
 * the rows either side (is_ridge reads them): the rows whose distances
 * find_ridges reads. Returns whether any is flagged. */
static int mark_rows(const qc__gap_grid *g, const unsigned char *shut, unsigned char *rows)
{
    size_t j, cells = g->nx * g->ny, k;
    int any = 0;

    memset(rows, 0, g->ny);
    for (k = next_free(shut, 0, cells); k < cells; k = next_free(shut, (j + 1) * g->nx, cells)) {
        j = k / g->nx;
        rows[j] = 1;
        rows[j > 0 ? j - 1 : j] = 1;
        rows[j + 1 < g->ny ? j + 1 : j] = 1;
        any = 1;
    }
    return any;
}

/* Marks in mask (2) the ridge cells among the free ones (0 in shut), their
 * count to *nr (every other ridge cell lies within SEED_GAP * d of a
 * point, so would get no seed: not tested). */
static void find_ridges(const qc__gap_grid *g, unsigned char *mask, const unsigned char *shut,
                        size_t *nr)
{
    size_t k, cells = g->nx * g->ny;

    *nr = 0;
    for (k = next_free(shut, 0, cells); k < cells; k = next_free(shut, k + 1, cells))
        if (is_ridge(g, mask, k % g->nx, k / g->nx)) {
            mask[k] |= 2;
            (*nr)++;
        }
}

int qc__sample_medial(qc_ctx *ctx, const qc_region *region, double d, double margin,
                      qc_points *out)
{
    qc__rindex ix;
    int rc;

    QC__TRY(qc__rindex_build(ctx, region, &ix));
    rc = qc__sample_medial_ix(ctx, region, &ix, d, margin, out);
    qc__rindex_free(ctx, &ix);
    return rc;
}

int qc__sample_medial_ix(qc_ctx *ctx, const qc_region *region, const qc__rindex *ix, double d,
                         double margin, qc_points *out)
{
    qc__gap_grid g;
    qc__near_grid ng;
    unsigned char *mask = NULL, *blocked = NULL;
    ridge *rg = NULL;
    size_t cells, k, nr = 0, i;
    qc_bbox box = qc_region_bbox(region);
    int rc;

    memset(&ng, 0, sizeof ng);
    rc = qc__gap_grid_inside(ctx, region, d / CELLS_PER_D, &g, &mask);
    cells = g.nx * g.ny;
    if (rc < 0)
        goto out;
    qc__gap_seed_region(&g, region);
    /* blocked: the cells, then a flag per row */
    if ((blocked = qc__alloc(ctx, cells + g.ny)) == NULL)
        rc = QC_ENOMEM;
    if (rc == QC_OK) /* first: the ridge cells near its points get no seed */
        rc = corner_seeds(ctx, region, ix, d, margin, out);
    if (rc < 0)
        goto out;
    for (k = 0; k < cells; k++) /* shut: outside, or (block_near) a point near */
        blocked[k] = !mask[k];
    block_near(&g, out, d, blocked);
    /* the distances only in the rows find_ridges reads: round free cells */
    if (mark_rows(&g, blocked, blocked + cells) &&
        (rc = qc__gap_transform_far(ctx, &g, blocked + cells)) < 0)
        goto out;
    find_ridges(&g, mask, blocked, &nr);
    rg = qc__alloc_array(ctx, nr ? nr : 1, sizeof *rg);
    if (rg == NULL) {
        rc = QC_ENOMEM;
        goto out;
    }
    nr = 0;
    for (k = next_free(blocked, 0, cells); k < cells; k = next_free(blocked, k + 1, cells))
        if (mask[k] & 2) {
            rg[nr].f = g.f[k];
            rg[nr].at = (uint32_t)k;
            nr++;
        }
    qsort(rg, nr, sizeof *rg, cmp_ridge); /* deepest in a corner first */
    rc = qc__near_grid_init(ctx, &ng, box, d);
    for (i = 0; i < out->n && rc == QC_OK; i++)
        rc = qc__near_grid_add(ctx, &ng, out, i);
    for (k = 0; k < nr && rc == QC_OK; k++) {
        rc = qc__near_grid_push_clear(ctx, &ng, out, ix, qc__gap_grid_centre(&g, rg[k].at),
                                      SEED_GAP * d, margin);
    }
out:
    qc__free(ctx, rg, (nr ? nr : 1) * sizeof *rg);
    qc__near_grid_free(ctx, &ng);
    qc__free(ctx, g.f, cells * sizeof *g.f);
    qc__free(ctx, blocked, cells + g.ny);
    qc__free(ctx, mask, cells);
    return rc;
}
