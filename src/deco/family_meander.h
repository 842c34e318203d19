/*
 * The meander's seed curve (family_meander_seed.c) and curve evolution
 * (family_meander_grow.c), shared with family_meander.c and the tests.
 */
#ifndef QC_FAMILY_MEANDER_H
#define QC_FAMILY_MEANDER_H

#include "deco_internal.h"

typedef struct qc__grow_opts {
    double d;          /* line spacing: parts of the curve repel within d */
    double clear;      /* distance kept from the boundary and the holes */
    double turn;       /* smallest turn radius */
    double wiggle;     /* 0..1: the random push, times WIGGLE_STEP d */
    size_t iterations; /* rounds of the evolution (a work count, not a clock) */
    double max_len;    /* the curve stops growing beyond this length, mm */
    uint64_t seed;
    int open;          /* c is open: its first and last vertex stay put */
    const qc__sdf *sdf; /* the region's distance field */
} qc__grow_opts;

/*
 * Evolves the closed curve c (points in order, closing implicitly; or open,
 * ends pinned, with o->open) inside
 * the field's region: each round resamples it (vertex spacing kept within
 * [0.2 d, 0.45 d]), fairs it, pushes it by a seeded random amount and by
 * short-range repulsion between non-neighbouring parts and from the
 * boundary, every move capped so the curve never passes through itself.
 * A uniform grid finds the neighbours: each round is linear in the curve's
 * vertex count. Deterministic for a seed. Errors: QC_ENOMEM (c is then
 * left valid, as it was after some round).
 */
/*
 * The curve the evolution starts from, into *c (emptied first): the outline
 * of a spanning tree over Poisson points of region (and, with axis, points
 * on its medial axis), closed, or with ports (a tile) open from ports[0] to
 * ports[1]; it does not cross itself. s is region's distance field.
 * Errors: QC_EEMPTY (no inside), QC_ENOMEM, and the sampler's.
 */
QC__HIDDEN int qc__meander_seed(qc_ctx *ctx, const qc_region *region, const qc__sdf *s,
                                const qc_params *prm, const qc_vec2 *ports, int axis,
                                qc_points *c);

QC__HIDDEN int qc__meander_grow(qc_ctx *ctx, qc_points *c, const qc__grow_opts *o);

/*
 * Eases the vertices of c (open: its ends stay) that turn tighter than turn
 * (mm): each moves halfway to its neighbours' midpoint, in passes kept only
 * while c stays d/20 inside s's region and does not cross itself.
 * Errors: QC_ENOMEM.
 */
QC__HIDDEN int qc__meander_ease(qc_ctx *ctx, qc_points *c, int open, double turn,
                                const qc__sdf *s, double d);

/* 1 if segment ab stays inner (mm) or more inside s's region, else 0. */
QC__HIDDEN int qc__meander_seg_inside(const qc__sdf *s, qc_vec2 a, qc_vec2 b, double inner);

/*
 * Waves the straight runs of c (open: its ends stay) longer than run d
 * (within d/20 of their chord): a sine of about 1.5 d, 0.07 d either side
 * (near the boundary no nearer it than 0.06 d), kept where it stays inside
 * s's region and crosses nothing. Errors: QC_ENOMEM.
 */
QC__HIDDEN int qc__meander_wave(qc_ctx *ctx, qc_points *c, int open, double d, double run,
                                const qc__sdf *s);

/*
 * Rounds the turns of c (open: its ends stay) tighter than turn (mm) as
 * the tests measure them (the circle through a vertex and the points turn
 * before and after it along c): their segments are split, then each run of
 * tight vertices moves, a few rounds over, towards the middle of those
 * points, kept only where the whole run stays d/20 inside s's region,
 * crosses nothing and leaves no seam point that was within 1/4 in of the
 * curve further away; where that fails, outwards: the curve out to two
 * radii either side moves back out, so the corner stays and its legs
 * spread. Straight runs are waved before and after. Errors: QC_ENOMEM.
 */
QC__HIDDEN int qc__meander_round(qc_ctx *ctx, qc_points *c, int open, double turn,
                                 const qc__sdf *s, double d);

/*
 * Sends the evolved curve c (open: its ends stay) into every convex corner
 * of region sharper than 100 degrees that it leaves further than issue 16's
 * reach: a narrow tongue from its nearest segment down the bisector, kept
 * only where it stays inside (s) and crosses nothing. Errors: QC_ENOMEM.
 */
QC__HIDDEN int qc__meander_reach(qc_ctx *ctx, const qc_region *region, const qc__sdf *s,
                                 double d, int open, qc_points *c);

/*
 * Closes the widest empty discs the curve c (open: its ends stay) leaves
 * in region (wider than 0.57 d): a bump of one line into each (0.6 d
 * either side along the curve, up to 0.25 d high), from whichever side
 * narrows the widest gap round it most; where none does, every vertex
 * within 0.7 d beyond the disc moves radially towards its centre, by up
 * to 0.15 d. Kept only where it narrows that gap, crosses nothing, turns
 * no tighter than d/4 where the curve did not, and moves no line near the
 * seams (s) away from them; no vertex is added. A few passes; one that
 * widens the widest disc, or makes the curve cross itself, is undone.
 * Curves beyond 8000 vertices are left alone (a work budget).
 * Deterministic. Errors: QC_ENOMEM.
 */
QC__HIDDEN int qc__meander_holes(qc_ctx *ctx, const qc_region *region, const qc__sdf *s,
                                 double d, int open, qc_points *c);

/*
 * Appends to out the Catmull-Rom spline through pts[0..n) (closed != 0
 * joins the last point to the first), every span that would make the
 * flattened path cross itself, or (sdf not NULL) stray outside sdf's
 * region, drawn flatter, down to its chord: if the polyline does not cross
 * itself, neither does the path. d (mm) sizes the search grid. Errors:
 * QC_ENOMEM, and qc_curve_catmull_rom's.
 */
QC__HIDDEN int qc__meander_smooth(qc_ctx *ctx, const qc_vec2 *pts, size_t n, int closed,
                                  double d, const qc__sdf *sdf, qc_path *out);

#endif
