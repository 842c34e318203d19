/*
 * The options generate and skeleton share: --region, --units and one
 * --NAME VALUE per row of the library's parameter table, so a parameter
 * added to the table is a CLI option without touching this file.
 */
#include <getopt.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cli.h"

#define MAX_ROWS (sizeof ((cli_pattern_opts *)0)->raw / sizeof(char *))

struct option *cli_pattern_options(const struct option *fixed, size_t nfixed)
{
    size_t nrows, i;
    const qc_param_info *t = qc_param_table(&nrows);
    struct option *o = calloc(nfixed + nrows + 4, sizeof *o);

    if (o == NULL || nrows > MAX_ROWS) {
        free(o);
        return NULL;
    }
    memcpy(o, fixed, nfixed * sizeof *o);
    o[nfixed].name = "region";
    o[nfixed].has_arg = required_argument;
    o[nfixed].val = CLI_PARAM_BASE - 1;
    o[nfixed + 1].name = "units";
    o[nfixed + 1].has_arg = required_argument;
    o[nfixed + 1].val = CLI_PARAM_BASE - 2;
    o[nfixed + 2].name = "repeat";
    o[nfixed + 2].has_arg = required_argument;
    o[nfixed + 2].val = CLI_PARAM_BASE - 3;
    for (i = 0; i < nrows; i++) {
        o[nfixed + 3 + i].name = t[i].name;
        o[nfixed + 3 + i].has_arg = required_argument;
        o[nfixed + 3 + i].val = CLI_PARAM_BASE + (int)i;
    }
    return o;
}

void cli_pattern_init(cli_pattern_opts *o)
{
    memset(o, 0, sizeof *o);
    o->region = "rect:8x8";
    o->units = "in";
    o->mm_per_unit = 25.4;
}

/* --repeat CxR: the two counts go to repeat-cols and repeat-rows (checked there). */
static int take_repeat(cli_pattern_opts *o, const char *arg)
{
    const char *x = strchr(arg, 'x');
    size_t n, cols = (size_t)(qc_param_find("repeat-cols") - qc_param_table(&n));
    size_t rows = (size_t)(qc_param_find("repeat-rows") - qc_param_table(&n));

    if (x == NULL || x == arg || (size_t)(x - arg) >= sizeof o->repeat[0] ||
        strlen(x + 1) >= sizeof o->repeat[1] || x[1] == '\0')
        return 0;
    memcpy(o->repeat[0], arg, (size_t)(x - arg));
    o->repeat[0][x - arg] = '\0';
    strcpy(o->repeat[1], x + 1);
    o->raw[cols] = o->repeat[0];
    o->raw[rows] = o->repeat[1];
    return 1;
}

int cli_pattern_take(cli_pattern_opts *o, int opt, const char *arg)
{
    size_t nrows;

    qc_param_table(&nrows);
    if (opt == CLI_PARAM_BASE - 3) {
        if (!take_repeat(o, arg)) {
            cli_error("--repeat: '%s' is not COLSxROWS (e.g. 3x2)", arg);
            o->bad = 1;
        }
    } else if (opt == CLI_PARAM_BASE - 1)
        o->region = arg;
    else if (opt == CLI_PARAM_BASE - 2)
        o->units = arg;
    else if (opt >= CLI_PARAM_BASE && (size_t)(opt - CLI_PARAM_BASE) < nrows)
        o->raw[opt - CLI_PARAM_BASE] = arg;
    else
        return 0;
    return 1;
}

void cli_length_range(const char *name, double mm, double lo, double hi, double mm_per_unit)
{
    const char *u = cli_units_name(mm_per_unit);
    char also[48] = "";

    if (mm_per_unit != 1.0)
        snprintf(also, sizeof also, " (%.4g mm)", mm);
    cli_error("%s %.4g %s%s out of range [%.4g, %.4g] %s", name, mm / mm_per_unit, u, also,
              lo / mm_per_unit, hi / mm_per_unit, u);
}

int cli_parse_length(const char *s, double mm_per_unit, double *mm)
{
    static const struct { const char *suffix; double mm; } units[] = {
        {"mm", 1.0}, {"cm", 10.0}, {"in", 25.4}};
    size_t len = strlen(s), i;
    char buf[64];

    for (i = 0; i < 3; i++) {
        size_t sl = strlen(units[i].suffix);
        if (len > sl && len - sl < sizeof buf && strcmp(s + len - sl, units[i].suffix) == 0) {
            memcpy(buf, s, len - sl);
            buf[len - sl] = '\0';
            if (cli_parse_double(buf, mm) != 0)
                return -1;
            *mm *= units[i].mm;
            return isfinite(*mm) ? 0 : -2;
        }
    }
    if (cli_parse_double(s, mm) != 0)
        return -1;
    *mm *= mm_per_unit;
    return isfinite(*mm) ? 0 : -2;
}

