/* The --stats JSON object. */
#ifndef QUILTC_CLI_STATS_JSON_H
#define QUILTC_CLI_STATS_JSON_H

#include "cli.h"

/* How the estimate counts: stitches per inch, sewing speed, bobbin capacity
 * (0: no bobbin count). */
typedef struct cli_sewing {
    double spi, speed_mm_s, bobbin_mm;
} cli_sewing;

/* Prints one line of JSON: counts, lengths, the stitch estimate, ms per stage. */
void cli_stats_print(FILE *f, const qc_result *res, const qc_plan *plan, const cli_timer *t,
                     const cli_sewing *sew);
/* Bobbins for the sewn length (thread take-up as the top thread's), or 0. */
double cli_bobbins(const qc_plan_estimate *est, const cli_sewing *sew);
/* One line per file written on stderr: "wrote FILE (fmt): N stitches at S spi,
 * Y yd of thread, about T" (m of thread unless inches). */
void cli_say_written(const char *const *paths, const int *formats, size_t n,
                     const qc_plan *plan, const cli_sewing *sew, int inches);

#endif
