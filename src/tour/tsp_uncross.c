/*
 * Makes the tour simple: every pair of tour edges that cross properly
 * (decided by the exact orientation predicate on the caller's coordinates)
 * is replaced by the 2-opt move that uncrosses it. Two properly crossing
 * segments are always longer than the two that join their ends on the same
 * side, so each move shortens the tour exactly and the process ends.
 *
 * A box tree over the points in Hilbert order, each leaf bounding its
 * points' two tour edges, finds the crossings of the tour once; those
 * edges go on a stack. Each edge taken from the stack that still exists
 * and still crosses some edge is uncrossed, and the two edges the move
 * creates go on the stack (a reversal changes no other segment). Boxes
 * only grow, so they stay valid as edges change. When the stack is empty,
 * every edge has been checked against every edge it coexisted with.
 */
#include <stdlib.h>
#include <string.h>

#include "tour_internal.h"

typedef struct uncross {
    qc__tsp *s;
    qc__btree tree;
    uint32_t *stack; /* pairs: edges to check */
    size_t n, cap;
    uint32_t lo;      /* the edges of points below lo are not looked at */
    int first;        /* stop at the first crossing (else stack them all) */
    uint32_t c, d;    /* the crossing edge found */
} uncross;

static int sgn(double v)
{
    return (v > 0.0) - (v < 0.0);
}

static int cross_properly(qc_vec2 a, qc_vec2 b, qc_vec2 c, qc_vec2 d)
{
    int o1 = sgn(qc_orient2d(a, b, c)), o2 = sgn(qc_orient2d(a, b, d));

    if (o1 == 0 || o2 == 0 || o1 == o2)
        return 0;
    o1 = sgn(qc_orient2d(c, d, a));
    o2 = sgn(qc_orient2d(c, d, b));
    return o1 != 0 && o2 != 0 && o1 != o2;
}

static qc__box seg_box(qc_vec2 a, qc_vec2 b)
{
    qc__box x;

    x.x0 = a.x < b.x ? a.x : b.x;
    x.x1 = a.x < b.x ? b.x : a.x;
    x.y0 = a.y < b.y ? a.y : b.y;
    x.y1 = a.y < b.y ? b.y : a.y;
    return x;
}

static void grow(qc__box *b, qc_vec2 p)
{
    b->x0 = p.x < b->x0 ? p.x : b->x0;
    b->x1 = p.x > b->x1 ? p.x : b->x1;
    b->y0 = p.y < b->y0 ? p.y : b->y0;
    b->y1 = p.y > b->y1 ? p.y : b->y1;
}

static int overlap(const qc__box *a, const qc__box *b)
{
    return a->x0 <= b->x1 && b->x0 <= a->x1 && a->y0 <= b->y1 && b->y0 <= a->y1;
}

static int push_edge(uncross *u, uint32_t a, uint32_t b)
{
    if (QC__RESERVE(u->s->ctx, u->stack, u->cap, 2 * u->n + 2) < 0)
        return qc__fail(u->s->ctx, QC_ENOMEM, "tsp: out of memory listing crossings");
    u->stack[2 * u->n] = a;
    u->stack[2 * u->n + 1] = b;
    u->n++;
    return QC_OK;
}

/*
 * Looks for edges (v, next(v)), v >= lo, in the subtree (level, node) that
 * cross (a, b). 1 when the search should stop (first crossing found), -1
 * on allocation failure, else 0.
 */
