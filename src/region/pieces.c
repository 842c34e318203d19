/*
 * qc_region_pieces: a region of separate pieces (two squares, the letters
 * "OB", the patches of one SVG shape) as one region per piece, so each is
 * sewn on its own and nothing is stitched across the gap between them.
 */
#include <math.h>
#include <string.h>

#include "region_index.h"

static size_t ring_start(const qc_region *r, size_t k)
{
    return k ? r->ring_end[k - 1] : 0;
}

static double ring_area(const qc_region *r, size_t k)
{
    size_t s = ring_start(r, k), e = r->ring_end[k], i, j = e - 1;
    double a = 0;

    for (i = s; i < e; j = i++)
        a += (r->v[j].x - r->v[s].x) * (r->v[i].y - r->v[s].y) -
             (r->v[i].x - r->v[s].x) * (r->v[j].y - r->v[s].y);
    return a / 2;
}

/* Whether ring k lies inside ring q: normalized rings neither cross nor
 * touch, so one vertex decides. */
static int ring_inside(const qc_region *r, size_t k, size_t q)
{
    size_t s = ring_start(r, q), e = r->ring_end[q], i, j = e - 1;
    qc_vec2 p = r->v[ring_start(r, k)];
    int in = 0;

    for (i = s; i < e; j = i++)
        in ^= qc__ray_edge(p, r->v[j], r->v[i]) & 1;
    return in;
}

/* The outer ring that directly holds ring k (the smallest containing one
 * of positive area), or k itself when k is outer. */
static size_t owner(const qc_region *r, const double *area, const qc_bbox *box, size_t k)
{
    size_t q, best = k;

    if (area[k] > 0)
        return k;
    for (q = 0; q < r->nrings; q++) {
        if (q == k || area[q] <= 0 || box[k].min.x < box[q].min.x ||
            box[k].min.y < box[q].min.y || box[k].max.x > box[q].max.x ||
            box[k].max.y > box[q].max.y)
            continue;
        if ((best == k || area[q] < area[best]) && ring_inside(r, k, q))
            best = q;
    }
    return best;
}

void qc_region_pieces_free(qc_ctx *ctx, qc_region *pieces, size_t n)
{
    size_t i;

    if (pieces == NULL)
        return;
    for (i = 0; i < n; i++)
        qc_region_free(ctx, &pieces[i]);
    qc__free(ctx, pieces, n * sizeof *pieces);
}

int qc_region_pieces(qc_ctx *ctx, const qc_region *r, qc_region **pieces, size_t *n)
{
    double *area = NULL;
    qc_bbox *box = NULL;
    size_t *piece_of = NULL, k, np = 0;
    qc_region *out = NULL;
    int rc = QC_ENOMEM;

    *pieces = NULL;
    *n = 0;
    if (r == NULL || r->nrings == 0)
        return qc__fail(ctx, QC_EEMPTY, "the region has no ring");
    area = (double *)qc__alloc_array(ctx, r->nrings, sizeof *area);
    box = (qc_bbox *)qc__alloc_array(ctx, r->nrings, sizeof *box);
    piece_of = (size_t *)qc__alloc_array(ctx, r->nrings, sizeof *piece_of);
    if (area == NULL || box == NULL || piece_of == NULL)
        goto out_free;
    for (k = 0; k < r->nrings; k++) {
        area[k] = ring_area(r, k);
        box[k] = qc__points_bbox(r->v + ring_start(r, k), r->ring_end[k] - ring_start(r, k));
        if (area[k] > 0)
            piece_of[k] = np++;
    }
    if (np == 0) {
        rc = qc__fail(ctx, QC_EEMPTY, "the region has no outer ring");
        goto out_free;
    }
    out = (qc_region *)qc__alloc_array(ctx, np, sizeof *out);
    if (out == NULL)
        goto out_free;
    memset(out, 0, np * sizeof *out);
    for (k = 0; k < r->nrings; k++) {
        size_t o = owner(r, area, box, k);

        if (area[o] <= 0)
            continue; /* a hole with no outer ring: not normalized input */
        rc = qc_region_add_ring(ctx, &out[piece_of[o]], r->v + ring_start(r, k),
                                r->ring_end[k] - ring_start(r, k));
        if (rc < 0) {
            qc_region_pieces_free(ctx, out, np);
            out = NULL;
            goto out_free;
        }
    }
    *pieces = out;
    *n = np;
    rc = QC_OK;
out_free:
    qc__free(ctx, area, r->nrings * sizeof *area);
    qc__free(ctx, box, r->nrings * sizeof *box);
    qc__free(ctx, piece_of, r->nrings * sizeof *piece_of);
    return rc;
}
