/*
 * Local search on the array tour: 2-opt over the candidate lists with
 * don't-look bits (a FIFO of active points), Or-opt (segments of 1-3
 * points moved next to a candidate, either way round), and the
 * perturbation: a random segment swap (a local double bridge) followed by
 * local search from its ends, undone unless the tour got shorter or stays
 * within a slack of the best (the walk ends back at the best). Every change is a reversal of positions, so an undo replays the
 * log backwards.
 */
#include <string.h>

#include "tour_internal.h"

/* Longest segment a kick swaps: at equal time, 100-300 beat 30 on TSPLIB
 * (pr2392, pcb3038, fnl4461: 0.6-1.0% against 0.9% after 3x the time). */
#define KICK_MAX 100
/* The budget's (LK rounds): up to 2000 points, 1000 ms, seeds 1-3, 200 or
 * 400 gave 0.13% above the optima, 100 gave 0.18%, 50 gave 0.21%. */
#define KICK_MAX_LK 200

/* Swaps the points at positions i .. i+run-1 with those at j, j-1, ...,
 * j-run+1 (no wrap on either side): size_t indices and four pairs a turn,
 * so a pair costs about 9 instructions where 32-bit indices, extended at
 * each load, cost 15 (on TSPLIB a fifth of the default's instructions
 * were here). */
static void swap_run(uint32_t *t, uint32_t *pos, size_t i, size_t j, size_t run)
{
    size_t end = i + run, sum = i + j;

    for (; i + 3 < end; i += 4) {
        size_t k = sum - i;
        uint32_t a0 = t[i], b0 = t[k], a1 = t[i + 1], b1 = t[k - 1];
        uint32_t a2 = t[i + 2], b2 = t[k - 2], a3 = t[i + 3], b3 = t[k - 3];

        t[i] = b0, t[k] = a0, t[i + 1] = b1, t[k - 1] = a1;
        t[i + 2] = b2, t[k - 2] = a2, t[i + 3] = b3, t[k - 3] = a3;
        pos[b0] = (uint32_t)i, pos[a0] = (uint32_t)k;
        pos[b1] = (uint32_t)(i + 1), pos[a1] = (uint32_t)(k - 1);
        pos[b2] = (uint32_t)(i + 2), pos[a2] = (uint32_t)(k - 2);
        pos[b3] = (uint32_t)(i + 3), pos[a3] = (uint32_t)(k - 3);
    }
    for (; i < end; i++) {
        uint32_t a = t[i], b = t[sum - i];

        t[i] = b;
        pos[b] = (uint32_t)i;
        t[sum - i] = a;
        pos[a] = (uint32_t)(sum - i);
    }
}

/* Reverses positions i, i+1, ..., i+len-1 (cyclic): the pairs in runs
 * where neither end wraps, so the inner loop has no wrap tests (the
 * kicks' re-optimisation spends a fifth of its time here). */
static void reverse_raw(qc__tsp *s, uint32_t i, uint32_t len)
{
    uint32_t m = s->m, j = i + len - 1, h = len / 2;

    if (j >= m)
        j -= m;
    while (h > 0) {
        uint32_t run = h;

        if (run > m - i)
            run = m - i;
        if (run > j + 1)
            run = j + 1;
        swap_run(s->t, s->pos, i, j, run);
        i += run;
        j -= run;
        h -= run;
        if (i == m)
            i = 0;
        if (j == UINT32_MAX)
            j = m - 1;
    }
}

/* A log entry (i, ROTATED | l1 << 16 | l2): positions i.. held segments of
 * l1 then l2 points, now swapped (reversals are shorter than 2^28). */
#define ROTATED 0x80000000u

/* Swaps the adjacent segments of l1 and l2 points from position i (cyclic):
 * each point written once, where three reversals write each twice (the
 * kicks spent a third of their reversal time on theirs). */
