/*
 * Branching tiles (paper §7.1, Fig. 27): "distributing two special
 * vertically-mirrored points ..., using the tree node containing the start
 * point as the root ... and modifying the traversal algorithm such that the
 * skeleton path terminates at the end point". The ports are added to the
 * tree as leaves; the walk defers, at each node, the child towards the exit
 * port, so every other branch is sewn down and back as a detour and the
 * walk ends at the exit without returning. Collision tests see each item
 * also where it sits in the neighbouring tiles.
 */
#include <math.h>
#include <string.h>

#include "branching_tile.h"

#define NONE UINT32_MAX

/* Angle of v - u in [0, 2 pi). */
static double heading(const qc_vec2 *p, uint32_t u, uint32_t v)
{
    double a = qc_atan2(p[v].y - p[u].y, p[v].x - p[u].x);
    return a < 0.0 ? a + 2.0 * QC_PI : a;
}

/* Sorts the neighbours a[0..n) of u counter-clockwise from direction from,
 * strictly after it (so the parent sorts last), like qc_tree_walk. */
static void sort_ccw(const qc_vec2 *p, uint32_t u, uint32_t *a, size_t n, double *key,
                     double from)
{
    size_t i, j;

    for (i = 0; i < n; i++) {
        double k = heading(p, u, a[i]) - from;
        while (k <= 0.0)
            k += 2.0 * QC_PI;
        key[i] = k;
    }
    for (i = 1; i < n; i++) {
        double k = key[i];
        uint32_t v = a[i];
        for (j = i; j > 0 && (key[j - 1] > k || (key[j - 1] == k && a[j - 1] > v)); j--) {
            key[j] = key[j - 1];
            a[j] = a[j - 1];
        }
        key[j] = k;
        a[j] = v;
    }
}

typedef struct twalk {
    uint32_t *start, *adj, *par, *towards, *next, *stack;
    double *key;
    size_t n, nadj, maxdeg;
} twalk;

static void twalk_free(qc_ctx *ctx, twalk *w)
{
    qc__free(ctx, w->start, (w->n + 1) * sizeof *w->start);
    qc__free(ctx, w->adj, w->nadj * sizeof *w->adj);
    qc__free(ctx, w->par, w->n * sizeof *w->par);
    qc__free(ctx, w->towards, w->n * sizeof *w->towards);
    qc__free(ctx, w->next, w->n * sizeof *w->next);
    qc__free(ctx, w->stack, w->n * sizeof *w->stack);
    qc__free(ctx, w->key, (w->maxdeg + 1) * sizeof *w->key);
}

/* CSR adjacency, the parents from the entry port, the path to the exit. */
static int twalk_prepare(qc_ctx *ctx, const qc__btile *t, twalk *w)
{
    size_t n = t->n, i, sp = 0, reached = 1;
    uint32_t in = (uint32_t)(n - 2), u;

    w->n = n;
    w->nadj = 2 * t->ne;
    w->start = qc__alloc_array(ctx, n + 1, sizeof *w->start);
    w->adj = qc__alloc_array(ctx, w->nadj, sizeof *w->adj);
    w->par = qc__alloc_array(ctx, n, sizeof *w->par);
    w->towards = qc__alloc_array(ctx, n, sizeof *w->towards);
    w->next = qc__alloc_array(ctx, n, sizeof *w->next);
    w->stack = qc__alloc_array(ctx, n, sizeof *w->stack);
    if (w->start == NULL || w->adj == NULL || w->par == NULL || w->towards == NULL ||
        w->next == NULL || w->stack == NULL)
        return QC_ENOMEM;
    memset(w->start, 0, (n + 1) * sizeof *w->start);
    for (i = 0; i < t->ne; i++) {
        w->start[t->e[i].a + 1]++;
        w->start[t->e[i].b + 1]++;
    }
    for (i = 0; i < n; i++) {
        if (w->start[i + 1] > w->maxdeg)
            w->maxdeg = w->start[i + 1];
        w->start[i + 1] += w->start[i];
    }
    for (i = 0; i < t->ne; i++) { /* fill, advancing start[], then shift back */
        w->adj[w->start[t->e[i].a]++] = t->e[i].b;
        w->adj[w->start[t->e[i].b]++] = t->e[i].a;
    }
    for (i = n; i > 0; i--)
        w->start[i] = w->start[i - 1];
    w->start[0] = 0;
    w->key = qc__alloc_array(ctx, w->maxdeg + 1, sizeof *w->key);
    if (w->key == NULL)
        return QC_ENOMEM;
    /* parents by depth-first search from the entry port */
    memset(w->par, 0xff, n * sizeof *w->par);
    memset(w->towards, 0xff, n * sizeof *w->towards);
    w->par[in] = in;
    w->stack[sp++] = in;
    while (sp > 0) {
        u = w->stack[--sp];
        for (i = w->start[u]; i < w->start[u + 1]; i++) {
            uint32_t v = w->adj[i];
            if (v == w->par[u])
                continue;
            if (w->par[v] != NONE)
                return qc__fail(ctx, QC_EINVAL, "the edges hold a cycle through point %lu",
                                (unsigned long)v);
            w->par[v] = u;
            w->stack[sp++] = v;
            reached++;
        }
    }
    if (reached != n)
        return qc__fail(ctx, QC_EINVAL, "the edges do not connect all %lu points: not a "
                        "spanning tree", (unsigned long)(n - 2));
    for (u = (uint32_t)(n - 1); u != in; u = w->par[u])
        w->towards[w->par[u]] = u;
    return QC_OK;
}

