/*
 * The curve the meander's evolution starts from: the outline of a spanning
 * tree, drawn d/2 to each side, so neighbouring lines already lie about d
 * apart. The tree joins Poisson points 2d apart and points on the medial
 * axis (src/sample/medial.c): a Poisson fill misses strips narrower than
 * its margin and stops short of sharp corners, and the evolution moves a
 * vertex only a few d in all, so what the seed does not reach stays bare.
 * Where the outline comes nearer the boundary than it may, it is pulled
 * in along the distance field; if it then crosses itself, the medial
 * points are left out (a closed curve that does not cross is the hard
 * invariant the evolution keeps).
 */
#include <math.h>
#include <string.h>

#include "family_meander.h"
#include "../sample/sample_internal.h"

#define SEED_SPACING 2.0 /* tree points, times d */
#define FILL_MARGIN 0.9  /* the Poisson points' margin, times d */
#define AXIS_MARGIN 0.3  /* the medial points' margin, times d */
#define INNER 0.15       /* the outline is pulled at least this far inside, times d */

/* c with p at its front (at_end 0) or its end, unless already there. */
static int pin(qc_ctx *ctx, qc_points *c, qc_vec2 p, int at_end)
{
    qc_vec2 e = at_end ? c->v[c->n - 1] : c->v[0];

    if (e.x == p.x && e.y == p.y)
        return QC_OK;
    QC__TRY(qc_points_push(ctx, c, p));
    if (!at_end) {
        memmove(c->v + 1, c->v, (c->n - 1) * sizeof *c->v);
        c->v[0] = p;
    }
    return QC_OK;
}

/* The tree's points into *pts: the Poisson fill, and with axis the medial
 * points; a region too small for any gets one point at its widest place,
 * and *half shrinks to fit there. */
static int tree_points(qc_ctx *ctx, const qc_region *region, const qc__sdf *s,
                       const qc_params *prm, int axis, qc_points *pts, double *half)
{
    qc_sample_params sp;
    double d = prm->spacing;
    qc_vec2 at;
    double room;

    memset(&sp, 0, sizeof sp);
    sp.kind = QC_SAMPLE_POISSON;
    sp.spacing = SEED_SPACING * d;
    sp.margin = FILL_MARGIN * d;
    sp.seed = prm->seed;
    QC__TRY(qc_sample(ctx, region, &sp, pts));
    if (axis)
        QC__TRY(qc__sample_medial(ctx, region, SEED_SPACING * d, AXIS_MARGIN * d, pts));
    if (pts->n > 0)
        return QC_OK;
    room = qc__sdf_max(s, &at); /* small: a loop that fits at the widest place */
    if (!(room > 0.0))
        return qc__fail(ctx, QC_EEMPTY, "meander: the region has no inside");
    *half = fmin(*half, 0.6 * room);
    return qc_points_push(ctx, pts, at);
}

/* The point of the tree's edges (or, with none, its one point) nearest q. */
static qc_vec2 tree_nearest(const qc_points *pts, const qc_edges *e, qc_vec2 q)
{
    qc_vec2 best = pts->v[0];
    double bd = HUGE_VAL;
    size_t k;

    for (k = 0; k < e->n; k++) {
        qc_vec2 a = pts->v[e->e[k].a], b = pts->v[e->e[k].b], s;
        double ux = b.x - a.x, uy = b.y - a.y, l2 = ux * ux + uy * uy, t = 0.0, dd;
        if (l2 > 0.0)
            t = fmax(0.0, fmin(1.0, ((q.x - a.x) * ux + (q.y - a.y) * uy) / l2));
        s = QC__V2(a.x + t * ux, a.y + t * uy);
        dd = (q.x - s.x) * (q.x - s.x) + (q.y - s.y) * (q.y - s.y);
        if (dd < bd) {
            bd = dd;
            best = s;
        }
    }
    return best;
}

/* Outline vertices nearer the boundary than INNER d (or outside) moved
 * towards the tree, along the line to its nearest point, until they are
 * INNER d inside (or halfway to the tree where the tree itself is nearer
 * the boundary): the outline narrows like a tube squeezed round its core,
 * which keeps its order round every node. */
