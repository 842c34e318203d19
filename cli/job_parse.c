/* Reading a quilt job file: keys, types and ranges, named when wrong. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "job.h"

static int bad(const char *where, const char *key, const char *what)
{
    return cli_json_bad("job: ", where, key, what);
}

static int check_keys(const cJSON *obj, const char *where, const char *const *known)
{
    return cli_json_check_keys("job: ", obj, where, known);
}

static int take_params(block *b, const cJSON *params)
{
    return cli_json_take_params("job: ", params, b->where, b->values, &b->pat);
}

static int take_block(const job *j, block *b, const cJSON *o)
{
    static const char *const known[] = {"region", "at", "rotate", "family", "motif", "params",
                                        "top", "plan", NULL};
    const cJSON *v;
    size_t nrows;
    double mm;
    int rc;

    cli_pattern_init(&b->pat);
    b->pat.units = j->units;
    snprintf(b->label, sizeof b->label, "job: %s", b->where);
    b->pat.where = b->label;
    if (!cJSON_IsObject(o))
        return bad(b->where, "", "expected an object");
    if ((rc = check_keys(o, b->where, known)) != CLI_OK)
        return rc;
    if ((v = cJSON_GetObjectItemCaseSensitive(o, "region")) != NULL) {
        if (!cJSON_IsString(v))
            return bad(b->where, "region", "expected a shape or an SVG file name");
        b->pat.region = v->valuestring;
    }
    if ((v = cJSON_GetObjectItemCaseSensitive(o, "top")) != NULL) {
        if (!cJSON_IsString(v))
            return bad(b->where, "top", "expected an SVG file name");
        if (cJSON_GetObjectItemCaseSensitive(o, "region") != NULL)
            return bad(b->where, "top", "a block has a region or a top, not both");
        b->top = v->valuestring;
    }
    if ((v = cJSON_GetObjectItemCaseSensitive(o, "plan")) != NULL) {
        if (b->top == NULL)
            return bad(b->where, "plan", "a plan needs a \"top\"");
        b->plan = v;
    }
    if ((v = cJSON_GetObjectItemCaseSensitive(o, "at")) != NULL) {
        if (!cJSON_IsArray(v) || cJSON_GetArraySize(v) != 2 ||
            !cJSON_IsNumber(cJSON_GetArrayItem(v, 0)) || !cJSON_IsNumber(cJSON_GetArrayItem(v, 1)))
            return bad(b->where, "at", "expected [x, y]");
        b->at[0] = cJSON_GetArrayItem(v, 0)->valuedouble;
        b->at[1] = cJSON_GetArrayItem(v, 1)->valuedouble;
        mm = cli_units_mm(j->units);
        if (!(fabs(b->at[0]) * mm <= MAX_AT_MM && fabs(b->at[1]) * mm <= MAX_AT_MM))
            return bad(b->where, "at", "expected [x, y] within 100000 mm of 0");
    }
    if ((v = cJSON_GetObjectItemCaseSensitive(o, "rotate")) != NULL) {
        if (!cJSON_IsNumber(v) || !(fabs(v->valuedouble) <= 360))
            return bad(b->where, "rotate", "expected degrees in [-360, 360]");
        b->rotate = v->valuedouble;
    }
    if ((v = cJSON_GetObjectItemCaseSensitive(o, "motif")) != NULL) {
        if (!cJSON_IsString(v))
            return bad(b->where, "motif", "expected a comma-separated list");
        b->pat.motifs = v->valuestring;
    }
    if ((v = cJSON_GetObjectItemCaseSensitive(o, "family")) != NULL) {
        size_t r = (size_t)(qc_param_find("family") - qc_param_table(&nrows));
        if (!cJSON_IsString(v) || strlen(v->valuestring) >= VALUE_LEN)
            return bad(b->where, "family", "expected a family name");
        strcpy(b->values[r], v->valuestring);
        b->pat.raw[r] = b->values[r];
    }
    if ((v = cJSON_GetObjectItemCaseSensitive(o, "params")) != NULL)
        return take_params(b, v);
    return CLI_OK;
}

int cli_job_parse(job *j, const cJSON *root)
{
    static const char *const known[] = {"units", "tie", "output", "blocks", NULL};
    const cJSON *v, *blocks;
    size_t i;
    int rc;

    if (!cJSON_IsObject(root))
        return bad("top level", "", "expected an object");
    if ((rc = check_keys(root, "top level", known)) != CLI_OK)
        return rc;
    j->units = "in";
    j->tie = 3;
    if ((v = cJSON_GetObjectItemCaseSensitive(root, "units")) != NULL) {
        if (!cJSON_IsString(v) || cli_units_mm(v->valuestring) == 0)
            return bad("top level", "units", "expected \"in\", \"mm\" or \"cm\"");
        j->units = v->valuestring;
    }
    if ((v = cJSON_GetObjectItemCaseSensitive(root, "tie")) != NULL) {
        if (!cJSON_IsNumber(v) || v->valuedouble < 0 || v->valuedouble > 100 ||
            v->valuedouble != floor(v->valuedouble))
            return bad("top level", "tie", "expected a count from 0 to 100");
        j->tie = (int)v->valuedouble;
    }
    if ((v = cJSON_GetObjectItemCaseSensitive(root, "output")) != NULL) {
        const cJSON *o;
        if (!cJSON_IsArray(v))
            return bad("top level", "output", "expected a list of file names");
        cJSON_ArrayForEach(o, v) {
            if (!cJSON_IsString(o) || j->nout == MAX_JOB_OUTPUTS)
                return bad("top level", "output", "expected at most 16 file names");
            j->outputs[j->nout++] = o->valuestring;
        }
    }
    blocks = cJSON_GetObjectItemCaseSensitive(root, "blocks");
    if (!cJSON_IsArray(blocks) || cJSON_GetArraySize(blocks) < 1 ||
        cJSON_GetArraySize(blocks) > MAX_BLOCKS)
        return bad("top level", "blocks", "expected a list of 1 to 1024 blocks");
    j->n = (size_t)cJSON_GetArraySize(blocks);
    j->blocks = calloc(j->n, sizeof *j->blocks);
    if (j->blocks == NULL)
        return bad("top level", "blocks", "out of memory");
    for (i = 0; i < j->n; i++) {
        snprintf(j->blocks[i].where, sizeof j->blocks[i].where, "blocks[%lu]", (unsigned long)i);
        if ((rc = take_block(j, &j->blocks[i], cJSON_GetArrayItem(blocks, (int)i))) != CLI_OK)
            return rc;
    }
    return CLI_OK;
}
