/* Flattening cubic Béziers by adaptive subdivision; length and bbox. */
#include <math.h>

#include "curve_internal.h"

/* Depth bound: 2^20 chords per cubic at most, whatever the input. */
#define FLAT_MAX_DEPTH 20

static int finite(qc_vec2 p)
{
    return fabs(p.x) <= 1e300 && fabs(p.y) <= 1e300;
}

static qc_vec2 half(qc_vec2 p, qc_vec2 s)
{
    qc_vec2 r;

    r.x = p.x + 0.5 * (s.x - p.x);
    r.y = p.y + 0.5 * (s.y - p.y);
    return r;
}

/* qc_cubic_split(q, 0.5, l, r), its arithmetic to the bit (lerp at t =
 * 0.5), here without the call: a million cubics split 2 million times at
 * 10^6 pattern points. l or r may be q. */
static void split_half(const qc_vec2 *q, qc_vec2 *l, qc_vec2 *r)
{
    qc_vec2 a = half(q[0], q[1]), b = half(q[1], q[2]), c = half(q[2], q[3]);
    qc_vec2 d = half(a, b), e = half(b, c), f = half(d, e);
    qc_vec2 q0 = q[0], q3 = q[3];

    l[0] = q0;
    l[1] = a;
    l[2] = d;
    l[3] = f;
    r[0] = f;
    r[1] = e;
    r[2] = c;
    r[3] = q3;
}

/* Emits the points after c[0] of one cubic. The curve lies in the hull of
 * its control points, so control points within tol of the chord bound the
 * curve's distance from each emitted chord by tol. Iterative, depth-first,
 * left half first: the output order is the curve's order. Backwards, the
 * right half goes first and the same pieces' ends come last to first (a
 * node's halves are the same whichever is sewn first: the same points). */
static int flatten_cubic(const qc_vec2 c[4], double tol2, int backwards,
                         qc__curve_point_fn fn, void *ud)
{
    qc_vec2 stack[FLAT_MAX_DEPTH + 2][4];
    int depth[FLAT_MAX_DEPTH + 2];
    int sp = 0, k, rc;

    for (k = 0; k < 4; k++)
        stack[0][k] = c[k];
    depth[0] = 0;
    sp = 1;
    while (sp > 0) {
        qc_vec2 *q = stack[sp - 1];
        int d = depth[sp - 1];

        if (d >= FLAT_MAX_DEPTH || (qc__seg_dist2(q[1], q[0], q[3]) <= tol2 &&
                                    qc__seg_dist2(q[2], q[0], q[3]) <= tol2)) {
            rc = fn(ud, q[3], 0);
            if (rc < 0)
                return rc;
            sp--;
            continue;
        }
        /* halves: the one sewn first on top, q becomes the other (popped
         * after it; the split reads q whole before it writes) */
        if (backwards)
            split_half(q, q, stack[sp]);
        else
            split_half(q, stack[sp], q);
        depth[sp - 1] = d + 1;
        depth[sp] = d + 1;
        sp++;
    }
    return QC_OK;
}

/* Command c's own points (not the pen's start before a first command). */
static int cmd_points(const qc_path *path, size_t c, size_t k, qc_vec2 cur, double tol2,
                      int backwards, qc__curve_point_fn fn, void *ud)
{
    unsigned char cmd = path->cmd[c];

    if (cmd == QC_PATH_CUBIC) {
        qc_vec2 q[4];

        qc__curve_cubic(path, k, cur, q);
        if (finite(q[0]) && finite(q[1]) && finite(q[2]) && finite(q[3]))
            return flatten_cubic(q, tol2, backwards, fn, ud);
        return fn(ud, q[3], 0); /* NaN would subdivide to the depth bound for nothing */
    }
    return fn(ud, path->pt[k], cmd == QC_PATH_MOVE);
}

