/* qc_delaunay's front end: checks, duplicates, the degenerate cases (too
 * few, all collinear), the Hilbert insertion order; then qc__triangulate. */
#include <string.h>

#include "graph_delaunay.h"

void qc_mesh_free(qc_ctx *ctx, qc_mesh *mesh)
{
    if (mesh == NULL)
        return;
    qc__free(ctx, mesh->tri, 3 * mesh->tri_cap * sizeof *mesh->tri);
    qc__free(ctx, mesh->dup_of, mesh->dup_cap * sizeof *mesh->dup_of);
    qc_edges_free(ctx, &mesh->edges);
    memset(mesh, 0, sizeof *mesh);
}

/* Orderable bits of a double: unsigned order == numeric order (-0 < +0
 * does not matter here: points are distinct). */
static uint64_t order_bits(double v)
{
    uint64_t u;

    memcpy(&u, &v, sizeof u);
    return (u >> 63) ? ~u : u | ((uint64_t)1 << 63);
}

/* Collinear distinct points: the chain of neighbours along the line. */
static int collinear_chain(qc_ctx *ctx, const qc_vec2 *p, const uint32_t *idx,
                           size_t m, qc_mesh *out)
{
    uint64_t *key = qc__alloc_array(ctx, m, sizeof *key);
    uint32_t *val = qc__alloc_array(ctx, m, sizeof *val);
    int vertical = 1, rc = QC_ENOMEM;
    size_t i;

    if (key == NULL || val == NULL)
        goto out_free;
    for (i = 1; i < m; i++)
        if (p[idx[i]].x != p[idx[0]].x)
            vertical = 0;
    for (i = 0; i < m; i++) {
        key[i] = order_bits(vertical ? p[idx[i]].y : p[idx[i]].x);
        val[i] = idx[i];
    }
    if (qc__radix_sort(ctx, key, val, m, 0) < 0)
        goto out_free;
    out->edges.e = qc__alloc_array(ctx, m - 1, sizeof *out->edges.e);
    if (out->edges.e == NULL)
        goto out_free;
    out->edges.cap = m - 1;
    for (i = 0; i + 1 < m; i++) {
        uint32_t a = val[i], b = val[i + 1];

        out->edges.e[i].a = a < b ? a : b;
        out->edges.e[i].b = a < b ? b : a;
    }
    out->edges.n = m - 1;
    rc = QC_OK;
out_free:
    qc__free(ctx, key, m * sizeof *key);
    qc__free(ctx, val, m * sizeof *val);
    return rc < 0 ? qc__fail(ctx, rc, "delaunay: out of memory (%lu collinear points)",
                             (unsigned long)m)
                  : rc;
}

static int build(qc_ctx *ctx, const qc_vec2 *p, uint32_t *uniq, size_t m,
                 qc_mesh *out)
{
    uint32_t *ord = NULL, k;
    qc_vec2 *q = NULL;
    size_t i;
    int rc;

    if (m < 3) {
        out->status = QC_MESH_TOO_FEW;
        if (m < 2)
            return QC_OK;
        return qc_edges_push(ctx, &out->edges, uniq[0], uniq[1]);
    }
    ord = qc__alloc_array(ctx, m, sizeof *ord);
    q = qc__alloc_array(ctx, m, sizeof *q);
    rc = ord == NULL || q == NULL ? QC_ENOMEM
                                  : qc__hilbert_order(ctx, p, uniq, m, ord);
    if (rc < 0)
        goto out_free;
    for (k = 2; k < m; k++)
        if (qc_orient2d(p[ord[0]], p[ord[1]], p[ord[k]]) != 0.0)
            break;
    if (k == m) {
        out->status = QC_MESH_COLLINEAR;
        rc = collinear_chain(ctx, p, uniq, m, out);
        goto out_free;
    }
    {
        uint32_t t = ord[2];
        ord[2] = ord[k];
        ord[k] = t;
    }
    for (i = 0; i < m; i++)
        q[i] = p[ord[i]];
    rc = qc__triangulate(ctx, q, ord, (uint32_t)m, out);
out_free:
    qc__free(ctx, ord, m * sizeof *ord);
    qc__free(ctx, q, m * sizeof *q);
    return rc < 0 && ctx->status != rc
               ? qc__fail(ctx, rc, "delaunay: out of memory for %lu points",
                          (unsigned long)m)
               : rc;
}

int qc_delaunay(qc_ctx *ctx, const qc_vec2 *p, size_t n, qc_mesh *out)
{
    memset(out, 0, sizeof *out);
    QC__TRY(qc__check_points(ctx, p, n, "delaunay"));
    return qc__delaunay_checked(ctx, p, n, out);
}

int qc__delaunay_checked(qc_ctx *ctx, const qc_vec2 *p, size_t n, qc_mesh *out)
{
    uint32_t *uniq;
    size_t i, m = 0;
    int rc;

    memset(out, 0, sizeof *out);
    out->n = n;
    if (n == 0)
        return out->status = QC_MESH_TOO_FEW, QC_OK;
    out->dup_of = qc__alloc_array(ctx, n, sizeof *out->dup_of);
    if (out->dup_of == NULL)
        return qc__fail(ctx, QC_ENOMEM, "delaunay: out of memory for %lu points",
                        (unsigned long)n);
    out->dup_cap = n;
    rc = qc__find_duplicates(ctx, p, n, out->dup_of, &out->ndup);
    uniq = rc < 0 ? NULL : qc__alloc_array(ctx, n - out->ndup, sizeof *uniq);
    if (uniq == NULL) {
        qc_mesh_free(ctx, out);
        return qc__fail(ctx, QC_ENOMEM, "delaunay: out of memory for %lu points",
                        (unsigned long)n);
    }
    for (i = 0; i < n; i++)
        if (out->dup_of[i] == i)
            uniq[m++] = (uint32_t)i;
    out->status = QC_MESH_OK;
    rc = build(ctx, p, uniq, m, out);
    qc__free(ctx, uniq, m * sizeof *uniq);
    if (rc < 0) {
        qc_mesh_free(ctx, out);
        return rc;
    }
    out->n = n;
    return QC_OK;
}
