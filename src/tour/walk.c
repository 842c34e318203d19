/*
 * The tree walk of paper §4.2 (Fig. 5): depth first from the root, the
 * children of each node taken counter-clockwise starting from the direction
 * back to its parent, so the walk traces the tree's outline (or, to an end
 * point, every other branch as a detour and then on to the end); and
 * qc_nearest_point for choosing the root.
 */
#include <string.h>

#include "internal.h"

uint32_t qc_nearest_point(const qc_vec2 *p, size_t n, qc_vec2 q)
{
    size_t i, best = 0;
    double bd = 0.0;

    for (i = 0; i < n; i++) {
        double dx = p[i].x - q.x, dy = p[i].y - q.y, d = dx * dx + dy * dy;
        if (i == 0 || d < bd) {
            bd = d;
            best = i;
        }
    }
    return (uint32_t)best;
}

typedef struct walk_ctx {
    const qc_vec2 *p;
    uint32_t *start, *adj; /* CSR adjacency */
    double *key;           /* scratch: sort keys of one node's neighbours */
} walk_ctx;

/* Angle of v - u in [0, 2 pi). */
static double heading(const qc_vec2 *p, uint32_t u, uint32_t v)
{
    double a = qc_atan2(p[v].y - p[u].y, p[v].x - p[u].x);
    return a < 0.0 ? a + 2.0 * QC_PI : a;
}

/* Sorts u's neighbours counter-clockwise from direction `from`: the root's
 * from +x inclusive, others' from the parent exclusive (the parent sorts
 * last). Insertion sort: degrees are small. */
static void sort_neighbours(walk_ctx *w, uint32_t u, double from, int is_root)
{
    uint32_t *a = w->adj + w->start[u];
    size_t n = w->start[u + 1] - w->start[u], i, j;

    for (i = 0; i < n; i++) {
        double k = heading(w->p, u, a[i]) - from;
        while (k < 0.0 || (k == 0.0 && !is_root))
            k += 2.0 * QC_PI;
        w->key[i] = k;
    }
    for (i = 1; i < n; i++) {
        double k = w->key[i];
        uint32_t v = a[i];
        for (j = i; j > 0 && (w->key[j - 1] > k || (w->key[j - 1] == k && a[j - 1] > v)); j--) {
            w->key[j] = w->key[j - 1];
            a[j] = a[j - 1];
        }
        w->key[j] = k;
        a[j] = v;
    }
}

static int build_adjacency(qc_ctx *ctx, walk_ctx *w, size_t n, const qc_edge *e, size_t m,
                           size_t *max_degree)
{
    size_t i;

    w->start = qc__alloc_array(ctx, n + 1, sizeof *w->start);
    w->adj = qc__alloc_array(ctx, 2 * m + 1, sizeof *w->adj);
    if (w->start == NULL || w->adj == NULL)
        return QC_ENOMEM;
    memset(w->start, 0, (n + 1) * sizeof *w->start);
    for (i = 0; i < m; i++) {
        if (e[i].a >= n || e[i].b >= n || e[i].a == e[i].b)
            return qc__fail(ctx, QC_EINVAL, "edge %lu (%lu, %lu) is not an edge of %lu points",
                            (unsigned long)i, (unsigned long)e[i].a, (unsigned long)e[i].b,
                            (unsigned long)n);
        w->start[e[i].a + 1]++;
        w->start[e[i].b + 1]++;
    }
    *max_degree = 0;
    for (i = 0; i < n; i++) {
        if (w->start[i + 1] > *max_degree)
            *max_degree = w->start[i + 1];
        w->start[i + 1] += w->start[i];
    }
    for (i = 0; i < m; i++) { /* fill, advancing start[], then shift back */
        w->adj[w->start[e[i].a]++] = e[i].b;
        w->adj[w->start[e[i].b]++] = e[i].a;
    }
    for (i = n; i > 0; i--)
        w->start[i] = w->start[i - 1];
    w->start[0] = 0;
    return QC_OK;
}

#define NONE UINT32_MAX

/* towards[u] = the neighbour of u on the tree path from root to end (NONE
 * off that path), from parents found by a depth-first search from root. */
static int path_to_end(qc_ctx *ctx, const walk_ctx *w, size_t n, uint32_t root, uint32_t end,
                       uint32_t *towards)
{
    uint32_t *par = qc__alloc_array(ctx, n, sizeof *par);
    uint32_t *stack = qc__alloc_array(ctx, n, sizeof *stack);
    size_t sp = 0, i;
    uint32_t u;
    int rc = QC_OK;

    if (par == NULL || stack == NULL) {
        rc = QC_ENOMEM;
        goto out;
    }
    memset(par, 0xff, n * sizeof *par);
    par[root] = root;
    stack[sp++] = root;
    while (sp > 0 && rc == QC_OK) {
        u = stack[--sp];
        for (i = w->start[u]; i < w->start[u + 1]; i++) {
            uint32_t v = w->adj[i];
            if (v == par[u])
                continue;
            if (par[v] != NONE) {
                rc = qc__fail(ctx, QC_EINVAL, "the edges hold a cycle through point %lu",
                              (unsigned long)v);
                break;
            }
            par[v] = u;
            stack[sp++] = v;
        }
    }
    if (rc == QC_OK && par[end] == NONE)
        rc = qc__fail(ctx, QC_EINVAL, "end point %lu is not connected to the root %lu",
                      (unsigned long)end, (unsigned long)root);
    if (rc == QC_OK)
        for (u = end; u != root; u = par[u])
            towards[par[u]] = u;
out:
    qc__free(ctx, par, n * sizeof *par);
    qc__free(ctx, stack, n * sizeof *stack);
    return rc;
}

