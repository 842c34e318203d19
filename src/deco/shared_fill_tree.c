/*
 * Fixed-width fill outlines (paper §7.1): the tree walked down and back each
 * branch with the path kept w/2 to the walker's side, so it outlines the
 * tree as one loop. Half-edges are sorted counter-clockwise round each
 * node; the right-hand walk takes, at every node, the next edge
 * counter-clockwise after the one it came in by. Consecutive offset lines
 * meet at their mitre where the outline turns inward (the wedge between
 * two branches), by a round join where it turns outward, and round a
 * semicircle (or a tip circle) at the leaves.
 */
#include <math.h>
#include <string.h>

#include "deco_internal.h"

/* ---- building ---- */

uint32_t qc__ftree_rep(const qc__ftree *t, uint32_t v)
{
    while (t->rep[v] != v)
        v = t->rep[v];
    return v;
}

typedef struct slot {
    uint32_t tgt, eid;
} slot;

/* Whether the direction v->a comes strictly before v->b counter-clockwise from +x. */
static int before(const qc_vec2 *p, uint32_t v, uint32_t a, uint32_t b)
{
    double ay = p[a].y - p[v].y, by = p[b].y - p[v].y;
    int ha = ay < 0.0 || (ay == 0.0 && p[a].x < p[v].x);
    int hb = by < 0.0 || (by == 0.0 && p[b].x < p[v].x);
    double o;

    if (ha != hb)
        return ha < hb;
    o = qc_orient2d(p[v], p[a], p[b]);
    if (o != 0.0)
        return o > 0.0;
    return a < b;
}

static void sort_slots(const qc_vec2 *p, uint32_t v, slot *s, size_t n, slot *tmp)
{
    size_t w, i;

    if (n < 12) { /* insertion sort: the common case (MST degrees are at most 6) */
        for (i = 1; i < n; i++) {
            slot x = s[i];
            size_t j = i;
            while (j > 0 && before(p, v, x.tgt, s[j - 1].tgt)) {
                s[j] = s[j - 1];
                j--;
            }
            s[j] = x;
        }
        return;
    }
    for (w = 1; w < n; w *= 2) { /* bottom-up merge sort */
        for (i = 0; i < n; i += 2 * w) {
            size_t m = i + w < n ? i + w : n, e = i + 2 * w < n ? i + 2 * w : n;
            size_t a = i, b = m, k = i;
            while (a < m && b < e)
                tmp[k++] = before(p, v, s[b].tgt, s[a].tgt) ? s[b++] : s[a++];
            while (a < m)
                tmp[k++] = s[a++];
            while (b < e)
                tmp[k++] = s[b++];
        }
        memcpy(s, tmp, n * sizeof *s);
    }
}

void qc__ftree_free(qc_ctx *ctx, qc__ftree *t)
{
    if (t == NULL)
        return;
    qc__free(ctx, t->off, (t->n + 1) * sizeof *t->off);
    qc__free(ctx, t->rep, t->n * sizeof *t->rep);
    /* allocated with at least one element (qc__ftree_build) */
    qc__free(ctx, t->src, (t->nh ? t->nh : 1) * sizeof *t->src);
    qc__free(ctx, t->tgt, (t->nh ? t->nh : 1) * sizeof *t->tgt);
    qc__free(ctx, t->twin, (t->nh ? t->nh : 1) * sizeof *t->twin);
    memset(t, 0, sizeof *t);
}

