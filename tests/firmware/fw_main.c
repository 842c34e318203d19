/*
 * A firmware-style program over the Cortex-M core library: no malloc, only a
 * static arena handed to qc_ctx_init. It generates one pattern, plans its
 * stitches and writes the PAT to stdout (semihosting under qemu-arm), so
 * tests/check_firmware.sh can compare the bytes with the native CLI's. The
 * arena's peak use goes to stderr.
 *
 * argv: FAMILY SPACING_MM SEED (a rect:100x100 mm block, 3 tie stitches).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "quiltc.h"

#define ARENA_BYTES (2u << 20)

/* A bump arena: blocks carry their size; freeing or growing the newest
 * block reuses its space, anything else is simply not reclaimed. */
typedef struct arena {
    unsigned char *mem;
    size_t used, peak, cap, last; /* last: offset of the newest block */
} arena;

static void *arena_alloc(void *ud, void *ptr, size_t old_size, size_t new_size)
{
    arena *a = ud;
    unsigned char *p = ptr;
    size_t need = (new_size + 15u) & ~(size_t)15u;

    if (p != NULL && p == a->mem + a->last) { /* the newest block: in place */
        if (new_size == 0) {
            a->used = a->last;
            return NULL;
        }
        if (need > a->cap - a->last)
            return NULL;
        a->used = a->last + need;
    } else {
        if (new_size == 0)
            return NULL;
        if (need > a->cap - a->used)
            return NULL;
        a->last = a->used;
        a->used += need;
        if (p != NULL)
            memcpy(a->mem + a->last, p, old_size < new_size ? old_size : new_size);
        p = a->mem + a->last;
    }
    if (a->used > a->peak)
        a->peak = a->used;
    return p;
}

static int to_stdout(void *ud, const void *data, size_t len)
{
    (void)ud;
    return fwrite(data, 1, len, stdout) == len ? 0 : -1;
}

int main(int argc, char **argv)
{
    static unsigned char mem[ARENA_BYTES] __attribute__((aligned(16)));
    arena a = {mem, 0, 0, ARENA_BYTES, 0};
    qc_ctx ctx;
    qc_region region = {0};
    qc_params p;
    qc_result res = {0};
    qc_plan plan = {0};
    qc_stitch_params sp;
    int family;

    if (argc != 4) {
        fputs("usage: fw FAMILY SPACING_MM SEED\n", stderr);
        return 2;
    }
    qc_ctx_init(&ctx, arena_alloc, &a);
    memset(&p, 0, sizeof p);
    memset(&sp, 0, sizeof sp);
    sp.tie_stitches = 3;
    family = qc_param_choice(qc_param_find("family"), argv[1]);
    qc_params_set(&ctx, &p, "seed", 0.0); /* marks the seed given */
    p.seed = strtoul(argv[3], NULL, 10);
    if (qc_params_set(&ctx, &p, "family", family) < 0 ||
        qc_params_set(&ctx, &p, "spacing", atof(argv[2])) < 0 ||
        qc_region_shape(&ctx, "rect:100x100", 1.0, &region) < 0 ||
        qc_generate(&ctx, &region, &p, NULL, NULL, &res) < 0 ||
        qc_stitch_plan(&ctx, &res.path, NULL, &sp, &plan) < 0 ||
        qc_io_write(&ctx, QC_FORMAT_PAT, &plan, NULL, to_stdout, NULL) < 0) {
        fprintf(stderr, "fw: %s\n", qc_errmsg(&ctx));
        return 1;
    }
    fflush(stdout);
    fprintf(stderr, "fw: %lu stitch points, arena peak %lu bytes\n", (unsigned long)plan.n,
            (unsigned long)a.peak);
    qc_plan_free(&ctx, &plan);
    qc_result_free(&ctx, &res);
    qc_region_free(&ctx, &region);
    return 0;
}
