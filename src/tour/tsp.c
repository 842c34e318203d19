/*
 * The built-in TSP (paper §4.2, issues 3 and 21): greedy-edge construction
 * over k-nearest-neighbour candidates, 2-opt with neighbour lists and
 * don't-look bits, Or-opt, Or-3opt (tsp_or3opt.c, its lists completed by
 * Delaunay neighbours in tsp_cand.c), perturbation rounds (the default's
 * own, then the caller's budget, which adds LK chains), and a final pass removing
 * every proper crossing by exact predicates. Works on the distinct points;
 * copies of a point follow their first copy in the tour (zero-length
 * edges cross nothing).
 */
#include <string.h>

#include "tour_internal.h"

#define TSP_MAX_POINTS (1u << 28) /* slots of the greedy sort keys fit 32 bits */
#define TSP_MAX_COORD 1e150       /* squared distances stay finite */
#define DEFAULT_K 10
/* The lists of the default alone: 6 nearest and 3 Delaunay neighbours
 * (tsp_cand.c), a few % less time for the same length. */
#define DEFAULT_K_QUICK 9
#define DEFAULT_KICK_SLACK 0.5 /* average edges (qc__tsp_perturb) */
#define BUDGET_SLACK 1.0

static void release(qc__tsp *s)
{
    qc_ctx *ctx = s->ctx;
    size_t m = s->m;

    qc__free(ctx, s->sorted, s->n * sizeof *s->sorted);
    qc__free(ctx, s->ustart, (m + 1) * sizeof *s->ustart);
    qc__free(ctx, s->q, m * sizeof *s->q);
    qc__free(ctx, s->nb, m * s->k * sizeof *s->nb);
    qc__free(ctx, s->nbd, m * s->k * sizeof *s->nbd);
    qc__free(ctx, s->t, m * sizeof *s->t);
    qc__free(ctx, s->pos, m * sizeof *s->pos);
    qc__free(ctx, s->queue, m * sizeof *s->queue);
    qc__free(ctx, s->inq, m);
    qc__free(ctx, s->log, s->log_cap * sizeof *s->log);
}

static int check(qc_ctx *ctx, const qc_vec2 *p, size_t n)
{
    size_t i;

    if (n > TSP_MAX_POINTS)
        return qc__fail(ctx, QC_ELIMIT, "tsp: %lu points, at most %lu", (unsigned long)n,
                        (unsigned long)TSP_MAX_POINTS);
    if (n > 0 && p == NULL)
        return qc__fail(ctx, QC_EINVAL, "tsp: NULL points");
    for (i = 0; i < n; i++) {
        double x = p[i].x, y = p[i].y;
        if (!(x >= -TSP_MAX_COORD && x <= TSP_MAX_COORD && y >= -TSP_MAX_COORD &&
              y <= TSP_MAX_COORD))
            return qc__fail(ctx, QC_ERANGE, "tsp: point %lu (%g, %g) is not finite or beyond "
                            "1e150", (unsigned long)i, x, y);
    }
    return QC_OK;
}

/* The tour of distinct points, copies expanded, rotated to start at 0. */
static void emit(const qc__tsp *s, qc_order *out)
{
    uint32_t u0 = 0, i, j, at;
    size_t w = out->n;

    for (i = 0; i < s->m; i++) /* the distinct point holding caller index 0 */
        if (s->sorted[s->ustart[i]] == 0)
            u0 = i;
    at = s->pos[u0];
    for (i = 0; i < s->m; i++) {
        uint32_t u = s->t[at];
        for (j = s->ustart[u]; j < s->ustart[u + 1]; j++)
            out->i[w++] = s->sorted[j];
        at = at + 1 == s->m ? 0 : at + 1;
    }
    out->n = w;
}

