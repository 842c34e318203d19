/* qc_sample: checks the request against the limits, then dispatches by kind. */
#include <math.h>

#include "sample_internal.h"

/* Area each point stands for. Poisson uses the densest packing (hexagonal),
 * an upper bound on the count. */
static double area_per_point(int kind, double d)
{
    switch (kind) {
    case QC_SAMPLE_SQUARE: return d * d;
    case QC_SAMPLE_TRIANGLE:
    case QC_SAMPLE_POISSON: return d * d * 0.8660254037844386;
    case QC_SAMPLE_HEX: return d * d * 1.299038105676658;
    case QC_SAMPLE_SNUB: return d * d * 0.9330127018922193; /* (2 + sqrt 3) / 4 */
    default: return 0.0;
    }
}

double qc_sample_estimate(const qc_region *region, const qc_sample_params *params)
{
    double cell = area_per_point(params->kind, params->spacing);

    if (!(cell > 0.0))
        return 0.0;
    return fabs(qc_region_area(region)) / cell;
}

int qc__sample_check(qc_ctx *ctx, const qc_region *region, const qc_sample_params *sp)
{
    size_t limit = sp->max_points ? sp->max_points : QC_MAX_POINTS;
    double est, box_count;
    qc_bbox box;

    if (region == NULL || region->nrings == 0)
        return qc__fail(ctx, QC_EEMPTY, "the region has no outline");

    if (sp->kind < QC_SAMPLE_TRIANGLE || sp->kind > QC_SAMPLE_POISSON)
        return qc__fail(ctx, QC_EINVAL, "unknown point distribution %d", sp->kind);
    if (!(sp->spacing > 0.0) || !(sp->spacing < 1e6))
        return qc__fail(ctx, QC_ERANGE, "spacing %g mm must be positive and finite", sp->spacing);
    if (!(sp->margin >= 0.0) || !(sp->margin < 1e6))
        return qc__fail(ctx, QC_ERANGE, "margin %g mm must be zero or more and finite",
                        sp->margin);
    if (region->nrings > QC_MAX_REGION_RINGS)
        return qc__fail(ctx, QC_ELIMIT,
                        "the region has %lu outlines and holes, over the limit of %u",
                        (unsigned long)region->nrings, QC_MAX_REGION_RINGS);
    est = qc_sample_estimate(region, sp);
    if (est > (double)limit)
        return qc__fail(ctx, QC_ELIMIT,
                        "about %.0f points at spacing %g mm exceed the limit of %lu; "
                        "raise the spacing", est, sp->spacing, (unsigned long)limit);
    /* the lattice is walked over the whole box: bound that too */
    box = qc_region_bbox(region);
    box_count = (box.max.x - box.min.x + 2 * sp->spacing) *
                (box.max.y - box.min.y + 2 * sp->spacing) /
                area_per_point(sp->kind, sp->spacing);
    if (box_count > 64.0 * (double)limit)
        return qc__fail(ctx, QC_ELIMIT,
                        "the region's box holds about %.0f lattice sites at spacing %g mm; "
                        "raise the spacing", box_count, sp->spacing);
    return QC_OK;
}

int qc__sample_fill(qc_ctx *ctx, const qc__rindex *ix, const qc_sample_params *params,
                    qc_points *out)
{
    size_t n0 = out->n;
    int rc;

    if (params->kind == QC_SAMPLE_POISSON)
        rc = qc__sample_poisson(ctx, ix, params->spacing, params->margin, params->seed,
                                params->poisson_k > 0 ? params->poisson_k : 30, out);
    else
        rc = qc__sample_lattice(ctx, ix, params->kind, params->spacing, params->margin, out);
    if (rc < 0)
        out->n = n0;
    return rc;
}

int qc_sample(qc_ctx *ctx, const qc_region *region, const qc_sample_params *params,
              qc_points *out)
{
    qc__rindex ix;
    int rc; /* on error out is as on entry (core.h) */

    QC__TRY(qc__sample_check(ctx, region, params));
    QC__TRY(qc__rindex_build(ctx, region, &ix));
    rc = qc__sample_fill(ctx, &ix, params, out);
    qc__rindex_free(ctx, &ix);
    return rc;
}
