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

/* Writes text with control characters (C0, DEL, UTF-8 C1) and invalid
 * UTF-8 escaped (\n, \x1B, \u009B): text from files never drives the
 * terminal. */
void cli_put_escaped(FILE *f, const char *text);
/* Prints "quiltc: <message>" as one line on stderr, control characters
 * escaped. */
void cli_error(const char *fmt, ...) CLI_PRINTF(1, 2);
/* A reader's warning (qc_warn_fn; ud is the file's name): one line on
 * stderr, "quiltc: FILE: warning: text". */
void cli_warn_file(void *ud, const char *text);
/* SVG reading options that print warnings about path, sized to max_bytes. */
void cli_svg_opts(qc_svg_opts *opts, const char *path, size_t max_bytes);
/* Prints the context's error ("quiltc: what: detail") and returns CLI_RUNTIME,
 * or CLI_USAGE for parameter range/choice errors. */
int cli_fail(const qc_ctx *ctx, const char *what, int status);

/* getopt returned '?' or ':' for arg: one line naming it and the help command. */
void cli_bad_option(const char *command, const char *arg, int c);

/* getopt_long that refuses abbreviated long options: returns
 * CLI_GETOPT_REPORTED after one line naming the typed and the full name. */
#define CLI_GETOPT_REPORTED (-2)
struct option;
int cli_getopt(int argc, char **argv, const char *shortopts, const struct option *opts);

/* A length: a number in mm_per_unit, or with its own suffix mm, cm, in.
 * 0, -1 (not a length) or -2 (too large). */
int cli_parse_length(const char *s, double mm_per_unit, double *mm);
/* One line: "NAME 0.01 in (0.254 mm) out of range [0.01969, 39.37] in". */
void cli_length_range(const char *name, double mm, double lo, double hi, double mm_per_unit);
/* "0.254 mm" in the user's units: "0.01 in" (in), "0.0254 cm"... */
const char *cli_units_name(double mm_per_unit);

/* Reads a whole file (at most max bytes) into a NUL-terminated buffer. */
int cli_read_file(const char *path, size_t max, char **buf, size_t *len);

/* An output being written: a temporary file beside the file (or beside the
 * file a symbolic link names), renamed into place when every output is
 * done; a device or FIFO is written in place; "-" is stdout. */
typedef struct cli_output {
    FILE *f;
    char *path, *tmp; /* tmp NULL: written in place */
    char *buf;        /* f's buffer (NULL: stdio's own), freed when f is closed */
    int failed;       /* a write failed: reported when it is closed */
} cli_output;

/* qc_write_fn over a cli_output. */
int cli_output_write(void *ud, const void *data, size_t len);

/* Strict number parsing: the whole string, finite. 0 on success. */
int cli_parse_double(const char *s, double *out);
int cli_parse_u64(const char *s, unsigned long long *out);
/* "in" -> 25.4, "mm" -> 1, "cm" -> 10; 0 if unknown. */
double cli_units_mm(const char *units);

/* A region from a built-in shape spec ("rect:8x8") or an SVG file, in mm,
 * normalized, moved so its bounding box starts at (0, 0). */
int cli_load_region(qc_ctx *ctx, const char *spec, double mm_per_unit, qc_region *out);
/* The same, but an SVG is read as a quilt top: every patch's rings in one
 * region (not normalized: patches share seams), moved to the origin. */
int cli_load_top(qc_ctx *ctx, const char *spec, double mm_per_unit, qc_region *out);
/* The same, and the top's patches moved alike in *ps (none for a shape
 * spec; free with qc_patches_free). */
int cli_load_top_patches(qc_ctx *ctx, const char *spec, double mm_per_unit, qc_region *out,
                         qc_patches *ps);

/* Monotonic milliseconds. */
double cli_now_ms(void);

/* CLI_OK, or CLI_USAGE after one line when two outputs name one file. */
int cli_outputs_distinct(const char *const *paths, size_t n);
/* Writes outputs paths[0..n) (at most CLI_MAX_OUTPUTS) whole or not at
 * all: each opened under a temporary name and filled by write(ud, i, out),
 * which returns a CLI status after one line on failure; then all are
 * renamed into place, or all removed. Two names for one file are refused. */
#define CLI_MAX_OUTPUTS 16
typedef int (*cli_write_one)(void *ud, size_t i, cli_output *out);
int cli_write_outputs(const char *const *paths, size_t n, cli_write_one write, void *ud);
/* The same for a stitch plan in formats[i] to each path ("-" = stdout). */
int cli_write_plans(qc_ctx *ctx, const char *const *paths, const int *formats, size_t n,
                    const qc_plan *plan, const qc_io_opts *opts);
