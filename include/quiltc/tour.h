/*
 * Visiting orders (paper §4.2): the depth-first walk of a tree with children
 * taken counter-clockwise from the parent, and a TSP tour.
 */
#ifndef QUILTC_TOUR_H
#define QUILTC_TOUR_H

#include "core.h"

#ifdef __cplusplus
extern "C" {
#endif

/*
 * Depth-first walk of the tree (p, edges; n points, n-1 edges, connected)
 * from root. At each node the children are visited counter-clockwise,
 * starting from the direction of the parent (for the root: from the +x
 * axis). Every tree edge is traversed twice, down and back, so the walk has
 * 2(n-1)+1 entries and starts and ends at root. Appended to *out (on error
 * as on entry, core.h).
 * Errors: QC_EINVAL (root out of range, or the edges are not a spanning
 * tree: the message says why), QC_ENOMEM.
 */
int qc_tree_walk(qc_ctx *ctx, const qc_vec2 *p, size_t n, const qc_edge *edges,
                 size_t nedges, uint32_t root, qc_order *out);
/*
 * As qc_tree_walk, but the walk ends at end without coming back (a tile's
 * exit port, paper §7.1): at each node on the path from root to end, the
 * child towards end is visited last, after every other branch has been
 * sewn down and back. 2(n-1)+1 - depth(end) entries; end == root gives
 * qc_tree_walk. Errors: as qc_tree_walk (also end out of range).
 */
int qc_tree_walk_to(qc_ctx *ctx, const qc_vec2 *p, size_t n, const qc_edge *edges,
                    size_t nedges, uint32_t root, uint32_t end, qc_order *out);

/* Index of the point nearest q (lowest index on ties); 0 for n == 0. */
uint32_t qc_nearest_point(const qc_vec2 *p, size_t n, qc_vec2 q);

/* Also the `tsp` parameter's values (qc_params.tsp, choices 1..4). */
typedef enum qc_tsp_method {
    QC_TSP_METHOD_DEFAULT = 0, /* Or-3opt */
    QC_TSP_METHOD_GREEDY,      /* greedy-edge construction only */
    QC_TSP_METHOD_2OPT,        /* + 2-opt with neighbour lists, don't-look bits */
    QC_TSP_METHOD_OROPT,       /* + Or-opt */
    QC_TSP_METHOD_OR3OPT       /* + Or-3opt (sequential 3-opt segment moves),
                                  QC_TSP_OR3OPT_KICKS(n) kicks and Or-3opt again;
                                  perturbation rounds then search with Or-3opt
                                  and LK chains of 2-opt moves */
} qc_tsp_method;

/* The kicks Or-3opt always spends on n points, before perturb_iterations:
 * each a segment-local double bridge re-optimised around its ends by
 * 2-opt and Or-opt, the walk going on from tours up to half an average
 * edge longer than the best and ending at the best. From 50,000 points
 * fewer (0.3n: at 624,100 points 11% less time for 0.09% of length). */
#define QC_TSP_OR3OPT_KICKS(n) \
    ((uint64_t)(n) >= 50000 ? (uint64_t)(n) * 3 / 10 : (uint64_t)(n) * 11 / 20)

typedef struct qc_tsp_params {
    int method;          /* qc_tsp_method */
    int neighbours;      /* candidate list size; 0 = 10 (9 for Or-3opt
                            without perturb_iterations) */
    uint64_t seed;       /* for the perturbation phase */
    uint64_t perturb_iterations; /* extra perturbation rounds (kicks) after
                                    local search; the core has no clock, so
                                    a time budget becomes rounds through
                                    qc_tsp_rounds_for_ms */
} qc_tsp_params;

/*
 * The perturbation rounds standing for a budget of ms milliseconds: a
 * fixed work count (QC_TSP_ROUNDS_PER_MS per ms, measured on TSPLIB
 * instances of 10^3-10^4 points on a 2020s desktop core), never a clock,
 * so a tour's bytes do not depend on the machine's speed. 0 for ms <= 0 or
 * NaN; at most 2^62.
 */
#define QC_TSP_ROUNDS_PER_MS 50
uint64_t qc_tsp_rounds_for_ms(double ms);

/*
 * A closed tour through all n points: out receives n indices (appended),
 * starting at index 0; the closing edge back to the start is implicit.
 * With method >= 2OPT no two edges cross properly (collinear input may
 * still overlap along its line). Perturbation runs with OROPT and OR3OPT;
 * neighbours is capped at 32. n <= 3 is returned in index order.
 * Errors: QC_EINVAL (unknown method, negative neighbours, NULL arrays),
 * QC_ERANGE (NaN/inf or beyond 1e150), QC_ELIMIT (above 2^28 points),
 * QC_ENOMEM.
 */
int qc_tsp(qc_ctx *ctx, const qc_vec2 *p, size_t n, const qc_tsp_params *params,
           qc_order *out);

/* Length of the closed tour order[0..m) over p, mm. */
double qc_tour_length(const qc_vec2 *p, const uint32_t *order, size_t m, int closed);

#ifdef __cplusplus
}
#endif
#endif
