/*
 * Wanderer's shortcut for its joins (family_wanderer_chain.c), shared with
 * family_wanderer.c and the tests.
 */
#ifndef QC_FAMILY_WANDERER_H
#define QC_FAMILY_WANDERER_H

#include "deco_internal.h"

/* A polyline kept beside the collision grid, its segment boxes worked out
 * once: the join sewn last, which most failing joins cross. */
enum { QC__WCHAIN_MAX = 32, QC__WCHAIN_GROUP = 4 };

typedef struct qc__wchain {
    qc_vec2 p[QC__WCHAIN_MAX + 1];
    qc_bbox seg[QC__WCHAIN_MAX];
    qc_bbox grp[QC__WCHAIN_MAX / QC__WCHAIN_GROUP]; /* of QC__WCHAIN_GROUP segments each */
    qc_bbox all;  /* of every segment */
    size_t n; /* points, 0: none kept */
} qc__wchain;

/* Keeps pts[0..n) (2 <= n <= QC__WCHAIN_MAX + 1) in c. */
QC__HIDDEN void qc__wchain_set(qc__wchain *c, const qc_vec2 *pts, size_t n);

/* 1 if segment s[0..1] touches a segment of c (the test below, one segment). */
QC__HIDDEN int qc__wchain_seg_touch(const qc__wchain *c, const qc_vec2 *s);


/* 1 if a segment k of the polyline q[0..nq) that skip(ud, k) does not
 * exempt touches a segment of c, by the collision grid's own pair test
 * (boxes within 1e-9 mm, then separating axes): a hit here is one that
 * qc__cgrid_hit_polyline finds for c's chain too, so a query may stop at it. */
QC__HIDDEN int qc__wchain_touch(const qc__wchain *c, const qc_vec2 *q, size_t nq,
                                int (*skip)(void *ud, size_t k), void *ud);

#endif
