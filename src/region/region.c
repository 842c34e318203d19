/* Region storage and the queries every stage asks: inside, distance to the boundary, area, box. */
#include <math.h>
#include <string.h>

#include "internal.h"
#include "region_index.h"

void qc_region_free(qc_ctx *ctx, qc_region *r)
{
    if (r == NULL)
        return;
    qc__free(ctx, r->v, r->v_cap * sizeof *r->v);
    qc__free(ctx, r->ring_end, r->ring_cap * sizeof *r->ring_end);
    memset(r, 0, sizeof *r);
}

int qc_region_add_ring(qc_ctx *ctx, qc_region *r, const qc_vec2 *pts, size_t n)
{
    if (n > 1 && pts[0].x == pts[n - 1].x && pts[0].y == pts[n - 1].y)
        n--;
    if (n < 3)
        return qc__fail(ctx, QC_EDEGENERATE, "a ring needs 3 vertices, got %lu",
                        (unsigned long)n);
    if (r->nv + n > UINT32_MAX)
        return qc__fail(ctx, QC_ELIMIT, "region has more than %lu vertices",
                        (unsigned long)UINT32_MAX);
    QC__TRY(QC__RESERVE(ctx, r->v, r->v_cap, r->nv + n));
    QC__TRY(QC__RESERVE(ctx, r->ring_end, r->ring_cap, r->nrings + 1));
    memcpy(r->v + r->nv, pts, n * sizeof *pts);
    r->nv += n;
    r->ring_end[r->nrings++] = (uint32_t)r->nv;
    return QC_OK;
}

int qc__ray_edge(qc_vec2 p, qc_vec2 a, qc_vec2 b)
{
    double cross = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);

    if (cross == 0.0 && p.x >= fmin(a.x, b.x) && p.x <= fmax(a.x, b.x) &&
        p.y >= fmin(a.y, b.y) && p.y <= fmax(a.y, b.y))
        return 2;
    return (a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
}

int qc_region_contains(const qc_region *r, qc_vec2 p)
{
    size_t k, start = 0;
    int inside = 0;

    for (k = 0; k < r->nrings; k++) {
        size_t end = r->ring_end[k], i, j = end - 1;

        for (i = start; i < end; j = i++) {
            int m = qc__ray_edge(p, r->v[j], r->v[i]);
            if (m == 2) /* on the edge counts as inside */
                return 1;
            inside ^= m;
        }
        start = end;
    }
    return inside;
}

double qc_region_boundary_distance(const qc_region *r, qc_vec2 p)
{
    size_t k, start = 0;
    double best = HUGE_VAL;

    for (k = 0; k < r->nrings; k++) {
        size_t end = r->ring_end[k], i, j = end - 1;

        for (i = start; i < end; j = i++)
            best = fmin(best, qc__seg_dist2(p, r->v[j], r->v[i]));
        start = end;
    }
    return sqrt(best);
}

double qc_region_area(const qc_region *r)
{
    size_t k, start = 0;
    double area = 0.0;

    for (k = 0; k < r->nrings; k++) {
        size_t end = r->ring_end[k], i, j = end - 1;

        for (i = start; i < end; j = i++)
            area += r->v[j].x * r->v[i].y - r->v[i].x * r->v[j].y;
        start = end;
    }
    return area * 0.5;
}

qc_bbox qc_region_bbox(const qc_region *r)
{
    qc_bbox b = {{0.0, 0.0}, {0.0, 0.0}};
    size_t i;

    if (r->nv == 0)
        return b;
    b.min = b.max = r->v[0];
    for (i = 1; i < r->nv; i++) {
        b.min.x = fmin(b.min.x, r->v[i].x);
        b.min.y = fmin(b.min.y, r->v[i].y);
        b.max.x = fmax(b.max.x, r->v[i].x);
        b.max.y = fmax(b.max.y, r->v[i].y);
    }
    return b;
}

int qc_region_copy(qc_ctx *ctx, qc_region *dst, const qc_region *src)
{
    memset(dst, 0, sizeof *dst);
    if (src->nv == 0)
        return QC_OK;
    dst->v = qc__alloc_array(ctx, src->nv, sizeof *dst->v);
    dst->ring_end = qc__alloc_array(ctx, src->nrings, sizeof *dst->ring_end);
    if (dst->v == NULL || dst->ring_end == NULL) {
        qc__free(ctx, dst->v, src->nv * sizeof *dst->v);
        qc__free(ctx, dst->ring_end, src->nrings * sizeof *dst->ring_end);
        memset(dst, 0, sizeof *dst);
        return QC_ENOMEM;
    }
    memcpy(dst->v, src->v, src->nv * sizeof *dst->v);
    memcpy(dst->ring_end, src->ring_end, src->nrings * sizeof *dst->ring_end);
    dst->nv = dst->v_cap = src->nv;
    dst->nrings = dst->ring_cap = src->nrings;
    return QC_OK;
}

void qc_region_translate(qc_region *r, double dx, double dy)
{
    size_t i;

    for (i = 0; i < r->nv; i++) {
        r->v[i].x += dx;
        r->v[i].y += dy;
    }
}
