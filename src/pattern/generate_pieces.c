/*
 * A region of separate pieces (two squares, the letters "OB"): each piece
 * is sewn on its own and the pieces are joined by a jump (a MOVE; the
 * stitch plan ties off both ends), never by a stitched line across the gap
 * outside the region. A piece too small for any point is left out.
 */
#include <math.h>
#include <string.h>

#include "pattern_internal.h"

static int positive_rings(const qc_region *r)
{
    size_t k, start = 0, n = 0;

    for (k = 0; k < r->nrings; k++) {
        size_t end = r->ring_end[k], i, j = end - 1;
        double a = 0;

        for (i = start; i < end; j = i++)
            a += (r->v[j].x - r->v[start].x) * (r->v[i].y - r->v[start].y) -
                 (r->v[i].x - r->v[start].x) * (r->v[j].y - r->v[start].y);
        n += a > 0;
        start = end;
    }
    return n > 1;
}

static int merge(qc_ctx *ctx, qc_result *out, const qc_result *sub, double area,
                 double *covered)
{
    uint32_t base = (uint32_t)out->points.n;
    qc_stats *a = &out->stats;
    const qc_stats *b = &sub->stats;
    size_t i;

    for (i = 0; i < sub->points.n; i++)
        QC__TRY(qc_points_push(ctx, &out->points, sub->points.v[i]));
    for (i = 0; i < sub->edges.n; i++)
        QC__TRY(qc_edges_push(ctx, &out->edges, sub->edges.e[i].a + base,
                              sub->edges.e[i].b + base));
    for (i = 0; i < sub->order.n; i++)
        QC__TRY(qc_order_push(ctx, &out->order, sub->order.i[i] + base));
    QC__TRY(qc_path_append(ctx, &out->path, &sub->path, 0));
    a->motifs_placed += b->motifs_placed;
    a->motifs_shrunk += b->motifs_shrunk;
    a->motifs_rotated += b->motifs_rotated;
    a->motifs_flipped += b->motifs_flipped;
    a->motifs_skipped += b->motifs_skipped;
    a->joins_unfixed += b->joins_unfixed;
    if (b->pebbles > 0) {
        a->radius_min = a->pebbles > 0 ? fmin(a->radius_min, b->radius_min) : b->radius_min;
        a->radius_max = fmax(a->radius_max, b->radius_max);
        a->radius_mean = (a->radius_mean * (double)a->pebbles +
                          b->radius_mean * (double)b->pebbles) /
                         (double)(a->pebbles + b->pebbles);
    }
    a->pebbles += b->pebbles;
    a->pebbles_under3 += b->pebbles_under3;
    *covered += b->coverage * area;
    a->largest_gap_mm = fmax(a->largest_gap_mm, b->largest_gap_mm);
    return QC_OK;
}

/* The given points inside piece. */
static int given_in(qc_ctx *ctx, const qc_region *piece, const qc_points *given, qc_points *out)
{
    size_t i;

    for (i = 0; i < given->n; i++)
        if (qc_region_contains(piece, given->v[i]))
            QC__TRY(qc_points_push(ctx, out, given->v[i]));
    return QC_OK;
}

int qc__generate_pieces(qc_ctx *ctx, const qc_region *region, const qc_points *given,
                        const qc_motif_set *motifs, qc_result *out, int *handled)
{
    const qc_params *p = &out->params;
    int use_given = p->points == QC_POINTS_GIVEN && given != NULL && given->n > 0;
    qc_region *pieces = NULL;
    size_t n = 0, k, sewn = 0;
    double covered = 0, area = 0;
    int rc = QC_OK;

    *handled = 0;
    if (region == NULL || region->nrings < 2 || !positive_rings(region))
        return QC_OK;
    if (use_given)
        QC__TRY(qc__check_given_inside(ctx, region, given, p->margin));
    QC__TRY(qc_region_pieces(ctx, region, &pieces, &n));
    *handled = 1;
    for (k = 0; k < n && rc >= 0; k++) {
        qc_result sub;
        qc_points g = {0};
        double a = qc_region_area(&pieces[k]);

        memset(&sub, 0, sizeof sub);
        sub.params = out->params;
        if (use_given)
            rc = given_in(ctx, &pieces[k], given, &g);
        if (rc >= 0 && (!use_given || g.n > 0)) {
            rc = qc__generate_one(ctx, &pieces[k], use_given ? &g : NULL, motifs, &sub);
            if (rc == QC_EEMPTY) { /* nothing fits in this piece: leave it */
                qc_clear_error(ctx);
                rc = QC_OK;
            } else if (rc >= 0) {
                rc = merge(ctx, out, &sub, a, &covered);
                sewn++;
            }
        }
        area += a;
        qc_result_free(ctx, &sub);
        qc_points_free(ctx, &g);
    }
    qc_region_pieces_free(ctx, pieces, n);
    if (rc >= 0 && sewn == 0)
        rc = qc__fail(ctx, QC_EEMPTY,
                      "no piece of the region (%lu pieces) fits a point at spacing %g mm with "
                      "margin %g mm", (unsigned long)n, p->spacing, p->margin);
    if (rc < 0)
        return rc;
    out->stats.coverage = area > 0 ? covered / area : 0;
    qc__path_fit(ctx, &out->path);
    out->stats.points = out->points.n;
    out->stats.edges = out->edges.n;
    out->stats.order = out->order.n;
    qc_curve_measure(&out->path, QC__STATS_TOL_MM, &out->stats.length_mm, &out->stats.bbox);
    out->stats.pieces = qc_path_pieces(&out->path);
    return QC_OK;
}
