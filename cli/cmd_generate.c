/* quiltc generate: region + parameters -> one continuous stitch path -> machine files. */
#include <getopt.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "concorde.h"
#include "machine_opts.h"
#include "stats_json.h"

typedef struct gen_opts {
    cli_pattern_opts pat;
    cli_machine_opts mach;
    const char *out[CLI_MAX_OUTPUTS];
    size_t nout;
    const char *format;
    const char *upload;
    const char *quilt_width;
    int stats, quiet, tie, tie_given, concorde;
    double feed;
} gen_opts;

/* --help after --family F lists only F's parameters. */
static void usage(FILE *f, const char *family)
{
    int fam = family != NULL ? qc_family_from_name(family) : -1;

    fputs("usage: quiltc generate [options]\n"
          "Generates one continuous free-motion pattern inside a block outline.\n"
          "  -o, --output FILE        write FILE, format from its extension (repeatable;\n"
          "                           default pattern.pat and pattern.svg); - is stdout\n"
          "  --format NAME            pat, qli, dxf, hpgl, qcc, iqp, bqm, gcode, svg\n"
          "  --motif LIST             motifs: built-in names and .svg files, comma-separated\n"
          "  --tie N                  tie-off stitches at each start and end (default 0;\n"
          "                           pantograph rows: give 3 to tie off every row)\n"
          "  --quilt-width LEN        pantographs: as many columns as fit across LEN\n"
          "  --feed MM_PER_MIN        G-code feed rate (default 1500)\n"
          "  --stats                  one JSON object of figures on stderr\n"
          "  --upload DEVICE          send the first output to a machine (VID:PID or BUS-PORT)\n"
          "  --tsp concorde           tour skeletons: the tour of a concorde program on PATH\n"
          "  -q, --quiet              no progress output\n",
          f);
    if (fam <= 0) {
        const qc_family_desc *d;
        size_t i;

        fputs("Families (--family NAME; --family NAME --help lists its parameters):\n", f);
        for (i = 0; (d = qc_family_info(i)) != NULL; i++)
            fprintf(f, "  %-24s %s\n", d->name, d->summary);
    }
    cli_pattern_help(f, fam > 0 ? 1u << fam : 0xFFFFFFFFu);
    cli_machine_help(f);
    fputs("Lengths are in --units unless suffixed (12mm, 0.5in). Example:\n"
          "  quiltc generate --region heart:10 --family branching --spacing 0.6 -o heart.pat\n",
          f);
}

static int parse(int argc, char **argv, gen_opts *g)
{
    static const struct option fixed[] = {
        {"output", required_argument, NULL, 'o'}, {"format", required_argument, NULL, 'f'},
        {"motif", required_argument, NULL, 'm'},  {"tie", required_argument, NULL, 't'},
        {"stats", no_argument, NULL, 's'},        {"upload", required_argument, NULL, 'u'},
        {"quiet", no_argument, NULL, 'q'},        {"help", no_argument, NULL, 'h'},
        {"feed", required_argument, NULL, 'F'},   {"quilt-width", required_argument, NULL, 'W'},
        CLI_MACHINE_OPTIONS,
    };
    struct option *opts = cli_pattern_options(fixed, sizeof fixed / sizeof fixed[0]);
    int c, rc = CLI_OK, help = 0;
    unsigned long long tie;
    size_t n_rows;

    if (opts == NULL) {
        cli_error("out of memory");
        return CLI_RUNTIME;
    }
    optind = 1;
    opterr = 0; /* our own one-line messages */
    while (rc == CLI_OK && (c = cli_getopt(argc, argv, ":o:qh", opts)) != -1) {
        switch (c) {
        case 'o':
            if (g->nout == CLI_MAX_OUTPUTS) {
                cli_error("at most %d outputs", CLI_MAX_OUTPUTS);
                rc = CLI_USAGE;
            } else
                g->out[g->nout++] = optarg;
            break;
        case 'f': g->format = optarg; break;
        case 'm': g->pat.motifs = optarg; break;
        case 's': g->stats = 1; break;
        case 'u': g->upload = optarg; break;
        case 'W': g->quilt_width = optarg; break;
        case 'q': g->quiet = 1; break;
        case 't':
            if (cli_parse_u64(optarg, &tie) != 0 || tie > 100) {
                cli_error("--tie: '%s' is not a count from 0 to 100", optarg);
                rc = CLI_USAGE;
            }
            g->tie = (int)tie;
            g->tie_given = 1;
            break;
        case 'F':
            if (cli_parse_double(optarg, &g->feed) != 0 || !(g->feed > 0) || g->feed > 1e5) {
                cli_error("--feed: '%s' is not a feed rate in (0, 100000] mm/min", optarg);
                rc = CLI_USAGE;
            }
            break;
        case 'h': help = 1; break;
        case CLI_GETOPT_REPORTED: rc = CLI_USAGE; break;
        default:
            if (c == CLI_PARAM_BASE + (int)(qc_param_find("tsp") - qc_param_table(&n_rows)) &&
                strcmp(optarg, "concorde") == 0)
                g->concorde = 1; /* the program, not a built-in method */
            else if (!cli_pattern_take(&g->pat, c, optarg) && !cli_machine_take(&g->mach, c, optarg)) {
                cli_bad_option("generate", argv[optind - 1], c);
                rc = CLI_USAGE;
            }
        }
    }
    free(opts);
    if (rc == CLI_OK && help) {
        size_t n;
        usage(stdout, g->pat.raw[qc_param_find("family") - qc_param_table(&n)]);
        return -1;
    }
    if (rc == CLI_OK && optind < argc) {
        cli_error("generate: unexpected argument '%s'", argv[optind]);
        rc = CLI_USAGE;
    }
    return rc;
}

