/*
 * Internals of the TSP solver split across src/tour/tsp*.c and knn.c. Not
 * installed. The solver works on the distinct points only (duplicates are
 * put back next to their first copy at the end), renumbered along a Hilbert
 * curve so that neighbours in space are neighbours in memory.
 */
#ifndef QC_TOUR_INTERNAL_H
#define QC_TOUR_INTERNAL_H

#include <math.h>

#include "internal.h"

#define QC__TSP_MAX_K 32        /* largest candidate list */
#define QC__TSP_GREEDY_K 10     /* candidates the greedy construction sorts */
#define QC__TSP_LEAF 8          /* points (or tour edges) per leaf of a box tree */
#define QC__TSP_MAX_LEVELS 40
/* Moves whose shorter side is longer than this are skipped by the local
 * search (never by the uncrossing): at 10^6 points they cost a fifth of
 * the time for 0.2% of length; below 10^5 points no move is that long. */
#define QC__TSP_MAX_REVERSAL 50000

/* ---- box trees (knn.c) ---- */

typedef struct qc__box {
    double x0, y0, x1, y1;
} qc__box;

/* A packed binary tree of boxes over consecutive leaves: level 0 holds the
 * leaves (filled by the caller), level l+1 node j bounds level l nodes 2j
 * and 2j+1; the top level is one root. */
typedef struct qc__btree {
    qc__box *box;
    size_t total;                        /* boxes allocated */
    size_t off[QC__TSP_MAX_LEVELS];      /* first box of each level */
    size_t cnt[QC__TSP_MAX_LEVELS];      /* boxes in each level */
    int levels;
} qc__btree;

/* Allocates a tree of nleaves (>= 1) leaves; the caller fills box[0..nleaves). */
QC__HIDDEN int qc__btree_init(qc_ctx *ctx, qc__btree *t, size_t nleaves);
/* Computes the upper levels from the leaves. */
QC__HIDDEN void qc__btree_finish(qc__btree *t);
QC__HIDDEN void qc__btree_free(qc_ctx *ctx, qc__btree *t);

/* One query's best k so far, sorted by (squared distance, index): the box
 * tree's and the grid's (knn.c, knn_grid.c). */
typedef struct qc__knn_best {
    unsigned k, have;
    double d2[QC__TSP_MAX_K];
    uint32_t id[QC__TSP_MAX_K];
} qc__knn_best;

static inline void qc__knn_offer(qc__knn_best *b, double d2, uint32_t id)
{
    unsigned j;

    if (b->have == b->k &&
        !(d2 < b->d2[b->k - 1] || (d2 == b->d2[b->k - 1] && id < b->id[b->k - 1])))
        return;
    j = b->have < b->k ? b->have++ : b->k - 1;
    for (; j > 0 && (b->d2[j - 1] > d2 || (b->d2[j - 1] == d2 && b->id[j - 1] > id)); j--) {
        b->d2[j] = b->d2[j - 1];
        b->id[j] = b->id[j - 1];
    }
    b->d2[j] = d2;
    b->id[j] = id;
}

/*
 * The k nearest neighbours of every point of q[0..m) among the others
 * (m >= 2, k <= min(m - 1, QC__TSP_MAX_K)), nearest first, ties by index:
 * nb[i * k .. i * k + k). Points should come in a spatially coherent order
 * (a Hilbert curve): leaves are runs of QC__TSP_LEAF consecutive points.
 * Exact for any distribution, O(m log m) expected. QC_OK or QC_ENOMEM.
 * (Lists forced to hold neighbours from each quadrant were tried: they
 * made the TSPLIB tours 0.5-2% longer on average.)
 */
QC__HIDDEN int qc__knn(qc_ctx *ctx, const qc_vec2 *q, size_t m, unsigned k, uint32_t *nb,
                       int *even);
/* The same lists over a uniform grid for evenly spread points (knn_grid.c,
 * which qc__knn tries first, setting *even, if not NULL, when it took
 * them): QC_OK, QC_ENOMEM, or 1 when it declines. */
QC__HIDDEN int qc__knn_grid(qc_ctx *ctx, const qc_vec2 *q, size_t m, unsigned k, uint32_t *nb);

