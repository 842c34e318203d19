/*
 * Internals of the quilt stage: the seam graph (seams.c) every patch
 * boundary lies on, and the shortest travel along it (seam_route.c).
 */
#ifndef QC_QUILT_INTERNAL_H
#define QC_QUILT_INTERNAL_H

#include "internal.h"

/*
 * The seams of a top: every patch vertex, those within tol of each other
 * merged, and every patch edge split where another patch's vertex lies on
 * it (a T-junction), so two patches sharing a seam share its graph edges.
 * Vertices are numbered in order of x (then y). Each ring of each patch is
 * kept as its refined list of vertex numbers.
 */
typedef struct qc__seams {
    qc_vec2 *v;          /* seam vertices */
    size_t nv;
    uint32_t *adj_start; /* neighbours of k: adj[adj_start[k] .. adj_start[k+1]) */
    uint32_t *adj;
    size_t nadj;
    uint32_t *bnd;       /* the rings' vertex numbers, ring after ring (closed implicitly) */
    size_t nbnd;
    size_t *ring_end;    /* ring r: bnd[r ? ring_end[r-1] : 0 .. ring_end[r]) */
    size_t nrings;
    size_t *patch_end;   /* patch i: rings [i ? patch_end[i-1] : 0 .. patch_end[i]) */
    size_t npatch;
    size_t v_cap, bnd_cap, ring_cap, adj_cap; /* allocated sizes, for freeing */
} qc__seams;

QC__HIDDEN int qc__seams_build(qc_ctx *ctx, const qc_patches *ps, double tol, qc__seams *out);
QC__HIDDEN void qc__seams_free(qc_ctx *ctx, qc__seams *s);

/* A point on a seam: on the graph edge u-v (u == v: at vertex u). */
typedef struct qc__seam_pt {
    qc_vec2 p;
    uint32_t u, v;
} qc__seam_pt;

/* The point of patch i's boundary nearest p. */
QC__HIDDEN qc__seam_pt qc__seams_nearest(const qc__seams *s, size_t patch, qc_vec2 p);

/* Shortest distances along the seams from one seam point (Dijkstra). */
typedef struct qc__seam_dist {
    double *d;       /* per vertex; HUGE_VAL when unreachable */
    uint32_t *prev;  /* previous vertex on the way; UINT32_MAX at the source */
    qc__seam_pt from;
    struct { double d; uint32_t k; } *heap;
    size_t nheap, heap_cap;
} qc__seam_dist;

QC__HIDDEN int qc__seam_dist_init(qc_ctx *ctx, const qc__seams *s, qc__seam_dist *sd);
QC__HIDDEN void qc__seam_dist_free(qc_ctx *ctx, const qc__seams *s, qc__seam_dist *sd);
QC__HIDDEN int qc__seam_dist_from(qc_ctx *ctx, const qc__seams *s, qc__seam_dist *sd,
                                  qc__seam_pt from);
/* The length of the shortest travel from sd->from to `to` (HUGE_VAL when
 * the seams do not connect them); with path != NULL its points (from
 * first, to last) are appended to *path. */
QC__HIDDEN double qc__seam_travel(qc_ctx *ctx, const qc__seams *s, const qc__seam_dist *sd,
                                  qc__seam_pt to, qc_points *path, int *rc);

/* A patch's pattern flattened, its segments in a grid (links.c): for the
 * straight links between the pattern and the seams. */
typedef struct qc__links {
    qc_points flat;
    qc_order ends;  /* where each piece of flat ends */
    qc__seg_grid grid;
    int have_grid;
} qc__links;

QC__HIDDEN int qc__links_init(qc_ctx *ctx, const qc_path *pattern, qc__links *lk);
QC__HIDDEN void qc__links_free(qc_ctx *ctx, qc__links *lk);
/* The seam point of patch `patch` (its region) to link p to: the nearest
 * when that link crosses no pattern segment, else the nearest of a bounded
 * number of others whose link crosses none and stays inside the patch,
 * else the nearest. */
QC__HIDDEN qc__seam_pt qc__links_seam_pt(const qc__links *lk, const qc__seams *s,
                                         const qc_region *region, size_t patch, qc_vec2 p);

#endif
