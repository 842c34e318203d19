/*
 * The points a pattern is built on (qc_generate): the fill (lattice or
 * Poisson) and, to carry the stitching out to the seams, a row along every
 * seam with the fill kept clear of it, points in corners and star points
 * and down narrow strips (medial.c), and points in the holes left over
 * (holes.c). docs/coverage.md has the figures.
 */
#include <math.h>

#include "sample_internal.h"

/* Times d: the row's offset inside the boundary; its step along it: for a
 * tree, shorter than the fill keeps from it (ROW_CLEAR), so the spanning
 * tree chains the row (its links are the shortest); for a tour, which
 * follows the row anyway, about the fill's own spacing (a motif at every
 * point: no denser border); and the largest hole left (a line through
 * Poisson points d apart leaves circles of radius d between them; 0.95
 * brings the vine's farthest fabric under d for 10% more points in a large
 * Poisson fill, each still 0.95 d from every other). */
#define ROW_OFFSET 0.4
#define ROW_STEP_TREE 0.6
#define ROW_STEP_TOUR 0.9
#define ROW_CLEAR 0.7
#define HOLE_GAP 0.95

/* The steps after the request's check, over one index of the region. */
static int to_seams(qc_ctx *ctx, const qc_region *region, const qc__rindex *ix,
                    const qc_sample_params *sp, const qc_sample_params *fill_sp, int row,
                    qc_points *out)
{
    qc_points fill = {0};
    double d = sp->spacing, m = sp->margin;
    size_t n0 = out->n;
    int rc;

    if (row == QC__ROW_NONE) {
        rc = qc__sample_fill(ctx, ix, sp, out);
        if (rc == QC_OK)
            rc = qc__sample_medial_ix(ctx, region, ix, d, m, out);
        return rc;
    }
    rc = qc__sample_fill(ctx, ix, fill_sp, &fill);
    if (rc == QC_OK)
        rc = qc__sample_contour(ctx, region, ix, fmax(ROW_OFFSET * d, m),
                                (row == QC__ROW_TOUR ? ROW_STEP_TOUR : ROW_STEP_TREE) * d, m, out);
    if (rc == QC_OK)
        rc = qc__points_append_clear(ctx, out, n0, &fill, ROW_CLEAR * d);
    if (rc == QC_OK)
        rc = qc__sample_medial_ix(ctx, region, ix, d, m, out);
    if (rc == QC_OK)
        rc = qc__sample_fill_holes_ix(ctx, region, ix, d, m, HOLE_GAP * d, out);
    qc_points_free(ctx, &fill);
    return rc;
}

int qc__sample_to_seams(qc_ctx *ctx, const qc_region *region, const qc_sample_params *sp,
                        int row, qc_points *out)
{
    qc_sample_params fill_sp = *sp;
    qc__rindex ix;
    size_t n0 = out->n;
    int rc;

    /* the fill's request is checked (the fill keeps clear of the row) */
    fill_sp.margin = fmax(sp->margin, (ROW_OFFSET + ROW_CLEAR) * sp->spacing);
    QC__TRY(qc__sample_check(ctx, region, row == QC__ROW_NONE ? sp : &fill_sp));
    QC__TRY(qc__rindex_build(ctx, region, &ix));
    rc = to_seams(ctx, region, &ix, sp, &fill_sp, row, out);
    qc__rindex_free(ctx, &ix);
    if (rc < 0)
        out->n = n0;
    return rc;
}
