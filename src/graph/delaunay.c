/*
 * Delaunay triangulation by incremental insertion in Hilbert order
 * (Bowyer-Watson cavities found by exact incircle tests, point location by a
 * stochastic visibility walk). The hull is closed by "ghost" triangles
 * (a, b, INF) so every insertion is the same cavity retriangulation; a ghost
 * is in conflict when the new point is strictly outside its hull edge or on
 * that edge's interior. With exact predicates every step is decided exactly,
 * so cocircular sets and lattices give a valid (not unique) triangulation.
 */
#include <string.h>

#include "graph_delaunay.h"

typedef struct bedge {
    uint32_t u, v, out; /* cavity boundary edge u->v, the triangle outside */
} bedge;

typedef struct dt {
    const qc_vec2 *q; /* points in insertion order */
    uint32_t inf;     /* == number of points: the ghost vertex */
    uint32_t *v, *nb; /* 3 per triangle: vertices CCW, neighbour across v[i]v[i+1] */
    uint32_t *stamp;  /* cavity mark per triangle */
    uint32_t *start;  /* per vertex (+ INF): new triangle whose boundary edge starts there */
    uint32_t ntri, last, it;
    uint32_t *cav;
    size_t cav_cap;
    bedge *b;
    size_t b_cap;
    uint64_t rng;
} dt;

static int strictly_between(qc_vec2 a, qc_vec2 b, qc_vec2 p)
{
    if (a.x != b.x)
        return (a.x < p.x && p.x < b.x) || (b.x < p.x && p.x < a.x);
    return (a.y < p.y && p.y < b.y) || (b.y < p.y && p.y < a.y);
}

static int conflict(const dt *d, uint32_t t, qc_vec2 p)
{
    const uint32_t *v = d->v + 3 * (size_t)t;

    if (v[2] == d->inf) {
        double o = qc_orient2d(d->q[v[0]], d->q[v[1]], p);

        return o > 0.0 || (o == 0.0 && strictly_between(d->q[v[0]], d->q[v[1]], p));
    }
    return qc_incircle(d->q[v[0]], d->q[v[1]], d->q[v[2]], p) > 0.0;
}

/* A triangle in conflict with p: walk from the last finite triangle. */
static uint32_t locate(dt *d, qc_vec2 p)
{
    uint32_t t = d->last;

    for (;;) {
        const uint32_t *v = d->v + 3 * (size_t)t;
        uint32_t r, j, moved = 0;

        if (v[2] == d->inf)
            return t; /* entered across a hull edge p is strictly outside of */
        d->rng = d->rng * 6364136223846793005u + 1442695040888963407u;
        r = (uint32_t)(d->rng >> 33) % 3;
        for (j = 0; j < 3; j++) {
            uint32_t i = (r + j) % 3;

            if (qc_orient2d(d->q[v[i]], d->q[v[(i + 1) % 3]], p) < 0.0) {
                t = d->nb[3 * (size_t)t + i];
                moved = 1;
                break;
            }
        }
        if (!moved)
            return t; /* p in the closed triangle: strictly in its circle */
    }
}

static uint32_t edge_index(const dt *d, uint32_t t, uint32_t a, uint32_t b)
{
    const uint32_t *v = d->v + 3 * (size_t)t;

    return v[0] == a && v[1] == b ? 0 : v[1] == a && v[2] == b ? 1 : 2;
}

static int insert(qc_ctx *ctx, dt *d, uint32_t pi)
{
    qc_vec2 p = d->q[pi];
    size_t ncav = 0, nb = 0, k;
    uint32_t t0 = locate(d, p);

    d->it++;
    QC__TRY(QC__RESERVE(ctx, d->cav, d->cav_cap, 1));
    d->cav[ncav++] = t0;
    d->stamp[t0] = d->it;
    for (k = 0; k < ncav; k++) {
        uint32_t t = d->cav[k], i;

        for (i = 0; i < 3; i++) {
            uint32_t o = d->nb[3 * (size_t)t + i];

            if (d->stamp[o] == d->it)
                continue;
            if (conflict(d, o, p)) {
                QC__TRY(QC__RESERVE(ctx, d->cav, d->cav_cap, ncav + 1));
                d->stamp[o] = d->it;
                d->cav[ncav++] = o;
            } else {
                QC__TRY(QC__RESERVE(ctx, d->b, d->b_cap, nb + 1));
                d->b[nb].u = d->v[3 * (size_t)t + i];
                d->b[nb].v = d->v[3 * (size_t)t + (i + 1) % 3];
                d->b[nb].out = o;
                nb++;
            }
        }
    }
    /* nb == ncav + 2 new triangles: reuse the cavity's slots, then append. */
    for (k = 0; k < nb; k++) {
        uint32_t t = k < ncav ? d->cav[k] : d->ntri++;
        uint32_t u = d->b[k].u, w = d->b[k].v, *v = d->v + 3 * (size_t)t;
        uint32_t *n = d->nb + 3 * (size_t)t;

        if (u == d->inf) { /* (INF, w, p) -> (w, p, INF) */
            v[0] = w, v[1] = pi, v[2] = u;
            n[2] = d->b[k].out;
        } else if (w == d->inf) { /* (u, INF, p) -> (p, u, INF) */
            v[0] = pi, v[1] = u, v[2] = w;
            n[1] = d->b[k].out;
        } else {
            v[0] = u, v[1] = w, v[2] = pi;
            n[0] = d->b[k].out;
            d->last = t;
        }
        d->start[u] = t;
        d->nb[3 * (size_t)d->b[k].out + edge_index(d, d->b[k].out, w, u)] = t;
        d->b[k].out = t; /* from here on: the new triangle */
    }
    for (k = 0; k < nb; k++) {
        uint32_t t = d->b[k].out, w = d->b[k].v, s = d->start[w];

        d->nb[3 * (size_t)t + edge_index(d, t, w, pi)] = s;
        d->nb[3 * (size_t)s + edge_index(d, s, pi, w)] = t;
    }
    return QC_OK;
}

