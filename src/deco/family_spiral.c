/*
 * Spiral (beyond the paper): the region's offset rings (shared_contour.c,
 * the same rings echo sews), one turn per ring, each turn stepping on to
 * the next ring by a single short step: a spiral shaped by the outline, so
 * it fills corners and narrow strips without leaving the margin and
 * without running back over its own turns. It starts on the ring nearest
 * the centre (the point farthest from the boundary, or start-x/start-y) and
 * winds outward; rings the chain of steps cannot reach (where the region
 * splits) are joined in by ladders (family_echo_join.c), so it stays one
 * path that never crosses itself and sews no place more than twice. Given
 * a start at the boundary (a top's seam), it winds in and back out between
 * its turns, to end beside the start (family_spiral_out.c).
 *
 * Archimedean: rings d apart. Fermat: the ring n turns out from the centre
 * lies d sqrt(n) deep, so every turn adds the same area (pi d^2 on a disc)
 * and the turns close in outward, never more than d apart.
 */
#include "deco_internal.h"

static qc_vec2 centre_of(const qc_params *params, const qc__contour *c)
{
    qc_vec2 p;

    if (qc_params_given(params, QC_PARAM_ID_START_X) ||
        qc_params_given(params, QC_PARAM_ID_START_Y)) {
        p.x = params->start_x;
        p.y = params->start_y;
        return p;
    }
    return c->at_max;
}

/* Whether the start given lies outside the second ring (nearer the
 * boundary than the centre, as where a top enters a patch at a seam): the
 * line then leaves at the boundary too, so the (Archimedean) spiral winds
 * in and out (family_spiral_out.c). Fermat rings crowd at the boundary,
 * too close for the band's steps: they keep the one-arm spiral. */
static int starts_at_boundary(const qc_params *params, const qc__contour *c)
{
    qc_vec2 p;

    if (!qc_params_given(params, QC_PARAM_ID_START_X) &&
        !qc_params_given(params, QC_PARAM_ID_START_Y))
        return 0;
    p = centre_of(params, c);
    return qc__sdf_at(&c->sdf, p) < c->l0 + 0.5 * params->spacing;
}

int qc_deco_spiral(qc_ctx *ctx, const qc_region *region, const qc_params *params,
                   const qc_skeleton *skel, const qc_motif_set *motifs, qc_path *out,
                   qc_stats *stats)
{
    qc__contour c;
    int rc;

    (void)skel;
    (void)motifs;
    QC__TRY(qc__contour_build(ctx, region, params->spacing, params->margin,
                              params->spiral == QC_SPIRAL_FERMAT, "spiral", &c));
    rc = 0;
    if (params->spiral != QC_SPIRAL_FERMAT && starts_at_boundary(params, &c))
        rc = qc__spiral_in_out(ctx, region, params, &c, centre_of(params, &c), out, stats);
    if (rc == 0)
        rc = qc__contour_sew(ctx, region, params, &c, centre_of(params, &c), 1, out, stats);
    qc__contour_free(ctx, &c);
    return rc < 0 ? rc : QC_OK;
}

const qc_family_desc qc__family_spiral = {
    QC_FAMILY_SPIRAL, "spiral", "one spiral from the centre along the outline's offset rings", 0,
    QC_PARAM_BIT(QC_PARAM_ID_SPIRAL), qc_deco_spiral, NULL};
