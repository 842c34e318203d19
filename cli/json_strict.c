/*
 * A job file's JSON, read strictly: cJSON keeps every member of an object,
 * so a key given twice is found by walking siblings and refused (readers
 * disagree on which one wins: cJSON's lookup takes the first, another
 * validator the last); text after the value is refused; nesting deeper than
 * cJSON's limit is named as such instead of as malformed JSON.
 */
#include <string.h>

#include "job.h"

/* The first object member, anywhere in v, whose key an earlier sibling has. */
static const cJSON *duplicate_key(const cJSON *v, int depth)
{
    const cJSON *a, *b, *d;

    if (depth > CJSON_NESTING_LIMIT)
        return NULL;
    for (a = v->child; a != NULL; a = a->next) {
        if (cJSON_IsObject(v))
            for (b = v->child; b != a; b = b->next)
                if (strcmp(a->string, b->string) == 0)
                    return a;
        if ((d = duplicate_key(a, depth + 1)) != NULL)
            return d;
    }
    return NULL;
}

/* Deepest [ or { nesting outside strings. */
static size_t nesting(const char *s, size_t len)
{
    size_t i, depth = 0, max = 0;
    int in_str = 0;

    for (i = 0; i < len; i++) {
        char c = s[i];
        if (in_str) {
            if (c == '\\')
                i++;
            else if (c == '"')
                in_str = 0;
        } else if (c == '"')
            in_str = 1;
        else if (c == '[' || c == '{')
            max = ++depth > max ? depth : max;
        else if ((c == ']' || c == '}') && depth > 0)
            depth--;
    }
    return max;
}

cJSON *cli_json_parse(const char *buf, size_t len, const char *file)
{
    const char *end = NULL;
    const cJSON *dup;
    cJSON *root;
    size_t i;

    if (nesting(buf, len) > CJSON_NESTING_LIMIT) {
        cli_error("job: %s: nested more than %d deep", file, CJSON_NESTING_LIMIT);
        return NULL;
    }
    root = cJSON_ParseWithLengthOpts(buf, len, &end, 0);
    if (root == NULL) {
        const char *at = cJSON_GetErrorPtr();
        cli_error("job: %s: malformed JSON at byte %ld", file,
                  at != NULL ? (long)(at - buf) : -1L);
        return NULL;
    }
    for (i = end != NULL ? (size_t)(end - buf) : len; i < len; i++)
        if (strchr(" \t\r\n", buf[i]) == NULL) {
            cli_error("job: %s: text after the JSON value at byte %lu", file, (unsigned long)i);
            cJSON_Delete(root);
            return NULL;
        }
    if ((dup = duplicate_key(root, 0)) != NULL) {
        cli_error("job: %s: key \"%s\" is given twice in one object", file, dup->string);
        cJSON_Delete(root);
        return NULL;
    }
    return root;
}
