/* Shared helpers of quiltc-bench (bench/main.c calls each stage's bench). */
#ifndef QC_BENCH_H
#define QC_BENCH_H

#include <stddef.h>

#include "quiltc.h"

void bench_graph(void);
void bench_lattice(void);
void bench_tour(void);
/* The TSPLIB part of bench_tour alone (issue 21's table). */
void bench_tsplib(void);
void bench_pebbling(void);
void bench_families(void);
/* Every family at 10^3 points beside issue 21's 5 ms / 15 ms goals (bench_families_1k.c). */
void bench_families_1k(void);
void bench_families_1m(void); /* opt-in: slow */
void bench_meander(void);
void bench_quilt(void);

/* An allocator hook (qc_ctx_init) that counts the library's live and peak bytes. */
typedef struct bench_meter {
    size_t live, peak;
} bench_meter;
void *bench_meter_alloc(void *ud, void *ptr, size_t old_size, size_t new_size);

/* Monotonic seconds. */
double bench_now(void);
/* CPU seconds of the process (what a shared machine's load disturbs least). */
double bench_cpu(void);
/* Peak resident set of the process so far, bytes. */
size_t bench_peak_rss(void);
/* n uniform points in [0, side)^2 from seed (malloc'ed; NULL on failure). */
qc_vec2 *bench_uniform(size_t n, double side, uint64_t seed);
/* About n points of a hexagonal (honeycomb) lattice of unit spacing
 * (malloc'ed); *got receives the count. */
qc_vec2 *bench_hex(size_t n, size_t *got);

#endif
