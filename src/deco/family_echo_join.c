/*
 * Joining offset rings into one continuous path.
 *
 * Candidate steps are cast along each ring's normal, both ways, to the
 * first ring they meet, so a step crosses no ring. Taken shortest first
 * (Kruskal over the rings) they become links of a spanning tree:
 * - a ladder: both rings are opened over a short cut and the cut ends
 *   joined by two parallel steps; the walk goes out along one step, round
 *   the other ring (and, depth first, everything linked to it) and back
 *   along the other step, so ring directions alternate (back and forth);
 * - a spur, for rings too small to cut: one step sewn out and back;
 * - a tail (spiral mode, laid before the others): from just short of where
 *   the walk entered a ring, one step on to the next ring; the walk never
 *   comes back, so a chain of tails is a spiral.
 * A link is only taken if its steps cross no ring and no earlier step and
 * its cuts keep clear of the cuts already on both rings, so the path never
 * crosses itself. Whatever stays unlinked is reached by a straight jump.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "deco_internal.h"

#define NONE UINT32_MAX

enum { L_LADDER, L_SPUR, L_TAIL };

typedef struct lrec {
    uint32_t ra, rb;      /* the rings it joins */
    unsigned char kind;
} lrec;

typedef struct cand {
    double len;
    uint32_t ga, gb; /* ray origin and the vertex it reached */
} cand;

typedef struct joiner {
    const qc__rings *r;
    const qc__join_opts *o;
    const qc_vec2 *p;
    size_t n;             /* vertices */
    size_t nr;            /* rings */
    uint32_t *ring;       /* per vertex: its ring */
    uint32_t *nxt, *prv;  /* per vertex: the next and previous vertex round its ring */
    qc__seg_grid grid;    /* a segment is named by its first vertex */
    /* links */
    uint32_t *used;       /* per vertex: 1 + the link whose cut (or its margin) holds it, or 0 */
    uint32_t *lk;         /* per cut end: its link, or NONE */
    uint32_t *partner;    /* per cut end: the paired vertex on the other ring */
    uint32_t *other;      /* per cut end: the cut's other end on its ring (itself: spur) */
    signed char *ahead;   /* per cut end: +1 when the cut lies forward of it */
    lrec *links;
    size_t nlinks, links_cap;
    uint32_t *uf;         /* union-find over rings */
    qc_vec2 *steps;       /* accepted steps, 2 points each */
    size_t nsteps, steps_cap;
    uint32_t *tail_y, *tail_to; /* per ring: where its tail leaves, where it lands */
    int low_ok;           /* last resort: steps may leave the vmin zone */
    int any_side;         /* last resort: level-0 rings cast outward too */
    qc__join_info *info;
} joiner;

static size_t rstart(const joiner *j, uint32_t k)
{
    return k ? j->r->end.i[k - 1] : 0;
}

static size_t rsize(const joiner *j, uint32_t k)
{
    return j->r->end.i[k] - rstart(j, k);
}

/* The casts and the segment grid ask this for every segment they pass:
 * a table, filled once. */
static uint32_t step_v(const joiner *j, uint32_t g, int dir)
{
    return dir > 0 ? j->nxt[g] : j->prv[g];
}

static double cross2(qc_vec2 a, qc_vec2 b)
{
    return a.x * b.y - a.y * b.x;
}

static qc_vec2 sub2(qc_vec2 a, qc_vec2 b)
{
    qc_vec2 r;
    r.x = a.x - b.x;
    r.y = a.y - b.y;
    return r;
}

/* The distance from a to b (not squared). */
static double point_dist(qc_vec2 a, qc_vec2 b)
{
    return qc_hypot(a.x - b.x, a.y - b.y);
}

/* ---- segment grid ---- */

static uint32_t next_vertex(const void *ud, uint32_t g)
{
    return step_v((const joiner *)ud, g, 1);
}

/* First ring segment the ray o + t u (0 < t <= len) meets, skipping the
 * segments at vertex go; returns the hit's nearer vertex or NONE. */
