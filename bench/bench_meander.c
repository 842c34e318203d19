/* Meander (issue 17's speed goals): an 8 x 8 in block at d = 0.4 in
 * (goal 100 ms) and a 100 x 100 in top at d = 0.3 in (goal 3 s), through
 * qc_generate with the largest-gap stat off, wall and CPU time (the
 * machine is shared); peak bytes per mm of thread show the memory is
 * linear. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "bench.h"

static void run(double side_in, double d_in, int reps)
{
    char spec[64];
    qc_ctx ctx;
    qc_region region = {0};
    qc_params p;
    bench_meter m = {0, 0};
    double best = 1e30, cpu = 1e30, len = 0;
    int r;

    qc_ctx_init(&ctx, bench_meter_alloc, &m);
    snprintf(spec, sizeof spec, "rect:%gx%g", side_in, side_in);
    memset(&p, 0, sizeof p);
    qc_params_set(&ctx, &p, "family", QC_FAMILY_MEANDER);
    qc_params_set(&ctx, &p, "spacing", d_in * 25.4);
    p.skip_gap_stat = 1;
    if (qc_region_shape(&ctx, spec, 25.4, &region) != QC_OK)
        reps = 0;
    for (r = 0; r < reps; r++) {
        qc_result res;
        double t0;
        clock_t c0;

        m.peak = m.live;
        t0 = bench_now();
        c0 = clock();
        if (qc_generate(&ctx, &region, &p, NULL, NULL, &res) != QC_OK)
            break;
        best = fmin(best, bench_now() - t0);
        cpu = fmin(cpu, (double)(clock() - c0) / CLOCKS_PER_SEC);
        len = res.stats.length_mm;
        qc_result_free(&ctx, &res);
    }
    if (r < reps || reps == 0)
        printf("meander: %s\n", qc_errmsg(&ctx));
    else
        printf("meander %5g x %-5g in at d %.2f in: %9.1f ms (cpu %9.1f ms), thread %8.0f mm, "
               "peak %6.1f B/mm\n",
               side_in, side_in, d_in, best * 1e3, cpu * 1e3, len, (double)m.peak / len);
    qc_region_free(&ctx, &region);
}

void bench_meander(void)
{
    printf("meander: best of a few runs of qc_generate (largest-gap stat off)\n");
    run(8, 0.4, 5);
    run(25, 0.3, 1);
    run(100, 0.3, 1);
}