static void rotate_raw(qc__tsp *s, uint32_t i, uint32_t l1, uint32_t l2)
{
    uint32_t *t = s->t, *pos = s->pos, m = s->m, tmp[KICK_MAX_LK], r, at;
    size_t k;

    if (i + l1 + l2 <= m) { /* no wrap: three copies */
        memcpy(tmp, t + i, l1 * sizeof *t);
        memmove(t + i, t + i + l1, l2 * sizeof *t);
        memcpy(t + i + l2, tmp, l1 * sizeof *t);
        for (k = i; k < (size_t)i + l1 + l2; k++) /* size_t: no extension per point */
            pos[t[k]] = (uint32_t)k;
        return;
    }
    for (r = 0, at = i; r < l1; r++, at = at + 1 == m ? 0 : at + 1)
        tmp[r] = t[at];
    for (r = 0, at = i; r < l2; r++, at = at + 1 == m ? 0 : at + 1) {
        uint32_t from = at + l1 >= m ? at + l1 - m : at + l1;
        t[at] = t[from];
        pos[t[at]] = at;
    }
    for (r = 0; r < l1; r++, at = at + 1 == m ? 0 : at + 1) {
        t[at] = tmp[r];
        pos[tmp[r]] = at;
    }
}

static void replay_raw(qc__tsp *s, uint32_t i, uint32_t e)
{
    if (e & ROTATED) /* back: l2 points then l1 */
        rotate_raw(s, i, e & 0xffffu, e >> 16 & 0x7fffu);
    else
        reverse_raw(s, i, e);
}

static int log_entry(qc__tsp *s, uint32_t i, uint32_t e)
{
    if (!s->logging)
        return QC_OK;
    if (QC__RESERVE(s->ctx, s->log, s->log_cap, 2 * s->nlog + 2) < 0)
        return qc__fail(s->ctx, QC_ENOMEM, "tsp: out of memory for the undo log");
    s->log[2 * s->nlog] = i;
    s->log[2 * s->nlog + 1] = e;
    s->nlog++;
    return QC_OK;
}

static int reverse_logged(qc__tsp *s, uint32_t i, uint32_t len)
{
    if (len < 2)
        return QC_OK;
    QC__TRY(log_entry(s, i, len));
    reverse_raw(s, i, len);
    return QC_OK;
}

/* Reverses the tour path from a forward to b, or the rest of the tour
 * (the same cycle), whichever is shorter. */
static int reverse_path(qc__tsp *s, uint32_t a, uint32_t b)
{
    uint32_t m = s->m, i = s->pos[a], j = s->pos[b];
    uint32_t len = (j >= i ? j - i : j + m - i) + 1;

    if (2 * (size_t)len > m) {
        i = j + 1 == m ? 0 : j + 1;
        len = m - len;
    }
    return reverse_logged(s, i, len);
}

int qc__tsp_move2(qc__tsp *s, uint32_t a, uint32_t b, uint32_t c, uint32_t d)
{
    /* forward: a b .. c d -> a c .. b d; backward (b a .. d c in the array):
     * -> b d .. a c */
    if (qc__tsp_next(s, a) == b)
        return reverse_path(s, b, c);
    return reverse_path(s, a, d);
}

/* ---- the queue of points whose don't-look bit is off ---- */

void qc__tsp_push(qc__tsp *s, uint32_t a)
{
    size_t at;

    if (s->inq[a])
        return;
    s->inq[a] = 1;
    at = s->qhead + s->qcount++;
    s->queue[at >= s->m ? at - s->m : at] = a;
}

static int pop(qc__tsp *s, uint32_t *a)
{
    if (s->qcount == 0)
        return 0;
    *a = s->queue[s->qhead];
    s->qhead = s->qhead + 1 == s->m ? 0 : s->qhead + 1;
    s->qcount--;
    s->inq[*a] = 0;
    return 1;
}

void qc__tsp_queue_all(qc__tsp *s)
{
    uint32_t i;

    for (i = 0; i < s->m; i++)
        qc__tsp_push(s, s->t[i]);
}

/* ---- 2-opt ---- */

/* From this many points on, the default's kicks sweep the points in
 * Hilbert order (each near the last: memory stays in cache) and their
 * re-optimisation reverses at most KICK_REVERSAL positions. On 623,518
 * points (bench/: a jittered grid) the kicks took 4.8 s of 6.4 s: 3.9 s
 * now for 0.05% of length (10^5 points: 0.94 -> 0.59 s, +0.05%). Below,
 * random positions as before: on TSPLIB (up to 18,512 points, all in
 * cache) the sweep gave 2.08% above the optima against 1.85%. */