static int solve(qc__tsp *s, int method, int neighbours, const qc_tsp_params *params)
{
    qc_ctx *ctx = s->ctx;
    uint32_t m, i;
    double delta = 0.0;
    uint64_t extra, seed;
    int quick, even;

    QC__TRY(qc__tsp_prepare(s));
    m = s->m;
    s->t = qc__alloc_array(ctx, m, sizeof *s->t);
    s->pos = qc__alloc_array(ctx, m, sizeof *s->pos);
    if (s->t == NULL || s->pos == NULL)
        return qc__fail(ctx, QC_ENOMEM, "tsp: out of memory for a tour of %lu points",
                        (unsigned long)m);
    if (m <= 3) { /* any order is optimal */
        for (i = 0; i < m; i++)
            s->t[i] = s->pos[i] = i;
        return QC_OK;
    }
    extra = params ? params->perturb_iterations : 0;
    /* The default alone runs lighter (below); before a budget, whose time
     * dwarfs it, it runs in full: the budget's figures stay. */
    quick = method == QC_TSP_METHOD_OR3OPT && extra == 0;
    s->k = (unsigned)(neighbours == 0 ? (quick ? DEFAULT_K_QUICK : DEFAULT_K)
                      : neighbours > QC__TSP_MAX_K ? QC__TSP_MAX_K : neighbours);
    if (s->k > m - 1)
        s->k = m - 1;
    s->nb = qc__alloc_array(ctx, (size_t)m * s->k, sizeof *s->nb);
    if (s->nb == NULL)
        return qc__fail(ctx, QC_ENOMEM, "tsp: out of memory for %u neighbours of %lu points",
                        s->k, (unsigned long)m);
    QC__TRY(qc__knn(ctx, s->q, m, s->k, s->nb, &even));
    QC__TRY(qc__tsp_greedy(s));
    if (method == QC_TSP_METHOD_OR3OPT) {
        /* Delaunay neighbours reach across clusters; evenly spread points
         * (the grid took their lists) have none to reach across, and the
         * default alone does as well with its nearest: TSPLIB seeds 1-4
         * 1.77% -> 1.72% above the optima, 927 Poisson points 12% fewer
         * instructions. A budget's LK rounds keep them (without: +1000 ms
         * 0.12% -> 0.17%, +10 s 0.10% -> 0.28% on the slowest three). */
        if (!even || !quick)
            QC__TRY(qc__tsp_add_delaunay(s));
        QC__TRY(qc__tsp_cache_dists(s));
    }
    if (method == QC_TSP_METHOD_GREEDY)
        return QC_OK;
    s->queue = qc__alloc_array(ctx, m, sizeof *s->queue);
    s->inq = qc__alloc(ctx, m);
    if (s->queue == NULL || s->inq == NULL)
        return qc__fail(ctx, QC_ENOMEM, "tsp: out of memory for the search of %lu points",
                        (unsigned long)m);
    memset(s->inq, 0, m);
    qc__tsp_queue_all(s);
    QC__TRY(qc__tsp_local_search(s, QC__TSP_LEVEL_2OPT, &delta));
    /* Below the reversal limit the default alone reaches any crossing by
     * its searches and uncrosses at its end only (TSPLIB: 4% of its time);
     * above, crossings needing long reversals are left to the uncrossing,
     * and the kicks should start without them (624,100 points: 0.4%). */
    if (!quick || m > s->max_reversal)
        QC__TRY(qc__tsp_uncross(s));
    if (method == QC_TSP_METHOD_2OPT)
        return QC_OK;
    seed = params ? params->seed : 0;
    qc__tsp_queue_all(s);
    if (method == QC_TSP_METHOD_OROPT) {
        QC__TRY(qc__tsp_local_search(s, QC__TSP_LEVEL_OROPT, &delta));
        QC__TRY(qc__tsp_perturb(s, QC__TSP_LEVEL_OROPT, extra, seed, 0.0, 0));
        return qc__tsp_uncross(s);
    }
    QC__TRY(qc__tsp_local_search(s, QC__TSP_LEVEL_OR3OPT, &delta));
    /* The default's own kicks re-optimise with Or-opt only, then one Or-3opt
     * pass: on TSPLIB, at equal time, 0.6n such kicks beat 0.35n searched
     * with Or-3opt (2.0% against 2.24% above the optima). Walking on from
     * tours up to half an average edge longer than the best, 0.55n kicks
     * give 1.75% (seeds 1-3) at 2.9x Or-opt's time (0.6n keeping only
     * shorter tours: 1.82% at 3.3x). A budget's rounds search deeper (LK
     * chains, tsp_or3opt.c) and walk on within one edge: up to 2000 points,
     * 1000 ms, 0.13% above the optima (within 0.2 edge, Or-3opt: 0.31%).
     * Alone, the default's kicks are lighter: Or-opt moves only segments
     * of 1-2 points starting at the popped point (each end of a kick is
     * queued anyway) and each kick goes to the longer of two random edges;
     * with the lists of 9 and one uncrossing, TSPLIB 1.75% -> 1.78% above
     * the optima (seeds 1-3) for 2.9x -> 2.4x Or-opt's time (bench, seed
     * 1: 1.85% -> 1.86%, 3.02x -> 2.40x). */
    s->light_kicks = quick;
    QC__TRY(qc__tsp_perturb(s, QC__TSP_LEVEL_OROPT, QC_TSP_OR3OPT_KICKS(m), seed,
                            DEFAULT_KICK_SLACK, 1));
    s->light_kicks = 0;
    qc__tsp_queue_all(s);
    QC__TRY(qc__tsp_local_search(s, QC__TSP_LEVEL_OR3OPT, &delta));
    QC__TRY(qc__tsp_perturb(s, QC__TSP_LEVEL_LK, extra, seed ^ UINT64_C(0x9e3779b97f4a7c15),
                            BUDGET_SLACK, 0));
    return qc__tsp_uncross(s);
}