static int tile_walk(qc_ctx *ctx, qc__btile *t)
{
    twalk w;
    uint32_t in = (uint32_t)(t->n - 2), out = (uint32_t)(t->n - 1), u;
    int rc;

    memset(&w, 0, sizeof w);
    rc = twalk_prepare(ctx, t, &w);
    if (rc == QC_OK)
        rc = QC__RESERVE(ctx, t->order.i, t->order.cap, 2 * t->n);
    if (rc < 0)
        goto out_free;
    u = in;
    w.next[in] = w.start[in];
    rc = qc_order_push(ctx, &t->order, in);
    while (rc == QC_OK) {
        uint32_t v = NONE;

        while (v == NONE && w.next[u] < w.start[u + 1]) {
            v = w.adj[w.next[u]++];
            if (v == w.par[u] || v == w.towards[u])
                v = NONE;
        }
        if (v == NONE && w.towards[u] != NONE) {
            v = w.towards[u];
            w.towards[u] = NONE; /* never back here: the walk ends beyond */
        }
        if (v != NONE) {
            sort_ccw(t->p, v, w.adj + w.start[v], w.start[v + 1] - w.start[v], w.key,
                     heading(t->p, v, u));
            w.next[v] = w.start[v];
            u = v;
        } else if (u == out || u == in) {
            break;
        } else {
            u = w.par[u];
        }
        rc = qc_order_push(ctx, &t->order, u);
    }
out_free:
    twalk_free(ctx, &w);
    return rc;
}

void qc__btile_free(qc_ctx *ctx, qc__btile *t)
{
    if (t == NULL)
        return;
    qc__free(ctx, t->p, t->n * sizeof *t->p);
    qc__free(ctx, t->e, t->ne * sizeof *t->e);
    qc_order_free(ctx, &t->order);
    qc__free(ctx, t->tmp, t->tmp_cap * sizeof *t->tmp);
    memset(t, 0, sizeof *t);
}

int qc__btile_make(qc_ctx *ctx, const qc_region *region, const qc_skeleton *skel,
                   int all_over, qc__btile *t, qc_skeleton *out)
{
    size_t n = skel->n, i;
    qc_bbox box;
    int rc;

    memset(t, 0, sizeof *t);
    if (n == 0)
        return qc__fail(ctx, QC_EEMPTY, "branching needs at least one point");
    if (n > 1 && (skel->edges == NULL || skel->nedges + 1 != n))
        return qc__fail(ctx, QC_EINVAL, "branching tiles need a spanning tree (skeleton mst), "
                        "got %lu edges for %lu points",
                        (unsigned long)(skel->edges != NULL ? skel->nedges : 0),
                        (unsigned long)n);
    if (n > (size_t)UINT32_MAX - 2)
        return qc__fail(ctx, QC_ELIMIT, "branching tile of %lu points", (unsigned long)n);
    for (i = 0; i + 1 < n; i++)
        if (skel->edges[i].a >= n || skel->edges[i].b >= n || skel->edges[i].a == skel->edges[i].b)
            return qc__fail(ctx, QC_EINVAL, "edge %lu (%lu, %lu) is not an edge of %lu points",
                            (unsigned long)i, (unsigned long)skel->edges[i].a,
                            (unsigned long)skel->edges[i].b, (unsigned long)n);
    QC__TRY(qc_tile_ports(ctx, region, &t->entry, &t->exit));
    box = qc_region_bbox(region);
    t->dx = t->exit.x - t->entry.x;
    t->dy = box.max.y - box.min.y;
    t->shift[t->nshift++] = (qc_vec2){t->dx, 0.0};
    t->shift[t->nshift++] = (qc_vec2){-t->dx, 0.0};
    if (all_over) {
        int sx, sy;
        for (sy = -1; sy <= 1; sy += 2)
            for (sx = -1; sx <= 1; sx++)
                t->shift[t->nshift++] = (qc_vec2){sx * t->dx, sy * t->dy};
    }
    t->p = qc__alloc_array(ctx, n + 2, sizeof *t->p);
    t->e = qc__alloc_array(ctx, n + 1, sizeof *t->e);
    if (t->p == NULL || t->e == NULL) {
        qc__free(ctx, t->p, (n + 2) * sizeof *t->p);
        qc__free(ctx, t->e, (n + 1) * sizeof *t->e);
        memset(t, 0, sizeof *t);
        return QC_ENOMEM;
    }
    t->n = n + 2;
    t->ne = n + 1;
    memcpy(t->p, skel->p, n * sizeof *t->p);
    if (n > 1)
        memcpy(t->e, skel->edges, (n - 1) * sizeof *t->e);
    t->p[n] = t->entry;
    t->p[n + 1] = t->exit;
    t->e[n - 1].a = qc__tile_port_node(skel->p, n, t->e, n - 1, t->entry);
    t->e[n - 1].b = (uint32_t)n;
    t->e[n].a = qc__tile_port_node(skel->p, n, t->e, n - 1, t->exit);
    t->e[n].b = (uint32_t)(n + 1);
    rc = tile_walk(ctx, t);
    if (rc < 0) {
        qc__btile_free(ctx, t);
        return rc;
    }
    memset(out, 0, sizeof *out);
    out->p = t->p;
    out->n = t->n;
    out->edges = t->e;
    out->nedges = t->ne;
    out->order = t->order.i;
    out->norder = t->order.n;
    out->root = (uint32_t)n;
    return QC_OK;
}