int qc__ftree_build(qc_ctx *ctx, const qc_vec2 *p, size_t n, const qc_edge *e, size_t ne,
                    qc__ftree *t)
{
    slot *sl = NULL, *tmp = NULL;
    uint32_t *side = NULL;
    size_t i, nh = 0, maxdeg = 0;
    int rc = QC_ENOMEM;

    memset(t, 0, sizeof *t);
    t->p = p;
    t->n = n;
    for (i = 0; i < ne; i++)
        if (e[i].a >= n || e[i].b >= n)
            return qc__fail(ctx, QC_EINVAL, "fill: edge %lu (%lu, %lu) beyond %lu points",
                            (unsigned long)i, (unsigned long)e[i].a, (unsigned long)e[i].b,
                            (unsigned long)n);
    t->off = qc__alloc_array(ctx, n + 1, sizeof *t->off);
    t->rep = qc__alloc_array(ctx, n ? n : 1, sizeof *t->rep);
    if (t->off == NULL || t->rep == NULL)
        goto fail;
    qc__uf_init(t->rep, n);
    for (i = 0; i < ne; i++) /* duplicates: one node */
        if (p[e[i].a].x == p[e[i].b].x && p[e[i].a].y == p[e[i].b].y)
            qc__uf_union(t->rep, e[i].a, e[i].b);
    for (i = 0; i < n; i++)
        t->rep[i] = qc__uf_find(t->rep, (uint32_t)i);
    memset(t->off, 0, (n + 1) * sizeof *t->off);
    for (i = 0; i < ne; i++) {
        uint32_t a = t->rep[e[i].a], b = t->rep[e[i].b];
        if (a != b) {
            t->off[a + 1]++;
            t->off[b + 1]++;
            nh += 2;
        }
    }
    for (i = 0; i < n; i++) {
        if (t->off[i + 1] > maxdeg)
            maxdeg = t->off[i + 1];
        t->off[i + 1] += t->off[i];
    }
    t->nh = nh;
    t->src = qc__alloc_array(ctx, nh ? nh : 1, sizeof *t->src);
    t->tgt = qc__alloc_array(ctx, nh ? nh : 1, sizeof *t->tgt);
    t->twin = qc__alloc_array(ctx, nh ? nh : 1, sizeof *t->twin);
    sl = qc__alloc_array(ctx, nh ? nh : 1, sizeof *sl);
    tmp = qc__alloc_array(ctx, maxdeg ? maxdeg : 1, sizeof *tmp);
    side = qc__alloc_array(ctx, ne ? 2 * ne : 1, sizeof *side);
    if (t->src == NULL || t->tgt == NULL || t->twin == NULL || sl == NULL || tmp == NULL ||
        side == NULL)
        goto fail;
    {
        size_t k;
        for (k = 0; k < nh; k++) /* fill cursor: src doubles as a per-node counter */
            t->src[k] = 0;
        for (i = 0; i < ne; i++) {
            uint32_t a = t->rep[e[i].a], b = t->rep[e[i].b];
            if (a == b)
                continue;
            sl[t->off[a] + t->src[t->off[a]]].tgt = b;
            sl[t->off[a] + t->src[t->off[a]]++].eid = (uint32_t)(2 * i);
            sl[t->off[b] + t->src[t->off[b]]].tgt = a;
            sl[t->off[b] + t->src[t->off[b]]++].eid = (uint32_t)(2 * i + 1);
        }
    }
    for (i = 0; i < n; i++) {
        size_t b = t->off[i], d = t->off[i + 1] - b, k;
        sort_slots(p, (uint32_t)i, sl + b, d, tmp);
        for (k = b; k < b + d; k++) {
            t->src[k] = (uint32_t)i;
            t->tgt[k] = sl[k].tgt;
            side[sl[k].eid] = (uint32_t)k;
        }
    }
    for (i = 0; i < nh; i++)
        t->twin[i] = side[sl[i].eid ^ 1u];
    rc = QC_OK;
fail:
    qc__free(ctx, sl, (nh ? nh : 1) * sizeof *sl);
    qc__free(ctx, tmp, (maxdeg ? maxdeg : 1) * sizeof *tmp);
    qc__free(ctx, side, (ne ? 2 * ne : 1) * sizeof *side);
    if (rc < 0) {
        qc__ftree_free(ctx, t);
        return qc__fail(ctx, QC_ENOMEM, "fill: out of memory for a %lu-point tree",
                        (unsigned long)n);
    }
    return QC_OK;
}

/* ---- walking ---- */

/* A turn whose sine is below this is no turn. */
#define STRAIGHT 1e-9

/* The half-edge after h turning by sense (+1 right-hand, -1 left-hand). */
static uint32_t next_he(const qc__ftree *t, uint32_t h, int sense)
{
    uint32_t v = t->tgt[h], b = t->off[v], d = t->off[v + 1] - b;
    uint32_t k = t->twin[h] - b;

    return b + (uint32_t)((k + d + (uint32_t)(sense > 0 ? 1 : d - 1)) % d);
}

static qc_vec2 dir_of(const qc__ftree *t, uint32_t h)
{
    qc_vec2 a = t->p[t->src[h]], b = t->p[t->tgt[h]], r;
    double l = qc_hypot(b.x - a.x, b.y - a.y);

    r.x = (b.x - a.x) / l;
    r.y = (b.y - a.y) / l;
    return r;
}

static qc_vec2 add(qc_vec2 a, qc_vec2 b, double s)
{
    a.x += b.x * s;
    a.y += b.y * s;
    return a;
}