static uint32_t cast(const joiner *j, uint32_t go, qc_vec2 u, double len, double *t_out)
{
    const qc_vec2 *p = j->p;
    qc_vec2 o = p[go], e;
    uint32_t prev = step_v(j, go, -1), best = NONE;
    double bt = len;
    size_t c[4], x, y, q;

    e.x = o.x + u.x * len;
    e.y = o.y + u.y * len;
    qc__seg_grid_cells(&j->grid, o, e, c);
    for (y = c[1]; y <= c[3]; y++)
        for (x = c[0]; x <= c[2]; x++)
            for (q = j->grid.start[y * j->grid.gx + x]; q < j->grid.start[y * j->grid.gx + x + 1]; q++) {
                uint32_t s = j->grid.seg[q], s2;
                qc_vec2 a, ab, ao;
                double den, t, f;

                if (s == go || s == prev)
                    continue;
                s2 = step_v(j, s, 1);
                a = p[s];
                ab = sub2(p[s2], a);
                den = cross2(u, ab);
                if (fabs(den) < 1e-12)
                    continue;
                ao = sub2(a, o);
                t = cross2(ao, ab) / den;
                f = cross2(ao, u) / den;
                if (t <= 1e-9 || t >= bt || f < 0.0 || f > 1.0)
                    continue;
                bt = t;
                best = f < 0.5 ? s : s2;
            }
    *t_out = bt;
    return best;
}

static int proper(qc_vec2 a, qc_vec2 b, qc_vec2 c, qc_vec2 d)
{
    double o1 = qc_orient2d(a, b, c), o2 = qc_orient2d(a, b, d);
    double o3 = qc_orient2d(c, d, a), o4 = qc_orient2d(c, d, b);

    return ((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0));
}

/* Whether step ab crosses a ring or an accepted step, or (unless allowed)
 * leaves the margin zone. */
static int blocked(const joiner *j, qc_vec2 a, qc_vec2 b)
{
    const qc_vec2 *p = j->p;
    size_t c[4], x, y, q;

    if (j->o->sdf != NULL && !j->low_ok) {
        qc_vec2 m;
        int k;
        for (k = 1; k < 4; k++) {
            m.x = a.x + (b.x - a.x) * 0.25 * k;
            m.y = a.y + (b.y - a.y) * 0.25 * k;
            if (qc__sdf_exact(j->o->sdf, m, NULL) < j->o->vmin - 1e-9)
                return 1;
        }
    }
    qc__seg_grid_cells(&j->grid, a, b, c);
    for (y = c[1]; y <= c[3]; y++)
        for (x = c[0]; x <= c[2]; x++)
            for (q = j->grid.start[y * j->grid.gx + x]; q < j->grid.start[y * j->grid.gx + x + 1]; q++) {
                uint32_t s = j->grid.seg[q];
                if (proper(a, b, p[s], p[step_v(j, s, 1)]))
                    return 1;
            }
    for (q = 0; q < j->nsteps; q++)
        if (proper(a, b, j->steps[2 * q], j->steps[2 * q + 1]))
            return 1;
    return 0;
}

/* Whether vertex g is free (or taken only by link except). */
static int is_free(const joiner *j, uint32_t g, uint32_t except)
{
    return j->used[g] == 0 || j->used[g] - 1 == except;
}

/* Marks the arc lo .. hi (forward) and a vertex either side as link's. */
static void mark(joiner *j, uint32_t lo, uint32_t hi, uint32_t link)
{
    uint32_t x, stop = step_v(j, hi, 1);

    for (x = step_v(j, lo, -1);; x = step_v(j, x, 1)) {
        j->used[x] = link + 1;
        if (x == stop)
            break;
    }
}

/* The cut round g: its ends *lo (behind) and *hi (ahead), about half mm of
 * arc each way but at least one vertex and at most an eighth of the ring;
 * 0 when the ring is too small or the cut meets another. */
