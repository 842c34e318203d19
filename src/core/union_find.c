/* Union-find over 0..n-1 in one uint32_t array: path halving, and the
 * smaller root wins a union, so roots are deterministic (the lowest member
 * a set has gathered) and no rank array is needed. */
#include "internal.h"

void qc__uf_init(uint32_t *parent, size_t n)
{
    size_t i;

    for (i = 0; i < n; i++)
        parent[i] = (uint32_t)i;
}

uint32_t qc__uf_find(uint32_t *parent, uint32_t x)
{
    while (parent[x] != x) {
        parent[x] = parent[parent[x]];
        x = parent[x];
    }
    return x;
}

int qc__uf_union(uint32_t *parent, uint32_t a, uint32_t b)
{
    a = qc__uf_find(parent, a);
    b = qc__uf_find(parent, b);
    if (a == b)
        return 0;
    parent[a > b ? a : b] = a < b ? a : b;
    return 1;
}
