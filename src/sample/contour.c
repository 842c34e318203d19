/*
 * A row of points along the seams: a fill that keeps its margin only on
 * average leaves stretches of seam a spacing or more from the nearest
 * line, and a stipple outline (width d / 3 round the tree) stays that far
 * off. Points every `step` along the contour offset inside every ring make
 * the tree run parallel to the seam there (they are nearer each other than
 * the fill is to them, so the spanning tree chains them).
 *
 * The boundary is walked in short steps (round reflex corners too); from
 * each boundary point the row sits along the inward normal at the offset,
 * or a quarter of the local width where that is less: the largest empty
 * disc touching the boundary there has radius R (found by bisection), and
 * R / 2 puts two rows a quarter of the width in from either side of a
 * strip, and runs the row into a convex corner along a line from its tip;
 * where that falls inside the margin, the row runs on along the margin
 * while the margin still fits (R above it), deeper into the corner.
 */
#include <math.h>

#include "sample_internal.h"

#define MARGIN_LINE 1.001 /* R at least this * margin: room for a point on the margin */
#define PER_STEP 8      /* boundary samples per step along the row */
#define PROBE_STEPS 12  /* bisection steps for the local width */
#define KEEP_APART 0.75 /* from another stretch of the row, times step */
#define TOUCH 0.999999  /* the empty disc touches the boundary at its foot */

typedef struct row_walk {
    const qc__rindex *ix;
    qc__near_grid grid;
    double offset, step, margin;
    qc_vec2 last; /* the last point placed on this ring */
    int placed;   /* on this ring */
    qc_points *out;
} row_walk;

/* Whether the disc of radius t touching the boundary at q (centre q + t n)
 * holds no boundary. */
static int disc_empty(const qc__rindex *ix, qc_vec2 q, qc_vec2 n, double t)
{
    return qc__rindex_admits(ix, QC__V2(q.x + t * n.x, q.y + t * n.y), t * TOUCH);
}

/* How far in along n from q the row runs: the offset, or half the radius
 * of the largest empty disc touching the boundary at q where that is less. */
static double local_offset(const qc__rindex *ix, qc_vec2 q, qc_vec2 n, double offset)
{
    double lo = 0, hi = 2 * offset;
    int k;

    if (disc_empty(ix, q, n, hi))
        return offset;
    for (k = 0; k < PROBE_STEPS; k++) {
        double mid = 0.5 * (lo + hi);
        if (disc_empty(ix, q, n, mid))
            lo = mid;
        else
            hi = mid;
    }
    return 0.5 * lo;
}

/* The row's point for boundary point q and inward unit normal n, if it
 * keeps the margin and its distance from the points already placed. */
/* Whether every point the row could place for q (q + c n, c between the
 * margin and the offset: what offer keeps) lies nearer the last point than
 * the step, so offer would drop it whatever local_offset finds: the
 * distance along the line is convex in c, its largest at an end; the
 * slack covers the rounding of the distance offer works out. */
static int surely_too_near(const row_walk *w, qc_vec2 q, qc_vec2 n)
{
    double c0 = w->margin, c1 = fmax(w->margin, w->offset);
    double d0 = qc_hypot(q.x + c0 * n.x - w->last.x, q.y + c0 * n.y - w->last.y);
    double d1 = qc_hypot(q.x + c1 * n.x - w->last.x, q.y + c1 * n.y - w->last.y);

    return w->placed && fmax(d0, d1) < w->step * (1.0 - 1e-9);
}

static int offer(qc_ctx *ctx, row_walk *w, qc_vec2 q, qc_vec2 n)
{
    double c;
    qc_vec2 p;

    if (surely_too_near(w, q, n)) /* the usual case: 8 boundary samples a step */
        return QC_OK;
    c = local_offset(w->ix, q, n, w->offset);

    if (c < w->margin && 2 * c >= w->margin * MARGIN_LINE)
        c = w->margin;
    if (!(c >= w->margin))
        return QC_OK;
    p = QC__V2(q.x + c * n.x, q.y + c * n.y);
    if (w->placed && qc_hypot(p.x - w->last.x, p.y - w->last.y) < w->step)
        return QC_OK;
    if (qc__near_grid_near(&w->grid, w->out, p, KEEP_APART * w->step) ||
        !qc__rindex_admits(w->ix, p, w->margin * TOUCH))
        return QC_OK;
    if (w->out->n >= QC_MAX_POINTS)
        return qc__fail(ctx, QC_ELIMIT, "the seam row at step %g mm passes the limit of %lu "
                        "points; raise the spacing", w->step, (unsigned long)QC_MAX_POINTS);
    QC__TRY(qc_points_push(ctx, w->out, p));
    QC__TRY(qc__near_grid_add(ctx, &w->grid, w->out, w->out->n - 1));
    w->last = p;
    w->placed = 1;
    return QC_OK;
}

