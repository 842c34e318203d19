/*
 * Meander (beyond the paper's §7.1 stipple): one closed, non-crossing curve
 * that fills the region at line spacing d. It starts as the outline of a
 * spanning tree over Poisson points 2d apart, drawn d/2 to each side (so
 * neighbouring lines already lie about d apart), and is then evolved
 * (family_meander_grow.c) until its spacing evens out, its lobes round and it
 * reaches into the corners. Sewn through a closed Catmull-Rom spline from
 * the vertex nearest the start; a requested start also gets legs out to
 * the boundary there, so patches can be joined.
 */
#include <math.h>
#include <string.h>

#include "family_meander.h"

#define SEED_SPACING 2.0  /* tree points, times d */
#define CLEAR 0.4         /* distance kept from the boundary, times d */
#define SDF_STEP (1.0 / 3.0) /* distance grid, times d */
#define GROW_LEN 1.0      /* the curve grows to area / d times this */
#define GAP_RES (1.0 / 6.0)

/* The distance grid's step: d/3, finer for a region smaller than a few d. */
static double sdf_step(const qc_region *region, double d)
{
    qc_bbox b = qc_region_bbox(region);
    double side = fmin(b.max.x - b.min.x, b.max.y - b.min.y);

    return fmin(SDF_STEP * d, side / 8.0);
}

/* The tree outline the evolution starts from, into *c. */
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

/* The tree outline the evolution starts from, into *c: closed, or with
 * ports (a tile) open from ports[0] to ports[1]. */
static int seed_curve(qc_ctx *ctx, const qc_region *region, const qc_params *prm,
                      const qc_vec2 *ports, qc_points *c)
{
    qc_sample_params sp;
    qc_points pts = {0};
    qc_edges edges = {0};
    qc__ftree t;
    qc__fstyle st;
    qc_vec2 start;
    double d = prm->spacing, half = 0.5 * d;
    int rc;

    memset(&t, 0, sizeof t);
    memset(&sp, 0, sizeof sp);
    sp.kind = QC_SAMPLE_POISSON;
    sp.spacing = SEED_SPACING * d;
    sp.margin = (CLEAR + 0.5) * d;
    sp.seed = prm->seed;
    rc = qc_sample(ctx, region, &sp, &pts);
    if (rc == QC_OK && pts.n == 0) { /* small: a loop that fits at the widest place */
        qc__sdf s;
        qc_vec2 at;
        rc = qc__sdf_build(ctx, region, sdf_step(region, d), &s);
        if (rc == QC_OK) {
            double room = qc__sdf_max(&s, &at);
            qc__sdf_free(ctx, &s);
            if (!(room > 0.0))
                rc = qc__fail(ctx, QC_EEMPTY, "meander: the region has no inside");
            else
                rc = qc_points_push(ctx, &pts, at);
            half = fmin(half, 0.6 * room);
        }
    }
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
    if (rc == QC_OK && ports != NULL && c->n > 0)
        rc = pin(ctx, c, ports[0], 0);
    if (rc == QC_OK && ports != NULL && c->n > 0)
        rc = pin(ctx, c, ports[1], 1);
    qc__ftree_free(ctx, &t);
    qc_points_free(ctx, &pts);
    qc_edges_free(ctx, &edges);
    return rc;
}

/* The boundary point nearest p. */
static qc_vec2 to_boundary(const qc__sdf *s, qc_vec2 p)
{
    qc_vec2 g;
    double v = qc__sdf_exact(s, p, &g);

    return QC__V2(p.x - v * g.x, p.y - v * g.y);
}

/* The curve as sewn: opened at the vertex nearest the start; with a start
 * asked for, it leaves from the boundary there and returns beside it. */
static int sew(qc_ctx *ctx, const qc_points *c, const qc__sdf *s, const qc_region *region,
               const qc_params *prm, qc_path *out)
{
    int given = qc_params_given(prm, QC_PARAM_ID_START_X) ||
                qc_params_given(prm, QC_PARAM_ID_START_Y);
    qc_vec2 start = given ? QC__V2(prm->start_x, prm->start_y) : qc_region_bbox(region).min;
    size_t n = c->n, k = qc__nearest_point(c->v, c->n, start), i;
    qc_points r = {0};
    int rc = QC_OK;

    if (given)
        rc = qc_points_push(ctx, &r, to_boundary(s, c->v[k]));
    for (i = 0; i < n && rc == QC_OK; i++)
        rc = qc_points_push(ctx, &r, c->v[(k + i) % n]);
    if (given && rc == QC_OK)
        rc = qc_points_push(ctx, &r, to_boundary(s, c->v[(k + n - 1) % n]));
    if (rc == QC_OK)
        rc = qc_curve_catmull_rom(ctx, r.v, r.n, !given, out);
    qc_points_free(ctx, &r);
    return rc;
}

