/*
 * Measuring patterns: the largest gap a path leaves in its region (the
 * biggest empty circle the needle never enters), and proper self-crossings.
 * Used by the families' statistics, by tests and by `quiltc check`.
 */
#ifndef QUILTC_MEASURE_H
#define QUILTC_MEASURE_H

#include "core.h"
#include "region.h"

#ifdef __cplusplus
extern "C" {
#endif

/*
 * Radius in mm of the largest circle centred inside region that neither the
 * polyline pts[0..n) (consecutive points joined; n == 1 is a point) nor the
 * region's boundary enters. Method: the region's bounding box is rasterised
 * at `resolution` mm (raised so the grid has at most 2^22 cells), every cell
 * the path or the boundary passes through is a seed, an exact Euclidean
 * distance transform (Felzenszwalb-Huttenlocher) gives each inside cell's
 * clearance, and the best cell's exact clearance (distance to the nearest
 * segment and boundary edge, O(n)) is returned. The result never exceeds
 * the true largest gap and is at most about 2.2 * resolution below it.
 * O(cells + n + path length / resolution) time, 9 bytes per cell.
 * centre_out (may be NULL) receives the circle's centre. n == 0 measures
 * the region alone. Returns the radius (>= 0), or a negative QC_E* code:
 * QC_EINVAL (region NULL or without rings, pts NULL with n > 0, resolution
 * not > 0), QC_ERANGE (NaN/inf), QC_ENOMEM.
 */
double qc_largest_gap(qc_ctx *ctx, const qc_region *region, const qc_vec2 *pts,
                      size_t n, double resolution, qc_vec2 *centre_out);

/*
 * qc_largest_gap over every piece of path (curves flattened to 0.01 mm;
 * the jumps between pieces are not sewn and do not count).
 */
double qc_path_largest_gap(qc_ctx *ctx, const qc_region *region, const qc_path *path,
                           double resolution, qc_vec2 *centre_out);

/*
 * Counts the proper crossings of the polyline pts[0..n) with itself (closed
 * != 0 adds the segment from pts[n-1] back to pts[0]): pairs of
 * non-adjacent segments whose interiors cross at one point, decided by the
 * exact orient2d predicate. Touching, overlapping and collinear segments do
 * not count; zero-length segments are skipped. Uniform grid, about linear
 * for paths whose segments are of similar length. *count receives the
 * number. Segments piled in one spot (a hostile file: 40,000 stitches all
 * through one point) would make it quadratic: when the pairs sharing grid
 * cells exceed QC_MAX_CROSSING_PAIRS it fails with QC_ELIMIT, decided
 * after binning, before any pair is tested. Errors: QC_EINVAL (pts or count
 * NULL), QC_ENOMEM, QC_ELIMIT.
 */
#define QC_MAX_CROSSING_PAIRS 20000000u /* about a second of exact tests */
int qc_path_self_crossings(qc_ctx *ctx, const qc_vec2 *pts, size_t n, int closed,
                           size_t *count);

#ifdef __cplusplus
}
#endif
#endif
