/* Fields shared by job files and quilt plans (see json_fields.h). */
#include <stdio.h>
#include <string.h>

#include "json_fields.h"

int cli_json_bad(const char *prefix, const char *where, const char *key, const char *what)
{
    cli_error("%s%s%s%s: %s", prefix, where, *key ? "." : "", key, what);
    return CLI_USAGE;
}

int cli_json_check_keys(const char *prefix, const cJSON *obj, const char *where,
                        const char *const *known)
{
    const cJSON *it;

    cJSON_ArrayForEach(it, obj) {
        size_t i;
        int ok = 0;

        for (i = 0; known[i] != NULL; i++)
            ok |= strcmp(it->string, known[i]) == 0;
        if (!ok)
            return cli_json_bad(prefix, where, it->string, "unknown key");
    }
    return CLI_OK;
}

int cli_json_take_params(const char *prefix, const cJSON *params, const char *where,
                         char (*values)[CLI_JSON_VALUE_LEN], cli_pattern_opts *pat)
{
    const cJSON *it;
    char key[96];
    size_t nrows;
    const qc_param_info *table = qc_param_table(&nrows);

    if (!cJSON_IsObject(params))
        return cli_json_bad(prefix, where, "params", "expected an object");
    cJSON_ArrayForEach(it, params) {
        const qc_param_info *row = qc_param_find(it->string);
        size_t r;

        snprintf(key, sizeof key, "params.%s", it->string);
        if (row == NULL || strcmp(row->name, "family") == 0)
            return cli_json_bad(prefix, where, key, "unknown parameter (see 'quiltc list params')");
        r = (size_t)(row - table);
        if (cJSON_IsNumber(it))
            snprintf(values[r], CLI_JSON_VALUE_LEN, "%.17g", it->valuedouble);
        else if (cJSON_IsString(it) && strlen(it->valuestring) < CLI_JSON_VALUE_LEN)
            strcpy(values[r], it->valuestring);
        else
            return cli_json_bad(prefix, where, key, "expected a number or a short string");
        pat->raw[r] = values[r];
    }
    return CLI_OK;
}
