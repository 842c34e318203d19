/*
 * Trimming an overgrown closed path to its region (paper §5.3.1, Fig. 11
 * middle): each stretch outside is replaced by the boundary between where
 * it leaves and where it comes back, so the result stays one piece.
 * Crossings are decided by exact orientation tests with every zero taken
 * as negative (a consistent perturbation), so the inside/outside state
 * flips exactly when the path changes side.
 */
#include <math.h>
#include <string.h>

#include "pebble_internal.h"

typedef struct trim {
    qc_ctx *ctx;
    qc__pbound *b;
    qc_path *out;
    qc_vec2 ref;
    double nudge;      /* points on the boundary are drawn this far inside */
    int inside;        /* where the path is now */
    int started;       /* out has this path's first point */
    int head_open;     /* started outside and not yet in */
    qc__pcross exit_at, first_at;
    qc_points stretch; /* the current stretch outside, from its exit */
    qc_points head;    /* the stretch before the first entry */
    qc_points cand[2]; /* the two ways round the ring */
    qc__pcross *cr;
    size_t cr_cap;
    size_t jumps;
} trim;

static int emit(trim *T, qc_vec2 p)
{
    if (!T->started) {
        T->started = 1;
        if (T->out->ncmd == 0)
            return qc_path_move_to(T->ctx, T->out, p);
    }
    return qc_path_line_to(T->ctx, T->out, p);
}

/* The crossing x moved a hair inside, off its edge: where two stretches of
 * the path both follow the boundary they then only touch. The region lies
 * left of every edge (outer rings counter-clockwise, holes clockwise). */
static qc_vec2 inside_of(const trim *T, const qc__pcross *x)
{
    const qc_region *r = T->b->region;
    uint32_t lo, hi, e = x->edge;
    qc_vec2 a, b, p = x->at;
    double len;

    qc__pbound_ring(r, e, &lo, &hi);
    a = r->v[e];
    b = r->v[e + 1 < hi ? e + 1 : lo];
    len = qc_hypot(b.x - a.x, b.y - a.y);
    if (len > 0) {
        p.x -= T->nudge * (b.y - a.y) / len;
        p.y += T->nudge * (b.x - a.x) / len;
    }
    return p;
}

/* Winding number of the closed polyline a (then b reversed) round q. */
static int winding(const qc_points *a, const qc_points *b, qc_vec2 q)
{
    size_t na = a->n, nb = b->n, n = na + nb, i;
    int w = 0;

    for (i = 0; i < n; i++) {
        size_t j = i + 1 < n ? i + 1 : 0;
        qc_vec2 p0 = i < na ? a->v[i] : b->v[nb - 1 - (i - na)];
        qc_vec2 p1 = j < na ? a->v[j] : b->v[nb - 1 - (j - na)];
        double o = (p1.x - p0.x) * (q.y - p0.y) - (p1.y - p0.y) * (q.x - p0.x);
        if (p0.y <= q.y && q.y < p1.y && o > 0)
            w++;
        else if (p1.y <= q.y && q.y < p0.y && o < 0)
            w--;
    }
    return w;
}

static double poly_len(const qc_points *p)
{
    double l = 0;
    size_t i;

    for (i = 1; i < p->n; i++)
        l += qc_hypot(p->v[i].x - p->v[i - 1].x, p->v[i].y - p->v[i - 1].y);
    return l;
}

/* Position of x along edge e (0 at its first vertex). */
static double along(const qc_region *r, uint32_t e, uint32_t nxt, qc_vec2 x)
{
    qc_vec2 a = r->v[e], b = r->v[nxt];
    double ex = b.x - a.x, ey = b.y - a.y, l2 = ex * ex + ey * ey;

    return l2 > 0 ? ((x.x - a.x) * ex + (x.y - a.y) * ey) / l2 : 0;
}

/* The boundary from exit x1 to entry x2, both ways round their ring. */
static int ring_ways(trim *T, const qc__pcross *x1, const qc__pcross *x2)
{
    const qc_region *r = T->b->region;
    uint32_t lo, hi, e1 = x1->edge, e2 = x2->edge, k;
    double t1, t2;
    int rc = QC_OK;

#define NEXT(v) ((v) + 1 < hi ? (v) + 1 : lo)
#define PREV(v) ((v) > lo ? (v) - 1 : hi - 1)
    qc__pbound_ring(r, e1, &lo, &hi);
    t1 = along(r, e1, NEXT(e1), x1->at);
    t2 = along(r, e2, NEXT(e2), x2->at);
    T->cand[0].n = T->cand[1].n = 0;
    rc = qc_points_push(T->ctx, &T->cand[0], x1->at);
    if (rc == QC_OK)
        rc = qc_points_push(T->ctx, &T->cand[1], x1->at);
    if (rc == QC_OK && !(e1 == e2 && t2 >= t1)) { /* forward */
        for (k = NEXT(e1);; k = NEXT(k)) {
            rc = qc_points_push(T->ctx, &T->cand[0], r->v[k]);
            if (rc != QC_OK || k == e2)
                break;
        }
    }
    if (rc == QC_OK && !(e1 == e2 && t2 <= t1)) { /* backward */
        for (k = e1;; k = PREV(k)) {
            rc = qc_points_push(T->ctx, &T->cand[1], r->v[k]);
            if (rc != QC_OK || k == NEXT(e2))
                break;
        }
    }
#undef NEXT
#undef PREV
    if (rc == QC_OK)
        rc = qc_points_push(T->ctx, &T->cand[0], x2->at);
    if (rc == QC_OK)
        rc = qc_points_push(T->ctx, &T->cand[1], x2->at);
    return rc;
}

