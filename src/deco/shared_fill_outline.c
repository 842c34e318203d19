/*
 * The outline runner shared by Fixed-width fill (family_fill.c) and
 * Stippling (family_stipple.c), paper §7.1, Fig. 26: the spanning tree
 * outlined at width w as one closed, non-crossing loop (shared_fill_tree.c),
 * drawn straight (fill) or through a centripetal Catmull-Rom spline
 * (stipple). With a tile mode
 * the region is a tile: the path runs from its left port to its mirrored
 * right port (the ports joined to the tree as extra leaves, the port-to-port
 * branch crossed once) and the tile is laid out repeat_cols x repeat_rows.
 */
#include <math.h>
#include <string.h>

#include "deco_internal.h"

/* Largest-gap statistic resolution, times d. */
#define GAP_RES (1.0 / 6.0)

/* Tile: the outline from the left port to the right port. */
static int tile_outline(qc_ctx *ctx, const qc_region *region, const qc_params *prm,
                        const qc_skeleton *skel, qc__fstyle *st, qc_points *pts,
                        qc_vec2 *entry, qc_vec2 *exit)
{
    size_t n = skel->n, ne = skel->nedges, i;
    qc_vec2 *p = qc__alloc_array(ctx, n + 2, sizeof *p);
    qc_edge *e = qc__alloc_array(ctx, ne + 2, sizeof *e);
    double *tip = qc__alloc_array(ctx, n + 2, sizeof *tip);
    qc__ftree t;
    qc_bbox box = qc_region_bbox(region);
    int rc, all = prm->tile == QC_TILE_ALL_OVER;

    memset(&t, 0, sizeof t);
    if (p == NULL || e == NULL || tip == NULL) {
        rc = QC_ENOMEM;
        goto out;
    }
    rc = qc_tile_ports(ctx, region, entry, exit);
    if (rc < 0)
        goto out;
    memcpy(p, skel->p, n * sizeof *p);
    if (ne > 0) /* a one-point skeleton has no edge array */
        memcpy(e, skel->edges, ne * sizeof *e);
    p[n] = *entry;
    p[n + 1] = *exit;
    e[ne].a = qc__tile_port_node(skel->p, n, skel->edges, ne, *entry);
    e[ne].b = (uint32_t)n;
    e[ne + 1].a = qc__tile_port_node(skel->p, n, skel->edges, ne, *exit);
    e[ne + 1].b = (uint32_t)(n + 1);
    /* wrap: a tip circle keeps clear of the edges a neighbouring tile shares */
    for (i = 0; i < n + 2; i++) {
        double room = fmin(p[i].x - box.min.x, box.max.x - p[i].x);
        if (all)
            room = fmin(room, fmin(p[i].y - box.min.y, box.max.y - p[i].y));
        tip[i] = fmin(st->tip, room - 0.1 * st->half * 2.0);
    }
    st->tip_at = tip;
    rc = qc__ftree_build(ctx, p, n + 2, e, ne + 2, &t);
    if (rc == QC_OK)
        rc = qc__ftree_open(ctx, &t, (uint32_t)n, (uint32_t)(n + 1), st, pts);
out:
    st->tip_at = NULL;
    qc__ftree_free(ctx, &t);
    qc__free(ctx, p, (n + 2) * sizeof *p);
    qc__free(ctx, e, (ne + 2) * sizeof *e);
    qc__free(ctx, tip, (n + 2) * sizeof *tip);
    return rc;
}

int qc__fill_outline(qc_ctx *ctx, const qc_region *region, const qc_params *prm,
                     const qc_skeleton *skel, const qc__outline_style *style, qc_path *out,
                     qc_stats *stats)
{
    const char *name = style->name;
    qc__fstyle st;
    qc__ftree t;
    qc_points pts = {0};
    qc_path one = {0}, rep = {0};
    qc_vec2 entry, exit;
    double d = prm->spacing, w = prm->width;
    int tiled = prm->tile == QC_TILE_EDGE_TO_EDGE || prm->tile == QC_TILE_ALL_OVER;
    size_t i;
    int rc;

    memset(&t, 0, sizeof t);
    if (skel->n == 0)
        return qc__fail(ctx, QC_EEMPTY, "%s needs at least one point", name);
    if (skel->n > 1 && (skel->edges == NULL || skel->nedges + 1 != skel->n))
        return qc__fail(ctx, QC_EINVAL, "%s needs a spanning tree (skeleton mst), got %lu edges "
                        "for %lu points", name, (unsigned long)skel->nedges,
                        (unsigned long)skel->n);
    if (!(w > 0.0) || !(d > 0.0))
        return qc__fail(ctx, QC_ERANGE, "%s width %g mm and spacing %g mm must be > 0", name,
                        w, d);
    memset(&st, 0, sizeof st);
    st.half = 0.5 * w;
    st.tip = prm->tip == QC_TIP_CIRCLE ? fmin(1.5 * w, 0.4 * d) : 0.0;
    st.arc_step = style->arc_step;
    if (tiled) {
        rc = tile_outline(ctx, region, prm, skel, &st, &pts, &entry, &exit);
    } else {
        rc = qc__ftree_build(ctx, skel->p, skel->n, skel->edges, skel->nedges, &t);
        if (rc == QC_OK)
            rc = qc__ftree_loop(ctx, &t, skel->root < skel->n ? skel->root : 0, &st, &pts);
    }
    if (rc < 0)
        goto out;
    if (style->smooth) {
        rc = qc_curve_catmull_rom(ctx, pts.v, pts.n, !tiled, &one);
    } else {
        rc = qc_path_move_to(ctx, &one, pts.v[0]);
        for (i = 1; i < pts.n && rc == QC_OK; i++)
            rc = qc_path_line_to(ctx, &one, pts.v[i]);
        if (rc == QC_OK && !tiled)
            rc = qc_path_line_to(ctx, &one, pts.v[0]);
    }
    if (rc < 0)
        goto out;
    if (stats != NULL && !prm->skip_gap_stat) {
        double g = qc_path_largest_gap(ctx, region, &one, GAP_RES * d, NULL);
        if (g < 0.0) {
            rc = (int)g;
            goto out;
        }
        stats->largest_gap_mm = g;
    }
    if (tiled) {
        qc_bbox box = qc_region_bbox(region);
        unsigned cols = prm->repeat_cols >= 1.0 ? (unsigned)prm->repeat_cols : 1u;
        unsigned rows = prm->repeat_rows >= 1.0 ? (unsigned)prm->repeat_rows : 1u;
        double h = box.max.y - box.min.y;
        size_t k;

        rc = qc_tile_layout(ctx, &one, exit.x - entry.x, h, cols, rows, prm->row_offset, &rep);
        /* rows are sewn top down: lift them so the bottom row sits on the
         * tile's own box, keeping every coordinate above the region's corner */
        for (k = 0; k < rep.npt; k++)
            rep.pt[k].y += (double)(rows - 1) * h;
        if (rc == QC_OK)
            rc = qc_path_append(ctx, out, &rep, 1);
    } else {
        rc = qc_path_append(ctx, out, &one, 1);
    }
out:
    qc__ftree_free(ctx, &t);
    qc_points_free(ctx, &pts);
    qc_path_free(ctx, &one);
    qc_path_free(ctx, &rep);
    return rc;
}
