/*
 * quiltc skeleton: the points and the tree or tour the patterns are built on
 * (paper §4), as JSON or as an SVG picture like the paper's Fig. 4.
 */
#include <cjson/cJSON.h>
#include <getopt.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "concorde.h"

typedef struct skel_opts {
    cli_pattern_opts pat;
    const char *out[CLI_MAX_OUTPUTS];
    size_t nout;
    const char *format, *path, *tsp;
} skel_opts;

static void usage(FILE *f)
{
    fputs("usage: quiltc skeleton [options]\n"
          "Writes the sampled points with their spanning tree walk or TSP tour.\n"
          "  -o, --output FILE        .json (default, - for stdout) or .svg (repeatable)\n"
          "  --path mst|tsp           tree walk (default) or closed tour\n"
          "  --tsp greedy|2opt|oropt|or3opt|concorde   tour method (default or3opt;\n"
          "                           concorde: program on PATH)\n",
          f);
    cli_pattern_help(f, 1u << QC_FAMILY_VINE);
}

static int row_of(const char *name)
{
    size_t n;
    return (int)(qc_param_find(name) - qc_param_table(&n));
}

static int parse(int argc, char **argv, skel_opts *s)
{
    static const struct option fixed[] = {
        {"output", required_argument, NULL, 'o'},
        {"path", required_argument, NULL, 'p'},
        {"help", no_argument, NULL, 'h'},
    };
    struct option *opts = cli_pattern_options(fixed, sizeof fixed / sizeof fixed[0]);
    int c, rc = CLI_OK;

    if (opts == NULL)
        return CLI_RUNTIME;
    optind = 1;
    opterr = 0; /* our own one-line messages */
    while (rc == CLI_OK && (c = cli_getopt(argc, argv, ":o:h", opts)) != -1) {
        if (c == CLI_GETOPT_REPORTED)
            rc = CLI_USAGE;
        else if (c == 'o' && s->nout == CLI_MAX_OUTPUTS) {
            cli_error("skeleton: at most %d outputs", CLI_MAX_OUTPUTS);
            rc = CLI_USAGE;
        } else if (c == 'o')
            s->out[s->nout++] = optarg;
        else if (c == 'p')
            s->path = optarg;
        else if (c == 'h') {
            usage(stdout);
            rc = -1;
        } else if (c == CLI_PARAM_BASE + row_of("tsp") && strcmp(optarg, "concorde") == 0)
            s->tsp = optarg;
        else if (!cli_pattern_take(&s->pat, c, optarg)) {
            cli_bad_option("skeleton", argv[optind - 1], c);
            rc = CLI_USAGE;
        }
    }
    free(opts);
    s->pat.fit_points = 1; /* --points without --region: the points' own box */
    if (rc == CLI_OK && s->path != NULL && strcmp(s->path, "mst") != 0 &&
        strcmp(s->path, "tsp") != 0) {
        cli_error("--path: unknown '%s' (mst or tsp)", s->path);
        rc = CLI_USAGE;
    }
    if (rc == CLI_OK && optind < argc) {
        cli_error("skeleton: unexpected argument '%s'", argv[optind]);
        rc = CLI_USAGE;
    }
    return rc;
}

static double order_length(const qc_result *r, int closed)
{
    return qc_tour_length(r->points.v, r->order.i, r->order.n, closed);
}

static char *to_json(const qc_result *r, int tour)
{
    cJSON *o = cJSON_CreateObject(), *pts, *edges, *order;
    size_t i;
    char *text;

    if (o == NULL)
        return NULL;
    cJSON_AddStringToObject(o, "units", "mm");
    pts = cJSON_AddArrayToObject(o, "points");
    for (i = 0; pts != NULL && i < r->points.n; i++) {
        double xy[2];
        xy[0] = r->points.v[i].x;
        xy[1] = r->points.v[i].y;
        cJSON_AddItemToArray(pts, cJSON_CreateDoubleArray(xy, 2));
    }
    edges = cJSON_AddArrayToObject(o, "edges");
    for (i = 0; edges != NULL && i < r->edges.n; i++) {
        int ab[2];
        ab[0] = (int)r->edges.e[i].a;
        ab[1] = (int)r->edges.e[i].b;
        cJSON_AddItemToArray(edges, cJSON_CreateIntArray(ab, 2));
    }
    order = cJSON_AddArrayToObject(o, "order");
    for (i = 0; order != NULL && i < r->order.n; i++)
        cJSON_AddItemToArray(order, cJSON_CreateNumber(r->order.i[i]));
    cJSON_AddNumberToObject(o, "length_mm", order_length(r, tour));
    text = cJSON_PrintUnformatted(o);
    cJSON_Delete(o);
    return text;
}

