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
 * QC_PACKED_POINTS_BUDGET(n) motif points for n skeleton points, estimated
 * before the pebbles are packed (n times the smallest motif) and counted once
 * the motifs are chosen, before any is drawn (QC_ELIMIT: a 60,000-vertex
 * motif would take gigabytes). The budget grows with the block, sized from
 * the memory goal of 1 KB per point (issue 21): QC_PACKED_POINTS_PER_POINT
 * motif points per skeleton point (a built-in motif of up to 18 points at
 * the lattices' 1.35-1.45 pebbles per point fits), and never less than
 * QC_MAX_PACKED_POINTS, so a small block may carry a detailed motif. */
int qc_deco_packing(qc_ctx *ctx, const qc_region *region, const qc_params *params,
                    const qc_skeleton *skel, const qc_motif_set *motifs,
                    qc_path *out, qc_stats *stats);
#define QC_MAX_PACKED_POINTS 4000000u
#define QC_PACKED_POINTS_PER_POINT 28u
#define QC_PACKED_POINTS_BUDGET(n)                                         \
    ((double)(n) * QC_PACKED_POINTS_PER_POINT > (double)QC_MAX_PACKED_POINTS \
         ? (double)(n) * QC_PACKED_POINTS_PER_POINT                          \
         : (double)QC_MAX_PACKED_POINTS)
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
/* Meander: one closed curve grown to fill the region (meander.c). */
int qc_deco_meander(qc_ctx *ctx, const qc_region *region, const qc_params *params,
                    const qc_skeleton *skel, const qc_motif_set *motifs,
                    qc_path *out, qc_stats *stats);

#ifdef __cplusplus
}
#endif
#endif