/* Replaces the stretch outside (T->stretch, from x1 to x2) by the boundary. */
static int join(trim *T, const qc__pcross *x1, const qc__pcross *x2)
{
    const qc_region *r = T->b->region;
    uint32_t lo1, hi1, lo2, hi2;
    const qc_points *pick;
    size_t i;
    int w0, w1;

    if (qc__pbound_ring(r, x1->edge, &lo1, &hi1) != qc__pbound_ring(r, x2->edge, &lo2, &hi2)) {
        T->jumps++; /* out by one ring, in by another: no boundary joins them */
        return emit(T, inside_of(T, x2));
    }
    QC__TRY(ring_ways(T, x1, x2));
    w0 = winding(&T->stretch, &T->cand[0], T->ref);
    w1 = winding(&T->stretch, &T->cand[1], T->ref);
    if ((w0 == 0) != (w1 == 0))
        pick = w0 == 0 ? &T->cand[0] : &T->cand[1];
    else
        pick = poly_len(&T->cand[0]) <= poly_len(&T->cand[1]) ? &T->cand[0] : &T->cand[1];
    for (i = 1; i + 1 < pick->n; i++)
        QC__TRY(emit(T, pick->v[i]));
    return emit(T, inside_of(T, x2));
}

/* The straight piece a -> b. */
static int segment(trim *T, qc_vec2 a, qc_vec2 b)
{
    size_t ncr = 0, i;

    if (a.x == b.x && a.y == b.y)
        return QC_OK;
    QC__TRY(qc__pbound_cross_list(T->ctx, T->b, a, b, &T->cr, &T->cr_cap, &ncr));
    for (i = 0; i < ncr; i++) {
        const qc__pcross *x = &T->cr[i];
        if (T->inside) { /* leaving */
            QC__TRY(emit(T, inside_of(T, x)));
            T->exit_at = *x;
            T->stretch.n = 0;
            QC__TRY(qc_points_push(T->ctx, &T->stretch, x->at));
        } else if (T->head_open) { /* in for the first time */
            QC__TRY(qc_points_push(T->ctx, &T->head, x->at));
            T->head_open = 0;
            T->first_at = *x;
            QC__TRY(emit(T, inside_of(T, x)));
        } else {
            QC__TRY(qc_points_push(T->ctx, &T->stretch, x->at));
            QC__TRY(join(T, &T->exit_at, x));
        }
        T->inside = !T->inside;
    }
    if (T->inside)
        return emit(T, b);
    return qc_points_push(T->ctx, T->head_open ? &T->head : &T->stretch, b);
}

/* Whether the cubic's control points lie in a disk clear of the boundary. */
static int cubic_clear(trim *T, const qc_vec2 *q)
{
    qc_vec2 m;
    double rad = 0;
    int i;

    m.x = (q[0].x + q[1].x + q[2].x + q[3].x) / 4;
    m.y = (q[0].y + q[1].y + q[2].y + q[3].y) / 4;
    for (i = 0; i < 4; i++)
        rad = fmax(rad, qc_hypot(q[i].x - m.x, q[i].y - m.y));
    rad = rad * (1 + 1e-9) + 1e-9;
    return qc__pbound_dist(T->b, m, 2 * rad) > rad;
}

