/*
 * The region's signed distance field for offsetting (echo, spiral): exact
 * distances to the nearest boundary edge on a grid, found near the
 * boundary and carried inward by two raster sweeps, each node keeping its
 * nearest edge; then exact distance queries anywhere from those edges.
 * The iso-contours are traced in shared_sdf_rings.c.
 */
#include <math.h>
#include <stddef.h>
#include <string.h>

#include "deco_internal.h"

/* 2^24 nodes (14 bytes each while built: about 235 MB) hold a 10 m block at
 * d = 10 mm and a 3.5 m block at d = 2 mm within the d / 2 grid echo and
 * spiral accept. */
#define MAX_NODES ((size_t)1 << 24)
#define NONE UINT32_MAX
/* doubles per edge in eg */
#define EG 5

void qc__sdf_free(qc_ctx *ctx, qc__sdf *s)
{
    size_t n;

    if (s == NULL)
        return;
    n = s->nx * s->ny;
    qc__free(ctx, s->v, n * sizeof *s->v);
    qc__free(ctx, s->seg, n * sizeof *s->seg);
    if (s->region != NULL) {
        qc__free(ctx, s->prev, s->region->nv * sizeof *s->prev);
        qc__free(ctx, s->next, s->region->nv * sizeof *s->next);
        qc__free(ctx, s->ring, s->region->nv * sizeof *s->ring);
        qc__free(ctx, s->eg, s->region->nv * EG * sizeof *s->eg);
    }
    qc__free(ctx, s->flat, n);
    memset(s, 0, sizeof *s);
}

/* Edge e runs from vertex prev[e] to vertex e; inside is on its left. */
static void edge_ends(const qc__sdf *s, uint32_t e, qc_vec2 *a, qc_vec2 *b)
{
    *a = s->region->v[s->prev[e]];
    *b = s->region->v[e];
}

static uint32_t edge_next(const qc__sdf *s, uint32_t e)
{
    return s->next[e];
}

/* Squared distance from p to edge e; *t receives the nearest point's
 * parameter. The edge's start, vector and squared length come from eg
 * (the queries ask them of the same edges again and again). */
static double edge_d2(const qc__sdf *s, uint32_t e, qc_vec2 p, double *t)
{
    const double *g = s->eg + (size_t)e * EG;
    double ax = g[0], ay = g[1], ex = g[2], ey = g[3], len2 = g[4], u, dx, dy;

    u = len2 > 0.0 ? ((p.x - ax) * ex + (p.y - ay) * ey) / len2 : 0.0;
    u = u < 0.0 ? 0.0 : u > 1.0 ? 1.0 : u;
    dx = p.x - (ax + u * ex);
    dy = p.y - (ay + u * ey);
    *t = u;
    return dx * dx + dy * dy;
}

/* From edge *e (squared distance *d2, parameter *t), moves along its ring
 * while a neighbouring edge is nearer to p: boundaries of many short edges
 * defeat the sweeps' neighbour propagation by a little. */
static void descend(const qc__sdf *s, qc_vec2 p, uint32_t *e, double *d2, double *t)
{
    size_t guard;

    for (guard = 0; guard < s->region->nv; guard++) {
        uint32_t c[2], best = *e;
        double bd = *d2, bt = *t, tt, q;
        int i;

        c[0] = s->prev[*e];
        c[1] = s->next[*e];
        for (i = 0; i < 2; i++) {
            q = edge_d2(s, c[i], p, &tt);
            if (q < bd) {
                bd = q;
                bt = tt;
                best = c[i];
            }
        }
        if (best == *e)
            return;
        *e = best;
        *d2 = bd;
        *t = bt;
    }
}

/* If edge b lies within SCAN edges of edge a along their ring (either
 * way), tries every edge between them for p. */
#define SCAN 128
static void scan_between(const qc__sdf *s, qc_vec2 p, uint32_t a, uint32_t b, uint32_t *best,
                         double *bd, double *bt)
{
    const qc_region *r = s->region;
    uint32_t k = s->ring[a], e;
    size_t start = k ? r->ring_end[k - 1] : 0, len = r->ring_end[k] - start, fwd;
    int dir;

    if (s->ring[b] != k)
        return;
    fwd = ((size_t)b + len - a) % len;
    if (fwd <= SCAN)
        dir = 1;
    else if (len - fwd <= SCAN)
        dir = -1;
    else
        return;
    for (e = dir > 0 ? s->next[a] : s->prev[a]; e != b; e = dir > 0 ? s->next[e] : s->prev[e]) {
        double t, d2 = edge_d2(s, e, p, &t);
        if (d2 < *bd || (d2 == *bd && e < *best)) {
            *bd = d2;
            *best = e;
            *bt = t;
        }
    }
}

