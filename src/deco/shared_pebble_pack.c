/*
 * Pebbling, phases 1 and 2 (paper §5.3.1). Phase 1 visits the skeleton in
 * its order: each point gets the largest circle that touches no pebble
 * placed before it (at most r_seed d), hanging from its parent's pebble;
 * where that leaves a gap, a filler fills it (step 3), or the pebble slides
 * towards its parent until it touches it. Phase 2 grows leaves away from
 * their parent and pebbles touching two others along the two's common
 * tangent circles, until they touch one more pebble or the boundary.
 * Phase 3 (ours, issue 16) puts pebbles into the corners and along the
 * seams the first two left bare.
 *
 * Every growth keeps the pebble tangent to what it hangs from: a circle
 * (x0 + u s, r0 + s) keeps the point x0 - u r0 and grows nested, so the
 * first contact with a pebble or an edge has a closed form. Neighbours come
 * from a uniform grid, so each query is O(1) and the whole run near-linear.
 */
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "pebble_pack.h"

#define R_MIN 0.1     /* smallest pebble, times d */
#define GROW_MAX 1.5  /* phase 2 radius cap, times r_seed d */
#define MOVE_MAX 1.0  /* phase 2: a pebble's centre moves at most this, times d */
#define TOUCH 1e-6    /* pebbles this close (times d) touch */
#define OVER_K 0.5    /* overgrow: a centre stays OVER_K r inside */
#define ARG_BOUND 0xFFFFFFFEu

typedef qc__pack pack;

void qc__pebbles_free(qc_ctx *ctx, qc__pebbles *pb)
{
    if (pb == NULL)
        return;
    qc__free(ctx, pb->c, pb->cap * sizeof *pb->c);
    qc__free(ctx, pb->r, pb->cap * sizeof *pb->r);
    qc__free(ctx, pb->parent, pb->cap * sizeof *pb->parent);
    qc__free(ctx, pb->node, pb->cap * sizeof *pb->node);
    qc__free(ctx, pb->flags, pb->cap * sizeof *pb->flags);
    qc__free(ctx, pb->contacts, pb->cap * sizeof *pb->contacts);
    qc__free(ctx, pb->motif, pb->n * sizeof *pb->motif);
    qc__free(ctx, pb->xf, pb->n * sizeof *pb->xf);
    memset(pb, 0, sizeof *pb);
}

static double dist(qc_vec2 a, qc_vec2 b)
{
    double dx = a.x - b.x, dy = a.y - b.y;
    return sqrt(dx * dx + dy * dy);
}

/* ---- the pebble grid ---- */

static uint32_t clamp_cell(double c, uint32_t n)
{
    return !(c >= 0) ? 0 : c >= (double)(n - 1) ? n - 1 : (uint32_t)c;
}

static uint32_t cell_of(const pack *P, qc_vec2 p)
{
    return clamp_cell((p.y - P->y0) / P->h, P->ny) * P->nx +
           clamp_cell((p.x - P->x0) / P->h, P->nx);
}

static void cell_box(const pack *P, qc_vec2 x, double reach, uint32_t r[4])
{
    r[0] = clamp_cell((x.x - reach - P->x0) / P->h, P->nx);
    r[1] = clamp_cell((x.y - reach - P->y0) / P->h, P->ny);
    r[2] = clamp_cell((x.x + reach - P->x0) / P->h, P->nx);
    r[3] = clamp_cell((x.y + reach - P->y0) / P->h, P->ny);
}

/*
 * The walk over the grid: every pebble j in the cells (cx, cy) of the block
 * r[4] = x0, y0, x1, y1 (inclusive; cell_box), row by row, each cell's list
 * in order, skipping the cells where keep is false (list_for_each in the
 * Linux kernel's manner: the loop costs what three written loops cost).
 */
#define FOR_EACH_PEBBLE_IF(P, r, cx, cy, j, keep)                                           \
    for ((cy) = (r)[1]; (cy) <= (r)[3]; (cy)++)                                              \
        for ((cx) = (r)[0]; (cx) <= (r)[2]; (cx)++)                                          \
            for ((j) = (keep) ? (P)->head[(cy) * (P)->nx + (cx)] : QC__PEB_NONE;             \
                 (j) != QC__PEB_NONE; (j) = (P)->node[j].next)
#define FOR_EACH_PEBBLE(P, r, cx, cy, j) FOR_EACH_PEBBLE_IF(P, r, cx, cy, j, 1)

/* The block of cells within ring cells of (c0x, c0y), clamped to the grid. */
static void ring_box(const pack *P, uint32_t c0x, uint32_t c0y, uint32_t ring, uint32_t r[4])
{
    r[0] = c0x >= ring ? c0x - ring : 0;
    r[1] = c0y >= ring ? c0y - ring : 0;
    r[2] = c0x + ring < P->nx ? c0x + ring : P->nx - 1;
    r[3] = c0y + ring < P->ny ? c0y + ring : P->ny - 1;
}

static void grid_insert(pack *P, uint32_t i)
{
    uint32_t c = cell_of(P, P->pb->c[i]);

    P->node[i].c = P->pb->c[i];
    P->node[i].r = P->pb->r[i];
    P->node[i].cell = c;
    P->node[i].next = P->head[c];
    P->head[c] = i;
}

static void grid_remove(pack *P, uint32_t i)
{
    uint32_t *at = &P->head[P->node[i].cell];

    while (*at != i)
        at = &P->node[*at].next;
    *at = P->node[i].next;
}

static uint32_t place(pack *P, qc_vec2 c, double r, uint32_t parent, uint32_t node,
                      unsigned flags)
{
    qc__pebbles *pb = P->pb;
    uint32_t i = (uint32_t)pb->n++;

    pb->c[i] = c;
    pb->r[i] = r;
    pb->parent[i] = parent;
    pb->node[i] = node;
    pb->flags[i] = (unsigned char)flags;
    pb->contacts[i] = 0;
    if (r > P->rmax)
        P->rmax = r;
    grid_insert(P, i);
    return i;
}

static void move_to(pack *P, uint32_t i, qc_vec2 c, double r)
{
    grid_remove(P, i);
    P->pair.valid = 0;
    P->pb->c[i] = c;
    P->pb->r[i] = r;
    if (r > P->rmax)
        P->rmax = r;
    grid_insert(P, i);
}

/* ---- queries ---- */

/*
 * Largest radius (at most cap) of a circle at x touching no pebble (but ex0,
 * ex1, ex2) and keeping its centre k r from the boundary; *arg receives the
 * pebble that limits it, ARG_BOUND or QC__PEB_NONE (cap). Once a pebble
 * brings it below stop, some value below stop (the caller only asks
 * whether it reaches stop: the rest of the walk and the boundary are
 * skipped; -HUGE_VAL never stops).
 */
