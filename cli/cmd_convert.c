/* quiltc convert IN OUT: a pattern in any format quiltc writes into any other. */
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "stats_json.h"

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
    cli_sewing sew = {12, 25.4, 0}; /* generate's defaults */
    const char *file[2] = {NULL, NULL};
    int fmt, rc, a, nfile = 0, quiet = 0;

    if (argc == 2 && strcmp(argv[1], "--help") == 0) {
        puts("usage: quiltc convert [-q] IN.ext OUT.ext\n"
             "Writes the pattern of IN in OUT's format; both are any of pat, qli, dxf,\n"
             "plt (hpgl), qcc, iqp, bqm, gcode (nc), svg. Travel stays travel (QCC has none).\n"
             "From an SVG every shape is sewn except dashed lines (jumps) and the\n"
             "element with id=\"region\" (the outline quiltc draws in its previews).\n"
             "Prints a line for the file written (-q, --quiet: none).");
        return CLI_OK;
    }
    for (a = 1; a < argc; a++) {
        if (strcmp(argv[a], "-q") == 0 || strcmp(argv[a], "--quiet") == 0)
            quiet = 1;
        else if (argv[a][0] == '-' && argv[a][1] != '\0') {
            cli_bad_option("convert", argv[a], '?');
            return CLI_USAGE;
        } else if (nfile == 2) {
            nfile++;
            break;
        } else
            file[nfile++] = argv[a];
    }
    if (nfile != 2) {
        cli_error("convert: expected IN and OUT (see 'quiltc convert --help')");
        return CLI_USAGE;
    }
    fmt = qc_format_from_name(file[1]);
    if (fmt < 0) {
        cli_error("'%s': unknown output format", file[1]);
        return CLI_USAGE;
    }
    qc_ctx_init(&ctx, NULL, NULL);
    rc = cli_read_plan(&ctx, file[0], &plan);
    if (rc == CLI_OK) {
        memset(&io, 0, sizeof io);
        io.svg_inches = 1;
        rc = cli_write_plan(&ctx, file[1], fmt, &plan, &io);
    }
    if (rc == CLI_OK && !quiet)
        cli_say_written(&file[1], &fmt, 1, &plan, &sew, 1);
    qc_plan_free(&ctx, &plan);
    return rc;
}