/* Tries edge e for node k at p (qc__seg_dist2's arithmetic on eg). */
static void relax(const qc__sdf *s, double *d2, size_t k, qc_vec2 p, uint32_t e)
{
    const double *g;
    double q, t, ex, ey;

    if (e == NONE || e == s->seg[k])
        return;
    g = s->eg + (size_t)e * EG;
    t = g[4] > 0.0 ? ((p.x - g[0]) * g[2] + (p.y - g[1]) * g[3]) / g[4] : 0.0;
    t = t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t;
    ex = g[0] + t * g[2] - p.x;
    ey = g[1] + t * g[3] - p.y;
    q = ex * ex + ey * ey;
    if (q < d2[k] || (q == d2[k] && e < s->seg[k])) {
        d2[k] = q;
        s->seg[k] = e;
    }
}

static qc_vec2 node_at(const qc__sdf *s, size_t i, size_t j)
{
    qc_vec2 p;
    p.x = s->x0 + (double)i * s->h;
    p.y = s->y0 + (double)j * s->h;
    return p;
}

/* Exact distances round every edge (nodes within two cells of it). */
static void seed_edges(qc__sdf *s, double *d2)
{
    const qc_region *r = s->region;
    size_t e;

    for (e = 0; e < r->nv; e++) {
        qc_vec2 a, b;
        double len, steps;
        size_t m, t;

        edge_ends(s, (uint32_t)e, &a, &b);
        len = qc_hypot(b.x - a.x, b.y - a.y);
        steps = ceil(len / (0.5 * s->h));
        m = steps < 1.0 ? 1 : (size_t)fmin(steps, 1e8);
        for (t = 0; t <= m; t++) {
            double f = (double)t / (double)m;
            double gx = floor((a.x + (b.x - a.x) * f - s->x0) / s->h);
            double gy = floor((a.y + (b.y - a.y) * f - s->y0) / s->h);
            long x, y;

            for (y = (long)gy - 1; y <= (long)gy + 2; y++)
                for (x = (long)gx - 1; x <= (long)gx + 2; x++) {
                    size_t k;
                    if (x < 0 || y < 0 || (size_t)x >= s->nx || (size_t)y >= s->ny)
                        continue;
                    k = (size_t)y * s->nx + (size_t)x;
                    if (s->seg[k] != e) /* samples h / 2 apart: most nodes had e already */
                        relax(s, d2, k, node_at(s, (size_t)x, (size_t)y), (uint32_t)e);
                }
        }
    }
}

/* Tries the nearest edge of node k + o for node k at (i, j) (inline test
 * first: neighbours mostly share their nearest edge). */
#define TRY_NB(o)                                                      \
    do {                                                               \
        uint32_t e_ = seg[k + (o)];                                    \
        if (e_ != seg[k] && e_ != NONE)                                \
            relax(s, d2, k, node_at(s, i, j), e_);                     \
    } while (0)

/* Carries the nearest edges: forward sweep, then backward (8SSEDT order). */
static void sweep(qc__sdf *s, double *d2)
{
    size_t nx = s->nx, ny = s->ny, i, j, k;
    const uint32_t *seg = s->seg;

    for (j = 0; j < ny; j++) {
        for (i = 0; i < nx; i++) {
            k = j * nx + i;
            if (i > 0)
                TRY_NB(-1);
            if (j > 0) {
                TRY_NB(-(ptrdiff_t)nx);
                if (i > 0)
                    TRY_NB(-(ptrdiff_t)nx - 1);
                if (i + 1 < nx)
                    TRY_NB(-(ptrdiff_t)nx + 1);
            }
        }
        for (i = nx - 1; i-- > 0;) {
            k = j * nx + i;
            TRY_NB(1);
        }
    }
    for (j = ny; j-- > 0;) {
        for (i = nx; i-- > 0;) {
            k = j * nx + i;
            if (i + 1 < nx)
                TRY_NB(1);
            if (j + 1 < ny) {
                TRY_NB((ptrdiff_t)nx);
                if (i + 1 < nx)
                    TRY_NB((ptrdiff_t)nx + 1);
                if (i > 0)
                    TRY_NB((ptrdiff_t)nx - 1);
            }
        }
        for (i = 1; i < nx; i++) {
            k = j * nx + i;
            TRY_NB(-1);
        }
    }
}

#undef TRY_NB

/* The grid's spacing for a wanted h (raised by 1.25 until the nodes fit)
 * and its node counts. */
