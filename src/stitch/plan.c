/* The stitch plan: flatten, clip, merge short and split long segments, tie off. */
#include <math.h>
#include <string.h>

#include "../curve/curve_internal.h"
#include "quiltc/curve.h"
#include "stitch_internal.h"

#define DEF_TOLERANCE 0.127
#define DEF_MIN_SEGMENT 0.508
#define DEF_TIE_LENGTH 0.5
#define MAX_TIE_STITCHES 100
/* mm: a corner's stitch shorter than this is merged all the same: check
 * calls stitches under 0.1 mm faults, and rounding both ends to the 0.001 in
 * of .pat and .qli can shorten one by 2 * 0.0005 * sqrt(2) in = 0.036 mm */
#define MIN_CORNER_STITCH 0.15
/* mm a merge may move the path: 0.001 in, what the rounding of .pat and
 * .qli moves it anyway (a pebble can hug a seam 0.05 mm away) */
#define MERGE_STRAY 0.0254

void qc_plan_free(qc_ctx *ctx, qc_plan *plan)
{
    if (plan == NULL)
        return;
    qc__free(ctx, plan->p, plan->cap * sizeof *plan->p);
    qc__free(ctx, plan->flags, plan->cap);
    memset(plan, 0, sizeof *plan);
}

/* Grows both arrays to a new capacity at once, so a failure leaves the plan
 * exactly as it was (both blocks keep the old capacity). An empty plan
 * takes exactly what is asked: build() reserves its counted points. */
static int plan_grow(qc_ctx *ctx, qc_plan *plan, size_t need)
{
    size_t cap = plan->cap ? plan->cap : need > 16 ? need : 16;
    qc_vec2 *p;
    unsigned char *f;

    while (cap < need) {
        if (cap > ((size_t)-1) / 2 / sizeof *p)
            return qc__fail(ctx, QC_ENOMEM, "out of memory: plan of %lu points",
                            (unsigned long)need);
        cap *= 2;
    }
    p = (qc_vec2 *)qc__alloc_array(ctx, cap, sizeof *p);
    if (p == NULL)
        return QC_ENOMEM;
    f = (unsigned char *)qc__alloc(ctx, cap);
    if (f == NULL) {
        qc__free(ctx, p, cap * sizeof *p);
        return qc__fail(ctx, QC_ENOMEM, "out of memory: plan of %lu points",
                        (unsigned long)need);
    }
    if (plan->n > 0) {
        memcpy(p, plan->p, plan->n * sizeof *p);
        memcpy(f, plan->flags, plan->n);
    }
    qc__free(ctx, plan->p, plan->cap * sizeof *plan->p);
    qc__free(ctx, plan->flags, plan->cap);
    plan->p = p;
    plan->flags = f;
    plan->cap = cap;
    return QC_OK;
}

/* qc_plan_push, static so the stitch loop (build makes the room first, so
 * it rarely grows) stores without a call per point. */
static int plan_add(qc_ctx *ctx, qc_plan *plan, qc_vec2 p, unsigned flags)
{
    if (plan->n >= plan->cap)
        QC__TRY(plan_grow(ctx, plan, plan->n + 1));
    plan->p[plan->n] = p;
    plan->flags[plan->n] = (unsigned char)flags;
    plan->n++;
    return QC_OK;
}

int qc_plan_push(qc_ctx *ctx, qc_plan *plan, qc_vec2 p, unsigned flags)
{
    return plan_add(ctx, plan, p, flags);
}

typedef struct resolved {
    double tol, min_seg, max_seg, tie_len;
    double floor_len, keep; /* the merge's: MIN_CORNER_STITCH and MERGE_STRAY at most */
    /* a stitch whose square is at most this is shorter than max_seg,
     * whatever the square root rounds to: no root, no split (HUGE_VAL
     * without a maximum) */
    double short2;
    int ties;
} resolved;

