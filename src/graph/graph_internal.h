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

/* Sorts e[0..m) (a < b < n each) by (exact squared length, a, b), the
 * MST's order (edge_sort.c). QC_OK or QC_ENOMEM (e then in some order). */
QC__HIDDEN int qc__sort_edges(qc_ctx *ctx, const qc_vec2 *p, size_t n, qc_edge *e, size_t m);

/* The sign of |a - b|^2 - |c - d|^2, exactly (len2.c: a float filter, then
 * 128-bit or big integers): the order that makes both MST modes agree on
 * every input. */
QC__HIDDEN int qc__cmp_len2(qc_vec2 a, qc_vec2 b, qc_vec2 c, qc_vec2 d);
/*
 * Exact squared lengths as 256-bit integer keys, for sorting a group of
 * near-equal edges without a comparison in exact arithmetic per pair:
 * every finite double is an integer times 2^e for e the exponent of its
 * last mantissa bit; e, the lowest over a group's coordinates
 * (qc__len2_key_scale lowers *e, start INT_MAX), makes every
 * |ab|^2 / 2^(2e) an integer, written by qc__len2_key as key[0] 2^192 +
 * ... + key[3] (most significant first). It returns 0 when that would not
 * fit (a difference wider than 126 bits at scale e: coordinates some 2^70
 * apart in magnitude): sort such a group with qc__cmp_len2.
 */
QC__HIDDEN void qc__len2_key_scale(qc_vec2 a, qc_vec2 b, int *e);
QC__HIDDEN int qc__len2_key(qc_vec2 a, qc_vec2 b, int e, uint64_t key[4]);
/* Exponent span within which qc__cmp_len2 works in 128 bits. */
#define QC__INT_SPAN 9
/* The same in big integers alone (what qc__cmp_len2 falls back to when
 * the coordinates' exponents span more than QC__INT_SPAN); for tests. */
QC__HIDDEN int qc__cmp_len2_big(qc_vec2 a, qc_vec2 b, qc_vec2 c, qc_vec2 d);

#endif