static int run(trim *T, const qc_path *in, double tol, qc_path *one, qc_points *flat)
{
    size_t i, k = 0;
    qc_vec2 cur, start;

    if (in->ncmd == 0)
        return qc__fail(T->ctx, QC_EEMPTY, "nothing to trim");
    start = cur = in->pt[0];
    T->inside = qc_region_contains(T->b->region, start);
    T->head_open = !T->inside;
    if (T->inside)
        QC__TRY(emit(T, start));
    else
        QC__TRY(qc_points_push(T->ctx, &T->head, start));
    k = qc_path_cmd_points(in->cmd[0]);
    for (i = 1; i < in->ncmd; i++) {
        const qc_vec2 *p = in->pt + k;
        k += qc_path_cmd_points(in->cmd[i]);
        if (in->cmd[i] != QC_PATH_CUBIC) {
            QC__TRY(segment(T, cur, p[0]));
            cur = p[0];
            continue;
        }
        {
            qc_vec2 q[4];
            size_t j;
            q[0] = cur;
            q[1] = p[0];
            q[2] = p[1];
            q[3] = p[2];
            if (T->inside && T->started && cubic_clear(T, q)) {
                QC__TRY(qc_path_cubic_to(T->ctx, T->out, q[1], q[2], q[3]));
                cur = q[3];
                continue;
            }
            one->ncmd = one->npt = 0;
            flat->n = 0;
            QC__TRY(qc_path_move_to(T->ctx, one, q[0]));
            QC__TRY(qc_path_cubic_to(T->ctx, one, q[1], q[2], q[3]));
            QC__TRY(qc_curve_flatten(T->ctx, one, tol, flat, NULL));
            for (j = 1; j < flat->n; j++) {
                QC__TRY(segment(T, cur, flat->v[j]));
                cur = flat->v[j];
            }
            QC__TRY(segment(T, cur, q[3]));
            cur = q[3];
        }
    }
    QC__TRY(segment(T, cur, start)); /* closed: back to the start */
    if (T->head_open)
        return qc__fail(T->ctx, QC_EEMPTY, "the pattern lies wholly outside the region");
    if (!T->inside) { /* the last stretch runs on into the first */
        for (i = 1; i < T->head.n; i++)
            QC__TRY(qc_points_push(T->ctx, &T->stretch, T->head.v[i]));
        QC__TRY(join(T, &T->exit_at, &T->first_at));
    }
    return QC_OK;
}

/* Where the offset lines of edges a and b meet (their common point when
 * they run on in one line). 0 when they are parallel the other way. */
static int meet(const qc_vec2 *p, const qc_vec2 *e, uint32_t a, uint32_t b, qc_vec2 *at)
{
    double den = e[a].x * e[b].y - e[a].y * e[b].x, t;

    if (fabs(den) < 1e-12) {
        if (e[a].x * e[b].x + e[a].y * e[b].y <= 0)
            return 0;
        *at = p[b];
        return 1;
    }
    t = ((p[b].x - p[a].x) * e[b].y - (p[b].y - p[a].y) * e[b].x) / den;
    at->x = p[a].x + t * e[a].x;
    at->y = p[a].y + t * e[a].y;
    return 1;
}

/*
 * One ring moved delta inwards (left of every edge): each edge's line
 * moved, consecutive lines met; an edge whose moved piece turns round (too
 * short for the move) is dropped and its neighbours met directly, until
 * none does. Into out (cleared first); 0 when the ring vanishes.
 */
static int ring_inset(qc_ctx *ctx, const qc_vec2 *v, uint32_t m, double delta, qc_points *out,
                      int *ok)
{
    qc_vec2 *p = qc__alloc_array(ctx, m, sizeof *p), *e = qc__alloc_array(ctx, m, sizeof *e);
    uint32_t *prv = qc__alloc_array(ctx, m, sizeof *prv), *nxt = qc__alloc_array(ctx, m, sizeof *nxt);
    uint32_t *todo = qc__alloc_array(ctx, 2 * (size_t)m, sizeof *todo);
    unsigned char *gone = qc__alloc(ctx, m);
    uint32_t i, n = 0, first = 0, live = m;
    size_t nt = 0;
    int rc = QC_OK;

    *ok = 0;
    out->n = 0;
    if (p == NULL || e == NULL || prv == NULL || nxt == NULL || todo == NULL || gone == NULL) {
        rc = QC_ENOMEM;
        goto out;
    }
    for (i = 0; i < m; i++) { /* unit directions; repeated vertices give no edge */
        qc_vec2 a = v[i], b = v[(i + 1) % m];
        double l = qc_hypot(b.x - a.x, b.y - a.y);
        gone[i] = !(l > 0);
        if (l > 0) {
            e[i].x = (b.x - a.x) / l;
            e[i].y = (b.y - a.y) / l;
            p[i].x = a.x - delta * e[i].y;
            p[i].y = a.y + delta * e[i].x;
            n++;
        }
    }
    if (n < 3)
        goto out;
    live = n;
    { /* link the edges left */
        uint32_t last = m;
        for (i = 0; i < m; i++)
            if (!gone[i]) {
                if (last == m)
                    first = i;
                else
                    nxt[last] = i;
                prv[i] = last;
                last = i;
            }
        nxt[last] = first;
        prv[first] = last;
    }
    for (i = 0; i < m; i++)
        if (!gone[i])
            todo[nt++] = i;
    while (nt > 0 && live >= 3) {
        uint32_t k = todo[--nt];
        qc_vec2 s0, s1;
        if (gone[k])
            continue;
        if (!meet(p, e, prv[k], k, &s0) || !meet(p, e, k, nxt[k], &s1))
            goto out; /* doubles back on itself */
        if ((s1.x - s0.x) * e[k].x + (s1.y - s0.y) * e[k].y > 0)
            continue;
        gone[k] = 1; /* turned round: drop it, look at its neighbours again */
        live--;
        nxt[prv[k]] = nxt[k];
        prv[nxt[k]] = prv[k];
        if (k == first)
            first = nxt[k];
        todo[nt++] = prv[k];
        todo[nt++] = nxt[k];
    }
    if (live < 3)
        goto out;
    i = first;
    do {
        qc_vec2 s0;
        if (!meet(p, e, prv[i], i, &s0))
            goto out;
        rc = qc_points_push(ctx, out, s0);
        i = nxt[i];
    } while (rc == QC_OK && i != first);
    *ok = rc == QC_OK;
out:
    qc__free(ctx, p, m * sizeof *p);
    qc__free(ctx, e, m * sizeof *e);
    qc__free(ctx, prv, m * sizeof *prv);
    qc__free(ctx, nxt, m * sizeof *nxt);
    qc__free(ctx, todo, 2 * (size_t)m * sizeof *todo);
    qc__free(ctx, gone, m);
    return rc;
}