static int cut_round(const joiner *j, uint32_t g, double half, uint32_t *lo, uint32_t *hi)
{
    const qc_vec2 *p = j->p;
    size_t size = rsize(j, j->ring[g]), most = size / 8, steps;
    double arc;
    uint32_t a = g, b = g, x;

    if (size < 8)
        return 0;
    for (arc = 0.0, steps = 0; (arc < half && steps < most) || steps == 0; steps++) {
        x = step_v(j, a, -1);
        arc += point_dist(p[x], p[a]);
        a = x;
    }
    for (arc = 0.0, steps = 0; (arc < half && steps < most) || steps == 0; steps++) {
        x = step_v(j, b, 1);
        arc += point_dist(p[x], p[b]);
        b = x;
    }
    for (x = step_v(j, a, -1);; x = step_v(j, x, 1)) { /* the cut and a vertex either side */
        if (!is_free(j, x, NONE))
            return 0;
        if (x == step_v(j, b, 1))
            break;
    }
    *lo = a;
    *hi = b;
    return 1;
}

static int add_link(qc_ctx *ctx, joiner *j, uint32_t ra, uint32_t rb, int kind, uint32_t *id)
{
    QC__TRY(QC__RESERVE(ctx, j->links, j->links_cap, j->nlinks + 1));
    j->links[j->nlinks].ra = ra;
    j->links[j->nlinks].rb = rb;
    j->links[j->nlinks].kind = (unsigned char)kind;
    *id = (uint32_t)j->nlinks++;
    return QC_OK;
}

static int add_step(qc_ctx *ctx, joiner *j, qc_vec2 a, qc_vec2 b)
{
    QC__TRY(QC__RESERVE(ctx, j->steps, j->steps_cap, 2 * j->nsteps + 2));
    j->steps[2 * j->nsteps] = a;
    j->steps[2 * j->nsteps + 1] = b;
    j->nsteps++;
    return QC_OK;
}

static void set_end(joiner *j, uint32_t g, uint32_t partner, uint32_t other, int ahead, uint32_t id)
{
    j->partner[g] = partner;
    j->other[g] = other;
    j->ahead[g] = (signed char)ahead;
    j->lk[g] = id;
}

/* A ladder for candidate c: 1 if taken, 0 if not, or an error. */
static int try_ladder(qc_ctx *ctx, joiner *j, const cand *c, double half)
{
    const qc_vec2 *p = j->p;
    uint32_t a1, a2, b1, b2, pa1, pa2, id;
    qc_vec2 dir;
    double s1, s2;

    if (!cut_round(j, c->ga, half, &a1, &a2) || !cut_round(j, c->gb, half, &b1, &b2))
        return 0;
    dir = sub2(p[c->gb], p[c->ga]);
    s1 = cross2(dir, sub2(p[a1], p[c->ga]));
    s2 = cross2(dir, sub2(p[b1], p[c->ga]));
    if ((s1 > 0) == (s2 > 0)) {
        pa1 = b1;
        pa2 = b2;
    } else {
        pa1 = b2;
        pa2 = b1;
    }
    if (proper(p[a1], p[pa1], p[a2], p[pa2]) || blocked(j, p[a1], p[pa1]) ||
        blocked(j, p[a2], p[pa2]))
        return 0;
    QC__TRY(add_link(ctx, j, j->ring[c->ga], j->ring[c->gb], L_LADDER, &id));
    QC__TRY(add_step(ctx, j, p[a1], p[pa1]));
    QC__TRY(add_step(ctx, j, p[a2], p[pa2]));
    mark(j, a1, a2, id);
    mark(j, b1, b2, id);
    set_end(j, a1, pa1, a2, 1, id);
    set_end(j, a2, pa2, a1, -1, id);
    set_end(j, b1, pa1 == b1 ? a1 : a2, b2, 1, id);
    set_end(j, b2, pa2 == b2 ? a2 : a1, b1, -1, id);
    j->info->ladders++;
    return 1;
}