/* ---- the solver state ---- */


typedef struct qc__tsp {
    qc_ctx *ctx;
    const qc_vec2 *p;   /* the caller's points (exact geometry) */
    size_t n;           /* the caller's count */
    uint32_t m;         /* distinct points */
    qc_vec2 *q;         /* the m distinct points (exact copies), Hilbert order */
    uint32_t *sorted;   /* n caller indices, grouped by distinct point */
    uint32_t *ustart;   /* m + 1: distinct point u is sorted[ustart[u] .. ustart[u+1]) */
    unsigned k;         /* candidates per point */
    uint32_t *nb;       /* m * k candidate lists */
    double *nbd;        /* their distances (Or-3opt only), or NULL */
    double eps;         /* gains below this are rounding noise */
    uint32_t max_reversal; /* the searches skip moves reversing more */
    int light_kicks;    /* the default's own kicks (tsp_opt.c): Or-opt moves
                           only segments of 1-2 points starting at the point
                           popped; kicks go to the longer of two edges */

    /* the tour over 0..m-1 as an array with positions */
    uint32_t *t, *pos;
    /* the don't-look bits as a FIFO of active points */
    uint32_t *queue;
    unsigned char *inq;
    size_t qhead, qcount;
    /* reversals done since the last qc__tsp_log_reset (perturbation undo) */
    int logging;
    uint32_t *log;      /* pairs (first position, length) */
    size_t nlog, log_cap;
} qc__tsp;

/* Distance between distinct points a and b. */
static inline double qc__tsp_dist(const qc__tsp *s, uint32_t a, uint32_t b)
{
    double dx = s->q[a].x - s->q[b].x, dy = s->q[a].y - s->q[b].y;
    return sqrt(dx * dx + dy * dy);
}

/* The distance from a to its j-th candidate: the search loops read the
 * cache Or-3opt fills (a third of their time went to these square roots
 * and the loads of the candidates' points), Or-opt computes it. */
static inline double qc__tsp_cand_dist(const qc__tsp *s, uint32_t a, unsigned j)
{
    size_t at = (size_t)a * s->k + j;
    return s->nbd ? s->nbd[at] : qc__tsp_dist(s, a, s->nb[at]);
}

/* Sorts the caller's points along a Hilbert curve, groups duplicates and
 * fills q, sorted, ustart, m and eps (tsp_prep.c). QC_OK or QC_ENOMEM. */
/* Whether x is among the k ids of list (neighbour lists are short). */
static inline int qc__tsp_listed(const uint32_t *list, unsigned k, uint32_t x)
{
    unsigned j;

    for (j = 0; j < k; j++)
        if (list[j] == x)
            return 1;
    return 0;
}

QC__HIDDEN int qc__tsp_prepare(qc__tsp *s);

/* Gives the last slots of each candidate list to Delaunay neighbours the
 * nearest miss (tsp_cand.c); nothing beyond the triangulation's range.
 * QC_OK or QC_ENOMEM. */
QC__HIDDEN int qc__tsp_add_delaunay(qc__tsp *s);

/* Fills nbd from the final candidate lists (tsp_cand.c). QC_OK or
 * QC_ENOMEM. */
QC__HIDDEN int qc__tsp_cache_dists(qc__tsp *s);

/* Greedy-edge tour over the candidate lists, fragments joined greedily then
 * along the Hilbert order; fills t and pos (tsp_construct.c). */
QC__HIDDEN int qc__tsp_greedy(qc__tsp *s);

/* ---- local search (tsp_opt.c) ---- */

static inline uint32_t qc__tsp_next(const qc__tsp *s, uint32_t a)
{
    uint32_t i = s->pos[a] + 1;
    return s->t[i == s->m ? 0 : i];
}

static inline uint32_t qc__tsp_prev(const qc__tsp *s, uint32_t a)
{
    uint32_t i = s->pos[a];
    return s->t[i == 0 ? s->m - 1 : i - 1];
}

/* The tour's arrays and the points in locals for the searches' inner
 * loops: they store through pointers the compiler cannot tell apart from
 * s, so read through s each field was reloaded at every candidate. */
