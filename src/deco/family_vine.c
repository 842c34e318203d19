/*
 * The vine (paper §4.3): the skeleton's visiting order smoothed by a
 * centripetal Catmull-Rom spline. A tree walk runs down and back each
 * branch; a tour closes on itself.
 */
#include "internal.h"

int qc_deco_vine(qc_ctx *ctx, const qc_region *region, const qc_params *params,
                 const qc_skeleton *skel, const qc_motif_set *motifs, qc_path *out,
                 qc_stats *stats)
{
    qc_points pts = {0};
    size_t i;
    int rc = QC_OK;

    (void)region;
    (void)params;
    (void)motifs;
    (void)stats;
    if (skel->norder == 0)
        return qc__fail(ctx, QC_EEMPTY, "the vine needs at least one point");
    for (i = 0; i < skel->norder && rc == QC_OK; i++)
        rc = qc_points_push(ctx, &pts, skel->p[skel->order[i]]);
    if (rc == QC_OK && pts.n == 1) /* a lone point: a tiny stitch in place */
        rc = qc_path_move_to(ctx, out, pts.v[0]);
    else if (rc == QC_OK)
        rc = qc_curve_catmull_rom(ctx, pts.v, pts.n, skel->edges == NULL, out);
    qc_points_free(ctx, &pts);
    return rc;
}

const qc_family_desc qc__family_vine = {
    QC_FAMILY_VINE, "vine", "the skeleton's walk smoothed into one vine (paper §4.3)",
    QC_FAMILY_NEEDS_POINTS, 0, qc_deco_vine, NULL};