/* A spur for candidate c (one step sewn both ways). */
static int try_spur(qc_ctx *ctx, joiner *j, const cand *c)
{
    const qc_vec2 *p = j->p;
    uint32_t id;

    if (!is_free(j, c->ga, NONE) || !is_free(j, c->gb, NONE) ||
        !is_free(j, step_v(j, c->ga, 1), NONE) || !is_free(j, step_v(j, c->ga, -1), NONE) ||
        !is_free(j, step_v(j, c->gb, 1), NONE) || !is_free(j, step_v(j, c->gb, -1), NONE) ||
        blocked(j, p[c->ga], p[c->gb]))
        return 0;
    QC__TRY(add_link(ctx, j, j->ring[c->ga], j->ring[c->gb], L_SPUR, &id));
    QC__TRY(add_step(ctx, j, p[c->ga], p[c->gb]));
    mark(j, c->ga, c->ga, id);
    mark(j, c->gb, c->gb, id);
    set_end(j, c->ga, c->gb, c->ga, 0, id);
    set_end(j, c->gb, c->ga, c->gb, 0, id);
    j->info->spurs++;
    return 1;
}

static int cmp_cand(const void *pa, const void *pb)
{
    const cand *a = pa, *b = pb;

    if (a->len != b->len)
        return a->len < b->len ? -1 : 1;
    if (a->ga != b->ga)
        return a->ga < b->ga ? -1 : 1;
    return (a->gb > b->gb) - (a->gb < b->gb);
}

/* The unit normal at vertex g to side (+1 left: the higher side). */
static int normal_at(const joiner *j, uint32_t g, int side, qc_vec2 *u)
{
    qc_vec2 t = sub2(j->p[step_v(j, g, 1)], j->p[step_v(j, g, -1)]);
    double l = qc_hypot(t.x, t.y);

    if (!(l > 0.0))
        return 0;
    u->x = -t.y / l * side;
    u->y = t.x / l * side;
    return 1;
}

/* Candidate links, gathered then taken shortest first. */
typedef struct cands {
    cand *v;
    size_t n, cap;
} cands;

static int cands_push(qc_ctx *ctx, cands *c, double len, uint32_t ga, uint32_t gb)
{
    QC__TRY(QC__RESERVE(ctx, c->v, c->cap, c->n + 1));
    c->v[c->n].len = len;
    c->v[c->n].ga = ga;
    c->v[c->n++].gb = gb;
    return QC_OK;
}

/* Tries the candidates shortest first as ladders (spur == 0) or spurs,
 * skipping those whose rings are joined by then; frees them. *linked
 * counts the unions made. */
static int cands_take(qc_ctx *ctx, joiner *j, cands *c, int spur, double half, int rc,
                      size_t *linked)
{
    size_t k;

    if (rc == QC_OK && c->n > 0)
        qsort(c->v, c->n, sizeof *c->v, cmp_cand);
    for (k = 0; k < c->n && rc == QC_OK; k++) {
        uint32_t ra = j->ring[c->v[k].ga], rb = j->ring[c->v[k].gb];

        if (qc__uf_find(j->uf, ra) == qc__uf_find(j->uf, rb))
            continue;
        rc = spur ? try_spur(ctx, j, &c->v[k]) : try_ladder(ctx, j, &c->v[k], half);
        if (rc == 1) {
            qc__uf_union(j->uf, ra, rb);
            ++*linked;
            rc = QC_OK;
        }
    }
    qc__free(ctx, c->v, c->cap * sizeof *c->v);
    return rc;
}

/* Casts candidate links every `every` mm of arc (0: every vertex), from
 * all rings or (only_from != NONE) only from rings outside only_from's
 * tree, and takes them (cands_take). */
