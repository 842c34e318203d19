/*
 * Offsetting by distance fields: the region's signed distance on a grid
 * (exact distances to the nearest boundary edge, found near the boundary
 * and carried inward by two raster sweeps, each node keeping its nearest
 * edge), exact distance queries anywhere from those edges, and the
 * iso-contours by marching squares, all levels in one pass. Contour
 * vertices are moved onto the exact level (Newton along the grid edge) and
 * chords that stray from it are split, so every vertex lies at its level
 * to about 1e-9 mm and every chord within 0.2% of the level spacing.
 * Offsetting this way handles concave outlines, holes and rings that split
 * or vanish without special cases.
 */
#include <math.h>
#include <stddef.h>
#include <string.h>

#include "deco_internal.h"
#include "../measure/measure_internal.h"

#define MAX_NODES ((size_t)1 << 22)
#define NONE UINT32_MAX
/* A chord may stray from its level by this fraction of the level step. */
#define CHORD_TOL 0.002
#define SPLIT_DEPTH 12

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

/* Squared distance from p to edge e; *t receives the nearest point's parameter. */
static double edge_d2(const qc__sdf *s, uint32_t e, qc_vec2 p, double *t)
{
    qc_vec2 a, b;
    double ex, ey, len2, u, dx, dy;

    edge_ends(s, e, &a, &b);
    ex = b.x - a.x;
    ey = b.y - a.y;
    len2 = ex * ex + ey * ey;
    u = len2 > 0.0 ? ((p.x - a.x) * ex + (p.y - a.y) * ey) / len2 : 0.0;
    u = u < 0.0 ? 0.0 : u > 1.0 ? 1.0 : u;
    dx = p.x - (a.x + u * ex);
    dy = p.y - (a.y + u * ey);
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

/* Tries edge e for node k at p. */
static void relax(const qc__sdf *s, double *d2, size_t k, qc_vec2 p, uint32_t e)
{
    qc_vec2 a, b;
    double q;

    if (e == NONE || e == s->seg[k])
        return;
    edge_ends(s, e, &a, &b);
    q = qc__seg_dist2(p, a, b);
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
                for (x = (long)gx - 1; x <= (long)gx + 2; x++)
                    if (x >= 0 && y >= 0 && (size_t)x < s->nx && (size_t)y < s->ny)
                        relax(s, d2, (size_t)y * s->nx + (size_t)x,
                              node_at(s, (size_t)x, (size_t)y), (uint32_t)e);
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

int qc__sdf_build(qc_ctx *ctx, const qc_region *region, double h, qc__sdf *out)
{
    qc_bbox box;
    unsigned char *mask = NULL;
    size_t n = 0, k, e;
    int rc = QC_ENOMEM;

    memset(out, 0, sizeof *out);
    if (region == NULL || region->nrings == 0 || region->nv < 3)
        return qc__fail(ctx, QC_EEMPTY, "distance grid: the region has no outline");
    if (!(h > 0.0) || !isfinite(h))
        return qc__fail(ctx, QC_ERANGE, "distance grid: spacing %g mm must be > 0", h);
    box = qc_region_bbox(region);
    for (;;) {
        double fx = floor((box.max.x - box.min.x) / h) + 5.0;
        double fy = floor((box.max.y - box.min.y) / h) + 5.0;
        if (fx * fy <= (double)MAX_NODES) {
            out->nx = (size_t)fx;
            out->ny = (size_t)fy;
            break;
        }
        h *= 1.25;
    }
    out->h = h;
    out->x0 = box.min.x - 2.0 * h;
    out->y0 = box.min.y - 2.0 * h;
    out->region = region;
    n = out->nx * out->ny;
    out->v = qc__alloc_array(ctx, n, sizeof *out->v);
    out->seg = qc__alloc_array(ctx, n, sizeof *out->seg);
    out->prev = qc__alloc_array(ctx, region->nv, sizeof *out->prev);
    out->next = qc__alloc_array(ctx, region->nv, sizeof *out->next);
    out->ring = qc__alloc_array(ctx, region->nv, sizeof *out->ring);
    mask = qc__alloc(ctx, n);
    out->flat = qc__alloc(ctx, n);
    if (out->v == NULL || out->seg == NULL || out->prev == NULL || out->next == NULL ||
        out->ring == NULL || mask == NULL || out->flat == NULL)
        goto out;
    for (k = 0, e = 0; k < region->nrings; k++) {
        size_t start = e, last = region->ring_end[k] - 1;
        for (; e <= last; e++) {
            out->prev[e] = (uint32_t)(e == start ? last : e - 1);
            out->next[e] = (uint32_t)(e == last ? start : e + 1);
            out->ring[e] = (uint32_t)k;
        }
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
    for (k = 0; k < n; k++) {
        double t = 0.0;

        descend(out, node_at(out, k % out->nx, k / out->nx), &out->seg[k], &out->v[k], &t);
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

/* qc__sdf_exact that also gives the nearest edge (*edge) and whether the
 * nearest point is inside it (*flat: the distance is to a line there). */
static double exact_full(const qc__sdf *s, qc_vec2 p, qc_vec2 *grad, uint32_t *edge, int *flat)
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

    return exact_full(s, p, grad, &e, &flat);
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

/* ---- marching squares ---- */

void qc__rings_free(qc_ctx *ctx, qc__rings *r)
{
    if (r == NULL)
        return;
    qc_points_free(ctx, &r->pts);
    qc_order_free(ctx, &r->end);
    qc_order_free(ctx, &r->level);
}

/* Levels strictly below v: L_k = l0 + k step < v, decided by the same
 * comparison as cell_links (inv = 1 / step only guesses). */
static uint32_t band(double v, double l0, double step, double inv, size_t max_levels)
{
    double c;
    size_t k;

    if (!(v > l0))
        return 0;
    c = (v - l0) * inv;
    k = c < (double)max_levels ? (size_t)c : max_levels;
    while (k < max_levels && l0 + (double)k * step < v)
        k++;
    while (k > 0 && !(l0 + (double)(k - 1) * step < v))
        k--;
    return (uint32_t)k;
}

typedef struct ms {
    const qc__sdf *s;
    size_t hcount;   /* horizontal grid edges: (nx - 1) * ny */
    /* one level's contour pieces: from grid edge from[i] to grid edge to[i] */
    uint32_t *from, *to;
    size_t nlinks, links_cap;
    /* open-addressing hash from a grid edge to the link leaving it */
    uint32_t *slot;  /* link + 1, or 0 */
    uint32_t *at;    /* per link: its slot */
    size_t hsize;    /* power of two >= 2 links_cap */
    qc_points tmp;   /* the ring being traced */
    uint32_t *feat;  /* per traced vertex: its nearest edge when a line's, else NONE */
    size_t feat_cap;
    double tol;      /* exact-level tolerance, mm */
    double chord;    /* chord tolerance, mm */
} ms;

/* Grid edge k of cell (i, j): 0 bottom, 1 right, 2 top, 3 left. */
static uint32_t cell_edge(const ms *m, size_t i, size_t j, int k)
{
    size_t nx = m->s->nx;

    switch (k) {
    case 0: return (uint32_t)(j * (nx - 1) + i);
    case 1: return (uint32_t)(m->hcount + j * nx + i + 1);
    case 2: return (uint32_t)((j + 1) * (nx - 1) + i);
    default: return (uint32_t)(m->hcount + j * nx + i);
    }
}

/* The level crossing on grid edge e: exact by interpolation when both
 * nodes are nearest to one line, else a linear guess then Newton on the
 * exact distance along the edge (bisection keeps it bracketed). *feat
 * receives the line's edge, or NONE. */
static qc_vec2 crossing(const ms *m, uint32_t e, double level, uint32_t *feat)
{
    const qc__sdf *s = m->s;
    size_t a, b;
    double t, lo = 0.0, hi = 1.0, va, vb;
    qc_vec2 pa, dir, p, g;
    uint32_t fe = NONE;
    int it, flat = 0;

    if (e < m->hcount) {
        size_t j = e / (s->nx - 1), i = e % (s->nx - 1);
        a = j * s->nx + i;
        b = a + 1;
        dir.x = s->h;
        dir.y = 0.0;
    } else {
        a = e - m->hcount;
        b = a + s->nx;
        dir.x = 0.0;
        dir.y = s->h;
    }
    pa.x = s->x0 + (double)(a % s->nx) * s->h;
    pa.y = s->y0 + (double)(a / s->nx) * s->h;
    va = s->v[a];
    vb = s->v[b];
    t = (level - va) / (vb - va);
    t = t > 0.0 ? (t < 1.0 ? t : 1.0) : 0.0;
    if (s->seg[a] == s->seg[b] && s->flat[a] && s->flat[b]) {
        p.x = pa.x + t * dir.x;
        p.y = pa.y + t * dir.y;
        *feat = s->seg[a];
        return p;
    }
    for (it = 0; it < 40; it++) {
        double v, dv;

        p.x = pa.x + t * dir.x;
        p.y = pa.y + t * dir.y;
        v = exact_full(s, p, &g, &fe, &flat) - level;
        if (fabs(v) <= m->tol)
            break;
        if ((v > 0.0) == (vb > va))
            hi = t;
        else
            lo = t;
        dv = g.x * dir.x + g.y * dir.y;
        t = dv != 0.0 ? t - v / dv : -1.0;
        if (!(t > lo && t < hi))
            t = 0.5 * (lo + hi);
    }
    p.x = pa.x + t * dir.x;
    p.y = pa.y + t * dir.y;
    *feat = flat ? fe : NONE;
    return p;
}

static void link(ms *m, uint32_t from, uint32_t to)
{
    m->from[m->nlinks] = from;
    m->to[m->nlinks++] = to;
}

static size_t hash_of(const ms *m, uint32_t key)
{
    return (size_t)((key * 2654435761u) & (uint32_t)(m->hsize - 1));
}

/* The link leaving grid edge key, or NONE. */
static uint32_t find_link(const ms *m, uint32_t key)
{
    size_t h = hash_of(m, key);

    while (m->slot[h] != 0) {
        if (m->from[m->slot[h] - 1] == key)
            return m->slot[h] - 1;
        h = (h + 1) & (m->hsize - 1);
    }
    return NONE;
}

static void index_links(ms *m)
{
    size_t i;

    for (i = 0; i < m->nlinks; i++) {
        size_t h = hash_of(m, m->from[i]);
        while (m->slot[h] != 0)
            h = (h + 1) & (m->hsize - 1);
        m->slot[h] = (uint32_t)i + 1;
        m->at[i] = (uint32_t)h;
    }
}

/* Links the contour pieces of cell (i, j) at level (corners above or not),
 * each with the higher corners on its left. */
static void cell_links(ms *m, size_t i, size_t j, double level)
{
    const qc__sdf *s = m->s;
    size_t k0 = j * s->nx + i;
    double v[4];
    int up[4], nin = 0, nout = 0, c;
    int entry[2], exit_[2];

    v[0] = s->v[k0];
    v[1] = s->v[k0 + 1];
    v[2] = s->v[k0 + s->nx + 1];
    v[3] = s->v[k0 + s->nx];
    for (c = 0; c < 4; c++)
        up[c] = v[c] > level;
    for (c = 0; c < 4; c++) {
        if (up[c] && !up[(c + 1) & 3])
            entry[nin++] = c;
        if (!up[c] && up[(c + 1) & 3])
            exit_[nout++] = c;
    }
    if (nin == 1) {
        link(m, cell_edge(m, i, j, entry[0]), cell_edge(m, i, j, exit_[0]));
    } else if (nin == 2) { /* saddle: decided by the cell's mean */
        int centre = (v[0] + v[1] + v[2] + v[3]) * 0.25 > level;
        if (up[0]) { /* c0, c2 above: entries 0, 2; exits 1, 3 */
            link(m, cell_edge(m, i, j, 0), cell_edge(m, i, j, centre ? 1 : 3));
            link(m, cell_edge(m, i, j, 2), cell_edge(m, i, j, centre ? 3 : 1));
        } else { /* c1, c3 above: entries 1, 3; exits 0, 2 */
            link(m, cell_edge(m, i, j, 3), cell_edge(m, i, j, centre ? 0 : 2));
            link(m, cell_edge(m, i, j, 1), cell_edge(m, i, j, centre ? 2 : 0));
        }
    }
}

/* The point where the line mid + t n crosses the level, |t| <= reach:
 * bracketed from t = 0 outward, then regula falsi (Illinois) with
 * bisection; 0 if no crossing is bracketed. */
static int level_on_line(const qc__sdf *s, qc_vec2 mid, qc_vec2 n, double level, double reach,
                         double tol, qc_vec2 *out)
{
    qc_vec2 g, q;
    double f0 = qc__sdf_exact(s, mid, &g) - level, dir, lo = 0.0, flo = f0, hi, fhi = f0, t, ft;
    int it, side = 0, way;

    /* towards the level along the gradient first, then the other way */
    dir = ((g.x * n.x + g.y * n.y) >= 0.0) == (f0 > 0.0) ? -1.0 : 1.0;
    for (way = 0; way < 2; way++, dir = -dir) {
        lo = 0.0;
        flo = f0;
        for (hi = fmax(fabs(f0), 1e-3 * reach);; hi *= 2.0) {
            if (hi > reach)
                hi = reach;
            q.x = mid.x + dir * hi * n.x;
            q.y = mid.y + dir * hi * n.y;
            fhi = qc__sdf_exact(s, q, NULL) - level;
            if ((fhi > 0.0) != (f0 > 0.0) || hi >= reach)
                break;
            lo = hi;
            flo = fhi;
        }
        if ((fhi > 0.0) != (f0 > 0.0))
            break;
    }
    if ((fhi > 0.0) == (f0 > 0.0))
        return 0;
    ft = fhi;
    for (it = 0; it < 100 && !(fabs(ft) <= tol); it++) {
        t = flo != fhi ? hi - fhi * (hi - lo) / (fhi - flo) : 0.5 * (lo + hi);
        if (!(t > fmin(lo, hi) && t < fmax(lo, hi)) || it % 8 == 7)
            t = 0.5 * (lo + hi);
        q.x = mid.x + dir * t * n.x;
        q.y = mid.y + dir * t * n.y;
        ft = qc__sdf_exact(s, q, NULL) - level;
        if ((ft > 0.0) == (flo > 0.0)) {
            lo = t;
            flo = ft;
            if (side == -1)
                fhi *= 0.5;
            side = -1;
        } else {
            hi = t;
            fhi = ft;
            if (side == 1)
                flo *= 0.5;
            side = 1;
        }
    }
    if (!(fabs(ft) <= tol))
        return 0;
    *out = q;
    return 1;
}

/* Appends the chord a-b's interior points: where the chord strays from the
 * level, the level's crossing of its perpendicular bisector, recursively. */
static int split_chord(qc_ctx *ctx, const ms *m, qc_vec2 a, qc_vec2 b, double level,
                       int depth, qc_points *out)
{
    qc_vec2 mid, n, q;
    double len = qc_hypot(b.x - a.x, b.y - a.y), v;

    if (depth >= SPLIT_DEPTH || len <= 4.0 * m->chord)
        return QC_OK;
    mid.x = 0.5 * (a.x + b.x);
    mid.y = 0.5 * (a.y + b.y);
    v = qc__sdf_exact(m->s, mid, NULL);
    if (fabs(v - level) <= m->chord)
        return QC_OK;
    n.x = -(b.y - a.y) / len;
    n.y = (b.x - a.x) / len;
    if (!level_on_line(m->s, mid, n, level, 4.0 * len, m->tol, &q))
        return QC_OK;
    QC__TRY(split_chord(ctx, m, a, q, level, depth + 1, out));
    QC__TRY(qc_points_push(ctx, out, q));
    return split_chord(ctx, m, q, b, level, depth + 1, out);
}

/* Emits the traced ring in m->tmp: duplicates dropped, chords split
 * unless both ends lie at the level of one line (then so does the chord). */
static int emit_ring(qc_ctx *ctx, ms *m, double level, uint32_t lv, qc__rings *out)
{
    qc_vec2 *t = m->tmp.v;
    uint32_t *f = m->feat;
    double eps = 1e-9 * m->s->h;
    size_t n = 0, i, begin = out->pts.n;

    for (i = 0; i < m->tmp.n; i++) /* compact near-duplicates */
        if (n == 0 || fabs(t[i].x - t[n - 1].x) + fabs(t[i].y - t[n - 1].y) > eps) {
            t[n] = t[i];
            f[n++] = f[i];
        }
    while (n > 1 && fabs(t[0].x - t[n - 1].x) + fabs(t[0].y - t[n - 1].y) <= eps)
        n--;
    if (n < 3)
        return QC_OK;
    for (i = 0; i < n; i++) {
        size_t k = (i + 1) % n;

        QC__TRY(qc_points_push(ctx, &out->pts, t[i]));
        if (f[i] == NONE || f[i] != f[k])
            QC__TRY(split_chord(ctx, m, t[i], t[k], level, 0, &out->pts));
    }
    if (out->pts.n - begin < 3) {
        out->pts.n = begin;
        return QC_OK;
    }
    QC__TRY(qc_order_push(ctx, &out->end, (uint32_t)out->pts.n));
    return qc_order_push(ctx, &out->level, lv);
}

/* Counts (fill == 0) or stores the cells crossed by each level; bands[q]:
 * the number of levels below node q. */
static void bucket(const qc__sdf *s, const uint32_t *bands, size_t *count, size_t *cells,
                   int fill)
{
    size_t i, j, nx = s->nx;

    for (j = 0; j + 1 < s->ny; j++) {
        const uint32_t *r0 = bands + j * nx, *r1 = r0 + nx;

        for (i = 0; i + 1 < nx; i++) {
            uint32_t lo = r0[i], hi = r0[i], b;

            lo = r0[i + 1] < lo ? r0[i + 1] : lo;
            hi = r0[i + 1] > hi ? r0[i + 1] : hi;
            lo = r1[i] < lo ? r1[i] : lo;
            hi = r1[i] > hi ? r1[i] : hi;
            lo = r1[i + 1] < lo ? r1[i + 1] : lo;
            hi = r1[i + 1] > hi ? r1[i + 1] : hi;
            for (b = lo; b < hi; b++) {
                if (fill)
                    cells[count[b]++] = j * nx + i;
                else
                    count[b + 1]++;
            }
        }
    }
}

static size_t ring_begin(const qc__rings *r, size_t k)
{
    return k ? r->end.i[k - 1] : 0;
}

static double ring_area(const qc__rings *r, size_t k, qc_bbox *box)
{
    size_t b = ring_begin(r, k), e = r->end.i[k], i, j = e - 1;
    double a = 0.0;

    box->min = box->max = r->pts.v[b];
    for (i = b; i < e; j = i++) {
        const qc_vec2 *p = r->pts.v;
        a += p[j].x * p[i].y - p[i].x * p[j].y;
        box->min.x = fmin(box->min.x, p[i].x);
        box->min.y = fmin(box->min.y, p[i].y);
        box->max.x = fmax(box->max.x, p[i].x);
        box->max.y = fmax(box->max.y, p[i].y);
    }
    return 0.5 * fabs(a);
}

static int boxes_meet(qc_bbox a, qc_bbox b)
{
    return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y;
}

static int seg_cross(qc_vec2 a, qc_vec2 b, qc_vec2 c, qc_vec2 d)
{
    double o1 = qc_orient2d(a, b, c), o2 = qc_orient2d(a, b, d);
    double o3 = qc_orient2d(c, d, a), o4 = qc_orient2d(c, d, b);

    return ((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0));
}

/* Whether small ring k properly crosses ring q. */
static int rings_cross(const qc__rings *r, size_t k, size_t q, qc_bbox kbox)
{
    const qc_vec2 *p = r->pts.v;
    size_t kb = ring_begin(r, k), ke = r->end.i[k], qb = ring_begin(r, q), qe = r->end.i[q];
    size_t i, j, pi, pj;

    for (j = qb, pj = qe - 1; j < qe; pj = j++) {
        qc_bbox sb;
        sb.min.x = fmin(p[pj].x, p[j].x);
        sb.min.y = fmin(p[pj].y, p[j].y);
        sb.max.x = fmax(p[pj].x, p[j].x);
        sb.max.y = fmax(p[pj].y, p[j].y);
        if (!boxes_meet(sb, kbox))
            continue;
        for (i = kb, pi = ke - 1; i < ke; pi = i++)
            if (seg_cross(p[pi], p[i], p[pj], p[j]))
                return 1;
    }
    return 0;
}

/* Whether ring k crosses itself. */
static int ring_self_cross(const qc__rings *r, size_t k)
{
    const qc_vec2 *p = r->pts.v + ring_begin(r, k);
    size_t n = r->end.i[k] - ring_begin(r, k), i, j;

    for (i = 0; i < n; i++)
        for (j = i + 2; j < n; j++)
            if (!(i == 0 && j == n - 1) &&
                seg_cross(p[i], p[i + 1], p[j], p[(j + 1) % n]))
                return 1;
    return 0;
}

/* Drops the small rings (area under 4 h^2) from ring first on that cross a
 * larger ring of their level: marching squares loses a sharp tip's thin
 * wedge between grid nodes and keeps its end as an island, and once every
 * vertex sits on the exact level the island crosses the body. The wedge
 * beyond is narrower than the grid. Self-crossing small rings (both sides
 * of such a wedge on the same lines) go too. */
static void prune_islands(qc__rings *r, size_t first, double h)
{
    size_t k, q, kept = first, w;

    w = ring_begin(r, first);
    for (k = first; k < r->end.n; k++) {
        qc_bbox kbox, qbox;
        double ka = ring_area(r, k, &kbox);
        size_t b = ring_begin(r, k), e = r->end.i[k], i;
        int drop = ka < 4.0 * h * h && ring_self_cross(r, k);

        for (q = first; q < r->end.n && ka < 4.0 * h * h && !drop; q++) {
            double qa;
            if (q == k || r->level.i[q] != r->level.i[k])
                continue;
            qa = ring_area(r, q, &qbox);
            if ((qa > ka || (qa == ka && q < k)) && boxes_meet(kbox, qbox))
                drop = rings_cross(r, k, q, kbox);
        }
        if (drop)
            continue;
        for (i = b; i < e; i++) /* compact in place */
            r->pts.v[w++] = r->pts.v[i];
        r->end.i[kept] = (uint32_t)w;
        r->level.i[kept++] = r->level.i[k];
    }
    r->end.n = r->level.n = kept;
    r->pts.n = w;
}

/* The level's vertices from b0 on joined by succ (indices relative to
 * b0): finds the pairs of segments (a, succ[a]), (c, succ[c]) that cross
 * properly, binned in a grid of about cell mm, and for each pair whose
 * ends no earlier pair touched, exchanges succ[a] and succ[c] (mark[]
 * bit 0: touched in this pass, bit 1: ever). *found counts the crossings
 * seen. */
static int uncross_pass(qc_ctx *ctx, const qc_vec2 *p, uint32_t *succ, size_t n, double cell,
                        unsigned char *mark, size_t *found)
{
    size_t k, i, gx, gy, ncell, total = 0;
    size_t *start = NULL;
    uint32_t *seg = NULL;
    qc_bbox box;
    int rc = QC_ENOMEM;

    *found = 0;
    box.min = box.max = p[0];
    for (i = 1; i < n; i++) {
        box.min.x = p[i].x < box.min.x ? p[i].x : box.min.x;
        box.min.y = p[i].y < box.min.y ? p[i].y : box.min.y;
        box.max.x = p[i].x > box.max.x ? p[i].x : box.max.x;
        box.max.y = p[i].y > box.max.y ? p[i].y : box.max.y;
    }
    while (((box.max.x - box.min.x) / cell + 1.0) * ((box.max.y - box.min.y) / cell + 1.0) >
           2.0 * (double)n + 64.0)
        cell *= 1.5;
    gx = (size_t)((box.max.x - box.min.x) / cell) + 1;
    gy = (size_t)((box.max.y - box.min.y) / cell) + 1;
    ncell = gx * gy;
    start = qc__alloc_array(ctx, ncell + 1, sizeof *start);
    if (start == NULL)
        return QC_ENOMEM;
    memset(start, 0, (ncell + 1) * sizeof *start);
    for (k = 0; k < 2; k++) { /* pass 0 counts, pass 1 fills */
        for (i = 0; i < n; i++) {
            qc_vec2 a = p[i], c = p[succ[i]];
            size_t x0 = (size_t)(((a.x < c.x ? a.x : c.x) - box.min.x) / cell);
            size_t x1 = (size_t)(((a.x > c.x ? a.x : c.x) - box.min.x) / cell);
            size_t y0 = (size_t)(((a.y < c.y ? a.y : c.y) - box.min.y) / cell);
            size_t y1 = (size_t)(((a.y > c.y ? a.y : c.y) - box.min.y) / cell);
            size_t x, y;

            x1 = x1 < gx ? x1 : gx - 1;
            y1 = y1 < gy ? y1 : gy - 1;
            for (y = y0; y <= y1; y++)
                for (x = x0; x <= x1; x++) {
                    if (k == 0)
                        start[y * gx + x + 1]++;
                    else
                        seg[start[y * gx + x]++] = (uint32_t)i;
                }
        }
        if (k == 0) {
            for (i = 0; i < ncell; i++)
                start[i + 1] += start[i];
            total = start[ncell];
            seg = qc__alloc_array(ctx, total ? total : 1, sizeof *seg);
            if (seg == NULL)
                goto out;
        } else {
            for (i = ncell; i > 0; i--)
                start[i] = start[i - 1];
            start[0] = 0;
        }
    }
    for (i = 0; i < n; i++)
        mark[i] &= 2; /* keep "ever swapped" */
    for (i = 0; i < ncell; i++) /* every pair in a cell */
        for (k = start[i]; k < start[i + 1]; k++) {
            size_t q;
            for (q = k + 1; q < start[i + 1]; q++) {
                uint32_t a = seg[k], c = seg[q], an = succ[a], cn = succ[c];
                if (c == an || a == cn || a == c || !seg_cross(p[a], p[an], p[c], p[cn]))
                    continue;
                ++*found;
                if ((mark[a] | mark[an] | mark[c] | mark[cn]) & 1)
                    continue;
                mark[a] = mark[an] = mark[c] = mark[cn] = 3;
                succ[a] = cn; /* a -> cn and c -> an: uncrossed, directions kept */
                succ[c] = an;
            }
        }
    rc = QC_OK;
out:
    qc__free(ctx, start, (ncell + 1) * sizeof *start);
    qc__free(ctx, seg, seg != NULL ? (total ? total : 1) * sizeof *seg : 0);
    return rc;
}

/* Where a level set is thinner than the grid (a neck near a saddle, a
 * ridge just above the level) marching squares cannot tell its sides
 * apart, and once the vertices sit on the exact level its rings may cross.
 * Each crossing of segments a -> a', c -> c' is undone by joining a -> c'
 * and c -> a' instead, which cuts a self-crossing ring into two or merges
 * two rings into one, keeping every vertex and direction (the neck, being
 * thinner than the grid, is cut or closed). Rings from `first` on. */
static int untangle(qc_ctx *ctx, qc__rings *r, size_t first, double h)
{
    size_t b0, n, k, i, pass, found = 1, w;
    uint32_t *succ = NULL, lv;
    unsigned char *mark = NULL;
    qc_vec2 *tmp = NULL;
    int rc = QC_ENOMEM;

    if (first >= r->end.n)
        return QC_OK;
    b0 = ring_begin(r, first);
    n = r->pts.n - b0;
    lv = r->level.i[first];
    succ = qc__alloc_array(ctx, n, sizeof *succ);
    mark = qc__alloc(ctx, n);
    if (succ == NULL || mark == NULL)
        goto out;
    for (k = first; k < r->end.n; k++) {
        size_t b = ring_begin(r, k) - b0, e = r->end.i[k] - b0;
        for (i = b; i < e; i++)
            succ[i] = (uint32_t)(i + 1 < e ? i + 1 : b);
    }
    memset(mark, 0, n);
    for (pass = 0; pass < 32 && found > 0; pass++) {
        rc = uncross_pass(ctx, r->pts.v + b0, succ, n, 2.0 * h, mark, &found);
        if (rc < 0)
            goto out;
    }
    rc = QC_ENOMEM;
    if (pass == 1) { /* nothing crossed */
        rc = QC_OK;
        goto out;
    }
    tmp = qc__alloc_array(ctx, n, sizeof *tmp);
    if (tmp == NULL)
        goto out;
    r->end.n = r->level.n = first;
    for (i = 0, w = 0; i < n; i++) { /* the cycles, in order of their first vertex */
        size_t c = i, w0 = w, q;
        int swapped = 0;
        double area = 0.0;

        if (mark[i] & 4)
            continue;
        do {
            mark[c] |= 4;
            swapped |= mark[c] & 2;
            tmp[w++] = r->pts.v[b0 + c];
            c = succ[c];
        } while (!(mark[c] & 4));
        for (q = w0; q < w; q++) {
            qc_vec2 u = tmp[q], v = tmp[q + 1 < w ? q + 1 : w0];
            area += u.x * v.y - v.x * u.y;
        }
        /* a sliver cut off a neck thinner than the grid goes */
        if (w - w0 < 3 || (swapped && fabs(0.5 * area) < h * h)) {
            w = w0;
            continue;
        }
        if (qc_order_push(ctx, &r->end, (uint32_t)(b0 + w)) < 0 ||
            qc_order_push(ctx, &r->level, lv) < 0)
            goto out;
    }
    memcpy(r->pts.v + b0, tmp, w * sizeof *tmp);
    r->pts.n = b0 + w;
    rc = QC_OK;
out:
    qc__free(ctx, succ, n * sizeof *succ);
    qc__free(ctx, mark, n);
    qc__free(ctx, tmp, n * sizeof *tmp);
    return rc;
}

/* Traces one level's links (indexed) into rings. */
static int trace_level(qc_ctx *ctx, ms *m, double level, uint32_t lv, unsigned char *done,
                       qc__rings *out)
{
    size_t t;
    int rc = QC_OK;

    memset(done, 0, m->nlinks);
    for (t = 0; t < m->nlinks && rc == QC_OK; t++) {
        uint32_t e0 = m->from[t], c = e0, l = (uint32_t)t;

        if (done[t])
            continue;
        m->tmp.n = 0;
        do {
            uint32_t fe = NONE;
            qc_vec2 q = crossing(m, c, level, &fe);

            done[l] = 1;
            rc = qc_points_push(ctx, &m->tmp, q);
            if (rc == QC_OK)
                rc = QC__RESERVE(ctx, m->feat, m->feat_cap, m->tmp.n);
            if (rc == QC_OK)
                m->feat[m->tmp.n - 1] = fe;
            c = m->to[l];
            l = c == e0 ? NONE : find_link(m, c);
        } while (rc == QC_OK && l != NONE && !done[l]);
        if (rc == QC_OK)
            rc = emit_ring(ctx, m, level, lv, out);
    }
    for (t = 0; t < m->nlinks; t++)
        m->slot[m->at[t]] = 0;
    return rc;
}

int qc__sdf_rings(qc_ctx *ctx, const qc__sdf *s, double l0, double step, size_t max_levels,
                  qc__rings *out)
{
    size_t first = out->end.n;
    ms m;
    size_t k, total = 0, lv, most = 0;
    size_t *count = NULL, *cells = NULL, nnode = s->nx * s->ny;
    uint32_t *bands = NULL;
    unsigned char *done = NULL;
    int rc = QC_ENOMEM;

    memset(&m, 0, sizeof m);
    m.s = s;
    m.hcount = (s->nx - 1) * s->ny;
    m.tol = 1e-9 * (fabs(l0) + step + s->h);
    m.chord = CHORD_TOL * step;
    count = qc__alloc_array(ctx, max_levels + 1, sizeof *count);
    bands = qc__alloc_array(ctx, nnode, sizeof *bands);
    if (count == NULL || bands == NULL)
        goto out;
    for (k = 0; k < nnode; k++)
        bands[k] = band(s->v[k], l0, step, 1.0 / step, max_levels);
    memset(count, 0, (max_levels + 1) * sizeof *count);
    bucket(s, bands, count, NULL, 0);
    for (lv = 0; lv < max_levels; lv++) {
        most = count[lv + 1] > most ? count[lv + 1] : most;
        count[lv + 1] += count[lv];
    }
    total = count[max_levels];
    cells = qc__alloc_array(ctx, total ? total : 1, sizeof *cells);
    m.links_cap = 2 * most + 2;
    for (m.hsize = 4; m.hsize < 2 * m.links_cap; m.hsize *= 2)
        ;
    m.from = qc__alloc_array(ctx, m.links_cap, sizeof *m.from);
    m.to = qc__alloc_array(ctx, m.links_cap, sizeof *m.to);
    m.at = qc__alloc_array(ctx, m.links_cap, sizeof *m.at);
    m.slot = qc__alloc_array(ctx, m.hsize, sizeof *m.slot);
    done = qc__alloc(ctx, m.links_cap);
    if (cells == NULL || m.from == NULL || m.to == NULL || m.at == NULL || m.slot == NULL ||
        done == NULL)
        goto out;
    memset(m.slot, 0, m.hsize * sizeof *m.slot);
    bucket(s, bands, count, cells, 1); /* count[lv] now ends level lv */
    rc = QC_OK;
    for (lv = 0; lv < max_levels && rc == QC_OK; lv++) {
        size_t b = lv ? count[lv - 1] : 0, e = count[lv], t;
        double level = l0 + (double)lv * step;

        m.nlinks = 0;
        for (t = b; t < e; t++)
            cell_links(&m, cells[t] % s->nx, cells[t] / s->nx, level);
        index_links(&m);
        {
            size_t lv_first = out->end.n;
            rc = trace_level(ctx, &m, level, (uint32_t)lv, done, out);
            if (rc == QC_OK)
                rc = untangle(ctx, out, lv_first, s->h);
        }
    }
out:
    qc__free(ctx, count, (max_levels + 1) * sizeof *count);
    qc__free(ctx, cells, (total ? total : 1) * sizeof *cells);
    qc__free(ctx, bands, nnode * sizeof *bands);
    qc__free(ctx, m.from, m.links_cap * sizeof *m.from);
    qc__free(ctx, m.to, m.links_cap * sizeof *m.to);
    qc__free(ctx, m.at, m.links_cap * sizeof *m.at);
    qc__free(ctx, m.slot, m.hsize * sizeof *m.slot);
    qc__free(ctx, done, m.links_cap);
    qc_points_free(ctx, &m.tmp);
    qc__free(ctx, m.feat, m.feat_cap * sizeof *m.feat);
    if (rc < 0)
        return qc__fail(ctx, rc, "out of memory tracing offset rings");
    prune_islands(out, first, s->h);
    return QC_OK;
}
