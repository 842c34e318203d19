/* Internals of the graph stage shared between its files. Not installed. */
#ifndef QC_GRAPH_INTERNAL_H
#define QC_GRAPH_INTERNAL_H

#include "internal.h"

/*
 * Stable LSD radix sort of key[0..n) by bits [shift, 64), carrying val[]
 * along when val != NULL. Digits that are equal in every key are skipped.
 * QC_OK or QC_ENOMEM (arrays untouched on failure).
 */
QC__HIDDEN int qc__radix_sort(qc_ctx *ctx, uint64_t *key, uint32_t *val,
                              size_t n, unsigned shift);

/* Checks p[0..n) for NaN/inf and n < 2^31: QC_OK, QC_ERANGE or QC_ELIMIT. */
QC__HIDDEN int qc__check_points(qc_ctx *ctx, const qc_vec2 *p, size_t n,
                                const char *who);

/* The sign of |a - b|^2 - |c - d|^2, exactly (a float filter, then
 * expansions): the order that makes both MST modes agree on every input. */
QC__HIDDEN int qc__cmp_len2(qc_vec2 a, qc_vec2 b, qc_vec2 c, qc_vec2 d);

#endif
