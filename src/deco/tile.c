/* Tiles: the entry and exit ports of a tile and the pantograph layout of copies. */
#include <math.h>

#include "deco_internal.h"

int qc_tile_ports(qc_ctx *ctx, const qc_region *region, qc_vec2 *entry, qc_vec2 *exit)
{
    qc_bbox box;
    double y, lo = HUGE_VAL, hi = -HUGE_VAL, tol;
    size_t k, rs = 0;

    if (region == NULL || region->nrings == 0)
        return qc__fail(ctx, QC_EINVAL, "tile ports: the region has no ring");
    box = qc_region_bbox(region);
    y = 0.5 * (box.min.y + box.max.y);
    for (k = 0; k < region->nrings; k++) {
        size_t end = region->ring_end[k], i, p = end - 1;

        for (i = rs; i < end; p = i++) {
            qc_vec2 a = region->v[p], b = region->v[i];
            if ((a.y > y) != (b.y > y)) {
                double x = a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y);
                lo = fmin(lo, x);
                hi = fmax(hi, x);
            } else if (a.y == y && b.y == y) {
                lo = fmin(lo, fmin(a.x, b.x));
                hi = fmax(hi, fmax(a.x, b.x));
            }
        }
        rs = end;
    }
    if (!(lo < HUGE_VAL))
        return qc__fail(ctx, QC_EINVAL, "tile ports: the line y = %g mm misses the region", y);
    /* the next copy enters where this one leaves, a tile width on: that
     * point is on the outline only when the line meets both sides of the
     * box (a rectangle's do; a heart's do not, and its copies would be
     * sewn across the fabric outside it) */
    tol = 1e-9 * (box.max.x - box.min.x);
    if (lo > box.min.x + tol || hi < box.max.x - tol)
        return qc__fail(ctx, QC_EINVAL,
                        "tile: at mid-height (y = %g mm) the region spans x = %g..%g mm, not "
                        "its full width %g..%g mm; copies join at the left and right edges, "
                        "so a tile must reach both there (a rectangle does)",
                        y, lo, hi, box.min.x, box.max.x);
    entry->x = lo;
    entry->y = y;
    exit->x = lo + (box.max.x - box.min.x);
    exit->y = y;
    return QC_OK;
}

/* Appends tile moved by (tx, ty), reversed when rev, without its first point. */
static int append_copy(qc_ctx *ctx, const qc_path *tile, double tx, double ty, int rev,
                       qc_path *out)
{
    size_t c, k;

    if (!rev) {
        for (c = 1, k = 1; c < tile->ncmd; c++) {
            const qc_vec2 *q = tile->pt + k;
            qc_vec2 a, b, e;

            if (tile->cmd[c] == QC_PATH_CUBIC) {
                a.x = q[0].x + tx; a.y = q[0].y + ty;
                b.x = q[1].x + tx; b.y = q[1].y + ty;
                e.x = q[2].x + tx; e.y = q[2].y + ty;
                QC__TRY(qc_path_cubic_to(ctx, out, a, b, e));
                k += 3;
            } else {
                e.x = q[0].x + tx; e.y = q[0].y + ty;
                QC__TRY(qc_path_line_to(ctx, out, e));
                k += 1;
            }
        }
        return QC_OK;
    }
    k = tile->npt;
    for (c = tile->ncmd; c-- > 1;) {
        size_t m = qc_path_cmd_points(tile->cmd[c]);
        const qc_vec2 *q = tile->pt + k - m;
        qc_vec2 s = tile->pt[k - m - 1], a, b, e; /* the command's start point */

        e.x = s.x + tx; e.y = s.y + ty;
        if (tile->cmd[c] == QC_PATH_CUBIC) {
            a.x = q[1].x + tx; a.y = q[1].y + ty;
            b.x = q[0].x + tx; b.y = q[0].y + ty;
            QC__TRY(qc_path_cubic_to(ctx, out, a, b, e));
        } else {
            QC__TRY(qc_path_line_to(ctx, out, e));
        }
        k -= m;
    }
    return QC_OK;
}

int qc__tile_budget(qc_ctx *ctx, size_t tile_points, unsigned cols, unsigned rows)
{
    double total = (double)tile_points * (double)cols * (double)rows;

    if (total > (double)QC_MAX_TILED_POINTS)
        return qc__fail(ctx, QC_ELIMIT,
                        "tiles: %u x %u copies of a %lu-point tile make %.0f points, over the "
                        "limit of %u; repeat fewer tiles or raise the spacing",
                        cols, rows, (unsigned long)tile_points, total, QC_MAX_TILED_POINTS);
    return QC_OK;
}

/* The rows of qc_tile_layout (jump: each row its own piece) and of
 * qc_tile_repeat (rows joined by a line down the side), appended to out
 * (checked arguments). Rows alternate direction, so the next row starts on
 * the side where the last one ended. */
