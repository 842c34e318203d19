/*
 * Meander (beyond the paper's §7.1 stipple): one closed, non-crossing curve
 * that fills the region at line spacing d. It starts as the outline of a
 * spanning tree (family_meander_seed.c) and is then evolved
 * (family_meander_grow.c) until its spacing evens out, its lobes round and it
 * reaches into the corners. Sewn through a closed Catmull-Rom spline from
 * the vertex nearest the start, flatter where it would cross itself
 * (family_meander_smooth.c); a requested start also gets legs out to
 * the boundary there, so patches can be joined.
 */
#include <math.h>
#include <string.h>

#include "family_meander.h"
#include "../curve/keep_inside.h"

#define CLEAR 0.22        /* distance kept from the boundary, times d: the
                           * seam within 1/4 in (0.42 d at d = 0.6 in) of a
                           * stitch, the mouths of the channels too */
#define SDF_STEP (1.0 / 3.0) /* distance grid, times d */
#define GROW_LEN 1.0      /* the curve grows to area / d times this ... */
#define RIM_LEN 1.0       /* ... and the rim's share of what the clearance frees */
#define GAP_RES (1.0 / 6.0)
#define CHECK_TOL 0.01   /* flattening for the crossing check, mm (as the tests measure) */

/* The distance grid's step: d/3, finer for a region smaller than a few d. */
static double sdf_step(const qc_region *region, double d)
{
    qc_bbox b = qc_region_bbox(region);
    double side = fmin(b.max.x - b.min.x, b.max.y - b.min.y);

    return fmin(SDF_STEP * d, side / 8.0);
}

/* The length of region's rings, mm. */
static double perimeter(const qc_region *r)
{
    double len = 0.0;
    size_t k, i = 0;

    for (k = 0; k < r->nrings; k++) {
        size_t first = i, end = r->ring_end[k];
        for (; i < end; i++) {
            qc_vec2 a = r->v[i], b = r->v[i + 1 < end ? i + 1 : first];
            len += qc_hypot(b.x - a.x, b.y - a.y);
        }
    }
    return len;
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
        rc = qc__meander_smooth(ctx, r.v, r.n, !given, prm->spacing, s, out);
    qc_points_free(ctx, &r);
    return rc;
}

/* 1 if qc_generate's keep-inside pass would change path (a chord over a
 * cusp rerouted round its tip: a V far tighter than the turn radius, and
 * a long straight run) or path, so kept, crosses itself; 0 if not, or an
 * error. */
