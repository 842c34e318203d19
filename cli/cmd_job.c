/*
 * quiltc job quilt.json: a whole quilt of blocks, each with its region,
 * place, rotation, family and parameters, generated and joined into one
 * file in serpentine row order, with a jump and tie-offs between blocks.
 *
 * {"units": "in", "tie": 3, "output": ["quilt.pat"],
 *  "blocks": [{"region": "rect:8x8", "at": [0, 0], "rotate": 0,
 *              "family": "stipple", "motif": "leaf", "params": {"spacing": 0.5}}]}
 */
#include <cjson/cJSON.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"

#define MAX_BLOCKS 1024
#define MAX_JOB_BYTES ((size_t)1 << 20)
#define VALUE_LEN 48
#define MAX_AT_MM 1e5 /* block corners: 100 m is beyond any quilt */

typedef struct block {
    cli_pattern_opts pat;
    char values[64][VALUE_LEN]; /* numbers from JSON, as option text */
    double at[2], rotate;
    char where[32];             /* "blocks[3]" for messages */
    char label[40];             /* "job: blocks[3]", for the parameters' messages */
    qc_path path;               /* in the quilt's frame */
    qc_vec2 lo;                 /* lower-left of its box, for ordering */
} block;

typedef struct job {
    const char *units;
    int tie;
    const char *outputs[16];
    size_t nout;
    block *blocks;
    size_t n;
} job;

static int bad(const char *where, const char *key, const char *what)
{
    cli_error("job: %s%s%s: %s", where, *key ? "." : "", key, what);
    return CLI_USAGE;
}

static int check_keys(const cJSON *obj, const char *where, const char *const *known)
{
    const cJSON *it;

    cJSON_ArrayForEach(it, obj) {
        size_t i;
        int ok = 0;
        for (i = 0; known[i] != NULL; i++)
            ok |= strcmp(it->string, known[i]) == 0;
        if (!ok)
            return bad(where, it->string, "unknown key");
    }
    return CLI_OK;
}

static int take_params(block *b, const cJSON *params)
{
    const cJSON *it;
    char key[96];
    size_t nrows;
    const qc_param_info *table = qc_param_table(&nrows);

    if (!cJSON_IsObject(params))
        return bad(b->where, "params", "expected an object");
    cJSON_ArrayForEach(it, params) {
        const qc_param_info *row = qc_param_find(it->string);
        size_t r;
        snprintf(key, sizeof key, "params.%s", it->string);
        if (row == NULL || strcmp(row->name, "family") == 0)
            return bad(b->where, key, "unknown parameter (see 'quiltc list params')");
        r = (size_t)(row - table);
        if (cJSON_IsNumber(it))
            snprintf(b->values[r], VALUE_LEN, "%.17g", it->valuedouble);
        else if (cJSON_IsString(it) && strlen(it->valuestring) < VALUE_LEN)
            strcpy(b->values[r], it->valuestring);
        else
            return bad(b->where, key, "expected a number or a short string");
        b->pat.raw[r] = b->values[r];
    }
    return CLI_OK;
}

