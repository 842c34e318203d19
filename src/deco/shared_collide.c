/*
 * Collision grid: convex polygons binned into uniform cells by their box,
 * so a query touches only its neighbourhood (linear total cost); exact
 * answers by the separating-axis theorem.
 */
#include <math.h>
#include <string.h>

#include "deco_internal.h"

static void poly_box(const qc_vec2 *p, size_t n, qc_bbox *b)
{
    /* in locals: through b, every store might change p, so every load repeats */
    double x0 = p[0].x, y0 = p[0].y, x1 = x0, y1 = y0;
    size_t i;

    for (i = 1; i < n; i++) {
        double x = p[i].x, y = p[i].y;
        x0 = x < x0 ? x : x0;
        y0 = y < y0 ? y : y0;
        x1 = x > x1 ? x : x1;
        y1 = y > y1 ? y : y1;
    }
    b->min.x = x0;
    b->min.y = y0;
    b->max.x = x1;
    b->max.y = y1;
}

static int boxes_apart(const qc_bbox *a, const qc_bbox *b, double eps)
{
    return a->max.x + eps < b->min.x || b->max.x + eps < a->min.x ||
           a->max.y + eps < b->min.y || b->max.y + eps < a->min.y;
}

int qc__cgrid_init(qc_ctx *ctx, qc__cgrid *g, qc_bbox box, double cell, size_t max_cells)
{
    double w = box.max.x - box.min.x, h = box.max.y - box.min.y;
    double cells;
    size_t i, n;

    memset(g, 0, sizeof *g);
    if (!(cell > 0))
        cell = 1;
    if (max_cells < 16)
        max_cells = 16;
    cells = (w / cell + 1) * (h / cell + 1);
    if (cells > (double)max_cells)
        cell *= sqrt(cells / (double)max_cells) * 1.01;
    g->x0 = box.min.x;
    g->y0 = box.min.y;
    g->cell = cell;
    g->nx = (uint32_t)(w / cell) + 1;
    g->ny = (uint32_t)(h / cell) + 1;
    n = (size_t)g->nx * g->ny;
    g->head = qc__alloc_array(ctx, n, sizeof *g->head);
    if (g->head == NULL)
        return qc__fail(ctx, QC_ENOMEM, "collision grid of %zu cells", n);
    for (i = 0; i < n; i++)
        g->head[i] = UINT32_MAX;
    return QC_OK;
}

void qc__cgrid_free(qc_ctx *ctx, qc__cgrid *g)
{
    qc__free(ctx, g->head, (size_t)g->nx * g->ny * sizeof *g->head);
    qc__free(ctx, g->ent, g->ent_cap * sizeof *g->ent);
    qc__free(ctx, g->item, g->item_cap * sizeof *g->item);
    qc__free(ctx, g->stamp, g->stamp_cap * sizeof *g->stamp);
    qc__free(ctx, g->v, g->v_cap * sizeof *g->v);
    memset(g, 0, sizeof *g);
}

/* The column (y 0) or row (y 1) of coordinate v, clamped to the grid. */
static uint32_t cell_of(const qc__cgrid *g, double v, int y)
{
    double c = (v - (y ? g->y0 : g->x0)) / g->cell;
    double lim = y ? g->ny - 1 : g->nx - 1;

    /* truncation is floor here: negatives clamp to 0 first */
    return !(c >= 0) ? 0 : c > lim ? (uint32_t)lim : (uint32_t)c;
}

static void cell_range(const qc__cgrid *g, const qc_bbox *b, uint32_t r[4])
{
    r[0] = cell_of(g, b->min.x, 0);
    r[1] = cell_of(g, b->min.y, 1);
    r[2] = cell_of(g, b->max.x, 0);
    r[3] = cell_of(g, b->max.y, 1);
}

/* Room for need elements, growing by a quarter past the owner's
 * reservation (qc__cgrid_reserve) rather than doubling: at 10^6 points
 * these arrays are hundreds of MB and the reservation is close. */
static int grow(qc_ctx *ctx, void **p, size_t *cap, size_t need, size_t elem)
{
    size_t want = *cap + *cap / 4 + 64;

    if (need <= *cap)
        return QC_OK;
    return qc__reserve_exact(ctx, p, cap, want > need ? want : need, elem);
}

