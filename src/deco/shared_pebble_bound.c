/*
 * The region's edges in the collision grid (shared_collide.c), queried the way
 * pebbles need: the distance to the boundary, the first radius at which a
 * circle growing along a ray meets it (closed form per edge), and the
 * crossings of a segment, decided by exact orientation tests.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "pebble_internal.h"

int qc__pbound_init(qc_ctx *ctx, qc__pbound *b, const qc_region *region, double cell,
                    size_t max_cells)
{
    qc_bbox box = qc_region_bbox(region);
    size_t ring;
    int rc;

    memset(b, 0, sizeof *b);
    b->region = region;
    rc = qc__cgrid_init(ctx, &b->g, box, cell, max_cells);
    if (rc == QC_OK)
        rc = qc__cgrid_reserve(ctx, &b->g, region->nv, 2 * region->nv, 4 * region->nv);
    for (ring = 0; rc == QC_OK && ring < region->nrings; ring++) {
        size_t lo = ring ? region->ring_end[ring - 1] : 0, hi = region->ring_end[ring], i;
        for (i = lo; i < hi && rc == QC_OK; i++) {
            qc_vec2 e[2];
            e[0] = region->v[i];
            e[1] = region->v[i + 1 < hi ? i + 1 : lo];
            rc = qc__cgrid_add(ctx, &b->g, e, 2, 0, (uint32_t)i);
        }
    }
    if (rc != QC_OK)
        qc__pbound_free(ctx, b);
    return rc;
}

void qc__pbound_free(qc_ctx *ctx, qc__pbound *b)
{
    qc__cgrid_free(ctx, &b->g);
    b->region = NULL;
}

size_t qc__pbound_ring(const qc_region *r, uint32_t v, uint32_t *lo, uint32_t *hi)
{
    size_t a = qc__region_ring_of(r, v);

    *lo = a ? r->ring_end[a - 1] : 0;
    *hi = r->ring_end[a];
    return a;
}

/* Cells under the box [x0, x1] x [y0, y1], clamped to the grid. */
static void cell_range(const qc__cgrid *g, double x0, double y0, double x1, double y1,
                       uint32_t r[4])
{
    double c[4], lim[2]; /* the limits converted once (a size_t to double is dear) */
    int k;

    c[0] = (x0 - g->x0) / g->cell;
    c[1] = (y0 - g->y0) / g->cell;
    c[2] = (x1 - g->x0) / g->cell;
    c[3] = (y1 - g->y0) / g->cell;
    lim[0] = (double)(g->nx - 1);
    lim[1] = (double)(g->ny - 1);
    for (k = 0; k < 4; k++)
        r[k] = !(c[k] >= 0) ? 0 : c[k] > lim[k & 1] ? (uint32_t)lim[k & 1] : (uint32_t)c[k];
}

static void new_stamp(qc__cgrid *g)
{
    if (++g->cur == 0) {
        memset(g->stamp, 0, g->nitem * sizeof *g->stamp);
        g->cur = 1;
    }
}

/* Walks the items under a box once each: *e is the cursor (start at
 * UINT32_MAX with *x = r[0] - 1 ... handled inside). Returns the next item or
 * UINT32_MAX at the end. */
typedef struct walk {
    uint32_t r[4], x, y, e;
} walk;

/* The walk over the cells w->r, set already. */
static void walk_begin(qc__cgrid *g, walk *w)
{
    w->x = w->r[0];
    w->y = w->r[1];
    w->e = g->head[(size_t)w->y * g->nx + w->x];
    new_stamp(g);
}

static void walk_start(qc__cgrid *g, walk *w, double x0, double y0, double x1, double y1)
{
    cell_range(g, x0, y0, x1, y1, w->r);
    walk_begin(g, w);
}

/* Whether no edge is filed under the cells r (most of a packing's
 * queries, away from the boundary: answered without a walk). */
static int cells_empty(const qc__cgrid *g, const uint32_t r[4])
{
    uint32_t x, y;

    for (y = r[1]; y <= r[3]; y++)
        for (x = r[0]; x <= r[2]; x++)
            if (g->head[(size_t)y * g->nx + x] != UINT32_MAX)
                return 0;
    return 1;
}

