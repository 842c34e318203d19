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
 * 2(n-1)+1 entries and starts and ends at root. Appended to *out.
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

/* Also the `tsp` parameter's values (qc_params.tsp, choices 1..3). */
typedef enum qc_tsp_method {
    QC_TSP_METHOD_DEFAULT = 0, /* Or-opt */
    QC_TSP_METHOD_GREEDY,      /* greedy-edge construction only */
    QC_TSP_METHOD_2OPT,        /* + 2-opt with neighbour lists, don't-look bits */
    QC_TSP_METHOD_OROPT        /* + Or-opt */
} qc_tsp_method;

typedef struct qc_tsp_params {
    int method;          /* qc_tsp_method */
    int neighbours;      /* candidate list size; 0 = 10 */
    uint64_t seed;       /* for the perturbation phase */
    uint64_t perturb_iterations; /* Or-opt perturbation rounds after local
                                    search; the core has no clock, so the CLI
                                    turns --tsp-time into rounds */
} qc_tsp_params;

/*
 * A closed tour through all n points: out receives n indices (appended),
 * starting at index 0; the closing edge back to the start is implicit.
 * With method >= 2OPT no two edges cross properly (collinear input may
 * still overlap along its line). Perturbation runs with OROPT only;
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