typedef struct qc__view {
    const uint32_t *t, *pos;
    const qc_vec2 *q;
    uint32_t m;
    int far; /* qc__tsp_too_far can hold */
} qc__view;

static inline qc__view qc__view_of(const qc__tsp *s)
{
    qc__view v;

    v.t = s->t;
    v.pos = s->pos;
    v.q = s->q;
    v.m = s->m;
    v.far = s->m / 2 > s->max_reversal;
    return v;
}

static inline uint32_t qc__vnext(qc__view v, uint32_t a)
{
    uint32_t i = v.pos[a] + 1;
    return v.t[i == v.m ? 0 : i];
}

static inline uint32_t qc__vprev(qc__view v, uint32_t a)
{
    uint32_t i = v.pos[a];
    return v.t[i == 0 ? v.m - 1 : i - 1];
}

/* qc__tsp_dist's arithmetic, the same bits. */
static inline double qc__vdist(qc__view v, uint32_t a, uint32_t b)
{
    double dx = v.q[a].x - v.q[b].x, dy = v.q[a].y - v.q[b].y;
    return sqrt(dx * dx + dy * dy);
}

/* Replaces tour edges (a, b) and (c, d), both traversed in the same
 * direction (b follows a as d follows c), by (a, c) and (b, d), reversing
 * the shorter side. QC_OK or QC_ENOMEM (logging only). */
QC__HIDDEN int qc__tsp_move2(qc__tsp *s, uint32_t a, uint32_t b, uint32_t c, uint32_t d);

/* Clears a's don't-look bit (queues it). */
QC__HIDDEN void qc__tsp_push(qc__tsp *s, uint32_t a);
/* Makes room for the queue; queues every point in tour order. */
QC__HIDDEN void qc__tsp_queue_all(qc__tsp *s);
/* Whether a move reversing between a and c costs too much (huge tours;
 * never when the shorter side of any move is within the limit). Inline:
 * the searches of every file ask it of each candidate. */
static inline int qc__tsp_too_far(const qc__tsp *s, uint32_t a, uint32_t c)
{
    uint32_t d;

    if (s->m / 2 <= s->max_reversal)
        return 0;
    d = s->pos[c] >= s->pos[a] ? s->pos[c] - s->pos[a] : s->pos[a] - s->pos[c];
    return d > s->max_reversal && s->m - d > s->max_reversal;
}

/* How far the local search goes: each level adds a move. */
enum { QC__TSP_LEVEL_2OPT, QC__TSP_LEVEL_OROPT, QC__TSP_LEVEL_OR3OPT, QC__TSP_LEVEL_LK };

/* Local search from the queue until it empties, with the moves of level;
 * adds the applied gains (negative) to *delta. QC_OK or QC_ENOMEM. */
QC__HIDDEN int qc__tsp_local_search(qc__tsp *s, int level, double *delta);
/* The best Or-3opt move at a (tsp_or3opt.c); applies it, queues its ends
 * and returns 1, or 0 when none shortens the tour. *rc gets QC_ENOMEM
 * when the undo log cannot grow. */
QC__HIDDEN int qc__tsp_try_or3opt(qc__tsp *s, uint32_t a, double *delta, int *rc);
/* The best LK chain of 2-opt moves from an edge at a (tsp_or3opt.c):
 * keeps its shortest prefix, queues its ends and returns 1, or leaves the
 * tour as it was and returns 0. *rc as for qc__tsp_try_or3opt. */
QC__HIDDEN int qc__tsp_try_lk(qc__tsp *s, uint32_t a, double *delta, int *rc);
/* rounds of kick + local search at level, each kept if the tour stays
 * within slack_edges average edges of the best so far (0: only shorter
 * tours); ends at the best. sweep: on large inputs the kicks follow the
 * Hilbert order with bounded reversals (tsp_opt.c), else random. */
QC__HIDDEN int qc__tsp_perturb(qc__tsp *s, int level, uint64_t rounds, uint64_t seed,
                               double slack_edges, int sweep);

/* Removes every proper crossing, decided exactly on the caller's points, by
 * 2-opt moves (each shortens the tour, so it ends) (tsp_uncross.c). */
QC__HIDDEN int qc__tsp_uncross(qc__tsp *s);

#endif
