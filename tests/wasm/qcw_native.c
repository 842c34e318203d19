/*
 * The page's bindings (wasm/quiltc_wasm.c) compiled natively: a small driver
 * taking the CLI's generate options (--region, --units, --NAME VALUE for
 * every row of the parameter table, --motif, --tie, -o FILE...), so
 * tests/wasm/identity.mjs can compare the WebAssembly module's bytes with
 * the same binding code built by the native compiler, and both with the CLI.
 * --stats prints the run's figures (qcw_stats_json) on stderr.
 * `qcw_native quilt TOP.svg ...` sews a quilt top as `quiltc quilt` does
 * (qcw_top_svg, qcw_quilt; --join, --tie default 3), its plan given as rules:
 * --rule 'id=goose-*;label=Star point' appends a rule (keys id, class,
 * label, fill; "" for any patch) and --rule-set NAME=VALUE sets the last
 * rule's parameter (family=none leaves its patches unquilted).
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "quiltc.h"
#include "quiltc_wasm.h"

#define MAX_OUT 16
#define MAX_RULE_ARGS 128

static char *read_file(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    char *buf = NULL;
    long n;

    if (f == NULL || fseek(f, 0, SEEK_END) != 0 || (n = ftell(f)) < 0 ||
        fseek(f, 0, SEEK_SET) != 0 || (buf = malloc((size_t)n + 1)) == NULL ||
        fread(buf, 1, (size_t)n, f) != (size_t)n) {
        fprintf(stderr, "qcw_native: cannot read '%s'\n", path);
        free(buf);
        if (f != NULL)
            fclose(f);
        return NULL;
    }
    fclose(f);
    buf[n] = '\0';
    *len = (size_t)n;
    return buf;
}

static int ends_with(const char *s, const char *suffix)
{
    size_t n = strlen(s), k = strlen(suffix);
    return n >= k && strcmp(s + n - k, suffix) == 0;
}

/* A number; lengths may carry their own unit (12mm, 0.5in), as in the CLI. */
static double number(const char *s, double scale)
{
    char *end;
    double v = strtod(s, &end);

    if (scale != 1.0 || strcmp(end, "mm") == 0 || strcmp(end, "cm") == 0 ||
        strcmp(end, "in") == 0) {
        if (strcmp(end, "mm") == 0)
            scale = 1.0;
        else if (strcmp(end, "cm") == 0)
            scale = 10.0;
        else if (strcmp(end, "in") == 0)
            scale = 25.4;
    }
    return v * scale;
}

static int die(qcw_job *job, const char *what)
{
    const char *why = qcw_error(job);

    fprintf(stderr, "qcw_native: %s: %s\n", what, why[0] != '\0' ? why : "bad --rule or --rule-set");
    qcw_free(job);
    return 1;
}

/* Built-in names and .svg files, comma-separated, in order. */
static int load_motifs(qcw_job *job, const char *spec)
{
    char *copy = malloc(strlen(spec) + 1), *item;
    int rc = QC_OK;

    if (copy == NULL)
        return QC_ENOMEM;
    strcpy(copy, spec);
    for (item = strtok(copy, ","); item != NULL && rc == QC_OK; item = strtok(NULL, ",")) {
        if (ends_with(item, ".svg")) {
            size_t len;
            char *svg = read_file(item, &len);

            rc = svg != NULL ? qcw_motif_svg(job, svg, len, item) : QC_EIO;
            free(svg);
        } else {
            rc = qcw_motifs(job, item);
        }
    }
    free(copy);
    return rc;
}

/* Options of both modes: generate's, and quilt's top, rules and join. */
typedef struct {
    const char *region, *units, *motifs, *format, *top;
    const char *out[MAX_OUT];
    const char *names[64], *values[64];
    const char *rule_arg[MAX_RULE_ARGS]; /* --rule MATCH and --rule-set NAME=VALUE, in order */
    int rule_is_match[MAX_RULE_ARGS];
    size_t nout, nparams, nrule_args;
    double mm;
    int tie, join, stats;
} options;