static int is_file(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISREG(st.st_mode);
}

/* How messages name parameter `name`: "--spacing" on the command line,
 * "job: blocks[2].params.spacing" (or ".family") in a job file. */
static const char *label(const cli_pattern_opts *o, const char *name, char *buf, size_t size)
{
    if (o->where == NULL)
        snprintf(buf, size, "--%s", name);
    else
        snprintf(buf, size, "%s.%s%s", o->where, strcmp(name, "family") == 0 ? "" : "params.",
                 name);
    return buf;
}

static int take_row(qc_ctx *ctx, cli_pattern_opts *o, const qc_param_info *row, const char *s)
{
    double v;
    unsigned long long seed;
    char name[96];
    int rc;

    label(o, row->name, name, sizeof name);

    switch (row->type) {
    case QC_PARAM_ENUM: {
        int c = qc_param_choice(row, s);
        if (c < 0 && strcmp(row->name, "points") == 0 && is_file(s)) {
            o->points_file = s;
            c = QC_POINTS_GIVEN;
        }
        if (c < 0 && strcmp(row->name, "points") == 0 && (strchr(s, '.') || strchr(s, '/'))) {
            char *buf;
            size_t len;
            if (cli_read_file(s, 1, &buf, &len) == 0) { /* else it said why: missing, ... */
                free(buf);
                cli_error("%s: cannot read '%s'", name, s);
            }
            return CLI_RUNTIME;
        }
        if (c < 0) {
            cli_error("%s: unknown choice '%s' (one of %s%s)", name, s, row->choices,
                      strcmp(row->name, "points") == 0 ? ", or a CSV/TSPLIB file" : "");
            return CLI_USAGE;
        }
        v = c;
        break;
    }
    case QC_PARAM_SEED:
        if (cli_parse_u64(s, &seed) != 0) {
            cli_error("%s: '%s' is not a whole number from 0 to 2^64-1", name, s);
            return CLI_USAGE;
        }
        qc_params_set_seed(&o->params, (uint64_t)seed);
        return CLI_OK;
    case QC_PARAM_LENGTH:
        rc = cli_parse_length(s, o->mm_per_unit, &v);
        if (rc == -2) {
            cli_error("%s: '%s' is too large a length", name, s);
            return CLI_USAGE;
        }
        if (rc != 0) {
            cli_error("%s: '%s' is not a length (a number, optionally with mm, cm or in)",
                      name, s);
            return CLI_USAGE;
        }
        if (!(v >= row->min && v <= row->max)) { /* in the user's units, not the library's mm */
            cli_length_range(name, v, row->min, row->max, o->mm_per_unit);
            return CLI_USAGE;
        }
        break;
    default:
        if (cli_parse_double(s, &v) != 0) {
            cli_error("%s: '%s' is not a number", name, s);
            return CLI_USAGE;
        }
    }
    if (qc_params_set(ctx, &o->params, row->name, v) < 0)
        return cli_fail(ctx, o->where != NULL ? o->where : "parameters", ctx->status);
    return CLI_OK;
}

int cli_pattern_finish(qc_ctx *ctx, cli_pattern_opts *o)
{
    size_t nrows, i;
    const qc_param_info *t = qc_param_table(&nrows);
    qc_params resolved;

    if (o->bad)
        return CLI_USAGE;
    o->mm_per_unit = cli_units_mm(o->units);
    if (o->mm_per_unit == 0.0) {
        cli_error("--units: unknown unit '%s' (in, inch, mm or cm)", o->units);
        return CLI_USAGE;
    }
    for (i = 0; i < nrows; i++)
        if (o->raw[i] != NULL) {
            int rc = take_row(ctx, o, &t[i], o->raw[i]);
            if (rc != CLI_OK)
                return rc;
        }
    /* check ranges now, so a bad value is a usage error before any work */
    if (qc_params_resolve(ctx, &o->params, &resolved) < 0)
        return cli_fail(ctx, o->where != NULL ? o->where : "parameters", ctx->status);
    return CLI_OK;
}

