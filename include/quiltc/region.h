/*
 * Regions: a quilt block outline with holes, as closed polygon rings in
 * millimetres, y up. After qc_region_normalize the rings are simple, do not
 * cross each other, outer rings run counter-clockwise and holes clockwise,
 * so a point is inside when it is inside an odd number of rings.
 */
#ifndef QUILTC_REGION_H
#define QUILTC_REGION_H

#include "core.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct qc_region {
    qc_vec2 *v;         /* all ring vertices, ring after ring; rings close implicitly */
    size_t nv, v_cap;
    uint32_t *ring_end; /* ring k holds v[k ? ring_end[k-1] : 0 .. ring_end[k]) */
    size_t nrings, ring_cap;
} qc_region;

void qc_region_free(qc_ctx *ctx, qc_region *r);

/* Appends a ring of n >= 3 vertices as given (a closing duplicate of the first is dropped). */
int qc_region_add_ring(qc_ctx *ctx, qc_region *r, const qc_vec2 *pts, size_t n);

/* Rings (outlines and holes) a region read from SVG or sampled may have:
 * normalizing and sampling grow faster than linearly in them (20,000 tiny
 * islands took 2 s, 490,000 over 120 s), and a quilt block has a handful.
 * qc_io_read_svg_region and qc_sample refuse more with QC_ELIMIT. */
#define QC_MAX_REGION_RINGS 10000u

/*
 * Validates and orients: QC_EEMPTY (no ring), QC_ERANGE (NaN/inf or a
 * coordinate beyond 1e6 mm), QC_EDEGENERATE (zero area), QC_EINTERSECT
 * (a ring crosses itself or another; the message says where, in mm).
 * Then outer rings are made CCW and holes CW by nesting depth.
 */
int qc_region_normalize(qc_ctx *ctx, qc_region *r);

/* Built-in shapes: "rect:WxH", "circle:D", "hexagon:D", "star:D", "heart:D";
 * sizes in the caller's unit, mm_per_unit converts (25.4 for inches).
 * The shape's bounding box has its lower-left corner at (0, 0). Normalized. */
int qc_region_shape(qc_ctx *ctx, const char *spec, double mm_per_unit,
                    qc_region *out);

/* Even-odd inside test; points on the boundary count as inside. */
int qc_region_contains(const qc_region *r, qc_vec2 p);
/* Distance from p to the nearest boundary edge (any ring), mm. */
double qc_region_boundary_distance(const qc_region *r, qc_vec2 p);
/* Signed area sum (outer positive, holes negative), mm^2. */
double qc_region_area(const qc_region *r);
qc_bbox qc_region_bbox(const qc_region *r);
/* Copies src into dst (dst is overwritten, not freed first). */
int qc_region_copy(qc_ctx *ctx, qc_region *dst, const qc_region *src);
/* Moves every vertex by (dx, dy). */
void qc_region_translate(qc_region *r, double dx, double dy);

#ifdef __cplusplus
}
#endif
#endif
