/* Internals of the sampling stage. Not installed. */
#ifndef QC_SAMPLE_INTERNAL_H
#define QC_SAMPLE_INTERNAL_H

#include "region_index.h"

/* Checks a qc_sample request against the limits (sample.c). */
QC__HIDDEN int qc__sample_check(qc_ctx *ctx, const qc_region *region, const qc_sample_params *sp);
/* qc_sample's fill over the index of its region, the request checked. */
QC__HIDDEN int qc__sample_fill(qc_ctx *ctx, const qc__rindex *ix, const qc_sample_params *params,
                               qc_points *out);

/* Lattice points of kind inside the index's region, margin from its edges,
 * spacing d, the lattice centred on the region's box. Appends to out. */
QC__HIDDEN int qc__sample_lattice(qc_ctx *ctx, const qc__rindex *ix, int kind, double d,
                                  double margin, qc_points *out);

/* Bridson Poisson-disk points (pairwise >= d) filling every part of the region. */
QC__HIDDEN int qc__sample_poisson(qc_ctx *ctx, const qc__rindex *ix, double d, double margin,
                                  uint64_t seed, int k, qc_points *out);

/* Squares no Poisson candidate can take: each lies wholly nearer than d
 * to a placed point (cover.c). */
typedef struct qc__cover {
    double x0, y0, side, reach, lim; /* lim = reach^2, reach d less a slack */
    size_t nx, ny;
    unsigned char *dead; /* nx by ny, 1 where marked */
} qc__cover;

QC__HIDDEN int qc__cover_init(qc_ctx *ctx, qc__cover *c, qc_bbox box, double d, double side);
QC__HIDDEN void qc__cover_free(qc_ctx *ctx, qc__cover *c);
/* Marks the squares wholly within reach of q (a point just placed). */
QC__HIDDEN void qc__cover_mark(qc__cover *c, qc_vec2 q);

/* ceil(t), 0 when that is not positive; and floor(u), n - 1 when that is
 * more, -1 when u < 0 (nothing): a cell range round a point without a
 * libm call per row (truncation is floor for u >= 0; t and u are cell
 * indices, far inside a long). */
static inline long qc__ceil_from0(double t)
{
    long c;

    if (!(t > 0.0))
        return 0;
    c = (long)t;
    return (double)c < t ? c + 1 : c;
}

static inline long qc__floor_below(double u, size_t n)
{
    if (u < 0.0)
        return -1;
    return u < (double)n - 1 ? (long)u : (long)n - 1;
}

/* Whether p (inside the box) lies in a marked square: then a point lies
 * nearer than d to it. */
static inline int qc__cover_holds(const qc__cover *c, qc_vec2 p)
{
    size_t i = (size_t)((p.x - c->x0) / c->side), j = (size_t)((p.y - c->y0) / c->side);

    return c->dead[(j < c->ny ? j : c->ny - 1) * c->nx + (i < c->nx ? i : c->nx - 1)];
}

/* Adds points on the medial axis of region (the ridge of the boundary
 * distance, on a d / 4 raster), deepest in a corner first, each at least
 * margin inside and 0.8 d from every point of out: so sharp points, corners
 * and strips too narrow for the fill get points (medial.c). Appends. */
QC__HIDDEN int qc__sample_medial(qc_ctx *ctx, const qc_region *region, double d,
                                 double margin, qc_points *out);
/* As qc__sample_medial, with the region's index given. */
QC__HIDDEN int qc__sample_medial_ix(qc_ctx *ctx, const qc_region *region, const qc__rindex *ix,
                                    double d, double margin, qc_points *out);

/* Points of a growing set near a query point: a uniform grid of chains
 * (near_grid.c). Queries answer for radii up to the cell size. */
typedef struct qc__near_grid {
    double x0, y0, cell;
    size_t gx, gy;
    size_t *head, *next; /* chains over the points; SIZE_MAX ends */
    size_t cap;
} qc__near_grid;

