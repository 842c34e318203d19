/*
 * Euclidean MST. Edges are totally ordered by (exact squared length, a, b)
 * with a < b, so the tree is unique and both modes agree edge for edge
 * (an MST edge under exact lengths has an empty closed diametral disk, so
 * every Delaunay triangulation holds it): Kruskal over the Delaunay edges (which contain the EMST) plus
 * zero-length edges joining duplicates to their first copy, or a dense
 * O(n^2) Prim over the complete graph (the paper's complete graph without
 * its n^2/2 edge list: 20000 points would need 3 GB for Kruskal).
 */
#include <limits.h>
#include <stdlib.h>
#include <string.h>

#include "graph_delaunay.h"

#define COMPLETE_MAX 20000

static double len2(const qc_vec2 *p, uint32_t a, uint32_t b)
{
    double dx = p[a].x - p[b].x, dy = p[a].y - p[b].y;

    return dx * dx + dy * dy;
}

static uint64_t len_key(double l)
{
    uint64_t u;

    memcpy(&u, &l, sizeof u); /* l >= +0: the bits order like the values */
    return u;
}

/* (|a1 b1|, a1, b1) < (|a2 b2|, a2, b2) with a < b in each; lengths exact. */
static int before(const qc_vec2 *p, uint32_t a1, uint32_t b1, uint32_t a2, uint32_t b2)
{
    int c = qc__cmp_len2(p[a1], p[b1], p[a2], p[b2]);

    if (c != 0)
        return c < 0;
    return a1 != a2 ? a1 < a2 : b1 < b2;
}

static int edge_before(const qc_vec2 *p, qc_edge x, qc_edge y)
{
    return before(p, x.a, x.b, y.a, y.b);
}

static void sift(const qc_vec2 *p, qc_edge *e, size_t i, size_t m)
{
    for (;;) {
        size_t c = 2 * i + 1;
        qc_edge t;

        if (c >= m)
            return;
        if (c + 1 < m && edge_before(p, e[c], e[c + 1]))
            c++;
        if (!edge_before(p, e[i], e[c]))
            return;
        t = e[i], e[i] = e[c], e[c] = t;
        i = c;
    }
}

/* Sorts a run of edges in place by the total order (no allocation). */
static void sort_run(const qc_vec2 *p, qc_edge *e, size_t m)
{
    size_t i, j;

    if (m <= 24) {
        for (i = 1; i < m; i++) {
            qc_edge x = e[i];
            for (j = i; j > 0 && edge_before(p, x, e[j - 1]); j--)
                e[j] = e[j - 1];
            e[j] = x;
        }
        return;
    }
    for (i = m / 2; i-- > 0;)
        sift(p, e, i, m);
    for (i = m; i-- > 1;) {
        qc_edge t = e[0];
        e[0] = e[i], e[i] = t;
        sift(p, e, 0, i);
    }
}

/* An edge with its exact squared length in integers (qc__len2_int). */
typedef struct int_key {
    uint64_t hi, lo;
    qc_edge e;
} int_key;

static int int_key_cmp(const void *x, const void *y)
{
    const int_key *a = x, *b = y;

    if (a->hi != b->hi)
        return a->hi < b->hi ? -1 : 1;
    if (a->lo != b->lo)
        return a->lo < b->lo ? -1 : 1;
    if (a->e.a != b->e.a)
        return a->e.a < b->e.a ? -1 : 1;
    return (a->e.b > b->e.b) - (a->e.b < b->e.b);
}

/* Sorts a run by exact integer keys when its coordinates allow (lattice
 * runs of thousands of equal-length edges: one key per edge instead of
 * exact arithmetic per comparison); else by sort_run. */
static int sort_run_keyed(qc_ctx *ctx, const qc_vec2 *p, qc_edge *e, size_t m, int_key **buf,
                          size_t *cap)
{
    int lo = INT_MAX, hi = INT_MIN, ok = 1;
    size_t i;

    for (i = 0; i < m && ok; i++)
        ok = qc__int_span_add(p[e[i].a].x, &lo, &hi) && qc__int_span_add(p[e[i].a].y, &lo, &hi) &&
             qc__int_span_add(p[e[i].b].x, &lo, &hi) && qc__int_span_add(p[e[i].b].y, &lo, &hi);
    if (m <= 24 || !ok || (hi != INT_MIN && hi - lo > QC__INT_SPAN)) {
        sort_run(p, e, m);
        return QC_OK;
    }
    QC__TRY(QC__RESERVE(ctx, *buf, *cap, m));
    for (i = 0; i < m; i++) {
        qc__len2_int(p[e[i].a], p[e[i].b], lo, &(*buf)[i].hi, &(*buf)[i].lo);
        (*buf)[i].e = e[i];
    }
    qsort(*buf, m, sizeof **buf, int_key_cmp); /* keys are distinct: deterministic */
    for (i = 0; i < m; i++)
        e[i] = (*buf)[i].e;
    return QC_OK;
}