static int query(uncross *u, int level, size_t node, uint32_t a, uint32_t b, const qc__box *qb)
{
    qc__tsp *s = u->s;
    size_t v = (node << level) * QC__TSP_LEAF;
    size_t end = ((node + 1) << level) * QC__TSP_LEAF;
    int r;

    if (end <= u->lo || !overlap(u->tree.box + u->tree.off[level] + node, qb))
        return 0;
    if (level > 0) {
        r = query(u, level - 1, 2 * node, a, b, qb);
        if (r == 0 && 2 * node + 1 < u->tree.cnt[level - 1])
            r = query(u, level - 1, 2 * node + 1, a, b, qb);
        return r;
    }
    if (end > s->m)
        end = s->m;
    if (v < u->lo)
        v = u->lo;
    for (; v < end; v++) {
        uint32_t c = (uint32_t)v, d = qc__tsp_next(s, c);
        qc__box eb;

        if (c == a || c == b || d == a || d == b)
            continue; /* the same edge, or edges sharing a point */
        eb = seg_box(s->q[c], s->q[d]);
        if (!overlap(&eb, qb) || !cross_properly(s->q[a], s->q[b], s->q[c], s->q[d]))
            continue;
        if (u->first) {
            u->c = c;
            u->d = d;
            return 1;
        }
        if (push_edge(u, a, b) < 0 || push_edge(u, c, d) < 0)
            return -1;
    }
    return 0;
}

/* Leaf boxes: each point with both its tour edges. */
static void build(uncross *u)
{
    qc__tsp *s = u->s;
    size_t j, i;

    for (j = 0; j < u->tree.cnt[0]; j++) {
        size_t end = (j + 1) * QC__TSP_LEAF < s->m ? (j + 1) * QC__TSP_LEAF : s->m;
        qc__box b = seg_box(s->q[j * QC__TSP_LEAF], s->q[j * QC__TSP_LEAF]);

        for (i = j * QC__TSP_LEAF; i < end; i++) {
            grow(&b, s->q[i]);
            grow(&b, s->q[qc__tsp_next(s, (uint32_t)i)]);
            grow(&b, s->q[qc__tsp_prev(s, (uint32_t)i)]);
        }
        u->tree.box[j] = b;
    }
    qc__btree_finish(&u->tree);
}

/* Point a gained the neighbour b: grows a's leaf and its ancestors. */
static void widen(uncross *u, uint32_t a, uint32_t b)
{
    size_t j = a / QC__TSP_LEAF;
    int l;

    for (l = 0; l < u->tree.levels; l++, j /= 2) {
        qc__box *x = u->tree.box + u->tree.off[l] + j;
        qc_vec2 p = u->s->q[b];
        if (p.x >= x->x0 && p.x <= x->x1 && p.y >= x->y0 && p.y <= x->y1)
            break;
        grow(x, p);
    }
}

/* ---- the first look: a grid ---- */

/* The first look for crossings files each tour edge in the cells of a grid
 * its box meets (about EDGES_PER_CELL a cell) and tests the edges sharing a
 * cell, each pair once (in the cell of the lower-left corner of their
 * boxes' overlap); it finds the pairs the box tree's scan from every edge
 * finds, and stacks them in its order (by the lower first point, then the
 * higher). A 10 m wanderer (623,518 points): the scan's queries were 3.8%
 * of the whole run's profile, the uncrossing with the grid 1.7%. Long
 * edges over a fine grid (GRID_MAX_FILED) or clusters in a coarse one
 * (GRID_MAX_PAIRS) leave it to the scan. */
#define EDGES_PER_CELL 2
#define GRID_MAX_FILED 16
#define GRID_MAX_PAIRS 16 /* per edge: pairs sharing a cell (clustered points) */

typedef struct egrid {
    double x0, y0, inv;
    uint32_t gx, gy;
} egrid;

static uint32_t cell_x(const egrid *g, double x)
{
    double f = (x - g->x0) * g->inv;

    return f > 0 ? (f < g->gx ? (uint32_t)f : g->gx - 1) : 0;
}

static uint32_t cell_y(const egrid *g, double y)
{
    double f = (y - g->y0) * g->inv;

    return f > 0 ? (f < g->gy ? (uint32_t)f : g->gy - 1) : 0;
}

