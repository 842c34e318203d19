/*
 * The vine (paper §4.3): the skeleton's visiting order smoothed by a
 * centripetal Catmull-Rom spline. A tour closes on itself. A tree walk
 * runs down and back each branch: every visit of a point is moved a little
 * off the branch, into the wedge the walk turns through there (counter-
 * clockwise from where it came from to where it goes: the side the walk
 * keeps, children being taken counter-clockwise), so the two passes of a
 * branch run side by side, one either side, and the vine traces the tree's
 * outline instead of sewing each branch twice over itself and crossing it.
 * An open walk (to an end point) takes the end's branch out of that order,
 * so it is smoothed through its points as they are.
 */
#include <math.h>

#include "internal.h"
#include "region_index.h"

/* Each pass keeps this far to its side of the branch, times d. */
#define SIDE 0.12
/* A narrow wedge's point lies at most this many sides out (a miter limit),
 * and at most this share of the shorter branch at it. */
#define MITER 2.5
#define SHORT 0.4
/* A branch longer than this, times d, gets a point beside its middle too:
 * without it the spline between two far ends can swing across the branch
 * into the other pass. */
#define LONG 0.75

/* How the passes are set beside the branches. */
typedef struct sides {
    double h;              /* how far */
    double len;            /* branches longer than this get a middle point */
    double clear;          /* a moved point keeps this from the boundary */
    const qc__rindex *ix;  /* the region's (NULL: none to keep clear of) */
} sides;

static double heading(qc_vec2 from, qc_vec2 to)
{
    return qc_atan2(to.y - from.y, to.x - from.x);
}

/* q, or q pulled back towards v until it keeps clear of the boundary (v
 * itself at worst): a branch near the outline, or across a notch, must not
 * be pushed out of the region, where keep_inside cannot always bring it
 * back. */
static qc_vec2 keep_clear(const sides *sd, qc_vec2 v, qc_vec2 q)
{
    int k;

    if (sd->ix == NULL)
        return q;
    for (k = 0; k < 4; k++) {
        if (qc__rindex_admits(sd->ix, q, sd->clear))
            return q;
        q.x = v.x + 0.5 * (q.x - v.x);
        q.y = v.y + 0.5 * (q.y - v.y);
    }
    return v;
}

/* v moved into the wedge counter-clockwise from v->u to v->w (u == w: a
 * tip): a convex wedge by one point on its bisector, far enough to keep h
 * from both branches; a reflex one by points h from v at most a quarter
 * turn apart, round it like a round join (a tip gets a round cap, so the
 * spline meets no point head on and curls); the first `most` of them. */
static int side_points(qc_ctx *ctx, const sides *sd, qc_vec2 u, qc_vec2 v, qc_vec2 w, int most,
                       qc_points *pts)
{
    double h = sd->h;
    double a = heading(v, u), t = heading(v, w) - a, dist, step;
    double shorter = fmin(qc_hypot(u.x - v.x, u.y - v.y), qc_hypot(w.x - v.x, w.y - v.y));
    int k, m;

    while (t <= 0.0)
        t += 2.0 * QC_PI;
    while (t > 2.0 * QC_PI)
        t -= 2.0 * QC_PI;
    if (t < QC_PI) {
        m = 1;
        dist = fmin(h / qc_sin(0.5 * t), MITER * h);
    } else {
        m = (int)ceil(t / (0.5 * QC_PI) - 1e-9) - 1;
        dist = h;
    }
    dist = fmin(dist, SHORT * shorter);
    step = t / (double)(m + 1);
    for (k = 1; k <= m && k <= most; k++) {
        qc_vec2 q;
        q.x = v.x + dist * qc_cos(a + step * (double)k);
        q.y = v.y + dist * qc_sin(a + step * (double)k);
        QC__TRY(qc_points_push(ctx, pts, keep_clear(sd, v, q)));
    }
    return QC_OK;
}

