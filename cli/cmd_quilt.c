/*
 * quiltc quilt TOP.svg: a pieced top (every closed shape a patch, kept where
 * drawn) quilted patch by patch, joined into one line along the seams.
 */
#include <getopt.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "quilt_plan.h"

#define MAX_PLAN_BYTES ((size_t)1 << 20)

typedef struct quilt_opts {
    cli_pattern_opts pat;
    const char *top, *plan_file, *format, *seam_gap;
    const char *out[CLI_MAX_OUTPUTS];
    size_t nout;
    int join, stats, quiet, tie;
    double feed;
} quilt_opts;

static void usage(FILE *f)
{
    fputs("usage: quiltc quilt TOP.svg [options]\n"
          "Quilts a pieced top: every closed shape of TOP.svg is a patch, kept where it is\n"
          "drawn; each patch gets its own pattern and one line sews them all, travelling\n"
          "from patch to patch along the seams (in the ditch).\n"
          "  -o, --output FILE        write FILE, format from its extension (repeatable;\n"
          "                           default quilt.pat and quilt.svg); - is stdout\n"
          "  --format NAME            pat, qli, dxf, hpgl, qcc, iqp, bqm, gcode, svg\n"
          "  --plan PLAN.json         a family and parameters per patch (see README)\n"
          "  --join ditch|jump        travel along seams (default), or jump between patches\n"
          "  --seam-gap LEN           edges drawn up to LEN apart are one seam (default\n"
          "                           0.1 mm; up to 10 mm)\n"
          "  --motif LIST             motifs: built-in names and .svg files, comma-separated\n"
          "  --tie N                  tie-off stitches at each start and end (default 3)\n"
          "  --feed MM_PER_MIN        G-code feed rate (default 1500)\n"
          "  --stats                  one JSON object of figures per patch and totals on stderr\n"
          "  -q, --quiet              no progress output\n"
          "Every option of 'quiltc generate' (--family, --spacing, ...) applies to every\n"
          "patch a plan rule does not set. Example:\n"
          "  quiltc quilt examples/sawtooth-star.svg --plan examples/sawtooth-star.json "
          "-o star.pat\n",
          f);
}

static int parse(int argc, char **argv, quilt_opts *q)
{
    static const struct option fixed[] = {
        {"output", required_argument, NULL, 'o'}, {"format", required_argument, NULL, 'f'},
        {"motif", required_argument, NULL, 'm'},  {"tie", required_argument, NULL, 't'},
        {"stats", no_argument, NULL, 's'},        {"plan", required_argument, NULL, 'p'},
        {"quiet", no_argument, NULL, 'q'},        {"help", no_argument, NULL, 'h'},
        {"feed", required_argument, NULL, 'F'},   {"join", required_argument, NULL, 'j'},
        {"seam-gap", required_argument, NULL, 'g'},
    };
    struct option *opts = cli_pattern_options(fixed, sizeof fixed / sizeof fixed[0]);
    int c, rc = CLI_OK, help = 0;
    unsigned long long tie;

    if (opts == NULL) {
        cli_error("out of memory");
        return CLI_RUNTIME;
    }
    optind = 1;
    opterr = 0;
    while (rc == CLI_OK && (c = getopt_long(argc, argv, ":o:qh", opts, NULL)) != -1) {
        switch (c) {
        case 'o':
            if (q->nout == CLI_MAX_OUTPUTS) {
                cli_error("at most %d outputs", CLI_MAX_OUTPUTS);
                rc = CLI_USAGE;
            } else
                q->out[q->nout++] = optarg;
            break;
        case 'f': q->format = optarg; break;
        case 'm': q->pat.motifs = optarg; break;
        case 's': q->stats = 1; break;
        case 'p': q->plan_file = optarg; break;
        case 'g': q->seam_gap = optarg; break;
        case 'q': q->quiet = 1; break;
        case 'h': help = 1; break;
        case 'j':
            if (strcmp(optarg, "ditch") == 0)
                q->join = QC_JOIN_DITCH;
            else if (strcmp(optarg, "jump") == 0)
                q->join = QC_JOIN_JUMP;
            else {
                cli_error("--join: '%s' is neither ditch nor jump", optarg);
                rc = CLI_USAGE;
            }
            break;
        case 't':
            if (cli_parse_u64(optarg, &tie) != 0 || tie > 100) {
                cli_error("--tie: '%s' is not a count from 0 to 100", optarg);
                rc = CLI_USAGE;
            }
            q->tie = (int)tie;
            break;
        case 'F':
            if (cli_parse_double(optarg, &q->feed) != 0 || !(q->feed > 0) || q->feed > 1e5) {
                cli_error("--feed: '%s' is not a feed rate in (0, 100000] mm/min", optarg);
                rc = CLI_USAGE;
            }
            break;
        default:
            if (c == CLI_PARAM_BASE - 1) {
                cli_error("quilt: the top is the SVG file named on the command line, not "
                          "--region");
                rc = CLI_USAGE;
            } else if (!cli_pattern_take(&q->pat, c, optarg)) {
                cli_bad_option("quilt", argv[optind - 1], c);
                rc = CLI_USAGE;
            }
        }
    }
    free(opts);
    if (rc == CLI_OK && help) {
        usage(stdout);
        return -1;
    }
    if (rc == CLI_OK && optind < argc)
        q->top = argv[optind++];
    if (rc == CLI_OK && optind < argc) {
        cli_error("quilt: unexpected argument '%s'", argv[optind]);
        rc = CLI_USAGE;
    }
    if (rc == CLI_OK && q->top == NULL) {
        cli_error("quilt: expected a TOP.svg file");
        rc = CLI_USAGE;
    }
    return rc;
}