static egrid make_egrid(const qc__tsp *s)
{
    qc__box b = seg_box(s->q[0], s->q[0]);
    double w, h, target, side;
    egrid g;
    uint32_t i;

    for (i = 1; i < s->m; i++)
        grow(&b, s->q[i]);
    w = b.x1 - b.x0, h = b.y1 - b.y0;
    target = (double)s->m / EDGES_PER_CELL + 1;
    side = sqrt(w * h / target);
    g.x0 = b.x0, g.y0 = b.y0;
    side = side > (w + h) / target ? side : (w + h) / target;
    if (!(side > 0)) /* distinct points: only if they are too close to tell */
        side = 1;
    while ((w / side + 1) * (h / side + 1) > 2 * target)
        side *= 1.25;
    g.gx = (uint32_t)(w / side + 1), g.gy = (uint32_t)(h / side + 1);
    g.inv = 1 / side;
    return g;
}

static int cmp_u64(const void *x, const void *y)
{
    uint64_t a = *(const uint64_t *)x, b = *(const uint64_t *)y;

    return (a > b) - (a < b);
}

/* Tests the edges from a and c (a < c) met in cell (cx, cy); 1 if they
 * cross properly and this cell reports them. */
static int cell_pair(const qc__tsp *s, const egrid *g, uint32_t cx, uint32_t cy, uint32_t a,
                     uint32_t c)
{
    uint32_t b = qc__tsp_next(s, a), d = qc__tsp_next(s, c);
    qc__box ab, cd;

    if (c == b || d == a || d == b)
        return 0; /* edges sharing a point */
    ab = seg_box(s->q[a], s->q[b]);
    cd = seg_box(s->q[c], s->q[d]);
    if (!overlap(&ab, &cd))
        return 0;
    if (cell_x(g, ab.x0 > cd.x0 ? ab.x0 : cd.x0) != cx ||
        cell_y(g, ab.y0 > cd.y0 ? ab.y0 : cd.y0) != cy)
        return 0;
    return cross_properly(s->q[a], s->q[b], s->q[c], s->q[d]);
}

/* Stacks every crossing pair as the scan would: 0, or 1 when the grid
 * would be too large (nothing stacked), or QC_ENOMEM. */
static int grid_scan(uncross *u)
{
    qc__tsp *s = u->s;
    qc_ctx *ctx = s->ctx;
    egrid g = make_egrid(s);
    size_t ncell = (size_t)g.gx * g.gy, filed = 0, npair = 0, cap = 0, tests = 0, i, j, k;
    size_t *start = NULL;
    uint32_t *edge = NULL, c, x, y;
    uint64_t *pair = NULL;
    int rc = QC_ENOMEM;

    for (c = 0; c < s->m; c++) {
        qc__box e = seg_box(s->q[c], s->q[qc__tsp_next(s, c)]);
        filed += (size_t)(cell_x(&g, e.x1) - cell_x(&g, e.x0) + 1) *
                 (cell_y(&g, e.y1) - cell_y(&g, e.y0) + 1);
    }
    if (filed > (size_t)GRID_MAX_FILED * s->m)
        return 1;
    start = qc__alloc_array(ctx, ncell + 1, sizeof *start);
    edge = qc__alloc_array(ctx, filed, sizeof *edge);
    if (start == NULL || edge == NULL)
        goto out;
    memset(start, 0, (ncell + 1) * sizeof *start);
    for (k = 0; k < 2; k++) { /* count, then file in order of c */
        for (c = 0; c < s->m; c++) {
            qc__box e = seg_box(s->q[c], s->q[qc__tsp_next(s, c)]);
            for (y = cell_y(&g, e.y0); y <= cell_y(&g, e.y1); y++)
                for (x = cell_x(&g, e.x0); x <= cell_x(&g, e.x1); x++) {
                    size_t at = (size_t)y * g.gx + x;
                    if (k == 0)
                        start[at + 1]++;
                    else
                        edge[start[at]++] = c;
                }
        }
        if (k == 0) {
            for (i = 0; i < ncell; i++) {
                tests += start[i + 1] * (start[i + 1] - (start[i + 1] > 0)) / 2;
                start[i + 1] += start[i];
            }
            if (tests > (size_t)GRID_MAX_PAIRS * s->m) {
                rc = 1;
                goto out;
            }
        } else
            for (i = ncell; i > 0; i--) /* back to each cell's first entry */
                start[i] = start[i - 1];
        start[0] = 0;
    }
    for (i = 0; i < ncell; i++)
        for (j = start[i]; j < start[i + 1]; j++)
            for (k = j + 1; k < start[i + 1]; k++)
                if (cell_pair(s, &g, (uint32_t)(i % g.gx), (uint32_t)(i / g.gx), edge[j],
                              edge[k])) {
                    if (QC__RESERVE(ctx, pair, cap, npair + 1) < 0)
                        goto out;
                    pair[npair++] = (uint64_t)edge[j] << 32 | edge[k];
                }
    if (npair > 1) /* (qsort takes no null array, even of none) */
        qsort(pair, npair, sizeof *pair, cmp_u64);
    for (i = 0; i < npair; i++) {
        uint32_t a = (uint32_t)(pair[i] >> 32);
        c = (uint32_t)pair[i];
        if (push_edge(u, a, qc__tsp_next(s, a)) < 0 || push_edge(u, c, qc__tsp_next(s, c)) < 0)
            goto out;
    }
    rc = QC_OK;
out:
    qc__free(ctx, start, (ncell + 1) * sizeof *start);
    qc__free(ctx, edge, filed * sizeof *edge);
    qc__free(ctx, pair, cap * sizeof *pair);
    return rc;
}