static int resolve(qc_ctx *ctx, const qc_stitch_params *in, resolved *r)
{
    qc_stitch_params z;

    if (in == NULL) {
        memset(&z, 0, sizeof z);
        in = &z;
    }
    r->tol = in->tolerance == 0 ? DEF_TOLERANCE : in->tolerance;
    r->min_seg = in->min_segment == 0 ? DEF_MIN_SEGMENT
                 : in->min_segment < 0 ? 0 : in->min_segment;
    r->max_seg = in->max_segment;
    r->tie_len = in->tie_length == 0 ? DEF_TIE_LENGTH : in->tie_length;
    r->floor_len = fmin(r->min_seg, MIN_CORNER_STITCH);
    r->keep = fmin(r->tol, MERGE_STRAY);
    r->ties = in->tie_stitches;
    r->short2 = r->max_seg > 0 ? r->max_seg * r->max_seg * (1 - 1e-9) : HUGE_VAL;
    if (!(r->tol > 0 && r->tol <= 1000))
        return qc__fail(ctx, QC_ERANGE,
                        "stitch tolerance %g mm must be in (0, 1000]", in->tolerance);
    if (!(r->min_seg >= 0 && r->min_seg <= 1000))
        return qc__fail(ctx, QC_ERANGE,
                        "minimum segment %g mm must be <= 1000", in->min_segment);
    if (!(r->max_seg >= 0 && r->max_seg <= 1e6) ||
        (r->max_seg > 0 && r->max_seg < 0.01))
        return qc__fail(ctx, QC_ERANGE,
                        "maximum segment %g mm must be 0 (no limit) or in [0.01, 1e6]",
                        in->max_segment);
    if (r->max_seg > 0 && r->max_seg < r->min_seg)
        return qc__fail(ctx, QC_ERANGE,
                        "maximum segment %g mm is below the minimum segment %g mm",
                        r->max_seg, r->min_seg);
    if (r->ties < 0 || r->ties > MAX_TIE_STITCHES)
        return qc__fail(ctx, QC_ERANGE, "tie stitches %d must be in [0, %d]",
                        r->ties, MAX_TIE_STITCHES);
    if (!(r->tie_len > 0 && r->tie_len <= 100))
        return qc__fail(ctx, QC_ERANGE, "tie length %g mm must be in (0, 100]",
                        in->tie_length);
    return QC_OK;
}

static double dist(qc_vec2 a, qc_vec2 b)
{
    return qc_hypot(b.x - a.x, b.y - a.y);
}

static qc_vec2 along(qc_vec2 at, qc_vec2 towards, double l)
{
    double d = dist(at, towards);
    qc_vec2 q;

    if (l >= d)
        return towards; /* exactly on the next point, not a rounding away */
    q.x = at.x + (towards.x - at.x) / d * l;
    q.y = at.y + (towards.y - at.y) / d * l;
    return q;
}

/* N stitches back and forth between at and at + l along towards. */
static int tie_off(qc_ctx *ctx, qc_plan *out, qc_vec2 at, qc_vec2 towards, double l,
                   const resolved *r)
{
    qc_vec2 far = along(at, towards, l);
    int k;

    for (k = 1; k <= r->ties; k++)
        QC__TRY(plan_add(ctx, out, (k & 1) ? far : at, QC_ST_TIE));
    return QC_OK;
}

/* Whether the stitch from stop (where the start tie leaves the needle) may
 * skip m[1..i] and run to m[i + 1]: m[i] is too close to stop to sew to,
 * or the skip keeps the shape, as in the merge (a corner stays). */
static int skippable(const qc_vec2 *m, size_t i, qc_vec2 stop, const resolved *r)
{
    size_t j;

    if (dist(stop, m[i]) < r->floor_len)
        return 1;
    for (j = 1; j <= i; j++)
        if (qc__seg_dist2(m[j], stop, m[i + 1]) > r->keep * r->keep)
            return 0;
    return 1;
}

/* The start tie's length (*l) and the first point sewn after it. An odd tie
 * leaves the needle l along the first segment; points closer than min_seg
 * to it are dropped as the merge drops them (a corner stays, nothing under
 * floor_len does). If that would drop the piece's last point, or m[1] is a
 * corner that close, the tie runs to m[1] instead (and m[1] is where the
 * needle stands); a later corner that close stays as a short stitch. */
static size_t start_tie(const qc_vec2 *m, size_t n, const resolved *r, double *l)
{
    qc_vec2 stop;
    size_t i = 1;

    *l = fmin(r->tie_len, dist(m[0], m[1]));
    if (!(r->ties & 1))
        return 1;
    stop = along(m[0], m[1], *l);
    while (i + 1 < n && dist(stop, m[i]) < r->min_seg && skippable(m, i, stop, r))
        i++;
    /* the piece's end, or its first corner, within reach: the tie runs to
     * m[1] (unless that makes a tie stitch longer than max_seg) */
    if (dist(stop, m[i]) < r->min_seg &&
        (i + 1 == n || (i == 1 && !(r->max_seg > 0 && dist(m[0], m[1]) > r->max_seg)))) {
        *l = dist(m[0], m[1]);
        return 1;
    }
    return i;
}

