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
 * consecutive points (closer than 1e-9 mm) are skipped (no division by
 * zero). Centripetal parameterisation has no cusps or self-loops within a
 * segment; open ends take the tangent of their chord (end points reflected),
 * and where the path doubles back on itself the curve turns round smoothly
 * (to the left) instead of stopping dead, so the derivative never vanishes.
 * n == 0 appends nothing; one distinct point appends only the MOVE.
 * Errors: QC_EINVAL (pts NULL), QC_ERANGE (a coordinate NaN, inf or beyond
 * 1e9 mm), QC_ENOMEM (out is then unchanged).
 */
int qc_curve_catmull_rom(qc_ctx *ctx, const qc_vec2 *pts, size_t n, int closed,
                         qc_path *out);

/*
 * Flattens path into polylines: every CUBIC subdivided (iteratively, at most
 * 20 levels deep) until its control points lie within tol mm of the chord,
 * so the curve is within tol of the polyline. Points are appended to out;
 * piece_end (may be NULL) receives, for each piece (MOVE), the index in out
 * one past its last point. A path not starting with MOVE starts at (0, 0).
 * Deterministic. Errors: QC_ERANGE (tol not > 0, a point NaN or inf), QC_ELIMIT (2^32 points),
 * QC_ENOMEM (out and piece_end as on entry, core.h).
 */
int qc_curve_flatten(qc_ctx *ctx, const qc_path *path, double tol,
                     qc_points *out, qc_order *piece_end);

/* Length of path in mm (sewn length: MOVEs between pieces excluded),
 * curves flattened to tol (tol <= 0 means 0.01 mm). Allocates nothing. */
double qc_curve_length(const qc_path *path, double tol);

/* One cubic Bezier segment q[0..3]: its point and derivative at t in [0, 1],
 * and its split at t (l and r receive 4 points each; r may alias q). */
qc_vec2 qc_cubic_point(const qc_vec2 *q, double t);
qc_vec2 qc_cubic_tangent(const qc_vec2 *q, double t);
void qc_cubic_split(const qc_vec2 *q, double t, qc_vec2 *l, qc_vec2 *r);
/* Bounding box of the path's flattened points (control points excluded);
 * all zero for an empty path. tol as for qc_curve_length. */
qc_bbox qc_curve_bbox(const qc_path *path, double tol);
/* The length and box of path without flattening it (the stats of every
 * result): each cubic's arc length by Gauss-Legendre on pieces smooth
 * enough for it (halved otherwise), within 1e-5 of the arc where
 * flattening to 0.05 mm falls 1e-3 short; its box exact, from the
 * extrema (it holds qc_curve_bbox's and reaches at most tol beyond).
 * tol only bounds the halving round a cusp (<= 0 means 0.01 mm). */
void qc_curve_measure(const qc_path *path, double tol, double *length, qc_bbox *box);

#ifdef __cplusplus
}
#endif
#endif
