/* Internals of curve/: the allocation-free flattening walk shared by
 * qc_curve_flatten, qc_curve_length and qc_curve_bbox. */
#ifndef QC_CURVE_INTERNAL_H
#define QC_CURVE_INTERNAL_H

#include "internal.h"

/* Receives each flattened point; start != 0 marks the first point of a piece.
 * A negative return stops the walk and is returned by qc__curve_walk. */
typedef int (*qc__curve_point_fn)(void *ud, qc_vec2 p, int start);

/* Walks path's points in order, cubics subdivided until their control points
 * lie within tol of the chord. A path not starting with MOVE starts at its
 * first command's start, (0, 0). Returns QC_OK or the callback's status. */
QC__HIDDEN int qc__curve_walk(const qc_path *path, double tol,
                              qc__curve_point_fn fn, void *ud);

/* The control points of the cubic command whose points start at
 * path->pt[k], the pen standing at cur. */
static inline void qc__curve_cubic(const qc_path *path, size_t k, qc_vec2 cur, qc_vec2 q[4])
{
    q[0] = cur;
    q[1] = path->pt[k];
    q[2] = path->pt[k + 1];
    q[3] = path->pt[k + 2];
}

/* Points a command takes of the path's point array, as the walk reads them. */
#define QC__CURVE_CMD_POINTS(cmd) ((cmd) == QC_PATH_CUBIC ? 3u : 1u)

/* The points of command c alone (qc__curve_walk's step): its points start
 * at path->pt[k], the pen stands at cur; tol2 is the tolerance squared.
 * backwards != 0 gives the same points last to first. */
QC__HIDDEN int qc__curve_cmd(const qc_path *path, size_t c, size_t k, qc_vec2 cur,
                             double tol2, int backwards, qc__curve_point_fn fn, void *ud);

/* qc_curve_flatten's refusals: a tolerance out of range, a point not finite. */
QC__HIDDEN int qc__curve_flatten_check(qc_ctx *ctx, const qc_path *path, double tol);

/* qc_curve_flatten into empty out and ends for a path it frees, the path
 * shrinking as the points grow (flatten_taking.c): the same points. */
QC__HIDDEN int qc__curve_flatten_taking(qc_ctx *ctx, qc_path *path, double tol,
                                        qc_points *out, qc_order *ends);
/* The same for a caller that has made qc__curve_flatten_check's checks
 * itself (the stitch plan: every point within 1e6 mm, tol in (0, 1000]),
 * without a second pass over the path's points. */
QC__HIDDEN int qc__curve_flatten_taking_checked(qc_ctx *ctx, qc_path *path, double tol,
                                                qc_points *out, qc_order *ends);

/* Widens box to hold p; the first point (*any == 0) sets it. Comparisons,
 * not fmin/fmax (a call per point): a NaN coordinate gives way as in fmin. */
static inline void qc__box_take(qc_bbox *box, int *any, qc_vec2 p)
{
    if (!*any) {
        box->min = p;
        box->max = p;
        *any = 1;
        return;
    }
    if (p.x < box->min.x || box->min.x != box->min.x)
        box->min.x = p.x;
    if (p.y < box->min.y || box->min.y != box->min.y)
        box->min.y = p.y;
    if (-p.x < -box->max.x || box->max.x != box->max.x)
        box->max.x = p.x;
    if (-p.y < -box->max.y || box->max.y != box->max.y)
        box->max.y = p.y;
}

#endif
