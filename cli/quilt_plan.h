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

#define MAX_PLAN_RULES 256
#define PLAN_VALUE_LEN 48

typedef struct plan_rule {
    const char *id, *cls, *label; /* "*" wildcards; NULL matches anything */
    uint32_t fill;
    int has_fill, has_match;
    int none;                     /* "family": "none": leave unquilted */
    cli_pattern_opts pat;         /* the command line's options, then the rule's */
    char values[64][PLAN_VALUE_LEN];
    char where[40];               /* "plan: rules[2]" */
    size_t matched;               /* patches it chose for */
    qc_motif_set motifs;
} plan_rule;

typedef struct quilt_plan {
    plan_rule *rule;
    size_t n;
} quilt_plan;

/* Reads the rules from the parsed root (an array) over base (the command
 * line's options, copied into each rule). CLI_OK, or CLI_USAGE after one
 * line naming the key ("plan: rules[1].match.fill: ..."). Free with
 * cli_quilt_plan_free. */
int cli_quilt_plan_parse(quilt_plan *p, const cJSON *root, const cli_pattern_opts *base);
void cli_quilt_plan_free(qc_ctx *ctx, quilt_plan *p);
/* The first rule matching patch, or NULL. */
plan_rule *cli_quilt_plan_match(quilt_plan *p, const qc_patch *patch);
/* '*' matches any run of characters. */
int cli_glob(const char *pattern, const char *s);

#endif
