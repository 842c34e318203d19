/* The context and allocation through the caller's hook. */
#include <string.h>

#include "internal.h"

const char *qc_version(void)
{
    return QC_VERSION_STRING;
}

int qc_version_number(void)
{
    return QC_VERSION_NUMBER;
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

/* A refused context's allocator: every later call fails with QC_ENOMEM
 * rather than touching a struct of another layout. */
static void *refused_alloc(void *ud, void *ptr, size_t old_size, size_t new_size)
{
    (void)ud;
    (void)ptr;
    (void)old_size;
    (void)new_size;
    return NULL;
}

/* Same ABI: the major version, and before 1.0 the minor too (the soname's rule). */
static int same_abi(int header_version)
{
    int major = header_version / 10000, minor = header_version / 100 % 100;

    if (header_version < 0 || major != QC_VERSION_MAJOR)
        return 0;
    return QC_VERSION_MAJOR != 0 || minor == QC_VERSION_MINOR;
}

int qc_ctx_init_(qc_ctx *ctx, qc_alloc_fn alloc, void *alloc_ud, int header_version,
                 size_t ctx_size)
{
    if (ctx == NULL)
        return QC_EINVAL;
    if (same_abi(header_version) && ctx_size == sizeof *ctx) {
        memset(ctx, 0, sizeof *ctx);
        ctx->alloc = alloc != NULL ? alloc : DEFAULT_ALLOC;
        ctx->alloc_ud = alloc_ud;
        return QC_OK;
    }
    if (ctx_size < sizeof *ctx)
        return QC_EVERSION; /* the caller's struct is too small to write into */
    memset(ctx, 0, sizeof *ctx);
    ctx->alloc = refused_alloc;
    return qc__fail(ctx, QC_EVERSION,
                    "quiltc header %d.%d.%d (qc_ctx %lu bytes) does not match the library "
                    "%s (qc_ctx %lu bytes): rebuild against the installed headers",
                    header_version / 10000, header_version / 100 % 100, header_version % 100,
                    (unsigned long)ctx_size, QC_VERSION_STRING, (unsigned long)sizeof *ctx);
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

int qc__reserve_exact(qc_ctx *ctx, void **ptr, size_t *cap, size_t need, size_t elem)
{
    void *p;

    if (need <= *cap)
        return QC_OK;
    if (need > (size_t)-1 / elem)
        return qc__fail(ctx, QC_ENOMEM, "array of %lu elements too large",
                        (unsigned long)need);
    p = qc__realloc(ctx, *ptr, *cap * elem, need * elem);
    if (p == NULL)
        return QC_ENOMEM;
    *ptr = p;
    *cap = need;
    return QC_OK;
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