int qc__curve_cmd(const qc_path *path, size_t c, size_t k, qc_vec2 cur, double tol2,
                  int backwards, qc__curve_point_fn fn, void *ud)
{
    int start = c == 0 && path->cmd[c] != QC_PATH_MOVE; /* the pen's start is a point */
    int rc = QC_OK;

    if (start && !backwards)
        rc = fn(ud, cur, 1);
    if (rc >= 0)
        rc = cmd_points(path, c, k, cur, tol2, backwards, fn, ud);
    if (rc >= 0 && start && backwards)
        rc = fn(ud, cur, 1);
    return rc;
}

int qc__curve_walk(const qc_path *path, double tol, qc__curve_point_fn fn,
                   void *ud)
{
    size_t c, k = 0;
    qc_vec2 cur = {0, 0};
    double tol2 = tol * tol;
    int rc;

    for (c = 0; c < path->ncmd; c++) {
        rc = qc__curve_cmd(path, c, k, cur, tol2, 0, fn, ud);
        if (rc < 0)
            return rc;
        k += QC__CURVE_CMD_POINTS(path->cmd[c]);
        cur = path->pt[k - 1];
    }
    return QC_OK;
}

typedef struct flat_out {
    qc_ctx *ctx;
    qc_points *pts;
    qc_order *ends;
    int any;
} flat_out;

static int collect(void *ud, qc_vec2 p, int start)
{
    flat_out *o = (flat_out *)ud;

    if (o->pts->n >= UINT32_MAX)
        return qc__fail(o->ctx, QC_ELIMIT, "flattened path exceeds 2^32 points");
    if (start && o->any && o->ends != NULL)
        QC__TRY(qc_order_push(o->ctx, o->ends, (uint32_t)o->pts->n));
    o->any = 1;
    return qc_points_push(o->ctx, o->pts, p);
}

int qc__curve_flatten_check(qc_ctx *ctx, const qc_path *path, double tol)
{
    size_t i;

    if (!(tol > 0) || tol > 1e6)
        return qc__fail(ctx, QC_ERANGE,
                        "flattening tolerance %g mm must be > 0", tol);
    for (i = 0; i < path->npt; i++)
        if (!finite(path->pt[i]))
            return qc__fail(ctx, QC_ERANGE, "path point %lu (%g, %g) is not finite",
                            (unsigned long)i, path->pt[i].x, path->pt[i].y);
    return QC_OK;
}

int qc_curve_flatten(qc_ctx *ctx, const qc_path *path, double tol,
                     qc_points *out, qc_order *piece_end)
{
    flat_out o;
    size_t n0 = out->n, e0 = piece_end != NULL ? piece_end->n : 0;
    int rc;

    QC__TRY(qc__curve_flatten_check(ctx, path, tol));
    o.ctx = ctx;
    o.pts = out;
    o.ends = piece_end;
    o.any = 0;
    rc = qc__curve_walk(path, tol, collect, &o);
    if (rc == QC_OK && o.any && piece_end != NULL)
        rc = qc_order_push(ctx, piece_end, (uint32_t)out->n);
    if (rc < 0) { /* as on entry (core.h) */
        out->n = n0;
        if (piece_end != NULL)
            piece_end->n = e0;
    }
    return rc;
}

typedef struct measure {
    qc_vec2 last;
    double len;
    qc_bbox box;
    int any;
} measure;

static int measure_point(void *ud, qc_vec2 p, int start)
{
    measure *m = (measure *)ud;

    if (!start && m->any)
        m->len += qc_hypot(p.x - m->last.x, p.y - m->last.y);
    qc__box_take(&m->box, &m->any, p);
    m->last = p;
    return QC_OK;
}

static measure measure_path(const qc_path *path, double tol)
{
    measure m;

    m.last.x = m.last.y = 0;
    m.len = 0;
    m.box.min = m.last;
    m.box.max = m.last;
    m.any = 0;
    if (!(tol > 0))
        tol = 0.01;
    (void)qc__curve_walk(path, tol, measure_point, &m);
    return m;
}

double qc_curve_length(const qc_path *path, double tol)
{
    return measure_path(path, tol).len;
}

qc_bbox qc_curve_bbox(const qc_path *path, double tol)
{
    return measure_path(path, tol).box;
}
