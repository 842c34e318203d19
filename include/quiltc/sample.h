/*
 * Point distributions (paper §4.1), clipped to a region with its holes and
 * kept at least `margin` from every boundary edge.
 */
#ifndef QUILTC_SAMPLE_H
#define QUILTC_SAMPLE_H

#include "core.h"
#include "region.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum qc_sample_kind {
    QC_SAMPLE_TRIANGLE = 1, /* equilateral triangles: 6 neighbours at d */
    QC_SAMPLE_SQUARE,       /* grid: 4 neighbours at d */
    QC_SAMPLE_HEX,          /* honeycomb vertices: 3 neighbours at d */
    QC_SAMPLE_SNUB,         /* 3.3.4.3.4 snub square: 5 neighbours at d */
    QC_SAMPLE_POISSON       /* Bridson Poisson-disk, every pair >= d apart */
} qc_sample_kind;

typedef struct qc_sample_params {
    int kind;         /* qc_sample_kind */
    double spacing;   /* d, mm: nearest-neighbour distance (tessellations) or minimum distance (Poisson) */
    double margin;    /* mm kept from the boundary; tessellations and Poisson alike */
    uint64_t seed;    /* Poisson: the stream; tessellations: the lattice phase is fixed */
    int poisson_k;    /* Bridson's candidates per active point; 0 = 30 */
    size_t max_points;/* refuse (QC_ELIMIT) before allocating when the estimate exceeds it; 0 = QC_MAX_POINTS */
} qc_sample_params;

/*
 * Samples points inside region (normalized) into *out (appended; *out may be
 * zeroed). Errors: QC_EINVAL (unknown kind), QC_ERANGE (spacing <= 0, NaN,
 * or margin < 0), QC_ELIMIT (estimated count above max_points, or more than
 * QC_MAX_REGION_RINGS rings: refused before any large allocation), QC_ENOMEM. An empty result is QC_OK with
 * out->n == 0; callers decide whether that is an error.
 */
int qc_sample(qc_ctx *ctx, const qc_region *region, const qc_sample_params *params,
              qc_points *out);

/* Estimated count for the request (area / cell area), for limit checks. */
double qc_sample_estimate(const qc_region *region, const qc_sample_params *params);

#ifdef __cplusplus
}
#endif
#endif
