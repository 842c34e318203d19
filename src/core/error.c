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
    /* one line, whatever the quoted input held; no C0, DEL or UTF-8 C1
     * control (U+0080..U+009F, such as U+009B, CSI) reaches a terminal */
    for (p = ctx->msg; *p != '\0'; p++) {
        unsigned char c = (unsigned char)*p, d = (unsigned char)p[1];
        if (c < 0x20 || c == 0x7f)
            *p = ' ';
        else if (c == 0xC2 && d >= 0x80 && d <= 0x9F)
            p[0] = p[1] = ' ';
    }
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
