/*
 * A spatial index over a region's boundary edges, for the many inside and
 * near-the-boundary questions sampling asks (10^6 points against a
 * 10^5-vertex outline); the region, sample and pattern stages share it, so
 * it lives in the core. Not installed. An outline of many edges also gets
 * a finer raster of cells that knows, per cell, how many rings of cells no
 * edge passes through surround it and which side it lies on: most queries
 * end there, exactly, without looking at an edge.
 */
#ifndef QC_REGION_INDEX_H
#define QC_REGION_INDEX_H

#include "internal.h"

typedef struct qc__rindex {
    const qc_region *region;
    uint32_t *next;         /* next[a] = the other end of the edge from vertex a */
    qc_bbox box;
    double cell;            /* square grid cell size, mm */
    size_t nx, ny;
    uint32_t *cell_start;   /* nx*ny+1 offsets into cell_edge (CSR) */
    uint32_t *cell_edge;    /* edge = index of its first vertex in region->v */
    size_t ncell_edge;
    double band;            /* horizontal band height for the ray test */
    size_t nband;
    uint32_t *band_start;   /* nband+1 offsets into band_edge */
    uint32_t *band_edge;
    size_t nband_edge;
    /* the finer raster (info NULL: none): per cell the Chebyshev distance,
     * in cells, to the nearest cell an edge passes through (the low bits,
     * capped at QC__RINDEX_RINGS), and QC__RINDEX_INSIDE when that is 2 or
     * more and the cell lies inside */
    unsigned char *info;
    double fcell, slack; /* its cell size; slack: what a bound from it allows for rounding */
    size_t fnx, fny;
} qc__rindex;

#define QC__RINDEX_RINGS 127u
#define QC__RINDEX_INSIDE 128u

/* Indexes region's edges (region must outlive the index). QC_OK, QC_ENOMEM. */
QC__HIDDEN int qc__rindex_build(qc_ctx *ctx, const qc_region *region, qc__rindex *ix);
QC__HIDDEN void qc__rindex_free(qc_ctx *ctx, qc__rindex *ix);
/* How edge ab meets the ray from p towards +x: 2 when p lies on ab, 1 when
 * the ray crosses it (the even-odd rule's count), else 0. */
QC__HIDDEN int qc__ray_edge(qc_vec2 p, qc_vec2 a, qc_vec2 b);
/* As qc_region_contains. */
QC__HIDDEN int qc__rindex_contains(const qc__rindex *ix, qc_vec2 p);
/* Whether some boundary edge is closer to p than r. */
QC__HIDDEN int qc__rindex_near(const qc__rindex *ix, qc_vec2 p, double r);
/* Inside and at least margin from every edge. */
QC__HIDDEN int qc__rindex_admits(const qc__rindex *ix, qc_vec2 p, double margin);
/* 1 when all of box b lies inside the region, no boundary edge's box
 * meeting it; 0 when it may not (near an edge, outside, or a box too large
 * to check cheaply): a fast path for callers that would otherwise sample
 * the box's contents point by point. */
QC__HIDDEN int qc__rindex_box_inside(const qc__rindex *ix, qc_bbox b);

#endif