static int parse(int argc, char **argv, options *o)
{
    size_t i = 1;

    memset(o, 0, sizeof *o);
    o->region = "rect:8x8";
    o->units = "in";
    if (argc > 2 && strcmp(argv[1], "quilt") == 0) {
        o->top = argv[2];
        o->tie = 3; /* quiltc quilt's default */
        i = 3;
    }
    for (; i < (size_t)argc; i++) {
        const char *a = argv[i], *v = i + 1 < (size_t)argc ? argv[i + 1] : NULL;

        if (strcmp(a, "--stats") == 0) {
            o->stats = 1;
            continue;
        }
        if (v == NULL || strncmp(a, "-", 1) != 0) {
            fprintf(stderr, "qcw_native: bad argument '%s'\n", a);
            return 2;
        }
        i++;
        if (strcmp(a, "-o") == 0 && o->nout < MAX_OUT)
            o->out[o->nout++] = v;
        else if (strcmp(a, "--region") == 0)
            o->region = v;
        else if (strcmp(a, "--units") == 0)
            o->units = v;
        else if (strcmp(a, "--motif") == 0)
            o->motifs = v;
        else if (strcmp(a, "--format") == 0)
            o->format = v;
        else if (strcmp(a, "--tie") == 0)
            o->tie = atoi(v);
        else if (strcmp(a, "--join") == 0)
            o->join = strcmp(v, "jump") == 0;
        else if ((strcmp(a, "--rule") == 0 || strcmp(a, "--rule-set") == 0) &&
                 o->nrule_args < MAX_RULE_ARGS) {
            o->rule_is_match[o->nrule_args] = strcmp(a, "--rule") == 0;
            o->rule_arg[o->nrule_args++] = v;
        } else if (strncmp(a, "--", 2) == 0 && o->nparams < 64) {
            o->names[o->nparams] = a + 2;
            o->values[o->nparams++] = v;
        } else {
            fprintf(stderr, "qcw_native: bad option '%s'\n", a);
            return 2;
        }
    }
    o->mm = strcmp(o->units, "mm") == 0 ? 1.0 : strcmp(o->units, "cm") == 0 ? 10.0 : 25.4;
    return 0;
}

/* A row's value as qcw_param takes it: enums as choices, lengths in mm. */
static double param_value(const qc_param_info *row, const char *text, double mm)
{
    if (row->type == QC_PARAM_ENUM)
        return qc_param_choice(row, text);
    return number(text, row->type == QC_PARAM_LENGTH ? mm : 1.0);
}

static int set_params(qcw_job *job, const options *o)
{
    size_t i;
    int rc = QC_OK;

    qcw_params_reset(job, strcmp(o->units, "in") == 0);
    for (i = 0; i < o->nparams && rc == QC_OK; i++) {
        const qc_param_info *row = qc_param_find(o->names[i]);

        if (row == NULL) {
            fprintf(stderr, "qcw_native: unknown parameter '%s'\n", o->names[i]);
            return QC_EINVAL;
        }
        if (row->type == QC_PARAM_SEED) {
            unsigned long long s = strtoull(o->values[i], NULL, 10);
            rc = qcw_seed(job, (double)(s >> 32), (double)(s & 0xffffffffu));
        } else
            rc = qcw_param(job, o->names[i], param_value(row, o->values[i], o->mm));
    }
    if (rc == QC_OK && o->motifs != NULL)
        rc = load_motifs(job, o->motifs);
    return rc;
}

/* "id=goose-*;fill=#e67e22": one rule's match (edits spec in place). */
static int add_rule(qcw_job *job, char *spec)
{
    const char *field[4] = {"", "", "", ""};
    static const char *const key[4] = {"id", "class", "label", "fill"};
    char *item, *next;
    size_t k;

    for (item = spec; item != NULL && *item != '\0'; item = next) {
        char *eq = strchr(item, '=');

        next = strchr(item, ';');
        if (next != NULL)
            *next++ = '\0';
        if (eq == NULL)
            return QC_EINVAL;
        *eq = '\0';
        for (k = 0; k < 4 && strcmp(item, key[k]) != 0; k++)
            ;
        if (k == 4)
            return QC_EINVAL;
        field[k] = eq + 1;
    }
    return qcw_rule_add(job, field[0], field[1], field[2], field[3]);
}

