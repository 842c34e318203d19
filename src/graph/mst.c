/*
 * Euclidean MST. Edges are totally ordered by (exact squared length, a, b)
 * with a < b, so the tree is unique and both modes agree edge for edge
 * (an MST edge under exact lengths has an empty closed diametral disk, so
 * every Delaunay triangulation holds it): Kruskal over the Delaunay edges (which contain the EMST) plus
 * zero-length edges joining duplicates to their first copy, or a dense
 * O(n^2) Prim over the complete graph (the paper's complete graph without
 * its n^2/2 edge list: 20000 points would need 3 GB for Kruskal).
 */

#include "graph_delaunay.h"

#define COMPLETE_MAX 20000

/* (|a1 b1|, a1, b1) < (|a2 b2|, a2, b2) with a < b in each; lengths exact. */
static int before(const qc_vec2 *p, uint32_t a1, uint32_t b1, uint32_t a2, uint32_t b2)
{
    int c = qc__cmp_len2(p[a1], p[b1], p[a2], p[b2]);

    if (c != 0)
        return c < 0;
    return a1 != a2 ? a1 < a2 : b1 < b2;
}

/* Kruskal over the sorted e[0..m): tree edges to out (n - 1 of them). */
static int kruskal(qc_ctx *ctx, const qc_edge *e, size_t m, size_t n,
                   qc_edges *out)
{
    uint32_t *parent = qc__alloc_array(ctx, n, sizeof *parent);
    size_t i, got = 0;

    if (parent == NULL)
        return qc__fail(ctx, QC_ENOMEM, "mst: out of memory for %lu points",
                        (unsigned long)n);
    qc__uf_init(parent, n);
    for (i = 0; i < m && got + 1 < n; i++) {
        if (!qc__uf_union(parent, e[i].a, e[i].b))
            continue;
        out->e[out->n++] = e[i];
        got++;
    }
    qc__free(ctx, parent, n * sizeof *parent);
    return QC_OK;
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
    if ((rc = qc__sort_edges(ctx, p, n, e, m)) < 0)
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
    rc = qc__sort_edges(ctx, p, n, out->e + start, n - 1);
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
