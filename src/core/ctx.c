/* The context and allocation through the caller's hook. */
#include <string.h>

#include "internal.h"

const char *qc_version(void)
{
    return QC_VERSION_STRING;
}

#ifdef QC_NO_DEFAULT_ALLOC
/* Firmware without a libc heap: a NULL hook fails every allocation, and
 * nothing links against malloc. */
static void *no_alloc(void *ud, void *ptr, size_t old_size, size_t new_size)
{
    (void)ud;
    (void)ptr;
    (void)old_size;
    (void)new_size;
    return NULL;
}
#define DEFAULT_ALLOC no_alloc
#else
#define DEFAULT_ALLOC qc_default_alloc
#endif

void qc_ctx_init(qc_ctx *ctx, qc_alloc_fn alloc, void *alloc_ud)
{
    memset(ctx, 0, sizeof *ctx);
    ctx->alloc = alloc != NULL ? alloc : DEFAULT_ALLOC;
    ctx->alloc_ud = alloc_ud;
}

void *qc__realloc(qc_ctx *ctx, void *ptr, size_t old_size, size_t new_size)
{
    void *p;

    if (new_size == 0) {
        qc__free(ctx, ptr, old_size);
        return NULL;
    }
    p = ctx->alloc(ctx->alloc_ud, ptr, ptr != NULL ? old_size : 0, new_size);
    if (p == NULL)
        qc__fail(ctx, QC_ENOMEM, "out of memory allocating %lu bytes",
                 (unsigned long)new_size);
    return p;
}

void *qc__alloc(qc_ctx *ctx, size_t size)
{
    return size != 0 ? qc__realloc(ctx, NULL, 0, size) : NULL;
}

void qc__free(qc_ctx *ctx, void *ptr, size_t size)
{
    if (ptr != NULL)
        ctx->alloc(ctx->alloc_ud, ptr, size, 0);
}

void *qc__alloc_array(qc_ctx *ctx, size_t count, size_t elem)
{
    if (elem != 0 && count > (size_t)-1 / elem) {
        qc__fail(ctx, QC_ENOMEM, "allocation of %lu x %lu bytes overflows",
                 (unsigned long)count, (unsigned long)elem);
        return NULL;
    }
    return qc__alloc(ctx, count * elem);
}

int qc__reserve(qc_ctx *ctx, void **ptr, size_t *cap, size_t need, size_t elem)
{
    size_t ncap;
    void *p;

    if (need <= *cap)
        return QC_OK;
    ncap = *cap < 16 ? 16 : *cap;
    while (ncap < need) {
        if (ncap > (size_t)-1 / 2)
            return qc__fail(ctx, QC_ENOMEM, "array of %lu elements too large",
                            (unsigned long)need);
        ncap *= 2;
    }
    if (ncap > (size_t)-1 / elem)
        return qc__fail(ctx, QC_ENOMEM, "array of %lu elements too large",
                        (unsigned long)ncap);
    p = qc__realloc(ctx, *ptr, *cap * elem, ncap * elem);
    if (p == NULL)
        return QC_ENOMEM;
    *ptr = p;
    *cap = ncap;
    return QC_OK;
}
