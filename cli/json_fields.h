/*
 * The JSON object fields that jobs and quilt plans share: one error line
 * naming where and the key, unknown keys refused, and a "params" object
 * taken as option text for cli_pattern_opts.
 */
#ifndef CLI_JSON_FIELDS_H
#define CLI_JSON_FIELDS_H

#include <cjson/cJSON.h>

#include "cli.h"

#define CLI_JSON_VALUE_LEN 48 /* a parameter's value as option text */

/* "PREFIXWHERE.KEY: WHAT" (no ".KEY" when key is empty); returns CLI_USAGE. */
int cli_json_bad(const char *prefix, const char *where, const char *key, const char *what);
/* CLI_OK when every key of obj is in known (NULL-terminated), else the
 * first unknown one named. */
int cli_json_check_keys(const char *prefix, const cJSON *obj, const char *where,
                        const char *const *known);
/* Takes params (an object of table parameters, numbers or short strings)
 * into values[row] and pat->raw[row]; "family" and unknown names refused. */
int cli_json_take_params(const char *prefix, const cJSON *params, const char *where,
                         char (*values)[CLI_JSON_VALUE_LEN], cli_pattern_opts *pat);

#endif
