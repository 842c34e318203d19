/*
 * A quilt job file (quiltc job): its blocks, each with its region, place,
 * rotation, family and parameters, read from JSON and checked key by key.
 * job_parse.c reads; cmd_job.c generates and joins.
 */
#ifndef QC_CLI_JOB_H
#define QC_CLI_JOB_H

#include <cjson/cJSON.h>

#include "cli.h"
#include "json_fields.h"

#define MAX_BLOCKS 1024
#define MAX_JOB_OUTPUTS CLI_MAX_OUTPUTS
#define MAX_JOB_BYTES ((size_t)1 << 20)
#define VALUE_LEN CLI_JSON_VALUE_LEN
#define MAX_AT_MM 1e5 /* block corners: 100 m is beyond any quilt */
#define JOB_MAX_TSP_MS 600000.0 /* the blocks' tsp-time together: one block's maximum */

typedef struct block {
    cli_pattern_opts pat;
    char values[64][VALUE_LEN]; /* numbers from JSON, as option text */
    double at[2], rotate;
    const char *top;            /* a pieced top (SVG) instead of a region */
    const cJSON *plan;          /* its plan (rules), or NULL */
    char where[32];             /* "blocks[3]" for messages */
    char label[40];             /* "job: blocks[3]", for the parameters' messages */
    qc_path path;               /* in the quilt's frame */
    qc_region outline;          /* its region (or top's patches) there, for overlaps */
    qc_vec2 lo;                 /* lower-left of its box, for ordering */
} block;

typedef struct job {
    const char *units;
    int tie;
    const char *outputs[MAX_JOB_OUTPUTS];
    size_t nout;
    block *blocks;
    size_t n;
} job;

/* Parses a job file's text strictly: no key twice in one object, nothing
 * after the value, nesting within cJSON's limit. NULL after one line. */
cJSON *cli_json_parse(const char *buf, size_t len, const char *file);

/* Reads the parsed document root into *j (zeroed by the caller): every key
 * known, every value of the right type and range, each block's parameters
 * as cli_pattern_opts (converted later by cli_pattern_finish). CLI_OK, or
 * CLI_USAGE after one line naming the key ("job: blocks[2].at: ...").
 * Strings point into root; free j->blocks with free(). */
int cli_job_parse(job *j, const cJSON *root);

/* Converts every block's parameters (cli_pattern_finish) and checks the
 * job's total budget before any work: the blocks' estimated points within
 * QC_MAX_POINTS, their tsp-time within JOB_MAX_TSP_MS. CLI_OK, or an error
 * after one line naming the block where the budget ran out. */
int cli_job_budget(qc_ctx *ctx, job *j);

/* Strings made for a job's resolved file names. */
typedef struct cli_job_names {
    char **s;
    size_t n, cap;
} cli_job_names;

/* Rewrites the job's file names relative to the directory of file (the job
 * file's path); the new strings go to *names (free with
 * cli_job_names_free). Unless allow_outside, every file name must stay
 * inside that folder (cli_path_inside). CLI_OK, or an error after one line. */
int cli_job_resolve_names(job *j, const char *file, int allow_outside, cli_job_names *names);
void cli_job_names_free(cli_job_names *names);

/* CLI_OK when name (as the job wrote it; path, the name resolved beside the
 * job) is relative, has no "..", and resolves inside root (the job's
 * folder, resolved); else CLI_USAGE after one line starting with what. */
int cli_path_inside(const char *root, const char *name, const char *path, const char *what);

#endif
