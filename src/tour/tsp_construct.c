/*
 * Greedy-edge construction: candidate edges (the k nearest neighbours of
 * every point) in increasing length, each taken when both ends have degree
 * below 2 and it closes no cycle. The fragments left over are joined by
 * further greedy rounds over their end points, and the last few in Hilbert
 * order of their first end, each turned to start at the end nearer the
 * tour so far.
 */
#include <string.h>

#include "tour_internal.h"

#define NONE UINT32_MAX
#define END_K 8         /* candidates per fragment end in the joining rounds */
#define MAX_ROUNDS 24

typedef struct greedy {
    qc__tsp *s;
    unsigned char *deg;
    uint32_t *adj;    /* two slots per point */
    uint32_t *parent; /* union-find over fragments */
    size_t edges;
} greedy;

static void try_link(greedy *g, uint32_t u, uint32_t v)
{
    if (g->deg[u] >= 2 || g->deg[v] >= 2 || !qc__uf_union(g->parent, u, v))
        return;
    g->adj[2 * u + g->deg[u]++] = v;
    g->adj[2 * v + g->deg[v]++] = u;
    g->edges++;
}

/* Sort key: the squared length as a float (its bits order like the values),
 * then the slot, so ties keep a fixed order. */
static uint64_t edge_key(const qc_vec2 *q, uint32_t a, uint32_t b, size_t slot)
{
    double dx = q[a].x - q[b].x, dy = q[a].y - q[b].y;
    float f = (float)(dx * dx + dy * dy);
    uint32_t bits;

    memcpy(&bits, &f, sizeof bits);
    return (uint64_t)bits << 32 | (uint64_t)slot;
}

/*
 * One greedy pass over the k-nearest-neighbour candidates among the points
 * id[0..c) (id == NULL: all m points, with the solver's lists). Each edge
 * once (a pair listed both ways keeps the lower index's slot).
 */
static int greedy_pass(greedy *g, const uint32_t *id, size_t c, const qc_vec2 *pts,
                       const uint32_t *nb, unsigned stride, unsigned k)
{
    qc_ctx *ctx = g->s->ctx;
    uint64_t *key = qc__alloc_array(ctx, c * k, sizeof *key);
    size_t a, nkey = 0, i;
    unsigned j;
    int rc;

    if (key == NULL)
        return qc__fail(ctx, QC_ENOMEM, "tsp: out of memory for %lu candidate edges",
                        (unsigned long)(c * k));
    for (a = 0; a < c; a++)
        for (j = 0; j < k; j++) {
            uint32_t b = nb[a * stride + j];
            uint32_t u = id ? id[a] : (uint32_t)a, v = id ? id[b] : b;

            if (b < a && qc__tsp_listed(nb + (size_t)b * stride, k, (uint32_t)a))
                continue;
            if (id != NULL && qc__uf_find(g->parent, u) == qc__uf_find(g->parent, v))
                continue;
            key[nkey++] = edge_key(pts, (uint32_t)a, b, a * k + j);
        }
    rc = qc__radix_sort(ctx, key, NULL, nkey, 32);
    for (i = 0; i < nkey && rc == QC_OK; i++) {
        size_t slot = (uint32_t)key[i];
        uint32_t x = (uint32_t)(slot / k), y = nb[(size_t)x * stride + slot % k];

        if (id != NULL) {
            x = id[x];
            y = id[y];
        }
        try_link(g, x, y);
    }
    qc__free(ctx, key, c * k * sizeof *key);
    return rc;
}

