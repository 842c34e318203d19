/*
 * The page's bindings (wasm/quiltc_wasm.c) compiled natively: a small driver
 * taking the CLI's generate options (--region, --units, --NAME VALUE for
 * every row of the parameter table, --motif, --tie, -o FILE...), so
 * tests/wasm/identity.mjs can compare the WebAssembly module's bytes with
 * the same binding code built by the native compiler, and both with the CLI.
 * --stats prints the run's figures (qcw_stats_json) on stderr.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "quiltc.h"
#include "quiltc_wasm.h"

#define MAX_OUT 16

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
    fprintf(stderr, "qcw_native: %s: %s\n", what, qcw_error(job));
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

int main(int argc, char **argv)
{
    const char *region = "rect:8x8", *units = "in", *motifs = NULL, *format = NULL;
    const char *out[MAX_OUT];
    const char *names[64], *values[64];
    size_t nout = 0, nparams = 0, i;
    double mm = 25.4;
    int tie = 0, stats = 0, rc;
    qcw_job *job;

    for (i = 1; i < (size_t)argc; i++) {
        const char *a = argv[i], *v = i + 1 < (size_t)argc ? argv[i + 1] : NULL;

        if (strcmp(a, "--stats") == 0) {
            stats = 1;
            continue;
        }
        if (v == NULL || strncmp(a, "-", 1) != 0) {
            fprintf(stderr, "qcw_native: bad argument '%s'\n", a);
            return 2;
        }
        i++;
        if (strcmp(a, "-o") == 0 && nout < MAX_OUT)
            out[nout++] = v;
        else if (strcmp(a, "--region") == 0)
            region = v;
        else if (strcmp(a, "--units") == 0)
            units = v;
        else if (strcmp(a, "--motif") == 0)
            motifs = v;
        else if (strcmp(a, "--format") == 0)
            format = v;
        else if (strcmp(a, "--tie") == 0)
            tie = atoi(v);
        else if (strncmp(a, "--", 2) == 0 && nparams < 64) {
            names[nparams] = a + 2;
            values[nparams++] = v;
        } else {
            fprintf(stderr, "qcw_native: bad option '%s'\n", a);
            return 2;
        }
    }
    mm = strcmp(units, "mm") == 0 ? 1.0 : strcmp(units, "cm") == 0 ? 10.0 : 25.4;
    job = qcw_new();
    if (job == NULL)
        return 1;
    if (ends_with(region, ".svg")) {
        size_t len;
        char *svg = read_file(region, &len);

        rc = svg != NULL ? qcw_region_svg(job, svg, len) : QC_EIO;
        free(svg);
    } else {
        rc = qcw_region_shape(job, region, mm);
    }
    if (rc < 0)
        return die(job, "region");
    qcw_params_reset(job, strcmp(units, "in") == 0);
    for (i = 0; i < nparams; i++) {
        const qc_param_info *row = qc_param_find(names[i]);
        double v;

        if (row == NULL) {
            fprintf(stderr, "qcw_native: unknown parameter '%s'\n", names[i]);
            qcw_free(job);
            return 2;
        }
        if (row->type == QC_PARAM_SEED) {
            unsigned long long s = strtoull(values[i], NULL, 10);
            rc = qcw_seed(job, (double)(s >> 32), (double)(s & 0xffffffffu));
        } else {
            if (row->type == QC_PARAM_ENUM)
                v = qc_param_choice(row, values[i]);
            else
                v = number(values[i], row->type == QC_PARAM_LENGTH ? mm : 1.0);
            rc = qcw_param(job, names[i], v);
        }
        if (rc < 0)
            return die(job, "parameters");
    }
    if (motifs != NULL && load_motifs(job, motifs) < 0)
        return die(job, "motifs");
    if (qcw_run(job, tie) < 0)
        return die(job, "generate");
    if (stats)
        fprintf(stderr, "%s\n", qcw_stats_json(job));
    for (i = 0; i < nout; i++) {
        FILE *f;

        if (qcw_export(job, format != NULL ? format : out[i]) < 0)
            return die(job, out[i]);
        f = fopen(out[i], "wb");
        if (f == NULL || fwrite(qcw_export_data(job), 1, qcw_export_size(job), f) !=
                             qcw_export_size(job)) {
            fprintf(stderr, "qcw_native: cannot write '%s'\n", out[i]);
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