#define GROW(ctx, arr, capv, need) grow((ctx), (void **)&(arr), &(capv), (need), sizeof *(arr))

/* Room for one more item of n vertices. */
static int item_room(qc_ctx *ctx, qc__cgrid *g, size_t n)
{
    if (n == 0 || n > 65535 || g->nitem >= UINT32_MAX - 1 || g->nv + n >= UINT32_MAX)
        return qc__fail(ctx, QC_ELIMIT, "collision grid item of %zu vertices", n);
    if (GROW(ctx, g->v, g->v_cap, g->nv + n) < 0)
        return QC_ENOMEM;
    if (GROW(ctx, g->item, g->item_cap, g->nitem + 1) < 0)
        return QC_ENOMEM;
    if (GROW(ctx, g->stamp, g->stamp_cap, g->nitem + 1) < 0)
        return QC_ENOMEM;
    return QC_OK;
}

/* Files the next item under cell (x, y). */
static int enter(qc_ctx *ctx, qc__cgrid *g, uint32_t x, uint32_t y)
{
    size_t c = (size_t)y * g->nx + x;

    if (g->nent >= UINT32_MAX - 1)
        return qc__fail(ctx, QC_ELIMIT, "collision grid full");
    if (GROW(ctx, g->ent, g->ent_cap, g->nent + 1) < 0)
        return QC_ENOMEM;
    g->ent[g->nent].item = (uint32_t)g->nitem;
    g->ent[g->nent].next = g->head[c];
    g->head[c] = (uint32_t)g->nent++;
    return QC_OK;
}

/* Stores the next item's vertices and fields. */
static void store(qc__cgrid *g, const qc_vec2 *poly, size_t n, const qc_bbox *b, unsigned kind,
                  int chain, uint32_t id)
{
    memcpy(g->v + g->nv, poly, n * sizeof *poly);
    g->item[g->nitem].box = *b;
    g->item[g->nitem].off = (uint32_t)g->nv;
    g->item[g->nitem].n = (uint16_t)n;
    g->item[g->nitem].kind = (uint8_t)kind;
    g->item[g->nitem].chain = (uint8_t)chain;
    g->item[g->nitem].id = id;
    g->stamp[g->nitem] = 0;
    g->nitem++;
    g->nv += n;
}

/* A polygon item (shape 0) or a shape item (1: no vertices stored). */
static int add_polygon(qc_ctx *ctx, qc__cgrid *g, const qc_vec2 *poly, size_t n, unsigned kind,
                       uint32_t id, int shape)
{
    qc_bbox b;
    uint32_t r[4], x, y;

    if (n == 0 || n > 65535)
        return qc__fail(ctx, QC_ELIMIT, "collision grid item of %zu vertices", n);
    QC__TRY(item_room(ctx, g, shape ? 1 : n));
    poly_box(poly, n, &b);
    cell_range(g, &b, r);
    for (y = r[1]; y <= r[3]; y++)
        for (x = r[0]; x <= r[2]; x++)
            QC__TRY(enter(ctx, g, x, y));
    if (!shape) {
        store(g, poly, n, &b, kind, 0, id);
        return QC_OK;
    }
    store(g, poly, 0, &b, kind, 2, id);
    g->item[g->nitem - 1].n = (uint16_t)n;
    return QC_OK;
}

int qc__cgrid_add(qc_ctx *ctx, qc__cgrid *g, const qc_vec2 *poly, size_t n,
                  unsigned kind, uint32_t id)
{
    return add_polygon(ctx, g, poly, n, kind, id, 0);
}

int qc__cgrid_add_shape(qc_ctx *ctx, qc__cgrid *g, const qc_vec2 *poly, size_t n,
                        unsigned kind, uint32_t id)
{
    if (g->shape == NULL)
        return qc__fail(ctx, QC_EINVAL, "collision grid: a shape item without a shape callback");
    return add_polygon(ctx, g, poly, n, kind, id, 1);
}