/* The side normal: right of travel for sense +1, left for -1. */
static qc_vec2 side_normal(qc_vec2 d, int sense)
{
    qc_vec2 n;
    n.x = d.y * sense;
    n.y = -d.x * sense;
    return n;
}

/* Points of the arc round c of radius r from unit a to unit b turning by
 * sense (+1 counter-clockwise), a full turn when a == b; first and last included. */
static int arc(qc_ctx *ctx, qc_points *out, qc_vec2 c, double r, qc_vec2 a, qc_vec2 b,
               int sense, double step)
{
    double ang = qc_atan2(sense * (a.x * b.y - a.y * b.x), a.x * b.x + a.y * b.y);
    double cs, sn;
    size_t k, m;
    qc_vec2 u = a;

    if (ang <= 1e-12)
        ang += 2.0 * QC_PI;
    m = (size_t)ceil(ang / step);
    m = m < 1 ? 1 : m;
    cs = qc_cos(ang / (double)m);
    sn = sense * qc_sin(ang / (double)m);
    for (k = 0; k < m; k++) {
        qc_vec2 w;
        QC__TRY(qc_points_push(ctx, out, add(c, u, r)));
        w.x = u.x * cs - u.y * sn;
        w.y = u.x * sn + u.y * cs;
        u = w;
    }
    return qc_points_push(ctx, out, add(c, b, r));
}

/* Which part of a join to emit. */
enum { J_ALL, J_FIRST, J_LAST };

/*
 * The join at v = tgt[h] from h's offset line to h2's (sense side): a cap
 * when h2 turns straight back, a mitre where the outline turns inward, a
 * round join where it turns outward. J_FIRST: only the end of h's line;
 * J_LAST: only the start of h2's line.
 */
static int join(qc_ctx *ctx, const qc__ftree *t, uint32_t h, uint32_t h2, int sense,
                const qc__fstyle *st, int part, qc_points *out)
{
    uint32_t v = t->tgt[h];
    qc_vec2 c = t->p[v], d1 = dir_of(t, h), d2 = dir_of(t, h2);
    qc_vec2 n1 = side_normal(d1, sense), n2 = side_normal(d2, sense);
    double cr = d1.x * d2.y - d1.y * d2.x, dt = d1.x * d2.x + d1.y * d2.y;
    double hw = st->half;

    if (h2 == t->twin[h]) { /* leaf: round the tip */
        double R = st->tip_at != NULL ? st->tip_at[v] : st->tip;
        qc_vec2 a, b;

        if (R > hw * 1.0001) {
            qc_vec2 src = t->p[t->src[h]];
            double len = qc_hypot(c.x - src.x, c.y - src.y), s;

            R = fmin(R, qc_hypot(0.5 * len, hw));
            s = sqrt(R * R - hw * hw);
            a = add(n1, d1, -s / hw); /* (n1 hw - d1 s) / R */
            a.x *= hw / R;
            a.y *= hw / R;
            b = add(n2, d1, -s / hw);
            b.x *= hw / R;
            b.y *= hw / R;
        } else {
            R = hw;
            a = n1;
            b = n2;
        }
        if (part == J_FIRST)
            return qc_points_push(ctx, out, add(c, a, R));
        if (part == J_LAST)
            return qc_points_push(ctx, out, add(c, b, R));
        return arc(ctx, out, c, R, a, b, sense, st->arc_step);
    }
    /* inward: the mitre; so too a turn too slight to round (collinear
     * points, as a row along a straight seam: the arc would take a
     * rounding error's turn for a full circle) */
    if (sense * cr < 0.0 || (fabs(cr) <= STRAIGHT && dt > 0.0)) {
        double k = 1.0 + (n1.x * n2.x + n1.y * n2.y);
        qc_vec2 m;

        k = k < 0.25 ? 0.25 : k; /* at most twice w/2 out: no spikes */
        m.x = c.x + (n1.x + n2.x) * hw / k;
        m.y = c.y + (n1.y + n2.y) * hw / k;
        return qc_points_push(ctx, out, m);
    }
    if (part == J_FIRST)
        return qc_points_push(ctx, out, add(c, n1, hw));
    if (part == J_LAST)
        return qc_points_push(ctx, out, add(c, n2, hw));
    return arc(ctx, out, c, hw, n1, n2, sense, st->arc_step);
}

