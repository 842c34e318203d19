/* xoshiro256** seeded through splitmix64: fast, portable, same stream everywhere. */
#include "internal.h"

static uint64_t splitmix64(uint64_t *x)
{
    uint64_t z = (*x += UINT64_C(0x9E3779B97F4A7C15));
    z = (z ^ (z >> 30)) * UINT64_C(0xBF58476D1CE4E5B9);
    z = (z ^ (z >> 27)) * UINT64_C(0x94D049BB133111EB);
    return z ^ (z >> 31);
}

void qc_rng_seed(qc_rng *rng, uint64_t seed)
{
    int i;

    for (i = 0; i < 4; i++)
        rng->s[i] = splitmix64(&seed);
}

uint64_t qc_rng_u64(qc_rng *rng)
{
    return qc__rng_u64(rng);
}

double qc_rng_unit(qc_rng *rng)
{
    return qc__rng_unit(rng);
}

uint64_t qc_rng_below(qc_rng *rng, uint64_t n)
{
    uint64_t limit = (uint64_t)0 - ((uint64_t)0 - n) % n; /* multiple of n, or 0 for 2^64 */
    uint64_t r;

    do {
        r = qc__rng_u64(rng);
    } while (limit != 0 && r >= limit);
    return r % n;
}
