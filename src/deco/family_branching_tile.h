/*
 * Branching tiles (paper §7.1, Fig. 27), used by family_branching.c: the skeleton
 * with the tile's two ports added as leaves and walked from the entry port
 * to the exit port, the neighbouring copies for wrapped collision tests,
 * and the layout of the finished tile.
 */
#ifndef QC_BRANCHING_TILE_H
#define QC_BRANCHING_TILE_H

#include "deco_internal.h"

typedef struct qc__btile {
    qc_vec2 *p;        /* the skeleton's points, then the entry and exit ports */
    qc_edge *e;        /* its edges, then the two port stubs */
    size_t n, ne;      /* points and edges, ports and stubs included */
    qc_order order;    /* the walk: entry port first, exit port last */
    qc_vec2 entry, exit;
    double dx, dy;     /* from a tile to its right-hand / upper neighbour */
    qc_vec2 shift[14]; /* where the neighbours sit: 2 (edge-to-edge), 8 (all-over)
                        * or 14 (all-over, rows offset) */
    size_t nshift;
    qc_vec2 *tmp;      /* scratch for shifted polygons */
    size_t tmp_cap;
} qc__btile;

/*
 * Builds the tile's skeleton into *t and views it as *out: the ports of
 * region (qc_tile_ports) join the nearest points whose stubs cross no tree
 * edge (the entry's point is the root), and the walk visits, at each node,
 * the other children counter-clockwise from the parent before the child
 * towards the exit, so it ends at the exit port without coming back. Every
 * edge off the entry-exit path is walked down and back, the path once.
 * all_over: neighbours above and below too. Errors: QC_EINVAL (no tree, or
 * the ports), QC_ENOMEM; *t is then freed.
 */
QC__HIDDEN int qc__btile_make(qc_ctx *ctx, const qc_region *region, const qc_skeleton *skel,
                              int all_over, qc__btile *t, qc_skeleton *out);
/* Rows laid out with an offset (qc_tile_layout): an all-over tile's
 * neighbours above and below sit row_offset tiles to either side. */
QC__HIDDEN void qc__btile_offset_rows(qc__btile *t, double row_offset);
QC__HIDDEN void qc__btile_free(qc_ctx *ctx, qc__btile *t);

/* Sets the vine's tangents at the ports horizontal (so copies join
 * smoothly) and its ends exactly on the ports. The vine: MOVE then cubics. */
QC__HIDDEN void qc__btile_flat_ports(const qc__btile *t, qc_path *vine);

/* Adds poly to g, and its copies moved to each neighbour that overlap the
 * grid's box: collisions wrap across the tile's edges. */
QC__HIDDEN int qc__btile_grid_add(qc_ctx *ctx, qc__btile *t, qc__cgrid *g, const qc_vec2 *poly,
                                  size_t n, unsigned kind, uint32_t id);

/* Appends cols x rows copies of tile to out (qc_tile_layout, the rows lifted
 * so the bottom row sits on the tile's box). On error out is as it was. */
QC__HIDDEN int qc__btile_layout(qc_ctx *ctx, const qc__btile *t, const qc_params *prm,
                                const qc_path *tile, qc_path *out);

#endif