/* The region with every edge moved delta inwards, or an error when that
 * changes its shape (a ring vanishing or turning, edges crossing). */
static int region_inset(qc_ctx *ctx, const qc_region *r, double delta, qc_region *out)
{
    qc_points ring = {0};
    size_t k;
    int rc = QC_OK;

    memset(out, 0, sizeof *out);
    for (k = 0; k < r->nrings && rc == QC_OK; k++) {
        uint32_t lo = k ? r->ring_end[k - 1] : 0, hi = r->ring_end[k], m = hi - lo, i;
        double a0 = 0, a1 = 0;
        int ok;
        rc = ring_inset(ctx, r->v + lo, m, delta, &ring, &ok);
        if (rc != QC_OK)
            break;
        for (i = 0; i < m; i++) { /* keeps its turn; the signed area falls (holes grow) */
            qc_vec2 v = r->v[lo + i], w = r->v[lo + (i + 1) % m];
            a0 += v.x * w.y - v.y * w.x;
        }
        for (i = 0; i < ring.n; i++) {
            qc_vec2 v = ring.v[i], w = ring.v[(i + 1) % ring.n];
            a1 += v.x * w.y - v.y * w.x;
        }
        if (!ok || ring.n < 3 || (a0 > 0) != (a1 > 0) || a1 >= a0)
            rc = qc__fail(ctx, QC_EDEGENERATE, "ring %lu vanishes when inset by %g mm",
                          (unsigned long)k, delta);
        else
            rc = qc_region_add_ring(ctx, out, ring.v, ring.n);
    }
    qc_points_free(ctx, &ring);
    if (rc == QC_OK)
        rc = qc_region_normalize(ctx, out);
    if (rc != QC_OK)
        qc_region_free(ctx, out);
    return rc;
}

int qc__path_trim(qc_ctx *ctx, const qc_region *region, double cell, size_t max_cells,
                  double inset, const qc_path *in, qc_vec2 ref, double tol, qc_path *out,
                  size_t *jumps)
{
    trim T;
    qc_region ins;
    qc__pbound b;
    qc_path one = {0};
    qc_points flat = {0};
    const qc_region *use = region;
    int rc = inset > 0 ? region_inset(ctx, region, inset, &ins) : QC_EDEGENERATE;

    if (rc == QC_ENOMEM)
        return rc;
    if (rc == QC_OK)
        use = &ins;
    else if (inset > 0)
        qc_clear_error(ctx); /* too fine to inset: the region itself */
    rc = qc__pbound_init(ctx, &b, use, cell, max_cells);
    if (rc != QC_OK) {
        if (use == &ins)
            qc_region_free(ctx, &ins);
        return rc;
    }
    memset(&T, 0, sizeof T);
    T.ctx = ctx;
    T.b = &b;
    T.out = out;
    T.ref = ref;
    T.nudge = 1e-4 * tol;
    rc = run(&T, in, tol, &one, &flat);
    if (jumps != NULL)
        *jumps += T.jumps;
    qc_path_free(ctx, &one);
    qc_points_free(ctx, &flat);
    qc_points_free(ctx, &T.stretch);
    qc_points_free(ctx, &T.head);
    qc_points_free(ctx, &T.cand[0]);
    qc_points_free(ctx, &T.cand[1]);
    qc__free(ctx, T.cr, T.cr_cap * sizeof *T.cr);
    qc__pbound_free(ctx, &b);
    if (use == &ins)
        qc_region_free(ctx, &ins);
    return rc;
}
