/*
 * qc_generate: the convenience tier over the stages, the one composition
 * the CLI and the web page share (so both give the same bytes):
 * sample -> graph -> tour -> family (decorate).
 */
#include <math.h>
#include <string.h>

#include "internal.h"
#include "pattern_internal.h"
#include "region_index.h"
#include "../curve/keep_inside.h"
#include "../sample/sample_internal.h"

/* The length and box in qc_stats come from qc_curve_measure, which does not
 * flatten (the arc length to 1e-5, the exact box): this only bounds its
 * halving round a cusp, well under a stitch (0.127 mm is the plan's). */
#define STATS_TOL_MM QC__STATS_TOL_MM
/* The farthest-fabric raster: d / 10 (its cells grow with the points, so
 * memory stays linear); exact along the boundary and at the winner. */
#define FABRIC_RES 0.1

static void trace(qc_ctx *ctx, const char *stage)
{
    if (ctx->trace != NULL)
        ctx->trace(ctx->trace_ud, stage);
}

/* Given points must lie in the region, margin from its boundary, as sampled
 * points do: a pattern sewn beyond the block would run into its neighbours
 * or the frame. */
int qc__check_given_inside(qc_ctx *ctx, const qc_region *region, const qc_points *given,
                           double margin)
{
    qc__rindex ix;
    qc_bbox box;
    size_t i;

    QC__TRY(qc__rindex_build(ctx, region, &ix));
    for (i = 0; i < given->n && qc__rindex_admits(&ix, given->v[i], margin); i++)
        ;
    qc__rindex_free(ctx, &ix);
    if (i == given->n)
        return QC_OK;
    box = qc_region_bbox(region);
    return qc__fail(ctx, QC_ERANGE,
                    "given point %lu (%g, %g) mm is not inside the region (%g..%g, %g..%g mm) "
                    "by the margin %g mm",
                    (unsigned long)i + 1, given->v[i].x, given->v[i].y, box.min.x, box.max.x,
                    box.min.y, box.max.y, margin);
}

/* Whether the family lays the region out as a tile (many regions: no
 * seams at its sides); a family without tiles ignores the parameter. */
static int is_tiled(const qc_family_desc *family, const qc_params *p)
{
    return (family->params & QC_PARAM_BIT(QC_PARAM_ID_TILE)) &&
           (p->tile == QC_TILE_EDGE_TO_EDGE || p->tile == QC_TILE_ALL_OVER);
}

static int sample_points(qc_ctx *ctx, const qc_region *region, const qc_params *p,
                         const qc_family_desc *family, const qc_points *given, qc_points *out)
{
    qc_sample_params sp;
    size_t i;
    int row;

    if (p->points == QC_POINTS_GIVEN) {
        if (given == NULL || given->n == 0)
            return qc__fail(ctx, QC_EEMPTY, "points 'given' but no points were supplied");
        if (given->n > QC_MAX_POINTS)
            return qc__fail(ctx, QC_ELIMIT, "%lu points exceed the limit of %lu",
                            (unsigned long)given->n, (unsigned long)QC_MAX_POINTS);
        QC__TRY(qc__check_given_inside(ctx, region, given, p->margin));
        for (i = 0; i < given->n; i++)
            QC__TRY(qc_points_push(ctx, out, given->v[i]));
        return QC_OK;
    }
    memset(&sp, 0, sizeof sp);
    sp.kind = p->points; /* a qc_sample_kind: QC_POINTS_GIVEN was handled above */
    sp.spacing = p->spacing;
    sp.margin = p->margin;
    sp.seed = p->seed;
    /* out to the seams, into corners, star points and strips; no row along
     * the seams for a family that reaches them itself, nor a tile (its
     * copies join at its sides) */
    if ((family->needs & QC_FAMILY_OWN_SEAMS) || is_tiled(family, p))
        row = QC__ROW_NONE;
    else
        row = p->skeleton == QC_SKELETON_TSP ? QC__ROW_TOUR : QC__ROW_TREE;
    QC__TRY(qc__sample_to_seams(ctx, region, &sp, row, out));
    if (out->n == 0)
        return qc__fail(ctx, QC_EEMPTY,
                        "no point fits in the region at spacing %g mm with margin %g mm",
                        p->spacing, p->margin);
    return QC_OK;
}

/* The root: the point nearest the requested start, else nearest the lower-left corner. */
static uint32_t pick_root(const qc_region *region, const qc_params *p, const qc_points *pts)
{
    qc_vec2 start;

    if (qc_params_given(p, QC_PARAM_ID_START_X) ||
        qc_params_given(p, QC_PARAM_ID_START_Y)) {
        start.x = p->start_x;
        start.y = p->start_y;
    } else {
        start = qc_region_bbox(region).min;
    }
    return qc_nearest_point(pts->v, pts->n, start);
}

/* A tour from ctx->tour must visit each of the n points once. */
static int check_permutation(qc_ctx *ctx, const qc_order *o, size_t n)
{
    unsigned char *seen;
    size_t i;
    int rc = QC_OK;

    if (o->n != n)
        return qc__fail(ctx, QC_EINVAL, "the caller's tour has %lu points, not %lu",
                        (unsigned long)o->n, (unsigned long)n);
    if ((seen = (unsigned char *)qc__alloc_array(ctx, n ? n : 1, 1)) == NULL)
        return QC_ENOMEM;
    memset(seen, 0, n);
    for (i = 0; i < n && rc == QC_OK; i++) {
        if (o->i[i] >= n || seen[o->i[i]])
            rc = qc__fail(ctx, QC_EINVAL, "the caller's tour is not a permutation of the "
                          "%lu points (point %lu)", (unsigned long)n, (unsigned long)o->i[i]);
        else
            seen[o->i[i]] = 1;
    }
    qc__free(ctx, seen, n ? n : 1);
    return rc;
}

