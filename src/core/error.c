/* Status codes and the context's last-error message. */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "internal.h"

const char *qc_strerror(int status)
{
    switch (status) {
#define QC__ERR_TEXT(name, value, text) \
    case QC_##name:                     \
        return text;
        QC_ERRNO_MAP(QC__ERR_TEXT)
#undef QC__ERR_TEXT
    }
    return "unknown error";
}

const char *qc_err_name(int status)
{
    switch (status) {
#define QC__ERR_NAME(name, value, text) \
    case QC_##name:                     \
        return #name;
        QC_ERRNO_MAP(QC__ERR_NAME)
#undef QC__ERR_NAME
    }
    return "EUNKNOWN";
}

int qc__fail(qc_ctx *ctx, int status, const char *fmt, ...)
{
    va_list ap;
    char *p;

    if (ctx == NULL)
        return status;
    ctx->status = status;
    va_start(ap, fmt);
    vsnprintf(ctx->msg, sizeof ctx->msg, fmt, ap);
    va_end(ap);
    /* one line, whatever the quoted input held */
    for (p = ctx->msg; *p != '\0'; p++)
        if ((unsigned char)*p < 0x20 || *p == 0x7f)
            *p = ' ';
    return status;
}

const char *qc_errmsg(const qc_ctx *ctx)
{
    return ctx != NULL ? ctx->msg : "";
}

void qc_clear_error(qc_ctx *ctx)
{
    ctx->status = QC_OK;
    ctx->msg[0] = '\0';
}
