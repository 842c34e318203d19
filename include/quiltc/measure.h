/*
 * Measuring patterns: the farthest any fabric lies from a stitch, bare
 * seams and corners, stitches outside the region, the largest gap a path
 * leaves in its region (the biggest empty circle the needle never enters),
 * and proper self-crossings.
 * Used by the families' statistics, by tests and by `quiltc check`.
 */
#ifndef QUILTC_MEASURE_H
#define QUILTC_MEASURE_H

#include "core.h"
#include "region.h"
#include "stitch.h"

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
 * O(cells + n + path length / resolution) time, 5 bytes per cell.
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

/*
 * Counts the sewn segments of plan (from each point to the next unless
 * the next starts a piece, QC_ST_JUMP) that leave region somewhere along
 * their length by more than tol mm: a stitched line across the gap between
 * two pieces, or across a notch, even when both its ends are inside. The
 * region need not be normalized (a quilt top's patches, sharing seams,
 * will do: a segment along a seam stays inside). *count receives the
 * number, *first (may be NULL) a point outside on the first such segment.
 * O(segments x boundary edges), plus samples every tol along segments that
 * come near the boundary. Errors: QC_EINVAL (NULL, no ring, tol not > 0).
 * Allocates nothing.
 */
int qc_plan_segments_outside(const qc_region *region, const qc_plan *plan, double tol,
                             size_t *count, qc_vec2 *first);

/*
 * How well a path covers its region, as a quilter sees it (see
 * docs/measures.md). All lengths mm.
 */
typedef struct qc_fabric {
    double farthest_mm;  /* farthest any point of the region, boundary included,
                            lies from the path: the bare fabric a quilter sees */
    qc_vec2 farthest_at; /* that point */
    double seam_bare;    /* share (0..1) of the boundary length farther than
                            seam_mm from the path */
    double worst_corner_mm; /* largest corner_mm over convex corners sharper
                               than 150 deg (0 when there is none) */
} qc_fabric;

/*
 * Measures the pieces of the polyline pts[0..n): piece k is
 * pts[ends[k-1] .. ends[k]) (ends NULL: one piece; consecutive points joined,
 * a piece of one point is a point). The region's bounding box is rasterised
 * at `resolution` mm (raised so the grid has at most 2^22 cells) and an exact
 * distance transform of the cells the path passes through finds the farthest
 * cell; the boundary is walked every min(resolution, 0.254) mm. Distances at
 * the farthest cell, along the boundary and at the corners are exact (a
 * segment grid answers them, with a local climb round the farthest cell):
 * farthest_mm is never above the true figure and at most about one cell
 * below it. seam_mm 0 means 6.35 (1/4 in).
 * corner_mm (NULL, or region->nv doubles) receives every ring vertex's
 * distance to the path. Errors: QC_EINVAL (region or out NULL, no ring,
 * n == 0, pts NULL, resolution not > 0), QC_ERANGE (NaN/inf), QC_ELIMIT
 * (2^31 points or more), QC_ENOMEM.
 */
int qc_fabric_measure(qc_ctx *ctx, const qc_region *region, const qc_vec2 *pts, size_t n,
                      const uint32_t *ends, size_t nends, double resolution, double seam_mm,
                      double *corner_mm, qc_fabric *out);

/* qc_fabric_measure over every piece of path (curves flattened to 0.05 mm;
 * jumps between pieces are not sewn and do not count). */
int qc_path_fabric(qc_ctx *ctx, const qc_region *region, const qc_path *path,
                   double resolution, double seam_mm, double *corner_mm, qc_fabric *out);

/* Interior angle in degrees of ring vertex i of a normalized region (< 180
 * convex, > 180 reflex), for reading corner_mm. */
double qc_region_corner_angle(const qc_region *region, size_t i);

/*
 * Where the pieces (as qc_fabric_measure) leave the region grown by tol_mm:
 * every segment is sampled every step_mm (0: 0.254, its ends included)
 * against the region and its holes. *segments receives the number of
 * segments with a sample outside (a piece of one point counts as one
 * segment), *worst_mm (may be NULL) the farthest such sample from the
 * boundary, *first (may be NULL) the first such sample. Errors: QC_EINVAL
 * (NULL arguments, no ring, tol_mm < 0), QC_ERANGE (NaN/inf), QC_ENOMEM.
 */
int qc_path_outside(qc_ctx *ctx, const qc_region *region, const qc_vec2 *pts, size_t n,
                    const uint32_t *ends, size_t nends, double tol_mm, double step_mm,
                    size_t *segments, double *worst_mm, qc_vec2 *first);

#ifdef __cplusplus
}
#endif
#endif
