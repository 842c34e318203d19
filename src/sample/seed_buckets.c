/*
 * Seed cells filed in square buckets of b cells, so a cell's nearest seed
 * is looked for among the few seeds round it rather than cell by cell: the
 * value a distance transform of the seeded raster gives the cell, for a
 * few cells (holes.c, medial.c).
 */
#include <string.h>

#include "sample_internal.h"
#include "../measure/measure_internal.h"

void qc__seed_buckets_free(qc_ctx *ctx, qc__seed_buckets *sb)
{
    qc__free(ctx, sb->start, ((size_t)(sb->bx * sb->by) + 1) * sizeof *sb->start);
    qc__free(ctx, sb->xy, 2 * (sb->n ? sb->n : 1) * sizeof *sb->xy);
}

int qc__seed_buckets_build(qc_ctx *ctx, size_t nx, size_t ny, const size_t *cell, size_t n,
                           long b, qc__seed_buckets *sb)
{
    size_t k, nb;

    sb->b = b;
    sb->bx = ((long)nx + b - 1) / b;
    sb->by = ((long)ny + b - 1) / b;
    sb->n = n;
    nb = (size_t)(sb->bx * sb->by);
    sb->start = qc__alloc_array(ctx, nb + 1, sizeof *sb->start);
    sb->xy = qc__alloc_array(ctx, 2 * (sb->n ? sb->n : 1), sizeof *sb->xy);
    if (sb->start == NULL || sb->xy == NULL) {
        qc__seed_buckets_free(ctx, sb);
        return QC_ENOMEM;
    }
    memset(sb->start, 0, (nb + 1) * sizeof *sb->start);
    for (k = 0; k < n; k++) /* counted, */
        sb->start[(long)(cell[k] / nx) / b * sb->bx + (long)(cell[k] % nx) / b + 1]++;
    for (k = 0; k < nb; k++) /* summed, */
        sb->start[k + 1] += sb->start[k];
    for (k = 0; k < n; k++) { /* filed (start[q] runs one bucket ahead meanwhile) */
        long x = (long)(cell[k] % nx), y = (long)(cell[k] / nx);
        uint32_t at = sb->start[y / b * sb->bx + x / b]++;
        sb->xy[2 * at] = x;
        sb->xy[2 * at + 1] = y;
    }
    for (k = nb; k > 0; k--)
        sb->start[k] = sb->start[k - 1];
    sb->start[0] = 0;
    return QC_OK;
}

/* Cell (i, j)'s squared distance to the nearest cell of bucket (x, y). */
static double box_dist2(const qc__seed_buckets *sb, long x, long y, long i, long j)
{
    long x0 = x * sb->b, y0 = y * sb->b, dx = 0, dy = 0;

    if (i < x0)
        dx = x0 - i;
    else if (i > x0 + sb->b - 1)
        dx = i - (x0 + sb->b - 1);
    if (j < y0)
        dy = y0 - j;
    else if (j > y0 + sb->b - 1)
        dy = j - (y0 + sb->b - 1);
    return (double)dx * (double)dx + (double)dy * (double)dy;
}

/* Looks in square rings of buckets outward until no nearer seed can lie
 * beyond (a seed outside rings 0..R lies more than R b cells away). */
double qc__seed_dist2(const qc__seed_buckets *sb, long i, long j)
{
    long bi = i / sb->b, bj = j / sb->b, r, x, y;
    double best = (double)(float)QC__GAP_FAR;

    for (r = 0; r <= sb->bx || r <= sb->by; r++) {
        double reach = (double)((r - 1) * sb->b);
        if (r > 0 && reach * reach >= best)
            break;
        for (y = bj - r; y <= bj + r; y++) {
            long step = (y == bj - r || y == bj + r) ? 1 : 2 * r;
            if (y < 0 || y >= sb->by)
                continue;
            for (x = bi - r; x <= bi + r; x += step > 0 ? step : 1) {
                uint32_t s, e;
                if (x < 0 || x >= sb->bx || box_dist2(sb, x, y, i, j) >= best)
                    continue; /* off the raster, or every seed in it no nearer */
                for (s = sb->start[y * sb->bx + x], e = sb->start[y * sb->bx + x + 1]; s < e;
                     s++) {
                    double dx = (double)(sb->xy[2 * s] - i), dy = (double)(sb->xy[2 * s + 1] - j);
                    double d2 = dx * dx + dy * dy;
                    best = d2 < best ? d2 : best;
                }
            }
        }
    }
    return best;
}