static int append_rows(qc_ctx *ctx, const qc_path *tile, double dx, double dy, unsigned cols,
                       unsigned rows, double offset, int jump, qc_path *out)
{
    unsigned r, c;

    for (r = 0; r < rows; r++) {
        int rev = (int)(r & 1u);
        double ty = -(double)r * dy, shift = rev ? offset * dx : 0.0;

        for (c = 0; c < cols; c++) {
            unsigned col = rev ? cols - 1 - c : c;
            double tx = (double)col * dx + shift;

            if (c == 0) {
                qc_vec2 s = rev ? tile->pt[tile->npt - 1] : tile->pt[0];
                s.x += tx;
                s.y += ty;
                if (out->ncmd == 0 || jump)
                    QC__TRY(qc_path_move_to(ctx, out, s));
                else
                    QC__TRY(qc_path_line_to(ctx, out, s));
            }
            QC__TRY(append_copy(ctx, tile, tx, ty, rev, out));
        }
    }
    return QC_OK;
}

/* Both layouts: arguments checked, out as on entry after an error. */
static int layout(qc_ctx *ctx, const qc_path *tile, double dx, double dy, unsigned cols,
                  unsigned rows, double offset, int jump, qc_path *out)
{
    size_t ncmd0 = out->ncmd, npt0 = out->npt;
    int rc;

    if (tile == NULL || tile->ncmd < 2 || tile->cmd[0] != QC_PATH_MOVE ||
        qc_path_pieces(tile) != 1)
        return qc__fail(ctx, QC_EINVAL, "tile repeat: the tile must be one piece of 2+ commands");
    if (cols == 0 || rows == 0)
        return qc__fail(ctx, QC_EINVAL, "tile repeat: %ux%u tiles", cols, rows);
    if (!isfinite(dx) || !isfinite(dy))
        return qc__fail(ctx, QC_EINVAL, "tile repeat: step (%g, %g) mm is not finite", dx, dy);
    if (!(offset >= 0.0 && offset < 1.0))
        return qc__fail(ctx, QC_EINVAL, "tile repeat: row offset %g is not in [0, 1)", offset);
    QC__TRY(qc__tile_budget(ctx, tile->npt, cols, rows));
    rc = append_rows(ctx, tile, dx, dy, cols, rows, offset, jump, out);
    if (rc < 0) { /* as on entry (core.h) */
        out->ncmd = ncmd0;
        out->npt = npt0;
    }
    return rc;
}

int qc_tile_layout(qc_ctx *ctx, const qc_path *tile, double dx, double dy, unsigned cols,
                   unsigned rows, double offset, qc_path *out)
{
    return layout(ctx, tile, dx, dy, cols, rows, offset, 1, out);
}

int qc_tile_repeat(qc_ctx *ctx, const qc_path *tile, double dx, double dy, unsigned cols,
                   unsigned rows, qc_path *out)
{
    return layout(ctx, tile, dx, dy, cols, rows, 0.0, 0, out);
}

/* Whether the segment a-p[bi] crosses or touches a tree edge not at bi. */
static int stub_crosses(const qc_vec2 *p, const qc_edge *e, size_t ne, qc_vec2 a, uint32_t bi)
{
    qc_vec2 b = p[bi];
    size_t k;

    for (k = 0; k < ne; k++) {
        qc_vec2 c = p[e[k].a], d = p[e[k].b];
        double o1, o2, o3, o4;

        if (e[k].a == bi || e[k].b == bi)
            continue;
        o1 = qc_orient2d(a, b, c);
        o2 = qc_orient2d(a, b, d);
        o3 = qc_orient2d(c, d, a);
        o4 = qc_orient2d(c, d, b);
        if (((o1 >= 0.0 && o2 <= 0.0) || (o1 <= 0.0 && o2 >= 0.0)) &&
            ((o3 >= 0.0 && o4 <= 0.0) || (o3 <= 0.0 && o4 >= 0.0)))
            return 1;
    }
    return 0;
}

uint32_t qc__tile_port_node(const qc_vec2 *p, size_t n, const qc_edge *e, size_t ne, qc_vec2 a)
{
    uint32_t best[PORT_CANDIDATES];
    double bd[PORT_CANDIDATES];
    size_t m = 0, i, k;

    for (i = 0; i < n; i++) {
        double dd = (p[i].x - a.x) * (p[i].x - a.x) + (p[i].y - a.y) * (p[i].y - a.y);
        if (m == PORT_CANDIDATES && dd >= bd[PORT_CANDIDATES - 1])
            continue;
        k = m < PORT_CANDIDATES ? m++ : PORT_CANDIDATES - 1;
        while (k > 0 && bd[k - 1] > dd) {
            bd[k] = bd[k - 1];
            best[k] = best[k - 1];
            k--;
        }
        bd[k] = dd;
        best[k] = (uint32_t)i;
    }
    for (k = 0; k < m; k++)
        if (!stub_crosses(p, e, ne, a, best[k]))
            return best[k];
    return best[0];
}
