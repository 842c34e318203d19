/*
 * The seam graph: the patches' rings on shared vertices. Vertices within
 * tol merge (a sweep in x order), then each ring edge takes every vertex
 * lying on it (T-junctions, where a sashing strip meets two blocks), so a
 * seam is one chain of graph edges whichever patch it is read from.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "quilt_internal.h"

typedef struct vref {
    qc_vec2 p;
    uint32_t i; /* global vertex number (patch ring vertices in order) */
} vref;

static int by_x(const void *pa, const void *pb)
{
    const vref *a = (const vref *)pa, *b = (const vref *)pb;

    if (a->p.x != b->p.x)
        return a->p.x < b->p.x ? -1 : 1;
    if (a->p.y != b->p.y)
        return a->p.y < b->p.y ? -1 : 1;
    return (a->i > b->i) - (a->i < b->i);
}

typedef struct on_edge {
    double t;
    uint32_t k;
} on_edge;

static int by_t(const void *pa, const void *pb)
{
    const on_edge *a = (const on_edge *)pa, *b = (const on_edge *)pb;

    if (a->t != b->t)
        return a->t < b->t ? -1 : 1;
    return (a->k > b->k) - (a->k < b->k);
}

static int by_edge(const void *pa, const void *pb)
{
    const qc_edge *a = (const qc_edge *)pa, *b = (const qc_edge *)pb;

    if (a->a != b->a)
        return a->a < b->a ? -1 : 1;
    return (a->b > b->b) - (a->b < b->b);
}

void qc__seams_free(qc_ctx *ctx, qc__seams *s)
{
    if (s->adj_start != NULL)
        qc__free(ctx, s->adj_start, (s->nv + 1) * sizeof *s->adj_start);
    qc__free(ctx, s->v, s->v_cap * sizeof *s->v);
    qc__free(ctx, s->adj, s->adj_cap * sizeof *s->adj);
    qc__free(ctx, s->bnd, s->bnd_cap * sizeof *s->bnd);
    qc__free(ctx, s->ring_end, s->ring_cap * sizeof *s->ring_end);
    qc__free(ctx, s->patch_end, s->npatch * sizeof *s->patch_end);
    memset(s, 0, sizeof *s);
}

/* Merges vertices within tol: *id receives each global vertex's seam
 * vertex, s->v the seam vertices in x order. */
static int merge_vertices(qc_ctx *ctx, vref *r, size_t n, double tol, uint32_t *id,
                          qc__seams *s)
{
    size_t a, b;

    qsort(r, n, sizeof *r, by_x);
    s->v = (qc_vec2 *)qc__alloc_array(ctx, n, sizeof *s->v);
    if (s->v == NULL)
        return QC_ENOMEM;
    s->v_cap = n;
    for (a = 0; a < n; a++) {
        uint32_t found = UINT32_MAX;

        for (b = a; b-- > 0 && r[a].p.x - r[b].p.x <= tol;)
            if (fabs(r[a].p.y - r[b].p.y) <= tol &&
                qc_hypot(r[a].p.x - r[b].p.x, r[a].p.y - r[b].p.y) <= tol) {
                found = id[r[b].i];
                break;
            }
        if (found == UINT32_MAX) {
            found = (uint32_t)s->nv;
            s->v[s->nv++] = r[a].p;
        }
        id[r[a].i] = found;
    }
    return QC_OK;
}

