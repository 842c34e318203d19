/*
 * Branching tiles (paper §7.1, Fig. 27): "distributing two special
 * vertically-mirrored points ..., using the tree node containing the start
 * point as the root ... and modifying the traversal algorithm such that the
 * skeleton path terminates at the end point". The ports are added to the
 * tree as leaves; qc_tree_walk_to defers, at each node, the child towards the exit
 * port, so every other branch is sewn down and back as a detour and the
 * walk ends at the exit without returning. Collision tests see each item
 * also where it sits in the neighbouring tiles.
 */
#include <math.h>
#include <string.h>

#include "family_branching_tile.h"

void qc__btile_free(qc_ctx *ctx, qc__btile *t)
{
    if (t == NULL)
        return;
    qc__free(ctx, t->p, t->n * sizeof *t->p);
    qc__free(ctx, t->e, t->ne * sizeof *t->e);
    qc_order_free(ctx, &t->order);
    qc__free(ctx, t->tmp, t->tmp_cap * sizeof *t->tmp);
    memset(t, 0, sizeof *t);
}

int qc__btile_make(qc_ctx *ctx, const qc_region *region, const qc_skeleton *skel,
                   int all_over, qc__btile *t, qc_skeleton *out)
{
    size_t n = skel->n, i;
    qc_bbox box;
    int rc;

    memset(t, 0, sizeof *t);
    if (n == 0)
        return qc__fail(ctx, QC_EEMPTY, "branching needs at least one point");
    if (n > 1 && (skel->edges == NULL || skel->nedges + 1 != n))
        return qc__fail(ctx, QC_EINVAL, "branching tiles need a spanning tree (skeleton mst), "
                        "got %lu edges for %lu points",
                        (unsigned long)(skel->edges != NULL ? skel->nedges : 0),
                        (unsigned long)n);
    if (n > (size_t)UINT32_MAX - 2)
        return qc__fail(ctx, QC_ELIMIT, "branching tile of %lu points", (unsigned long)n);
    for (i = 0; i + 1 < n; i++)
        if (skel->edges[i].a >= n || skel->edges[i].b >= n || skel->edges[i].a == skel->edges[i].b)
            return qc__fail(ctx, QC_EINVAL, "edge %lu (%lu, %lu) is not an edge of %lu points",
                            (unsigned long)i, (unsigned long)skel->edges[i].a,
                            (unsigned long)skel->edges[i].b, (unsigned long)n);
    QC__TRY(qc_tile_ports(ctx, region, &t->entry, &t->exit));
    box = qc_region_bbox(region);
    t->dx = t->exit.x - t->entry.x;
    t->dy = box.max.y - box.min.y;
    t->shift[t->nshift++] = (qc_vec2){t->dx, 0.0};
    t->shift[t->nshift++] = (qc_vec2){-t->dx, 0.0};
    if (all_over) {
        int sx, sy;
        for (sy = -1; sy <= 1; sy += 2)
            for (sx = -1; sx <= 1; sx++)
                t->shift[t->nshift++] = (qc_vec2){sx * t->dx, sy * t->dy};
    }
    t->p = qc__alloc_array(ctx, n + 2, sizeof *t->p);
    t->e = qc__alloc_array(ctx, n + 1, sizeof *t->e);
    if (t->p == NULL || t->e == NULL) {
        qc__free(ctx, t->p, (n + 2) * sizeof *t->p);
        qc__free(ctx, t->e, (n + 1) * sizeof *t->e);
        memset(t, 0, sizeof *t);
        return QC_ENOMEM;
    }
    t->n = n + 2;
    t->ne = n + 1;
    memcpy(t->p, skel->p, n * sizeof *t->p);
    if (n > 1)
        memcpy(t->e, skel->edges, (n - 1) * sizeof *t->e);
    t->p[n] = t->entry;
    t->p[n + 1] = t->exit;
    t->e[n - 1].a = qc__tile_port_node(skel->p, n, t->e, n - 1, t->entry);
    t->e[n - 1].b = (uint32_t)n;
    t->e[n].a = qc__tile_port_node(skel->p, n, t->e, n - 1, t->exit);
    t->e[n].b = (uint32_t)(n + 1);
    rc = qc_tree_walk_to(ctx, t->p, t->n, t->e, t->ne, (uint32_t)(t->n - 2),
                         (uint32_t)(t->n - 1), &t->order);
    if (rc < 0) {
        qc__btile_free(ctx, t);
        return rc;
    }
    memset(out, 0, sizeof *out);
    out->p = t->p;
    out->n = t->n;
    out->edges = t->e;
    out->nedges = t->ne;
    out->order = t->order.i;
    out->norder = t->order.n;
    out->root = (uint32_t)n;
    return QC_OK;
}

