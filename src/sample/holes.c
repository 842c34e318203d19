/*
 * Holes in a point set: Bridson's sampler tries k candidates round each
 * point, so it can leave a place more than d from every point, and the
 * fill clear of the seam row leaves a band where neither reaches. Such a
 * hole is a bare patch in every family (the path runs through or round
 * the points), so points go where the distance to the nearest point
 * (a d / 8 raster: a coarser one misses a hole by a tenth of d) exceeds
 * gap, farthest first, until none does.
 */
#include <math.h>
#include <string.h>

#include "sample_internal.h"
#include "../measure/measure_internal.h"

#define CELLS_PER_D 8.0 /* raster: d / 8 */

typedef struct hole {
    float f; /* squared distance to the nearest point, cells */
    uint32_t at;
} hole;

/* The cell qc__gap_seed_segment(g, p, p) zeroes (the same arithmetic, at
 * t = 0), or SIZE_MAX when p lies off the raster. */
static size_t seed_cell(const qc__gap_grid *g, qc_vec2 p)
{
    double xn = (double)g->nx, yn = (double)g->ny;
    double x = (p.x + (p.x - p.x) * 0.0 - g->x0) / g->h;
    double y = (p.y + (p.y - p.y) * 0.0 - g->y0) / g->h;

    if (!(x >= -1.0 && y >= -1.0 && x < xn + 1.0 && y < yn + 1.0))
        return SIZE_MAX;
    x = x > 0.0 ? (x < xn - 1.0 ? x : xn - 1.0) : 0.0;
    y = y > 0.0 ? (y < yn - 1.0 ? y : yn - 1.0) : 0.0;
    return (size_t)y * g->nx + (size_t)x;
}

/* Clears mask wherever a seed (the cell of a point of pts) lies within
 * squared cell distance lim: what stays set is a hole (its nearest seed
 * beyond lim), found by stamping a disk round each seed, cheaper than a
 * distance transform of the whole raster when seeds are points. The disk's
 * half-width per row is worked out once. */
static int stamp_seeds(qc_ctx *ctx, const qc__gap_grid *g, const size_t *seed, size_t ns,
                       unsigned char *mask, double lim)
{
    long r = (long)floor(sqrt(lim)), nx = (long)g->nx, ny = (long)g->ny, dy;
    long *half;
    size_t n;

    while ((double)(r + 1) * (double)(r + 1) <= lim)
        r++;
    while (r > 0 && (double)r * (double)r > lim)
        r--;
    half = qc__alloc_array(ctx, (size_t)(2 * r + 1), sizeof *half);
    if (half == NULL)
        return QC_ENOMEM;
    for (dy = -r; dy <= r; dy++) {
        long dx = r;
        while (dx > 0 && (double)dx * (double)dx + (double)dy * (double)dy > lim)
            dx--;
        half[dy + r] = dx;
    }
    for (n = 0; n < ns; n++) {
        long i = (long)(seed[n] % g->nx), j = (long)(seed[n] / g->nx);
        for (dy = -r; dy <= r; dy++) {
            long y = j + dy, lo = i - half[dy + r], hi = i + half[dy + r];
            if (y < 0 || y >= ny)
                continue;
            lo = lo < 0 ? 0 : lo;
            hi = hi >= nx ? nx - 1 : hi;
            memset(mask + y * nx + lo, 0, (size_t)(hi - lo + 1));
        }
    }
    qc__free(ctx, half, (size_t)(2 * r + 1) * sizeof *half);
    return QC_OK;
}

/* Sorts the holes farthest first, then by cell, by a radix sort of one
 * key each: the distance's bits inverted (a positive float's bits order as
 * its value), over the cell. The keys differ (the cells do), so the order
 * is the one comparing distance, then cell, gives. */