#define SWEEP_MIN_POINTS 50000
#define SWEEP_JITTER 64 /* points: the next kick is this near the sweep */
#define KICK_REVERSAL 1000

/* The best 2-opt move removing an edge at a; applies it. 1 if moved. */
static int try_2opt(qc__tsp *s, uint32_t a, double *delta, int *rc)
{
    qc__view v = qc__view_of(s);
    const uint32_t *nb = s->nb + (size_t)a * s->k;
    const double *nbd = s->nbd ? s->nbd + (size_t)a * s->k : NULL;
    double best = -s->eps;
    uint32_t bb = 0, bc = 0, bd = 0;
    unsigned j, k = s->k;
    int dir, found = 0;

    for (dir = 0; dir < 2; dir++) {
        uint32_t b = dir ? qc__vprev(v, a) : qc__vnext(v, a);
        double dab = qc__vdist(v, a, b);

        for (j = 0; j < k; j++) {
            uint32_t c = nb[j], d;
            double dac = nbd ? nbd[j] : qc__vdist(v, a, c), g;

            if (dac >= dab)
                break;
            d = dir ? qc__vprev(v, c) : qc__vnext(v, c);
            if (c == b || d == a || (v.far && qc__tsp_too_far(s, a, c)))
                continue;
            g = dac + qc__vdist(v, b, d) - dab - qc__vdist(v, c, d);
            if (g < best) {
                best = g;
                bb = b, bc = c, bd = d;
                found = 1;
            }
        }
    }
    if (!found)
        return 0;
    *rc = qc__tsp_move2(s, a, bb, bc, bd);
    *delta += best;
    qc__tsp_push(s, a);
    qc__tsp_push(s, bb);
    qc__tsp_push(s, bc);
    qc__tsp_push(s, bd);
    return 1;
}

/* ---- Or-opt ---- */

typedef struct or_move {
    uint32_t first, len; /* the segment: positions first .. first+len-1 */
    uint32_t x, y;       /* the edge it moves into, y = next(x) */
    int rev;             /* x is joined to the segment's last point */
    double gain;
} or_move;

static int in_segment(qc__view v, uint32_t first, uint32_t len, uint32_t c)
{
    uint32_t off = v.pos[c] >= first ? v.pos[c] - first : v.pos[c] + v.m - first;
    return off < len;
}

/* Candidate insertions of segment [first, first+len) next to the
 * candidates of its ends; keeps the best in *bm. */
static void or_segment(const qc__tsp *s, uint32_t first, uint32_t len, or_move *bm)
{
    qc__view v = qc__view_of(s);
    uint32_t m = v.m, last = first + len - 1 >= m ? first + len - 1 - m : first + len - 1;
    uint32_t s1 = v.t[first], s2 = v.t[last];
    uint32_t p = qc__vprev(v, s1), nx = qc__vnext(v, s2);
    double g1 = qc__vdist(v, p, s1) + qc__vdist(v, s2, nx) - qc__vdist(v, p, nx);
    double best = bm->gain;
    int end;
    unsigned j, k = s->k;

    if (g1 <= s->eps)
        return;
    for (end = 0; end < (len > 1 ? 2 : 1); end++) {
        uint32_t e = end ? s2 : s1, o = end ? s1 : s2;
        const uint32_t *nb = s->nb + (size_t)e * k;
        const double *nbd = s->nbd ? s->nbd + (size_t)e * k : NULL;

        for (j = 0; j < k; j++) {
            uint32_t c = nb[j], x;
            double dce = nbd ? nbd[j] : qc__vdist(v, e, c), g;

            if (dce >= g1)
                break;
            if (in_segment(v, first, len, c) || (v.far && qc__tsp_too_far(s, e, c)))
                continue;
            /* c, e ... o, next(c) */
            x = qc__vnext(v, c);
            if (!in_segment(v, first, len, x)) {
                g = dce + qc__vdist(v, o, x) - qc__vdist(v, c, x) - g1;
                if (g < best) {
                    best = g;
                    bm->gain = g;
                    bm->first = first, bm->len = len;
                    bm->x = c, bm->y = x, bm->rev = end;
                }
            }
            /* prev(c), o ... e, c */
            x = qc__vprev(v, c);
            if (!in_segment(v, first, len, x)) {
                g = dce + qc__vdist(v, o, x) - qc__vdist(v, c, x) - g1;
                if (g < best) {
                    best = g;
                    bm->gain = g;
                    bm->first = first, bm->len = len;
                    bm->x = x, bm->y = c, bm->rev = !end;
                }
            }
        }
    }
}