/* The stitch from a to b, split into equal parts no longer than max_seg. */
static int sew_to(qc_ctx *ctx, qc_plan *out, qc_vec2 a, qc_vec2 b, const resolved *r)
{
    double dx = b.x - a.x, dy = b.y - a.y;

    if (dx * dx + dy * dy > r->short2) { /* perhaps longer than max_seg: measured */
        double d = dist(a, b);

        if (d > r->max_seg) {
            double parts = ceil(d / r->max_seg);
            size_t j, np = (size_t)parts;

            for (j = 1; j < np; j++) {
                double t = (double)j / parts;
                qc_vec2 q;

                q.x = a.x + (b.x - a.x) * t;
                q.y = a.y + (b.y - a.y) * t;
                QC__TRY(plan_add(ctx, out, q, 0));
            }
        }
    }
    if (out->n < out->cap) { /* build() counted the room: no call per point */
        out->p[out->n] = b;
        out->flags[out->n++] = 0;
        return QC_OK;
    }
    return plan_add(ctx, out, b, 0);
}

static int emit_piece(qc_ctx *ctx, qc_plan *out, const qc_vec2 *m, size_t n,
                      const resolved *r)
{
    qc_vec2 cur = m[0];
    size_t i = 1;
    double l;

    QC__TRY(plan_add(ctx, out, m[0], QC_ST_JUMP));
    if (r->ties > 0) {
        i = start_tie(m, n, r, &l);
        QC__TRY(tie_off(ctx, out, m[0], m[1], l, r));
        if (r->ties & 1)
            cur = along(m[0], m[1], l);
    }
    for (; i < n; i++) {
        double dx = m[i].x - cur.x, dy = m[i].y - cur.y;

        if (dx * dx + dy * dy > 0) /* dist() > 0: the tie may already stand on m[1] */
            QC__TRY(sew_to(ctx, out, cur, m[i], r));
        cur = m[i];
    }
    if (r->ties == 0)
        return QC_OK;
    return tie_off(ctx, out, m[n - 1], m[n - 2], fmin(r->tie_len, dist(m[n - 1], m[n - 2])), r);
}

/* The points emit_piece makes for the n merged points m (a double, so a
 * huge split count cannot wrap). */
static double piece_points(const qc_vec2 *m, size_t n, const resolved *r)
{
    double total = 1.0 + 2.0 * r->ties;
    size_t i;

    if (!(r->max_seg > 0)) /* a point per stitch: no pass over the points */
        return total + (double)(n - 1);
    for (i = 1; i < n; i++) {
        double dx = m[i].x - m[i - 1].x, dy = m[i].y - m[i - 1].y;

        /* under short2 the quotient is below 1 (or rounds to it): one */
        total += dx * dx + dy * dy <= r->short2
                 ? 1.0 : fmax(1.0, ceil(dist(m[i - 1], m[i]) / r->max_seg));
    }
    return total;
}

/* The pieces of pts (ends) merged in place, each compacted to follow the
 * one before (ends then marks the kept points), and the points the plan
 * makes of them (*total). No second array beside the flattened points: at
 * 10^6 pattern points they are 27 million, the peak of a large job. */
static int merge_all(qc_ctx *ctx, qc_points *pts, qc_order *ends, const resolved *r,
                     double *total)
{
    qc__merge mg;
    size_t longest = 0, k, start = 0, kept = 0;

    for (k = 0; k < ends->n; k++) {
        if (ends->i[k] - start > longest)
            longest = ends->i[k] - start;
        start = ends->i[k];
    }
    QC__TRY(qc__merge_init(ctx, &mg, longest));
    *total = 0;
    for (k = 0, start = 0; k < ends->n; k++) {
        qc_vec2 *m = pts->v + kept;
        size_t cnt = qc__merge_piece(&mg, pts->v + start, ends->i[k] - start, r->min_seg,
                                     r->floor_len, r->keep, m);

        if (cnt >= 2)
            *total += piece_points(m, cnt, r);
        start = ends->i[k];
        kept += cnt;
        ends->i[k] = (uint32_t)kept;
    }
    pts->n = kept;
    qc__merge_free(ctx, &mg);
    qc__points_fit(ctx, pts);
    return QC_OK;
}

/* A single piece's plan without ties or splits is its merged points as they
 * stand: the plan takes their array (emit_piece writes point k only after
 * reading m[k] and adds nothing), so no second copy is made. */
