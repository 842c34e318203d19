/*
 * Or-3opt: the sequential 3-opt moves reachable over the neighbour lists
 * (t1 t2 removed, t2 joined to a candidate t3, t3 t4 removed, t4 joined to a
 * candidate t5, t5 t6 removed, t6 joined back to t1), each partial sum
 * kept positive so the lists prune the search. These are the segment moves
 * 2-opt and Or-opt miss: a segment of any length moved elsewhere, reversed
 * or not, and two adjacent segments swapped. Each move is applied as two or
 * three 2-opt moves (qc__tsp_move2), so the undo log sees only reversals.
 */
#include <string.h>

#include "tour_internal.h"

enum { KIND_2OPT, KIND_SWAP, KIND_BOTH_REVERSED, KIND_TWO_2OPT };

typedef struct move3 {
    uint32_t t1, t2, t3, t4, t5, t6;
    int kind;
    double gain; /* change of length, negative */
} move3;

/* The point after a walking in direction dir (0: along the array, 1: back). */
static inline uint32_t succ(qc__view v, uint32_t a, int dir)
{
    return dir ? qc__vprev(v, a) : qc__vnext(v, a);
}

static inline uint32_t pred(qc__view v, uint32_t a, int dir)
{
    return dir ? qc__vnext(v, a) : qc__vprev(v, a);
}

/* Steps from a to x walking in direction dir. */
static inline uint32_t steps(qc__view v, uint32_t a, uint32_t x, int dir)
{
    uint32_t pa = v.pos[a], px = v.pos[x];

    if (dir)
        return pa >= px ? pa - px : pa + v.m - px;
    return px >= pa ? px - pa : px + v.m - pa;
}

/* Whether x lies on the path from a to b (both included) walking in dir. */
static inline int on_path(qc__view v, uint32_t a, uint32_t b, uint32_t x, int dir)
{
    return steps(v, a, x, dir) <= steps(v, a, b, dir);
}

static void offer(move3 *bm, double gain, int kind, const uint32_t t[7])
{
    if (gain >= bm->gain)
        return;
    bm->gain = gain;
    bm->kind = kind;
    bm->t1 = t[1], bm->t2 = t[2], bm->t3 = t[3];
    bm->t4 = t[4], bm->t5 = t[5], bm->t6 = t[6];
}

/* Whether a move reversing between a and c costs too much (v.far: the
 * tour is long enough for it to). */
static inline int too_far(const qc__tsp *s, qc__view v, uint32_t a, uint32_t c)
{
    return v.far && qc__tsp_too_far(s, a, c);
}

/* The third exchange: t5 among t4's candidates, t6 beside it. g2 is the
 * gain so far with (t4, t5) not yet added; side 0 when t4 = succ(t3). */
static void close_3opt(const qc__tsp *s, qc__view v, uint32_t t[7], double g2, int side,
                       int dir, move3 *bm)
{
    const uint32_t *nb = s->nb + (size_t)t[4] * s->k;
    const double *nbd = s->nbd + (size_t)t[4] * s->k;
    unsigned j, k = s->k;
    double eps = s->eps;

    for (j = 0; j < k; j++) {
        double g = g2 - nbd[j];
        int h;

        if (g <= eps)
            break;
        t[5] = nb[j];
        if (t[5] == t[1] || (side == 1 && t[5] == t[3]))
            continue;
        if (side == 0) { /* t5 must lie on t2 .. t3: both ways round */
            if (!on_path(v, t[2], t[3], t[5], dir))
                continue;
            for (h = 0; h < 2; h++) {
                if (h == 0 && t[5] == t[3])
                    continue;
                if (h == 1 && t[5] == t[2])
                    continue;
                t[6] = h == 0 ? succ(v, t[5], dir) : pred(v, t[5], dir);
                if (too_far(s, v, t[3], t[6]) || too_far(s, v, t[2], t[5]))
                    continue;
                offer(bm, qc__vdist(v, t[6], t[1]) - g - qc__vdist(v, t[5], t[6]),
                      h == 0 ? KIND_SWAP : KIND_BOTH_REVERSED, t);
            }
        } else { /* t5 on t2 .. t4 takes its successor, beyond t3 its predecessor */
            t[6] = on_path(v, t[2], t[4], t[5], dir) ? succ(v, t[5], dir) : pred(v, t[5], dir);
            if (too_far(s, v, t[4], t[6]))
                continue;
            offer(bm, qc__vdist(v, t[6], t[1]) - g - qc__vdist(v, t[5], t[6]),
                  KIND_TWO_2OPT, t);
        }
    }
}