static double grid_step(qc_bbox box, double h, size_t *nx, size_t *ny)
{
    for (;;) {
        double fx = floor((box.max.x - box.min.x) / h) + 5.0;
        double fy = floor((box.max.y - box.min.y) / h) + 5.0;
        if (fx * fy <= (double)MAX_NODES) {
            *nx = (size_t)fx;
            *ny = (size_t)fy;
            return h;
        }
        h *= 1.25;
    }
}

double qc__sdf_step(const qc_region *region, double h)
{
    size_t nx, ny;

    if (region == NULL || region->nrings == 0 || !(h > 0.0) || !isfinite(h))
        return h;
    return grid_step(qc_region_bbox(region), h, &nx, &ny);
}

int qc__sdf_build(qc_ctx *ctx, const qc_region *region, double h, qc__sdf *out)
{
    unsigned char *mask = NULL;
    size_t n = 0, k, e, i, j;
    int rc = QC_ENOMEM;

    memset(out, 0, sizeof *out);
    if (region == NULL || region->nrings == 0 || region->nv < 3)
        return qc__fail(ctx, QC_EEMPTY, "distance grid: the region has no outline");
    if (!(h > 0.0) || !isfinite(h))
        return qc__fail(ctx, QC_ERANGE, "distance grid: spacing %g mm must be > 0", h);
    h = grid_step(qc_region_bbox(region), h, &out->nx, &out->ny);
    out->h = h;
    out->x0 = qc_region_bbox(region).min.x - 2.0 * h;
    out->y0 = qc_region_bbox(region).min.y - 2.0 * h;
    out->region = region;
    n = out->nx * out->ny;
    out->v = qc__alloc_array(ctx, n, sizeof *out->v);
    out->seg = qc__alloc_array(ctx, n, sizeof *out->seg);
    out->prev = qc__alloc_array(ctx, region->nv, sizeof *out->prev);
    out->next = qc__alloc_array(ctx, region->nv, sizeof *out->next);
    out->ring = qc__alloc_array(ctx, region->nv, sizeof *out->ring);
    out->eg = qc__alloc_array(ctx, region->nv * EG, sizeof *out->eg);
    mask = qc__alloc(ctx, n);
    out->flat = qc__alloc(ctx, n);
    if (out->v == NULL || out->seg == NULL || out->prev == NULL || out->next == NULL ||
        out->ring == NULL || out->eg == NULL || mask == NULL || out->flat == NULL)
        goto out;
    for (k = 0, e = 0; k < region->nrings; k++) {
        size_t start = e, last = region->ring_end[k] - 1;
        for (; e <= last; e++) {
            out->prev[e] = (uint32_t)(e == start ? last : e - 1);
            out->next[e] = (uint32_t)(e == last ? start : e + 1);
            out->ring[e] = (uint32_t)k;
        }
    }
    for (e = 0; e < region->nv; e++) {
        qc_vec2 a, b;
        double *g = out->eg + e * EG;

        edge_ends(out, (uint32_t)e, &a, &b);
        g[0] = a.x;
        g[1] = a.y;
        g[2] = b.x - a.x;
        g[3] = b.y - a.y;
        g[4] = g[2] * g[2] + g[3] * g[3];
    }
    for (k = 0; k < n; k++) {
        out->v[k] = HUGE_VAL; /* squared distances until the end */
        out->seg[k] = NONE;
    }
    seed_edges(out, out->v);
    sweep(out, out->v);
    rc = qc__raster_inside(ctx, region, out->x0, out->y0, h, out->nx, out->ny, mask);
    if (rc < 0)
        goto out;
    for (k = 0, j = 0; j < out->ny; j++)
        for (i = 0; i < out->nx; i++, k++) { /* row by row: no division per node */
            double t = 0.0;

            descend(out, node_at(out, i, j), &out->seg[k], &out->v[k], &t);
            out->v[k] = mask[k] ? sqrt(out->v[k]) : -sqrt(out->v[k]);
            out->flat[k] = t > 0.0 && t < 1.0;
        }
out:
    qc__free(ctx, mask, n);
    if (rc < 0) {
        qc__sdf_free(ctx, out);
        return qc__fail(ctx, rc, "out of memory for a %lu-node distance grid", (unsigned long)n);
    }
    return QC_OK;
}

/* The cell holding p (clamped into the grid). */
static void cell_of(const qc__sdf *s, qc_vec2 p, size_t *i, size_t *j, double *tx, double *ty)
{
    double fx = (p.x - s->x0) / s->h, fy = (p.y - s->y0) / s->h;

    double mx = (double)(s->nx - 1) - 1e-9, my = (double)(s->ny - 1) - 1e-9;

    fx = fx > 0.0 ? (fx < mx ? fx : mx) : 0.0;
    fy = fy > 0.0 ? (fy < my ? fy : my) : 0.0;
    *i = (size_t)fx;
    *j = (size_t)fy;
    *tx = fx - (double)*i;
    *ty = fy - (double)*j;
}

