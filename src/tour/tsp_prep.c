/*
 * TSP preparation: the caller's points sorted along a Hilbert curve (32
 * bits per axis over their bounding box, ties finished by exact (x, y,
 * index)), so duplicates become neighbours and are grouped, and the
 * distinct points are renumbered in curve order for locality.
 */
#include "tour_internal.h"

static uint32_t cell(double v, double lo, double scale)
{
    double f = (v - lo) * scale;

    if (!(f > 0.0))
        return 0;
    return f >= 4294967295.0 ? 4294967295u : (uint32_t)f;
}

/* Exact order of two caller points: x, then y, then index. */
static int before(const qc_vec2 *p, uint32_t a, uint32_t b)
{
    if (p[a].x != p[b].x)
        return p[a].x < p[b].x;
    if (p[a].y != p[b].y)
        return p[a].y < p[b].y;
    return a < b;
}

static void sift(const qc_vec2 *p, uint32_t *v, size_t i, size_t m)
{
    for (;;) {
        size_t c = 2 * i + 1;
        uint32_t t;

        if (c >= m)
            return;
        if (c + 1 < m && before(p, v[c], v[c + 1]))
            c++;
        if (!before(p, v[i], v[c]))
            return;
        t = v[i], v[i] = v[c], v[c] = t;
        i = c;
    }
}

/* Sorts a run of indices whose Hilbert cells tie (heap sort: no allocation,
 * no quadratic case however many points share a cell). */
static void sort_run(const qc_vec2 *p, uint32_t *v, size_t m)
{
    size_t i, j;

    if (m <= 16) {
        for (i = 1; i < m; i++) {
            uint32_t x = v[i];
            for (j = i; j > 0 && before(p, x, v[j - 1]); j--)
                v[j] = v[j - 1];
            v[j] = x;
        }
        return;
    }
    for (i = m / 2; i-- > 0;)
        sift(p, v, i, m);
    for (i = m; i-- > 1;) {
        uint32_t t = v[0];
        v[0] = v[i], v[i] = t;
        sift(p, v, 0, i);
    }
}

int qc__tsp_prepare(qc__tsp *s)
{
    const qc_vec2 *p = s->p;
    size_t n = s->n, i, r, m;
    double x0, y0, x1, y1, sx, sy, w;
    uint64_t *key;
    int rc;

    x0 = x1 = p[0].x;
    y0 = y1 = p[0].y;
    for (i = 1; i < n; i++) {
        x0 = p[i].x < x0 ? p[i].x : x0;
        x1 = p[i].x > x1 ? p[i].x : x1;
        y0 = p[i].y < y0 ? p[i].y : y0;
        y1 = p[i].y > y1 ? p[i].y : y1;
    }
    sx = x1 > x0 ? 4294967295.0 / (x1 - x0) : 0.0;
    sy = y1 > y0 ? 4294967295.0 / (y1 - y0) : 0.0;
    w = x1 - x0 > y1 - y0 ? x1 - x0 : y1 - y0;
    /* distances carry relative errors near 1e-16 of the extent */
    s->eps = w * 1e-12;

    key = qc__alloc_array(s->ctx, n, sizeof *key);
    s->sorted = qc__alloc_array(s->ctx, n, sizeof *s->sorted);
    if (key == NULL || s->sorted == NULL) {
        rc = qc__fail(s->ctx, QC_ENOMEM, "tsp: out of memory ordering %lu points",
                      (unsigned long)n);
        goto out;
    }
    for (i = 0; i < n; i++) {
        key[i] = qc__hilbert_key(cell(p[i].x, x0, sx), cell(p[i].y, y0, sy), 32);
        s->sorted[i] = (uint32_t)i;
    }
    rc = qc__radix_sort(s->ctx, key, s->sorted, n, 0);
    if (rc < 0)
        goto out;
    m = 0;
    for (i = 0; i < n; i = r) {
        for (r = i + 1; r < n && key[r] == key[i]; r++)
            ;
        if (r - i > 1)
            sort_run(p, s->sorted + i, r - i);
        m++;
        for (i++; i < r; i++) /* count the distinct points of the run */
            if (p[s->sorted[i]].x != p[s->sorted[i - 1]].x ||
                p[s->sorted[i]].y != p[s->sorted[i - 1]].y)
                m++;
    }
    s->m = (uint32_t)m;
    s->ustart = qc__alloc_array(s->ctx, m + 1, sizeof *s->ustart);
    s->q = qc__alloc_array(s->ctx, m, sizeof *s->q);
    if (s->ustart == NULL || s->q == NULL) {
        rc = qc__fail(s->ctx, QC_ENOMEM, "tsp: out of memory for %lu distinct points",
                      (unsigned long)m);
        goto out;
    }
    m = 0;
    for (i = 0; i < n; i++) {
        qc_vec2 a = p[s->sorted[i]];
        if (i == 0 || a.x != p[s->sorted[i - 1]].x || a.y != p[s->sorted[i - 1]].y) {
            s->ustart[m] = (uint32_t)i;
            s->q[m] = a;
            m++;
        }
    }
    s->ustart[m] = (uint32_t)n;
out:
    qc__free(s->ctx, key, n * sizeof *key);
    return rc;
}
