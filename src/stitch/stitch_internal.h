/* Internals of stitch/: clipping flattened pieces to a region, merging short steps. */
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

/* Scratch for qc__merge_piece, sized for the longest piece. */
typedef struct qc__merge {
    uint32_t *table;      /* a hash table of the piece's places (merge.c) */
    size_t slots;         /* its size: one and a half per point, one per cell */
    uint32_t *start;      /* per cell of a grid over the piece: its first slot */
    size_t cells;         /* cells at most */
    uint32_t *place;      /* per point: where the piece passes it again */
    unsigned char *gone;  /* a bit per place: a junction merged away */
    size_t cap;
} qc__merge;

#define QC__NOT_JOINT UINT32_MAX /* qc__merge_junctions: not a junction */

QC__HIDDEN int qc__merge_init(qc_ctx *ctx, qc__merge *mg, size_t longest);
QC__HIDDEN void qc__merge_free(qc_ctx *ctx, qc__merge *mg);

/*
 * mg->place[i] for the piece v[0..n) (n <= the longest given to init): for
 * a junction (v[i] recurs in v other than as a repeat of the point just
 * before: a run of equal points is one visit) the least index of its
 * place, else QC__NOT_JOINT (merge.c; what qc__merge_piece finds first,
 * reading a junction only at a short step).
 */
QC__HIDDEN void qc__merge_junctions(qc__merge *mg, const qc_vec2 *v, size_t n);
/*
 * Keeps in m the points of v[0..n) (n <= the longest given to init) that a
 * plan sews, returning how many (m may be v, or run over v from before it:
 * the merge compacts a piece in place): steps shorter than min_seg merged
 * where the path strays at most keep mm by it, short stitches kept where it
 * turns (unless under floor_len), points the piece passes twice kept in
 * place; the first and last points always stay (merge.c).
 */
QC__HIDDEN size_t qc__merge_piece(qc__merge *mg, const qc_vec2 *v, size_t n, double min_seg,
                                  double floor_len, double keep, qc_vec2 *m);

#endif