/* "spacing=0.3": the last rule's parameter; family=none leaves its patches alone. */
static int set_rule_param(qcw_job *job, char *item, double mm)
{
    char *eq = strchr(item, '=');
    const qc_param_info *row;

    if (eq == NULL)
        return QC_EINVAL;
    *eq = '\0';
    if (strcmp(item, "family") == 0 && strcmp(eq + 1, "none") == 0)
        return qcw_rule_none(job);
    row = qc_param_find(item);
    if (row == NULL || row->type == QC_PARAM_SEED)
        return QC_EINVAL;
    return qcw_rule_param(job, item, param_value(row, eq + 1, mm));
}

static int set_rules(qcw_job *job, const options *o)
{
    char buf[512];
    size_t i;
    int rc = QC_OK;

    for (i = 0; i < o->nrule_args && rc == QC_OK; i++) {
        if (strlen(o->rule_arg[i]) >= sizeof buf)
            return QC_EINVAL;
        strcpy(buf, o->rule_arg[i]);
        rc = o->rule_is_match[i] ? add_rule(job, buf) : set_rule_param(job, buf, o->mm);
    }
    return rc;
}

static int load_svg(const char *path, qcw_job *job, int top, double mm, const char *units)
{
    size_t len;
    char *svg = read_file(path, &len);
    int rc;

    if (svg == NULL)
        return QC_EIO;
    rc = top ? qcw_top_svg(job, svg, len, mm, units) : qcw_region_svg(job, svg, len);
    free(svg);
    return rc;
}

/* Loads, generates or sews; names the failing step in *what. */
static int run(qcw_job *job, const options *o, const char **what)
{
    int rc;

    *what = o->top != NULL ? "top" : "region";
    if (o->top != NULL)
        rc = load_svg(o->top, job, 1, o->mm, o->units);
    else if (ends_with(o->region, ".svg"))
        rc = load_svg(o->region, job, 0, o->mm, o->units);
    else
        rc = qcw_region_shape(job, o->region, o->mm);
    if (rc < 0)
        return rc;
    *what = "parameters";
    if ((rc = set_params(job, o)) < 0)
        return rc;
    if (o->top == NULL) {
        *what = "generate";
        return qcw_run(job, o->tie);
    }
    *what = "plan";
    if ((rc = set_rules(job, o)) < 0)
        return rc;
    *what = "quilt";
    return qcw_quilt(job, o->join, o->tie);
}

int main(int argc, char **argv)
{
    options o;
    const char *what;
    size_t i;
    qcw_job *job;

    if (parse(argc, argv, &o) != 0)
        return 2;
    job = qcw_new();
    if (job == NULL)
        return 1;
    if (run(job, &o, &what) < 0)
        return die(job, what);
    if (o.stats)
        fprintf(stderr, "%s\n", o.top != NULL ? qcw_quilt_stats_json(job) : qcw_stats_json(job));
    for (i = 0; i < o.nout; i++) {
        FILE *f;

        if (qcw_export(job, o.format != NULL ? o.format : o.out[i]) < 0)
            return die(job, o.out[i]);
        f = fopen(o.out[i], "wb");
        if (f == NULL || fwrite(qcw_export_data(job), 1, qcw_export_size(job), f) !=
                             qcw_export_size(job)) {
            fprintf(stderr, "qcw_native: cannot write '%s'\n", o.out[i]);
            if (f != NULL)
                fclose(f);
            qcw_free(job);
            return 1;
        }
        fclose(f);
    }
    qcw_free(job);
    return 0;
}
