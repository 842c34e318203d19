/*
 * Internals of the measures (src/measure/) that the sampler's corner and
 * medial-axis seeding (src/sample/medial.c) also uses: the largest-gap
 * distance raster.
 */
#ifndef QC_MEASURE_INTERNAL_H
#define QC_MEASURE_INTERNAL_H

#include "internal.h"

/* A raster of squared distances in cells (gap.c): the bounding box from
 * (x0, y0), cells h wide, f[j * nx + i]. */
#define QC__GAP_MAX_CELLS ((size_t)1 << 22)
#define QC__GAP_FAR 1e12 /* beyond any squared cell distance, yet FAR + q^2 stays exact */
typedef struct qc__gap_grid {
    double x0, y0, h;
    size_t nx, ny;
    float *f; /* squared cell distances: integers, exact in a float up to 2^24 */
} qc__gap_grid;

/* The centre of cell at (row-major: at = row * nx + column). */
QC__HIDDEN qc_vec2 qc__gap_grid_centre(const qc__gap_grid *g, size_t at);
/* Sizes g over box at resolution (raised until at most 2^22 cells); f NULL. */
QC__HIDDEN void qc__gap_grid_size(qc__gap_grid *g, qc_bbox box, double resolution);
/* The raster every use starts from: g sized over the region's box at
 * resolution, every cell QC__GAP_FAR, and *mask (nx * ny bytes) 1 where a
 * cell's centre is inside. QC_OK, or an error with g->f and *mask NULL. */
QC__HIDDEN int qc__gap_grid_inside(qc_ctx *ctx, const qc_region *region, double resolution,
                                   qc__gap_grid *g, unsigned char **mask);
/* Zeroes the cells segment ab passes through (points up to a cell outside
 * the box go to its edge cells). */
QC__HIDDEN void qc__gap_seed_segment(qc__gap_grid *g, qc_vec2 a, qc_vec2 b);
/* Zeroes the cells every ring edge of region passes through. */
QC__HIDDEN void qc__gap_seed_region(qc__gap_grid *g, const qc_region *region);
/* f, seeded (every cell 0 or QC__GAP_FAR), becomes each cell's squared distance
 * (in cells) to the nearest zero cell, capped at QC__GAP_FAR. */
QC__HIDDEN int qc__gap_transform(qc_ctx *ctx, qc__gap_grid *g);
/* As qc__gap_transform, for seeds far apart (a region's boundary only):
 * the same values, without first trying the near-seed way per row; with
 * rows (ny flags) not NULL, only in the rows flagged (the others hold
 * their column's distances, upper bounds). */
QC__HIDDEN int qc__gap_transform_far(qc_ctx *ctx, qc__gap_grid *g, const unsigned char *rows);
/* As qc__gap_transform, but exact only where it matters: where mask is set
 * and the cell's value exceeds floor; elsewhere f holds an upper bound (the
 * distance along its column, or a nearer one found on the way). With raise, floor rises to each new greatest
 * value, so the exact cells are the candidates for the maximum over mask,
 * and *best_at receives the first cell of that maximum (SIZE_MAX: none
 * above the floor), the cell a scan of qc__gap_transform would pick. */
QC__HIDDEN int qc__gap_transform_above(qc_ctx *ctx, qc__gap_grid *g, const unsigned char *mask,
                                       double floor, int raise, size_t *best_at);

#endif