/*
 * Sorts e[0..m) (a < b each) by (length, a, b): a radix sort on the upper
 * 32 bits of the squared length (sign, exponent, 20 mantissa bits), then
 * the few runs that tie there are finished exactly (by integer keys, or by
 * exact comparisons).
 */
static int sort_edges(qc_ctx *ctx, const qc_vec2 *p, qc_edge *e, size_t m)
{
    uint64_t *key = qc__alloc_array(ctx, m, sizeof *key);
    int_key *buf = NULL;
    size_t i, r, cap = 0;
    int rc = QC_OK;

    if (key == NULL)
        return qc__fail(ctx, QC_ENOMEM, "mst: out of memory sorting %lu edges",
                        (unsigned long)m);
    for (i = 0; i < m; i++)
        key[i] = (len_key(len2(p, e[i].a, e[i].b)) >> 32) << 32 | (uint64_t)i;
    if (qc__radix_sort(ctx, key, NULL, m, 32) < 0) {
        qc__free(ctx, key, m * sizeof *key);
        return QC_ENOMEM;
    }
    /* Permute through key[] as scratch: e[index in key[i]] -> position i. */
    for (i = 0; i < m; i++) {
        qc_edge x = e[(uint32_t)key[i]];
        key[i] = (uint64_t)x.a << 32 | x.b;
    }
    for (i = 0; i < m; i++) {
        e[i].a = (uint32_t)(key[i] >> 32);
        e[i].b = (uint32_t)key[i];
    }
    qc__free(ctx, key, m * sizeof *key);
    for (i = 0; i < m && rc == QC_OK; i = r) {
        uint64_t hi = len_key(len2(p, e[i].a, e[i].b)) >> 32;

        for (r = i + 1; r < m && len_key(len2(p, e[r].a, e[r].b)) >> 32 == hi; r++)
            ;
        if (r - i > 1)
            rc = sort_run_keyed(ctx, p, e + i, r - i, &buf, &cap);
    }
    qc__free(ctx, buf, cap * sizeof *buf);
    if (rc < 0)
        return qc__fail(ctx, rc, "mst: out of memory sorting %lu edges", (unsigned long)m);
    /* Computed lengths a few ulps apart may straddle two runs in the wrong
     * order: one insertion pass with the exact order mends that (it moves
     * nothing in the usual case, a comparison per edge). */
    for (i = 1; i < m; i++) {
        qc_edge x = e[i];
        for (r = i; r > 0 && edge_before(p, x, e[r - 1]); r--)
            e[r] = e[r - 1];
        e[r] = x;
    }
    return QC_OK;
}

static uint32_t find(uint32_t *parent, uint32_t x)
{
    while (parent[x] != x) {
        parent[x] = parent[parent[x]];
        x = parent[x];
    }
    return x;
}

/* Kruskal over the sorted e[0..m): tree edges to out (n - 1 of them). */
static int kruskal(qc_ctx *ctx, const qc_edge *e, size_t m, size_t n,
                   qc_edges *out)
{
    uint32_t *parent = qc__alloc_array(ctx, n, sizeof *parent);
    uint32_t *size = qc__alloc_array(ctx, n, sizeof *size);
    size_t i, got = 0;
    int rc = QC_ENOMEM;

    if (parent == NULL || size == NULL)
        goto out_free;
    for (i = 0; i < n; i++)
        parent[i] = (uint32_t)i, size[i] = 1;
    for (i = 0; i < m && got + 1 < n; i++) {
        uint32_t ra = find(parent, e[i].a), rb = find(parent, e[i].b);

        if (ra == rb)
            continue;
        if (size[ra] < size[rb]) {
            uint32_t t = ra;
            ra = rb;
            rb = t;
        }
        parent[rb] = ra;
        size[ra] += size[rb];
        out->e[out->n++] = e[i];
        got++;
    }
    rc = QC_OK;
out_free:
    qc__free(ctx, parent, n * sizeof *parent);
    qc__free(ctx, size, n * sizeof *size);
    return rc < 0 ? qc__fail(ctx, rc, "mst: out of memory for %lu points",
                             (unsigned long)n)
                  : rc;
}

