/*
 * Echo (beyond the paper): the region's outline echoed inward (and round
 * each hole outward) every d, starting at the margin: the level sets
 * margin + k d of the distance to the boundary (shared_sdf.c, shared_sdf_rings.c), so
 * concave outlines, holes and rings that split need no special case. The rings are
 * joined into one continuous path (family_echo_join.c): back-and-forth rings
 * joined by ladders of short steps (a closed loop), or a spiral of single
 * steps (an open path from the outside in).
 */
#include <math.h>
#include <string.h>

#include "deco_internal.h"

/* Grid spacing, times d. */
#define GRID 0.25
/* Ladder width and longest ordinary step, times d. */
#define GAP 0.3
#define REACH 2.5
/* The outermost ring keeps at least this from the boundary, times d. */
#define MIN_MARGIN 1e-3
/* Largest-gap raster, times d. */
#define GAP_RES (1.0 / 6.0)

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
    qc__sdf s;
    qc__rings rings;
    qc__join_opts jo;
    qc__join_info info;
    qc_points pts = {0};
    qc_path one = {0};
    qc_vec2 at;
    double d = params->spacing, l0, vmax;
    size_t i, levels;
    int rc;

    (void)skel;
    (void)motifs;
    memset(&s, 0, sizeof s);
    memset(&rings, 0, sizeof rings);
    if (region == NULL || region->nrings == 0)
        return qc__fail(ctx, QC_EEMPTY, "echo: the region has no outline");
    if (!(d > 0.0) || !isfinite(d))
        return qc__fail(ctx, QC_ERANGE, "echo: spacing %g mm must be > 0", d);
    l0 = fmax(params->margin, MIN_MARGIN * d);
    rc = qc__sdf_build(ctx, region, GRID * d, &s);
    if (rc < 0)
        return rc;
    if (s.h > 0.5 * d) {
        rc = qc__fail(ctx, QC_ELIMIT, "echo: spacing %g mm is too fine for a region this "
                      "size (grid %g mm)", d, s.h);
        goto out;
    }
    vmax = qc__sdf_max(&s, &at);
    if (!(vmax > l0)) {
        rc = qc__fail(ctx, QC_EEMPTY, "echo: no ring fits inside the margin of %g mm "
                      "(the region reaches %g mm from its boundary)", l0, fmax(vmax, 0.0));
        goto out;
    }
    levels = (size_t)floor((vmax - l0) / d) + 1;
    rc = qc__sdf_rings(ctx, &s, l0, d, levels, &rings);
    if (rc == QC_OK && rings.end.n == 0)
        rc = qc__fail(ctx, QC_EEMPTY, "echo: no ring fits inside the margin of %g mm", l0);
    if (rc < 0)
        goto out;
    memset(&jo, 0, sizeof jo);
    jo.gap = GAP * d;
    jo.reach = REACH * d;
    jo.start = (uint32_t)qc__nearest_point(rings.pts.v, rings.pts.n, start_point(region, params));
    jo.spiral = params->echo_join == QC_ECHO_SPIRAL;
    jo.sdf = &s;
    jo.vmin = l0;
    rc = qc__rings_join(ctx, &rings, &jo, &pts, &info);
    if (rc < 0)
        goto out;
    rc = qc_path_move_to(ctx, &one, pts.v[0]);
    for (i = 1; i < pts.n && rc == QC_OK; i++)
        rc = qc_path_line_to(ctx, &one, pts.v[i]);
    if (rc == QC_OK && stats != NULL && !params->skip_gap_stat) {
        double g = qc_largest_gap(ctx, region, pts.v, pts.n, GAP_RES * d, NULL);
        if (g < 0.0)
            rc = (int)g;
        else
            stats->largest_gap_mm = g;
        stats->joins_unfixed += info.jumps + info.low;
    }
    if (rc == QC_OK) /* all or nothing: *out as it was on failure */
        rc = qc_path_append(ctx, out, &one, 1);
out:
    qc__sdf_free(ctx, &s);
    qc__rings_free(ctx, &rings);
    qc_points_free(ctx, &pts);
    qc_path_free(ctx, &one);
    return rc;
}

const qc_family_desc qc__family_echo = {
    QC_FAMILY_ECHO, "echo", "the outline echoed inward every d, rings joined into one path", 0,
    QC_PARAM_BIT(QC_PARAM_ID_ECHO_JOIN), qc_deco_echo, NULL};
