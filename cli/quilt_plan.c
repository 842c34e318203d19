/* Reading a quilt plan: rules, their match and their parameters, named when wrong. */
#include <stdlib.h>
#include <string.h>

#include "quilt_plan.h"

static int bad(const char *where, const char *key, const char *what)
{
    return cli_json_bad("", where, key, what);
}

static int check_keys(const cJSON *obj, const char *where, const char *const *known)
{
    return cli_json_check_keys("", obj, where, known);
}

static int take_match(plan_rule *r, const cJSON *m)
{
    static const char *const known[] = {"id", "class", "label", "fill", NULL};
    const char *const *k;
    char where[96];
    int rc;

    snprintf(where, sizeof where, "%s.match", r->where);
    if (!cJSON_IsObject(m) || cJSON_GetArraySize(m) == 0)
        return bad(r->where, "match", "expected an object with id, class, label or fill");
    if ((rc = check_keys(m, where, known)) != CLI_OK)
        return rc;
    for (k = known; *k != NULL; k++) {
        const cJSON *v = cJSON_GetObjectItemCaseSensitive(m, *k);

        if (v == NULL)
            continue;
        if (!cJSON_IsString(v))
            return bad(where, *k, "expected a string");
        if (strcmp(*k, "id") == 0)
            r->match.id = v->valuestring;
        else if (strcmp(*k, "class") == 0)
            r->match.cls = v->valuestring;
        else if (strcmp(*k, "label") == 0)
            r->match.label = v->valuestring;
        else if (!qc_color_parse(v->valuestring, &r->match.fill)) {
            cli_error("%s.fill: '%s' is not a colour (#rgb, #rrggbb, rgb(r, g, b) or a name "
                      "such as navy)", where, v->valuestring);
            return CLI_USAGE;
        } else
            r->match.has_fill = 1;
    }
    r->has_match = 1;
    return CLI_OK;
}

static int take_params(plan_rule *r, const cJSON *params)
{
    return cli_json_take_params("", params, r->where, r->values, &r->pat);
}

static int take_rule(plan_rule *r, const cJSON *o)
{
    static const char *const known[] = {"match", "family", "motif", "params", NULL};
    const cJSON *v;
    size_t nrows, fam = (size_t)(qc_param_find("family") - qc_param_table(&nrows));
    int rc;

    if (!cJSON_IsObject(o))
        return bad(r->where, "", "expected an object");
    if ((rc = check_keys(o, r->where, known)) != CLI_OK)
        return rc;
    if ((v = cJSON_GetObjectItemCaseSensitive(o, "match")) != NULL &&
        (rc = take_match(r, v)) != CLI_OK)
        return rc;
    if ((v = cJSON_GetObjectItemCaseSensitive(o, "family")) != NULL) {
        if (!cJSON_IsString(v) || strlen(v->valuestring) >= PLAN_VALUE_LEN)
            return bad(r->where, "family", "expected a family name or \"none\"");
        if (strcmp(v->valuestring, "none") == 0)
            r->none = 1;
        else {
            strcpy(r->values[fam], v->valuestring);
            r->pat.raw[fam] = r->values[fam];
        }
    }
    if ((v = cJSON_GetObjectItemCaseSensitive(o, "motif")) != NULL) {
        if (!cJSON_IsString(v))
            return bad(r->where, "motif", "expected a comma-separated list");
        r->pat.motifs = v->valuestring;
    }
    if ((v = cJSON_GetObjectItemCaseSensitive(o, "params")) != NULL)
        return take_params(r, v);
    return CLI_OK;
}

int cli_quilt_plan_parse(quilt_plan *p, const cJSON *root, const cli_pattern_opts *base,
                         const char *prefix)
{
    size_t i;
    int rc;

    memset(p, 0, sizeof *p);
    if (!cJSON_IsArray(root) || cJSON_GetArraySize(root) < 1 ||
        cJSON_GetArraySize(root) > MAX_PLAN_RULES)
        return bad(prefix, "", "expected a list of 1 to 256 rules");
    p->n = (size_t)cJSON_GetArraySize(root);
    p->rule = calloc(p->n, sizeof *p->rule);
    if (p->rule == NULL) {
        p->n = 0;
        return bad("plan", "", "out of memory");
    }
    for (i = 0; i < p->n; i++) {
        plan_rule *r = &p->rule[i];

        r->pat = *base;
        snprintf(r->where, sizeof r->where, "%s[%lu]", prefix, (unsigned long)i);
        r->pat.where = r->where;
        if ((rc = take_rule(r, cJSON_GetArrayItem(root, (int)i))) != CLI_OK)
            return rc;
    }
    return CLI_OK;
}

void cli_quilt_plan_free(qc_ctx *ctx, quilt_plan *p)
{
    size_t i;

    for (i = 0; i < p->n; i++)
        qc_motif_set_free(ctx, &p->rule[i].motifs);
    free(p->rule);
    cJSON_Delete(p->doc);
    memset(p, 0, sizeof *p);
}

plan_rule *cli_quilt_plan_match(quilt_plan *p, const qc_patch *patch)
{
    size_t i;

    for (i = 0; i < p->n; i++) {
        if (qc_patch_matches(&p->rule[i].match, patch))
            return &p->rule[i];
    }
    return NULL;
}