static int take_block(const job *j, block *b, const cJSON *o)
{
    static const char *const known[] = {"region", "at", "rotate", "family", "motif", "params",
                                        NULL};
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

static int take_job(job *j, const cJSON *root)
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
            if (!cJSON_IsString(o) || j->nout == 16)
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

/* Generates block b in its own frame, then rotates it about its box's
 * lower-left corner and moves that corner to `at`. */
static int make_block(qc_ctx *ctx, block *b)
{
    qc_region region = {0};
    qc_points given = {0};
    qc_motif_set motifs = {0};
    qc_result res = {0};
    double mm, c, s;
    size_t i;
    int rc = cli_pattern_finish(ctx, &b->pat);

    if (rc == CLI_OK)
        rc = cli_pattern_load(ctx, &b->pat, &region, &given);
    if (rc == CLI_OK && b->pat.motifs != NULL)
        rc = cli_load_motifs(ctx, b->pat.motifs, &motifs);
    if (rc == CLI_OK && qc_generate(ctx, &region, &b->pat.params, &given,
                                    motifs.n ? &motifs : NULL, &res) < 0)
        rc = cli_fail(ctx, b->label, ctx->status);
    if (rc == CLI_OK) {
        mm = b->pat.mm_per_unit;
        c = qc_cos(b->rotate * QC_PI / 180);
        s = qc_sin(b->rotate * QC_PI / 180);
        for (i = 0; i < res.path.npt; i++) {
            qc_vec2 p = res.path.pt[i];
            res.path.pt[i].x = b->at[0] * mm + c * p.x - s * p.y;
            res.path.pt[i].y = b->at[1] * mm + s * p.x + c * p.y;
        }
        b->lo.x = b->at[0] * mm;
        b->lo.y = b->at[1] * mm;
        b->path = res.path; /* keep the path, free the rest */
        memset(&res.path, 0, sizeof res.path);
    }
    qc_result_free(ctx, &res);
    qc_motif_set_free(ctx, &motifs);
    qc_points_free(ctx, &given);
    qc_region_free(ctx, &region);
    return rc;
}

static int by_row_then_x(const void *pa, const void *pb)
{
    const block *a = *(const block *const *)pa, *b = *(const block *const *)pb;

    if (a->lo.y != b->lo.y)
        return a->lo.y < b->lo.y ? -1 : 1;
    return (a->lo.x > b->lo.x) - (a->lo.x < b->lo.x);
}

/* Serpentine rows: the bottom row left to right, the next right to left, ... */
static void sewing_order(block **order, size_t n)
{
    size_t i = 0, row = 0;

    qsort(order, n, sizeof *order, by_row_then_x);
    while (i < n) {
        size_t end = i;
        while (end < n && fabs(order[end]->lo.y - order[i]->lo.y) < 1.0)
            end++;
        if (row++ % 2 == 1) {
            size_t a = i, b = end - 1;
            for (; a < b; a++, b--) {
                block *t = order[a];
                order[a] = order[b];
                order[b] = t;
            }
        }
        i = end;
    }
}

/* One path, a piece per block; moved so nothing is negative (PAT needs that). */
static int join_blocks(qc_ctx *ctx, block **order, size_t n, qc_path *out)
{
    double minx = 0, miny = 0;
    size_t i;

    for (i = 0; i < n; i++)
        if (qc_path_append(ctx, out, &order[i]->path, 0) < 0)
            return cli_fail(ctx, "job", ctx->status);
    for (i = 0; i < out->npt; i++) {
        minx = fmin(minx, out->pt[i].x);
        miny = fmin(miny, out->pt[i].y);
    }
    for (i = 0; i < out->npt; i++) {
        out->pt[i].x -= minx;
        out->pt[i].y -= miny;
    }
    return CLI_OK;
}

static int run_job(qc_ctx *ctx, job *j, const char *const *outputs, size_t nout)
{
    block **order = calloc(j->n, sizeof *order);
    qc_path all = {0};
    qc_plan plan = {0};
    qc_stitch_params sp;
    qc_io_opts io;
    size_t i;
    int rc = order == NULL ? CLI_RUNTIME : CLI_OK;

    for (i = 0; i < j->n && rc == CLI_OK; i++) {
        order[i] = &j->blocks[i];
        rc = make_block(ctx, &j->blocks[i]);
    }
    if (rc == CLI_OK) {
        sewing_order(order, j->n);
        rc = join_blocks(ctx, order, j->n, &all);
    }
    memset(&sp, 0, sizeof sp);
    sp.tie_stitches = j->tie;
    if (rc == CLI_OK && qc_stitch_plan(ctx, &all, NULL, &sp, &plan) < 0)
        rc = cli_fail(ctx, "job", ctx->status);
    memset(&io, 0, sizeof io);
    io.svg_inches = strcmp(j->units, "in") == 0;
    for (i = 0; i < nout && rc == CLI_OK; i++) {
        int fmt = qc_format_from_name(outputs[i]);
        rc = fmt < 0 ? bad("output", outputs[i], "unknown format")
                     : cli_write_plan(ctx, outputs[i], fmt, &plan, &io);
    }
    qc_plan_free(ctx, &plan);
    qc_path_free(ctx, &all);
    free(order);
    return rc;
}

int cmd_job(int argc, char **argv)
{
    static const char *const fallback[] = {"quilt.pat"};
    const char *outputs[16];
    size_t nout = 0, i;
    const char *file = NULL;
    char *buf = NULL;
    size_t len;
    cJSON *root = NULL;
    job j;
    qc_ctx ctx;
    int rc = CLI_OK, a;

    for (a = 1; a < argc && rc == CLI_OK; a++) {
        if (strcmp(argv[a], "--help") == 0) {
            puts("usage: quiltc job QUILT.json [-o FILE]...\n"
                 "Generates every block of a quilt and joins them into one file (see README).");
            return CLI_OK;
        } else if (strcmp(argv[a], "-o") == 0 && a + 1 < argc && nout < 16)
            outputs[nout++] = argv[++a];
        else if (file == NULL && argv[a][0] != '-')
            file = argv[a];
        else {
            cli_bad_option("job", argv[a], '?');
            rc = CLI_USAGE;
        }
    }
    if (rc == CLI_OK && file == NULL) {
        cli_error("job: expected a QUILT.json file");
        rc = CLI_USAGE;
    }
    if (rc != CLI_OK)
        return rc;
    if (cli_read_file(file, MAX_JOB_BYTES, &buf, &len) != 0)
        return CLI_RUNTIME;
    memset(&j, 0, sizeof j);
    root = cJSON_ParseWithLength(buf, len);
    if (root == NULL) {
        const char *at = cJSON_GetErrorPtr();
        cli_error("job: %s: malformed JSON at byte %ld", file,
                  at != NULL ? (long)(at - buf) : -1L);
        rc = CLI_USAGE;
    } else
        rc = take_job(&j, root);
    if (rc == CLI_OK) {
        qc_ctx_init(&ctx, NULL, NULL);
        if (nout == 0)
            for (i = 0; i < j.nout; i++)
                outputs[nout++] = j.outputs[i];
        rc = run_job(&ctx, &j, nout ? outputs : fallback, nout ? nout : 1);
        for (i = 0; i < j.n; i++)
            qc_path_free(&ctx, &j.blocks[i].path);
    }
    free(j.blocks);
    cJSON_Delete(root);
    free(buf);
    return rc;
}