/* The inward unit normal of edge a -> b (the region lies on the left of
 * its normalized rings); 0 for a zero-length edge. */
static int inward(qc_vec2 a, qc_vec2 b, qc_vec2 *n)
{
    double l = qc_hypot(b.x - a.x, b.y - a.y);

    if (!(l > 0))
        return 0;
    *n = QC__V2(-(b.y - a.y) / l, (b.x - a.x) / l);
    return 1;
}

/* Round reflex vertex v, from normal n0 to n1 (turning clockwise): the
 * row is an arc about v there. */
static int walk_arc(qc_ctx *ctx, row_walk *w, qc_vec2 v, qc_vec2 n0, qc_vec2 n1)
{
    double cr = n0.x * n1.y - n0.y * n1.x, dt = n0.x * n1.x + n0.y * n1.y;
    double phi = qc_atan2(-cr, dt); /* > 0: the clockwise sweep */
    size_t m, k;

    if (!(cr < 0) || !(phi > 0))
        return QC_OK;
    m = (size_t)ceil(phi * w->offset * PER_STEP / w->step);
    for (k = 1; k < m; k++) {
        double a = -phi * (double)k / (double)m, ca = qc_cos(a), sa = qc_sin(a);
        QC__TRY(offer(ctx, w, v, QC__V2(n0.x * ca - n0.y * sa, n0.x * sa + n0.y * ca)));
    }
    return QC_OK;
}

static int walk_ring(qc_ctx *ctx, row_walk *w, const qc_region *r, size_t rs, size_t end)
{
    size_t i, prev = end - 1, k;
    qc_vec2 n0, n1;

    w->placed = 0;
    for (i = rs; i < end; prev = i++) {
        qc_vec2 a = r->v[i], b = r->v[i + 1 == end ? rs : i + 1];
        double len = qc_hypot(b.x - a.x, b.y - a.y);
        size_t m;

        if (!inward(a, b, &n1))
            continue;
        if (inward(r->v[prev], a, &n0))
            QC__TRY(walk_arc(ctx, w, a, n0, n1));
        m = (size_t)ceil(len * PER_STEP / w->step);
        for (k = 0; k < m; k++) {
            double u = ((double)k + 0.5) / (double)m;
            QC__TRY(offer(ctx, w, QC__V2(a.x + u * (b.x - a.x), a.y + u * (b.y - a.y)), n1));
        }
    }
    return QC_OK;
}

int qc__sample_contour(qc_ctx *ctx, const qc_region *region, const qc__rindex *ix,
                       double offset, double step, double margin, qc_points *out)
{
    row_walk w;
    size_t q, rs = 0, n0 = out->n, i;
    int rc;

    if (!(offset > 0) || !(step > 0))
        return QC_OK;
    w.ix = ix;
    w.offset = offset;
    w.step = step;
    w.margin = margin;
    w.out = out;
    w.placed = 0;
    w.last = QC__V2(0, 0);
    rc = qc__near_grid_init(ctx, &w.grid, qc_region_bbox(region), step);
    for (i = 0; i < n0 && rc == QC_OK; i++) /* keep apart from the points given before */
        rc = qc__near_grid_add(ctx, &w.grid, out, i);
    for (q = 0; q < region->nrings && rc == QC_OK; q++) {
        rc = walk_ring(ctx, &w, region, rs, region->ring_end[q]);
        rs = region->ring_end[q];
    }
    qc__near_grid_free(ctx, &w.grid);
    if (rc < 0)
        out->n = n0;
    return rc;
}