void cli_pattern_help(FILE *f, unsigned families)
{
    size_t nrows, i;
    const qc_param_info *t = qc_param_table(&nrows);

    fputs("  --region SHAPE|FILE.svg  rect:WxH, square:S, circle:D, hexagon:D, star:D, heart:D\n"
          "                           (sizes in --units) or an SVG outline; default rect:8x8\n"
          "  --units in|mm|cm         units of shape sizes and bare lengths; default in\n"
          "  --repeat CxR             tiles across and down (--repeat-cols, --repeat-rows)\n",
          f);
    for (i = 0; i < nrows; i++) {
        char name[64];
        if ((qc_param_families(&t[i]) & families) == 0)
            continue;
        snprintf(name, sizeof name, "--%s %s", t[i].name,
                 t[i].type == QC_PARAM_ENUM ? "CHOICE" : t[i].type == QC_PARAM_LENGTH ? "LEN" : "N");
        fprintf(f, "  %-24s %s", name, t[i].help);
        if (t[i].choices != NULL)
            fprintf(f, " (%s)", t[i].choices);
        else if (strstr(t[i].help, "default") != NULL || t[i].type == QC_PARAM_SEED)
            ; /* the help says it */
        else if (t[i].def_per_spacing > 0)
            fprintf(f, " (default %g d)", t[i].def_per_spacing);
        else if (strcmp(t[i].unit, "count") == 0 || strcmp(t[i].unit, "ratio") == 0)
            fprintf(f, " (default %g)", t[i].def);
        else
            fprintf(f, " (default %g%s%s)", t[i].def, t[i].unit[0] ? " " : "", t[i].unit);
        fputc('\n', f);
    }
}

/* The --points file, scaled like every bare number: in --units. */
static int load_points(qc_ctx *ctx, const cli_pattern_opts *o, qc_points *given)
{
    char *buf;
    size_t len, i;
    int st;

    if (cli_read_file(o->points_file, (size_t)256 << 20, &buf, &len) != 0)
        return CLI_RUNTIME;
    st = qc_io_read_points(ctx, buf, len, given);
    free(buf);
    if (st < 0) {
        cli_error("%s: %s", o->points_file, qc_errmsg(ctx));
        return CLI_RUNTIME;
    }
    for (i = 0; i < given->n; i++) {
        given->v[i].x *= o->mm_per_unit;
        given->v[i].y *= o->mm_per_unit;
    }
    return CLI_OK;
}

/* The points' bounding box grown by the margin (and a hair, so the points
 * on its edge are inside by the margin), as a rectangle region. */
static int fit_region(qc_ctx *ctx, const cli_pattern_opts *o, const qc_points *given,
                      qc_region *region)
{
    qc_params r;
    qc_vec2 lo = given->v[0], hi = given->v[0], ring[4];
    double m;
    size_t i;

    if (qc_params_resolve(ctx, &o->params, &r) < 0)
        return cli_fail(ctx, "parameters", ctx->status);
    for (i = 1; i < given->n; i++) {
        lo.x = fmin(lo.x, given->v[i].x);
        lo.y = fmin(lo.y, given->v[i].y);
        hi.x = fmax(hi.x, given->v[i].x);
        hi.y = fmax(hi.y, given->v[i].y);
    }
    m = r.margin * 1.001 + 0.01 + 1e-9 * fmax(fabs(hi.x) + fabs(hi.y), 1.0);
    ring[0].x = lo.x - m, ring[0].y = lo.y - m;
    ring[1].x = hi.x + m, ring[1].y = lo.y - m;
    ring[2].x = hi.x + m, ring[2].y = hi.y + m;
    ring[3].x = lo.x - m, ring[3].y = hi.y + m;
    memset(region, 0, sizeof *region);
    if (qc_region_add_ring(ctx, region, ring, 4) < 0 || qc_region_normalize(ctx, region) < 0) {
        qc_region_free(ctx, region);
        return cli_fail(ctx, o->points_file, ctx->status);
    }
    return CLI_OK;
}

int cli_pattern_load(qc_ctx *ctx, const cli_pattern_opts *o, qc_region *region,
                     qc_points *given)
{
    int rc;

    if (o->fit_points && !o->region_given && o->points_file != NULL) {
        rc = load_points(ctx, o, given);
        return rc == CLI_OK ? fit_region(ctx, o, given, region) : rc;
    }
    rc = cli_load_region(ctx, o->region, o->mm_per_unit, region);
    if (rc != CLI_OK || o->points_file == NULL)
        return rc;
    return load_points(ctx, o, given);
}