int cli_write_plan(qc_ctx *ctx, const char *path, int format, const qc_plan *plan,
                   const qc_io_opts *opts);

/* CLI_OK when p[0..n) lies in the region's box (times the tiles of a tiled
 * pattern), else CLI_RUNTIME after one line naming the family and region:
 * no writer emits a point another would refuse. */
int cli_check_inside(const qc_vec2 *p, size_t n, const qc_params *resolved,
                     const qc_region *region, const char *region_name, const char *what);
/* The same for the curve of path flattened to 0.01 mm (its control points
 * not checked): CLI_OK, CLI_RUNTIME, or a CLI_* status if flattening fails. */
int cli_check_path_inside(qc_ctx *ctx, const qc_path *path, const qc_params *resolved,
                          const qc_region *region, const char *region_name, const char *what);

/* Reads a .pat or .svg pattern into a plan. CLI_* status. */
int cli_read_plan(qc_ctx *ctx, const char *path, qc_plan *plan);

/* Appends motifs named in a comma-separated list of built-in names and .svg files. */
int cli_load_motifs(qc_ctx *ctx, const char *spec, qc_motif_set *set);

/* Region, units and parameter options shared by generate and skeleton. */
typedef struct cli_pattern_opts {
    const char *region;      /* shape spec or SVG file; default rect:8x8 */
    const char *units;       /* in | mm | cm; default in */
    double mm_per_unit;
    const char *points_file; /* --points FILE */
    const char *motifs;      /* --motif LIST */
    const char *raw[64];     /* raw value per parameter row, converted after parsing */
    char repeat[2][24];      /* --repeat CxR, split into repeat-cols and repeat-rows */
    int bad;                 /* an option was refused (already reported) */
    const char *where;       /* NULL, or "job: blocks[2]": messages name job keys */
    int region_given;        /* --region was typed */
    int fit_points;          /* no --region: the --points' box grown by the margin */
    qc_params params;
} cli_pattern_opts;

/* getopt_long's option list: the fixed ones then one per parameter row
 * (val = CLI_PARAM_BASE + row). *count receives the length. Caller frees. */
#define CLI_PARAM_BASE 1000
struct option;
struct option *cli_pattern_options(const struct option *fixed, size_t nfixed);
void cli_pattern_init(cli_pattern_opts *o);
/* Takes one option getopt returned (--region, --units, a parameter); 1 if it was one. */
int cli_pattern_take(cli_pattern_opts *o, int opt, const char *arg);
/* Converts the raw values into params (lengths in units unless suffixed). CLI_* status. */
int cli_pattern_finish(qc_ctx *ctx, cli_pattern_opts *o);
/* After cli_pattern_finish: one warning line on stderr naming the options
 * given that the resolved family does not read ("--motif is ignored by
 * family vine"); nothing when every one counts. */
void cli_pattern_warn_ignored(const cli_pattern_opts *o);
/* --quilt-width: sets repeat-cols to the most tiles (one the width of
 * region's box; offset rows reach further) that fit across width (a length
 * in the options' units). CLI_OK, or CLI_USAGE after one line (not tiled,
 * columns also given, none or over 100 fit). */
int cli_fit_columns(qc_ctx *ctx, cli_pattern_opts *o, const char *width,
                    const qc_region *region);
/* Prints the region/units/parameter part of a --help text. */
void cli_pattern_help(FILE *f, unsigned families);
/* Loads region (normalized, at the origin) and the given points, if any. CLI_* status. */
int cli_pattern_load(qc_ctx *ctx, const cli_pattern_opts *o, qc_region *region,
                     qc_points *given);

/* Stage timings recorded through qc_ctx's trace hook. */
typedef struct cli_timer {
    double t0, last;
    const char *stage;
    double ms[12];
    const char *name[12];
    size_t n;
} cli_timer;
void cli_timer_start(cli_timer *t, qc_ctx *ctx);
void cli_timer_mark(cli_timer *t, const char *stage);
void cli_timer_trace(void *ud, const char *stage);

int cmd_generate(int argc, char **argv);
int cmd_skeleton(int argc, char **argv);
int cmd_convert(int argc, char **argv);
int cmd_check(int argc, char **argv);
int cmd_list(int argc, char **argv);
int cmd_job(int argc, char **argv);
int cmd_quilt(int argc, char **argv);
int cmd_motifs(int argc, char **argv);
/* USB (usb_*.c, or usb_none.c when built with USB=0). */
int cmd_devices(int argc, char **argv);
int cmd_upload(int argc, char **argv);
int cmd_udev_rule(int argc, char **argv);
int cli_usb_send_file(const char *path, const char *device, int quiet);

#endif
