/* Optional exact tours: the concorde program, when it is on PATH. */
#ifndef QUILTC_CLI_CONCORDE_H
#define QUILTC_CLI_CONCORDE_H

#include "cli.h"

/* The skeleton of params (points sampled or given) toured by concorde,
 * started at the root (the core's tour hook, ctx->tour). CLI_* status. */
int cli_concorde_skeleton(qc_ctx *ctx, const qc_params *params, const qc_region *region,
                          const qc_points *given, qc_result *res);

/* qc_generate of params with concorde's tour in place of the built-in one
 * (families on a tour skeleton: wanderer, or --skeleton tsp), through the
 * core's tour hook, so the family decorates once. CLI_* status. */
int cli_concorde_generate(qc_ctx *ctx, const qc_params *params, const qc_region *region,
                          const qc_points *given, const qc_motif_set *motifs, qc_result *res);

#endif