static int sort_holes(qc_ctx *ctx, hole *hs, size_t n)
{
    uint64_t *key = qc__alloc_array(ctx, n ? n : 1, sizeof *key);
    size_t k;
    int rc;

    if (key == NULL)
        return QC_ENOMEM;
    for (k = 0; k < n; k++) {
        uint32_t b;
        memcpy(&b, &hs[k].f, sizeof b);
        key[k] = (uint64_t)(uint32_t)~b << 32 | hs[k].at;
    }
    rc = qc__radix_sort(ctx, key, NULL, n, 0);
    for (k = 0; k < n && rc == QC_OK; k++) {
        uint32_t b = ~(uint32_t)(key[k] >> 32);
        memcpy(&hs[k].f, &b, sizeof b);
        hs[k].at = (uint32_t)key[k];
    }
    qc__free(ctx, key, (n ? n : 1) * sizeof *key);
    return rc;
}

/* The first hole cell (mask 1; the rest are 0) from k on, or cells: memchr
 * skips the bare raster far faster than a loop over its cells. */
static size_t next_hole(const unsigned char *mask, size_t k, size_t cells)
{
    const unsigned char *at = k < cells ? memchr(mask + k, 1, cells - k) : NULL;

    return at != NULL ? (size_t)(at - mask) : cells;
}

/* The number of hole cells, counted only up to most + 1. */
static size_t count_holes(const unsigned char *mask, size_t cells, size_t most)
{
    size_t n = 0, k;

    for (k = next_hole(mask, 0, cells); k < cells && n <= most; k = next_hole(mask, k + 1, cells))
        n++;
    return n;
}

/* The distances of the few hole cells (mask set) by looking round each
 * among the seeds, in buckets about twice the gap wide: no raster of
 * distances. Those beyond lim go to hs (room for nh), their count to *nout. */
static int few_holes(qc_ctx *ctx, const qc__gap_grid *g, const size_t *seed, size_t ns,
                     const unsigned char *mask, double lim, hole *hs, size_t *nout)
{
    size_t k, n = 0, cells = g->nx * g->ny;
    qc__seed_buckets sb;

    QC__TRY(qc__seed_buckets_build(ctx, g->nx, g->ny, seed, ns, 2 * (long)ceil(sqrt(lim)) + 1,
                                   &sb));
    for (k = next_hole(mask, 0, cells); k < cells; k = next_hole(mask, k + 1, cells)) {
        float f = (float)qc__seed_dist2(&sb, (long)(k % g->nx), (long)(k / g->nx));
        if ((double)f > lim) {
            hs[n].f = f;
            hs[n].at = (uint32_t)k;
            n++;
        }
    }
    qc__seed_buckets_free(ctx, &sb);
    *nout = n;
    return QC_OK;
}

/* The distances of many hole cells by one transform of a raster seeded at
 * the points. Those beyond lim go to *hs (allocated, room for *cap). */
static int many_holes(qc_ctx *ctx, qc__gap_grid *g, const qc_points *pts,
                      const unsigned char *mask, double lim, hole **hs, size_t *cap,
                      size_t *nout)
{
    size_t cells = g->nx * g->ny, k, n = 0;
    int rc;

    g->f = qc__alloc_array(ctx, cells, sizeof *g->f);
    if (g->f == NULL)
        return QC_ENOMEM;
    for (k = 0; k < cells; k++)
        g->f[k] = (float)QC__GAP_FAR;
    for (k = 0; k < pts->n; k++)
        qc__gap_seed_segment(g, pts->v[k], pts->v[k]);
    rc = qc__gap_transform_above(ctx, g, mask, lim, 0, &k);
    if (rc < 0)
        return rc;
    for (k = 0; k < cells; k++)
        n += mask[k] && (double)g->f[k] > lim;
    *cap = n ? n : 1;
    *hs = qc__alloc_array(ctx, *cap, sizeof **hs);
    if (*hs == NULL)
        return QC_ENOMEM;
    n = 0;
    for (k = 0; k < cells; k++)
        if (mask[k] && (double)g->f[k] > lim) {
            (*hs)[n].f = g->f[k];
            (*hs)[n].at = (uint32_t)k;
            n++;
        }
    *nout = n;
    return QC_OK;
}