/* First seam vertex with x >= x0 (vertices are in x order). */
static size_t lower_x(const qc__seams *s, double x0)
{
    size_t lo = 0, hi = s->nv;

    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (s->v[mid].x < x0)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

/* Appends to s->bnd the seam vertices strictly inside edge a-b, in order. */
static int split_edge(qc_ctx *ctx, qc__seams *s, uint32_t a, uint32_t b,
                      double tol, on_edge **hits, size_t *hit_cap)
{
    qc_vec2 pa = s->v[a], pb = s->v[b];
    double minx = fmin(pa.x, pb.x) - tol, maxx = fmax(pa.x, pb.x) + tol;
    double miny = fmin(pa.y, pb.y) - tol, maxy = fmax(pa.y, pb.y) + tol;
    double dx = pb.x - pa.x, dy = pb.y - pa.y, len2 = dx * dx + dy * dy;
    size_t k, nh = 0;

    for (k = lower_x(s, minx); k < s->nv && s->v[k].x <= maxx; k++) {
        qc_vec2 q = s->v[k];
        double t;

        if (k == a || k == b || q.y < miny || q.y > maxy)
            continue;
        t = ((q.x - pa.x) * dx + (q.y - pa.y) * dy) / len2;
        if (!(t > 0 && t < 1) || qc__seg_dist2(q, pa, pb) > tol * tol)
            continue;
        QC__TRY(QC__RESERVE(ctx, *hits, *hit_cap, nh + 1));
        (*hits)[nh].t = t;
        (*hits)[nh++].k = (uint32_t)k;
    }
    if (nh == 0)
        return QC_OK;
    qsort(*hits, nh, sizeof **hits, by_t);
    QC__TRY(QC__RESERVE(ctx, s->bnd, s->bnd_cap, s->nbnd + nh));
    for (k = 0; k < nh; k++)
        s->bnd[s->nbnd++] = (*hits)[k].k;
    return QC_OK;
}

/* The rings as refined vertex lists (no repeats, closing repeat dropped). */
static int build_rings(qc_ctx *ctx, const qc_patches *ps, const uint32_t *id, double tol,
                       qc__seams *s)
{
    on_edge *hits = NULL;
    size_t hit_cap = 0, i, k, g = 0;
    int rc = QC_OK;

    for (i = 0; i < ps->n && rc >= 0; i++) {
        const qc_region *r = &ps->p[i].region;
        size_t start = 0;

        for (k = 0; k < r->nrings && rc >= 0; k++) {
            size_t end = r->ring_end[k], j, first = s->nbnd;

            for (j = start; j < end && rc >= 0; j++) {
                uint32_t a = id[g + j], b = id[g + (j + 1 < end ? j + 1 : start)];

                if (s->nbnd == first || s->bnd[s->nbnd - 1] != a) {
                    rc = QC__RESERVE(ctx, s->bnd, s->bnd_cap, s->nbnd + 1);
                    if (rc >= 0)
                        s->bnd[s->nbnd++] = a;
                }
                if (rc >= 0 && a != b)
                    rc = split_edge(ctx, s, a, b, tol, &hits, &hit_cap);
            }
            while (s->nbnd > first + 1 && s->bnd[s->nbnd - 1] == s->bnd[first])
                s->nbnd--;
            if (rc >= 0)
                rc = QC__RESERVE(ctx, s->ring_end, s->ring_cap, s->nrings + 1);
            if (rc >= 0)
                s->ring_end[s->nrings++] = s->nbnd;
            start = end;
        }
        g += r->nv;
        s->patch_end[i] = s->nrings;
    }
    qc__free(ctx, hits, hit_cap * sizeof *hits);
    return rc;
}

/* Undirected edges of every ring, deduplicated, as adjacency lists. */
static int build_adjacency(qc_ctx *ctx, qc__seams *s)
{
    qc_edge *e = (qc_edge *)qc__alloc_array(ctx, s->nbnd, sizeof *e);
    size_t ne = 0, r, j, start = 0, m = 0;
    uint32_t *fill;

    if (e == NULL)
        return QC_ENOMEM;
    for (r = 0; r < s->nrings; r++) {
        size_t end = s->ring_end[r];

        for (j = start; end - start >= 2 && j < end; j++) {
            uint32_t a = s->bnd[j], b = s->bnd[j + 1 < end ? j + 1 : start];
            if (a == b)
                continue;
            e[ne].a = a < b ? a : b;
            e[ne++].b = a < b ? b : a;
        }
        start = end;
    }
    qsort(e, ne, sizeof *e, by_edge);
    for (j = 0; j < ne; j++)
        if (m == 0 || e[j].a != e[m - 1].a || e[j].b != e[m - 1].b)
            e[m++] = e[j];
    s->adj_start = (uint32_t *)qc__alloc_array(ctx, s->nv + 1, sizeof *s->adj_start);
    s->nadj = 2 * m;
    s->adj_cap = s->nadj ? s->nadj : 1;
    s->adj = (uint32_t *)qc__alloc_array(ctx, s->adj_cap, sizeof *s->adj);
    fill = (uint32_t *)qc__alloc_array(ctx, s->nv + 1, sizeof *fill);
    if (s->adj_start == NULL || s->adj == NULL || fill == NULL) {
        qc__free(ctx, e, s->nbnd * sizeof *e);
        qc__free(ctx, fill, (s->nv + 1) * sizeof *fill);
        return QC_ENOMEM;
    }
    memset(s->adj_start, 0, (s->nv + 1) * sizeof *s->adj_start);
    for (j = 0; j < m; j++) {
        s->adj_start[e[j].a + 1]++;
        s->adj_start[e[j].b + 1]++;
    }
    for (j = 0; j < s->nv; j++)
        s->adj_start[j + 1] += s->adj_start[j];
    memcpy(fill, s->adj_start, (s->nv + 1) * sizeof *fill);
    for (j = 0; j < m; j++) {
        s->adj[fill[e[j].a]++] = e[j].b;
        s->adj[fill[e[j].b]++] = e[j].a;
    }
    qc__free(ctx, fill, (s->nv + 1) * sizeof *fill);
    qc__free(ctx, e, s->nbnd * sizeof *e);
    return QC_OK;
}

int qc__seams_build(qc_ctx *ctx, const qc_patches *ps, double tol, qc__seams *out)
{
    vref *r = NULL;
    uint32_t *id = NULL;
    size_t n = 0, i, j, g = 0;
    int rc = QC_ENOMEM;

    memset(out, 0, sizeof *out);
    for (i = 0; i < ps->n; i++)
        n += ps->p[i].region.nv;
    if (n == 0 || n >= UINT32_MAX)
        return qc__fail(ctx, n ? QC_ELIMIT : QC_EEMPTY, "quilt: %lu patch vertices",
                        (unsigned long)n);
    r = (vref *)qc__alloc_array(ctx, n, sizeof *r);
    id = (uint32_t *)qc__alloc_array(ctx, n, sizeof *id);
    out->patch_end = (size_t *)qc__alloc_array(ctx, ps->n, sizeof *out->patch_end);
    out->npatch = out->patch_end != NULL ? ps->n : 0;
    if (r == NULL || id == NULL || out->patch_end == NULL)
        goto out_free;
    for (i = 0; i < ps->n; i++)
        for (j = 0; j < ps->p[i].region.nv; j++, g++) {
            r[g].p = ps->p[i].region.v[j];
            r[g].i = (uint32_t)g;
        }
    rc = merge_vertices(ctx, r, n, tol, id, out);
    if (rc >= 0)
        rc = build_rings(ctx, ps, id, tol, out);
    if (rc >= 0)
        rc = build_adjacency(ctx, out);
out_free:
    qc__free(ctx, r, n * sizeof *r);
    qc__free(ctx, id, n * sizeof *id);
    if (rc < 0)
        qc__seams_free(ctx, out);
    return rc;
}