static int kept_differs(qc_ctx *ctx, const qc_region *region, const qc_path *path)
{
    qc_path kept = {0};
    qc_points flat = {0};
    size_t n = 0, fixed = 0;
    int rc = qc_path_append(ctx, &kept, path, 0);

    if (rc == QC_OK)
        rc = qc__path_keep_inside(ctx, region, "meander", &kept, &fixed);
    if (rc == QC_OK && fixed == 0)
        rc = qc_curve_flatten(ctx, &kept, CHECK_TOL, &flat, NULL);
    if (rc == QC_OK && fixed == 0)
        rc = qc_path_self_crossings(ctx, flat.v, flat.n, 0, &n);
    n += fixed;
    qc_path_free(ctx, &kept);
    qc_points_free(ctx, &flat);
    return rc < 0 ? rc : n > 0;
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
    int rc, axis;

    (void)skel;
    (void)motifs;
    memset(&s, 0, sizeof s);
    if (!(d > 0.0))
        return qc__fail(ctx, QC_ERANGE, "meander spacing %g mm must be > 0", d);
    /* the curve grows to GROW_LEN area / d with vertices d/4 or more apart:
     * refuse what cannot fit before the distance grid is built */
    if (4.0 * GROW_LEN * fabs(qc_region_area(region)) / (d * d) > (double)QC_MAX_POINTS)
        return qc__fail(ctx, QC_ELIMIT,
                        "meander: about %.0f curve points at spacing %g mm exceed the limit "
                        "of %lu; raise the spacing",
                        4.0 * GROW_LEN * fabs(qc_region_area(region)) / (d * d), d,
                        (unsigned long)QC_MAX_POINTS);
    rc = tiled ? qc_tile_ports(ctx, region, &ports[0], &ports[1]) : QC_OK;
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
    /* lines d apart, the outermost CLEAR d (not d/2) in from the boundary:
     * a strip of width W holds (W + d - 2 CLEAR d) / d of them */
    o.max_len = GROW_LEN * (fabs(qc_region_area(region)) +
                            RIM_LEN * (0.5 - CLEAR) * d * perimeter(region)) / d;
    o.seed = params->seed;
    o.sdf = &s;
    o.open = tiled;
    /* seeded on the medial axis too; should qc_generate's keep-inside pass
     * then have to reroute it (a chord over a cusp: the heart's, seed 17,
     * turned 0.15 d round the tip with a 2.45 d straight run) or make it
     * cross itself, seeded as before */
    for (axis = 1; axis >= 0 && rc == QC_OK; axis--) {
        one.ncmd = one.npt = 0;
        rc = qc__meander_seed(ctx, region, &s, params, tiled ? ports : NULL, axis, &c);
        if (rc == QC_OK)
            rc = qc__meander_grow(ctx, &c, &o);
        if (rc == QC_OK)
            rc = qc__meander_ease(ctx, &c, tiled, o.turn, &s, d);
        if (rc == QC_OK)
            rc = qc__meander_reach(ctx, region, &s, d, tiled, &c);
        if (rc == QC_OK) /* and where the tongues leave the curve */
            rc = qc__meander_ease(ctx, &c, tiled, o.turn, &s, d);
        if (rc == QC_OK) /* the holes the evolution left, closed in */
            rc = qc__meander_holes(ctx, region, &s, d, tiled, &c);
        if (rc == QC_OK) /* the corners the spline would still turn too tightly */
            rc = qc__meander_round(ctx, &c, tiled, o.turn, &s, d);
        if (rc == QC_OK) /* and the holes the rounding opened again */
            rc = qc__meander_holes(ctx, region, &s, d, tiled, &c);
        if (rc == QC_OK) /* and the turns those bumps tightened */
            rc = qc__meander_round(ctx, &c, tiled, o.turn, &s, d);
        if (rc == QC_OK)
            rc = tiled ? qc__meander_smooth(ctx, c.v, c.n, 0, d, NULL, &one)
                       : sew(ctx, &c, &s, region, params, &one);
        if (rc == QC_OK && (tiled || !axis))
            break;
        if (rc == QC_OK) {
            int differs = kept_differs(ctx, region, &one);
            if (differs < 0)
                rc = differs;
            else if (!differs)
                break;
        }
    }
    if (rc == QC_OK && stats != NULL && !params->skip_gap_stat) {
        double g = qc_path_largest_gap(ctx, region, &one, GAP_RES * d, NULL);
        if (g < 0.0)
            rc = (int)g;
        else
            stats->largest_gap_mm = g;
    }
    if (rc == QC_OK && tiled) { /* rows as stipple lays them: a piece each (tile.c) */
        qc_bbox box = qc_region_bbox(region);
        unsigned cols = params->repeat_cols >= 1.0 ? (unsigned)params->repeat_cols : 1u;
        unsigned rows = params->repeat_rows >= 1.0 ? (unsigned)params->repeat_rows : 1u;
        double h = box.max.y - box.min.y;
        size_t k;

        rc = qc_tile_layout(ctx, &one, ports[1].x - ports[0].x, h, cols, rows,
                            params->row_offset, &rep);
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
        QC_PARAM_BIT(QC_PARAM_ID_REPEAT_COLS) | QC_PARAM_BIT(QC_PARAM_ID_REPEAT_ROWS) |
        QC_PARAM_BIT(QC_PARAM_ID_ROW_OFFSET),
    qc_deco_meander, NULL};