static int link_round(qc_ctx *ctx, joiner *j, double every, double reach, double half, int spur,
                      uint32_t only_from, size_t *linked)
{
    const qc_vec2 *p = j->p;
    cands cs = {NULL, 0, 0};
    size_t k, i;
    int rc = QC_OK;

    *linked = 0;
    for (k = 0; k < j->nr && rc == QC_OK; k++) {
        size_t b = rstart(j, (uint32_t)k), e = j->r->end.i[k];
        double acc = every;

        if (only_from != NONE &&
            qc__uf_find(j->uf, (uint32_t)k) == qc__uf_find(j->uf, j->ring[only_from]))
            continue;
        for (i = b; i < e && rc == QC_OK; i++) {
            uint32_t prv = step_v(j, (uint32_t)i, -1);
            int side;

            acc += point_dist(p[i], p[prv]);
            if (acc < every || j->used[i])
                continue;
            acc = 0.0;
            for (side = 1; side >= -1 && rc == QC_OK; side -= 2) {
                double tt;
                uint32_t hit;
                qc_vec2 u;

                if (side < 0 && j->r->level.i[k] == 0 && !j->any_side)
                    continue; /* outside the outermost rings: the margin */
                if (!normal_at(j, (uint32_t)i, side, &u))
                    continue;
                hit = cast(j, (uint32_t)i, u, reach, &tt);
                if (hit == NONE || j->ring[hit] == k ||
                    qc__uf_find(j->uf, j->ring[hit]) == qc__uf_find(j->uf, (uint32_t)k))
                    continue;
                rc = cands_push(ctx, &cs, tt, (uint32_t)i, hit);
            }
        }
    }
    return cands_take(ctx, j, &cs, spur, half, rc, linked);
}

/* ---- spiral: a chain of tails from the start ---- */

/* The vertex about gap mm of arc behind x (at least one vertex back) with
 * the arc free but for link `except`; NONE if taken or the ring is small. */
static uint32_t tail_origin(const joiner *j, uint32_t x, double gap, uint32_t except)
{
    size_t size = rsize(j, j->ring[x]), steps = 0;
    double arc = 0.0;
    uint32_t y = x, z;

    if (size < 8 || !is_free(j, x, except) || !is_free(j, step_v(j, x, 1), except))
        return NONE;
    while (arc < gap || steps == 0) {
        z = step_v(j, y, -1);
        arc += point_dist(j->p[z], j->p[y]);
        y = z;
        if (++steps > size / 4 || !is_free(j, y, except))
            return NONE;
    }
    if (!is_free(j, step_v(j, y, -1), except))
        return NONE;
    return y;
}

/* The vertex about arc mm ahead of x (at least one vertex on). */
static uint32_t advance(const joiner *j, uint32_t x, double arc)
{
    size_t size = rsize(j, j->ring[x]), steps = 0;
    double run = 0.0;

    while (run < arc && ++steps < size) {
        uint32_t z = step_v(j, x, 1);
        run += point_dist(j->p[z], j->p[x]);
        x = z;
    }
    return x;
}

/* A tail from just short of x: the vertex it lands on, or NONE. */
static uint32_t try_tail(joiner *j, uint32_t x, double gap, uint32_t in_link, uint32_t *y_out)
{
    const qc_vec2 *p = j->p;
    uint32_t k = j->ring[x], y = tail_origin(j, x, gap, in_link), hit;
    int side;

    if (y == NONE)
        return NONE;
    for (side = 1; side >= -1; side -= 2) {
        qc_vec2 u;
        double tt;

        if (!normal_at(j, y, side, &u))
            continue;
        hit = cast(j, y, u, j->o->reach, &tt);
        if (hit != NONE && qc__uf_find(j->uf, j->ring[hit]) != qc__uf_find(j->uf, k) &&
            is_free(j, hit, NONE) && is_free(j, step_v(j, hit, 1), NONE) &&
            is_free(j, step_v(j, hit, -1), NONE) && !blocked(j, p[y], p[hit])) {
            *y_out = y;
            return hit;
        }
    }
    return NONE;
}

/* Lays the chain of tails from *start: the first ring may start a little
 * further on (*start moves), later rings leave a longer gap if they must. */
static int lay_tails(qc_ctx *ctx, joiner *j, uint32_t *start)
{
    const qc_vec2 *p = j->p;
    uint32_t x = *start, in_link = NONE;
    double gap = j->o->gap;
    size_t guard;

    for (guard = 0; guard < j->nr; guard++) {
        uint32_t k = j->ring[x], hit = NONE, y = NONE, id, xx = x;
        int a;

        for (a = 0; a < 8 && hit == NONE; a++) {
            xx = in_link == NONE ? advance(j, x, 1.5 * gap * a) : x;
            hit = try_tail(j, xx, in_link == NONE ? gap : gap * (1.0 + 0.5 * a), in_link, &y);
        }
        if (hit == NONE)
            return QC_OK;
        if (in_link == NONE)
            *start = x = xx;
        QC__TRY(add_link(ctx, j, k, j->ring[hit], L_TAIL, &id));
        QC__TRY(add_step(ctx, j, p[y], p[hit]));
        mark(j, y, x, id); /* the gap this ring's walk leaves */
        mark(j, hit, hit, id);
        j->tail_y[k] = y;
        j->tail_to[k] = hit;
        qc__uf_union(j->uf, k, j->ring[hit]);
        j->info->tails++;
        in_link = id;
        x = hit;
    }
    return QC_OK;
}

