/*
 * The join sewn last, tested on its own before a join's grid query: nearly
 * every join that fails crosses it (the curve arriving at the primitive it
 * leaves), and a direct test finds that without walking the grid's cells.
 * Only a shortcut to "hit": a clear answer still goes to the grid.
 */
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
    c->n = n;
}

int qc__wchain_seg_touch(const qc__wchain *c, const qc_vec2 *s)
{
    size_t grp, m;
    qc_bbox sb;

    if (c->n < 2)
        return 0;
    seg_box(s, &sb);
    /* from the chain's end, where the crossings are; a group's box first */
    for (grp = (c->n - 2) / QC__WCHAIN_GROUP + 1; grp-- > 0;) {
        size_t lo = grp * QC__WCHAIN_GROUP, hi = lo + QC__WCHAIN_GROUP;
        if (apart(&sb, &c->grp[grp]))
            continue;
        for (m = hi < c->n - 1 ? hi : c->n - 1; m-- > lo;)
            if (!apart(&sb, &c->seg[m]) && qc__convex_touch(s, 2, c->p + m, 2, 1e-9))
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
