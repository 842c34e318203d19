/* Internals of stitch/: clipping flattened pieces to a region. */
#ifndef QC_STITCH_INTERNAL_H
#define QC_STITCH_INTERNAL_H

#include "internal.h"

/*
 * Appends to out/out_end the parts of the pieces in/in_end (as from
 * qc_curve_flatten) that lie inside region (boundary counts as inside); a
 * piece leaving and re-entering the region becomes several pieces, cut
 * exactly where segments cross ring edges. QC_OK or QC_ENOMEM.
 */
QC__HIDDEN int qc__clip_pieces(qc_ctx *ctx, const qc_points *in,
                               const qc_order *in_end, const qc_region *region,
                               qc_points *out, qc_order *out_end);

#endif
