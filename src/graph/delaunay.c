/*
 * Delaunay triangulation by incremental insertion in Hilbert order
 * (Bowyer-Watson cavities found by exact incircle tests, point location by a
 * stochastic visibility walk). The hull is closed by "ghost" triangles
 * (a, b, INF) so every insertion is the same cavity retriangulation; a ghost
 * is in conflict when the new point is strictly outside its hull edge or on
 * that edge's interior. With exact predicates every step is decided exactly,
 * so cocircular sets and lattices give a valid (not unique) triangulation.
 */
#include <math.h>
#include <string.h>

#include "graph_delaunay.h"

typedef struct bedge {
    uint32_t u, v, out; /* cavity boundary edge u->v, the triangle outside */
} bedge;

typedef struct dt {
    const qc_vec2 *q; /* points in insertion order */
    uint32_t inf;     /* == number of points: the ghost vertex */
    uint32_t *tr;     /* 8 per triangle: vertices CCW, the neighbours across
                         v[i]v[i+1], the cavity mark, padding: 32 bytes, so
                         a triangle never straddles a cache line */
    uint32_t *start;  /* per vertex (+ INF): new triangle whose boundary edge starts there */
    uint32_t ntri, last, it;
    uint32_t *cav;
    size_t cav_cap;
    bedge *b;
    size_t b_cap;
    qc_rng rng;       /* the walk's random first edges, two bits a step */
    uint64_t bits;
    unsigned nbits;
} dt;

#define TV(d, t) ((d)->tr + 8 * (size_t)(t))
#define TN(d, t) (TV(d, t) + 3)
#define TS(d, t) (TV(d, t)[6])

/* The predicates' floating-point filters, inlined here for speed; the exact
 * functions decide whenever the filter cannot. */
static double orient(qc_vec2 a, qc_vec2 b, qc_vec2 c)
{
    double l = (a.x - c.x) * (b.y - c.y), r = (a.y - c.y) * (b.x - c.x);
    double det = l - r, bound = (3.0 + 16.0 * 0x1p-53) * 0x1p-53 * (fabs(l) + fabs(r));

    return det > bound || -det > bound ? det : qc_orient2d(a, b, c);
}

static double incircle(qc_vec2 a, qc_vec2 b, qc_vec2 c, qc_vec2 d)
{
    double adx = a.x - d.x, bdx = b.x - d.x, cdx = c.x - d.x;
    double ady = a.y - d.y, bdy = b.y - d.y, cdy = c.y - d.y;
    double bc1 = bdx * cdy, bc2 = cdx * bdy, al = adx * adx + ady * ady;
    double ca1 = cdx * ady, ca2 = adx * cdy, bl = bdx * bdx + bdy * bdy;
    double ab1 = adx * bdy, ab2 = bdx * ady, cl = cdx * cdx + cdy * cdy;
    double det = al * (bc1 - bc2) + bl * (ca1 - ca2) + cl * (ab1 - ab2);
    double bound = (10.0 + 96.0 * 0x1p-53) * 0x1p-53 *
                   ((fabs(bc1) + fabs(bc2)) * al + (fabs(ca1) + fabs(ca2)) * bl +
                    (fabs(ab1) + fabs(ab2)) * cl);

    return det > bound || -det > bound ? det : qc_incircle(a, b, c, d);
}

static int strictly_between(qc_vec2 a, qc_vec2 b, qc_vec2 p)
{
    if (a.x != b.x)
        return (a.x < p.x && p.x < b.x) || (b.x < p.x && p.x < a.x);
    return (a.y < p.y && p.y < b.y) || (b.y < p.y && p.y < a.y);
}

static int conflict(const dt *d, uint32_t t, qc_vec2 p)
{
    const uint32_t *v = TV(d, t);

    if (v[2] == d->inf) {
        double o = orient(d->q[v[0]], d->q[v[1]], p);

        return o > 0.0 || (o == 0.0 && strictly_between(d->q[v[0]], d->q[v[1]], p));
    }
    return incircle(d->q[v[0]], d->q[v[1]], d->q[v[2]], p) > 0.0;
}