/* ---- the walk ---- */

typedef struct frame {
    uint32_t cur, stop;
    int dir;
} frame;

/* Walks from g round its ring and, depth first, everything linked to it. */
static int walk(qc_ctx *ctx, joiner *j, uint32_t g, qc_points *out, frame *stack, int tails)
{
    const qc_vec2 *p = j->p;
    size_t top = 0;
    uint32_t k = j->ring[g];

    QC__TRY(qc_points_push(ctx, out, p[g]));
    stack[top].cur = g;
    stack[top].stop = tails && j->tail_y[k] != NONE ? j->tail_y[k] : g;
    stack[top++].dir = 1;
    while (top > 0) {
        frame *f = &stack[top - 1];
        uint32_t u = step_v(j, f->cur, f->dir), id;

        QC__TRY(qc_points_push(ctx, out, p[u]));
        if (u == f->stop) {
            top--;
            if (top > 0) { /* back along the second step */
                QC__TRY(qc_points_push(ctx, out, p[stack[top - 1].cur]));
            } else if (tails && j->tail_y[j->ring[u]] == u) { /* on along the tail */
                uint32_t x = j->tail_to[j->ring[u]];
                k = j->ring[x];
                QC__TRY(qc_points_push(ctx, out, p[x]));
                stack[0].cur = x;
                stack[0].stop = j->tail_y[k] != NONE ? j->tail_y[k] : x;
                stack[0].dir = 1;
                top = 1;
            }
            continue;
        }
        f->cur = u;
        id = j->lk[u];
        if (id == NONE || j->links[id].kind == L_TAIL)
            continue;
        if (j->links[id].kind == L_SPUR) { /* out and back, resuming here */
            uint32_t pv = j->partner[u];
            QC__TRY(qc_points_push(ctx, out, p[pv]));
            stack[top].cur = pv;
            stack[top].stop = pv;
            stack[top++].dir = 1;
        } else if (j->ahead[u] == f->dir) { /* a ladder: resume past the cut */
            uint32_t pv = j->partner[u], w = j->other[u];
            f->cur = w;
            QC__TRY(qc_points_push(ctx, out, p[pv]));
            stack[top].cur = pv;
            stack[top].stop = j->partner[w];
            stack[top++].dir = -j->ahead[pv];
        }
    }
    return QC_OK;
}

/* The free vertex nearest to vertex g (g itself if none is free). */
static uint32_t nearest_free(const joiner *j, uint32_t g)
{
    size_t i;
    uint32_t best = g;
    double bd = HUGE_VAL;

    for (i = 0; i < j->n; i++) {
        double d;
        if (j->used[i])
            continue;
        d = (j->p[i].x - j->p[g].x) * (j->p[i].x - j->p[g].x) +
            (j->p[i].y - j->p[g].y) * (j->p[i].y - j->p[g].y);
        if (d < bd) {
            bd = d;
            best = (uint32_t)i;
        }
    }
    return best;
}

static void jn_free(qc_ctx *ctx, joiner *j)
{
    qc__free(ctx, j->ring, j->n * sizeof *j->ring);
    qc__free(ctx, j->nxt, j->n * sizeof *j->nxt);
    qc__free(ctx, j->prv, j->n * sizeof *j->prv);
    qc__free(ctx, j->used, j->n * sizeof *j->used);
    qc__free(ctx, j->lk, j->n * sizeof *j->lk);
    qc__free(ctx, j->partner, j->n * sizeof *j->partner);
    qc__free(ctx, j->other, j->n * sizeof *j->other);
    qc__free(ctx, j->ahead, j->n);
    qc__free(ctx, j->uf, j->nr * sizeof *j->uf);
    qc__free(ctx, j->tail_y, j->nr * sizeof *j->tail_y);
    qc__free(ctx, j->tail_to, j->nr * sizeof *j->tail_to);
    qc__seg_grid_free(ctx, &j->grid);
    qc__free(ctx, j->steps, j->steps_cap * sizeof *j->steps);
    qc__free(ctx, j->links, j->links_cap * sizeof *j->links);
}