static uint32_t walk_next(qc__cgrid *g, walk *w)
{
    for (;;) {
        while (w->e != UINT32_MAX) {
            uint32_t it = g->ent[w->e].item;
            w->e = g->ent[w->e].next;
            if (g->stamp[it] != g->cur) {
                g->stamp[it] = g->cur;
                return it;
            }
        }
        if (w->x < w->r[2]) {
            w->x++;
        } else if (w->y < w->r[3]) {
            w->y++;
            w->x = w->r[0];
        } else {
            return UINT32_MAX;
        }
        w->e = g->head[(size_t)w->y * g->nx + w->x];
    }
}

double qc__pbound_dist(qc__pbound *b, qc_vec2 x, double reach)
{
    qc__cgrid *g = &b->g;
    double best2 = reach * reach;
    walk w;
    uint32_t it;

    if (g->nitem == 0)
        return reach;
    cell_range(g, x.x - reach, x.y - reach, x.x + reach, x.y + reach, w.r);
    if (cells_empty(g, w.r))
        return reach;
    walk_begin(g, &w);
    while ((it = walk_next(g, &w)) != UINT32_MAX) {
        const qc_vec2 *v = g->v + g->item[it].off;
        double d2 = qc__seg_dist2(x, v[0], v[1]);
        if (d2 < best2)
            best2 = d2;
    }
    return best2 < reach * reach ? sqrt(best2) : reach;
}

size_t qc__pbound_gather(qc__pbound *b, const double *box, uint32_t *out, size_t cap)
{
    qc__cgrid *g = &b->g;
    size_t n = 0;
    walk w;
    uint32_t it;

    if (g->nitem == 0)
        return 0;
    walk_start(g, &w, box[0], box[1], box[2], box[3]);
    while ((it = walk_next(g, &w)) != UINT32_MAX) {
        if (n == cap)
            return cap + 1;
        out[n++] = it;
    }
    return n;
}

double qc__pbound_dist_among(const qc__pbound *b, const uint32_t *items, size_t n, qc_vec2 x,
                             double reach)
{
    const qc__cgrid *g = &b->g;
    double best2 = reach * reach;
    size_t m;

    for (m = 0; m < n; m++) {
        const qc_vec2 *v = g->v + g->item[items[m]].off;
        double d2 = qc__seg_dist2(x, v[0], v[1]);
        if (d2 < best2)
            best2 = d2;
    }
    return best2 < reach * reach ? sqrt(best2) : reach;
}

/* First s >= 0 with |w + u s| = k (r0 + s) (w = x0 - e), or -1; the
 * circle at s = 0 keeps |w| >= k r0. */
static double point_root(qc_vec2 w, qc_vec2 u, double r0, double k)
{
    double kr = k * r0, bh = w.x * u.x + w.y * u.y - k * kr;
    double c = w.x * w.x + w.y * w.y - kr * kr, a = 1 - k * k, disc;

    if (c <= 0)
        return 0;
    if (bh >= 0)
        return -1;
    disc = bh * bh - a * c; /* (B/2)^2 - AC */
    if (disc < 0)
        return -1;
    return c / (-bh + sqrt(disc)); /* the smaller root, stably */
}