static double clearance_to(pack *P, qc_vec2 x, double cap, double stop, uint32_t ex0,
                           uint32_t ex1, uint32_t ex2, uint32_t *arg)
{
    const qc__pebbles *pb = P->pb;
    double best = cap, db;
    uint32_t j, a = QC__PEB_NONE;
    uint32_t r[4], cx, cy;

    cell_box(P, x, cap + P->rmax, r);
    FOR_EACH_PEBBLE(P, r, cx, cy, j) {
        double dx = x.x - P->node[j].c.x, dy = x.y - P->node[j].c.y, far = best + P->node[j].r, v;
        if ((far > 0 && dx * dx + dy * dy >= far * far) || j == ex0 || j == ex1 || j == ex2)
            continue;
        v = sqrt(dx * dx + dy * dy) - P->node[j].r;
        if (v < best) {
            best = v;
            a = j;
            if (best < stop)
                return best; /* only ever lower from here */
        }
    }
    if (best > 0) {
        db = qc__pbound_dist(P->b, x, pb->k * best) / pb->k;
        if (db < best) {
            best = db;
            a = ARG_BOUND;
        }
    }
    if (arg != NULL)
        *arg = a;
    return best;
}

static double clearance(pack *P, qc_vec2 x, double cap, uint32_t ex0, uint32_t ex1,
                        uint32_t ex2, uint32_t *arg)
{
    return clearance_to(P, x, cap, -HUGE_VAL, ex0, ex1, ex2, arg);
}

/* The circle (x0 + u s, r0 + s): the largest s <= cap touching no pebble
 * (but ex0, ex1) and keeping k (r0 + s) from the boundary. */
static double ray(pack *P, qc_vec2 x0, double r0, qc_vec2 u, double cap, uint32_t ex0,
                  uint32_t ex1)
{
    const qc__pebbles *pb = P->pb;
    qc_vec2 xf = QC__V2(x0.x + u.x * cap, x0.y + u.y * cap);
    double best = cap;
    uint32_t j;
    uint32_t r[4], cx, cy;

    if (!(cap > 0))
        return 0;
    cell_box(P, xf, r0 + cap + P->rmax, r); /* the circles nest in the last one */
    FOR_EACH_PEBBLE(P, r, cx, cy, j) {
        double ax, ay, bq, num, den;
        if (j == ex0 || j == ex1)
            continue;
        ax = x0.x - P->node[j].c.x;
        ay = x0.y - P->node[j].c.y;
        bq = P->node[j].r + r0;
        num = ax * ax + ay * ay - bq * bq;
        den = bq - (ax * u.x + ay * u.y);
        if (num <= 0)
            return 0;
        if (den > 0 && num / (2 * den) < best)
            best = num / (2 * den);
    }
    return qc__pbound_ray(P->b, x0, r0, u, best, pb->k);
}

/* Whether q lies on the same side of the boundary as p (p inside). */
static int same_side(pack *P, qc_vec2 p, qc_vec2 q)
{
    return (qc__pbound_crossings(P->b, p, q) & 1) == 0;
}

/* The pebble whose edge is nearest x (growing square searches). */
static uint32_t nearest(pack *P, qc_vec2 x)
{
    double reach = P->h, best = HUGE_VAL;
    uint32_t a = QC__PEB_NONE;

    for (;;) {
        uint32_t j;
        uint32_t r[4], cx, cy;
        cell_box(P, x, reach, r);
        FOR_EACH_PEBBLE(P, r, cx, cy, j) {
            double v = dist(x, P->node[j].c) - P->node[j].r;
            if (v < best || (v == best && j < a)) {
                best = v;
                a = j;
            }
        }
        if ((a != QC__PEB_NONE && best <= reach - P->rmax) ||
            (r[0] == 0 && r[1] == 0 && r[2] == P->nx - 1 && r[3] == P->ny - 1))
            return a;
        reach *= 2;
    }
}

static qc_vec2 unit_from(qc_vec2 a, qc_vec2 b)
{
    double l = dist(a, b);
    return l > 0 ? QC__V2((b.x - a.x) / l, (b.y - a.y) / l) : QC__V2(1, 0);
}

#define NEAR 6
#define RETRIES 2 /* passes over the hemmed-in points */

/* Up to NEAR pebbles whose edges lie within reach of x, nearest first. */
static size_t nearest_few(pack *P, qc_vec2 x, double reach, uint32_t *out)
{
    double g[NEAR];
    uint32_t j;
    size_t n = 0;
    uint32_t r[4], cx, cy;

    cell_box(P, x, reach + P->rmax, r);
    FOR_EACH_PEBBLE(P, r, cx, cy, j) {
        double v = dist(x, P->node[j].c) - P->node[j].r;
        size_t k;
        if (v > reach || (n == NEAR && v >= g[NEAR - 1]))
            continue;
        k = n < NEAR ? n++ : NEAR - 1;
        while (k > 0 && (g[k - 1] > v || (g[k - 1] == v && out[k - 1] > j))) {
            g[k] = g[k - 1];
            out[k] = out[k - 1];
            k--;
        }
        g[k] = v;
        out[k] = j;
    }
    return n;
}

/* ---- phase 1: sizes, in the skeleton's order ---- */

/* Whether the straight stitch from pebble b to the circle (x, c) (between
 * the two facing points) keeps clear of the boundary and every pebble. */
static int bridge_clear(pack *P, qc_vec2 x, double c, uint32_t b)
{
    const qc__pebbles *pb = P->pb;
    qc_vec2 u = unit_from(pb->c[b], x), p, q, mid;
    double half, ex, ey, l2;
    uint32_t j;
    uint32_t r[4], cx, cy;

    p = QC__V2(pb->c[b].x + u.x * pb->r[b], pb->c[b].y + u.y * pb->r[b]);
    q = QC__V2(x.x - u.x * c, x.y - u.y * c);
    if (qc__pbound_crossings(P->b, p, q) != 0)
        return 0;
    mid = QC__V2(0.5 * (p.x + q.x), 0.5 * (p.y + q.y));
    half = 0.5 * dist(p, q);
    ex = q.x - p.x;
    ey = q.y - p.y;
    l2 = ex * ex + ey * ey;
    cell_box(P, mid, half + P->rmax, r);
    FOR_EACH_PEBBLE(P, r, cx, cy, j) {
        double t, dx, dy;
        if (j == b)
            continue;
        t = l2 > 0 ? ((P->node[j].c.x - p.x) * ex + (P->node[j].c.y - p.y) * ey) / l2 : 0;
        t = t < 0 ? 0 : t > 1 ? 1 : t;
        dx = p.x + t * ex - P->node[j].c.x;
        dy = p.y + t * ey - P->node[j].c.y;
        if (dx * dx + dy * dy < P->node[j].r * P->node[j].r * (1 - 1e-9))
            return 0;
    }
    return 1;
}

