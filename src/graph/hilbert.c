/* Insertion order for the Delaunay stage: points sorted along a Hilbert
 * curve over their bounding box, so consecutive insertions are near each
 * other and the point-location walk stays short. */
#include "graph_internal.h"
#include "graph_delaunay.h"

#define HBITS 16u

int qc__hilbert_order(qc_ctx *ctx, const qc_vec2 *p, const uint32_t *idx,
                      size_t m, uint32_t *out)
{
    uint64_t *key;
    double x0, y0, x1, y1, sx, sy, top = (double)((1u << HBITS) - 1);
    size_t i;

    if (m == 0)
        return QC_OK;
    key = qc__alloc_array(ctx, m, sizeof *key);
    if (key == NULL)
        return qc__fail(ctx, QC_ENOMEM, "delaunay: Hilbert keys for %lu points",
                        (unsigned long)m);
    x0 = x1 = p[idx[0]].x;
    y0 = y1 = p[idx[0]].y;
    for (i = 1; i < m; i++) {
        qc_vec2 q = p[idx[i]];
        x0 = q.x < x0 ? q.x : x0;
        x1 = q.x > x1 ? q.x : x1;
        y0 = q.y < y0 ? q.y : y0;
        y1 = q.y > y1 ? q.y : y1;
    }
    /* Halve before subtracting so huge extents cannot overflow to inf. */
    sx = x1 * 0.5 - x0 * 0.5 > 0.0 ? top / (x1 * 0.5 - x0 * 0.5) * 0.5 : 0.0;
    sy = y1 * 0.5 - y0 * 0.5 > 0.0 ? top / (y1 * 0.5 - y0 * 0.5) * 0.5 : 0.0;
    for (i = 0; i < m; i++) {
        qc_vec2 q = p[idx[i]];
        double fx = (q.x - x0) * sx, fy = (q.y - y0) * sy;
        uint32_t hx = fx >= top ? (uint32_t)top : fx > 0.0 ? (uint32_t)fx : 0;
        uint32_t hy = fy >= top ? (uint32_t)top : fy > 0.0 ? (uint32_t)fy : 0;

        key[i] = qc__hilbert_key(hx, hy, HBITS) << 32 | (uint64_t)i;
    }
    if (qc__radix_sort(ctx, key, NULL, m, 32) < 0) {
        qc__free(ctx, key, m * sizeof *key);
        return QC_ENOMEM;
    }
    for (i = 0; i < m; i++)
        out[i] = idx[(uint32_t)key[i]];
    qc__free(ctx, key, m * sizeof *key);
    return QC_OK;
}
