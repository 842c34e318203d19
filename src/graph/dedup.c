/* Exact duplicate detection by open addressing on the coordinates' bits:
 * O(n) and independent of the point order. */
#include <string.h>

#include "graph_delaunay.h"

static uint64_t bits(double v)
{
    uint64_t u;

    v += 0.0; /* -0 becomes +0 so both hash alike */
    memcpy(&u, &v, sizeof u);
    return u;
}

static uint64_t mix(uint64_t h)
{
    h ^= h >> 33;
    h *= 0xff51afd7ed558ccdu;
    h ^= h >> 33;
    h *= 0xc4ceb9fe1a85ec53u;
    h ^= h >> 33;
    return h;
}

int qc__find_duplicates(qc_ctx *ctx, const qc_vec2 *p, size_t n,
                        uint32_t *dup_of, size_t *ndup)
{
    size_t cap = 16, mask, i;
    uint32_t *slot;

    *ndup = 0;
    while (cap < 2 * n)
        cap *= 2;
    slot = qc__alloc_array(ctx, cap, sizeof *slot);
    if (slot == NULL)
        return qc__fail(ctx, QC_ENOMEM, "delaunay: duplicate table for %lu points",
                        (unsigned long)n);
    memset(slot, 0xff, cap * sizeof *slot);
    mask = cap - 1;
    for (i = 0; i < n; i++) {
        size_t h = (size_t)mix(bits(p[i].x) * 0x9e3779b97f4a7c15u ^ bits(p[i].y)) & mask;

        dup_of[i] = (uint32_t)i;
        for (;; h = (h + 1) & mask) {
            uint32_t j = slot[h];

            if (j == UINT32_MAX) {
                slot[h] = (uint32_t)i;
                break;
            }
            if (p[j].x == p[i].x && p[j].y == p[i].y) {
                dup_of[i] = j;
                (*ndup)++;
                break;
            }
        }
    }
    qc__free(ctx, slot, cap * sizeof *slot);
    return QC_OK;
}