/* The candidates' distances come from nbd, which Or-3opt always fills. */
static void search(const qc__tsp *s, uint32_t a, int dir, move3 *bm)
{
    qc__view v = qc__view_of(s);
    uint32_t t[7];
    const uint32_t *nb;
    const double *nbd;
    double d12, eps = s->eps;
    unsigned j, k = s->k;
    int side;

    t[0] = 0;
    t[1] = a;
    t[2] = succ(v, a, dir);
    d12 = qc__vdist(v, t[1], t[2]);
    nb = s->nb + (size_t)t[2] * k;
    nbd = s->nbd + (size_t)t[2] * k;
    for (j = 0; j < k; j++) {
        double g1 = d12 - nbd[j];

        if (g1 <= eps)
            break;
        t[3] = nb[j];
        if (t[3] == t[1] || too_far(s, v, t[2], t[3]))
            continue;
        for (side = 0; side < 2; side++) {
            double d34;

            t[4] = side ? pred(v, t[3], dir) : succ(v, t[3], dir);
            if (t[4] == (side ? t[2] : t[1]))
                continue;
            d34 = qc__vdist(v, t[3], t[4]);
            if (side == 1) /* closing (t4, t1) here is a 2-opt move */
                offer(bm, qc__vdist(v, t[4], t[1]) - g1 - d34, KIND_2OPT, t);
            close_3opt(s, v, t, g1 + d34, side, dir, bm);
        }
    }
}

static int apply(qc__tsp *s, const move3 *mv)
{
    switch (mv->kind) {
    case KIND_2OPT:
        return qc__tsp_move2(s, mv->t1, mv->t2, mv->t4, mv->t3);
    case KIND_SWAP: /* t1 [t2..t5][t6..t3] t4 -> t1 [t6..t3][t2..t5] t4 */
        QC__TRY(qc__tsp_move2(s, mv->t1, mv->t2, mv->t3, mv->t4));
        QC__TRY(qc__tsp_move2(s, mv->t1, mv->t3, mv->t6, mv->t5));
        return qc__tsp_move2(s, mv->t3, mv->t5, mv->t2, mv->t4);
    case KIND_BOTH_REVERSED: /* t1 [t2..t6][t5..t3] t4 -> t1 [t6..t2][t3..t5] t4 */
        QC__TRY(qc__tsp_move2(s, mv->t1, mv->t2, mv->t6, mv->t5));
        return qc__tsp_move2(s, mv->t2, mv->t5, mv->t3, mv->t4);
    default: /* a 2-opt move, then one more from the edge it made at t1 */
        QC__TRY(qc__tsp_move2(s, mv->t1, mv->t2, mv->t4, mv->t3));
        return qc__tsp_move2(s, mv->t1, mv->t4, mv->t6, mv->t5);
    }
}

int qc__tsp_try_or3opt(qc__tsp *s, uint32_t a, double *delta, int *rc)
{
    move3 bm;
    int dir;

    memset(&bm, 0, sizeof bm);
    bm.gain = -s->eps;
    bm.kind = -1;
    for (dir = 0; dir < 2; dir++)
        search(s, a, dir, &bm);
    if (bm.kind < 0)
        return 0;
    *rc = apply(s, &bm);
    *delta += bm.gain;
    qc__tsp_push(s, bm.t1);
    qc__tsp_push(s, bm.t2);
    qc__tsp_push(s, bm.t3);
    qc__tsp_push(s, bm.t4);
    if (bm.kind != KIND_2OPT) {
        qc__tsp_push(s, bm.t5);
        qc__tsp_push(s, bm.t6);
    }
    return 1;
}

/* ---- LK chains of 2-opt moves (the budget's deeper search) ---- */

#define LK_DEPTH 10   /* 2-opt moves in a chain */
#define LK_BREADTH 5  /* first moves tried from an edge */
/* Longest reversal a chain's move may make: the moves are applied on trial
 * and mostly undone, so on huge tours long ones would cost more than they
 * find (no limit below 2000 points). */
#define LK_REACH 1000

static int lk_too_far(const qc__tsp *s, uint32_t a, uint32_t c)
{
    uint32_t d = s->pos[c] >= s->pos[a] ? s->pos[c] - s->pos[a] : s->pos[a] - s->pos[c];
    return d > LK_REACH && s->m - d > LK_REACH;
}

typedef struct lk_chain {
    uint32_t mv[LK_DEPTH][4]; /* applied move2 arguments, for the undo */
    uint32_t out[LK_DEPTH + 1][2], in[LK_DEPTH][2]; /* edges removed, added */
    unsigned nmv, nout, nin;
} lk_chain;

static int has_edge(uint32_t (*e)[2], unsigned n, uint32_t a, uint32_t b)
{
    unsigned i;

    for (i = 0; i < n; i++)
        if ((e[i][0] == a && e[i][1] == b) || (e[i][0] == b && e[i][1] == a))
            return 1;
    return 0;
}

