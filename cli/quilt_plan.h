/*
 * A quilt plan (quiltc quilt --plan): an ordered list of rules, the first
 * whose "match" fits a patch choosing its family, motifs and parameters.
 *
 * [{"match": {"id": "star-*", "class": "point", "label": "Star",
 *             "fill": "#c0392b"}, "family": "pebbling", "params": {"spacing": 0.4}},
 *  {"match": {"fill": "white"}, "family": "none"},
 *  {"family": "stipple"}]
 */
#ifndef QC_CLI_QUILT_PLAN_H
#define QC_CLI_QUILT_PLAN_H

#include <cjson/cJSON.h>

#include "cli.h"
#include "json_fields.h"

#define MAX_PLAN_RULES 256
#define PLAN_VALUE_LEN CLI_JSON_VALUE_LEN

typedef struct plan_rule {
    qc_patch_match match;         /* id, class, label, fill (qc_patch_matches) */
    int has_match;
    int none;                     /* "family": "none": leave unquilted */
    cli_pattern_opts pat;         /* the command line's options, then the rule's */
    char values[64][PLAN_VALUE_LEN];
    char where[64];               /* "plan: rules[2]", "job: blocks[1].plan[2]" */
    size_t matched;               /* patches it chose for */
    qc_motif_set motifs;
} plan_rule;

typedef struct quilt_plan {
    plan_rule *rule;
    size_t n;
    cJSON *doc; /* the plan file's document the rules point into (owned), or NULL */
} quilt_plan;

/* Reads the rules from the parsed root (an array) over base (the command
 * line's options, copied into each rule). CLI_OK, or CLI_USAGE after one
 * line naming the key (prefix "plan: rules" gives "plan: rules[1].match.fill:
 * ..."). Free with cli_quilt_plan_free. */
int cli_quilt_plan_parse(quilt_plan *p, const cJSON *root, const cli_pattern_opts *base,
                         const char *prefix);
void cli_quilt_plan_free(qc_ctx *ctx, quilt_plan *p);
/* The first rule matching patch, or NULL. */
plan_rule *cli_quilt_plan_match(quilt_plan *p, const qc_patch *patch);

/* A top quilted by its plan (quilt_sew.c), shared by quiltc quilt and job. */
typedef struct cli_quilt {
    qc_patches ps;
    qc_motif_set base_motifs;
    qc_patch_job *jobs;
    const plan_rule **chosen; /* per patch; NULL: the base options */
    qc_quilt_result res;
} cli_quilt;

/* Reads top (an SVG of patches), refuses overlapping patches (naming both,
 * in base's units), finishes base's and every rule's options, chooses each
 * patch's rule (a rule matching nothing is an error) and quilts. where
 * prefixes messages ("quilt", "job: blocks[2]"). CLI status. */
int cli_quilt_sew(qc_ctx *ctx, cli_quilt *q, const char *top, quilt_plan *plan,
                  cli_pattern_opts *base, const qc_quilt_params *qp, const char *where);
void cli_quilt_free(qc_ctx *ctx, cli_quilt *q);
/* Every patch outline in one region (to draw). CLI status. */
int cli_quilt_outlines(qc_ctx *ctx, const qc_patches *ps, qc_region *out);

#endif
