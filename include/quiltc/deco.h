/*
 * Decoration (paper §5, §7.1): the pattern families, each a qc_family_fn
 * (see pattern.h): skeleton in, one continuous path out.
 */
#ifndef QUILTC_DECO_H
#define QUILTC_DECO_H

#include "core.h"
#include "pattern.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The smoothed tree walk alone (Catmull-Rom vine, paper §4.3). */
int qc_deco_vine(qc_ctx *ctx, const qc_region *region, const qc_params *params,
                 const qc_skeleton *skel, const qc_motif_set *motifs,
                 qc_path *out, qc_stats *stats);
/* Branching (§5.1): motifs at tips and along the vine. */
int qc_deco_branching(qc_ctx *ctx, const qc_region *region, const qc_params *params,
                      const qc_skeleton *skel, const qc_motif_set *motifs,
                      qc_path *out, qc_stats *stats);
/* Wanderer (§5.2): primitives on a tour joined by Béziers. */
int qc_deco_wanderer(qc_ctx *ctx, const qc_region *region, const qc_params *params,
                     const qc_skeleton *skel, const qc_motif_set *motifs,
                     qc_path *out, qc_stats *stats);
/* Pebbling (§5.3.1) and Shape Packing (§5.3.2). */
int qc_deco_pebbling(qc_ctx *ctx, const qc_region *region, const qc_params *params,
                     const qc_skeleton *skel, const qc_motif_set *motifs,
                     qc_path *out, qc_stats *stats);
/* Packing draws a copy of a motif per pebble: the copies may hold at most
 * QC_MAX_PACKED_POINTS motif points, counted once the motifs are chosen,
 * before any is drawn (QC_ELIMIT: a 60,000-vertex motif would take
 * gigabytes). */
int qc_deco_packing(qc_ctx *ctx, const qc_region *region, const qc_params *params,
                    const qc_skeleton *skel, const qc_motif_set *motifs,
                    qc_path *out, qc_stats *stats);
#define QC_MAX_PACKED_POINTS 4000000u
/* Fixed-width fill and stippling (§7.1). */
int qc_deco_fill(qc_ctx *ctx, const qc_region *region, const qc_params *params,
                 const qc_skeleton *skel, const qc_motif_set *motifs,
                 qc_path *out, qc_stats *stats);
int qc_deco_stipple(qc_ctx *ctx, const qc_region *region, const qc_params *params,
                    const qc_skeleton *skel, const qc_motif_set *motifs,
                    qc_path *out, qc_stats *stats);
/* Echo rings and spirals (beyond the paper); the skeleton is empty. */
int qc_deco_echo(qc_ctx *ctx, const qc_region *region, const qc_params *params,
                 const qc_skeleton *skel, const qc_motif_set *motifs,
                 qc_path *out, qc_stats *stats);
int qc_deco_spiral(qc_ctx *ctx, const qc_region *region, const qc_params *params,
                   const qc_skeleton *skel, const qc_motif_set *motifs,
                   qc_path *out, qc_stats *stats);

#ifdef __cplusplus
}
#endif
#endif