static int linked(const qc__tsp *s, uint32_t a, uint32_t b)
{
    return qc__tsp_next(s, a) == b || qc__tsp_prev(s, a) == b;
}

static int run(uncross *u)
{
    qc__tsp *s = u->s;
    uint32_t a, t;
    int rc;

    build(u);
    u->first = 0;
    rc = grid_scan(u);
    for (a = 0; rc == 1 && a < s->m; a++) { /* every crossing pair once */
        uint32_t b = qc__tsp_next(s, a);
        qc__box qb = seg_box(s->q[a], s->q[b]);

        u->lo = a + 1;
        if (query(u, u->tree.levels - 1, 0, a, b, &qb) < 0)
            return QC_ENOMEM;
    }
    if (rc < 0)
        return rc;
    u->first = 1;
    u->lo = 0;
    while (u->n > 0) {
        uint32_t b, c, d;
        qc__box qb;

        u->n--;
        a = u->stack[2 * u->n];
        b = u->stack[2 * u->n + 1];
        if (!linked(s, a, b))
            continue;
        qb = seg_box(s->q[a], s->q[b]);
        if (query(u, u->tree.levels - 1, 0, a, b, &qb) == 0)
            continue;
        c = u->c;
        d = u->d;
        if (qc__tsp_next(s, a) != b)
            t = a, a = b, b = t;
        if (qc__tsp_next(s, c) != d)
            t = c, c = d, d = t;
        QC__TRY(qc__tsp_move2(s, a, b, c, d));
        widen(u, a, c);
        widen(u, c, a);
        widen(u, b, d);
        widen(u, d, b);
        QC__TRY(push_edge(u, a, c));
        QC__TRY(push_edge(u, b, d));
    }
    return QC_OK;
}

int qc__tsp_uncross(qc__tsp *s)
{
    uncross u;
    int rc;

    if (s->m < 4)
        return QC_OK;
    memset(&u, 0, sizeof u);
    u.s = s;
    rc = qc__btree_init(s->ctx, &u.tree, (s->m + QC__TSP_LEAF - 1) / QC__TSP_LEAF);
    if (rc == QC_OK)
        rc = run(&u);
    qc__btree_free(s->ctx, &u.tree);
    qc__free(s->ctx, u.stack, u.cap * sizeof *u.stack);
    return rc;
}
