/*
 * The writers' common guard: a pattern reaching outside its block (a family
 * at --margin 0 may stray 2 mm past the edge) is refused with one message
 * for every output format, before any file is opened. Before this, .pat
 * alone refused (a negative coordinate) while .svg, .dxf and .gcode were
 * written silently. What is sewn is checked: the stitches, or a path's
 * curves flattened (a cubic's control points may lie past the seam while
 * the curve stays inside).
 */
#include "cli.h"

#define SLACK_MM 1e-6 /* rounding in the tile layout; nothing a machine would sew */
#define FLAT_TOL_MM 0.01 /* the curve within this of its flattened points */

int cli_check_inside(const qc_vec2 *p, size_t n, const qc_params *resolved,
                     const qc_region *region, const char *region_name, const char *what)
{
    qc_bbox box = qc_region_bbox(region), got;
    double w = box.max.x - box.min.x, h = box.max.y - box.min.y;
    size_t i;

    if (n == 0)
        return CLI_OK;
    if (resolved->tile == QC_TILE_EDGE_TO_EDGE || resolved->tile == QC_TILE_ALL_OVER) {
        /* tiles are laid out right and up from the first tile's box */
        /* odd rows moved right by the row offset (qc_tile_layout) */
        box.max.x = box.min.x + w * (resolved->repeat_cols >= 1 ? resolved->repeat_cols : 1) +
                    (resolved->repeat_rows >= 2 ? resolved->row_offset * w : 0.0);
        box.max.y = box.min.y + h * (resolved->repeat_rows >= 1 ? resolved->repeat_rows : 1);
    }
    got.min = got.max = p[0];
    for (i = 1; i < n; i++) {
        got.min.x = p[i].x < got.min.x ? p[i].x : got.min.x;
        got.min.y = p[i].y < got.min.y ? p[i].y : got.min.y;
        got.max.x = p[i].x > got.max.x ? p[i].x : got.max.x;
        got.max.y = p[i].y > got.max.y ? p[i].y : got.max.y;
    }
    if (got.min.x >= box.min.x - SLACK_MM && got.min.y >= box.min.y - SLACK_MM &&
        got.max.x <= box.max.x + SLACK_MM && got.max.y <= box.max.y + SLACK_MM)
        return CLI_OK;
    cli_error("%s: the %s pattern reaches %.4g..%.4g, %.4g..%.4g mm, outside the region %s "
              "(%.4g..%.4g, %.4g..%.4g mm); no file is written (a larger margin keeps it inside)",
              what, qc_family_name(resolved->family), got.min.x, got.max.x, got.min.y, got.max.y,
              region_name, box.min.x, box.max.x, box.min.y, box.max.y);
    return CLI_RUNTIME;
}

int cli_check_path_inside(qc_ctx *ctx, const qc_path *path, const qc_params *resolved,
                          const qc_region *region, const char *region_name, const char *what)
{
    qc_points flat = {0};
    int rc;

    if (qc_curve_flatten(ctx, path, FLAT_TOL_MM, &flat, NULL) < 0)
        return cli_fail(ctx, what, ctx->status);
    rc = cli_check_inside(flat.v, flat.n, resolved, region, region_name, what);
    qc_points_free(ctx, &flat);
    return rc;
}