int qc_tsp(qc_ctx *ctx, const qc_vec2 *p, size_t n, const qc_tsp_params *params,
           qc_order *out)
{
    int method = params && params->method != QC_TSP_METHOD_DEFAULT ? params->method
                                                                   : QC_TSP_METHOD_OR3OPT;
    int neighbours = params ? params->neighbours : 0;
    qc__tsp s;
    size_t i;
    int rc;

    if (out == NULL)
        return qc__fail(ctx, QC_EINVAL, "tsp: NULL output");
    if (method < QC_TSP_METHOD_GREEDY || method > QC_TSP_METHOD_OR3OPT)
        return qc__fail(ctx, QC_EINVAL, "tsp: unknown method %d", method);
    if (neighbours < 0)
        return qc__fail(ctx, QC_EINVAL, "tsp: %d neighbours", neighbours);
    QC__TRY(check(ctx, p, n));
    if (QC__RESERVE(ctx, out->i, out->cap, out->n + n) < 0)
        return qc__fail(ctx, QC_ENOMEM, "tsp: out of memory for a tour of %lu points",
                        (unsigned long)n);
    if (n <= 3) {
        for (i = 0; i < n; i++)
            out->i[out->n++] = (uint32_t)i;
        return QC_OK;
    }
    memset(&s, 0, sizeof s);
    s.ctx = ctx;
    s.p = p;
    s.n = n;
    s.max_reversal = QC__TSP_MAX_REVERSAL;
    rc = solve(&s, method, neighbours, params);
    if (rc == QC_OK)
        emit(&s, out);
    release(&s);
    return rc;
}

uint64_t qc_tsp_rounds_for_ms(double ms)
{
    double r = ms * QC_TSP_ROUNDS_PER_MS;

    if (!(r > 0.0))
        return 0;
    return r >= 4611686018427387904.0 ? (uint64_t)1 << 62 : (uint64_t)r;
}

double qc_tour_length(const qc_vec2 *p, const uint32_t *order, size_t m, int closed)
{
    double len = 0.0;
    size_t i;

    for (i = 1; i < m; i++)
        len += qc_hypot(p[order[i]].x - p[order[i - 1]].x, p[order[i]].y - p[order[i - 1]].y);
    if (closed && m > 1)
        len += qc_hypot(p[order[0]].x - p[order[m - 1]].x, p[order[0]].y - p[order[m - 1]].y);
    return len;
}
