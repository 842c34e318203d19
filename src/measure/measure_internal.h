/*
 * Internals shared by the measures (src/measure/) and the offsetting of
 * the echo and spiral families (src/deco/shared_sdf.c): rasterising a region.
 */
#ifndef QC_MEASURE_INTERNAL_H
#define QC_MEASURE_INTERNAL_H

#include "internal.h"

/*
 * Even-odd inside mask of region on the lattice (x0 + i h, y0 + j h),
 * i < nx, j < ny: mask[j * nx + i] = 1 inside, 0 outside (a sample exactly
 * on a crossing counts as inside on its right). Scanline with the edges
 * bucketed by row: O(nx ny + perimeter / h + edges). QC_OK or QC_ENOMEM.
 */
QC__HIDDEN int qc__raster_inside(qc_ctx *ctx, const qc_region *region, double x0,
                                 double y0, double h, size_t nx, size_t ny,
                                 unsigned char *mask);

/* Felzenszwalb-Huttenlocher 1-D squared distance transform of f[0..n)
 * (step 1) into d; v (n ints) and z (n + 1 doubles) are scratch. */
QC__HIDDEN void qc__edt_1d(const double *f, size_t n, double *d, int *v, double *z);

/* A raster of squared distances in cells (gap.c): the bounding box from
 * (x0, y0), cells h wide, f[j * nx + i]. */
#define QC__GAP_MAX_CELLS ((size_t)1 << 22)
#define QC__GAP_FAR 1e12 /* beyond any squared cell distance, yet FAR + q^2 stays exact */
typedef struct qc__gap_grid {
    double x0, y0, h;
    size_t nx, ny;
    float *f; /* squared cell distances: integers, exact in a float up to 2^24 */
} qc__gap_grid;

/* Sizes g over box at resolution (raised until at most 2^22 cells); f NULL. */
QC__HIDDEN void qc__gap_grid_size(qc__gap_grid *g, qc_bbox box, double resolution);
/* Zeroes the cells segment ab passes through (points up to a cell outside
 * the box go to its edge cells). */
QC__HIDDEN void qc__gap_seed_segment(qc__gap_grid *g, qc_vec2 a, qc_vec2 b);
/* f becomes each cell's squared distance (in cells) to the nearest zero cell. */
QC__HIDDEN int qc__gap_transform(qc_ctx *ctx, qc__gap_grid *g);

#endif
