/* File names inside a job file (regions, motif SVGs, point files, outputs)
 * are relative to the job file, as a user writing one beside its SVGs
 * expects, and must stay inside its folder unless --allow-outside
 * (path_inside.c); shape specs and built-in motif names are left alone. */
#define _XOPEN_SOURCE 700 /* realpath */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "job.h"

static char *keep(cli_job_names *o, char *s)
{
    if (s != NULL && o->n == o->cap) {
        size_t cap = o->cap ? 2 * o->cap : 16;
        char **t = realloc(o->s, cap * sizeof *t);
        if (t == NULL) {
            free(s);
            return NULL;
        }
        o->s = t;
        o->cap = cap;
    }
    if (s != NULL)
        o->s[o->n++] = s;
    return s;
}

/* Built-in shapes are "name:size"; anything else the region loader would
 * open as a file (it also opens a name that exists), so it is one here. */
static int is_file_name(const char *s)
{
    size_t n = strlen(s);

    return (n > 4 && strcmp(s + n - 4, ".svg") == 0) || strchr(s, '/') != NULL ||
           strchr(s, ':') == NULL;
}

typedef struct names_ctx {
    cli_job_names *o;
    const char *dir;  /* the job's folder with its '/', or "" */
    char *root;       /* its resolved name; NULL with --allow-outside */
    int rc;           /* CLI_OK, or the status after one line */
} names_ctx;

/* dir + name for a relative file name, else name itself; checked inside the
 * job's folder. NULL after one line (c->rc says which error). */
static const char *beside(names_ctx *c, const char *name, const char *what)
{
    char *s;

    if (strcmp(name, "-") == 0)
        return name; /* stdout */
    if (c->dir[0] == '\0' || name[0] == '/') {
        s = NULL;
    } else {
        s = malloc(strlen(c->dir) + strlen(name) + 1);
        if (s == NULL || keep(c->o, s) == NULL) {
            cli_error("job: out of memory");
            c->rc = CLI_RUNTIME;
            return NULL;
        }
        sprintf(s, "%s%s", c->dir, name);
    }
    if (c->root != NULL &&
        (c->rc = cli_path_inside(c->root, name, s != NULL ? s : name, what)) != CLI_OK)
        return NULL;
    return s != NULL ? s : name;
}

/* A motif list with its .svg items made relative to dir, each checked. */
static const char *motifs_beside(names_ctx *c, const char *list, const char *what)
{
    size_t len = strlen(list), cap = len + 1, at = 0;
    const char *p = list;
    char *s, item[4096];

    for (; *p; p++)
        cap += *p == ',' ? strlen(c->dir) : 0;
    cap += strlen(c->dir);
    s = malloc(cap);
    if (s == NULL || keep(c->o, s) == NULL) {
        cli_error("job: out of memory");
        c->rc = CLI_RUNTIME;
        return NULL;
    }
    for (p = list; *p;) {
        size_t n = strcspn(p, ",");
        int file = n > 4 && strncmp(p + n - 4, ".svg", 4) == 0;
        if (file && c->root != NULL) {
            char *full = malloc(strlen(c->dir) + n + 1);
            if (full == NULL || n >= sizeof item) {
                free(full);
                cli_error("%s: motif name too long or out of memory", what);
                c->rc = CLI_USAGE;
                return NULL;
            }
            sprintf(item, "%.*s", (int)n, p);
            sprintf(full, "%s%s", p[0] == '/' ? "" : c->dir, item);
            c->rc = cli_path_inside(c->root, item, full, what);
            free(full);
            if (c->rc != CLI_OK)
                return NULL;
        }
        at += (size_t)sprintf(s + at, "%s%s%.*s", at ? "," : "",
                              file && p[0] != '/' ? c->dir : "", (int)n, p);
        p += n + (p[n] == ',');
    }
    return s;
}

/* A top's plan names motif files as its block does: beside the job. The
 * plan is the job's own parsed document, so its strings are rewritten in
 * place (checked for type later, by the plan's reader). */
static void plan_motifs_beside(names_ctx *c, const block *b)
{
    cJSON *rules = (cJSON *)b->plan, *r;
    char what[64];
    int k = 0;

    if (!cJSON_IsArray(rules))
        return;
    cJSON_ArrayForEach(r, rules) {
        cJSON *m = cJSON_GetObjectItemCaseSensitive(r, "motif");
        const char *s;

        snprintf(what, sizeof what, "job: %s.plan[%d].motif", b->where, k++);
        if (!cJSON_IsString(m))
            continue;
        if ((s = motifs_beside(c, m->valuestring, what)) == NULL)
            return;
        if (cJSON_SetValuestring(m, s) == NULL) {
            cli_error("%s: out of memory", what);
            c->rc = CLI_RUNTIME;
            return;
        }
    }
}

int cli_job_resolve_names(job *j, const char *file, int allow_outside, cli_job_names *o)
{
    const char *slash = strrchr(file, '/');
    char dir[4096], what[64];
    size_t i, points = (size_t)-1, nrows, k;
    const qc_param_info *t = qc_param_table(&nrows);
    names_ctx c;

    dir[0] = '\0';
    if (slash != NULL && (size_t)(slash - file) + 2 > sizeof dir) {
        cli_error("job: '%s': directory name too long", file);
        return CLI_USAGE;
    }
    if (slash != NULL) {
        memcpy(dir, file, (size_t)(slash - file) + 1);
        dir[slash - file + 1] = '\0';
    }
    c.o = o;
    c.dir = dir;
    c.rc = CLI_OK;
    c.root = NULL;
    if (!allow_outside && (c.root = realpath(dir[0] ? dir : ".", NULL)) == NULL) {
        cli_error("job: cannot resolve the folder of '%s'", file);
        return CLI_RUNTIME;
    }
    for (k = 0; k < nrows; k++)
        if (strcmp(t[k].name, "points") == 0)
            points = k;
    for (i = 0; i < j->n && c.rc == CLI_OK; i++) {
        block *b = &j->blocks[i];
        snprintf(what, sizeof what, "job: %s.region", b->where);
        if (b->pat.region != NULL && is_file_name(b->pat.region) &&
            (b->pat.region = beside(&c, b->pat.region, what)) == NULL)
            break;
        snprintf(what, sizeof what, "job: %s.top", b->where);
        if (b->top != NULL && (b->top = beside(&c, b->top, what)) == NULL)
            break;
        if (b->plan != NULL && (plan_motifs_beside(&c, b), c.rc != CLI_OK))
            break;
        snprintf(what, sizeof what, "job: %s.motif", b->where);
        if (b->pat.motifs != NULL && (b->pat.motifs = motifs_beside(&c, b->pat.motifs, what)) == NULL)
            break;
        snprintf(what, sizeof what, "job: %s.params.points", b->where);
        if (points != (size_t)-1 && b->pat.raw[points] != NULL &&
            qc_param_choice(&t[points], b->pat.raw[points]) < 0 &&
            (b->pat.raw[points] = beside(&c, b->pat.raw[points], what)) == NULL)
            break;
    }
    for (i = 0; i < j->nout && c.rc == CLI_OK; i++) {
        snprintf(what, sizeof what, "job: output[%lu]", (unsigned long)i);
        j->outputs[i] = beside(&c, j->outputs[i], what);
    }
    free(c.root);
    return c.rc;
}

void cli_job_names_free(cli_job_names *o)
{
    size_t i;

    for (i = 0; i < o->n; i++)
        free(o->s[i]);
    free(o->s);
    memset(o, 0, sizeof *o);
}