/* Moves the segment into edge (x, y) by up to three 2-opt moves:
 * p S n .. x y  ->  p x .. n S' y  ->  p n .. x S' y  (->  p n .. x S y). */
static int or_apply(qc__tsp *s, const or_move *mv)
{
    uint32_t m = s->m, last = mv->first + mv->len - 1 >= m ? mv->first + mv->len - 1 - m
                                                             : mv->first + mv->len - 1;
    uint32_t s1 = s->t[mv->first], s2 = s->t[last];
    uint32_t p = qc__tsp_prev(s, s1), nx = qc__tsp_next(s, s2);

    if (mv->y != p)
        QC__TRY(qc__tsp_move2(s, p, s1, mv->x, mv->y));
    if (mv->x != nx)
        QC__TRY(qc__tsp_move2(s, p, mv->x, nx, s2));
    if (!mv->rev && mv->len > 1)
        QC__TRY(qc__tsp_move2(s, mv->x, s2, s1, mv->y));
    return QC_OK;
}

static int try_oropt(qc__tsp *s, uint32_t a, double *delta, int *rc)
{
    uint32_t m = s->m, len, maxlen = m - 3 < 3 ? m - 3 : 3, pa = s->pos[a];
    or_move bm;
    uint32_t s1, s2, p, nx;

    bm.gain = -s->eps;
    bm.len = 0;
    if (s->light_kicks && maxlen > 2)
        maxlen = 2;
    for (len = 1; len <= maxlen; len++) {
        or_segment(s, pa, len, &bm);    /* a first */
        if (len > 1 && !s->light_kicks) /* a last */
            or_segment(s, pa >= len - 1 ? pa - (len - 1) : pa + m - (len - 1), len, &bm);
    }
    if (bm.len == 0)
        return 0;
    s1 = s->t[bm.first];
    s2 = s->t[bm.first + bm.len - 1 >= m ? bm.first + bm.len - 1 - m : bm.first + bm.len - 1];
    p = qc__tsp_prev(s, s1);
    nx = qc__tsp_next(s, s2);
    *rc = or_apply(s, &bm);
    *delta += bm.gain;
    qc__tsp_push(s, s1);
    qc__tsp_push(s, s2);
    qc__tsp_push(s, p);
    qc__tsp_push(s, nx);
    qc__tsp_push(s, bm.x);
    qc__tsp_push(s, bm.y);
    return 1;
}

int qc__tsp_local_search(qc__tsp *s, int level, double *delta)
{
    uint32_t a;
    int rc = QC_OK;

    if (s->m < 5)
        level = QC__TSP_LEVEL_2OPT;
    while (rc == QC_OK && pop(s, &a)) {
        if (try_2opt(s, a, delta, &rc))
            continue;
        if (level >= QC__TSP_LEVEL_OROPT && try_oropt(s, a, delta, &rc))
            continue;
        if (level >= QC__TSP_LEVEL_OR3OPT && qc__tsp_try_or3opt(s, a, delta, &rc))
            continue;
        if (level >= QC__TSP_LEVEL_LK)
            qc__tsp_try_lk(s, a, delta, &rc);
    }
    if (rc < 0) { /* leave the queue empty */
        while (pop(s, &a))
            ;
    }
    return rc;
}

/* ---- perturbation ---- */

/* Swaps two short adjacent segments after position i: a B C d -> a C B d.
 * Adds the change of length to *delta. */