int qc__cgrid_add_chain(qc_ctx *ctx, qc__cgrid *g, const qc_vec2 *pts, size_t n,
                        unsigned kind, uint32_t id)
{
    qc_bbox b;
    size_t k;
    uint32_t x, y, cx, cy; /* point k's cell */

    if (n < 2 || n > 65535)
        return qc__fail(ctx, QC_ELIMIT, "collision grid chain of %zu vertices", n);
    QC__TRY(item_room(ctx, g, n));
    cx = cell_of(g, pts[0].x, 0);
    cy = cell_of(g, pts[0].y, 1);
    for (k = 0; k + 1 < n; k++) {
        uint32_t nx = cell_of(g, pts[k + 1].x, 0), ny = cell_of(g, pts[k + 1].y, 1);
        /* the segment box's cell range, cell_of being monotone: its ends' */
        uint32_t x0 = cx < nx ? cx : nx, x1 = cx < nx ? nx : cx;
        uint32_t y0 = cy < ny ? cy : ny, y1 = cy < ny ? ny : cy;

        cx = nx;
        cy = ny;
        /* a cell already holding this item has it at its head: the
         * item's entries are the last filed */
        for (y = y0; y <= y1; y++)
            for (x = x0; x <= x1; x++) {
                uint32_t h = g->head[(size_t)y * g->nx + x];
                if (h == UINT32_MAX || g->ent[h].item != g->nitem)
                    QC__TRY(enter(ctx, g, x, y));
            }
    }
    poly_box(pts, n, &b);
    store(g, pts, n, &b, kind, 1, id);
    return QC_OK;
}

/* Projects p onto axis (ax, ay): [lo, hi]. */
static void project(const qc_vec2 *p, size_t n, double ax, double ay, double *lo, double *hi)
{
    size_t i;

    double l = p[0].x * ax + p[0].y * ay, h = l;

    for (i = 1; i < n; i++) {
        double d = p[i].x * ax + p[i].y * ay;
        if (d < l)
            l = d;
        if (d > h)
            h = d;
    }
    *lo = l;
    *hi = h;
}

/* A convex polygon's edge data, worked out on first need for all the items
 * a query meets (the same arithmetic as per test, so the same answers):
 * its edge vectors and lengths (seg_poly_apart), its edge normals and its
 * own extent along each (separated_by). Polygons of fewer than 3 or more
 * than EDGE_CACHE vertices go without. */
#define EDGE_CACHE 32

typedef struct edges {
    const qc_vec2 *p;
    size_t n;
    int have_e, have_n;
    double ex[EDGE_CACHE], ey[EDGE_CACHE], el[EDGE_CACHE];
    double ax[EDGE_CACHE], ay[EDGE_CACHE], len[EDGE_CACHE], lo[EDGE_CACHE], hi[EDGE_CACHE];
    unsigned char have_lh[EDGE_CACHE]; /* lo[i], hi[i] worked out (separated_by) */
} edges;

static void edges_init(edges *e, const qc_vec2 *p, size_t n)
{
    e->p = p;
    e->n = n;
    e->have_e = e->have_n = 0;
}

/* e's edge vectors, worked out if need be (their lengths on first use,
 * -1 till then): e, or NULL when it goes without. */
static edges *edge_vectors(edges *e)
{
    size_t i, n;

    if (e == NULL || e->n < 3 || e->n > EDGE_CACHE)
        return NULL;
    for (i = 0, n = e->n; !e->have_e && i < n; i++) {
        qc_vec2 a = e->p[i], b = e->p[i + 1 == n ? 0 : i + 1];
        double ex = b.x - a.x, ey = b.y - a.y;
        e->ex[i] = ex;
        e->ey[i] = ey;
        e->el[i] = -1;
    }
    e->have_e = 1;
    return e;
}

/* e's normals, worked out if need be (its extents on first use): e, or NULL. */
static edges *edge_normals(edges *e)
{
    size_t i, n;

    if (e == NULL || e->n < 3 || e->n > EDGE_CACHE)
        return NULL;
    for (i = 0, n = e->n; !e->have_n && i < n; i++) {
        qc_vec2 p = e->p[i], q = e->p[i + 1 == n ? 0 : i + 1];
        double ax = q.y - p.y, ay = p.x - q.x, len = sqrt(ax * ax + ay * ay);
        e->ax[i] = ax;
        e->ay[i] = ay;
        e->len[i] = len;
        e->have_lh[i] = 0;
    }
    e->have_n = 1;
    return e;
}