int qc__sample_fill_holes(qc_ctx *ctx, const qc_region *region, double d, double margin,
                          double gap, qc_points *out)
{
    qc__rindex ix;
    int rc;

    QC__TRY(qc__rindex_build(ctx, region, &ix));
    rc = qc__sample_fill_holes_ix(ctx, region, &ix, d, margin, gap, out);
    qc__rindex_free(ctx, &ix);
    return rc;
}

int qc__sample_fill_holes_ix(qc_ctx *ctx, const qc_region *region, const qc__rindex *ix,
                             double d, double margin, double gap, qc_points *out)
{
    qc__gap_grid g;
    qc__near_grid ng;
    unsigned char *mask = NULL;
    hole *hs = NULL;
    size_t *seed = NULL, cells, k, nh = 0, cap = 0, i, ns = 0, npts = out->n;
    qc_bbox box = qc_region_bbox(region);
    double lim;
    int rc;

    if (out->n == 0 || !(gap > 0))
        return QC_OK;
    memset(&ng, 0, sizeof ng);
    /* the raster of qc__gap_grid_inside, its distances only if many holes */
    qc__gap_grid_size(&g, box, d / CELLS_PER_D);
    cells = g.nx * g.ny;
    lim = gap / g.h;
    lim *= lim;
    mask = qc__alloc(ctx, cells);
    rc = mask == NULL ? QC_ENOMEM
                      : qc__raster_inside(ctx, region, g.x0 + 0.5 * g.h, g.y0 + 0.5 * g.h, g.h,
                                          g.nx, g.ny, mask);
    if (rc == QC_OK)
        rc = qc__near_grid_init(ctx, &ng, box, fmax(gap, d));
    if (rc == QC_OK && (seed = qc__alloc_array(ctx, npts, sizeof *seed)) == NULL)
        rc = QC_ENOMEM;
    for (k = 0; k < npts && rc == QC_OK; k++) /* the points' cells, those on the raster */
        if ((seed[ns] = seed_cell(&g, out->v[k])) != SIZE_MAX)
            ns++;
    if (rc == QC_OK)
        rc = stamp_seeds(ctx, &g, seed, ns, mask, lim);
    if (rc < 0)
        goto out;
    nh = count_holes(mask, cells, cells / 64);
    if (nh > cells / 64) { /* many holes: their distances by one transform */
        rc = many_holes(ctx, &g, out, mask, lim, &hs, &cap, &nh);
    } else {
        cap = nh ? nh : 1;
        hs = qc__alloc_array(ctx, cap, sizeof *hs);
        if (hs == NULL)
            rc = QC_ENOMEM;
        else if (nh > 0) /* none: no seeds to file */
            rc = few_holes(ctx, &g, seed, ns, mask, lim, hs, &nh);
    }
    if (rc < 0 || nh == 0)
        goto out;
    /* every hole's distance is above lim > 0: a positive float */
    if ((rc = sort_holes(ctx, hs, nh)) < 0)
        goto out;
    for (i = 0; i < out->n && rc == QC_OK; i++)
        rc = qc__near_grid_add(ctx, &ng, out, i);
    for (k = 0; k < nh && rc == QC_OK; k++) {
        qc_vec2 p = qc__gap_grid_centre(&g, hs[k].at);

        rc = qc__near_grid_push_clear(ctx, &ng, out, ix, p, gap, margin);
    }
out:
    qc__free(ctx, seed, npts * sizeof *seed); /* out grows meanwhile */
    qc__free(ctx, hs, cap * sizeof *hs);
    qc__near_grid_free(ctx, &ng);
    qc__free(ctx, g.f, cells * sizeof *g.f);
    qc__free(ctx, mask, cells);
    return rc;
}