double qc__pbound_ray(qc__pbound *b, qc_vec2 x0, double r0, qc_vec2 u, double cap, double k)
{
    qc__cgrid *g = &b->g;
    qc_vec2 x1;
    double best = cap, pad = k * (r0 + cap) + 1e-9;
    walk w;
    uint32_t it;

    if (g->nitem == 0 || !(cap > 0))
        return cap > 0 ? cap : 0;
    x1.x = x0.x + u.x * cap;
    x1.y = x0.y + u.y * cap;
    walk_start(g, &w, fmin(x0.x, x1.x) - pad, fmin(x0.y, x1.y) - pad, fmax(x0.x, x1.x) + pad,
               fmax(x0.y, x1.y) + pad);
    while ((it = walk_next(g, &w)) != UINT32_MAX) {
        const qc_vec2 *v = g->v + g->item[it].off;
        qc_vec2 a = v[0], e, n, wv;
        double len2, len, s0, su, s, t;
        int end;

        for (end = 0; end < 2; end++) { /* the two ends */
            wv.x = x0.x - v[end].x;
            wv.y = x0.y - v[end].y;
            s = point_root(wv, u, r0, k);
            if (s >= 0 && s < best)
                best = s;
        }
        e.x = v[1].x - a.x;
        e.y = v[1].y - a.y;
        len2 = e.x * e.x + e.y * e.y;
        if (!(len2 > 0))
            continue;
        len = sqrt(len2);
        n.x = -e.y / len;
        n.y = e.x / len;
        s0 = n.x * (x0.x - a.x) + n.y * (x0.y - a.y);
        su = n.x * u.x + n.y * u.y;
        if (s0 >= 0 && k - su > 0)
            s = fmax(0, (s0 - k * r0) / (k - su)); /* 0: touching already (rounding) */
        else if (s0 < 0 && k + su > 0)
            s = fmax(0, (-s0 - k * r0) / (k + su));
        else
            continue;
        if (!(s < best))
            continue;
        t = ((x0.x + u.x * s - a.x) * e.x + (x0.y + u.y * s - a.y) * e.y) / len2;
        if (t >= 0 && t <= 1)
            best = s;
    }
    return best;
}

/* Whether pq crosses the edge ab, every zero orientation taken as negative. */
static int crosses(qc_vec2 p, qc_vec2 q, qc_vec2 a, qc_vec2 b)
{
    int sp = qc_orient2d(a, b, p) > 0, sq = qc_orient2d(a, b, q) > 0;

    if (sp == sq)
        return 0;
    return (qc_orient2d(p, q, a) > 0) != (qc_orient2d(p, q, b) > 0);
}

size_t qc__pbound_crossings(qc__pbound *b, qc_vec2 p, qc_vec2 q)
{
    qc__cgrid *g = &b->g;
    size_t count = 0;
    walk w;
    uint32_t it;

    if (g->nitem == 0)
        return 0;
    walk_start(g, &w, fmin(p.x, q.x), fmin(p.y, q.y), fmax(p.x, q.x), fmax(p.y, q.y));
    while ((it = walk_next(g, &w)) != UINT32_MAX) {
        const qc_vec2 *v = g->v + g->item[it].off;
        count += (size_t)crosses(p, q, v[0], v[1]);
    }
    return count;
}

static int cmp_cross(const void *pa, const void *pb)
{
    const qc__pcross *a = pa, *b = pb;

    if (a->t != b->t)
        return a->t < b->t ? -1 : 1;
    return a->edge < b->edge ? -1 : a->edge > b->edge;
}

int qc__pbound_cross_list(qc_ctx *ctx, qc__pbound *b, qc_vec2 p, qc_vec2 q,
                          qc__pcross **list, size_t *cap, size_t *count)
{
    qc__cgrid *g = &b->g;
    walk w;
    uint32_t it;

    *count = 0;
    if (g->nitem == 0)
        return QC_OK;
    walk_start(g, &w, fmin(p.x, q.x), fmin(p.y, q.y), fmax(p.x, q.x), fmax(p.y, q.y));
    while ((it = walk_next(g, &w)) != UINT32_MAX) {
        const qc_vec2 *v = g->v + g->item[it].off;
        double ex, ey, o1, o2, t;
        qc__pcross *c;

        if (!crosses(p, q, v[0], v[1]))
            continue;
        QC__TRY(QC__RESERVE(ctx, *list, *cap, *count + 1));
        ex = v[1].x - v[0].x;
        ey = v[1].y - v[0].y;
        o1 = ex * (p.y - v[0].y) - ey * (p.x - v[0].x);
        o2 = ex * (q.y - v[0].y) - ey * (q.x - v[0].x);
        t = o1 != o2 ? o1 / (o1 - o2) : 0.5;
        t = t < 0 ? 0 : t > 1 ? 1 : t;
        c = &(*list)[(*count)++];
        c->t = t;
        c->edge = g->item[it].id;
        c->at.x = p.x + t * (q.x - p.x);
        c->at.y = p.y + t * (q.y - p.y);
    }
    if (*count > 1)
        qsort(*list, *count, sizeof **list, cmp_cross);
    return QC_OK;
}
