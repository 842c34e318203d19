/*
 * The join sewn last, tested on its own before a join's grid query: nearly
 * every join that fails crosses it (the curve arriving at the primitive it
 * leaves), and a direct test finds that without walking the grid's cells.
 * Only a shortcut to "hit": a clear answer still goes to the grid.
 */
#include <math.h>

#include "family_wanderer.h"

static void seg_box(const qc_vec2 *p, qc_bbox *b)
{
    b->min.x = p[0].x < p[1].x ? p[0].x : p[1].x;
    b->max.x = p[0].x < p[1].x ? p[1].x : p[0].x;
    b->min.y = p[0].y < p[1].y ? p[0].y : p[1].y;
    b->max.y = p[0].y < p[1].y ? p[1].y : p[0].y;
}

static int apart(const qc_bbox *a, const qc_bbox *b)
{
    return a->max.x + 1e-9 < b->min.x || b->max.x + 1e-9 < a->min.x ||
           a->max.y + 1e-9 < b->min.y || b->max.y + 1e-9 < a->min.y;
}

/* Whether a's own normal separates segments a and b by more than eps:
 * shared_collide.c's separated_by for two segments, the same arithmetic
 * in the same order (so the same answers), without its generality. */
static int normal_separates(const qc_vec2 *a, const qc_vec2 *b, double eps)
{
    double ax = a[1].y - a[0].y, ay = a[0].x - a[1].x;
    double alo = a[0].x * ax + a[0].y * ay, ahi = alo, blo, bhi, d, len, e;

    d = a[1].x * ax + a[1].y * ay;
    if (d < alo)
        alo = d;
    if (d > ahi)
        ahi = d;
    blo = bhi = b[0].x * ax + b[0].y * ay;
    d = b[1].x * ax + b[1].y * ay;
    if (d < blo)
        blo = d;
    if (d > bhi)
        bhi = d;
    if (!(ahi < blo || bhi < alo))
        return 0;
    len = sqrt(ax * ax + ay * ay);
    if (len < 1e-15)
        return 0;
    e = eps * len;
    return ahi + e < blo || bhi + e < alo;
}

/* qc__convex_touch of two segments whose boxes meet within 1e-9. */
static int segs_touch(const qc_vec2 *a, const qc_vec2 *b)
{
    return !normal_separates(a, b, 1e-9) && !normal_separates(b, a, 1e-9);
}

void qc__wchain_set(qc__wchain *c, const qc_vec2 *pts, size_t n)
{
    size_t k;

    c->n = 0;
    if (n < 2 || n > QC__WCHAIN_MAX + 1)
        return;
    c->p[0] = pts[0];
    for (k = 0; k + 1 < n; k++) {
        qc_bbox *g = &c->grp[k / QC__WCHAIN_GROUP];
        c->p[k + 1] = pts[k + 1];
        seg_box(pts + k, &c->seg[k]);
        if (k % QC__WCHAIN_GROUP == 0)
            *g = c->seg[k];
        if (c->seg[k].min.x < g->min.x)
            g->min.x = c->seg[k].min.x;
        if (c->seg[k].min.y < g->min.y)
            g->min.y = c->seg[k].min.y;
        if (c->seg[k].max.x > g->max.x)
            g->max.x = c->seg[k].max.x;
        if (c->seg[k].max.y > g->max.y)
            g->max.y = c->seg[k].max.y;
    }
    c->all = c->grp[0];
    for (k = 1; k <= (n - 2) / QC__WCHAIN_GROUP; k++) {
        const qc_bbox *g = &c->grp[k];
        c->all.min.x = g->min.x < c->all.min.x ? g->min.x : c->all.min.x;
        c->all.min.y = g->min.y < c->all.min.y ? g->min.y : c->all.min.y;
        c->all.max.x = g->max.x > c->all.max.x ? g->max.x : c->all.max.x;
        c->all.max.y = g->max.y > c->all.max.y ? g->max.y : c->all.max.y;
    }
    c->n = n;
}

int qc__wchain_seg_touch(const qc__wchain *c, const qc_vec2 *s)
{
    size_t grp, m;
    qc_bbox sb;

    if (c->n < 2)
        return 0;
    seg_box(s, &sb);
    if (apart(&sb, &c->all)) /* the whole chain's box first */
        return 0;
    /* from the chain's end, where the crossings are; a group's box first */
    for (grp = (c->n - 2) / QC__WCHAIN_GROUP + 1; grp-- > 0;) {
        size_t lo = grp * QC__WCHAIN_GROUP, hi = lo + QC__WCHAIN_GROUP;
        if (apart(&sb, &c->grp[grp]))
            continue;
        for (m = hi < c->n - 1 ? hi : c->n - 1; m-- > lo;)
            if (!apart(&sb, &c->seg[m]) && segs_touch(s, c->p + m))
                return 1;
    }
    return 0;
}

int qc__wchain_touch(const qc__wchain *c, const qc_vec2 *q, size_t nq,
                     int (*skip)(void *ud, size_t k), void *ud)
{
    size_t k;

    for (k = 0; k + 1 < nq; k++)
        if (!skip(ud, k) && qc__wchain_seg_touch(c, q + k))
            return 1;
    return 0;
}