/* Greedy rounds over the fragment ends while they keep merging well. */
static int join_rounds(greedy *g)
{
    qc__tsp *s = g->s;
    uint32_t *id = NULL, *nb = NULL;
    qc_vec2 *pts = NULL;
    size_t cap = 0, c, u, round;
    int rc = QC_OK;

    for (round = 0; round < MAX_ROUNDS; round++) {
        size_t frags = s->m - g->edges, before = g->edges;
        unsigned k;

        if (frags <= 1)
            break;
        c = 0;
        for (u = 0; u < s->m; u++)
            c += g->deg[u] < 2;
        if (cap == 0) { /* the first round has the most ends */
            cap = c;
            id = qc__alloc_array(s->ctx, cap, sizeof *id);
            pts = qc__alloc_array(s->ctx, cap, sizeof *pts);
            nb = qc__alloc_array(s->ctx, cap * END_K, sizeof *nb);
            if (id == NULL || pts == NULL || nb == NULL) {
                rc = qc__fail(s->ctx, QC_ENOMEM, "tsp: out of memory joining %lu fragments",
                              (unsigned long)frags);
                break;
            }
        }
        c = 0;
        for (u = 0; u < s->m; u++)
            if (g->deg[u] < 2) {
                id[c] = (uint32_t)u;
                pts[c++] = s->q[u];
            }
        k = c - 1 < END_K ? (unsigned)(c - 1) : END_K;
        rc = qc__knn(s->ctx, pts, c, k, nb, NULL);
        if (rc == QC_OK)
            rc = greedy_pass(g, id, c, pts, nb, k, k);
        if (rc < 0 || (g->edges - before) * 8 < frags)
            break; /* the rest is left to the curve order */
    }
    qc__free(s->ctx, id, cap * sizeof *id);
    qc__free(s->ctx, pts, cap * sizeof *pts);
    qc__free(s->ctx, nb, cap * END_K * sizeof *nb);
    return rc;
}

/* Lays the fragments into the tour array in the order of their first end. */
static void lay_out(greedy *g)
{
    qc__tsp *s = g->s;
    uint32_t u, at = 0;

    for (u = 0; u < s->m; u++)
        s->pos[u] = NONE;
    for (u = 0; u < s->m; u++) {
        uint32_t prev = NONE, cur = u, first = at;

        if (g->deg[u] >= 2 || s->pos[u] != NONE)
            continue;
        for (;;) {
            uint32_t nx = NONE;

            s->pos[cur] = at;
            s->t[at++] = cur;
            if (g->deg[cur] > 0 && g->adj[2 * cur] != prev)
                nx = g->adj[2 * cur];
            else if (g->deg[cur] > 1 && g->adj[2 * cur + 1] != prev)
                nx = g->adj[2 * cur + 1];
            if (nx == NONE)
                break;
            prev = cur;
            cur = nx;
        }
        if (first > 0) {
            uint32_t last = s->t[first - 1];
            if (qc__tsp_dist(s, last, cur) < qc__tsp_dist(s, last, u)) {
                uint32_t i = first, j = at - 1; /* enter by the nearer end */
                while (i < j) {
                    uint32_t x = s->t[i];
                    s->t[i] = s->t[j];
                    s->t[j] = x;
                    s->pos[s->t[i]] = i;
                    s->pos[s->t[j]] = j;
                    i++, j--;
                }
            }
        }
    }
}

int qc__tsp_greedy(qc__tsp *s)
{
    greedy g;
    int rc;

    memset(&g, 0, sizeof g);
    g.s = s;
    g.deg = qc__alloc(s->ctx, s->m);
    g.adj = qc__alloc_array(s->ctx, (size_t)s->m * 2, sizeof *g.adj);
    g.parent = qc__alloc_array(s->ctx, s->m, sizeof *g.parent);
    if (g.deg == NULL || g.adj == NULL || g.parent == NULL) {
        rc = qc__fail(s->ctx, QC_ENOMEM, "tsp: out of memory building a tour of %lu points",
                      (unsigned long)s->m);
        goto out;
    }
    memset(g.deg, 0, s->m);
    qc__uf_init(g.parent, s->m);
    rc = greedy_pass(&g, NULL, s->m, s->q, s->nb, s->k,
                     s->k < QC__TSP_GREEDY_K ? s->k : QC__TSP_GREEDY_K);
    if (rc == QC_OK)
        rc = join_rounds(&g);
    if (rc == QC_OK)
        lay_out(&g);
out:
    qc__free(s->ctx, g.deg, s->m);
    qc__free(s->ctx, g.adj, (size_t)s->m * 2 * sizeof *g.adj);
    qc__free(s->ctx, g.parent, s->m * sizeof *g.parent);
    return rc;
}
