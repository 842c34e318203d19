/* Curves (paper §4.3): Catmull-Rom smoothing, flattening and measuring paths. */
#ifndef QUILTC_CURVE_H
#define QUILTC_CURVE_H

#include "core.h"

#ifdef __cplusplus
extern "C" {
#endif

/*
 * Appends to *out a centripetal (alpha = 0.5) Catmull-Rom spline through
 * pts[0..n) as cubic Béziers: a MOVE to pts[0] when out is empty (else the
 * curve continues from the last point, which should equal pts[0]), then one
 * CUBIC per segment. closed != 0 also joins pts[n-1] to pts[0]. Coincident
 * consecutive points are skipped (no division by zero). Centripetal
 * parameterisation has no cusps or self-loops within a segment.
 */
int qc_curve_catmull_rom(qc_ctx *ctx, const qc_vec2 *pts, size_t n, int closed,
                         qc_path *out);

/*
 * Flattens path into polylines: every CUBIC subdivided until its control
 * polygon lies within tol mm of the chord. out receives points; piece_end
 * receives, for each piece (MOVE), the index one past its last point.
 * Errors: QC_ERANGE (tol <= 0), QC_ENOMEM.
 */
int qc_curve_flatten(qc_ctx *ctx, const qc_path *path, double tol,
                     qc_points *out, qc_order *piece_end);

/* Length of path in mm, curves flattened to tol. */
double qc_curve_length(const qc_path *path, double tol);
/* Bounding box of the path's flattened points (control points excluded). */
qc_bbox qc_curve_bbox(const qc_path *path, double tol);

#ifdef __cplusplus
}
#endif
#endif