static int build_tour(qc_ctx *ctx, const qc_params *p, const qc_points *pts,
                      uint32_t root, qc_order *order)
{
    qc_tsp_params tp;
    qc_order raw = {0};
    size_t i, at = 0;
    int rc;

    if (ctx->tour != NULL) {
        rc = ctx->tour(ctx->tour_ud, pts->v, pts->n, p->tsp_time_ms, &raw);
        if (rc == QC_OK)
            rc = check_permutation(ctx, &raw, pts->n);
    } else {
        memset(&tp, 0, sizeof tp);
        tp.method = p->tsp;
        tp.seed = p->seed;
        /* the core has no clock: the budget becomes a round count */
        tp.perturb_iterations = qc_tsp_rounds_for_ms(p->tsp_time_ms);
        rc = qc_tsp(ctx, pts->v, pts->n, &tp, &raw);
    }
    if (rc < 0)
        goto out;
    for (i = 0; i < raw.n; i++)
        if (raw.i[i] == root)
            at = i;
    for (i = 0; i < raw.n && rc == QC_OK; i++) /* rotate so the tour starts at root */
        rc = qc_order_push(ctx, order, raw.i[(at + i) % raw.n]);
out:
    qc_order_free(ctx, &raw);
    return rc;
}

static int build_skeleton(qc_ctx *ctx, const qc_region *region, const qc_params *p,
                          qc_result *res, qc_skeleton *skel)
{
    uint32_t root;

    memset(skel, 0, sizeof *skel);
    if (res->points.n == 0)
        return QC_OK;
    root = pick_root(region, p, &res->points);
    if (p->skeleton == QC_SKELETON_TSP) {
        trace(ctx, "tour");
        QC__TRY(build_tour(ctx, p, &res->points, root, &res->order));
    } else {
        trace(ctx, "graph");
        QC__TRY(qc_mst(ctx, res->points.v, res->points.n, (qc_mst_mode)p->mst, &res->edges));
        trace(ctx, "tour");
        QC__TRY(qc_tree_walk(ctx, res->points.v, res->points.n, res->edges.e,
                             res->edges.n, root, &res->order));
        skel->edges = res->edges.e;
        skel->nedges = res->edges.n;
    }
    skel->p = res->points.v;
    skel->n = res->points.n;
    skel->order = res->order.i;
    skel->norder = res->order.n;
    skel->root = root;
    return QC_OK;
}

int qc__generate_one(qc_ctx *ctx, const qc_region *region, const qc_points *given,
                     const qc_motif_set *motifs, qc_result *res)
{
    const qc_params *p = &res->params;
    qc_skeleton skel;
    const qc_family_desc *family = qc__family(p->family);

    if (family == NULL)
        return qc__fail(ctx, QC_EINVAL, "unknown family %d", p->family);
    if (region == NULL || region->nrings == 0)
        return qc__fail(ctx, QC_EEMPTY, "the region has no outline");
    if (family->needs & QC_FAMILY_NEEDS_POINTS) {
        trace(ctx, "sample");
        QC__TRY(sample_points(ctx, region, p, family, given, &res->points));
    }
    QC__TRY(build_skeleton(ctx, region, p, res, &skel));
    trace(ctx, "decorate");
    QC__TRY(family->run(ctx, region, p, &skel, motifs, &res->path, &res->stats));
    if (!is_tiled(family, p))
        QC__TRY(qc__path_keep_inside(ctx, region, family->name, &res->path, NULL));
    if (res->path.ncmd == 0)
        return qc__fail(ctx, QC_EEMPTY, "the %s family produced no path in this region",
                        family->name);
    qc__path_fit(ctx, &res->path);
    res->stats.points = res->points.n;
    res->stats.edges = res->edges.n;
    res->stats.order = res->order.n;
    qc_curve_measure(&res->path, STATS_TOL_MM, &res->stats.length_mm, &res->stats.bbox);
    res->stats.pieces = qc_path_pieces(&res->path);
    if (!p->skip_gap_stat) {
        trace(ctx, "measure");
        QC__TRY(qc_result_measure(ctx, region, res));
    }
    trace(ctx, "done");
    return QC_OK;
}

int qc_generate(qc_ctx *ctx, const qc_region *region, const qc_params *params,
                const qc_points *given, const qc_motif_set *motifs, qc_result *out)
{
    int rc;

    memset(out, 0, sizeof *out);
    rc = qc_params_resolve(ctx, params, &out->params);
    if (rc == QC_OK) {
        int handled = 0;

        rc = qc__generate_pieces(ctx, region, given, motifs, out, &handled);
        if (rc == QC_OK && !handled)
            rc = qc__generate_one(ctx, region, given, motifs, out);
    }
    if (rc < 0)
        qc_result_free(ctx, out);
    return rc;
}

void qc_result_free(qc_ctx *ctx, qc_result *res)
{
    if (res == NULL)
        return;
    qc_points_free(ctx, &res->points);
    qc_edges_free(ctx, &res->edges);
    qc_order_free(ctx, &res->order);
    qc_path_free(ctx, &res->path);
    memset(res, 0, sizeof *res);
}

/* The farthest fabric, the same figure for every family (the CLI's --stats,
 * the page and `quiltc check --region` all report it). */
int qc_result_measure(qc_ctx *ctx, const qc_region *region, qc_result *res)
{
    qc_fabric f;

    QC__TRY(qc_path_fabric(ctx, region, &res->path,
                           res->params.spacing * FABRIC_RES, 0.0,
                           NULL, &f));
    res->stats.farthest_fabric_mm = f.farthest_mm;
    res->stats.seam_bare = f.seam_bare;
    return QC_OK;
}