/* The pebble of size s hanging from pebble b towards x, tangent to it. */
static uint32_t hang(pack *P, uint32_t b, qc_vec2 x, double s, uint32_t m)
{
    const qc__pebbles *pb = P->pb;
    qc_vec2 u = unit_from(pb->c[b], x);
    qc_vec2 x0 = QC__V2(pb->c[b].x + u.x * pb->r[b], pb->c[b].y + u.y * pb->r[b]);

    return place(P, QC__V2(x0.x + u.x * s, x0.y + u.y * s), s, b, m, 0);
}

/* The root, c the room at x: held in by the boundary, the small size of the
 * r_seed pair, so its children still alternate r_seed d and (1 - r_seed) d. */
static void visit_root(pack *P, qc_vec2 x, uint32_t m, double c, uint32_t *anchor)
{
    qc__pebbles *pb = P->pb;

    if (c < pb->r_first)
        c = fmin(c, fmax(pb->r_min, P->d - pb->r_first));
    if (c >= pb->r_min)
        *anchor = place(P, x, c, QC__PEB_NONE, m, 0);
    else
        pb->dropped++;
}

/* The circle (x, c) from its parent a across a gap: a filler tangent to
 * both (step 3), else slid towards the parent. 1 when placed. */
static int across_gap(pack *P, qc_vec2 x, uint32_t m, uint32_t a, double c, double gap,
                      uint32_t *anchor)
{
    qc__pebbles *pb = P->pb;
    qc_vec2 u = unit_from(pb->c[a], x);
    qc_vec2 x0 = QC__V2(pb->c[a].x + u.x * pb->r[a], pb->c[a].y + u.y * pb->r[a]);
    double s;

    if ((pb->k < 1 && !same_side(P, pb->c[a], x0)) || (x0.x == pb->c[a].x && x0.y == pb->c[a].y))
        return 0; /* overgrown parent: no room on this side */
    if (gap / 2 >= pb->r_min &&
        ray(P, x0, 0, u, gap / 2, a, QC__PEB_NONE) >= gap / 2 * (1 - 1e-12)) {
        uint32_t f = place(P, QC__V2(x0.x + u.x * gap / 2, x0.y + u.y * gap / 2), gap / 2, a,
                           QC__PEB_NONE, QC__PEB_FILLER);
        *anchor = place(P, x, c, f, m, 0);
        return 1;
    }
    s = ray(P, x0, 0, u, pb->r_first, a, QC__PEB_NONE);
    if (s < pb->r_min)
        return 0;
    *anchor = place(P, QC__V2(x0.x + u.x * s, x0.y + u.y * s), s, a, m, 0);
    return 1;
}

/* Hanging from the roomiest of the pebbles near x (but a). 1 when placed. */
static int from_roomiest(pack *P, qc_vec2 x, uint32_t m, uint32_t a, double c,
                         uint32_t *anchor)
{
    const qc__pebbles *pb = P->pb;
    uint32_t near[NEAR], best = QC__PEB_NONE;
    double bs = 0;
    size_t k, nn = nearest_few(P, x, c + 2 * pb->r_first, near);

    for (k = 0; k < nn; k++) {
        uint32_t b = near[k];
        qc_vec2 u, x0;
        double s;
        if (b == a)
            continue;
        u = unit_from(pb->c[b], x);
        x0 = QC__V2(pb->c[b].x + u.x * pb->r[b], pb->c[b].y + u.y * pb->r[b]);
        if (pb->k < 1 && !same_side(P, pb->c[b], x0))
            continue;
        s = ray(P, x0, 0, u, pb->r_first, b, QC__PEB_NONE);
        if (s > bs) {
            bs = s;
            best = b;
        }
    }
    if (bs < pb->r_min)
        return 0;
    *anchor = hang(P, best, x, bs, m);
    return 1;
}

/* No tangent way in: a straight stitch (sewn there and back) from the
 * nearest pebble it reaches crossing nothing. Returns 1 when hemmed in
 * (tried later, or on the last try left rather than crossed). */
static int bridge_in(pack *P, qc_vec2 x, uint32_t m, uint32_t a, double c, uint32_t *anchor,
                     int last)
{
    qc__pebbles *pb = P->pb;
    uint32_t near[NEAR], best;
    size_t k, nn = nearest_few(P, x, c + 4 * pb->r_first, near);

    best = bridge_clear(P, x, c, a) ? a : QC__PEB_NONE;
    for (k = 0; k < nn; k++) {
        uint32_t b = near[k];
        if (b != a && (best == QC__PEB_NONE || dist(x, pb->c[b]) - pb->r[b] <
                                               dist(x, pb->c[best]) - pb->r[best]) &&
            bridge_clear(P, x, c, b))
            best = b;
    }
    if (best == QC__PEB_NONE && nn > 0) {
        *anchor = near[0];
        pb->dropped += (size_t)last;
        return !last;
    }
    /* else cut off from every pebble (another part of the region) */
    *anchor = place(P, x, c, best != QC__PEB_NONE ? best : a, m, QC__PEB_BRIDGE);
    return 0;
}

/* Skeleton point m (its parent's pebble a, or none): *anchor receives the
 * pebble its children hang from. Returns 1 when m is hemmed in by pebbles
 * and boundary with room for a pebble but no way in yet (tried again once
 * every point has been visited; dropped on the last try). */
static int visit(pack *P, const qc_vec2 *pts, uint32_t m, uint32_t a, uint32_t *anchor,
                 int last)
{
    qc__pebbles *pb = P->pb;
    qc_vec2 x = pts[m];
    double c, len, gap;
    uint32_t q;

    *anchor = a;
    if (pb->n > 0 ? !same_side(P, pb->c[a != QC__PEB_NONE ? a : 0], x)
                  : !qc_region_contains(P->b->region, x)) {
        pb->dropped++; /* outside the region */
        return 0;
    }
    c = clearance(P, x, pb->r_first, QC__PEB_NONE, QC__PEB_NONE, QC__PEB_NONE, &q);
    if (pb->n == 0) {
        visit_root(P, x, m, c, anchor);
        return 0;
    }
    if (a == QC__PEB_NONE)
        a = q < ARG_BOUND ? q : nearest(P, x);
    if (c < pb->r_min) { /* covered already */
        *anchor = q < ARG_BOUND ? q : a;
        pb->dropped++;
        return 0;
    }
    len = dist(x, pb->c[a]);
    if (c < pb->r_first && len - pb->r_first >= pb->r_min && len - pb->r_first < c)
        c = len - pb->r_first; /* held in: the small size of the pair, to keep alternating */
    gap = len - pb->r[a] - c;
    if (gap <= pb->touch) {
        *anchor = place(P, x, c, a, m, 0);
        return 0;
    }
    if (across_gap(P, x, m, a, c, gap, anchor) || from_roomiest(P, x, m, a, c, anchor))
        return 0;
    return bridge_in(P, x, m, a, c, anchor, last);
}

