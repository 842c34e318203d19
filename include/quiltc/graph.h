/*
 * Graphs over point sets (paper §4.2): the Delaunay triangulation with
 * robust adaptive predicates, and the Euclidean minimum spanning tree by
 * Kruskal over the Delaunay edges or the complete graph.
 */
#ifndef QUILTC_GRAPH_H
#define QUILTC_GRAPH_H

#include "core.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Shewchuk-style adaptive exact predicates, no global state.
 * orient2d > 0 when a, b, c turn counter-clockwise; incircle > 0 when d is
 * inside the circle through CCW a, b, c. The sign is always exact. */
double qc_orient2d(qc_vec2 a, qc_vec2 b, qc_vec2 c);
double qc_incircle(qc_vec2 a, qc_vec2 b, qc_vec2 c, qc_vec2 d);

typedef enum qc_mesh_status {
    QC_MESH_OK = 0,        /* a proper triangulation */
    QC_MESH_TOO_FEW,       /* fewer than 3 distinct points: no triangle */
    QC_MESH_COLLINEAR      /* all distinct points on one line: no triangle */
} qc_mesh_status;

typedef struct qc_mesh {
    uint32_t *tri;      /* 3 indices per triangle, counter-clockwise */
    size_t ntri, tri_cap;
    qc_edges edges;     /* every Delaunay edge once (a < b); for collinear
                           input the chain of sorted neighbours */
    uint32_t *dup_of;   /* dup_of[i] == i, or the index of an earlier
                           identical point that i duplicates */
    size_t n, dup_cap;
    size_t ndup;        /* how many points duplicate an earlier one */
    int status;         /* qc_mesh_status */
} qc_mesh;

/*
 * Delaunay triangulation of p[0..n) in O(n log n) expected time. Duplicates
 * are left out of the mesh and reported in dup_of. Degenerate inputs are not
 * errors: mesh->status says which. Errors: QC_ERANGE (NaN/inf coordinate,
 * the message names the index), QC_ELIMIT (n >= 2^31), QC_ENOMEM.
 */
int qc_delaunay(qc_ctx *ctx, const qc_vec2 *p, size_t n, qc_mesh *out);
void qc_mesh_free(qc_ctx *ctx, qc_mesh *mesh);

typedef enum qc_mst_mode {
    QC_MST_MODE_DELAUNAY = 0, /* Kruskal over the Delaunay edges, O(n log n) */
    QC_MST_MODE_COMPLETE = 1  /* Kruskal over all n(n-1)/2 edges, O(n^2 log n) (the paper's) */
} qc_mst_mode;

/*
 * Euclidean MST of p[0..n): n-1 edges (a < b) into *out (appended), sorted
 * by (length, a, b): ties are broken by the smaller index pair, so both
 * modes give the identical tree. Duplicate points join by zero-length edges.
 * Errors: QC_ERANGE (NaN/inf), QC_ELIMIT (complete mode above 20000 points),
 * QC_ENOMEM.
 */
int qc_mst(qc_ctx *ctx, const qc_vec2 *p, size_t n, qc_mst_mode mode,
           qc_edges *out);

#ifdef __cplusplus
}
#endif
#endif
