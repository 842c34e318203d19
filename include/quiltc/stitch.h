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
    double tolerance;   /* chord tolerance, mm; 0 = 0.127 (0.005 in) */
    double min_segment; /* merge shorter segments, mm; 0 = 0.508 (0.02 in); < 0 = keep all */
    double max_segment; /* split longer segments, mm; 0 = no limit */
    int tie_stitches;   /* tie-off stitches at each piece's start and end; 0 = none */
    double tie_length;  /* length of one tie-off stitch, mm; 0 = 0.5 */
    int clip;           /* non-zero: drop what lies outside clip region (pieces split, jumps added) */
} qc_stitch_params;

/* Builds *out (zeroed first) from path. clip_region may be NULL. Errors:
 * QC_EEMPTY (nothing to sew), QC_ERANGE (bad tolerance/lengths), QC_ENOMEM. */
int qc_stitch_plan(qc_ctx *ctx, const qc_path *path, const qc_region *clip_region,
                   const qc_stitch_params *params, qc_plan *out);
void qc_plan_free(qc_ctx *ctx, qc_plan *plan);
int qc_plan_push(qc_ctx *ctx, qc_plan *plan, qc_vec2 p, unsigned flags);

typedef struct qc_plan_estimate {
    size_t points, jumps, ties;
    double sewn_mm;      /* length sewn (needle down) */
    double travel_mm;    /* length of jumps */
    size_t stitches;     /* sewn_mm at spi stitches per inch */
    double thread_mm;    /* top thread: sewn_mm * 1.1 + 150 mm per piece (README) */
    double seconds;      /* at speed_mm_s for sewing, 4x for travel */
    qc_bbox bbox;
} qc_plan_estimate;

/* spi: stitches per inch (0 = 12); speed_mm_s: sewing speed (0 = 25.4 mm/s). */
void qc_plan_estimate_get(const qc_plan *plan, double spi, double speed_mm_s,
                          qc_plan_estimate *out);

#ifdef __cplusplus
}
#endif
#endif