/* The point h beside the middle of the branch from a to b, on the side a
 * pass from a to b keeps (its right), if the branch is longer than sd->len
 * and its middle lies inside. */
static int beside_middle(qc_ctx *ctx, const sides *sd, qc_vec2 a, qc_vec2 b, qc_points *pts)
{
    double dx = b.x - a.x, dy = b.y - a.y, l = qc_hypot(dx, dy);
    qc_vec2 m, q;

    if (!(l > sd->len))
        return QC_OK;
    m.x = 0.5 * (a.x + b.x);
    m.y = 0.5 * (a.y + b.y);
    if (sd->ix != NULL && !qc__rindex_contains(sd->ix, m))
        return QC_OK;
    q.x = m.x + sd->h * dy / l;
    q.y = m.y - sd->h * dx / l;
    return qc_points_push(ctx, pts, keep_clear(sd, m, q));
}

/* The closed walk's points, each moved to the side its pass keeps,
 * wrapping round at the root and ending on the first point. */
static int walk_sides(qc_ctx *ctx, const qc_skeleton *skel, const sides *sd, qc_points *pts)
{
    const qc_vec2 *p = skel->p;
    const uint32_t *o = skel->order;
    size_t n = skel->norder, i;

    for (i = 0; i < n; i++) {
        size_t a = i > 0 ? i - 1 : n - 2, b = i + 1 < n ? i + 1 : 1;

        QC__TRY(side_points(ctx, sd, p[o[a]], p[o[i]], p[o[b]], i + 1 < n ? 4 : 1, pts));
        if (i + 1 < n)
            QC__TRY(beside_middle(ctx, sd, p[o[i]], p[o[i + 1]], pts));
    }
    return QC_OK;
}

/* The closed walk beside its branches (within region, if not NULL). */
static int vine_sides(qc_ctx *ctx, const qc_region *region, const qc_params *params,
                      const qc_skeleton *skel, qc_points *pts)
{
    qc__rindex ix;
    sides sd;
    int rc;

    sd.h = SIDE * params->spacing;
    sd.len = LONG * params->spacing;
    sd.clear = 0.5 * fmin(params->margin, sd.h);
    sd.ix = NULL;
    if (region == NULL)
        return walk_sides(ctx, skel, &sd, pts);
    QC__TRY(qc__rindex_build(ctx, region, &ix));
    sd.ix = &ix;
    rc = walk_sides(ctx, skel, &sd, pts);
    qc__rindex_free(ctx, &ix);
    return rc;
}

int qc_deco_vine(qc_ctx *ctx, const qc_region *region, const qc_params *params,
                 const qc_skeleton *skel, const qc_motif_set *motifs, qc_path *out,
                 qc_stats *stats)
{
    qc_points pts = {0};
    size_t i;
    int rc = QC_OK;

    (void)motifs;
    (void)stats;
    if (skel->norder == 0)
        return qc__fail(ctx, QC_EEMPTY, "the vine needs at least one point");
    if (skel->edges != NULL && skel->norder > 2 && skel->order[0] == skel->order[skel->norder - 1])
        rc = vine_sides(ctx, region, params, skel, &pts);
    else
        for (i = 0; i < skel->norder && rc == QC_OK; i++)
            rc = qc_points_push(ctx, &pts, skel->p[skel->order[i]]);
    if (rc == QC_OK && pts.n == 1) /* a lone point: a tiny stitch in place */
        rc = qc_path_move_to(ctx, out, pts.v[0]);
    else if (rc == QC_OK)
        rc = qc_curve_catmull_rom(ctx, pts.v, pts.n, skel->edges == NULL, out);
    qc_points_free(ctx, &pts);
    return rc;
}

const qc_family_desc qc__family_vine = {
    QC_FAMILY_VINE, "vine", "the skeleton's walk smoothed into one vine, down and back each "
    "branch side by side (paper §4.3)", QC_FAMILY_NEEDS_POINTS, 0, qc_deco_vine, NULL};