double qc__sdf_at(const qc__sdf *s, qc_vec2 p)
{
    size_t i, j, k;
    double tx, ty;

    cell_of(s, p, &i, &j, &tx, &ty);
    k = j * s->nx + i;
    return (s->v[k] * (1 - tx) + s->v[k + 1] * tx) * (1 - ty) +
           (s->v[k + s->nx] * (1 - tx) + s->v[k + s->nx + 1] * tx) * ty;
}

static double cross3(qc_vec2 a, qc_vec2 b, qc_vec2 p)
{
    return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

/* Whether p, nearest to the corner vertex c between edges a->c and c->b,
 * is inside (left of both at a convex corner, of either at a reflex one). */
static int corner_inside(qc_vec2 a, qc_vec2 c, qc_vec2 b, qc_vec2 p)
{
    int l1 = cross3(a, c, p) > 0.0, l2 = cross3(c, b, p) > 0.0;

    return cross3(a, c, b) > 0.0 ? (l1 && l2) : (l1 || l2);
}

double qc__sdf_exact_full(const qc__sdf *s, qc_vec2 p, qc_vec2 *grad, uint32_t *edge, int *flat)
{
    const qc_region *r = s->region;
    uint32_t cand[4], best = NONE;
    size_t i, j, k, c;
    double tx, ty, bd = HUGE_VAL, bt = 0.0, dist;
    qc_vec2 a, b, q;
    int inside;

    cell_of(s, p, &i, &j, &tx, &ty);
    k = j * s->nx + i;
    cand[0] = s->seg[k];
    cand[1] = s->seg[k + 1];
    cand[2] = s->seg[k + s->nx];
    cand[3] = s->seg[k + s->nx + 1];
    for (c = 0; c < 4; c++) { /* descend() below tries each winner's neighbours */
        uint32_t e = cand[c];
        double t, d2;

        if (e == NONE || e == best || (c > 0 && e == cand[c - 1]))
            continue;
        d2 = edge_d2(s, e, p, &t);
        if (d2 < bd || (d2 == bd && e < best)) {
            bd = d2;
            best = e;
            bt = t;
        }
    }
    for (c = 1; c < 4; c++) /* edges between two candidates along a ring (short edges) */
        if (cand[c] != NONE && cand[0] != NONE && cand[c] != cand[0] && cand[c] != cand[c - 1])
            scan_between(s, p, cand[0], cand[c], &best, &bd, &bt);
    descend(s, p, &best, &bd, &bt);
    edge_ends(s, best, &a, &b);
    q.x = a.x + bt * (b.x - a.x);
    q.y = a.y + bt * (b.y - a.y);
    if (bt <= 0.0)
        inside = corner_inside(r->v[s->prev[s->prev[best]]], a, b, p);
    else if (bt >= 1.0)
        inside = corner_inside(a, b, r->v[edge_next(s, best)], p);
    else
        inside = cross3(a, b, p) >= 0.0;
    dist = sqrt(bd);
    *edge = best;
    *flat = bt > 0.0 && bt < 1.0;
    if (grad != NULL) {
        if (dist > 0.0) {
            grad->x = (p.x - q.x) / dist;
            grad->y = (p.y - q.y) / dist;
        } else { /* on the edge: its left normal */
            double l = qc_hypot(b.x - a.x, b.y - a.y);
            grad->x = l > 0.0 ? -(b.y - a.y) / l : 0.0;
            grad->y = l > 0.0 ? (b.x - a.x) / l : 0.0;
            inside = 1;
        }
        if (!inside) {
            grad->x = -grad->x;
            grad->y = -grad->y;
        }
    }
    return inside ? dist : -dist;
}

double qc__sdf_exact(const qc__sdf *s, qc_vec2 p, qc_vec2 *grad)
{
    uint32_t e;
    int flat;

    return qc__sdf_exact_full(s, p, grad, &e, &flat);
}

double qc__sdf_max(const qc__sdf *s, qc_vec2 *at)
{
    size_t k, best = 0;

    for (k = 1; k < s->nx * s->ny; k++)
        if (s->v[k] > s->v[best])
            best = k;
    at->x = s->x0 + (double)(best % s->nx) * s->h;
    at->y = s->y0 + (double)(best / s->nx) * s->h;
    return s->v[best];
}