static int kick(qc__tsp *s, qc_rng *rng, uint32_t i, uint32_t longest, double *delta)
{
    uint32_t m = s->m, lmax = (m - 2) / 2 < longest ? (m - 2) / 2 : longest;
    uint32_t l1 = 1 + (uint32_t)qc_rng_below(rng, lmax);
    uint32_t l2 = 1 + (uint32_t)qc_rng_below(rng, lmax);
    uint32_t ib1 = (i + 1) % m, ib2 = (i + l1) % m, ic1 = (i + l1 + 1) % m;
    uint32_t ic2 = (i + l1 + l2) % m, id = (i + l1 + l2 + 1) % m;
    uint32_t a = s->t[i], b1 = s->t[ib1], b2 = s->t[ib2], c1 = s->t[ic1], c2 = s->t[ic2];
    uint32_t d = s->t[id];

    *delta += qc__tsp_dist(s, a, c1) + qc__tsp_dist(s, c2, b1) + qc__tsp_dist(s, b2, d) -
              qc__tsp_dist(s, a, b1) - qc__tsp_dist(s, b2, c1) - qc__tsp_dist(s, c2, d);
    /* empty entries after it: the log fills as with the three reversals
     * (those of one point log nothing), so the walk's reset (log_max)
     * comes when it did */
    QC__TRY(log_entry(s, ib1, ROTATED | l1 << 16 | l2));
    if (l1 > 1)
        QC__TRY(log_entry(s, ib1, 0));
    if (l2 > 1)
        QC__TRY(log_entry(s, ib1, 0));
    rotate_raw(s, ib1, l1, l2);
    qc__tsp_push(s, a);
    qc__tsp_push(s, b1);
    qc__tsp_push(s, b2);
    qc__tsp_push(s, c1);
    qc__tsp_push(s, c2);
    qc__tsp_push(s, d);
    return QC_OK;
}

/* Reverts the logged reversals down to entry keep (the log holds every
 * reversal since the best tour so far). */
static void undo_to(qc__tsp *s, size_t keep)
{
    while (s->nlog > keep) {
        s->nlog--;
        replay_raw(s, s->log[2 * s->nlog], s->log[2 * s->nlog + 1]);
    }
}

int qc__tsp_perturb(qc__tsp *s, int level, uint64_t rounds, uint64_t seed, double slack_edges,
                    int sweep)
{
    uint64_t period = rounds < s->m ? rounds : s->m;
    qc_rng rng;
    uint64_t r;
    uint32_t i;
    double over = 0.0, slack = 0.0; /* the current tour's excess over the best */
    size_t log_max = 2 * (size_t)s->m + 1024;
    int rc = QC_OK;

    if (s->m < 8 || rounds == 0)
        return QC_OK;
    qc_rng_seed(&rng, seed);
    if (slack_edges > 0.0) {
        for (i = 0; i < s->m; i++)
            slack += qc__tsp_dist(s, s->t[i], qc__tsp_next(s, s->t[i]));
        slack *= slack_edges / s->m;
    }
    s->logging = 1;
    s->nlog = 0;
    if (sweep && s->m < SWEEP_MIN_POINTS)
        sweep = 0;
    if (sweep)
        s->max_reversal = KICK_REVERSAL;
    for (r = 0; r < rounds && rc == QC_OK; r++) {
        double delta = 0.0;
        size_t mark = s->nlog;
        uint32_t at;

        if (sweep) { /* near the point the sweep has reached */
            uint64_t u = (r % period) * s->m / period + qc_rng_below(&rng, SWEEP_JITTER);
            at = s->pos[u % s->m];
        } else {
            at = (uint32_t)qc_rng_below(&rng, s->m);
            if (s->light_kicks) { /* the longer edge of two is likelier wrong */
                uint32_t b = (uint32_t)qc_rng_below(&rng, s->m);
                if (qc__tsp_dist(s, s->t[b], qc__tsp_next(s, s->t[b])) >
                    qc__tsp_dist(s, s->t[at], qc__tsp_next(s, s->t[at])))
                    at = b;
            }
        }
        rc = kick(s, &rng, at, level == QC__TSP_LEVEL_LK ? KICK_MAX_LK : KICK_MAX, &delta);
        if (rc == QC_OK)
            rc = qc__tsp_local_search(s, level, &delta);
        if (rc == QC_OK && over + delta < -s->eps) { /* a new best */
            over = 0.0;
            s->nlog = 0;
        } else if (rc == QC_OK && slack > 0.0 && over + delta <= slack) {
            over += delta; /* a little longer: walk on from it */
        } else {
            undo_to(s, mark);
        }
        if (s->nlog > log_max) {
            undo_to(s, 0);
            over = 0.0;
        }
    }
    undo_to(s, 0);
    s->logging = 0;
    s->max_reversal = QC__TSP_MAX_REVERSAL;
    return rc;
}