/* First triangle from q[0], q[1], q[2] (not collinear) and its 3 ghosts. */
static void init_triangle(dt *d)
{
    uint32_t i;

    d->v[0] = 0, d->v[1] = 1, d->v[2] = 2;
    if (qc_orient2d(d->q[0], d->q[1], d->q[2]) < 0.0)
        d->v[1] = 2, d->v[2] = 1;
    for (i = 0; i < 3; i++) {
        uint32_t g = 1 + i, *v = d->v + 3 * (size_t)g, *n = d->nb + 3 * (size_t)g;

        d->nb[i] = g;
        v[0] = d->v[(i + 1) % 3], v[1] = d->v[i], v[2] = d->inf;
        n[0] = 0, n[1] = 1 + (i + 2) % 3, n[2] = 1 + (i + 1) % 3;
    }
    d->ntri = 4;
    d->last = 0;
}

static void dt_free(qc_ctx *ctx, dt *d, size_t m)
{
    size_t cap = 2 * m + 2;

    qc__free(ctx, d->v, 3 * cap * sizeof *d->v);
    qc__free(ctx, d->nb, 3 * cap * sizeof *d->nb);
    qc__free(ctx, d->stamp, cap * sizeof *d->stamp);
    qc__free(ctx, d->start, (m + 1) * sizeof *d->start);
    qc__free(ctx, d->cav, d->cav_cap * sizeof *d->cav);
    qc__free(ctx, d->b, d->b_cap * sizeof *d->b);
}

int qc__triangulate(qc_ctx *ctx, const qc_vec2 *q, const uint32_t *orig,
                    uint32_t m, qc_mesh *out)
{
    dt d;
    size_t cap = 2 * (size_t)m + 2, t, nt = 0, ne = 0;
    uint32_t i;
    int rc = QC_ENOMEM;

    memset(&d, 0, sizeof d);
    d.q = q;
    d.inf = m;
    d.rng = 0x853c49e6748fea9bu;
    d.v = qc__alloc_array(ctx, 3 * cap, sizeof *d.v);
    d.nb = qc__alloc_array(ctx, 3 * cap, sizeof *d.nb);
    d.stamp = qc__alloc_array(ctx, cap, sizeof *d.stamp);
    d.start = qc__alloc_array(ctx, (size_t)m + 1, sizeof *d.start);
    if (d.v == NULL || d.nb == NULL || d.stamp == NULL || d.start == NULL)
        goto out_free;
    memset(d.stamp, 0, cap * sizeof *d.stamp);
    init_triangle(&d);
    for (i = 3; i < m; i++)
        if ((rc = insert(ctx, &d, i)) < 0)
            goto out_free;
    for (t = 0; t < d.ntri; t++) {
        if (d.v[3 * t + 2] == d.inf)
            continue;
        nt++;
        for (i = 0; i < 3; i++) {
            uint32_t o = d.nb[3 * t + i];
            ne += d.v[3 * (size_t)o + 2] == d.inf || t < o;
        }
    }
    rc = QC_ENOMEM;
    out->tri = qc__alloc_array(ctx, 3 * nt, sizeof *out->tri);
    if (out->tri == NULL)
        goto out_free;
    out->tri_cap = nt;
    out->edges.e = qc__alloc_array(ctx, ne, sizeof *out->edges.e);
    if (out->edges.e == NULL)
        goto out_free;
    out->edges.cap = ne;
    for (t = 0; t < d.ntri; t++) {
        const uint32_t *v = d.v + 3 * t;

        if (v[2] == d.inf)
            continue;
        for (i = 0; i < 3; i++) {
            uint32_t o = d.nb[3 * t + i];

            out->tri[3 * out->ntri + i] = orig[v[i]];
            if (d.v[3 * (size_t)o + 2] == d.inf || t < o) {
                uint32_t a = orig[v[i]], b = orig[v[(i + 1) % 3]];
                qc_edge e;

                e.a = a < b ? a : b;
                e.b = a < b ? b : a;
                out->edges.e[out->edges.n++] = e;
            }
        }
        out->ntri++;
    }
    rc = QC_OK;
out_free:
    dt_free(ctx, &d, m);
    if (rc == QC_ENOMEM)
        rc = qc__fail(ctx, QC_ENOMEM, "delaunay: out of memory for %lu points",
                      (unsigned long)m);
    return rc;
}
