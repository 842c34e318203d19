/* Internals of the sampling stage. Not installed. */
#ifndef QC_SAMPLE_INTERNAL_H
#define QC_SAMPLE_INTERNAL_H

#include "region_index.h"

/* Lattice points of kind inside the index's region, margin from its edges,
 * spacing d, the lattice centred on the region's box. Appends to out. */
QC__HIDDEN int qc__sample_lattice(qc_ctx *ctx, const qc__rindex *ix, int kind, double d,
                                  double margin, qc_points *out);

/* Bridson Poisson-disk points (pairwise >= d) filling every part of the region. */
QC__HIDDEN int qc__sample_poisson(qc_ctx *ctx, const qc__rindex *ix, double d, double margin,
                                  uint64_t seed, int k, qc_points *out);

/* Adds points on the medial axis of region (the ridge of the boundary
 * distance, on a d / 4 raster), deepest in a corner first, each at least
 * margin inside and 0.8 d from every point of out: so sharp points, corners
 * and strips too narrow for the fill get points (medial.c). Appends. */
QC__HIDDEN int qc__sample_medial(qc_ctx *ctx, const qc_region *region, double d,
                                 double margin, qc_points *out);

#endif