int qc_deco_meander(qc_ctx *ctx, const qc_region *region, const qc_params *params,
                    const qc_skeleton *skel, const qc_motif_set *motifs, qc_path *out,
                    qc_stats *stats)
{
    qc_points c = {0};
    qc_path one = {0}, rep = {0};
    qc__sdf s;
    qc__grow_opts o;
    qc_vec2 ports[2];
    double d = params->spacing;
    int tiled = params->tile == QC_TILE_EDGE_TO_EDGE || params->tile == QC_TILE_ALL_OVER;
    int rc;

    (void)skel;
    (void)motifs;
    memset(&s, 0, sizeof s);
    if (!(d > 0.0))
        return qc__fail(ctx, QC_ERANGE, "meander spacing %g mm must be > 0", d);
    rc = tiled ? qc_tile_ports(ctx, region, &ports[0], &ports[1]) : QC_OK;
    if (rc == QC_OK)
        rc = seed_curve(ctx, region, params, tiled ? ports : NULL, &c);
    if (rc == QC_OK)
        rc = qc__sdf_build(ctx, region, sdf_step(region, d), &s);
    if (rc < 0)
        goto out;
    memset(&o, 0, sizeof o);
    o.d = d;
    o.clear = CLEAR * d;
    o.turn = params->turn_radius;
    o.wiggle = params->wiggle;
    o.iterations = (size_t)params->iterations;
    o.max_len = GROW_LEN * fabs(qc_region_area(region)) / d;
    o.seed = params->seed;
    o.sdf = &s;
    o.open = tiled;
    rc = qc__meander_grow(ctx, &c, &o);
    if (rc == QC_OK)
        rc = tiled ? qc_curve_catmull_rom(ctx, c.v, c.n, 0, &one)
                   : sew(ctx, &c, &s, region, params, &one);
    if (rc == QC_OK && stats != NULL && !params->skip_gap_stat) {
        double g = qc_path_largest_gap(ctx, region, &one, GAP_RES * d, NULL);
        if (g < 0.0)
            rc = (int)g;
        else
            stats->largest_gap_mm = g;
    }
    if (rc == QC_OK && tiled) { /* laid out as stipple lays its tiles (tile.c) */
        qc_bbox box = qc_region_bbox(region);
        unsigned cols = params->repeat_cols >= 1.0 ? (unsigned)params->repeat_cols : 1u;
        unsigned rows = params->repeat_rows >= 1.0 ? (unsigned)params->repeat_rows : 1u;
        double h = box.max.y - box.min.y;
        size_t k;

        rc = qc_tile_repeat(ctx, &one, ports[1].x - ports[0].x, h, cols, rows, &rep);
        for (k = 0; k < rep.npt; k++) /* the bottom row on the tile's own box */
            rep.pt[k].y += (double)(rows - 1) * h;
        if (rc == QC_OK)
            rc = qc_path_append(ctx, out, &rep, 1);
    } else if (rc == QC_OK) {
        rc = qc_path_append(ctx, out, &one, 1);
    }
out:
    qc__sdf_free(ctx, &s);
    qc_points_free(ctx, &c);
    qc_path_free(ctx, &one);
    qc_path_free(ctx, &rep);
    return rc;
}

const qc_family_desc qc__family_meander = {
    QC_FAMILY_MEANDER, "meander", "one closed curve grown by curve evolution, filling the block",
    0, /* it samples its own seed tree, 2d apart */
    QC_PARAM_BIT(QC_PARAM_ID_WIGGLE) | QC_PARAM_BIT(QC_PARAM_ID_TURN_RADIUS) |
        QC_PARAM_BIT(QC_PARAM_ID_ITERATIONS) | QC_PARAM_BIT(QC_PARAM_ID_TILE) |
        QC_PARAM_BIT(QC_PARAM_ID_REPEAT_COLS) | QC_PARAM_BIT(QC_PARAM_ID_REPEAT_ROWS),
    qc_deco_meander, NULL};