/* The point t4 beside t3 that a 2-opt move removing (t1, t2) and (t3, t4)
 * needs, or t2 when the move is degenerate or not allowed. */
static uint32_t lk_t4(const qc__tsp *s, const lk_chain *c, uint32_t t1, uint32_t t2, uint32_t t3)
{
    uint32_t t4 = qc__tsp_next(s, t2) == t1 ? qc__tsp_next(s, t3) : qc__tsp_prev(s, t3);

    if (t3 == t1 || t4 == t2 || lk_too_far(s, t2, t3) ||
        has_edge((uint32_t(*)[2])c->out, c->nout, t2, t3) ||
        has_edge((uint32_t(*)[2])c->in, c->nin, t3, t4))
        return t2;
    return t4;
}

/* One chain from edge (t1, t2) whose first move joins t2 to t3: moves are
 * applied as they go, then undone back to the shortest tour seen. Returns
 * the change kept (0 if none). */
static double lk_run(qc__tsp *s, uint32_t t1, uint32_t t2, uint32_t t3, int *rc)
{
    lk_chain c;
    double g = qc__tsp_dist(s, t1, t2), now = 0.0, best = -s->eps;
    unsigned keep = 0, depth, j;

    c.nmv = c.nin = 0;
    c.out[0][0] = t1, c.out[0][1] = t2;
    c.nout = 1;
    for (depth = 0; depth < LK_DEPTH && *rc == QC_OK; depth++) {
        uint32_t t4 = t2;
        double d23;

        if (depth == 0) {
            t4 = lk_t4(s, &c, t1, t2, t3);
        } else { /* the candidate with the best d(t3, t4) - d(t2, t3) */
            const uint32_t *nb = s->nb + (size_t)t2 * s->k;
            double bv = -1e300;

            for (j = 0; j < s->k; j++) {
                uint32_t x = nb[j], y;
                double dx = qc__tsp_cand_dist(s, t2, j);

                if (g - dx <= s->eps)
                    break;
                y = lk_t4(s, &c, t1, t2, x);
                if (y != t2 && qc__tsp_dist(s, x, y) - dx > bv) {
                    bv = qc__tsp_dist(s, x, y) - dx;
                    t3 = x, t4 = y;
                }
            }
        }
        d23 = qc__tsp_dist(s, t2, t3);
        if (t4 == t2 || g - d23 <= s->eps)
            break;
        *rc = qc__tsp_move2(s, t2, t1, t3, t4);
        c.mv[c.nmv][0] = t2, c.mv[c.nmv][1] = t3, c.mv[c.nmv][2] = t1, c.mv[c.nmv][3] = t4;
        c.nmv++;
        now += d23 + qc__tsp_dist(s, t1, t4) - qc__tsp_dist(s, t1, t2) - qc__tsp_dist(s, t3, t4);
        if (now < best) {
            best = now;
            keep = c.nmv;
        }
        g += qc__tsp_dist(s, t3, t4) - d23;
        c.in[c.nin][0] = t2, c.in[c.nin][1] = t3;
        c.nin++;
        c.out[c.nout][0] = t3, c.out[c.nout][1] = t4;
        c.nout++;
        t2 = t4;
    }
    while (c.nmv > keep && *rc == QC_OK) { /* the inverse of each move, last first */
        c.nmv--;
        *rc = qc__tsp_move2(s, c.mv[c.nmv][0], c.mv[c.nmv][1], c.mv[c.nmv][2], c.mv[c.nmv][3]);
    }
    if (keep == 0)
        return 0.0;
    qc__tsp_push(s, t1);
    for (j = 0; j < keep; j++) {
        qc__tsp_push(s, c.mv[j][0]);
        qc__tsp_push(s, c.mv[j][1]);
        qc__tsp_push(s, c.mv[j][3]);
    }
    return best;
}

int qc__tsp_try_lk(qc__tsp *s, uint32_t a, double *delta, int *rc)
{
    int side;
    unsigned j;

    for (side = 0; side < 2; side++) {
        uint32_t t2 = side ? qc__tsp_prev(s, a) : qc__tsp_next(s, a);
        const uint32_t *nb = s->nb + (size_t)t2 * s->k;
        double d12 = qc__tsp_dist(s, a, t2);

        for (j = 0; j < s->k && j < LK_BREADTH && *rc == QC_OK; j++) {
            double got;

            if (d12 - qc__tsp_cand_dist(s, t2, j) <= s->eps)
                break;
            got = lk_run(s, a, t2, nb[j], rc);
            if (got < 0.0) {
                *delta += got;
                return 1;
            }
        }
    }
    return 0;
}
