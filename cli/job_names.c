/* File names inside a job file (regions, motif SVGs, point files, outputs)
 * are relative to the job file, as a user writing one beside its SVGs
 * expects; shape specs and built-in motif names are left alone. */
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

static int is_file_name(const char *s)
{
    size_t n = strlen(s);

    return (n > 4 && strcmp(s + n - 4, ".svg") == 0) || strchr(s, '/') != NULL ||
           (strchr(s, ':') == NULL && strchr(s, '.') != NULL);
}

/* dir + name for a relative file name, else name itself; NULL if out of memory. */
static const char *beside(cli_job_names *o, const char *dir, const char *name)
{
    char *s;

    if (dir[0] == '\0' || name[0] == '/' || !is_file_name(name))
        return name;
    s = malloc(strlen(dir) + strlen(name) + 1);
    if (s != NULL)
        sprintf(s, "%s%s", dir, name);
    return keep(o, s);
}

/* A motif list with its .svg items made relative to dir. */
static const char *motifs_beside(cli_job_names *o, const char *dir, const char *list)
{
    size_t len = strlen(list), cap = len + 1, at = 0;
    const char *p = list;
    char *s;

    if (dir[0] == '\0')
        return list;
    for (; *p; p++)
        cap += *p == ',' ? strlen(dir) : 0;
    cap += strlen(dir);
    s = malloc(cap);
    if (s == NULL)
        return NULL;
    for (p = list; *p;) {
        size_t n = strcspn(p, ",");
        int file = n > 4 && strncmp(p + n - 4, ".svg", 4) == 0 && p[0] != '/';
        at += (size_t)sprintf(s + at, "%s%s%.*s", at ? "," : "", file ? dir : "", (int)n, p);
        p += n + (p[n] == ',');
    }
    return keep(o, s);
}

int cli_job_resolve_names(job *j, const char *file, cli_job_names *o)
{
    const char *slash = strrchr(file, '/');
    char dir[4096];
    size_t i, points = (size_t)-1, nrows, k;
    const qc_param_info *t = qc_param_table(&nrows);

    if (slash == NULL)
        return CLI_OK;
    if ((size_t)(slash - file) + 2 > sizeof dir) {
        cli_error("job: '%s': directory name too long", file);
        return CLI_USAGE;
    }
    memcpy(dir, file, (size_t)(slash - file) + 1);
    dir[slash - file + 1] = '\0';
    for (k = 0; k < nrows; k++)
        if (strcmp(t[k].name, "points") == 0)
            points = k;
    for (i = 0; i < j->n; i++) {
        block *b = &j->blocks[i];
        if (b->pat.region != NULL && (b->pat.region = beside(o, dir, b->pat.region)) == NULL)
            goto oom;
        if (b->top != NULL && (b->top = beside(o, dir, b->top)) == NULL)
            goto oom;
        if (b->pat.motifs != NULL &&
            (b->pat.motifs = motifs_beside(o, dir, b->pat.motifs)) == NULL)
            goto oom;
        if (points != (size_t)-1 && b->pat.raw[points] != NULL &&
            qc_param_choice(&t[points], b->pat.raw[points]) < 0 &&
            (b->pat.raw[points] = beside(o, dir, b->pat.raw[points])) == NULL)
            goto oom;
    }
    for (i = 0; i < j->nout; i++)
        if ((j->outputs[i] = beside(o, dir, j->outputs[i])) == NULL)
            goto oom;
    return CLI_OK;
oom:
    cli_error("job: out of memory");
    return CLI_RUNTIME;
}

void cli_job_names_free(cli_job_names *o)
{
    size_t i;

    for (i = 0; i < o->n; i++)
        free(o->s[i]);
    free(o->s);
    memset(o, 0, sizeof *o);
}
