/*
 * Stitches outside the region: every segment sampled along its length (not
 * only its ends), against the region grown by a tolerance, so a line that
 * cuts a hole's corner or jumps a notch between two inside points shows.
 */
#include <math.h>

#include "measure_internal.h"
#include "region_index.h"

#define STEP_DEFAULT_MM 0.254 /* 0.01 in */

/* Whether p lies outside region grown by tol; *depth its boundary distance. */
static int out_at(const qc__rindex *ix, const qc_region *region, qc_vec2 p, double tol,
                  double *depth)
{
    if (qc__rindex_contains(ix, p) || qc__rindex_near(ix, p, tol))
        return 0;
    *depth = qc_region_boundary_distance(region, p);
    return 1;
}

/* Samples segment ab; returns whether some sample is outside. */
static int segment_out(const qc__rindex *ix, const qc_region *region, qc_vec2 a, qc_vec2 b,
                       double tol, double step, double *worst, qc_vec2 *first, int *have)
{
    double len = qc_hypot(b.x - a.x, b.y - a.y), m = ceil(len / step), depth;
    size_t k, mm = m < 1.0 ? 1 : (m < 1e7 ? (size_t)m : 10000000u);
    int any = 0;

    for (k = 0; k <= mm; k++) {
        double t = (double)k / (double)mm;
        qc_vec2 p;
        p.x = a.x + (b.x - a.x) * t;
        p.y = a.y + (b.y - a.y) * t;
        if (!out_at(ix, region, p, tol, &depth))
            continue;
        any = 1;
        if (depth > *worst)
            *worst = depth;
        if (!*have) {
            *have = 1;
            *first = p;
        }
    }
    return any;
}

int qc_path_outside(qc_ctx *ctx, const qc_region *region, const qc_vec2 *pts, size_t n,
                    const uint32_t *ends, size_t nends, double tol_mm, double step_mm,
                    size_t *segments, double *worst_mm, qc_vec2 *first)
{
    qc__rindex ix;
    size_t q, b = 0, i, count = 0, np = ends != NULL ? nends : 1;
    double worst = 0.0;
    qc_vec2 at = {0.0, 0.0};
    int have = 0;

    if (region == NULL || region->nrings == 0 || segments == NULL || (pts == NULL && n > 0))
        return qc__fail(ctx, QC_EINVAL, "outside measure: no region, points or output");
    if (!(tol_mm >= 0.0) || !(tol_mm < HUGE_VAL))
        return qc__fail(ctx, QC_EINVAL, "outside measure: tolerance %g mm must be >= 0",
                        tol_mm);
    if (!(step_mm > 0.0))
        step_mm = STEP_DEFAULT_MM;
    for (i = 0; i < n; i++)
        if (!isfinite(pts[i].x) || !isfinite(pts[i].y))
            return qc__fail(ctx, QC_ERANGE, "outside measure: point %lu is not finite",
                            (unsigned long)i);
    QC__TRY(qc__rindex_build(ctx, region, &ix));
    for (q = 0; q < np; q++) {
        size_t e = ends != NULL ? ends[q] : n;
        if (e > n)
            e = n;
        if (e == b + 1)
            count += (size_t)segment_out(&ix, region, pts[b], pts[b], tol_mm, step_mm, &worst,
                                         &at, &have);
        for (i = b + 1; i < e; i++)
            count += (size_t)segment_out(&ix, region, pts[i - 1], pts[i], tol_mm, step_mm,
                                         &worst, &at, &have);
        b = e > b ? e : b;
    }
    qc__rindex_free(ctx, &ix);
    *segments = count;
    if (worst_mm != NULL)
        *worst_mm = worst;
    if (first != NULL)
        *first = at;
    return QC_OK;
}
