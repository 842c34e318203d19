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
    c->box.min = c->box.max = pts[0];
    for (k = 0; k + 1 < n; k++) {
        c->p[k + 1] = pts[k + 1];
        seg_box(pts + k, &c->seg[k]);
        if (c->seg[k].min.x < c->box.min.x)
            c->box.min.x = c->seg[k].min.x;
        if (c->seg[k].min.y < c->box.min.y)
            c->box.min.y = c->seg[k].min.y;
        if (c->seg[k].max.x > c->box.max.x)
            c->box.max.x = c->seg[k].max.x;
        if (c->seg[k].max.y > c->box.max.y)
            c->box.max.y = c->seg[k].max.y;
    }
    c->n = n;
}

int qc__wchain_touch(const qc__wchain *c, const qc_vec2 *q, size_t nq,
                     int (*skip)(void *ud, size_t k), void *ud)
{
    size_t k, m;

    for (k = 0; c->n >= 2 && k + 1 < nq; k++) {
        qc_bbox sb;
        seg_box(q + k, &sb);
        if (apart(&sb, &c->box) || skip(ud, k))
            continue;
        for (m = 0; m + 1 < c->n; m++)
            if (!apart(&sb, &c->seg[m]) && qc__convex_touch(q + k, 2, c->p + m, 2, 1e-9))
                return 1;
    }
    return 0;
}
