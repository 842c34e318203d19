/* Internals of qc_generate shared by generate.c and generate_pieces.c. */
#ifndef QC_PATTERN_INTERNAL_H
#define QC_PATTERN_INTERNAL_H

#include "internal.h"

/* One pattern in one connected region (res->params resolved). */
QC__HIDDEN int qc__generate_one(qc_ctx *ctx, const qc_region *region, const qc_points *given,
                                const qc_motif_set *motifs, qc_result *res);
/* QC_OK when every given point lies in region, margin from its boundary. */
QC__HIDDEN int qc__check_given_inside(qc_ctx *ctx, const qc_region *region,
                                      const qc_points *given, double margin);
/* A region of separate pieces: each sewn on its own, the results joined
 * (a MOVE, so a jump, between pieces). *handled = 0 (nothing done) when
 * the region is one piece. */
QC__HIDDEN int qc__generate_pieces(qc_ctx *ctx, const qc_region *region, const qc_points *given,
                                   const qc_motif_set *motifs, qc_result *out, int *handled);

#define QC__STATS_TOL_MM 0.05

#endif
