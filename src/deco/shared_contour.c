/*
 * Offset contours of a region, joined into one path: echo and spiral.
 * The distance grid (shared_sdf.c) gives the level sets margin + k d,
 * outermost first (shared_sdf_rings.c), and family_echo_join.c joins them
 * by ladders, spurs and (spiral mode) tails, so the path never crosses
 * itself and sews each place at most twice. Equal-area levels put the
 * rings d sqrt(n) in from the deepest point instead, as a Fermat spiral
 * spaces its turns.
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
/* Equal-area levels are traced one by one (a pass over the grid each) and
 * crowd outward (the outermost d / (2 sqrt n) apart), so the joins slow down:
 * 400 rings (a 10 in circle at 0.25 in) take about 3 s. */
#define MAX_AREA_LEVELS 400

void qc__contour_free(qc_ctx *ctx, qc__contour *c)
{
    qc__sdf_free(ctx, &c->sdf);
    qc__rings_free(ctx, &c->rings);
}

/* Levels l0 + d (u - sqrt(u^2 - k)), u = (vmax - l0) / d: ring k encloses
 * (on a disc) k pi d^2 less than the outermost; the innermost lies within
 * d of the deepest point and no two are more than d apart. */
static int area_levels(qc_ctx *ctx, qc__contour *c, double d, const char *who)
{
    double u = (c->vmax - c->l0) / d, n = floor(u * u - 1e-9) + 1.0;
    size_t k, lv;

    if (n > MAX_AREA_LEVELS)
        return qc__fail(ctx, QC_ELIMIT, "%s: %.0f equal-area rings (%g mm deep at spacing "
                        "%g mm) exceed the limit of %d", who, n, c->vmax - c->l0, d,
                        MAX_AREA_LEVELS);
    for (lv = 0; lv < (size_t)n; lv++) {
        double depth = sqrt(fmax(u * u - (double)lv, 0.0));
        double next = sqrt(fmax(u * u - (double)lv - 1.0, 0.0));
        size_t first = c->rings.end.n;

        QC__TRY(qc__sdf_rings(ctx, &c->sdf, c->l0 + d * (u - depth), d * (depth - next) + 1e-9 * d,
                              1, &c->rings));
        for (k = first; k < c->rings.end.n; k++)
            c->rings.level.i[k] = (uint32_t)lv;
    }
    return QC_OK;
}

int qc__contour_build(qc_ctx *ctx, const qc_region *region, double d, double margin,
                      int equal_area, const char *who, qc__contour *c)
{
    int rc;

    memset(c, 0, sizeof *c);
    if (region == NULL || region->nrings == 0)
        return qc__fail(ctx, QC_EEMPTY, "%s: the region has no outline", who);
    if (!(d > 0.0) || !isfinite(d))
        return qc__fail(ctx, QC_ERANGE, "%s: spacing %g mm must be > 0", who, d);
    c->l0 = fmax(margin, MIN_MARGIN * d);
    if (qc__sdf_step(region, GRID * d) > 0.5 * d) /* before the grid is allocated */
        return qc__fail(ctx, QC_ELIMIT, "%s: spacing %g mm is too fine for a region this "
                        "size (grid %g mm)", who, d, qc__sdf_step(region, GRID * d));
    QC__TRY(qc__sdf_build(ctx, region, GRID * d, &c->sdf));
    c->vmax = qc__sdf_max(&c->sdf, &c->at_max);
    if (!(c->vmax > c->l0)) {
        rc = qc__fail(ctx, QC_EEMPTY, "%s: no ring fits inside the margin of %g mm "
                      "(the region reaches %g mm from its boundary)", who, c->l0,
                      fmax(c->vmax, 0.0));
        goto fail;
    }
    if (equal_area)
        rc = area_levels(ctx, c, d, who);
    else
        rc = qc__sdf_rings(ctx, &c->sdf, c->l0, d,
                           (size_t)floor((c->vmax - c->l0) / d) + 1, &c->rings);
    if (rc == QC_OK && c->rings.end.n == 0)
        rc = qc__fail(ctx, QC_EEMPTY, "%s: no ring fits inside the margin of %g mm", who, c->l0);
    if (rc == QC_OK)
        rc = qc__contour_cap_peaks(ctx, c, d);
    if (rc == QC_OK)
        return QC_OK;
fail:
    qc__contour_free(ctx, c);
    return rc;
}

int qc__contour_sew(qc_ctx *ctx, const qc_region *region, const qc_params *params,
                    const qc__contour *c, qc_vec2 start, int spiral, qc_path *out,
                    qc_stats *stats)
{
    qc__join_opts jo;
    qc__join_info info;
    qc_points pts = {0};
    qc_path one = {0};
    double d = params->spacing;
    size_t i;
    int rc;

    memset(&jo, 0, sizeof jo);
    jo.gap = GAP * d;
    jo.reach = REACH * d;
    jo.start = (uint32_t)qc__nearest_point(c->rings.pts.v, c->rings.pts.n, start);
    jo.spiral = spiral;
    jo.sdf = &c->sdf;
    jo.vmin = c->l0;
    rc = qc__rings_join(ctx, &c->rings, &jo, &pts, &info);
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
    qc_points_free(ctx, &pts);
    qc_path_free(ctx, &one);
    return rc;
}
