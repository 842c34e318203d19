/* Stable LSD radix sort on 64-bit keys (8- or 11-bit digits): the graph stage
 * sorts up to ~3n edges and n Hilbert keys, the tour stage n Hilbert keys
 * and its candidate edges, where qsort is several times slower
 * (notes/performance.md). */
#include <string.h>

#include "internal.h"

/* Short arrays take 8-bit digits with the counts on the stack (no 16 KiB
 * of counts for a few hundred keys); long ones 11-bit digits, one pass in
 * three fewer. Both are the same stable sort. */
#define SMALL_N 65536u
#define SMALL_BITS 8u
#define LARGE_BITS 11u

int qc__radix_sort(qc_ctx *ctx, uint64_t *key, uint32_t *val, size_t n,
                   unsigned shift)
{
    uint64_t *k2;
    uint32_t *v2 = NULL;
    size_t small[(size_t)1 << SMALL_BITS], *count = small;
    unsigned bits = n < SMALL_N ? SMALL_BITS : LARGE_BITS, s;
    size_t digits = (size_t)1 << bits, mask = digits - 1;
    int in_tmp = 0;

    if (n < 2)
        return QC_OK;
    k2 = qc__alloc_array(ctx, n, sizeof *k2);
    if (k2 != NULL && bits != SMALL_BITS)
        count = qc__alloc_array(ctx, digits, sizeof *count);
    if (val != NULL && k2 != NULL && count != NULL)
        v2 = qc__alloc_array(ctx, n, sizeof *v2);
    if (k2 == NULL || count == NULL || (val != NULL && v2 == NULL)) {
        qc__free(ctx, k2, n * sizeof *k2);
        if (count != small)
            qc__free(ctx, count, digits * sizeof *count);
        return qc__fail(ctx, QC_ENOMEM, "radix sort of %lu keys: out of memory",
                        (unsigned long)n);
    }
    for (s = shift; s < 64; s += bits) {
        uint64_t *ks = in_tmp ? k2 : key, *kd = in_tmp ? key : k2;
        uint32_t *vs = in_tmp ? v2 : val, *vd = in_tmp ? val : v2;
        size_t i, sum = 0;

        memset(count, 0, digits * sizeof *count);
        for (i = 0; i < n; i++)
            count[(ks[i] >> s) & mask]++;
        if (count[(ks[0] >> s) & mask] == n)
            continue; /* this digit is the same everywhere */
        for (i = 0; i < digits; i++) {
            size_t c = count[i];
            count[i] = sum;
            sum += c;
        }
        if (val != NULL) {
            for (i = 0; i < n; i++) {
                size_t d = count[(ks[i] >> s) & mask]++;
                kd[d] = ks[i];
                vd[d] = vs[i];
            }
        } else {
            for (i = 0; i < n; i++)
                kd[count[(ks[i] >> s) & mask]++] = ks[i];
        }
        in_tmp = !in_tmp;
    }
    if (in_tmp) {
        memcpy(key, k2, n * sizeof *key);
        if (val != NULL)
            memcpy(val, v2, n * sizeof *val);
    }
    qc__free(ctx, k2, n * sizeof *k2);
    qc__free(ctx, v2, val != NULL ? n * sizeof *v2 : 0);
    if (count != small)
        qc__free(ctx, count, digits * sizeof *count);
    return QC_OK;
}
