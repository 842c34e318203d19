/* The block outline: a built-in shape or an SVG file, normalized and moved to the origin. */
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cli.h"

#define MAX_SVG_BYTES ((size_t)16 << 20)

static int looks_like_file(const char *spec)
{
    struct stat st;
    size_t n = strlen(spec);

    return (n > 4 && strcmp(spec + n - 4, ".svg") == 0) || stat(spec, &st) == 0 ||
           strchr(spec, '/') != NULL;
}

static int read_svg(qc_ctx *ctx, const char *path, qc_region *out)
{
    qc_svg_opts opts;
    char *buf;
    size_t len;
    int rc;

    if (cli_read_file(path, MAX_SVG_BYTES, &buf, &len) != 0)
        return CLI_RUNTIME;
    cli_svg_opts(&opts, path, MAX_SVG_BYTES);
    rc = qc_io_read_svg_region(ctx, buf, len, &opts, out);
    free(buf);
    if (rc == QC_OK)
        rc = qc_region_normalize(ctx, out);
    if (rc < 0) {
        cli_error("%s: %s", path, qc_errmsg(ctx));
        qc_region_free(ctx, out);
        return CLI_RUNTIME;
    }
    return CLI_OK;
}

/* A shape whose sizes end in a unit, "rect:8x8in", "circle:20cm", takes
 * that unit instead of --units, as lengths do. */
static int shape(qc_ctx *ctx, const char *spec, double mm_per_unit, qc_region *out)
{
    static const char *const units[] = {"mm", "cm", "in"};
    size_t n = strlen(spec), i;
    char buf[128];

    for (i = 0; i < 3; i++)
        if (n > 2 && n < sizeof buf && strcmp(spec + n - 2, units[i]) == 0 &&
            spec[n - 3] >= '0' && spec[n - 3] <= '9') {
            memcpy(buf, spec, n - 2);
            buf[n - 2] = '\0';
            return qc_region_shape(ctx, buf, cli_units_mm(units[i]), out);
        }
    return qc_region_shape(ctx, spec, mm_per_unit, out);
}

int cli_load_region(qc_ctx *ctx, const char *spec, double mm_per_unit, qc_region *out)
{
    qc_bbox box;

    memset(out, 0, sizeof *out);
    if (looks_like_file(spec)) {
        int rc = read_svg(ctx, spec, out);
        if (rc != CLI_OK)
            return rc;
    } else if (shape(ctx, spec, mm_per_unit, out) < 0) {
        cli_error("--region: %s", qc_errmsg(ctx));
        return CLI_USAGE;
    }
    box = qc_region_bbox(out);
    qc_region_translate(out, -box.min.x, -box.min.y);
    return CLI_OK;
}

/* A quilt top's patches (or a block outline) for checking a pattern
 * against: every patch's rings in one region, not normalized, since
 * patches share seams; the even-odd inside test still holds because
 * patches do not overlap. Moved to the origin as quiltc quilt moves it,
 * and with ps != NULL the patches themselves, moved alike (none for a
 * shape spec). */
int cli_load_top_patches(qc_ctx *ctx, const char *spec, double mm_per_unit, qc_region *out,
                         qc_patches *ps)
{
    qc_patches own;
    qc_patches *top = ps != NULL ? ps : &own;
    qc_svg_opts opts;
    qc_bbox box;
    char *buf;
    size_t len, i, k;
    int rc;

    memset(top, 0, sizeof *top);
    if (!looks_like_file(spec))
        return cli_load_region(ctx, spec, mm_per_unit, out);
    memset(out, 0, sizeof *out);
    if (cli_read_file(spec, MAX_SVG_BYTES, &buf, &len) != 0)
        return CLI_RUNTIME;
    cli_svg_opts(&opts, spec, MAX_SVG_BYTES);
    rc = qc_io_read_svg_patches(ctx, buf, len, &opts, top);
    free(buf);
    for (i = 0; rc == QC_OK && i < top->n; i++)
        for (k = 0; rc == QC_OK && k < top->p[i].region.nrings; k++) {
            const qc_region *r = &top->p[i].region;
            size_t s = k ? r->ring_end[k - 1] : 0;
            rc = qc_region_add_ring(ctx, out, r->v + s, r->ring_end[k] - s);
        }
    if (rc < 0) {
        cli_error("%s: %s", spec, qc_errmsg(ctx));
        qc_region_free(ctx, out);
        qc_patches_free(ctx, top);
        return CLI_RUNTIME;
    }
    box = qc_region_bbox(out);
    qc_region_translate(out, -box.min.x, -box.min.y);
    for (i = 0; i < top->n; i++)
        qc_region_translate(&top->p[i].region, -box.min.x, -box.min.y);
    if (ps == NULL)
        qc_patches_free(ctx, &own);
    return CLI_OK;
}

int cli_load_top(qc_ctx *ctx, const char *spec, double mm_per_unit, qc_region *out)
{
    return cli_load_top_patches(ctx, spec, mm_per_unit, out, NULL);
}