/* Iterative DFS; next[u] is the position of u's next neighbour to try. At a
 * node on the path to end the child towards end (towards[u]) comes last,
 * and the walk stops on reaching end. */
static int walk(qc_ctx *ctx, walk_ctx *w, size_t n, uint32_t root, uint32_t end,
                qc_order *out)
{
    uint32_t *parent = qc__alloc_array(ctx, n, sizeof *parent);
    uint32_t *next = qc__alloc_array(ctx, n, sizeof *next);
    uint32_t *towards = qc__alloc_array(ctx, n, sizeof *towards);
    size_t visited = 1;
    uint32_t u = root;
    int rc = QC_OK;

    if (parent == NULL || next == NULL || towards == NULL) {
        rc = QC_ENOMEM;
        goto out;
    }
    memset(next, 0xff, n * sizeof *next); /* NONE: not yet reached */
    memset(towards, 0xff, n * sizeof *towards);
    if (end != root)
        rc = path_to_end(ctx, w, n, root, end, towards);
    parent[root] = root;
    sort_neighbours(w, root, 0.0, 1);
    next[root] = w->start[root];
    if (rc == QC_OK)
        rc = qc_order_push(ctx, out, root);
    while (rc == QC_OK) {
        uint32_t v = NONE;

        while (v == NONE && next[u] < w->start[u + 1]) {
            v = w->adj[next[u]++];
            if ((v == parent[u] && u != root) || v == towards[u])
                v = NONE;
        }
        if (v == NONE && towards[u] != NONE) {
            v = towards[u];
            towards[u] = NONE; /* never back here: the walk ends beyond */
        }
        if (v != NONE) {
            if (next[v] != NONE) {
                rc = qc__fail(ctx, QC_EINVAL, "the edges hold a cycle through point %lu",
                              (unsigned long)v);
                break;
            }
            parent[v] = u;
            sort_neighbours(w, v, heading(w->p, v, u), 0);
            next[v] = w->start[v];
            visited++;
            u = v;
        } else if (u == root || u == end) {
            break;
        } else {
            u = parent[u];
        }
        rc = qc_order_push(ctx, out, u);
    }
    if (rc == QC_OK && visited != n)
        rc = qc__fail(ctx, QC_EINVAL, "the edges reach %lu of %lu points: not a spanning tree",
                      (unsigned long)visited, (unsigned long)n);
out:
    qc__free(ctx, parent, n * sizeof *parent);
    qc__free(ctx, next, n * sizeof *next);
    qc__free(ctx, towards, n * sizeof *towards);
    return rc;
}

int qc_tree_walk(qc_ctx *ctx, const qc_vec2 *p, size_t n, const qc_edge *edges, size_t nedges,
                 uint32_t root, qc_order *out)
{
    return qc_tree_walk_to(ctx, p, n, edges, nedges, root, root, out);
}

int qc_tree_walk_to(qc_ctx *ctx, const qc_vec2 *p, size_t n, const qc_edge *edges,
                    size_t nedges, uint32_t root, uint32_t end, qc_order *out)
{
    walk_ctx w;
    size_t max_degree = 0, n0 = out->n; /* on error out is as on entry (core.h) */
    int rc;

    if (n == 0 || root >= n || end >= n)
        return qc__fail(ctx, QC_EINVAL, "%s %lu is not one of %lu points",
                        root >= n ? "root" : "end", (unsigned long)(root >= n ? root : end),
                        (unsigned long)n);
    if (nedges != n - 1)
        return qc__fail(ctx, QC_EINVAL, "%lu edges for %lu points: a spanning tree has %lu",
                        (unsigned long)nedges, (unsigned long)n, (unsigned long)(n - 1));
    memset(&w, 0, sizeof w);
    w.p = p;
    rc = build_adjacency(ctx, &w, n, edges, nedges, &max_degree);
    if (rc == QC_OK) {
        w.key = qc__alloc_array(ctx, max_degree + 1, sizeof *w.key);
        rc = w.key == NULL ? QC_ENOMEM : walk(ctx, &w, n, root, end, out);
        qc__free(ctx, w.key, (max_degree + 1) * sizeof *w.key);
    }
    qc__free(ctx, w.start, (n + 1) * sizeof *w.start);
    qc__free(ctx, w.adj, (2 * nedges + 1) * sizeof *w.adj);
    if (rc < 0)
        out->n = n0;
    return rc;
}