/* A triangle in conflict with p: walk from the last finite triangle. */
static uint32_t locate(dt *d, qc_vec2 p)
{
    uint32_t t = d->last;

    for (;;) {
        const uint32_t *v = TV(d, t);
        uint32_t r, j, moved = 0;

        if (v[2] == d->inf)
            return t; /* entered across a hull edge p is strictly outside of */
        if (d->nbits == 0) {
            d->bits = qc_rng_u64(&d->rng);
            d->nbits = 32;
        }
        r = (uint32_t)(d->bits & 3u); /* a random first edge: the walk ends */
        r = r == 3 ? 0 : r;
        d->bits >>= 2;
        d->nbits--;
        for (j = 0; j < 3; j++) {
            uint32_t i = r + j < 3 ? r + j : r + j - 3;

            if (orient(d->q[v[i]], d->q[v[(i + 1) % 3]], p) < 0.0) {
                t = TN(d, t)[i];
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
    const uint32_t *v = TV(d, t);

    return v[0] == a && v[1] == b ? 0 : v[1] == a && v[2] == b ? 1 : 2;
}

static int insert(qc_ctx *ctx, dt *d, uint32_t pi)
{
    qc_vec2 p = d->q[pi];
    size_t ncav = 0, nb = 0, k;
    uint32_t t0 = locate(d, p);

    d->it++;
    if (d->cav_cap == 0)
        QC__TRY(QC__RESERVE(ctx, d->cav, d->cav_cap, 1));
    d->cav[ncav++] = t0;
    TS(d, t0) = d->it;
    for (k = 0; k < ncav; k++) {
        uint32_t t = d->cav[k], i;

        for (i = 0; i < 3; i++) {
            uint32_t o = TN(d, t)[i];

            if (TS(d, o) == d->it)
                continue;
            if (conflict(d, o, p)) {
                if (ncav == d->cav_cap)
                    QC__TRY(QC__RESERVE(ctx, d->cav, d->cav_cap, ncav + 1));
                TS(d, o) = d->it;
                d->cav[ncav++] = o;
            } else {
                if (nb == d->b_cap)
                    QC__TRY(QC__RESERVE(ctx, d->b, d->b_cap, nb + 1));
                d->b[nb].u = TV(d, t)[i];
                d->b[nb].v = TV(d, t)[(i + 1) % 3];
                d->b[nb].out = o;
                nb++;
            }
        }
    }
    /* nb == ncav + 2 new triangles: reuse the cavity's slots, then append. */
    for (k = 0; k < nb; k++) {
        uint32_t t = k < ncav ? d->cav[k] : d->ntri++;
        uint32_t u = d->b[k].u, w = d->b[k].v, *v = TV(d, t);
        uint32_t *n = TN(d, t);

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
        TN(d, d->b[k].out)[edge_index(d, d->b[k].out, w, u)] = t;
        d->b[k].out = t; /* from here on: the new triangle */
    }
    for (k = 0; k < nb; k++) {
        uint32_t t = d->b[k].out, w = d->b[k].v, s = d->start[w];

        TN(d, t)[edge_index(d, t, w, pi)] = s;
        TN(d, s)[edge_index(d, s, pi, w)] = t;
    }
    return QC_OK;
}

/* First triangle from q[0], q[1], q[2] (not collinear) and its 3 ghosts. */
static void init_triangle(dt *d)
{
    uint32_t i;

    TV(d, 0)[0] = 0, TV(d, 0)[1] = 1, TV(d, 0)[2] = 2;
    if (qc_orient2d(d->q[0], d->q[1], d->q[2]) < 0.0)
        TV(d, 0)[1] = 2, TV(d, 0)[2] = 1;
    for (i = 0; i < 3; i++) {
        uint32_t g = 1 + i, *v = TV(d, g), *n = TN(d, g);

        TN(d, 0)[i] = g;
        v[0] = TV(d, 0)[(i + 1) % 3], v[1] = TV(d, 0)[i], v[2] = d->inf;
        n[0] = 0, n[1] = 1 + (i + 2) % 3, n[2] = 1 + (i + 1) % 3;
    }
    d->ntri = 4;
    d->last = 0;
}

static void dt_free(qc_ctx *ctx, dt *d, size_t m)
{
    size_t cap = 2 * m + 2;

    qc__free(ctx, d->tr, 8 * cap * sizeof *d->tr);
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
    qc_rng_seed(&d.rng, 0x853c49e6748fea9bu);
    d.tr = qc__alloc_array(ctx, 8 * cap, sizeof *d.tr);
    d.start = qc__alloc_array(ctx, (size_t)m + 1, sizeof *d.start);
    if (d.tr == NULL || d.start == NULL)
        goto out_free;
    memset(d.tr, 0, 8 * cap * sizeof *d.tr);
    init_triangle(&d);
    for (i = 3; i < m; i++)
        if ((rc = insert(ctx, &d, i)) < 0)
            goto out_free;
    for (t = 0; t < d.ntri; t++) {
        if (TV(&d, t)[2] == d.inf)
            continue;
        nt++;
        for (i = 0; i < 3; i++) {
            uint32_t o = TN(&d, t)[i];
            ne += TV(&d, o)[2] == d.inf || t < o;
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
        const uint32_t *v = TV(&d, t);

        if (v[2] == d.inf)
            continue;
        for (i = 0; i < 3; i++) {
            uint32_t o = TN(&d, t)[i];

            out->tri[3 * out->ntri + i] = orig[v[i]];
            if (TV(&d, o)[2] == d.inf || t < o) {
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