/* Spurs from every free vertex outside start's tree to the nearest free
 * vertex of another tree within radius (rings that no normal reaches,
 * such as slivers at sharp tips). */
static int near_round(qc_ctx *ctx, joiner *j, double radius, uint32_t start, size_t *linked)
{
    const qc_vec2 *p = j->p;
    uint32_t main_root = qc__uf_find(j->uf, j->ring[start]);
    cands cs = {NULL, 0, 0};
    size_t g;
    int rc = QC_OK;

    *linked = 0;
    for (g = 0; g < j->n && rc == QC_OK; g++) {
        uint32_t rg = qc__uf_find(j->uf, j->ring[g]), best = NONE;
        double bd = radius;
        size_t c[4], x, y, q;
        qc_vec2 lo, hi;

        if (rg == main_root || j->used[g])
            continue;
        lo.x = p[g].x - radius;
        lo.y = p[g].y - radius;
        hi.x = p[g].x + radius;
        hi.y = p[g].y + radius;
        qc__seg_grid_cells(&j->grid, lo, hi, c);
        for (y = c[1]; y <= c[3]; y++)
            for (x = c[0]; x <= c[2]; x++)
                for (q = j->grid.start[y * j->grid.gx + x]; q < j->grid.start[y * j->grid.gx + x + 1]; q++) {
                    uint32_t h = j->grid.seg[q];
                    double dd = point_dist(p[g], p[h]);
                    if (dd < bd && !j->used[h] && qc__uf_find(j->uf, j->ring[h]) != rg) {
                        bd = dd;
                        best = h;
                    }
                }
        if (best != NONE)
            rc = cands_push(ctx, &cs, bd, (uint32_t)g, best);
    }
    return cands_take(ctx, j, &cs, 1, 0.0, rc, linked);
}

/* Ladders, then denser and farther ladders, spurs, and as a last resort
 * steps through the margin and spurs to the nearest vertex, until one tree
 * holds every ring. */
static int link_all(qc_ctx *ctx, joiner *j, uint32_t start)
{
    const qc__join_opts *o = j->o;
    size_t linked = 0, comps = j->nr, k;
    int pass;

    for (k = 0; k < j->nr; k++)
        if (qc__uf_find(j->uf, (uint32_t)k) != k)
            comps--;
    QC__TRY(link_round(ctx, j, 0.4 * o->reach, o->reach, 0.5 * o->gap, 0, NONE, &linked));
    comps -= linked;
    for (pass = 0; pass < 2 && comps > 1; pass++) {
        j->low_ok = j->any_side = pass;
        do { /* stragglers: every vertex, farther, narrower ladders, then spurs */
            QC__TRY(link_round(ctx, j, 0.0, 4.0 * o->reach, 0.25 * o->gap, 0, start, &linked));
            if (linked == 0)
                QC__TRY(link_round(ctx, j, 0.0, 4.0 * o->reach, 0.0, 1, start, &linked));
            if (linked == 0 && pass == 1)
                QC__TRY(near_round(ctx, j, 4.0 * o->reach, start, &linked));
            comps -= linked;
        } while (comps > 1 && linked > 0);
    }
    j->low_ok = j->any_side = 0;
    return QC_OK;
}

