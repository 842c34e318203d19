/*
 * Candidate lists for Or-3opt: the k nearest neighbours with the last
 * slots given to Delaunay neighbours the nearest miss. In clustered inputs
 * (TSPLIB's drilling instances) every one of a point's k nearest lies in
 * its own cluster, so no move can join two clusters better; the Delaunay
 * edges always reach across (the optimal tour's edges are mostly Delaunay
 * edges). The lists stay sorted by distance, so the searches' pruning by
 * distance holds. The greedy construction runs before, on the nearest
 * only (with the Delaunay slots it started 0.3% longer). On TSPLIB (20
 * instances, seeds 1-3) the default went from 2.07% to 1.82% above the
 * optima, fl1577 from 5.4% to 3.8% (seed 1). Evenly spread points (the
 * grid took their lists, knn_grid.c) skip this stage without a budget
 * (tsp.c).
 */
#include <string.h>

#include "tour_internal.h"
#include "../graph/graph_delaunay.h"

/* Slots of a list the Delaunay neighbours may take. */
#define DELAUNAY_SLOTS 3

/* The Delaunay stage's range: |x| is 0 or in [1e-40, 1e30]. */
static int in_range(double x)
{
    double a = fabs(x);
    return a == 0.0 || (a >= 1e-40 && a <= 1e30);
}

/* The Delaunay edges of the distinct points, already in Hilbert order (the
 * insertion order qc_delaunay would sort them into), so the triangulation
 * is run directly; no edges when all points are collinear. */
static int triangulate(const qc__tsp *s, qc_mesh *mesh)
{
    uint32_t m = s->m, k, i, *ord;
    qc_vec2 *q;
    int rc = QC_OK;

    for (k = 2; k < m; k++)
        if (qc_orient2d(s->q[0], s->q[1], s->q[k]) != 0.0)
            break;
    if (k == m)
        return QC_OK;
    ord = qc__alloc_array(s->ctx, m, sizeof *ord);
    q = qc__alloc_array(s->ctx, m, sizeof *q);
    if (ord == NULL || q == NULL)
        rc = qc__fail(s->ctx, QC_ENOMEM, "tsp: out of memory triangulating %lu points",
                      (unsigned long)m);
    if (rc == QC_OK) {
        for (i = 0; i < m; i++)
            ord[i] = i;
        ord[2] = k; /* the first three points make a triangle */
        ord[k] = 2;
        for (i = 0; i < m; i++)
            q[i] = s->q[ord[i]];
        rc = qc__triangulate(s->ctx, q, ord, m, mesh);
        if (rc < 0 && s->ctx->status != rc)
            rc = qc__fail(s->ctx, rc, "tsp: out of memory triangulating %lu points",
                          (unsigned long)m);
    }
    qc__free(s->ctx, ord, (size_t)m * sizeof *ord);
    qc__free(s->ctx, q, (size_t)m * sizeof *q);
    return rc;
}

/* The last slots of i's list go to its nearest Delaunay neighbours that
 * are not listed: each is at least as far as the list's last entry, so
 * the list stays sorted. */
static void give_slots(qc__tsp *s, uint32_t i, uint32_t *dn, uint32_t deg, unsigned slots)
{
    uint32_t *list = s->nb + (size_t)i * s->k;
    unsigned k = s->k, c = 0, j, h, take;

    for (j = 0; j < deg; j++) /* the unlisted ones to the front */
        if (!qc__tsp_listed(list, k, dn[j])) {
            uint32_t x = dn[c];
            dn[c++] = dn[j];
            dn[j] = x;
        }
    take = c < slots ? c : slots;
    for (j = 0; j < take; j++) { /* the nearest, in order */
        unsigned best = j;
        uint32_t x;

        for (h = j + 1; h < c; h++) {
            double dh = qc__tsp_dist(s, i, dn[h]), db = qc__tsp_dist(s, i, dn[best]);
            if (dh < db || (dh == db && dn[h] < dn[best]))
                best = h;
        }
        x = dn[j];
        dn[j] = dn[best];
        dn[best] = x;
        list[k - take + j] = dn[j];
    }
}

int qc__tsp_add_delaunay(qc__tsp *s)
{
    qc_ctx *ctx = s->ctx;
    uint32_t m = s->m, i, *start = NULL, *adj = NULL;
    unsigned slots = s->k / 3 < DELAUNAY_SLOTS ? s->k / 3 : DELAUNAY_SLOTS;
    qc_mesh mesh;
    size_t e, ne;
    int rc;

    if (slots == 0 || m < 4)
        return QC_OK;
    for (i = 0; i < m; i++)
        if (!in_range(s->q[i].x) || !in_range(s->q[i].y))
            return QC_OK; /* beyond the triangulation's range: nearest only */
    memset(&mesh, 0, sizeof mesh);
    rc = triangulate(s, &mesh);
    ne = mesh.edges.n;
    if (rc == QC_OK && ne > 0) {
        start = qc__alloc_array(ctx, (size_t)m + 1, sizeof *start);
        adj = qc__alloc_array(ctx, 2 * ne, sizeof *adj);
        if (start == NULL || adj == NULL)
            rc = qc__fail(ctx, QC_ENOMEM, "tsp: out of memory for %lu Delaunay edges",
                          (unsigned long)ne);
    }
    if (rc == QC_OK && ne > 0) { /* adjacency lists: i's are adj[start[i] .. start[i+1]) */
        memset(start, 0, ((size_t)m + 1) * sizeof *start);
        for (e = 0; e < ne; e++) {
            start[mesh.edges.e[e].a + 1]++;
            start[mesh.edges.e[e].b + 1]++;
        }
        for (i = 0; i < m; i++)
            start[i + 1] += start[i];
        for (e = 0; e < ne; e++) { /* start[a] runs on to a's end... */
            uint32_t a = mesh.edges.e[e].a, b = mesh.edges.e[e].b;
            adj[start[a]++] = b;
            adj[start[b]++] = a;
        }
        for (i = m; i > 0; i--) /* ...and is put back */
            start[i] = start[i - 1];
        start[0] = 0;
        for (i = 0; i < m; i++)
            give_slots(s, i, adj + start[i], start[i + 1] - start[i], slots);
    }
    qc__free(ctx, start, ((size_t)m + 1) * sizeof *start);
    qc__free(ctx, adj, 2 * ne * sizeof *adj);
    qc_mesh_free(ctx, &mesh);
    return rc;
}

int qc__tsp_cache_dists(qc__tsp *s)
{
    size_t i, total = (size_t)s->m * s->k;

    s->nbd = qc__alloc_array(s->ctx, total, sizeof *s->nbd);
    if (s->nbd == NULL)
        return qc__fail(s->ctx, QC_ENOMEM, "tsp: out of memory for %lu candidate distances",
                        (unsigned long)total);
    for (i = 0; i < total; i++)
        s->nbd[i] = qc__tsp_dist(s, (uint32_t)(i / s->k), s->nb[i]);
    return QC_OK;
}
