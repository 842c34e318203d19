/*
 * Shared by the fuzz targets (tests/fuzz/fuzz_*.c): a context over the
 * counting test allocator with a byte budget (so a hostile input that asks
 * for gigabytes gets QC_ENOMEM instead of killing the fuzzer), invariant
 * checks that abort with a message (a finding), sinks for the writers, and
 * a little reader that turns the fuzzer's bytes into choices.
 *
 * Each target defines LLVMFuzzerTestOneInput; built with
 * -fsanitize=fuzzer it runs under libFuzzer (make fuzz), built with
 * tests/fuzz/replay_main.c it replays files (tests/check_fuzz_regress.sh).
 */
#ifndef QC_FUZZ_COMMON_H
#define QC_FUZZ_COMMON_H

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "quiltc.h"
#include "testalloc.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define FUZZ_BUDGET ((size_t)512 << 20) /* live bytes one input may hold */

typedef struct fuzz_alloc {
    testalloc t;
    size_t budget;
} fuzz_alloc;

static inline void *fuzz_alloc_fn(void *ud, void *ptr, size_t old_size, size_t new_size)
{
    fuzz_alloc *a = ud;

    if (new_size > old_size && new_size - old_size > a->budget - a->t.live_bytes &&
        new_size != 0)
        return NULL;
    return testalloc_fn(&a->t, ptr, old_size, new_size);
}

/* A finding: print what broke and abort, so libFuzzer keeps the input. */
#define FUZZ_CHECK(cond, what)                                                      \
    do {                                                                            \
        if (!(cond)) {                                                              \
            fprintf(stderr, "fuzz invariant broken: %s (%s) at %s:%d\n", what, #cond, \
                    __FILE__, __LINE__);                                            \
            abort();                                                                \
        }                                                                           \
    } while (0)

static inline void fuzz_ctx_init(qc_ctx *ctx, fuzz_alloc *a)
{
    memset(a, 0, sizeof *a);
    a->budget = FUZZ_BUDGET;
    qc_ctx_init(ctx, fuzz_alloc_fn, a);
}

/*
 * QC_FUZZ_KNOWN="key,key": step around open findings already reported
 * (keys named where they are checked), so a long run goes on exploring.
 * Unset (the default, and in the replay), every check is on.
 */
static inline int fuzz_known(const char *key)
{
    const char *k = getenv("QC_FUZZ_KNOWN");

    return k != NULL && strstr(k, key) != NULL;
}

/* After a call: a status in range, a one-line message on failure. */
static inline void fuzz_check_status(const qc_ctx *ctx, int rc, const char *what)
{
    FUZZ_CHECK(rc <= 0 && rc > QC__ERR_LAST, what);
    if (rc < 0) {
        const char *m = qc_errmsg(ctx);
        FUZZ_CHECK(m[0] != '\0', "an error without a message");
        FUZZ_CHECK(strchr(m, '\n') == NULL && strchr(m, '\r') == NULL,
                   "an error message of more than one line");
    }
}

/* Everything freed, no wrong sizes passed to the allocator. */
static inline void fuzz_check_clean(const fuzz_alloc *a, const char *what)
{
    FUZZ_CHECK(a->t.size_mismatch == 0, what);
    FUZZ_CHECK(a->t.live_blocks == 0 && a->t.live_bytes == 0, what);
}

static inline int fuzz_all_zero(const void *p, size_t n)
{
    const unsigned char *c = p;
    size_t i;

    for (i = 0; i < n; i++)
        if (c[i] != 0)
            return 0;
    return 1;
}

/* An exact-size copy, so a read past len is an ASan report. */
static inline char *fuzz_copy(const uint8_t *data, size_t size)
{
    char *b = malloc(size ? size : 1);

    if (b != NULL && size)
        memcpy(b, data, size);
    return b;
}

/* A writer's sink that keeps the bytes, to read them back. */
typedef struct fuzz_grow {
    char *b;
    size_t n, cap;
} fuzz_grow;

static inline int fuzz_grow_fn(void *ud, const void *data, size_t len)
{
    fuzz_grow *g = ud;

    if (g->n + len > g->cap) {
        size_t cap = (g->n + len) * 2;
        char *nb = realloc(g->b, cap);
        if (nb == NULL)
            return -1;
        g->b = nb;
        g->cap = cap;
    }
    memcpy(g->b + g->n, data, len);
    g->n += len;
    return 0;
}

/* Writers' sinks: count bytes; fail after `fail_after` calls when non-zero. */
typedef struct fuzz_sink {
    size_t bytes, calls, fail_after;
} fuzz_sink;

static inline int fuzz_sink_fn(void *ud, const void *data, size_t len)
{
    fuzz_sink *s = ud;

    FUZZ_CHECK(data != NULL || len == 0, "writer passed NULL data");
    s->calls++;
    if (s->fail_after != 0 && s->calls >= s->fail_after)
        return -1;
    s->bytes += len;
    return 0;
}

/* The fuzzer's bytes as a stream of choices; past the end everything is 0. */
typedef struct fuzz_in {
    const uint8_t *p;
    size_t n, at;
} fuzz_in;

static inline unsigned fuzz_u8(fuzz_in *in)
{
    return in->at < in->n ? in->p[in->at++] : 0u;
}

static inline unsigned fuzz_u16(fuzz_in *in)
{
    unsigned a = fuzz_u8(in);
    return a | fuzz_u8(in) << 8;
}

static inline uint64_t fuzz_u64(fuzz_in *in)
{
    uint64_t v = 0;
    int i;

    for (i = 0; i < 8; i++)
        v |= (uint64_t)fuzz_u8(in) << (8 * i);
    return v;
}

static inline double fuzz_f64_bits(fuzz_in *in)
{
    uint64_t u = fuzz_u64(in);
    double d;

    memcpy(&d, &u, sizeof d);
    return d;
}

/* lo + (hi - lo) * t for a 16-bit t. */
static inline double fuzz_range(fuzz_in *in, double lo, double hi)
{
    return lo + (hi - lo) * (double)fuzz_u16(in) / 65535.0;
}

/* A hostile number: NaN, infinities, zero, negatives, huge, tiny, raw bits. */
static inline double fuzz_hostile(fuzz_in *in, double lo, double hi)
{
    switch (fuzz_u8(in) % 12) {
    case 0: return (double)NAN;
    case 1: return (double)INFINITY;
    case 2: return -(double)INFINITY;
    case 3: return 0.0;
    case 4: return -1.0;
    case 5: return 1e308;
    case 6: return -1e308;
    case 7: return 4.9e-324;
    case 8: return lo - (hi - lo) * 0.5 - 1e-9;
    case 9: return hi * 2.0 + 1.0;
    case 10: return nextafter(lo, -(double)INFINITY);
    default: return fuzz_f64_bits(in);
    }
}

#endif
