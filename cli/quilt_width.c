/*
 * --quilt-width W: as many pantograph columns as fit across the quilt. The
 * tile's width is its outline's (known once the region is loaded), and
 * the offset rows reach a fraction of a tile further, so that counts too.
 */
#include <math.h>

#include "cli.h"

int cli_fit_columns(qc_ctx *ctx, cli_pattern_opts *o, const char *width,
                    const qc_region *region)
{
    size_t n;
    const qc_param_info *cols = qc_param_find("repeat-cols");
    const char *u = cli_units_name(o->mm_per_unit);
    qc_params r;
    qc_bbox box = qc_region_bbox(region);
    double w = box.max.x - box.min.x, quilt, reach, fit;

    if (cli_parse_length(width, o->mm_per_unit, &quilt) != 0 || !(quilt > 0 && quilt <= 1e5)) {
        cli_error("--quilt-width: '%s' is not a length in (0, %g] %s", width,
                  1e5 / o->mm_per_unit, u);
        return CLI_USAGE;
    }
    if (qc_params_resolve(ctx, &o->params, &r) < 0)
        return cli_fail(ctx, "parameters", ctx->status);
    if (r.tile != QC_TILE_EDGE_TO_EDGE && r.tile != QC_TILE_ALL_OVER) {
        cli_error("--quilt-width lays out pantograph rows: give --tile edge-to-edge or all-over");
        return CLI_USAGE;
    }
    if (o->raw[cols - qc_param_table(&n)] != NULL) {
        cli_error("--quilt-width picks the columns: give it or --repeat/--repeat-cols, not both");
        return CLI_USAGE;
    }
    reach = r.repeat_rows >= 2 ? r.row_offset : 0.0; /* offset rows stick out */
    fit = floor(quilt / w - reach + 1e-9);
    if (fit < 1 || fit > cols->max) {
        cli_error("--quilt-width %g %s: %s tile of %.4g %s%s fits %.0f times across, not 1 to %g",
                  quilt / o->mm_per_unit, u, fit < 1 ? "a" : "the", w / o->mm_per_unit, u,
                  reach > 0 ? " (rows offset)" : "", fmax(fit, 0), cols->max);
        return CLI_USAGE;
    }
    if (qc_params_set(ctx, &o->params, "repeat-cols", fit) < 0)
        return cli_fail(ctx, "parameters", ctx->status);
    return CLI_OK;
}
