/*
 * Internals shared across the core's files: error reporting into the
 * context and allocation through the caller's hook. Not installed.
 */
#ifndef QC_INTERNAL_H
#define QC_INTERNAL_H

#include <stddef.h>

#include "quiltc.h"

#if defined(__GNUC__) && !defined(__EMSCRIPTEN__) && !defined(_WIN32)
#define QC__HIDDEN __attribute__((visibility("hidden")))
#define QC__PRINTF(f, a) __attribute__((format(printf, f, a)))
#else
#define QC__HIDDEN
#define QC__PRINTF(f, a)
#endif

/* Records status and a printf-style one-line message in ctx; returns status. */
QC__HIDDEN int qc__fail(qc_ctx *ctx, int status, const char *fmt, ...)
    QC__PRINTF(3, 4);

/* Allocation through ctx->alloc. qc__alloc(ctx, 0) returns NULL. */
QC__HIDDEN void *qc__alloc(qc_ctx *ctx, size_t size);
QC__HIDDEN void *qc__realloc(qc_ctx *ctx, void *ptr, size_t old_size,
                             size_t new_size);
QC__HIDDEN void qc__free(qc_ctx *ctx, void *ptr, size_t size);
/* count * elem bytes, or NULL (and QC_ENOMEM in ctx) on overflow or failure. */
QC__HIDDEN void *qc__alloc_array(qc_ctx *ctx, size_t count, size_t elem);

/*
 * Makes room for at least need elements of elem bytes in *ptr (capacity *cap,
 * in elements), growing geometrically. QC_OK, or QC_ENOMEM with *ptr intact.
 */
QC__HIDDEN int qc__reserve(qc_ctx *ctx, void **ptr, size_t *cap, size_t need,
                           size_t elem);

#define QC__RESERVE(ctx, arr, capv, need) \
    qc__reserve((ctx), (void **)&(arr), &(capv), (need), sizeof *(arr))

/* Squared distance from p to segment ab (a point when a == b); the one
 * formula every stage uses, so their answers agree to the bit. */
QC__HIDDEN double qc__seg_dist2(qc_vec2 p, qc_vec2 a, qc_vec2 b);

/* The bounding box of p[0..n), n >= 1. */
QC__HIDDEN qc_bbox qc__points_bbox(const qc_vec2 *p, size_t n);
/* cell, grown by half until a grid of that cell over box has at most
 * max_cells cells (bucket grids: about a constant number of items each). */
QC__HIDDEN double qc__fit_cell(qc_bbox box, double cell, double max_cells);

/* The families' descriptors, one per src/deco/family_NAME.c (QC_FAMILY_MAP). */
#define QC__FAMILY_DECL(id, name) QC__HIDDEN extern const qc_family_desc qc__family_##name;
QC_FAMILY_MAP(QC__FAMILY_DECL)
#undef QC__FAMILY_DECL
/* value checked against parameter id's row of the table (the one source of
 * each range): QC_OK, or qc_params_resolve's error and message. */
QC__HIDDEN int qc__param_check(qc_ctx *ctx, int id, double value);
/* The descriptor of family id (a qc_family), or NULL. */
QC__HIDDEN const qc_family_desc *qc__family(int id);

/* A point from its coordinates (a C99 compound literal). */
#define QC__V2(x, y) ((qc_vec2){(x), (y)})

/* Returns the status if it is an error. */
#define QC__TRY(expr)            \
    do {                         \
        int qc__rc_ = (expr);    \
        if (qc__rc_ < 0)         \
            return qc__rc_;      \
    } while (0)

#endif