static int take_points(qc_ctx *ctx, qc_points *pts, const resolved *r, qc_plan *out)
{
    size_t cnt = pts->n;

    out->flags = (unsigned char *)qc__alloc(ctx, pts->cap);
    if (out->flags == NULL)
        return QC_ENOMEM;
    out->p = pts->v;
    out->cap = pts->cap;
    out->n = 0;
    memset(pts, 0, sizeof *pts);
    return emit_piece(ctx, out, out->p, cnt, r);
}

/* The plan of the flattened pieces pts (ends), both merged in place. */
static int build(qc_ctx *ctx, qc_points *pts, qc_order *ends, const resolved *r, qc_plan *out)
{
    size_t k, start = 0;
    double total = 0;
    int rc = QC_OK;

    QC__TRY(merge_all(ctx, pts, ends, r, &total));
    /* counted first, so a split that would make too many points is refused
     * before the plan grows */
    if (total > QC_MAX_PLAN_POINTS)
        return qc__fail(ctx, QC_ELIMIT,
                        "the stitch plan would have %.3g points, more than the limit of %lu; "
                        "raise the maximum segment",
                        total, (unsigned long)QC_MAX_PLAN_POINTS);
    if (ends->n == 1 && pts->n >= 2 && out->cap == 0 && r->ties == 0 &&
        total == (double)pts->n)
        return take_points(ctx, pts, r, out);
    if (out->cap == 0 && total >= 1) /* counted: no doubling, no copies */
        rc = plan_grow(ctx, out, (size_t)total);
    for (k = 0; k < ends->n && rc == QC_OK; k++) {
        if (ends->i[k] - start >= 2)
            rc = emit_piece(ctx, out, pts->v + start, ends->i[k] - start, r);
        start = ends->i[k];
    }
    return rc;
}

/* qc_stitch_plan; taken, when not NULL, is path, freed once flattened. */
static int stitch_plan(qc_ctx *ctx, const qc_path *path, qc_path *taken,
                       const qc_region *clip_region, const qc_stitch_params *params,
                       qc_plan *out)
{
    qc_points pts = {0}, cpts = {0};
    qc_order ends = {0}, cends = {0};
    resolved r;
    size_t i;
    int rc;

    memset(out, 0, sizeof *out);
    QC__TRY(resolve(ctx, params, &r));
    for (i = 0; i < path->npt; i++)
        if (!(fabs(path->pt[i].x) <= 1e6 && fabs(path->pt[i].y) <= 1e6))
            return qc__fail(ctx, QC_ERANGE,
                            "path point %lu (%g, %g) is not finite or beyond 1e6 mm",
                            (unsigned long)i, path->pt[i].x, path->pt[i].y);
    if (taken != NULL) /* the path goes as the points come (checked above) */
        rc = qc__curve_flatten_taking_checked(ctx, taken, r.tol, &pts, &ends);
    else
        rc = qc_curve_flatten(ctx, path, r.tol, &pts, &ends);
    qc__points_fit(ctx, &pts); /* before the merge's buffers join it at the peak */
    if (rc == QC_OK && params != NULL && params->clip && clip_region != NULL) {
        rc = qc__clip_pieces(ctx, &pts, &ends, clip_region, &cpts, &cends);
        qc_points_free(ctx, &pts); /* cpts holds what is sewn */
        if (rc == QC_OK)
            rc = build(ctx, &cpts, &cends, &r, out);
    } else if (rc == QC_OK) {
        rc = build(ctx, &pts, &ends, &r, out);
    }
    qc_points_free(ctx, &pts);
    qc_order_free(ctx, &ends);
    qc_points_free(ctx, &cpts);
    qc_order_free(ctx, &cends);
    if (rc == QC_OK && out->n == 0)
        rc = qc__fail(ctx, QC_EEMPTY, "nothing to sew: the path has no segment%s",
                      params != NULL && params->clip && clip_region != NULL
                          ? " inside the clip region" : "");
    if (rc != QC_OK)
        qc_plan_free(ctx, out);
    return rc;
}

int qc_stitch_plan(qc_ctx *ctx, const qc_path *path, const qc_region *clip_region,
                   const qc_stitch_params *params, qc_plan *out)
{
    return stitch_plan(ctx, path, NULL, clip_region, params, out);
}

int qc_stitch_plan_taking(qc_ctx *ctx, qc_path *path, const qc_region *clip_region,
                          const qc_stitch_params *params, qc_plan *out)
{
    int rc = stitch_plan(ctx, path, path, clip_region, params, out);

    qc_path_free(ctx, path); /* also when refused before the flattening */
    return rc;
}