/* Whether b's projections d on (ax, ay) all lie above top, or all have
 * d + e below bottom: with top = ahi + e and bottom = alo, whether
 * ahi + e < blo or bhi + e < alo for b's extent [blo, bhi] (one of the d,
 * and rounding is monotone), without the whole extent: most pairs met
 * straddle, which the first few vertices show. */
static int all_beyond(const qc_vec2 *b, size_t nb, double ax, double ay, double top,
                      double bottom, double e)
{
    int above = 1, below = 1;
    size_t i;

    for (i = 0; i < nb; i++) {
        double d = b[i].x * ax + b[i].y * ay;
        above &= top < d;
        below &= d + e < bottom;
        if (!(above | below))
            return 0;
    }
    return 1;
}

/* Whether b straddles a on a's axis i (ax, ay), e >= 0, so that the axis
 * cannot separate them, by a's extent [alo, ahi] bounded without working
 * it out: ahi is at least the projection of a's vertex i, alo at most
 * that of the vertex across; a vertex of b below the one (+ e) and one
 * whose projection + e reaches the other fail both of all_beyond's tests. */
static int straddles(const qc_vec2 *a, size_t na, size_t i, const qc_vec2 *b, size_t nb,
                     double ax, double ay, double e)
{
    qc_vec2 p = a[i], q = a[i + na / 2 < na ? i + na / 2 : i + na / 2 - na];
    double top = p.x * ax + p.y * ay + e, low = q.x * ax + q.y * ay;
    int under = 0, over = 0;
    size_t k;

    for (k = 0; k < nb; k++) {
        double d = b[k].x * ax + b[k].y * ay;
        under |= !(top < d);
        over |= !(d + e < low);
        if (under & over)
            return 1;
    }
    return 0;
}

/* Whether an edge normal of a separates a from b (eps >= 0, in mm): on
 * some axis ahi + e < blo or bhi + e < alo, e = eps |axis|; ea: a's edge
 * data or NULL. */
static int separated_by(const qc_vec2 *a, size_t na, const qc_vec2 *b, size_t nb, double eps,
                        edges *ea)
{
    size_t i, ne = na == 2 ? 1 : na;
    edges *c = edge_normals(ea);

    for (i = 0; i < ne; i++) {
        double ax, ay, len, alo, ahi, e;
        if (c != NULL) {
            ax = c->ax[i];
            ay = c->ay[i];
            len = c->len[i];
        } else {
            qc_vec2 p = a[i], q = a[i + 1 == na ? 0 : i + 1];
            ax = q.y - p.y;
            ay = p.x - q.x;
            len = sqrt(ax * ax + ay * ay);
        }
        if (len < 1e-15)
            continue;
        e = eps * len;
        if (straddles(a, na, i, b, nb, ax, ay, e))
            continue;
        if (c != NULL && !c->have_lh[i]) {
            project(a, na, ax, ay, &c->lo[i], &c->hi[i]);
            c->have_lh[i] = 1;
        }
        if (c != NULL) {
            alo = c->lo[i];
            ahi = c->hi[i];
        } else {
            project(a, na, ax, ay, &alo, &ahi);
        }
        if (all_beyond(b, nb, ax, ay, ahi + e, alo, e))
            return 1;
    }
    return 0;
}

/* A segment against a convex CCW polygon in O(n): apart when one edge's
 * outer half-plane holds both ends, or the segment's line misses the
 * polygon. pe: p's edges, or NULL to work them out here. */