static void pull_in(qc_points *c, const qc__sdf *s, const qc_points *pts, const qc_edges *e,
                    double d)
{
    size_t i;
    int k;

    for (i = 0; i < c->n; i++) {
        qc_vec2 q = c->v[i], t, m;
        double lo = 0.0, hi = 1.0;
        if (qc__sdf_exact(s, q, NULL) >= INNER * d)
            continue;
        t = tree_nearest(pts, e, q);
        if (qc__sdf_exact(s, t, NULL) < 2.0 * INNER * d) {
            c->v[i] = QC__V2(0.5 * (q.x + t.x), 0.5 * (q.y + t.y));
            continue;
        }
        for (k = 0; k < 20; k++) { /* the largest fraction of t->q kept INNER d inside */
            double mid = 0.5 * (lo + hi);
            m = QC__V2(t.x + mid * (q.x - t.x), t.y + mid * (q.y - t.y));
            if (qc__sdf_exact(s, m, NULL) >= INNER * d)
                lo = mid;
            else
                hi = mid;
        }
        c->v[i] = QC__V2(t.x + lo * (q.x - t.x), t.y + lo * (q.y - t.y));
    }
}

/* One attempt: the outline of the tree over tree_points(axis). */
static int outline(qc_ctx *ctx, const qc_region *region, const qc__sdf *s,
                   const qc_params *prm, const qc_vec2 *ports, int axis, qc_points *c)
{
    qc_points pts = {0};
    qc_edges edges = {0};
    qc__ftree t;
    qc__fstyle st;
    qc_vec2 start;
    double half = 0.5 * prm->spacing;
    int rc;

    memset(&t, 0, sizeof t);
    c->n = 0;
    rc = tree_points(ctx, region, s, prm, axis, &pts, &half);
    if (rc == QC_OK)
        rc = qc_mst(ctx, pts.v, pts.n, QC_MST_MODE_DELAUNAY, &edges);
    if (rc == QC_OK && ports != NULL) { /* the ports join the tree as two more leaves */
        size_t n = pts.n;
        uint32_t a = qc__tile_port_node(pts.v, n, edges.e, edges.n, ports[0]);
        uint32_t b = qc__tile_port_node(pts.v, n, edges.e, edges.n, ports[1]);
        rc = qc_points_push(ctx, &pts, ports[0]);
        if (rc == QC_OK)
            rc = qc_points_push(ctx, &pts, ports[1]);
        if (rc == QC_OK)
            rc = qc_edges_push(ctx, &edges, a, (uint32_t)n);
        if (rc == QC_OK)
            rc = qc_edges_push(ctx, &edges, b, (uint32_t)n + 1);
    }
    if (rc == QC_OK)
        rc = qc__ftree_build(ctx, pts.v, pts.n, edges.e, edges.n, &t);
    if (rc == QC_OK) {
        int given = qc_params_given(prm, QC_PARAM_ID_START_X) ||
                    qc_params_given(prm, QC_PARAM_ID_START_Y);
        start = given ? QC__V2(prm->start_x, prm->start_y) : qc_region_bbox(region).min;
        memset(&st, 0, sizeof st);
        st.half = half;
        st.arc_step = QC_PI / 8.0;
        if (ports != NULL)
            rc = qc__ftree_open(ctx, &t, (uint32_t)pts.n - 2, (uint32_t)pts.n - 1, &st, c);
        else
            rc = qc__ftree_loop(ctx, &t, qc_nearest_point(pts.v, pts.n, start), &st, c);
    }
    if (rc == QC_OK && axis && edges.n > 0)
        pull_in(c, s, &pts, &edges, prm->spacing);
    if (rc == QC_OK && ports != NULL && c->n > 0)
        rc = pin(ctx, c, ports[0], 0);
    if (rc == QC_OK && ports != NULL && c->n > 0)
        rc = pin(ctx, c, ports[1], 1);
    qc__ftree_free(ctx, &t);
    qc_points_free(ctx, &pts);
    qc_edges_free(ctx, &edges);
    return rc;
}

int qc__meander_seed(qc_ctx *ctx, const qc_region *region, const qc__sdf *s,
                     const qc_params *prm, const qc_vec2 *ports, int axis, qc_points *c)
{
    size_t crossings = 0;
    int rc = outline(ctx, region, s, prm, ports, axis, c);

    if (rc == QC_OK && axis && c->n >= 3)
        rc = qc_path_self_crossings(ctx, c->v, c->n, ports == NULL, &crossings);
    if (rc == QC_OK && crossings > 0) /* the Poisson tree's outline alone does not cross */
        rc = outline(ctx, region, s, prm, ports, 0, c);
    return rc;
}
