/* The --stats JSON object. */
#ifndef QUILTC_CLI_STATS_JSON_H
#define QUILTC_CLI_STATS_JSON_H

#include "cli.h"

/* Prints one line of JSON: counts, lengths, the stitch estimate, ms per stage. */
void cli_stats_print(FILE *f, const qc_result *res, const qc_plan *plan, const cli_timer *t);

#endif