static int seg_poly_apart(const qc_vec2 *s, const qc_vec2 *p, size_t n, double eps,
                          edges *pcache)
{
    edges *pe = edge_vectors(pcache);
    double dx = s[1].x - s[0].x, dy = s[1].y - s[0].y, sl;
    double c;
    size_t i;

    for (i = 0; i < n; i++) {
        qc_vec2 a = p[i];
        double ex, ey, el, s0, s1;
        if (pe != NULL) {
            ex = pe->ex[i];
            ey = pe->ey[i];
        } else {
            qc_vec2 b = p[i + 1 == n ? 0 : i + 1];
            ex = b.x - a.x;
            ey = b.y - a.y;
        }
        s0 = ex * (s[0].y - a.y) - ey * (s[0].x - a.x);
        s1 = ex * (s[1].y - a.y) - ey * (s[1].x - a.x);
        /* -eps * el <= 0: an end on the inner side settles it without el */
        if (!(s0 < 0 && s1 < 0))
            continue;
        if (pe != NULL && pe->el[i] < 0)
            pe->el[i] = sqrt(ex * ex + ey * ey);
        el = pe != NULL ? pe->el[i] : sqrt(ex * ex + ey * ey);
        if (s0 < -eps * el && s1 < -eps * el) /* both right of a CCW edge: outside */
            return 1;
    }
    sl = sqrt(dx * dx + dy * dy);
    if (sl < 1e-15)
        return 0;
    /* the segment's own normal: hi + e < c or c + e < lo */
    c = -dy * s[0].x + dx * s[0].y;
    return all_beyond(p, n, -dy, dx, c + eps * sl, c, eps * sl);
}

/* How deep inside a polygon a point must be to settle an overlap: far
 * above the rounding of the projections (1e-13 mm at a metre), far below
 * any gap a caller asks about. */
#define DEEP 1e-6

/* The average of p's vertices: inside p (convex). */
static qc_vec2 mean_point(const qc_vec2 *p, size_t n)
{
    qc_vec2 c = {0, 0};
    size_t i;

    for (i = 0; i < n; i++) {
        c.x += p[i].x;
        c.y += p[i].y;
    }
    c.x /= (double)n;
    c.y /= (double)n;
    return c;
}

/* Whether c lies inside the CCW polygon p by more than DEEP from every
 * edge line (a CW polygon never qualifies). */
static int deep_inside(qc_vec2 c, const qc_vec2 *p, size_t n)
{
    size_t i;

    for (i = 0; i < n; i++) {
        qc_vec2 a = p[i], b = p[i + 1 == n ? 0 : i + 1];
        double ex = b.x - a.x, ey = b.y - a.y;
        double cr = ex * (c.y - a.y) - ey * (c.x - a.x);
        if (!(cr > 0) || cr * cr <= DEEP * DEEP * (ex * ex + ey * ey))
            return 0;
    }
    return 1;
}

/* A certificate that convex polygons a and b (3+ vertices each) overlap,
 * so that no axis separates them by any eps >= 0: the mean of one's
 * vertices (inside it) lies deep inside the other. On every axis both
 * projections then hold that point's, one by DEEP to spare, which the
 * projections' rounding cannot undo: the SAT's answer without its
 * na * nb products (a third of the motif pairs branching's queries meet;
 * the facing edges' normals, tried first, rarely separated the rest). */
static int overlap_certain(const qc_vec2 *a, size_t na, const qc_vec2 *b, size_t nb)
{
    return deep_inside(mean_point(a, na), b, nb) || deep_inside(mean_point(b, nb), a, na);
}

/* SAT once the boxes overlap; ea, eb: a's and b's edges or NULL. */
static int sat_touch_e(const qc_vec2 *a, size_t na, const qc_vec2 *b, size_t nb, double eps,
                       edges *ea, edges *eb)
{
    if (na == 2 && nb >= 3)
        return !seg_poly_apart(a, b, nb, eps, eb);
    if (nb == 2 && na >= 3)
        return !seg_poly_apart(b, a, na, eps, ea);
    if (na >= 3 && nb >= 3 && overlap_certain(a, na, b, nb))
        return 1;
    if (na >= 2 && separated_by(a, na, b, nb, eps, ea))
        return 0;
    if (nb >= 2 && separated_by(b, nb, a, na, eps, eb))
        return 0;
    return 1;
}

static int sat_touch(const qc_vec2 *a, size_t na, const qc_vec2 *b, size_t nb, double eps)
{
    return sat_touch_e(a, na, b, nb, eps, NULL, NULL);
}