static int phase1(pack *P, const qc_skeleton *skel)
{
    qc_ctx *ctx = P->ctx;
    size_t n = skel->n, i;
    int pass;
    uint32_t *anchor = qc__alloc_array(ctx, n, sizeof *anchor);
    unsigned char *seen = qc__alloc(ctx, n);
    int rc = QC_OK;

    if (anchor == NULL || seen == NULL) {
        rc = QC_ENOMEM;
        goto out;
    }
    memset(seen, 0, n);
    for (i = 0; i < skel->norder; i++) {
        uint32_t m = skel->order[i], par;
        if (seen[m])
            continue;
        par = i > 0 ? anchor[skel->order[i - 1]] : QC__PEB_NONE;
        seen[m] = (unsigned char)(1 + visit(P, skel->p, m, par, &anchor[m], 0));
    }
    /* points the order missed: the root first, each from its nearest pebble */
    for (i = 0; i <= n; i++) {
        uint32_t m = i == 0 ? (skel->root < n ? skel->root : 0) : (uint32_t)(i - 1);
        if (seen[m])
            continue;
        seen[m] = (unsigned char)(1 + visit(P, skel->p, m, QC__PEB_NONE, &anchor[m], 0));
    }
    /* the hemmed-in points again, now that every other point has its pebble */
    for (pass = 1; pass <= RETRIES; pass++)
        for (i = 0; i < n; i++)
            if (seen[i] == 2)
                seen[i] = (unsigned char)(1 + visit(P, skel->p, (uint32_t)i, QC__PEB_NONE,
                                                    &anchor[i], pass == RETRIES));
out:
    qc__free(ctx, anchor, n * sizeof *anchor);
    qc__free(ctx, seen, n);
    return rc;
}

/* ---- phase 2: growth ---- */

/* Pebbles touching i (up to 3 ids into ids) and whether the boundary does.
 * Past most pebbles the count stops there (most + 1, the boundary not
 * asked: *bound 0), for callers that want exactly a few. */
static unsigned contacts(pack *P, uint32_t i, uint32_t ids[3], int *bound, unsigned most)
{
    const qc__pebbles *pb = P->pb;
    qc_vec2 x = pb->c[i];
    double ri = pb->r[i];
    uint32_t j;
    unsigned count = 0;
    uint32_t r[4], cx, cy;

    cell_box(P, x, ri + P->rmax + pb->touch, r);
    FOR_EACH_PEBBLE(P, r, cx, cy, j) {
        double dx = x.x - P->node[j].c.x, dy = x.y - P->node[j].c.y;
        double far = ri + P->node[j].r + pb->touch;
        if (dx * dx + dy * dy > far * far || j == i)
            continue;
        if (count < 3)
            ids[count] = j;
        if (count++ == most) {
            *bound = 0;
            return count;
        }
    }
    *bound = qc__pbound_dist(P->b, x, pb->k * ri + 2 * pb->touch) <= pb->k * ri + pb->touch;
    return count;
}

/* The centre tangent to pebbles j and k at radius R on side s, or 0. What
 * depends on j and k alone (their distance, the unit vector from j to k)
 * is kept for the next call with the same pair (a growth asks for dozens
 * of radii); move_to forgets it. */
static int pair_centre(pack *P, uint32_t j, uint32_t k, double R, double s, qc_vec2 *out)
{
    qc__pair_frame *F = &P->pair;
    double a, b, along, h2;

    if (!F->valid || F->j != j || F->k != k) {
        const qc__pebbles *pb = P->pb;
        qc_vec2 cj = pb->c[j], ck = pb->c[k];
        F->j = j;
        F->k = k;
        F->valid = 1;
        F->cj = cj;
        F->rj = pb->r[j];
        F->rk = pb->r[k];
        F->D = dist(cj, ck);
        if (F->D > 0)
            F->e = QC__V2((ck.x - cj.x) / F->D, (ck.y - cj.y) / F->D);
    }
    if (!(F->D > 0))
        return 0;
    a = F->rj + R;
    b = F->rk + R;
    along = (F->D * F->D + a * a - b * b) / (2 * F->D);
    h2 = a * a - along * along;
    if (h2 < 0)
        return 0;
    h2 = sqrt(h2) * s;
    *out = QC__V2(F->cj.x + F->e.x * along - F->e.y * h2, F->cj.y + F->e.y * along + F->e.x * h2);
    return 1;
}

#define PAIR_NEAR 192 /* pebbles a pair search keeps at hand */

/* The pebbles (but i, j, k) a pair search may meet: pebble i's centre moves
 * at most MOVE_MAX d and its radius stays within r_grow, so nothing whose
 * edge is farther from i's centre matters (a d of slack for rounding). The
 * search asks up to 40 bisection steps of these few instead of the grid;
 * all 0 when more than fit (the grid is asked then). */
#define PAIR_SEGS 64 /* boundary segments a pair search keeps at hand */

typedef struct pair_near {
    uint32_t id[PAIR_NEAR];
    size_t n;
    int all;
    uint32_t seg[PAIR_SEGS]; /* when nseg <= PAIR_SEGS: every boundary */
    size_t nseg;             /* segment the search's circles can reach */
} pair_near;

static void pair_gather(pack *P, uint32_t i, uint32_t j, uint32_t k, pair_near *pn)
{
    const qc__pebbles *pb = P->pb;
    double reach = (MOVE_MAX + 1) * P->d + pb->r_grow;
    uint32_t q, r[4], cx, cy;

    pn->n = 0;
    pn->all = 1;
    pn->nseg = PAIR_SEGS + 1;
    cell_box(P, pb->c[i], reach + P->rmax, r);
    FOR_EACH_PEBBLE(P, r, cx, cy, q) {
        if (q == i || q == j || q == k || dist(pb->c[i], P->node[q].c) - P->node[q].r > reach)
            continue;
        if (pn->n == PAIR_NEAR) {
            pn->all = 0;
            return;
        }
        pn->id[pn->n++] = q;
    }
}

