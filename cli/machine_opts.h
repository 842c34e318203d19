/*
 * generate's options for the machine and the quilt, beside the pattern's:
 * where the block goes (--rotate, --mirror, --at, --clip), how it is sewn
 * and estimated (--spi, --stitch-length, --split-stitches, --speed,
 * --tie-length, --bobbin-yards) and how G-code lifts the pen (--pen-up, --pen-down).
 */
#ifndef QC_CLI_MACHINE_OPTS_H
#define QC_CLI_MACHINE_OPTS_H

#include <getopt.h>

#include "cli.h"

#define CLI_MACH_BASE 2000
enum {
    CLI_MACH_ROTATE = CLI_MACH_BASE, CLI_MACH_MIRROR, CLI_MACH_AT, CLI_MACH_CLIP,
    CLI_MACH_SPI, CLI_MACH_STITCH_LEN, CLI_MACH_SPEED, CLI_MACH_TIE_LEN, CLI_MACH_BOBBIN,
    CLI_MACH_PEN_UP, CLI_MACH_PEN_DOWN, CLI_MACH_SPLIT
};
/* The getopt_long rows, for an option list. */
#define CLI_MACHINE_OPTIONS                                                           \
    {"rotate", required_argument, NULL, CLI_MACH_ROTATE},                             \
    {"mirror", required_argument, NULL, CLI_MACH_MIRROR},                             \
    {"at", required_argument, NULL, CLI_MACH_AT},                                     \
    {"clip", no_argument, NULL, CLI_MACH_CLIP},                                       \
    {"spi", required_argument, NULL, CLI_MACH_SPI},                                   \
    {"stitch-length", required_argument, NULL, CLI_MACH_STITCH_LEN},                  \
    {"speed", required_argument, NULL, CLI_MACH_SPEED},                               \
    {"tie-length", required_argument, NULL, CLI_MACH_TIE_LEN},                        \
    {"bobbin-yards", required_argument, NULL, CLI_MACH_BOBBIN},                       \
    {"pen-up", required_argument, NULL, CLI_MACH_PEN_UP},                             \
    {"pen-down", required_argument, NULL, CLI_MACH_PEN_DOWN},                         \
    {"split-stitches", no_argument, NULL, CLI_MACH_SPLIT}

typedef struct cli_machine_opts {
    const char *raw[CLI_MACH_PEN_DOWN - CLI_MACH_BASE + 1]; /* as typed, by option */
    int clip;
    int split;            /* --split-stitches: no stitch longer than 1/spi in */
    /* resolved by cli_machine_finish */
    qc_place place;
    int placed;           /* a --rotate, --mirror or --at was given */
    double spi;           /* stitches per inch, 12 unless given */
    double speed_mm_s;    /* 25.4 unless given */
    double tie_length_mm; /* 0: the library's default */
    double bobbin_mm;     /* 0: no bobbin count */
} cli_machine_opts;

/* Takes one option getopt returned; 1 if it was one of these. */
int cli_machine_take(cli_machine_opts *m, int opt, const char *arg);
/* Converts the values, lengths in units (mm_per_unit) unless suffixed;
 * CLI_OK or CLI_USAGE after one line in the user's units. */
int cli_machine_finish(cli_machine_opts *m, double mm_per_unit);
/* The stitch plan's lengths for these options: with --split-stitches no
 * segment longer than one stitch (1/spi in), else the library's defaults. */
void cli_machine_stitch_params(const cli_machine_opts *m, qc_stitch_params *sp);
/* The --help lines. */
void cli_machine_help(FILE *f);

#endif
