/* Small geometric helpers the stages share, so their answers agree to the bit. */
#include <math.h>

#include "internal.h"

qc_bbox qc__points_bbox(const qc_vec2 *p, size_t n)
{
    qc_bbox b;
    size_t i;

    b.min = b.max = p[0];
    for (i = 1; i < n; i++) {
        b.min.x = p[i].x < b.min.x ? p[i].x : b.min.x;
        b.min.y = p[i].y < b.min.y ? p[i].y : b.min.y;
        b.max.x = p[i].x > b.max.x ? p[i].x : b.max.x;
        b.max.y = p[i].y > b.max.y ? p[i].y : b.max.y;
    }
    return b;
}

double qc__fit_cell(qc_bbox box, double cell, double max_cells)
{
    while (((box.max.x - box.min.x) / cell + 1.0) * ((box.max.y - box.min.y) / cell + 1.0) >
           max_cells)
        cell *= 1.5;
    return cell;
}

size_t qc__region_ring_of(const qc_region *r, size_t v)
{
    size_t lo = 0, hi = r->nrings - 1;

    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (r->ring_end[mid] > v)
            hi = mid;
        else
            lo = mid + 1;
    }
    return lo;
}

size_t qc__nearest_point(const qc_vec2 *p, size_t n, qc_vec2 q)
{
    size_t i, best = 0;
    double bd = HUGE_VAL;

    for (i = 0; i < n; i++) {
        double dx = p[i].x - q.x, dy = p[i].y - q.y, dd = dx * dx + dy * dy;

        if (dd < bd) {
            bd = dd;
            best = i;
        }
    }
    return best;
}