int qc__convex_touch(const qc_vec2 *a, size_t na, const qc_vec2 *b, size_t nb, double eps)
{
    qc_bbox ba, bb;

    poly_box(a, na, &ba);
    poly_box(b, nb, &bb);
    if (boxes_apart(&ba, &bb, eps))
        return 0;
    return sat_touch(a, na, b, nb, eps);
}

/* The items of the given kinds in the cells a box meets, each once per
 * query (stamped), nearest cells first in row order. */
typedef struct candidates {
    qc__cgrid *g;
    unsigned kinds;
    uint32_t r[4], x, y, e;
} candidates;

static void candidates_begin(qc__cgrid *g, const qc_bbox *b, unsigned kinds, candidates *c)
{
    if (++g->cur == 0) { /* the stamps wrapped: forget them */
        memset(g->stamp, 0, g->nitem * sizeof *g->stamp);
        g->cur = 1;
    }
    c->g = g;
    c->kinds = kinds;
    cell_range(g, b, c->r);
    c->x = c->r[0];
    c->y = c->r[1];
    c->e = g->head[(size_t)c->y * g->nx + c->x];
}

/* The next candidate, or NULL when the box's cells are exhausted. */
static const qc__cgrid_item *candidates_next(candidates *c)
{
    qc__cgrid *g = c->g;

    for (;;) {
        uint32_t it;

        while (c->e == UINT32_MAX) {
            if (++c->x > c->r[2]) {
                c->x = c->r[0];
                if (++c->y > c->r[3])
                    return NULL;
            }
            c->e = g->head[(size_t)c->y * g->nx + c->x];
        }
        it = g->ent[c->e].item;
        c->e = g->ent[c->e].next;
        if (g->stamp[it] == g->cur)
            continue;
        g->stamp[it] = g->cur;
        if (c->kinds & (1u << g->item[it].kind))
            return &g->item[it];
    }
}

/* Whether poly (box b, edges pe or NULL) touches item m whose vertices
 * are v: a chain's segments one by one, each behind its own box test, as
 * if each were an item. */
static int item_touch(const qc__cgrid_item *m, const qc_vec2 *v, const qc_vec2 *poly, size_t n,
                      const qc_bbox *b, edges *pe)
{
    size_t k;

    if (m->chain != 1)
        return sat_touch_e(poly, n, v, m->n, 1e-9, pe, NULL);
    for (k = 0; k + 1 < m->n; k++) {
        qc_bbox sb;
        poly_box(v + k, 2, &sb);
        if (!boxes_apart(b, &sb, 1e-9) && sat_touch_e(poly, n, v + k, 2, 1e-9, pe, NULL))
            return 1;
    }
    return 0;
}

/* Item m's vertices: stored, or asked of the shape callback. */
static const qc_vec2 *item_verts(const qc__cgrid *g, const qc__cgrid_item *m)
{
    return m->chain == 2 ? g->shape(g->shape_ud, m->id) : g->v + m->off;
}

int qc__cgrid_hit(qc__cgrid *g, const qc_vec2 *poly, size_t n, unsigned kinds,
                  qc__cgrid_skip skip, void *ud)
{
    const qc__cgrid_item *m;
    candidates c;
    qc_bbox b;
    edges pe;

    if (n == 0 || g->nitem == 0)
        return 0;
    edges_init(&pe, poly, n);
    poly_box(poly, n, &b);
    candidates_begin(g, &b, kinds, &c);
    while ((m = candidates_next(&c)) != NULL) {
        if (skip != NULL && skip(ud, m->kind, m->id))
            continue;
        if (boxes_apart(&b, &m->box, 1e-9))
            continue;
        if (item_touch(m, item_verts(g, m), poly, n, &b, &pe))
            return 1;
    }
    return 0;
}

int qc__cgrid_add_region(qc_ctx *ctx, qc__cgrid *g, const qc_region *region, unsigned kind)
{
    size_t ring, i;

    for (ring = 0; ring < region->nrings; ring++) {
        size_t lo = ring ? region->ring_end[ring - 1] : 0, hi = region->ring_end[ring];
        for (i = lo; i < hi; i++) {
            qc_vec2 e[2];
            e[0] = region->v[i];
            e[1] = region->v[i + 1 < hi ? i + 1 : lo];
            QC__TRY(qc__cgrid_add(ctx, g, e, 2, kind, 0));
        }
    }
    return QC_OK;
}