static int output_formats(const quilt_opts *q, int *fmt)
{
    size_t i;

    for (i = 0; i < q->nout; i++) {
        const char *name = q->format != NULL ? q->format : q->out[i];

        fmt[i] = qc_format_from_name(name);
        if (strcmp(q->out[i], "-") == 0 && q->format == NULL) {
            cli_error("-o -: give --format for standard output");
            return CLI_USAGE;
        }
        if (fmt[i] < 0) {
            cli_error("%s '%s': unknown format (pat, qli, dxf, plt, qcc, iqp, bqm, gcode, svg)",
                      q->format != NULL ? "--format" : "output", name);
            return CLI_USAGE;
        }
    }
    return cli_outputs_distinct(q->out, q->nout);
}

/* --seam-gap in the user's units (known once the pattern options are). */
static int seam_params(const quilt_opts *q, qc_quilt_params *qp)
{
    double u = q->pat.mm_per_unit;

    memset(qp, 0, sizeof *qp);
    qp->join = q->join;
    if (q->seam_gap == NULL)
        return CLI_OK;
    if (cli_parse_length(q->seam_gap, u, &qp->seam_tol) != 0) {
        cli_error("--seam-gap: '%s' is not a length", q->seam_gap);
        return CLI_USAGE;
    }
    if (!(qp->seam_tol > 0) || qp->seam_tol > QC_QUILT_MAX_SEAM_TOL) {
        cli_length_range("--seam-gap", qp->seam_tol, 0, QC_QUILT_MAX_SEAM_TOL, u);
        return CLI_USAGE;
    }
    return CLI_OK;
}

static int load_plan(const quilt_opts *q, quilt_plan *plan)
{
    char *buf = NULL;
    size_t len;
    cJSON *root;
    int rc;

    if (cli_read_file(q->plan_file, MAX_PLAN_BYTES, &buf, &len) != 0)
        return CLI_RUNTIME;
    root = cJSON_ParseWithLength(buf, len);
    if (root == NULL) {
        const char *at = cJSON_GetErrorPtr();
        cli_error("plan: %s: malformed JSON at byte %ld", q->plan_file,
                  at != NULL ? (long)(at - buf) : -1L);
        free(buf);
        return CLI_USAGE;
    }
    free(buf);
    rc = cli_quilt_plan_parse(plan, root, &q->pat, "plan: rules");
    plan->doc = root; /* the rules point into it */
    return rc;
}

/* pieces: the sewn path's, counted before the plan took it */
static void print_stats(const qc_patches *ps, const qc_quilt_result *res, size_t pieces,
                        const plan_rule *const *chosen, const qc_plan *plan, const cli_timer *t)
{
    cJSON *o = cJSON_CreateObject(), *arr, *ms;
    qc_plan_estimate est;
    double total = 0;
    size_t i, quilted = 0;
    char *text;

    if (o == NULL)
        return;
    qc_plan_estimate_get(plan, 0, 0, &est);
    arr = cJSON_AddArrayToObject(o, "patches");
    for (i = 0; i < res->npatch && arr != NULL; i++) {
        const qc_patch_result *pr = &res->patch[i];
        cJSON *p = cJSON_CreateObject();

        if (p == NULL)
            break;
        cJSON_AddNumberToObject(p, "patch", (double)i + 1);
        cJSON_AddStringToObject(p, "id", ps->p[i].id);
        cJSON_AddNumberToObject(p, "line", (double)ps->p[i].line);
        cJSON_AddStringToObject(p, "rule", chosen[i] != NULL ? chosen[i]->where + 6 : "default");
        cJSON_AddStringToObject(p, "family",
                                pr->order == SIZE_MAX ? "none" : qc_family_name(pr->family));
        if (pr->order != SIZE_MAX) {
            cJSON_AddNumberToObject(p, "order", (double)pr->order + 1);
            cJSON_AddNumberToObject(p, "length_mm", pr->length_mm);
            cJSON_AddNumberToObject(p, "largest_gap_mm", pr->largest_gap_mm);
            cJSON_AddNumberToObject(p, "farthest_fabric_mm", pr->farthest_fabric_mm);
            cJSON_AddNumberToObject(p, "seam_bare", pr->seam_bare);
            cJSON_AddNumberToObject(p, "pieces", (double)pr->pieces);
            if (pr->ditch_only)
                cJSON_AddTrueToObject(p, "ditch_only");
            total += pr->length_mm;
            quilted++;
        }
        cJSON_AddItemToArray(arr, p);
    }
    cJSON_AddNumberToObject(o, "quilted", (double)quilted);
    cJSON_AddNumberToObject(o, "unquilted", (double)(res->npatch - quilted));
    cJSON_AddNumberToObject(o, "pattern_mm", total);
    cJSON_AddNumberToObject(o, "ditch_mm", res->ditch_mm);
    cJSON_AddNumberToObject(o, "link_mm", res->link_mm);
    cJSON_AddNumberToObject(o, "jumps", (double)est.jumps);
    cJSON_AddNumberToObject(o, "pieces", (double)pieces);
    cJSON_AddNumberToObject(o, "sewn_mm", est.sewn_mm);
    cJSON_AddNumberToObject(o, "stitch_points", (double)plan->n);
    cJSON_AddNumberToObject(o, "stitches", (double)est.stitches);
    cJSON_AddNumberToObject(o, "thread_mm", est.thread_mm);
    cJSON_AddNumberToObject(o, "sew_seconds", est.seconds);
    ms = cJSON_AddObjectToObject(o, "ms");
    for (i = 0; ms != NULL && i < t->n; i++)
        cJSON_AddNumberToObject(ms, t->name[i], t->ms[i]);
    if (ms != NULL)
        cJSON_AddNumberToObject(ms, "total", t->last - t->t0);
    text = cJSON_PrintUnformatted(o);
    if (text != NULL) {
        fprintf(stderr, "%s\n", text);
        free(text);
    }
    cJSON_Delete(o);
}