void qc__btile_flat_ports(const qc__btile *t, qc_path *vine)
{
    size_t m = vine->npt;
    qc_vec2 *q = vine->pt;
    double l;

    if (vine->ncmd < 2 || m < 4)
        return;
    q[0] = t->entry;
    q[m - 1] = t->exit;
    l = qc_hypot(q[1].x - q[0].x, q[1].y - q[0].y);
    q[1].x = q[0].x + l;
    q[1].y = q[0].y;
    l = qc_hypot(q[m - 1].x - q[m - 2].x, q[m - 1].y - q[m - 2].y);
    q[m - 2].x = q[m - 1].x - l;
    q[m - 2].y = q[m - 1].y;
}

int qc__btile_grid_add(qc_ctx *ctx, qc__btile *t, qc__cgrid *g, const qc_vec2 *poly,
                       size_t n, unsigned kind, uint32_t id)
{
    double x1 = g->x0 + g->nx * g->cell, y1 = g->y0 + g->ny * g->cell;
    qc_bbox b;
    size_t i, k;

    QC__TRY(qc__cgrid_add(ctx, g, poly, n, kind, id));
    if (n == 0)
        return QC_OK;
    b.min = b.max = poly[0];
    for (i = 1; i < n; i++) {
        if (poly[i].x < b.min.x)
            b.min.x = poly[i].x;
        if (poly[i].y < b.min.y)
            b.min.y = poly[i].y;
        if (poly[i].x > b.max.x)
            b.max.x = poly[i].x;
        if (poly[i].y > b.max.y)
            b.max.y = poly[i].y;
    }
    for (k = 0; k < t->nshift; k++) {
        qc_vec2 s = t->shift[k];
        if (b.max.x + s.x < g->x0 || b.min.x + s.x > x1 || b.max.y + s.y < g->y0 ||
            b.min.y + s.y > y1)
            continue; /* that copy is beyond every query */
        QC__TRY(QC__RESERVE(ctx, t->tmp, t->tmp_cap, n));
        for (i = 0; i < n; i++) {
            t->tmp[i].x = poly[i].x + s.x;
            t->tmp[i].y = poly[i].y + s.y;
        }
        QC__TRY(qc__cgrid_add(ctx, g, t->tmp, n, kind, id));
    }
    return QC_OK;
}

int qc__btile_layout(qc_ctx *ctx, const qc__btile *t, const qc_params *prm, const qc_path *tile,
                     qc_path *out)
{
    unsigned cols = prm->repeat_cols >= 1.0 ? (unsigned)prm->repeat_cols : 1u;
    unsigned rows = prm->repeat_rows >= 1.0 ? (unsigned)prm->repeat_rows : 1u;
    size_t nc = out->ncmd, np = out->npt, k;
    double lift = (double)(rows - 1) * t->dy, copies = (double)cols * rows;
    int rc = QC_OK;

    /* room for every copy at once: no regrowth of a large path */
    if (copies * (double)tile->npt + (double)np + rows < (double)SIZE_MAX / 32) {
        size_t k2 = (size_t)cols * rows;
        rc = QC__RESERVE(ctx, out->cmd, out->cmd_cap, nc + k2 * tile->ncmd + rows);
        if (rc == QC_OK)
            rc = QC__RESERVE(ctx, out->pt, out->pt_cap, np + k2 * tile->npt + rows);
    }
    if (rc == QC_OK)
        rc = qc_tile_repeat(ctx, tile, t->dx, t->dy, cols, rows, out);
    if (rc < 0) {
        out->ncmd = nc;
        out->npt = np;
        return rc;
    }
    /* rows are sewn top down: lift them so the bottom row sits on the
     * tile's own box */
    for (k = np; k < out->npt; k++)
        out->pt[k].y += lift;
    return QC_OK;
}