int qc__cgrid_reserve(qc_ctx *ctx, qc__cgrid *g, size_t items, size_t verts, size_t entries)
{
    QC__TRY(QC__RESERVE_EXACT(ctx, g->item, g->item_cap, g->nitem + items));
    QC__TRY(QC__RESERVE_EXACT(ctx, g->stamp, g->stamp_cap, g->nitem + items));
    QC__TRY(QC__RESERVE_EXACT(ctx, g->v, g->v_cap, g->nv + verts));
    return QC__RESERVE_EXACT(ctx, g->ent, g->ent_cap, g->nent + entries);
}

/* Segment boxes worked out once per query (the polyline's) or once per
 * item (a chain's), rather than once per pair of segments. */
#define BOX_CACHE 32

/* Box of segment k of pts: from cache (n - 1 <= BOX_CACHE) or made. */
static void seg_box(const qc_vec2 *pts, const qc_bbox *cache, size_t k, qc_bbox *b)
{
    if (cache != NULL)
        *b = cache[k];
    else
        poly_box(pts + k, 2, b);
}

/* Whether polyline segment s (box sb) touches chain m (vertices v): its
 * segments near[0..nnear) (those whose boxes vb meet the polyline's box:
 * no other can meet sb), or all of them when near is NULL. */
static int seg_chain_touch(const qc__cgrid_item *m, const qc_vec2 *v, const qc_bbox *vb,
                           const unsigned char *near, size_t nnear, const qc_vec2 *s,
                           const qc_bbox *sb)
{
    size_t i, k, nk = near != NULL ? nnear : (size_t)m->n - 1;

    for (i = 0; i < nk; i++) {
        qc_bbox b;
        k = near != NULL ? near[i] : i;
        seg_box(v, vb, k, &b);
        if (!boxes_apart(sb, &b, 1e-9) && sat_touch(s, 2, v + k, 2, 1e-9))
            return 1;
    }
    return 0;
}

int qc__cgrid_hit_polyline(qc__cgrid *g, const qc_vec2 *pts, size_t n, unsigned kinds,
                           qc__cgrid_skip_seg skip, void *ud)
{
    const qc__cgrid_item *m;
    candidates c;
    qc_bbox b, qb[BOX_CACHE], mb[BOX_CACHE];
    unsigned char near[BOX_CACHE];
    const qc_bbox *qbp = n - 1 <= BOX_CACHE ? qb : NULL;
    size_t k;

    if (n < 2 || g->nitem == 0)
        return 0;
    poly_box(pts, n, &b);
    for (k = 0; qbp != NULL && k + 1 < n; k++)
        poly_box(pts + k, 2, &qb[k]);
    candidates_begin(g, &b, kinds, &c);
    while ((m = candidates_next(&c)) != NULL) {
        const qc_vec2 *v = NULL;
        const qc_bbox *mbp = NULL;
        const unsigned char *nearp = NULL;
        size_t nnear = 0;
        edges me;

        if (boxes_apart(&b, &m->box, 1e-9))
            continue;
        for (k = 0; k + 1 < n; k++) {
            qc_bbox sb;
            seg_box(pts, qbp, k, &sb);
            if (boxes_apart(&sb, &m->box, 1e-9))
                continue;
            if (skip != NULL && skip(ud, m->kind, m->id, k))
                continue;
            if (v == NULL) { /* once per item: a shape's vertices are made again */
                size_t i;
                v = item_verts(g, m);
                edges_init(&me, v, m->n);
                if (m->chain == 1 && m->n - 1 <= BOX_CACHE) {
                    for (i = 0; i + 1 < m->n; i++) {
                        poly_box(v + i, 2, &mb[i]);
                        if (!boxes_apart(&b, &mb[i], 1e-9))
                            near[nnear++] = (unsigned char)i;
                    }
                    mbp = mb;
                    nearp = near;
                }
            }
            if (m->chain != 1 ? sat_touch_e(pts + k, 2, v, m->n, 1e-9, NULL, &me)
                              : seg_chain_touch(m, v, mbp, nearp, nnear, pts + k, &sb))
                return 1;
        }
    }
    return 0;
}