int qc__rings_join(qc_ctx *ctx, const qc__rings *r, const qc__join_opts *o, qc_points *out,
                   qc__join_info *info)
{
    joiner j;
    frame *stack = NULL;
    size_t k, g, steps_safe;
    uint32_t start;
    int rc = QC_ENOMEM;

    memset(&j, 0, sizeof j);
    memset(info, 0, sizeof *info);
    if (r->end.n == 0 || r->pts.n == 0)
        return QC_OK;
    j.r = r;
    j.o = o;
    j.p = r->pts.v;
    j.n = r->pts.n;
    j.nr = r->end.n;
    j.info = info;
    j.ring = qc__alloc_array(ctx, j.n, sizeof *j.ring);
    j.nxt = qc__alloc_array(ctx, j.n, sizeof *j.nxt);
    j.prv = qc__alloc_array(ctx, j.n, sizeof *j.prv);
    j.used = qc__alloc_array(ctx, j.n, sizeof *j.used);
    j.lk = qc__alloc_array(ctx, j.n, sizeof *j.lk);
    j.partner = qc__alloc_array(ctx, j.n, sizeof *j.partner);
    j.other = qc__alloc_array(ctx, j.n, sizeof *j.other);
    j.ahead = qc__alloc(ctx, j.n);
    j.uf = qc__alloc_array(ctx, j.nr, sizeof *j.uf);
    j.tail_y = qc__alloc_array(ctx, j.nr, sizeof *j.tail_y);
    j.tail_to = qc__alloc_array(ctx, j.nr, sizeof *j.tail_to);
    stack = qc__alloc_array(ctx, j.nr + 1, sizeof *stack);
    if (j.ring == NULL || j.nxt == NULL || j.prv == NULL || j.used == NULL || j.lk == NULL || j.partner == NULL ||
        j.other == NULL || j.ahead == NULL || j.uf == NULL || j.tail_y == NULL ||
        j.tail_to == NULL || stack == NULL)
        goto out;
    qc__uf_init(j.uf, j.nr);
    for (k = 0, g = 0; k < j.nr; k++) {
        size_t b = g, e = r->end.i[k];

        j.tail_y[k] = j.tail_to[k] = NONE;
        for (; g < e; g++) {
            j.ring[g] = (uint32_t)k;
            j.nxt[g] = (uint32_t)(g + 1 == e ? b : g + 1);
            j.prv[g] = (uint32_t)(g == b ? e - 1 : g - 1);
        }
    }
    memset(j.used, 0, j.n * sizeof *j.used);
    memset(j.ahead, 0, j.n);
    for (g = 0; g < j.n; g++)
        j.partner[g] = j.other[g] = j.lk[g] = NONE;
    rc = qc__seg_grid_build(ctx, &j.grid, j.p, j.n, next_vertex, &j, 0.5 * o->reach, 4.0);
    start = o->start < j.n ? o->start : 0;
    if (rc == QC_OK && o->spiral)
        rc = lay_tails(ctx, &j, &start);
    steps_safe = j.nsteps;
    if (rc == QC_OK)
        rc = link_all(ctx, &j, start);
    if (rc < 0)
        goto out;
    for (k = steps_safe; k < j.nsteps && o->sdf != NULL; k++) { /* steps through the margin */
        qc_vec2 m;
        m.x = 0.5 * (j.steps[2 * k].x + j.steps[2 * k + 1].x);
        m.y = 0.5 * (j.steps[2 * k].y + j.steps[2 * k + 1].y);
        if (qc__sdf_exact(o->sdf, m, NULL) < o->vmin - 1e-9)
            info->low++;
    }
    if (j.tail_y[j.ring[start]] == NONE && j.used[start]) /* start outside every cut */
        start = nearest_free(&j, start);
    rc = walk(ctx, &j, start, out, stack, o->spiral);
    /* trees no link reached: jumped to, one after another */
    for (k = 0; k < j.nr && rc == QC_OK; k++) {
        uint32_t root = qc__uf_find(j.uf, (uint32_t)k);
        if (root == qc__uf_find(j.uf, j.ring[start]) || root != k)
            continue;
        for (g = rstart(&j, (uint32_t)k); g + 1 < r->end.i[k] && j.used[g]; g++)
            ;
        info->jumps++;
        rc = walk(ctx, &j, (uint32_t)g, out, stack, 0);
    }
out:
    jn_free(ctx, &j);
    qc__free(ctx, stack, (j.nr + 1) * sizeof *stack);
    return rc;
}