static int run(qc_ctx *ctx, quilt_opts *q, const int *fmt)
{
    quilt_plan plan;
    cli_quilt top;
    qc_region drawn = {0};
    qc_plan st = {0};
    qc_stitch_params sp;
    qc_quilt_params qp;
    qc_io_opts io;
    cli_timer timer;
    size_t pieces = 0;
    int rc = cli_pattern_finish(ctx, &q->pat);

    memset(&plan, 0, sizeof plan);
    memset(&top, 0, sizeof top);
    cli_timer_start(&timer, ctx);
    ctx->trace = NULL; /* the stages of every patch would repeat: time the whole */
    if (rc == CLI_OK)
        rc = seam_params(q, &qp);
    if (rc == CLI_OK && q->plan_file != NULL)
        rc = load_plan(q, &plan);
    cli_timer_mark(&timer, "quilt");
    if (rc == CLI_OK)
        rc = cli_quilt_sew(ctx, &top, q->top, &plan, &q->pat, &qp, "quilt");
    if (rc == CLI_OK)
        rc = cli_quilt_outlines(ctx, &top.ps, &drawn);
    if (rc == CLI_OK)
        qc_quilt_to_origin(&top.res, &drawn); /* PAT refuses negative coordinates */
    cli_timer_mark(&timer, "plan");
    memset(&sp, 0, sizeof sp);
    sp.tie_stitches = q->tie;
    pieces = qc_path_pieces(&top.res.path);
    /* nothing else reads the path: it goes as it is flattened */
    if (rc == CLI_OK && qc_stitch_plan_taking(ctx, &top.res.path, NULL, &sp, &st) < 0)
        rc = cli_fail(ctx, "stitch plan", ctx->status);
    cli_timer_mark(&timer, "write");
    memset(&io, 0, sizeof io);
    io.region = &drawn;
    io.svg_inches = q->pat.mm_per_unit == 25.4;
    io.feed_mm_min = q->feed;
    io.travel = &top.res.ditch;
    io.dxf_outlines = 1;
    if (rc == CLI_OK)
        rc = cli_write_plans(ctx, q->out, fmt, q->nout, &st, &io);
    cli_timer_mark(&timer, NULL);
    if (rc == CLI_OK && q->stats)
        print_stats(&top.ps, &top.res, pieces, top.chosen, &st, &timer);
    qc_plan_free(ctx, &st);
    qc_region_free(ctx, &drawn);
    cli_quilt_free(ctx, &top);
    cli_quilt_plan_free(ctx, &plan);
    return rc;
}

int cmd_quilt(int argc, char **argv)
{
    quilt_opts q;
    qc_ctx ctx;
    int fmt[CLI_MAX_OUTPUTS];
    int rc;

    memset(&q, 0, sizeof q);
    cli_pattern_init(&q.pat);
    q.tie = 3;
    qc_ctx_init(&ctx, NULL, NULL);
    rc = parse(argc, argv, &q);
    if (rc != CLI_OK)
        return rc < 0 ? CLI_OK : rc;
    if (q.nout == 0) {
        q.out[q.nout++] = "quilt.pat";
        q.out[q.nout++] = "quilt.svg";
    }
    rc = output_formats(&q, fmt);
    if (rc == CLI_OK)
        rc = run(&ctx, &q, fmt);
    return rc;
}
