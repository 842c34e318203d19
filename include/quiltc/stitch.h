/*
 * The stitch plan: a finished path for a machine. Curves flattened, tiny
 * segments merged, long ones split, tie-offs added, jumps marked. Writers
 * only encode a plan; they never change its geometry.
 */
#ifndef QUILTC_STITCH_H
#define QUILTC_STITCH_H

#include "core.h"
#include "region.h"

#ifdef __cplusplus
extern "C" {
#endif

enum {
    QC_ST_JUMP = 1, /* reach this point with the needle up (starts a piece) */
    QC_ST_TIE = 2   /* a tie-off stitch */
};

typedef struct qc_plan {
    qc_vec2 *p;            /* mm, y up, in the block's frame */
    unsigned char *flags;  /* QC_ST_* per point; p[0] always has QC_ST_JUMP */
    size_t n, cap;
} qc_plan;

typedef struct qc_stitch_params {
    double tolerance;   /* chord tolerance, mm, (0, 1000]; 0 = 0.127 (0.005 in) */
    double min_segment; /* merge shorter segments (not corners), mm; 0 = 0.508; < 0 = keep all */
    double max_segment; /* split longer segments, mm, >= 0.01; 0 = no limit */
    int tie_stitches;   /* tie-off stitches at each piece's start and end, 0..100; 0 = none */
    double tie_length;  /* length of one tie-off stitch, mm, (0, 100]; 0 = 0.5 */
    int clip;           /* non-zero: drop what lies outside clip region (pieces split, jumps added) */
} qc_stitch_params;

#define QC_MAX_PLAN_POINTS 50000000u /* about 850 MB of plan */

/*
 * Builds *out (zeroed first) from path, piece by piece (a piece starts at
 * each MOVE): curves flattened to tolerance; if clip and clip_region, only
 * what lies inside the region is kept (cut exactly at ring edges; a piece
 * that leaves and re-enters becomes two); points closer than min_segment to
 * the previous kept point dropped where that moves the path by at most
 * 0.001 in (else the earlier point moved onto it), but a corner stays as a
 * shorter stitch down to 0.15 mm, and a point the piece passes twice stays
 * (each piece's first and last points stay);
 * segments longer than max_segment split into equal parts; pieces reduced to
 * one point dropped. Each piece's first point has QC_ST_JUMP; after it and
 * after its last point come tie_stitches points flagged QC_ST_TIE going back
 * and forth over tie_length (at most the adjacent segment's length) along
 * the piece; points closer than min_segment to where the start tie leaves
 * the needle are dropped (if that would drop the piece's end, the tie runs
 * to the second point instead), so no stitch after it is shorter than
 * min_segment. params may be NULL (all defaults). clip_region may be NULL.
 * Errors: QC_EEMPTY (nothing to sew), QC_ERANGE (bad tolerance/lengths, a
 * path coordinate NaN or beyond 1e6 mm), QC_ELIMIT (more than
 * QC_MAX_PLAN_POINTS points, refused before the plan grows), QC_ENOMEM; *out
 * is then empty.
 */
int qc_stitch_plan(qc_ctx *ctx, const qc_path *path, const qc_region *clip_region,
                   const qc_stitch_params *params, qc_plan *out);
/* qc_stitch_plan that frees *path (left zeroed, whatever the outcome) as
 * soon as it is flattened, before the plan's own copies of the pattern are
 * made: a caller done with the path lowers the peak (at 10^6 points). */
int qc_stitch_plan_taking(qc_ctx *ctx, qc_path *path, const qc_region *clip_region,
                          const qc_stitch_params *params, qc_plan *out);
void qc_plan_free(qc_ctx *ctx, qc_plan *plan);
/* Appends one point with its QC_ST_* flags. QC_OK, or QC_ENOMEM with the
 * plan unchanged. */
int qc_plan_push(qc_ctx *ctx, qc_plan *plan, qc_vec2 p, unsigned flags);

typedef struct qc_plan_estimate {
    size_t points, jumps, ties; /* jumps: travel moves between pieces (p[0] excluded) */
    double sewn_mm;      /* length sewn (needle down), ties included */
    double travel_mm;    /* length of jumps */
    size_t stitches;     /* sewn_mm at spi stitches per inch, rounded */
    /* Top thread: sewn_mm * 1.1 (take-up in the quilt sandwich) + 150 mm per
     * piece (the tails pulled up, tied and buried at its start and end). */
    double thread_mm;
    double seconds;      /* sewing at speed_mm_s, travel at 4x that */
    qc_bbox bbox;        /* of all points; zero for an empty plan */
} qc_plan_estimate;

/* spi: stitches per inch (<= 0 means 12); speed_mm_s: sewing speed (<= 0
 * means 25.4 mm/s). Fills *out; allocates nothing. */
void qc_plan_estimate_get(const qc_plan *plan, double spi, double speed_mm_s,
                          qc_plan_estimate *out);

/* Placing a block on the quilt: mirror (QC_MIRROR_X negates x, a left-right
 * mirror image; QC_MIRROR_Y negates y), then rotate counter-clockwise (y up)
 * by rotate_deg, then move so the outline's bounding box has its lower-left
 * corner at `at` (mm). */
enum { QC_MIRROR_X = 1, QC_MIRROR_Y = 2 };
typedef struct qc_place {
    double rotate_deg; /* [-360, 360] */
    unsigned mirror;   /* QC_MIRROR_* bits */
    qc_vec2 at;        /* mm, within 1e6 */
} qc_place;
typedef struct qc_xform {
    double a, b, c, d, tx, ty; /* x' = a x + b y + tx, y' = c x + d y + ty */
} qc_xform;

/* The map of *pl for the block outlined by frame (its vertices give the
 * box). Quarter turns are exact. QC_OK, QC_EINVAL (NULL or empty frame) or
 * QC_ERANGE (rotation or place out of range). */
int qc_place_xform(qc_ctx *ctx, const qc_region *frame, const qc_place *pl, qc_xform *out);
/* Maps every point of plan by m (rigid maps keep stitch lengths). */
void qc_plan_transform(qc_plan *plan, const qc_xform *m);
/* Maps every vertex of r by m; a mirror image also reverses each ring, so
 * a normalized region stays normalized (outer rings CCW, holes CW). */
void qc_region_transform(qc_region *r, const qc_xform *m);

#ifdef __cplusplus
}
#endif
#endif