QC__HIDDEN int qc__near_grid_init(qc_ctx *ctx, qc__near_grid *g, qc_bbox box, double cell);
QC__HIDDEN void qc__near_grid_free(qc_ctx *ctx, qc__near_grid *g);
/* Files point i of pts (pts may grow between calls; add in any order). */
QC__HIDDEN int qc__near_grid_add(qc_ctx *ctx, qc__near_grid *g, const qc_points *pts, size_t i);
/* Whether a filed point of pts lies nearer than r (<= cell) to p. */
QC__HIDDEN int qc__near_grid_near(const qc__near_grid *g, const qc_points *pts, qc_vec2 p,
                                  double r);
/* Appends p to out and files it, unless a filed point lies nearer than r
 * or ix does not admit p at margin: the step the hole and medial seeds
 * end with. */
QC__HIDDEN int qc__near_grid_push_clear(qc_ctx *ctx, qc__near_grid *g, qc_points *out,
                                        const qc__rindex *ix, qc_vec2 p, double r,
                                        double margin);
/* Appends the points of cand that lie at least r from every point of
 * out[ref0, out->n) (the ones appended are not compared with each other). */
QC__HIDDEN int qc__points_append_clear(qc_ctx *ctx, qc_points *out, size_t ref0,
                                       const qc_points *cand, double r);

/* Seed cells of an nx by ny raster filed in square buckets of b cells
 * (seed_buckets.c). */
typedef struct qc__seed_buckets {
    long b, bx, by;
    uint32_t *start; /* bucket q's seeds: xy[2 * start[q] .. 2 * start[q + 1]) */
    long *xy;        /* the seeds' cells, column and row */
    size_t n;
} qc__seed_buckets;

/* Files the n cells (row-major indices) in buckets of b cells. */
QC__HIDDEN int qc__seed_buckets_build(qc_ctx *ctx, size_t nx, size_t ny, const size_t *cell,
                                      size_t n, long b, qc__seed_buckets *sb);
QC__HIDDEN void qc__seed_buckets_free(qc_ctx *ctx, qc__seed_buckets *sb);
/* Cell (i, j)'s squared distance to the nearest seed, cells, capped at
 * QC__GAP_FAR: the value qc__gap_transform gives it (integers, exact). */
QC__HIDDEN double qc__seed_dist2(const qc__seed_buckets *sb, long i, long j);

/*
 * A row of points along the contour offset inside every ring (holes too):
 * offset mm from the boundary, at most a quarter of the local width there
 * (so a strip gets two rows and a corner's rows run into it), step mm
 * apart along it, none nearer the boundary than margin (contour.c).
 * Appends to out.
 */
QC__HIDDEN int qc__sample_contour(qc_ctx *ctx, const qc_region *region, const qc__rindex *ix,
                                  double offset, double step, double margin, qc_points *out);

/* Adds points, farthest first, wherever a place inside (on a d / 8 raster)
 * lies farther than gap from every point of out, each at least margin
 * inside (holes.c). Appends. */
QC__HIDDEN int qc__sample_fill_holes(qc_ctx *ctx, const qc_region *region, double d,
                                     double margin, double gap, qc_points *out);
/* As qc__sample_fill_holes, with the region's index given. */
QC__HIDDEN int qc__sample_fill_holes_ix(qc_ctx *ctx, const qc_region *region,
                                        const qc__rindex *ix, double d, double margin,
                                        double gap, qc_points *out);

/*
 * The points qc_generate builds on: qc_sample's fill, then (row not
 * QC__ROW_NONE) a row along the seams with the fill kept clear of it, then
 * corner and medial seeds, then (with a row) points in the holes left
 * (to_seams.c). The row's step suits the skeleton: QC__ROW_TREE (a spanning
 * tree chains it) or QC__ROW_TOUR. Appends; on error out has its entry
 * count again. Corner seeds drop the points crowding them, those on entry
 * too, so qc_generate passes out empty.
 */
enum { QC__ROW_NONE = 0, QC__ROW_TREE, QC__ROW_TOUR };
QC__HIDDEN int qc__sample_to_seams(qc_ctx *ctx, const qc_region *region,
                                   const qc_sample_params *sp, int row, qc_points *out);

#endif
