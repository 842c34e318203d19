/*
 * Stippling (paper §7.1, Fig. 26): the fixed-width outline of the spanning
 * tree (w = d/3 by default) through a centripetal Catmull-Rom spline, which
 * reads as the classic meander; coarse tip arcs, since the spline rounds
 * them (the runner is shared with fill: shared_fill_outline.c).
 */
#include "deco_internal.h"

int qc_deco_stipple(qc_ctx *ctx, const qc_region *region, const qc_params *params,
                    const qc_skeleton *skel, const qc_motif_set *motifs, qc_path *out,
                    qc_stats *stats)
{
    static const qc__outline_style style = {"stipple", QC_PI / 4.0, 1};

    (void)motifs;
    return qc__fill_outline(ctx, region, params, skel, &style, out, stats);
}

/* A third of the spacing wide (fill's fifth, the table's default, reads as lines). */
static int stipple_default(const qc_params *p, int id, double *value)
{
    if (id != QC_PARAM_ID_WIDTH)
        return 0;
    *value = p->spacing / 3.0;
    return 1;
}

const qc_family_desc qc__family_stipple = {
    QC_FAMILY_STIPPLE, "stipple", "the tree outlined through a spline: the meander (paper §7.1)",
    QC_FAMILY_NEEDS_POINTS | QC_FAMILY_NEEDS_TREE, QC__FILL_PARAMS, qc_deco_stipple,
    stipple_default};