/* An SVG like the paper's Fig. 4: the region, the tree or tour, the points. */
static int write_svg(FILE *f, const qc_region *region, const qc_result *r, int tour)
{
    qc_bbox b = qc_region_bbox(region);
    double w = b.max.x, h = b.max.y;
    size_t i, k, start = 0;

    fprintf(f, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
               "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.3fmm\" height=\"%.3fmm\" "
               "viewBox=\"0 0 %.3f %.3f\">\n<g transform=\"matrix(1 0 0 -1 0 %.3f)\">\n",
            w, h, w, h, h);
    fputs("<path fill=\"#f4efe6\" stroke=\"#999\" stroke-width=\"0.3\" fill-rule=\"evenodd\" d=\"", f);
    for (k = 0; k < region->nrings; k++) {
        for (i = start; i < region->ring_end[k]; i++)
            fprintf(f, "%c%.3f %.3f", i == start ? 'M' : 'L', region->v[i].x, region->v[i].y);
        fputc('Z', f);
        start = region->ring_end[k];
    }
    fputs("\"/>\n<path fill=\"none\" stroke=\"#c0392b\" stroke-width=\"0.4\" d=\"", f);
    for (i = 0; i < r->order.n; i++) {
        qc_vec2 p = r->points.v[r->order.i[i]];
        fprintf(f, "%c%.3f %.3f", i == 0 ? 'M' : 'L', p.x, p.y);
    }
    fputs(tour ? "Z\"/>\n" : "\"/>\n", f);
    for (i = 0; i < r->points.n; i++)
        fprintf(f, "<circle cx=\"%.3f\" cy=\"%.3f\" r=\"0.8\" fill=\"#2c3e50\"/>\n",
                r->points.v[i].x, r->points.v[i].y);
    fputs("</g>\n</svg>\n", f);
    return ferror(f) ? -1 : 0;
}

typedef struct skel_job {
    const skel_opts *s;
    const char *const *outs;
    const qc_region *region;
    const qc_result *r;
} skel_job;

/* One output: SVG by its extension, else JSON. */
static int write_one(void *ud, size_t i, cli_output *o)
{
    const skel_job *j = ud;
    size_t n = strlen(j->outs[i]);
    int tour = j->s->path != NULL && strcmp(j->s->path, "tsp") == 0;

    if (n > 4 && strcmp(j->outs[i] + n - 4, ".svg") == 0) {
        if (write_svg(o->f, j->region, j->r, tour) != 0)
            o->failed = 1;
    } else {
        char *json = to_json(j->r, tour);
        if (json == NULL || fprintf(o->f, "%s\n", json) < 0)
            o->failed = 1;
        free(json);
    }
    return CLI_OK; /* a failed write is reported when the output is closed */
}

/* Every output written whole, or none; stdout when there is none. */
static int write_result(const skel_opts *s, const qc_region *region, const qc_result *r)
{
    static const char *const to_stdout[] = {"-"};
    skel_job j;

    j.s = s;
    j.outs = s->nout ? s->out : to_stdout;
    j.region = region;
    j.r = r;
    return cli_write_outputs(j.outs, s->nout ? s->nout : 1, write_one, &j);
}

int cmd_skeleton(int argc, char **argv)
{
    skel_opts s;
    qc_ctx ctx;
    qc_region region = {0};
    qc_points given = {0};
    qc_result res = {0};
    int rc;

    memset(&s, 0, sizeof s);
    cli_pattern_init(&s.pat);
    qc_ctx_init(&ctx, NULL, NULL);
    rc = parse(argc, argv, &s);
    if (rc != CLI_OK)
        return rc < 0 ? CLI_OK : rc;
    /* the vine family is the bare skeleton, smoothed: its result carries it */
    s.pat.raw[row_of("family")] = NULL;
    rc = cli_pattern_finish(&ctx, &s.pat);
    if (rc == CLI_OK) {
        qc_params_set(&ctx, &s.pat.params, "family", QC_FAMILY_VINE);
        if (s.path != NULL)
            qc_params_set(&ctx, &s.pat.params, "skeleton",
                          strcmp(s.path, "tsp") == 0 ? QC_SKELETON_TSP : QC_SKELETON_MST);
        rc = cli_pattern_load(&ctx, &s.pat, &region, &given);
    }
    if (rc == CLI_OK && s.tsp != NULL) {
        rc = cli_concorde_skeleton(&ctx, &s.pat.params, &region, &given, &res);
    } else if (rc == CLI_OK && qc_generate(&ctx, &region, &s.pat.params, &given, NULL, &res) < 0)
        rc = cli_fail(&ctx, "skeleton", ctx.status);
    if (rc == CLI_OK)
        rc = write_result(&s, &region, &res);
    qc_result_free(&ctx, &res);
    qc_points_free(&ctx, &given);
    qc_region_free(&ctx, &region);
    return rc;
}