/* The format of each output: --format, else the file's extension. */
static int output_formats(const gen_opts *g, int *fmt)
{
    size_t i;

    for (i = 0; i < g->nout; i++) {
        const char *name = g->format != NULL ? g->format : g->out[i];
        fmt[i] = qc_format_from_name(name);
        if (strcmp(g->out[i], "-") == 0 && g->format == NULL) {
            cli_error("-o -: give --format for standard output");
            return CLI_USAGE;
        }
        if (fmt[i] < 0) {
            cli_error("%s '%s': unknown format (pat, qli, dxf, plt, qcc, iqp, bqm, gcode, svg)",
                      g->format != NULL ? "--format" : "output", name);
            return CLI_USAGE;
        }
    }
    if (g->upload != NULL && strcmp(g->out[0], "-") == 0) {
        cli_error("--upload sends the first output, a file: not -o -");
        return CLI_USAGE;
    }
    return cli_outputs_distinct(g->out, g->nout);
}

/* Same composition as the web page (wasm/quiltc_wasm.c): generate, then plan. */
static int make_plan(qc_ctx *ctx, const gen_opts *g, const qc_region *region,
                     const qc_points *given, const qc_motif_set *motifs, qc_result *res,
                     qc_plan *plan, cli_timer *timer)
{
    qc_stitch_params sp;

    if (g->concorde) {
        int rc = cli_concorde_generate(ctx, &g->pat.params, region, given, motifs, res);
        if (rc != CLI_OK)
            return rc;
    } else if (qc_generate(ctx, region, &g->pat.params, given, motifs, res) < 0)
        return cli_fail(ctx, "generate", ctx->status);
    cli_timer_mark(timer, "plan");
    /* from here on only res's figures are read: each copy of the pattern
     * goes as soon as the next is made (the peak at 10^6 points) */
    qc_points_free(ctx, &res->points);
    qc_edges_free(ctx, &res->edges);
    qc_order_free(ctx, &res->order);
    cli_machine_stitch_params(&g->mach, &sp);
    sp.tie_stitches = g->tie;
    if (qc_stitch_plan_taking(ctx, &res->path, region, &sp, plan) < 0)
        return cli_fail(ctx, "stitch plan", ctx->status);
    return CLI_OK;
}

static int write_outputs(qc_ctx *ctx, const gen_opts *g, const int *fmt, const qc_region *region,
                         const qc_plan *plan)
{
    qc_io_opts io;

    memset(&io, 0, sizeof io);
    io.region = region;
    io.svg_inches = g->pat.mm_per_unit == 25.4;
    io.feed_mm_min = g->feed;
    io.pen_up = g->mach.raw[CLI_MACH_PEN_UP - CLI_MACH_BASE];
    io.pen_down = g->mach.raw[CLI_MACH_PEN_DOWN - CLI_MACH_BASE];
    return cli_write_plans(ctx, g->out, fmt, g->nout, plan, &io);
}

/* --mirror, --rotate, --at: the finished plan and its outline move together.
 * A .pat cannot hold a negative position: say which option put it there. */
