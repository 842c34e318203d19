/* Optional exact tours: the concorde program, when it is on PATH. */
#ifndef QUILTC_CLI_CONCORDE_H
#define QUILTC_CLI_CONCORDE_H

#include "cli.h"

/* The skeleton of params (points sampled or given) with its order replaced
 * by concorde's optimal tour, started at the root. CLI_* status. */
int cli_concorde_skeleton(qc_ctx *ctx, const qc_params *params, const qc_region *region,
                          const qc_points *given, qc_result *res);

/* qc_generate of params with the tour concorde's (families on a tour
 * skeleton: wanderer, or --skeleton tsp): the built-in tour is replaced
 * before the family decorates. CLI_* status. */
int cli_concorde_generate(qc_ctx *ctx, const qc_params *params, const qc_region *region,
                          const qc_points *given, const qc_motif_set *motifs, qc_result *res);

#endif