/* Whether the circle tangent to j and k at radius R on side s fits (its
 * centre into *at): clearance_to(at, R, R, i, j, k) >= R, the same answer
 * in any order of the pebbles, so here from the gathered ones, the last
 * pebble in the way first (the bisection's next misses meet it again). */
static int pair_fits(pack *P, pair_near *pn, uint32_t i, uint32_t j, uint32_t k, double R,
                     double s, qc_vec2 *at)
{
    const qc__pebbles *pb = P->pb;
    size_t m;

    if (!pair_centre(P, j, k, R, s, at) || dist(*at, pb->c[i]) > MOVE_MAX * P->d)
        return 0;
    if (!pn->all)
        return clearance_to(P, *at, R, R, i, j, k, NULL) >= R;
    for (m = 0; m < pn->n; m++) {
        uint32_t q = pn->id[m];
        double dx = at->x - P->node[q].c.x, dy = at->y - P->node[q].c.y, far = R + P->node[q].r;
        if (far > 0 && dx * dx + dy * dy >= far * far)
            continue;
        if (sqrt(dx * dx + dy * dy) - P->node[q].r < R) {
            pn->id[m] = pn->id[0];
            pn->id[0] = q;
            return 0;
        }
    }
    if (!(R > 0))
        return 1;
    return !((pn->nseg <= PAIR_SEGS
                  ? qc__pbound_dist_among(P->b, pn->seg, pn->nseg, *at, pb->k * R)
                  : qc__pbound_dist(P->b, *at, pb->k * R)) / pb->k < R);
}

typedef struct apo_pair { /* what apollonius needs of j and k, once per growth */
    qc_vec2 cj;
    double rj, rj2, ax, ay, a2, h0a, h1a;
} apo_pair;

static void apo_pair_init(const qc__pebbles *pb, uint32_t j, uint32_t k, apo_pair *A)
{
    double rk = pb->r[k];

    A->cj = pb->c[j];
    A->rj = pb->r[j];
    A->rj2 = A->rj * A->rj;
    A->ax = pb->c[k].x - pb->c[j].x;
    A->ay = pb->c[k].y - pb->c[j].y;
    A->a2 = A->ax * A->ax + A->ay * A->ay;
    A->h0a = A->a2 + A->rj2 - rk * rk;
    A->h1a = 2 * (A->rj - rk);
}

/*
 * The first R > r0 at which the circle tangent to j and k on side s (the
 * sign of cross(ck - cj, centre - cj)) touches the circle (cq, rq): the
 * three tangencies, differenced, are linear in the centre and R (the
 * problem of Apollonius), leaving a quadratic in R. HUGE_VAL when it never
 * does; -1 when the centres are collinear (not solved here).
 */
static double apollonius(const apo_pair *A, qc_vec2 cq, double rq, double s, double r0)
{
    double rj = A->rj, ax = A->ax, ay = A->ay, h0a = A->h0a, h1a = A->h1a;
    double bx = cq.x - A->cj.x, by = cq.y - A->cj.y;
    double det = 4 * (ax * by - ay * bx), h0b, h1b, y0x, y0y, y1x, y1y;
    double A2, B, C, best = HUGE_VAL, root[2];
    int nr = 0, m;

    if (!(fabs(det) > 1e-9 * 4 * (A->a2 + bx * bx + by * by)))
        return -1;
    h0b = bx * bx + by * by + A->rj2 - rq * rq;
    h1b = 2 * (rj - rq);
    /* y = M^-1 h, M = 2 [a; b] */
    y0x = (2 * by * h0a - 2 * ay * h0b) / det;
    y0y = (-2 * bx * h0a + 2 * ax * h0b) / det;
    y1x = (2 * by * h1a - 2 * ay * h1b) / det;
    y1y = (-2 * bx * h1a + 2 * ax * h1b) / det;
    A2 = y1x * y1x + y1y * y1y - 1;
    B = 2 * (y0x * y1x + y0y * y1y - rj);
    C = y0x * y0x + y0y * y0y - A->rj2;
    if (fabs(A2) < 1e-12) {
        if (B != 0)
            root[nr++] = -C / B;
    } else {
        double disc = B * B - 4 * A2 * C, q;
        if (disc < 0)
            return HUGE_VAL;
        q = -0.5 * (B + (B < 0 ? -sqrt(disc) : sqrt(disc)));
        if (q != 0) {
            root[nr++] = q / A2;
            root[nr++] = C / q;
        } else {
            root[nr++] = 0;
        }
    }
    for (m = 0; m < nr; m++) {
        double R = root[m], yx = y0x + R * y1x, yy = y0y + R * y1y;
        if (R > r0 * (1 + 1e-12) && R < best && (ax * yy - ay * yx) * s > 0)
            best = R;
    }
    return best;
}

