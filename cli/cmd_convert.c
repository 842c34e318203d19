/* quiltc convert IN OUT: a pattern in any format quiltc writes into any other. */
#include <stdlib.h>
#include <string.h>

#include "cli.h"

#define MAX_INPUT ((size_t)256 << 20)

/* Reads IN into a plan, in whichever machine format its extension names. */
int cli_read_plan(qc_ctx *ctx, const char *path, qc_plan *plan)
{
    char *buf;
    size_t len;
    int fmt = qc_format_from_name(path), rc;

    if (fmt < 0) {
        cli_error("'%s': unknown pattern format (pat, qli, dxf, plt, qcc, iqp, bqm, gcode, svg)",
                  path);
        return CLI_USAGE;
    }
    if (cli_read_file(path, MAX_INPUT, &buf, &len) != 0)
        return CLI_RUNTIME;
    if (fmt == QC_FORMAT_SVG) {
        /* as qc_io_read, with the reader's warnings printed */
        qc_svg_opts opts;
        qc_path sewn = {0};

        cli_svg_opts(&opts, path, 0); /* the reader's own limit, as qc_io_read */
        memset(plan, 0, sizeof *plan);
        rc = qc_io_read_svg_path(ctx, buf, len, &opts, &sewn);
        if (rc == QC_OK)
            rc = qc_stitch_plan(ctx, &sewn, NULL, NULL, plan);
        qc_path_free(ctx, &sewn);
    } else {
        rc = qc_io_read(ctx, fmt, buf, len, plan);
    }
    free(buf);
    if (rc < 0) {
        cli_error("%s: %s", path, qc_errmsg(ctx));
        return CLI_RUNTIME;
    }
    return CLI_OK;
}

int cmd_convert(int argc, char **argv)
{
    qc_ctx ctx;
    qc_plan plan = {0};
    qc_io_opts io;
    int fmt, rc;

    if (argc == 2 && strcmp(argv[1], "--help") == 0) {
        puts("usage: quiltc convert IN.ext OUT.ext\n"
             "Writes the pattern of IN in OUT's format; both are any of pat, qli, dxf,\n"
             "plt (hpgl), qcc, iqp, bqm, gcode (nc), svg. Travel stays travel (QCC has none).\n"
             "From an SVG every shape is sewn except dashed lines (jumps) and the\n"
             "element with id=\"region\" (the outline quiltc draws in its previews).");
        return CLI_OK;
    }
    if (argc != 3) {
        cli_error("convert: expected IN and OUT (see 'quiltc convert --help')");
        return CLI_USAGE;
    }
    fmt = qc_format_from_name(argv[2]);
    if (fmt < 0) {
        cli_error("'%s': unknown output format", argv[2]);
        return CLI_USAGE;
    }
    qc_ctx_init(&ctx, NULL, NULL);
    rc = cli_read_plan(&ctx, argv[1], &plan);
    if (rc == CLI_OK) {
        memset(&io, 0, sizeof io);
        io.svg_inches = 1;
        rc = cli_write_plan(&ctx, argv[2], fmt, &plan, &io);
    }
    qc_plan_free(&ctx, &plan);
    return rc;
}
