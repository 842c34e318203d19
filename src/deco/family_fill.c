/*
 * Fixed-width fill (paper §7.1, Fig. 26): the spanning tree outlined at
 * width w as one closed, non-crossing loop of straight lines and fine tip
 * arcs (the runner is shared with stippling: shared_fill_outline.c).
 */
#include "deco_internal.h"

int qc_deco_fill(qc_ctx *ctx, const qc_region *region, const qc_params *params,
                 const qc_skeleton *skel, const qc_motif_set *motifs, qc_path *out,
                 qc_stats *stats)
{
    static const qc__outline_style style = {"fill", QC_PI / 16.0, 0};

    (void)motifs;
    return qc__fill_outline(ctx, region, params, skel, &style, out, stats);
}

const qc_family_desc qc__family_fill = {
    QC_FAMILY_FILL, "fill", "the tree outlined at width w as one loop (paper §7.1)",
    QC_FAMILY_NEEDS_POINTS | QC_FAMILY_NEEDS_TREE, QC__FILL_PARAMS, qc_deco_fill, NULL};
