/*
 * Iso-contours of the distance field (shared_sdf.c) by marching squares, all
 * levels in one pass. Contour vertices are moved onto the exact level
 * (Newton along the grid edge) and chords that stray from it are split, so
 * every vertex lies at its level to about 1e-9 mm and every chord within
 * 0.2% of the level spacing. Offsetting this way handles concave outlines,
 * holes and rings that split or vanish without special cases; where a
 * level is thinner than the grid, shared_ring_repair.c mends what marching
 * squares cannot tell apart.
 */
#include <math.h>
#include <stddef.h>
#include <string.h>

#include "deco_internal.h"

#define NONE UINT32_MAX
/* A chord may stray from its level by this fraction of the level step. */
#define CHORD_TOL 0.002
#define SPLIT_DEPTH 12
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
        v = qc__sdf_exact_full(s, p, &g, &fe, &flat) - level;
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
                rc = qc__rings_untangle(ctx, out, lv_first, s->h);
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
    qc__rings_prune_islands(out, first, s->h);
    return QC_OK;
}
