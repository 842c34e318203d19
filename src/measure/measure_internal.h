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

#endif
