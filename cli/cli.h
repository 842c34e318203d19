/* quiltc CLI: shared helpers for the subcommands. */
#ifndef QUILTC_CLI_H
#define QUILTC_CLI_H

#include <stdio.h>

#include "quiltc.h"

/* Exit statuses: success, a runtime error, a usage error. */
enum { CLI_OK = 0, CLI_RUNTIME = 1, CLI_USAGE = 2 };

#if defined(__GNUC__)
#define CLI_PRINTF(f, a) __attribute__((format(printf, f, a)))
#else
#define CLI_PRINTF(f, a)
#endif

/* Prints "quiltc: <message>" as one line on stderr. */
void cli_error(const char *fmt, ...) CLI_PRINTF(1, 2);
/* Prints the context's error ("quiltc: what: detail") and returns CLI_RUNTIME,
 * or CLI_USAGE for parameter range/choice errors. */
int cli_fail(const qc_ctx *ctx, const char *what, int status);

/* Reads a whole file (at most max bytes) into a NUL-terminated buffer. */
int cli_read_file(const char *path, size_t max, char **buf, size_t *len);

/* An output written whole or not at all: a temp file renamed on commit. */
typedef struct cli_output {
    FILE *f;
    char *path, *tmp;
    int failed;
} cli_output;

int cli_output_open(cli_output *out, const char *path);
/* qc_write_fn over a cli_output. */
int cli_output_write(void *ud, const void *data, size_t len);
/* Flushes, syncs and renames into place; on failure removes the temp file. */
int cli_output_commit(cli_output *out);
void cli_output_abort(cli_output *out);

/* Strict number parsing: the whole string, finite. 0 on success. */
int cli_parse_double(const char *s, double *out);
int cli_parse_u64(const char *s, unsigned long long *out);
/* "in" -> 25.4, "mm" -> 1, "cm" -> 10; 0 if unknown. */
double cli_units_mm(const char *units);

/* A region from a built-in shape spec ("rect:8x8") or an SVG file, in mm,
 * normalized, moved so its bounding box starts at (0, 0). */
int cli_load_region(qc_ctx *ctx, const char *spec, double mm_per_unit, qc_region *out);

/* Monotonic milliseconds. */
double cli_now_ms(void);

/* Writes plan as format to path ("-" = stdout) atomically. */
int cli_write_plan(qc_ctx *ctx, const char *path, int format, const qc_plan *plan,
                   const qc_io_opts *opts);

/* Appends motifs named in a comma-separated list of built-in names and .svg files. */
int cli_load_motifs(qc_ctx *ctx, const char *spec, qc_motif_set *set);

int cmd_generate(int argc, char **argv);
int cmd_skeleton(int argc, char **argv);

#endif
