/* Helpers of the Delaunay stage split across files. Not installed. */
#ifndef QC_GRAPH_DELAUNAY_H
#define QC_GRAPH_DELAUNAY_H

#include "graph_internal.h"

/* out[0..m) = idx[0..m) reordered along a Hilbert curve of p[idx[i]]'s
 * bounding box (ties by position in idx). QC_OK or QC_ENOMEM. */
QC__HIDDEN int qc__hilbert_order(qc_ctx *ctx, const qc_vec2 *p,
                                 const uint32_t *idx, size_t m, uint32_t *out);

/* dup_of[i] = the first j <= i with p[j] == p[i] (-0 == +0); returns the
 * number of duplicates in *ndup. QC_OK or QC_ENOMEM. */
QC__HIDDEN int qc__find_duplicates(qc_ctx *ctx, const qc_vec2 *p, size_t n,
                                   uint32_t *dup_of, size_t *ndup);

/* Triangulates q[0..m) (distinct, q[0..2] not collinear, m < 2^31) and
 * sets out->tri/ntri/tri_cap and out->edges with the indices orig[] (each
 * edge once, a < b). QC_OK or QC_ENOMEM (out's arrays then freed by the
 * caller's qc_mesh_free). */
QC__HIDDEN int qc__triangulate(qc_ctx *ctx, const qc_vec2 *q,
                               const uint32_t *orig, uint32_t m, qc_mesh *out);

#endif
