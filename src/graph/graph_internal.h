/* Internals of the graph stage shared between its files. Not installed. */
#ifndef QC_GRAPH_INTERNAL_H
#define QC_GRAPH_INTERNAL_H

#include "internal.h"

/* Checks p[0..n) for NaN/inf, coordinates that are 0 or between
 * QC__COORD_MIN and QC__COORD_MAX mm in magnitude, and n < 2^31: QC_OK,
 * QC_ERANGE or QC_ELIMIT. */
#define QC__COORD_MIN 1e-40
#define QC__COORD_MAX 1e30
QC__HIDDEN int qc__check_points(qc_ctx *ctx, const qc_vec2 *p, size_t n,
                                const char *who);

/* qc_delaunay for points qc__check_points has already passed (qc_mst). */
QC__HIDDEN int qc__delaunay_checked(qc_ctx *ctx, const qc_vec2 *p, size_t n, qc_mesh *out);

/* The sign of |a - b|^2 - |c - d|^2, exactly (len2.c: a float filter, then
 * 128-bit or big integers): the order that makes both MST modes agree on
 * every input. */
QC__HIDDEN int qc__cmp_len2(qc_vec2 a, qc_vec2 b, qc_vec2 c, qc_vec2 d);
/*
 * Exact squared lengths as 128-bit integers. Coordinates whose exponents
 * lie within QC__INT_SPAN of each other (the points of one pattern) are all
 * integers times 2^e for e their lowest exponent (qc__int_span_add
 * accumulates it in *lo, *hi; 0 for subnormals, inf and NaN), each below
 * 2^62; then qc__len2_int gives |ab|^2 / 2^(2e) exactly as hi 2^64 + lo.
 */
#define QC__INT_SPAN 9
QC__HIDDEN int qc__int_span_add(double x, int *lo, int *hi);
QC__HIDDEN void qc__len2_int(qc_vec2 a, qc_vec2 b, int e, uint64_t *hi, uint64_t *lo);
/* The same in big integers alone (what qc__cmp_len2 falls back to when
 * the coordinates' exponents span more than QC__INT_SPAN); for tests. */
QC__HIDDEN int qc__cmp_len2_big(qc_vec2 a, qc_vec2 b, qc_vec2 c, qc_vec2 d);

#endif
