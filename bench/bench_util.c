/* Clock, memory and point-set helpers for the benches. */
#include <math.h>
#include <stdlib.h>
#include <sys/resource.h>
#include <time.h>

#include "bench.h"

double bench_now(void)
{
    struct timespec ts;

    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

double bench_cpu(void)
{
    struct timespec ts;

    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

void *bench_meter_alloc(void *ud, void *ptr, size_t old_size, size_t new_size)
{
    bench_meter *m = ud;

    if (new_size == 0) {
        free(ptr);
        m->live -= old_size;
        return NULL;
    }
    ptr = realloc(ptr, new_size);
    if (ptr != NULL) {
        m->live = m->live - old_size + new_size;
        if (m->live > m->peak)
            m->peak = m->live;
    }
    return ptr;
}

size_t bench_peak_rss(void)
{
    struct rusage ru;

    if (getrusage(RUSAGE_SELF, &ru) != 0)
        return 0;
    return (size_t)ru.ru_maxrss * 1024; /* kilobytes on Linux */
}

qc_vec2 *bench_uniform(size_t n, double side, uint64_t seed)
{
    qc_vec2 *p = malloc((n ? n : 1) * sizeof *p);
    qc_rng r;
    size_t i;

    if (p == NULL)
        return NULL;
    qc_rng_seed(&r, seed);
    for (i = 0; i < n; i++) {
        p[i].x = qc_rng_unit(&r) * side;
        p[i].y = qc_rng_unit(&r) * side;
    }
    return p;
}

qc_vec2 *bench_hex(size_t n, size_t *got)
{
    /* a honeycomb keeps 2 of every 3 triangular-lattice points */
    size_t w = (size_t)ceil(sqrt(1.5 * (double)n)), i, j, k = 0;
    qc_vec2 *p = malloc(w * w * sizeof *p);

    if (p == NULL)
        return NULL;
    for (j = 0; j < w && k < n; j++)
        for (i = 0; i < w && k < n; i++) {
            if ((i + 2 * (j & 1)) % 3 == 2)
                continue;
            p[k].x = (double)i + 0.5 * (double)(j & 1);
            p[k].y = (double)j * sqrt(3.0) / 2;
            k++;
        }
    *got = k;
    return p;
}
