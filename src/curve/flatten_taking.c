/*
 * Flattening a path the caller gives up, without the path and its flattened
 * points both whole at once (a large pattern's peak: 27 million points from
 * a path as large). The commands are flattened last to first, each one's
 * points made last to first straight into the output (a cubic's right half
 * first), and the path's point array shrinks behind the walk; the whole is
 * reversed at the end. A cubic is cut where qc_curve_flatten cuts it, so
 * the points are the same to the bit.
 */
#include <string.h>

#include "curve_internal.h"
#include "quiltc/curve.h"

typedef struct back {
    qc_ctx *ctx;
    qc_points *out;  /* the points, last to first */
    qc_order *ends;  /* where in out pieces start */
} back;

/* Appends p (the commands come last to first, each one's points backwards):
 * a piece's start, a command's first point, is recorded where it lands. */
static int to_out(void *ud, qc_vec2 p, int start)
{
    back *b = (back *)ud;
    qc_points *out = b->out;

    if (out->n >= UINT32_MAX - 1)
        return qc__fail(b->ctx, QC_ELIMIT, "flattened path exceeds 2^32 points");
    if (out->n < out->cap) /* almost always room: no call */
        out->v[out->n++] = p;
    else
        QC__TRY(qc_points_push(b->ctx, out, p));
    return start ? qc_order_push(b->ctx, b->ends, (uint32_t)(out->n - 1)) : QC_OK;
}

/* The path's points past k are read no more: their pages go back (a shrink
 * that fails leaves the path as it was). */
static void shrink_path(qc_ctx *ctx, qc_path *path, size_t k)
{
    qc_vec2 *pt;

    if (k == 0 || k > path->pt_cap - path->pt_cap / 8)
        return;
    pt = (qc_vec2 *)qc__realloc(ctx, path->pt, path->pt_cap * sizeof *pt, k * sizeof *pt);
    if (pt == NULL) {
        qc_clear_error(ctx);
        return;
    }
    path->pt = pt;
    path->pt_cap = k;
    path->npt = path->npt < k ? path->npt : k;
}

/* out (reversed) the other way round, and the starts recorded at reversed
 * positions made piece ends as qc_curve_flatten gives them. */
static int turn_round(qc_ctx *ctx, qc_points *out, qc_order *ends)
{
    size_t i, j, n = out->n, e = 0;

    for (i = 0, j = n; i + 1 < j; i++, j--) {
        qc_vec2 t = out->v[i];

        out->v[i] = out->v[j - 1];
        out->v[j - 1] = t;
    }
    for (i = 0, j = ends->n; i + 1 < j; i++, j--) {
        uint32_t t = ends->i[i];

        ends->i[i] = ends->i[j - 1];
        ends->i[j - 1] = t;
    }
    for (i = 0; i < ends->n; i++) { /* position r is n - 1 - r; the first starts nothing */
        uint32_t at = (uint32_t)(n - 1 - ends->i[i]);

        if (at > 0)
            ends->i[e++] = at;
    }
    ends->n = e;
    return n > 0 ? qc_order_push(ctx, ends, (uint32_t)n) : QC_OK;
}

int qc__curve_flatten_taking(qc_ctx *ctx, qc_path *path, double tol, qc_points *out,
                             qc_order *ends)
{
    QC__TRY(qc__curve_flatten_check(ctx, path, tol));
    return qc__curve_flatten_taking_checked(ctx, path, tol, out, ends);
}

int qc__curve_flatten_taking_checked(qc_ctx *ctx, qc_path *path, double tol, qc_points *out,
                                     qc_order *ends)
{
    back b;
    size_t c, k = 0;
    qc_vec2 zero = {0, 0};
    int rc;

    for (c = 0; c < path->ncmd; c++)
        k += QC__CURVE_CMD_POINTS(path->cmd[c]);
    b.ctx = ctx;
    b.out = out;
    b.ends = ends;
    rc = QC_OK;
    for (c = path->ncmd; c-- > 0 && rc == QC_OK;) {
        k -= QC__CURVE_CMD_POINTS(path->cmd[c]);
        rc = qc__curve_cmd(path, c, k, c > 0 ? path->pt[k - 1] : zero, tol * tol, 1, to_out, &b);
        shrink_path(ctx, path, k);
    }
    qc_path_free(ctx, path);
    return rc == QC_OK ? turn_round(ctx, out, ends) : rc;
}