static int place(qc_ctx *ctx, const gen_opts *g, const int *fmt, qc_region *region,
                 qc_plan *plan)
{
    qc_xform m;
    qc_plan_estimate est;
    double mpu = g->pat.mm_per_unit;
    size_t i;

    if (qc_place_xform(ctx, region, &g->mach.place, &m) < 0)
        return cli_fail(ctx, "place", ctx->status);
    qc_plan_transform(plan, &m);
    qc_region_transform(region, &m);
    qc_plan_estimate_get(plan, 0, 0, &est);
    for (i = 0; i < g->nout; i++)
        if (fmt[i] == QC_FORMAT_PAT && (est.bbox.min.x < -0.0005 * 25.4 ||
                                        est.bbox.min.y < -0.0005 * 25.4)) {
            cli_error("--at %g,%g %s puts the pattern's lower-left at (%g, %g) %s: a .pat "
                      "needs x and y >= 0", g->mach.place.at.x / mpu, g->mach.place.at.y / mpu,
                      cli_units_name(mpu), est.bbox.min.x / mpu, est.bbox.min.y / mpu,
                      cli_units_name(mpu));
            return CLI_USAGE;
        }
    return CLI_OK;
}

int cmd_generate(int argc, char **argv)
{
    gen_opts g;
    qc_ctx ctx;
    qc_region region = {0};
    qc_points given = {0};
    qc_motif_set motifs = {0};
    qc_result res = {0};
    qc_plan plan = {0};
    cli_timer timer;
    cli_sewing sew;
    int fmt[CLI_MAX_OUTPUTS];
    int rc;

    memset(&g, 0, sizeof g);
    cli_pattern_init(&g.pat);
    qc_ctx_init(&ctx, NULL, NULL);
    rc = parse(argc, argv, &g);
    if (rc != CLI_OK)
        return rc < 0 ? CLI_OK : rc;
    if (g.nout == 0) {
        g.out[g.nout++] = "pattern.pat";
        g.out[g.nout++] = "pattern.svg";
    }
    rc = cli_pattern_finish(&ctx, &g.pat);
    /* the largest gap and the farthest fabric are figures for --stats only
     * (the path is the same without them): measured when asked */
    if (rc == CLI_OK && !g.stats)
        g.pat.params.skip_gap_stat = 1;
    if (rc == CLI_OK)
        cli_pattern_warn_ignored(&g.pat);
    if (rc == CLI_OK)
        rc = cli_machine_finish(&g.mach, g.pat.mm_per_unit);
    if (rc == CLI_OK)
        rc = output_formats(&g, fmt);
    cli_timer_start(&timer, &ctx);
    if (rc == CLI_OK)
        rc = cli_pattern_load(&ctx, &g.pat, &region, &given);
    if (rc == CLI_OK && g.quilt_width != NULL)
        rc = cli_fit_columns(&ctx, &g.pat, g.quilt_width, &region);
    if (rc == CLI_OK && g.pat.motifs != NULL)
        rc = cli_load_motifs(&ctx, g.pat.motifs, &motifs);
    if (rc == CLI_OK)
        rc = make_plan(&ctx, &g, &region, &given, motifs.n ? &motifs : NULL, &res, &plan,
                       &timer);
    if (rc == CLI_OK && !g.tie_given && res.stats.pieces > 1) {
        int rows = res.params.tile == QC_TILE_EDGE_TO_EDGE || res.params.tile == QC_TILE_ALL_OVER;
        cli_error("warning: the pattern's %lu %s are joined by jumps without tie-offs; --tie 3 "
                  "ties off each", (unsigned long)res.stats.pieces, rows ? "rows" : "pieces");
    }
    cli_timer_mark(&timer, "write");
    if (rc == CLI_OK && g.mach.placed)
        rc = place(&ctx, &g, fmt, &region, &plan);
    if (rc == CLI_OK)
        rc = cli_check_inside(plan.p, plan.n, &res.params, &region,
                              g.pat.region != NULL ? g.pat.region : "rect:8x8", "generate");
    if (rc == CLI_OK)
        rc = write_outputs(&ctx, &g, fmt, &region, &plan);
    cli_timer_mark(&timer, NULL);
    sew.spi = g.mach.spi;
    sew.speed_mm_s = g.mach.speed_mm_s;
    sew.bobbin_mm = g.mach.bobbin_mm;
    if (rc == CLI_OK && !g.quiet)
        cli_say_written(g.out, fmt, g.nout, &plan, &sew, g.pat.mm_per_unit == 25.4);
    if (rc == CLI_OK && g.stats)
        cli_stats_print(stderr, &res, &plan, &timer, &sew);
    if (rc == CLI_OK && g.upload != NULL)
        rc = cli_usb_send_file(g.out[0], g.upload, g.quiet);
    qc_plan_free(&ctx, &plan);
    qc_result_free(&ctx, &res);
    qc_motif_set_free(&ctx, &motifs);
    qc_points_free(&ctx, &given);
    qc_region_free(&ctx, &region);
    return rc;
}