/* The radius at which the centre tangent to j and k has moved MOVE_MAX d, or hi. */
static double move_limit(pack *P, uint32_t i, uint32_t j, uint32_t k, double s, double hi)
{
    const qc__pebbles *pb = P->pb;
    double lo = pb->r[i];
    qc_vec2 x;
    int it;

    if (pair_centre(P, j, k, hi, s, &x) && dist(x, pb->c[i]) <= MOVE_MAX * P->d)
        return hi;
    for (it = 0; it < 40; it++) {
        double mid = 0.5 * (lo + hi);
        if (pair_centre(P, j, k, mid, s, &x) && dist(x, pb->c[i]) <= MOVE_MAX * P->d)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

/* Where the centre tangent to j and k on side s can be for every radius in
 * [lo, hi], in the frame of pair_centre (along e from c_j; h across, on
 * side s): along is linear in R and h^2 = a^2 - along^2 a convex quadratic
 * (|r_j - r_k| < D), so a box [b0, b1] x [b2, b3] holds them all. 0 when
 * the pebbles overlap that much (no box then). */
static int pair_box(const qc__pebbles *pb, uint32_t j, uint32_t k, double lo, double hi,
                    double *box)
{
    double D = dist(pb->c[j], pb->c[k]), rj = pb->r[j], rk = pb->r[k];
    double beta = D > 0 ? (rj - rk) / D : 1, alpha, q0, q1, qmin, v;

    if (!(fabs(beta) < 1))
        return 0;
    alpha = (D * D + (rj - rk) * (rj + rk)) / (2 * D);
    q0 = (rj + lo) * (rj + lo) - (alpha + beta * lo) * (alpha + beta * lo);
    q1 = (rj + hi) * (rj + hi) - (alpha + beta * hi) * (alpha + beta * hi);
    v = (alpha * beta - rj) / (1 - beta * beta); /* the quadratic's vertex */
    qmin = v > lo && v < hi ? (rj + v) * (rj + v) - (alpha + beta * v) * (alpha + beta * v)
                            : fmin(q0, q1);
    box[0] = fmin(alpha + beta * lo, alpha + beta * hi);
    box[1] = fmax(alpha + beta * lo, alpha + beta * hi);
    box[2] = sqrt(fmax(qmin, 0));
    box[3] = sqrt(fmax(fmax(q0, q1), 0));
    return 1;
}

/* The boundary segments within reach of the box of centres (in the frame
 * c_j, e, side s): its corners' bounding box grown by reach. */
static void pair_segs(const pack *P, pair_near *pn, qc_vec2 cj, qc_vec2 e, double s,
                      const double *box, double reach)
{
    double w[4] = {HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    int c;

    for (c = 0; c < 4; c++) {
        double u = box[c & 1], v = s * box[2 + (c >> 1)];
        double x = cj.x + e.x * u - e.y * v, y = cj.y + e.y * u + e.x * v;

        w[0] = fmin(w[0], x - reach);
        w[1] = fmin(w[1], y - reach);
        w[2] = fmax(w[2], x + reach);
        w[3] = fmax(w[3], y + reach);
    }
    pn->nseg = qc__pbound_gather(P->b, w, pn->seg, PAIR_SEGS);
}

/* Keeps of the gathered pebbles those that can be in the way of a circle
 * tangent to j and k at a radius in [lo, hi]: the bisection's many asks
 * then meet a few neighbours, not the whole reach. A pebble farther from
 * the box of centres than hi (and a slack far above rounding) cannot be. */
static void pair_narrow(const pack *P, pair_near *pn, uint32_t j, uint32_t k, double lo,
                        double hi, double s)
{
    const qc__pebbles *pb = P->pb;
    qc_vec2 cj = pb->c[j], e;
    double box[4], D = dist(cj, pb->c[k]);
    double slack = 1e-3 * (D + pb->r[j] + pb->r[k] + 2 * hi);
    size_t m, n = 0;

    pn->nseg = PAIR_SEGS + 1;
    if (!pn->all || !pair_box(pb, j, k, lo, hi, box))
        return;
    e = QC__V2((pb->c[k].x - cj.x) / D, (pb->c[k].y - cj.y) / D);
    pair_segs(P, pn, cj, e, s, box, pb->k * hi + slack);
    for (m = 0; m < pn->n; m++) {
        uint32_t q = pn->id[m];
        double dx = P->node[q].c.x - cj.x, dy = P->node[q].c.y - cj.y;
        double u = dx * e.x + dy * e.y, v = s * (dy * e.x - dx * e.y);
        double du = fmax(fmax(box[0] - u, u - box[1]), 0);
        double dv = fmax(fmax(box[2] - v, v - box[3]), 0);

        if (sqrt(du * du + dv * dv) - P->node[q].r < hi + slack)
            pn->id[n++] = q;
    }
    pn->n = n;
}

/* Step 2 by small steps and bisection: the general case. */
static double pair_search(pack *P, uint32_t i, uint32_t j, uint32_t k, double s, qc_vec2 *xout)
{
    qc__pebbles *pb = P->pb;
    qc_vec2 xlo = pb->c[i], xhi;
    double lo = pb->r[i], hi, span = pb->r_grow - pb->r[i], step = span / 16;
    int it;
    pair_near pn;

    pair_gather(P, i, j, k, &pn);
    pair_narrow(P, &pn, j, k, lo, pb->r_grow, s);

    while (lo < pb->r_grow) {
        hi = fmin(lo + step, pb->r_grow);
        if (!pair_centre(P, j, k, hi, s, &xhi))
            break;
        if (dist(xhi, xlo) > 0.5 * pb->r_min && step > span * 1e-6) {
            step /= 2; /* small moves: no pebble is jumped over */
            continue;
        }
        if (pair_fits(P, &pn, i, j, k, hi, s, &xhi)) {
            lo = hi;
            xlo = xhi;
            continue;
        }
        pair_narrow(P, &pn, j, k, lo, hi, s);
        for (it = 0; it < 40; it++) {
            double mid = 0.5 * (lo + hi);
            qc_vec2 xm;
            if (pair_fits(P, &pn, i, j, k, mid, s, &xm)) {
                lo = mid;
                xlo = xm;
            } else {
                hi = mid;
            }
        }
        break;
    }
    *xout = xlo;
    return lo;
}

/*
 * The radius (at most R) at which the circle tangent to j and k on side s,
 * grown from pebble i, first meets another pebble, in closed form: rings of
 * cells outwards from i's, until none can hold a pebble the growing circle
 * (moved at most MOVE_MAX d) reaches before R. -1 in a degenerate case,
 * where a search by steps must decide.
 */
static double first_contact(pack *P, uint32_t i, uint32_t j, uint32_t k, double s, double R)
{
    const qc__pebbles *pb = P->pb;
    qc_vec2 ci = pb->c[i], x;
    double r0 = pb->r[i];
    uint32_t ring, maxring = P->nx > P->ny ? P->nx : P->ny;
    uint32_t c0x = clamp_cell((ci.x - P->x0) / P->h, P->nx);
    uint32_t c0y = clamp_cell((ci.y - P->y0) / P->h, P->ny);
    double reach = 0, reach_R = -1; /* reach is asked again only when R changed */
    apo_pair A;

    apo_pair_init(pb, j, k, &A);
    for (ring = 0; ring <= maxring; ring++) {
        uint32_t r[4], cy;

        if (R != reach_R) {
            reach = MOVE_MAX * P->d;
            if (pair_centre(P, j, k, R, s, &x))
                reach = fmin(reach, dist(x, ci));
            reach += R; /* no pebble farther than this from ci is met */
            reach_R = R;
        }
        if (ring >= 2 && (double)(ring - 1) * P->h > reach + P->rmax)
            break;
        ring_box(P, c0x, c0y, ring, r);
        /* the cells on the ring's edge, row by row (its inside was walked
         * already): whole rows at the top and bottom, else its two ends */
        for (cy = r[1]; cy <= r[3]; cy++) {
            int whole = cy + ring == c0y || cy == c0y + ring;
            uint32_t cx = whole || c0x >= ring ? r[0] : r[2];
            for (; cx <= r[2]; cx = whole || cx == r[2] ? cx + 1 : r[2]) {
                uint32_t q;
                if (!whole && cx != c0x - ring && cx != c0x + ring)
                    break;
                for (q = P->head[cy * P->nx + cx]; q != QC__PEB_NONE; q = P->node[q].next) {
                    double rq, dx = P->node[q].c.x - ci.x, dy = P->node[q].c.y - ci.y;
                    double far = reach + P->node[q].r;
                    if (dx * dx + dy * dy > far * far || q == i || q == j || q == k)
                        continue;
                    rq = apollonius(&A, P->node[q].c, P->node[q].r, s, r0);
                    if (rq < 0)
                        return -1;
                    if (rq < R)
                        R = rq;
                }
            }
        }
    }
    return R;
}

/* Step 2: grows pebble i along the circles tangent to j and k. The first
 * pebble met comes in closed form; near the boundary (or in a degenerate
 * case) a search by steps decides. */
static int grow_pair(pack *P, uint32_t i, uint32_t j, uint32_t k)
{
    qc__pebbles *pb = P->pb;
    qc_vec2 ci = pb->c[i], cj = pb->c[j], ck = pb->c[k], x;
    double s = (ck.x - cj.x) * (ci.y - cj.y) - (ck.y - cj.y) * (ci.x - cj.x);
    double r0 = pb->r[i], R = pb->r_grow;
    int done = 0;

    if (!(R > r0))
        return 0;
    s = s < 0 ? -1 : 1;
    R = first_contact(P, i, j, k, s, R);
    if (R >= 0) {
        R = move_limit(P, i, j, k, s, R);
        R = r0 + (R - r0) * (1 - 1e-9); /* a hair short of the contact */
        done = pair_centre(P, j, k, R, s, &x) &&
               clearance_to(P, x, R, R * (1 - 1e-12), i, j, k, NULL) >= R * (1 - 1e-12);
    }
    if (!done)
        R = pair_search(P, i, j, k, s, &x);
    if (!(R > r0 * (1 + 1e-9)) || !same_side(P, ci, x))
        return 0;
    move_to(P, i, x, R);
    return 1;
}

/* Step 1: grows leaf i away from j, the one pebble it touches. */
static int grow_leaf(pack *P, uint32_t i, uint32_t j)
{
    qc__pebbles *pb = P->pb;
    qc_vec2 u = unit_from(pb->c[j], pb->c[i]), x = pb->c[i];
    double s = ray(P, x, pb->r[i], u, pb->r_grow - pb->r[i], i, j);

    if (s > MOVE_MAX * P->d)
        s = MOVE_MAX * P->d;
    if (!(s > pb->r[i] * 1e-9))
        return 0;
    move_to(P, i, QC__V2(x.x + u.x * s, x.y + u.y * s), pb->r[i] + s);
    return 1;
}

static int phase2(pack *P)
{
    qc_ctx *ctx = P->ctx;
    qc__pebbles *pb = P->pb;
    size_t n = pb->n, i;
    uint32_t *nkid = qc__alloc_array(ctx, n, sizeof *nkid);
    uint32_t *kid2 = qc__alloc_array(ctx, 2 * n, sizeof *kid2);
    int step;

    if (nkid == NULL || kid2 == NULL) {
        qc__free(ctx, nkid, n * sizeof *nkid);
        qc__free(ctx, kid2, 2 * n * sizeof *kid2);
        return QC_ENOMEM;
    }
    memset(nkid, 0, n * sizeof *nkid);
    for (i = 0; i < n; i++) { /* tree neighbours: the parent and up to two children kept */
        uint32_t p = pb->parent[i];
        if (p == QC__PEB_NONE)
            continue;
        if (nkid[p] < 2)
            kid2[2 * p + nkid[p]] = (uint32_t)i;
        nkid[p]++;
        if (pb->flags[i] & QC__PEB_BRIDGE)
            nkid[p] += 3; /* a bridged pebble's parent stays */
    }
    for (step = 1; step <= 2; step++) {
        for (i = 0; i < n; i++) {
            uint32_t ids[3], tn[2], ntn = 0, k;
            int bound;
            unsigned cnt;
            if (pb->flags[i] & QC__PEB_BRIDGE)
                continue;
            if (pb->parent[i] != QC__PEB_NONE)
                tn[ntn++] = pb->parent[i];
            if (nkid[i] > 2 || ntn + nkid[i] > (unsigned)step)
                continue;
            for (k = 0; k < nkid[i]; k++)
                tn[ntn++] = kid2[2 * i + k];
            cnt = contacts(P, (uint32_t)i, ids, &bound, (unsigned)step);
            if (bound || cnt != (unsigned)step)
                continue;
            /* the tree neighbours must be among the contacts */
            for (k = 0; k < ntn; k++)
                if (tn[k] != ids[0] && (step == 1 || tn[k] != ids[1]))
                    break;
            if (k < ntn)
                continue;
            if (step == 1 && ntn == 1)
                pb->grown_leaf += (size_t)grow_leaf(P, (uint32_t)i, ids[0]);
            else if (step == 2)
                pb->grown_pair += (size_t)grow_pair(P, (uint32_t)i, ids[0], ids[1]);
        }
    }
    qc__free(ctx, nkid, n * sizeof *nkid);
    qc__free(ctx, kid2, 2 * n * sizeof *kid2);
    return QC_OK;
}

/*
 * Every pebble's contacts (pebbles and boundary), each touching pair tested
 * once: from the pebble whose cell comes first (row by row), over the
 * cells from its own onwards; within one cell, from the lower id. The
 * pair's test is symmetric and either pebble's box holds the other. The
 * pebbles are taken cell by cell, so the neighbours walked are the ones
 * walked just before (in cache).
 */
static void count_contacts(pack *P)
{
    qc__pebbles *pb = P->pb;
    uint32_t c0x, c0y, i;

    memset(pb->contacts, 0, pb->n * sizeof *pb->contacts);
    for (c0y = 0; c0y < P->ny; c0y++)
        for (c0x = 0; c0x < P->nx; c0x++)
            for (i = P->head[c0y * P->nx + c0x]; i != QC__PEB_NONE; i = P->node[i].next) {
                qc_vec2 x = pb->c[i];
                double ri = pb->r[i];
                uint32_t r[4], cx, cy, j;
                int bound;

                cell_box(P, x, ri + P->rmax + pb->touch, r);
                r[1] = c0y;
                FOR_EACH_PEBBLE_IF(P, r, cx, cy, j, cy > c0y || cx >= c0x) {
                    double dx = x.x - P->node[j].c.x, dy = x.y - P->node[j].c.y;
                    double far = ri + P->node[j].r + pb->touch;
                    if (dx * dx + dy * dy > far * far || (cy == c0y && cx == c0x && j <= i))
                        continue;
                    pb->contacts[i] += pb->contacts[i] < 255;
                    pb->contacts[j] += pb->contacts[j] < 255;
                }
                bound = qc__pbound_dist(P->b, x, pb->k * ri + 2 * pb->touch) <=
                        pb->k * ri + pb->touch;
                pb->contacts[i] += (unsigned char)(bound && pb->contacts[i] < 255);
            }
}

/* ---- what phase 3 (shared_pebble_reach.c) asks of the packing ---- */

uint32_t qc__pack_place(qc__pack *P, qc_vec2 c, double r, uint32_t parent, unsigned flags)
{
    return place(P, c, r, parent, QC__PEB_NONE, flags);
}

double qc__pack_clearance(qc__pack *P, qc_vec2 x, double cap, uint32_t ex)
{
    return clearance(P, x, cap, ex, QC__PEB_NONE, QC__PEB_NONE, NULL);
}

double qc__pack_ray(qc__pack *P, qc_vec2 x0, qc_vec2 u, double cap, uint32_t ex)
{
    return ray(P, x0, 0, u, cap, ex, QC__PEB_NONE);
}

int qc__pack_same_side(qc__pack *P, qc_vec2 p, qc_vec2 q)
{
    return same_side(P, p, q);
}

uint32_t qc__pack_nearest(qc__pack *P, qc_vec2 x, double reach)
{
    uint32_t near[NEAR];

    return nearest_few(P, x, reach, near) > 0 ? near[0] : QC__PEB_NONE;
}

/* ---- the run ---- */

static int alloc_pebbles(qc_ctx *ctx, qc__pebbles *pb, size_t cap)
{
    pb->cap = cap;
    pb->c = qc__alloc_array(ctx, cap, sizeof *pb->c);
    pb->r = qc__alloc_array(ctx, cap, sizeof *pb->r);
    pb->parent = qc__alloc_array(ctx, cap, sizeof *pb->parent);
    pb->node = qc__alloc_array(ctx, cap, sizeof *pb->node);
    pb->flags = qc__alloc_array(ctx, cap, sizeof *pb->flags);
    pb->contacts = qc__alloc_array(ctx, cap, sizeof *pb->contacts);
    if (pb->c == NULL || pb->r == NULL || pb->parent == NULL || pb->node == NULL ||
        pb->flags == NULL || pb->contacts == NULL)
        return QC_ENOMEM;
    return QC_OK;
}

int qc__pebbles_pack(qc_ctx *ctx, const qc_region *region, qc__pbound *b,
                     const qc_params *params, const qc_skeleton *skel, qc__pebbles *pb)
{
    pack P;
    double d = params->spacing, rs = params->r_seed, cells;
    size_t n = skel->n, i, cap;
    qc_bbox box;
    int rc;

    memset(pb, 0, sizeof *pb);
    memset(&P, 0, sizeof P);
    if (n == 0)
        return qc__fail(ctx, QC_EEMPTY, "pebbling needs at least one point");
    QC__TRY(qc__param_check(ctx, QC_PARAM_ID_SPACING, d));
    QC__TRY(qc__param_check(ctx, QC_PARAM_ID_R_SEED, rs));
    if (n > QC_MAX_POINTS)
        return qc__fail(ctx, QC_ELIMIT, "%lu points exceed the limit of %lu",
                        (unsigned long)n, (unsigned long)QC_MAX_POINTS);
    box = qc_region_bbox(region);
    for (i = 0; i < n; i++) {
        qc_vec2 p = skel->p[i];
        if (!(fabs(p.x) <= 1e9 && fabs(p.y) <= 1e9))
            return qc__fail(ctx, QC_ERANGE, "skeleton point %lu is not finite",
                            (unsigned long)i);
        box.min.x = fmin(box.min.x, p.x);
        box.min.y = fmin(box.min.y, p.y);
        box.max.x = fmax(box.max.x, p.x);
        box.max.y = fmax(box.max.y, p.y);
    }
    for (i = 0; i < skel->norder; i++)
        if (skel->order[i] >= n)
            return qc__fail(ctx, QC_EINVAL, "skeleton order entry %lu is %lu, beyond %lu points",
                            (unsigned long)i, (unsigned long)skel->order[i], (unsigned long)n);
    pb->r_first = rs * d;
    pb->r_grow = GROW_MAX * rs * d;
    pb->r_min = R_MIN * d;
    pb->touch = TOUCH * d;
    pb->k = params->edge == QC_EDGE_OVERGROW ? OVER_K : 1;
    /* each point adds a pebble and at most one filler; so does each place
     * reach() tries */
    cap = 2 * n + 1 + 2 * qc__pack_reach_tries(region, d);
    rc = alloc_pebbles(ctx, pb, cap);
    P.ctx = ctx;
    P.b = b;
    P.pb = pb;
    P.d = d;
    if (rc == QC_OK) {
        P.node = qc__alloc_array(ctx, cap, sizeof *P.node);
        if (P.node == NULL)
            rc = QC_ENOMEM;
    }
    if (rc == QC_OK) { /* cells of about d, at most about 4 per pebble slot */
        double pad = pb->r_grow + d, w, h;
        P.x0 = box.min.x - pad;
        P.y0 = box.min.y - pad;
        w = box.max.x - box.min.x + 2 * pad;
        h = box.max.y - box.min.y + 2 * pad;
        P.h = d;
        cells = (w / P.h + 1) * (h / P.h + 1);
        if (cells > 4.0 * (double)cap + 1024)
            P.h *= sqrt(cells / (4.0 * (double)cap + 1024)) * 1.01;
        P.nx = (uint32_t)(w / P.h) + 1;
        P.ny = (uint32_t)(h / P.h) + 1;
        P.head = qc__alloc_array(ctx, (size_t)P.nx * P.ny, sizeof *P.head);
        if (P.head == NULL)
            rc = QC_ENOMEM;
        else
            memset(P.head, 0xFF, (size_t)P.nx * P.ny * sizeof *P.head);
    }
    if (rc == QC_OK)
        rc = phase1(&P, skel);
    if (rc == QC_OK && pb->n == 0)
        rc = qc__fail(ctx, QC_EEMPTY, "no pebble of radius %g mm (d/10) fits in the region "
                      "at any of the %lu points", pb->r_min, (unsigned long)n);
    if (rc == QC_OK)
        rc = phase2(&P);
    if (rc == QC_OK) {
        qc__pack_reach(&P);
        count_contacts(&P);
    }
    qc__free(ctx, P.head, (size_t)P.nx * P.ny * sizeof *P.head);
    qc__free(ctx, P.node, cap * sizeof *P.node);
    if (rc != QC_OK)
        qc__pebbles_free(ctx, pb);
    return rc;
}
