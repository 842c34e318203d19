/*
 * Echo (beyond the paper): the region's outline echoed inward (and round
 * each hole outward) every d, starting at the margin: the level sets
 * margin + k d of the distance to the boundary (shared_contour.c), so
 * concave outlines, holes and rings that split need no special case. The rings are
 * joined into one continuous path (family_echo_join.c): back-and-forth rings
 * joined by ladders of short steps (a closed loop), or a spiral of single
 * steps (an open path from the outside in).
 */
#include <string.h>

#include "deco_internal.h"

static qc_vec2 start_point(const qc_region *region, const qc_params *params)
{
    qc_vec2 s;

    if (qc_params_given(params, QC_PARAM_ID_START_X) ||
        qc_params_given(params, QC_PARAM_ID_START_Y)) {
        s.x = params->start_x;
        s.y = params->start_y;
    } else {
        s = qc_region_bbox(region).min;
    }
    return s;
}

int qc_deco_echo(qc_ctx *ctx, const qc_region *region, const qc_params *params,
                 const qc_skeleton *skel, const qc_motif_set *motifs, qc_path *out,
                 qc_stats *stats)
{
    qc__contour c;
    int rc;

    (void)skel;
    (void)motifs;
    QC__TRY(qc__contour_build(ctx, region, params->spacing, params->margin, 0, "echo", &c));
    rc = qc__contour_sew(ctx, region, params, &c, start_point(region, params),
                         params->echo_join == QC_ECHO_SPIRAL, out, stats);
    qc__contour_free(ctx, &c);
    return rc;
}

const qc_family_desc qc__family_echo = {
    QC_FAMILY_ECHO, "echo", "the outline echoed inward every d, rings joined into one path", 0,
    QC_PARAM_BIT(QC_PARAM_ID_ECHO_JOIN), qc_deco_echo, NULL};
