/* Rasterising regions (scanline inside masks) and the 1-D exact distance
 * transform: the measures and the echo/spiral offsetting (deco/sdf.c). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "internal.h"

/* Rows j whose y = y0 + j h satisfies lo <= y < hi, clamped to [0, ny). */
static void row_span(double lo, double hi, double y0, double h, size_t ny, size_t *j0,
                     size_t *j1)
{
    double a = ceil((lo - y0) / h) - 1.0, b = ceil((hi - y0) / h) + 1.0;

    a = a < 0.0 ? 0.0 : a;
    b = b > (double)ny ? (double)ny : b;
    *j0 = (size_t)a;
    *j1 = b > a ? (size_t)b : *j0;
}

static int cmp_double(const void *pa, const void *pb)
{
    double a = *(const double *)pa, b = *(const double *)pb;
    return (a > b) - (a < b);
}

/* Sorts a row's crossings: by insertion when few (most rows cross an
 * outline a few times; a qsort call costs more than the sort), else
 * qsort. Either way the same ascending values. */
#define FEW_CROSSINGS 16
static void sort_crossings(double *x, size_t n)
{
    size_t i, k;

    if (n > FEW_CROSSINGS) {
        qsort(x, n, sizeof *x, cmp_double);
        return;
    }
    for (i = 1; i < n; i++) {
        double t = x[i];
        for (k = i; k > 0 && x[k - 1] > t; k--)
            x[k] = x[k - 1];
        x[k] = t;
    }
}

/* Where the region's edges cross each row's line y0 + j h: with xs NULL
 * counts them into start[j + 1], else stores their x at start[j]++. */
static void row_crossings(const qc_region *region, double y0, double h, size_t ny,
                          size_t *start, double *xs)
{
    size_t k, rs = 0, j;

    for (k = 0; k < region->nrings; k++) {
        size_t end = region->ring_end[k], i, p = end - 1;

        for (i = rs; i < end; p = i++) {
            qc_vec2 a = region->v[p], b = region->v[i];
            size_t j0, j1;

            row_span(fmin(a.y, b.y), fmax(a.y, b.y), y0, h, ny, &j0, &j1);
            for (j = j0; j < j1; j++) {
                double y = y0 + (double)j * h;
                if ((a.y > y) == (b.y > y))
                    continue;
                if (xs == NULL)
                    start[j + 1]++;
                else
                    xs[start[j]++] = a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y);
            }
        }
        rs = end;
    }
}

int qc__raster_inside(qc_ctx *ctx, const qc_region *region, double x0, double y0,
                      double h, size_t nx, size_t ny, unsigned char *mask)
{
    size_t *start, j, total = 0;
    double *xs;

    memset(mask, 0, nx * ny);
    start = qc__alloc_array(ctx, ny + 1, sizeof *start);
    if (start == NULL)
        return QC_ENOMEM;
    memset(start, 0, (ny + 1) * sizeof *start);
    row_crossings(region, y0, h, ny, start, NULL);
    for (j = 0; j < ny; j++)
        start[j + 1] += start[j];
    total = start[ny];
    xs = qc__alloc_array(ctx, total ? total : 1, sizeof *xs);
    if (xs == NULL) {
        qc__free(ctx, start, (ny + 1) * sizeof *start);
        return QC_ENOMEM;
    }
    row_crossings(region, y0, h, ny, start, xs);
    /* start[j] now ends row j; row j begins at start[j - 1] */
    for (j = ny; j-- > 0;) {
        size_t b = j ? start[j - 1] : 0, e = start[j], c;

        sort_crossings(xs + b, e - b);
        for (c = b; c + 1 < e; c += 2) {
            double lo = ceil((xs[c] - x0) / h), hi = ceil((xs[c + 1] - x0) / h);

            lo = lo < 0.0 ? 0.0 : lo;
            hi = hi > (double)nx ? (double)nx : hi;
            if (hi > lo) /* the cells lo .. hi - 1 */
                memset(mask + j * nx + (size_t)lo, 1, (size_t)(hi - lo));
        }
    }
    qc__free(ctx, xs, (total ? total : 1) * sizeof *xs);
    qc__free(ctx, start, (ny + 1) * sizeof *start);
    return QC_OK;
}

void qc__edt_1d(const double *f, size_t n, double *d, int *v, double *z)
{
    int k = 0, q, nn = (int)n;
    double *hv = d; /* meanwhile f[v[k]] + v[k]^2 at d[k] (k <= q: d is free till the end) */

    if (nn < 1)
        return;
    v[0] = 0;
    hv[0] = f[0] + 0.0;
    z[0] = -HUGE_VAL;
    z[1] = HUGE_VAL;
    for (q = 1; q < nn; q++) {
        double hq = f[q] + (double)q * q, s;

        s = (hq - hv[k]) / (2.0 * (q - v[k]));
        while (s <= z[k]) { /* z[0] = -inf stops this at k == 0 */
            k--;
            s = (hq - hv[k]) / (2.0 * (q - v[k]));
        }
        k++;
        v[k] = q;
        hv[k] = hq;
        z[k] = s;
        z[k + 1] = HUGE_VAL;
    }
    k = 0;
    for (q = 0; q < nn; q++) {
        double dq;
        while (z[k + 1] < (double)q)
            k++;
        dq = (double)(q - v[k]);
        d[q] = dq * dq + f[v[k]];
    }
}