static int mst_delaunay(qc_ctx *ctx, const qc_vec2 *p, size_t n, qc_edges *out)
{
    qc_mesh mesh;
    qc_edge *e;
    size_t m, i;
    int rc;

    QC__TRY(qc__delaunay_checked(ctx, p, n, &mesh)); /* qc_mst checked p */
    /* The triangles are not needed: free them before the edge sort. */
    qc__free(ctx, mesh.tri, 3 * mesh.tri_cap * sizeof *mesh.tri);
    mesh.tri = NULL;
    mesh.tri_cap = mesh.ntri = 0;
    m = mesh.edges.n;
    rc = QC__RESERVE(ctx, mesh.edges.e, mesh.edges.cap, m + mesh.ndup);
    if (rc < 0)
        goto out_free;
    e = mesh.edges.e;
    for (i = 0; i < n; i++)
        if (mesh.dup_of[i] != i) {
            e[m].a = mesh.dup_of[i];
            e[m++].b = (uint32_t)i;
        }
    if ((rc = sort_edges(ctx, p, e, m)) < 0)
        goto out_free;
    rc = kruskal(ctx, e, m, n, out);
out_free:
    qc_mesh_free(ctx, &mesh);
    return rc;
}

static int mst_complete(qc_ctx *ctx, const qc_vec2 *p, size_t n, qc_edges *out)
{
    uint32_t *from = qc__alloc_array(ctx, n, sizeof *from);
    size_t i, k, start = out->n;
    uint32_t v = 0;
    int rc = QC_ENOMEM;

    if (from == NULL)
        goto out_free;
    for (i = 0; i < n; i++)
        from[i] = UINT32_MAX; /* UINT32_MAX: no edge yet; v itself: in the tree */
    from[0] = 0;
    for (k = 1; k < n; k++) {
        uint32_t w, bw = UINT32_MAX;

        for (w = 0; w < n; w++) {
            uint32_t a, b;

            if (from[w] == w)
                continue;
            a = v < w ? v : w;
            b = v < w ? w : v;
            if (from[w] == UINT32_MAX ||
                before(p, a, b, from[w] < w ? from[w] : w, from[w] < w ? w : from[w]))
                from[w] = v;
            if (bw == UINT32_MAX ||
                before(p, from[w] < w ? from[w] : w, from[w] < w ? w : from[w],
                       from[bw] < bw ? from[bw] : bw, from[bw] < bw ? bw : from[bw]))
                bw = w;
        }
        out->e[out->n].a = from[bw] < bw ? from[bw] : bw;
        out->e[out->n++].b = from[bw] < bw ? bw : from[bw];
        from[bw] = bw;
        v = bw;
    }
    rc = sort_edges(ctx, p, out->e + start, n - 1);
out_free:
    qc__free(ctx, from, n * sizeof *from);
    if (rc < 0)
        out->n = start;
    return rc < 0 && ctx->status != rc
               ? qc__fail(ctx, rc, "mst: out of memory for %lu points",
                          (unsigned long)n)
               : rc;
}

int qc_mst(qc_ctx *ctx, const qc_vec2 *p, size_t n, qc_mst_mode mode,
           qc_edges *out)
{
    size_t start = out->n;
    int rc;

    if (mode == QC_MST_MODE_DEFAULT)
        mode = QC_MST_MODE_DELAUNAY;
    if (mode != QC_MST_MODE_DELAUNAY && mode != QC_MST_MODE_COMPLETE)
        return qc__fail(ctx, QC_EINVAL, "mst: unknown mode %d", (int)mode);
    if (n >= ((size_t)1 << 30)) /* edge indices must fit in 32 bits */
        return qc__fail(ctx, QC_ELIMIT, "mst: %lu points, at most 2^30 - 1",
                        (unsigned long)n);
    if (mode == QC_MST_MODE_COMPLETE && n > COMPLETE_MAX)
        return qc__fail(ctx, QC_ELIMIT,
                        "mst: complete graph of %lu points, at most %d",
                        (unsigned long)n, COMPLETE_MAX);
    QC__TRY(qc__check_points(ctx, p, n, "mst"));
    if (n < 2)
        return QC_OK;
    QC__TRY(QC__RESERVE(ctx, out->e, out->cap, out->n + n - 1));
    rc = mode == QC_MST_MODE_COMPLETE ? mst_complete(ctx, p, n, out)
                                      : mst_delaunay(ctx, p, n, out);
    if (rc < 0)
        out->n = start;
    return rc;
}
