/* JSON answers and the binding's own messages (see qcw_internal.h). */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qcw_internal.h"

/* A message of the binding's own (the library's are set by qc__fail). */
int qcw__fail(qcw_job *job, int status, const char *fmt, const char *arg)
{
    snprintf(job->ctx.msg, sizeof job->ctx.msg, fmt, arg);
    job->ctx.status = status;
    return status;
}

/* ---- JSON text over a growing heap string ---- */


static int grow(qcw_text *t, size_t need)
{
    size_t cap;
    char *s;

    if (t->failed)
        return -1;
    if (t->n + need < t->cap)
        return 0;
    cap = (t->cap ? t->cap * 2 : 1024) + need;
    s = realloc(t->s, cap);
    if (s == NULL) {
        t->failed = 1;
        return -1;
    }
    t->s = s;
    t->cap = cap;
    return 0;
}

void qcw__add(qcw_text *t, const char *fmt, ...)
{
    va_list ap;
    int k;

    va_start(ap, fmt);
    k = vsnprintf(NULL, 0, fmt, ap);
    va_end(ap);
    if (k < 0) {
        t->failed = 1;
        return;
    }
    if (grow(t, (size_t)k + 1) != 0)
        return;
    va_start(ap, fmt);
    vsnprintf(t->s + t->n, t->cap - t->n, fmt, ap);
    va_end(ap);
    t->n += (size_t)k;
}

/* A JSON string literal. */
void qcw__add_str(qcw_text *t, const char *s)
{
    qcw__add(t, "\"");
    for (; s != NULL && *s != '\0'; s++) {
        unsigned char c = (unsigned char)*s;

        if (c == '"' || c == '\\')
            qcw__add(t, "\\%c", c);
        else if (c < 0x20)
            qcw__add(t, "\\u%04x", c);
        else
            qcw__add(t, "%c", c);
    }
    qcw__add(t, "\"");
}

const char *qcw__finish_json(qcw_job *job, qcw_text *t)
{
    free(job->json);
    job->json = NULL;
    if (t->failed || t->s == NULL)
        free(t->s);
    else
        job->json = t->s;
    return job->json != NULL ? job->json : "null";
}