int qc__ftree_loop(qc_ctx *ctx, const qc__ftree *t, uint32_t root, const qc__fstyle *st,
                   qc_points *out)
{
    uint32_t h0, hp, h, d;
    size_t guard;

    root = qc__ftree_rep(t, root);
    d = t->off[root + 1] - t->off[root];
    if (d == 0) { /* a lone point: a circle */
        qc_vec2 a = {1.0, 0.0};
        double R = st->tip > st->half ? st->tip : st->half;
        size_t before_n = out->n;
        QC__TRY(arc(ctx, out, t->p[root], R, a, a, 1, st->arc_step));
        out->n = before_n + (out->n - before_n) - 1; /* the loop closes itself */
        return QC_OK;
    }
    h0 = t->off[root];
    hp = t->twin[t->off[root] + d - 1];
    QC__TRY(join(ctx, t, hp, h0, 1, st, J_ALL, out));
    h = h0;
    for (guard = 0; guard <= t->nh; guard++) {
        uint32_t h2 = next_he(t, h, 1);
        if (h2 == h0)
            return QC_OK;
        QC__TRY(join(ctx, t, h, h2, 1, st, J_ALL, out));
        h = h2;
    }
    return qc__fail(ctx, QC_EINVAL, "fill: the edges do not form a tree");
}

int qc__ftree_open(qc_ctx *ctx, const qc__ftree *t, uint32_t a, uint32_t b,
                   const qc__fstyle *st, qc_points *out)
{
    uint32_t *via = NULL, *stack = NULL, *spine = NULL;
    size_t top = 0, ns = 0, i, guard;
    int rc = QC_OK;

    a = qc__ftree_rep(t, a);
    b = qc__ftree_rep(t, b);
    via = qc__alloc_array(ctx, t->n, sizeof *via);
    stack = qc__alloc_array(ctx, t->n, sizeof *stack);
    spine = qc__alloc_array(ctx, t->n, sizeof *spine);
    if (via == NULL || stack == NULL || spine == NULL) {
        rc = QC_ENOMEM;
        goto out;
    }
    /* the half-edge each node is reached by from a */
    for (i = 0; i < t->n; i++)
        via[i] = UINT32_MAX;
    stack[top++] = a;
    via[a] = UINT32_MAX - 1;
    while (top > 0) {
        uint32_t v = stack[--top], k;
        for (k = t->off[v]; k < t->off[v + 1]; k++)
            if (via[t->tgt[k]] == UINT32_MAX) {
                via[t->tgt[k]] = k;
                stack[top++] = t->tgt[k];
            }
    }
    if (via[b] == UINT32_MAX || a == b) {
        rc = qc__fail(ctx, QC_EINVAL, "fill: tile ports are not joined by the tree");
        goto out;
    }
    for (i = b; i != a; i = t->src[via[i]]) /* spine half-edges, b back to a */
        spine[ns++] = via[i];
    rc = qc_points_push(ctx, out, t->p[a]);
    for (i = ns; i-- > 1 && rc == QC_OK;) {
        uint32_t hin = spine[i], hout = spine[i - 1], h, h2;

        /* right of the spine: arrive by the diagonal, outline the branches */
        h = hin;
        h2 = next_he(t, h, 1);
        for (guard = 0; rc == QC_OK && guard <= t->nh; guard++) {
            if (h2 == hout) {
                rc = join(ctx, t, h, h2, 1, st, J_FIRST, out);
                break;
            }
            rc = join(ctx, t, h, h2, 1, st, J_ALL, out);
            h = h2;
            h2 = next_he(t, h, 1);
        }
        /* across the node to the left side, outline its branches clockwise */
        if (rc == QC_OK)
            rc = qc_points_push(ctx, out, t->p[t->tgt[hin]]);
        h = hin;
        h2 = next_he(t, h, -1);
        if (rc == QC_OK)
            rc = join(ctx, t, h, h2, -1, st, J_LAST, out);
        for (guard = 0; rc == QC_OK && h2 != hout && guard <= t->nh; guard++) {
            h = h2;
            h2 = next_he(t, h, -1);
            rc = join(ctx, t, h, h2, -1, st, J_ALL, out);
        }
    }
    if (rc == QC_OK)
        rc = qc_points_push(ctx, out, t->p[b]);
out:
    qc__free(ctx, via, t->n * sizeof *via);
    qc__free(ctx, stack, t->n * sizeof *stack);
    qc__free(ctx, spine, t->n * sizeof *spine);
    return rc;
}
