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
 * orient2d > 0 when a, b, c turn counter-clockwise (< 0 clockwise, 0
 * collinear); incircle > 0 when d is inside the circle through CCW a, b, c
 * (< 0 outside, 0 on it). The sign is exact for finite input whose
 * intermediate products neither overflow nor underflow (|coordinates| within
 * about 1e-70..1e70); the magnitude is only an approximation. */
double qc_orient2d(qc_vec2 a, qc_vec2 b, qc_vec2 c);
double qc_incircle(qc_vec2 a, qc_vec2 b, qc_vec2 c, qc_vec2 d);

typedef enum qc_mesh_status {
    QC_MESH_OK = 0,        /* a proper triangulation */
    QC_MESH_TOO_FEW,       /* fewer than 3 distinct points: no triangle */
    QC_MESH_COLLINEAR      /* all distinct points on one line: no triangle */
} qc_mesh_status;

typedef struct qc_mesh {
    uint32_t *tri;      /* 3 indices per triangle, counter-clockwise */
    size_t ntri, tri_cap; /* triangles used / allocated (3 indices each) */
    qc_edges edges;     /* every Delaunay edge once (a < b); for collinear
                           input the chain of sorted neighbours */
    uint32_t *dup_of;   /* dup_of[i] == i, or the index of an earlier
                           identical point that i duplicates */
    size_t n, dup_cap;
    size_t ndup;        /* how many points duplicate an earlier one */
    int status;         /* qc_mesh_status */
} qc_mesh;

/*
 * Delaunay triangulation of p[0..n) (any units), incremental insertion in
 * Hilbert-curve order, O(n log n) expected time, about 150 bytes per point
 * at peak. Every triangle's circumcircle is empty (qc_incircle <= 0 for all
 * points); cocircular sets such as lattices get one valid triangulation,
 * the same on every platform. Duplicates (-0 == +0) are left out of the mesh
 * and reported in dup_of (the first copy is kept). Degenerate inputs are not
 * errors: out->status says which (edges: QC_MESH_TOO_FEW gives the one edge
 * of 2 distinct points, QC_MESH_COLLINEAR the chain along the line).
 * *out is overwritten (zeroed first) and owned by the caller: release it
 * with qc_mesh_free, also after an error (harmless on a zeroed mesh).
 * Errors: QC_ERANGE (NaN/inf coordinate, the message names the index),
 * QC_ELIMIT (n >= 2^31), QC_ENOMEM.
 */
int qc_delaunay(qc_ctx *ctx, const qc_vec2 *p, size_t n, qc_mesh *out);
void qc_mesh_free(qc_ctx *ctx, qc_mesh *mesh);

/* Also the `mst` parameter's values (qc_params.mst, choices 1..2). */
typedef enum qc_mst_mode {
    QC_MST_MODE_DEFAULT = 0,  /* Delaunay */
    QC_MST_MODE_DELAUNAY = 1, /* Kruskal over the Delaunay edges, O(n log n) */
    QC_MST_MODE_COMPLETE = 2  /* the complete graph (the paper's), O(n^2) */
} qc_mst_mode;

/*
 * Euclidean MST of p[0..n): n-1 edges (a < b) appended to *out (nothing for
 * n < 2), sorted by (squared length as computed in double, a, b): a strict
 * total order, so the tree is unique and both modes give it edge for edge.
 * Duplicate points join their first copy by zero-length edges; collinear
 * input gives the chain. DELAUNAY mode: Kruskal over the Delaunay edges.
 * COMPLETE mode: the complete graph by a dense O(n^2)-time, O(n)-memory Prim
 * (Kruskal over n^2/2 edges would need gigabytes). On error *out keeps its
 * previous contents. Errors: QC_EINVAL (unknown mode), QC_ERANGE (NaN/inf,
 * the message names the index), QC_ELIMIT (n >= 2^30, or complete mode above
 * 20000 points), QC_ENOMEM.
 */
int qc_mst(qc_ctx *ctx, const qc_vec2 *p, size_t n, qc_mst_mode mode,
           qc_edges *out);

#ifdef __cplusplus
}
#endif
#endif
