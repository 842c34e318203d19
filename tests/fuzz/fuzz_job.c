/*
 * Fuzz target: a quilt job file, as `quiltc job` reads it: cJSON's parser
 * read strictly (cli/json_strict.c: duplicate keys, trailing text, depth),
 * then the job's own validation (cli_job_parse of cli/job_parse.c: keys,
 * units, tie, outputs, blocks, params) and, per block, the parameter
 * conversion and range check (cli_pattern_finish) and, for built-in
 * shapes, the region. No block is generated and no file is written
 * (generation has its own target, fuzz_generate). Runs with stderr closed (-close_fd_mask=2): the
 * CLI prints its one-line errors there.
 */
#include <stdlib.h>
#include <string.h>

#include "../../cli/job.h"
#include "fuzz_common.h"

/* "rect:4x4" style specs only: a name, a colon, no path (no file access). */
static int builtin_shape(const char *spec)
{
    const char *c = strchr(spec, ':');

    return c != NULL && c != spec && strchr(spec, '/') == NULL && strstr(spec, ".svg") == NULL;
}

static void validate(job *j)
{
    size_t i;

    for (i = 0; i < j->n; i++) {
        block *b = &j->blocks[i];
        fuzz_alloc a;
        qc_ctx ctx;
        int rc;

        fuzz_ctx_init(&ctx, &a);
        rc = cli_pattern_finish(&ctx, &b->pat);
        FUZZ_CHECK(rc == CLI_OK || rc == CLI_USAGE || rc == CLI_RUNTIME, "a CLI status");
        if (rc == CLI_OK && b->pat.points_file == NULL && builtin_shape(b->pat.region)) {
            qc_region r;
            rc = cli_load_region(&ctx, b->pat.region, b->pat.mm_per_unit, &r);
            FUZZ_CHECK(rc == CLI_OK || rc == CLI_USAGE, "a shape is loaded or refused");
            if (rc == CLI_OK)
                FUZZ_CHECK(r.nrings > 0, "a loaded shape has an outline");
            qc_region_free(&ctx, &r);
        }
        fuzz_check_clean(&a, "job block leaked");
    }
}

/* The job text as quiltc reads it: NUL-terminated, then strictly. */
static cJSON *fuzz_job_text(const uint8_t *data, size_t size)
{
    char *s = malloc(size + 1);
    cJSON *root;

    if (s == NULL)
        return NULL;
    memcpy(s, data, size);
    s[size] = '\0';
    root = cli_json_parse(s, size, "fuzz.json");
    free(s);
    return root;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    cJSON *root;
    job j;
    int rc;

    if (size > MAX_JOB_BYTES)
        return 0;
    memset(&j, 0, sizeof j);
    root = fuzz_job_text(data, size);
    if (root != NULL) {
        rc = cli_job_parse(&j, root);
        FUZZ_CHECK(rc == CLI_OK || rc == CLI_USAGE, "cli_job_parse status");
        if (rc == CLI_OK) {
            FUZZ_CHECK(j.n >= 1 && j.n <= MAX_BLOCKS, "block count within the cap");
            validate(&j);
        }
    }
    free(j.blocks);
    cJSON_Delete(root);
    return 0;
}