void qc__btile_offset_rows(qc__btile *t, double row_offset)
{
    double o = row_offset * t->dx;
    int sx, sy;

    if (t->nshift != 8 || !(row_offset > 0))
        return; /* edge-to-edge: no neighbour above or below */
    t->nshift = 2;
    for (sy = -1; sy <= 1; sy += 2)
        for (sx = -1; sx <= 1; sx++) {
            t->shift[t->nshift++] = (qc_vec2){sx * t->dx + o, sy * t->dy};
            t->shift[t->nshift++] = (qc_vec2){sx * t->dx - o, sy * t->dy};
        }
}

void qc__btile_flat_ports(const qc__btile *t, qc_path *vine)
{
    size_t m = vine->npt;
    qc_vec2 *q = vine->pt;
    double l;

    if (vine->ncmd < 2 || m < 4)
        return;
    q[0] = t->entry;
    q[m - 1] = t->exit;
    l = qc_hypot(q[1].x - q[0].x, q[1].y - q[0].y);
    q[1].x = q[0].x + l;
    q[1].y = q[0].y;
    l = qc_hypot(q[m - 1].x - q[m - 2].x, q[m - 1].y - q[m - 2].y);
    q[m - 2].x = q[m - 1].x - l;
    q[m - 2].y = q[m - 1].y;
}

int qc__btile_grid_add(qc_ctx *ctx, qc__btile *t, qc__cgrid *g, const qc_vec2 *poly,
                       size_t n, unsigned kind, uint32_t id)
{
    double x1 = g->x0 + g->nx * g->cell, y1 = g->y0 + g->ny * g->cell;
    qc_bbox b;
    size_t i, k;

    QC__TRY(qc__cgrid_add(ctx, g, poly, n, kind, id));
    if (n == 0)
        return QC_OK;
    b.min = b.max = poly[0];
    for (i = 1; i < n; i++) {
        if (poly[i].x < b.min.x)
            b.min.x = poly[i].x;
        if (poly[i].y < b.min.y)
            b.min.y = poly[i].y;
        if (poly[i].x > b.max.x)
            b.max.x = poly[i].x;
        if (poly[i].y > b.max.y)
            b.max.y = poly[i].y;
    }
    for (k = 0; k < t->nshift; k++) {
        qc_vec2 s = t->shift[k];
        if (b.max.x + s.x < g->x0 || b.min.x + s.x > x1 || b.max.y + s.y < g->y0 ||
            b.min.y + s.y > y1)
            continue; /* that copy is beyond every query */
        QC__TRY(QC__RESERVE(ctx, t->tmp, t->tmp_cap, n));
        for (i = 0; i < n; i++) {
            t->tmp[i].x = poly[i].x + s.x;
            t->tmp[i].y = poly[i].y + s.y;
        }
        QC__TRY(qc__cgrid_add(ctx, g, t->tmp, n, kind, id));
    }
    return QC_OK;
}

int qc__btile_layout(qc_ctx *ctx, const qc__btile *t, const qc_params *prm, const qc_path *tile,
                     qc_path *out)
{
    unsigned cols = prm->repeat_cols >= 1.0 ? (unsigned)prm->repeat_cols : 1u;
    unsigned rows = prm->repeat_rows >= 1.0 ? (unsigned)prm->repeat_rows : 1u;
    size_t nc = out->ncmd, np = out->npt, k;
    double lift = (double)(rows - 1) * t->dy, copies = (double)cols * rows;
    int rc = qc__tile_budget(ctx, tile->npt, cols, rows);

    if (rc < 0)
        return rc;
    /* room for every copy at once: no regrowth of a large path */
    if (copies * (double)tile->npt + (double)np + rows < (double)SIZE_MAX / 32) {
        size_t k2 = (size_t)cols * rows;
        rc = QC__RESERVE(ctx, out->cmd, out->cmd_cap, nc + k2 * tile->ncmd + rows);
        if (rc == QC_OK)
            rc = QC__RESERVE(ctx, out->pt, out->pt_cap, np + k2 * tile->npt + rows);
    }
    if (rc == QC_OK)
        rc = qc_tile_layout(ctx, tile, t->dx, t->dy, cols, rows, prm->row_offset, out);
    if (rc < 0) {
        out->ncmd = nc;
        out->npt = np;
        return rc;
    }
    /* rows are sewn top down: lift them so the bottom row sits on the
     * tile's own box */
    for (k = np; k < out->npt; k++)
        out->pt[k].y += lift;
    return QC_OK;
}
