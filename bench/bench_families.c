/* Every family through qc_generate, as the CLI and the page run it, on a
 * square block holding about 10^3 and 10^5 of its points at d = 10 mm: the
 * whole call and its decorate stage (the issues' targets: under 5 ms and
 * under 1 s), and the library's peak bytes per point. Echo and spiral have
 * no points: their block is the one that holds that many stipple points. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bench.h"

#define SPACING 10.0

/* Start of the decorate stage, through the context's trace hook. */
typedef struct stage_clock {
    double decorate_from, decorate;
    clock_t cpu_from, cpu; /* the same in CPU time (the 10^6 rows) */
} stage_clock;

static void on_stage(void *ud, const char *stage)
{
    stage_clock *c = ud;
    double now = bench_now();

    if (strcmp(stage, "decorate") == 0) {
        c->decorate_from = now;
        c->cpu_from = clock();
    } else if (strcmp(stage, "done") == 0 && c->decorate_from > 0) {
        c->decorate = now - c->decorate_from;
        c->cpu = clock() - c->cpu_from;
    }
}

/* Best of reps runs of qc_generate on a side x side block; *points, the
 * peak bytes and the decorate stage's best time through *deco, *peak. */
static double deco_cpu_last; /* the last run's decorate stage in CPU seconds */

static double time_generate(int family, double side, int reps, size_t *points, double *deco,
                            size_t *peak)
{
    char spec[64];
    qc_ctx ctx;
    qc_region region = {0};
    qc_params p;
    bench_meter m = {0, 0};
    stage_clock clk;
    double best = 1e30;
    int r;

    qc_ctx_init(&ctx, bench_meter_alloc, &m);
    snprintf(spec, sizeof spec, "rect:%.3fx%.3f", side, side);
    memset(&p, 0, sizeof p);
    qc_params_set(&ctx, &p, "family", family);
    qc_params_set(&ctx, &p, "spacing", SPACING);
    p.skip_gap_stat = 1; /* the gap is a measurement, not part of the pattern */
    ctx.trace = on_stage;
    ctx.trace_ud = &clk;
    *deco = 1e30;
    if (qc_region_shape(&ctx, spec, 1.0, &region) != QC_OK)
        reps = 0;
    for (r = 0; r < reps; r++) {
        qc_result res;
        double t0;

        memset(&clk, 0, sizeof clk);
        m.peak = m.live;
        t0 = bench_now();
        if (qc_generate(&ctx, &region, &p, NULL, NULL, &res) != QC_OK)
            break;
        best = fmin(best, bench_now() - t0);
        *deco = fmin(*deco, clk.decorate);
        deco_cpu_last = (double)clk.cpu / CLOCKS_PER_SEC;
        *points = res.stats.points;
        *peak = m.peak;
        qc_result_free(&ctx, &res);
    }
    if (r < reps || reps == 0)
        printf("%s: %s\n", qc_family_name(family), qc_errmsg(&ctx));
    qc_region_free(&ctx, &region);
    return best;
}

/* The block is sized by one trial run so the family's own points (Poisson
 * or its lattice) number about target; echo and spiral take stipple's. */
static void run(int family, size_t target, int reps)
{
    int sizer = family == QC_FAMILY_ECHO || family == QC_FAMILY_SPIRAL ? QC_FAMILY_STIPPLE
                                                                         : family;
    double side = sqrt((double)target) * SPACING, deco, t;
    size_t points = 0, peak = 0;

    time_generate(sizer, side, 1, &points, &deco, &peak);
    if (points > 0)
        side *= sqrt((double)target / (double)points);
    t = time_generate(family, side, reps, &points, &deco, &peak);
    printf("%-10s %6.0f mm block  points %7lu  generate %9.2f ms  decorate %9.2f ms  "
           "peak %7.1f B/pt\n",
           qc_family_name(family), side, (unsigned long)points, t * 1e3, deco * 1e3,
           (double)peak / (double)target);
}

/* 10^6 points (issue 21: <= 5 s, <= 1 KB per point), one run each on the
 * block the issue names, 10 m at d = 10 mm (10^6 cells of d^2; Poisson
 * sampling puts about 0.63 points in each, lattices 1 or more; echo and
 * spiral, which have none, are counted by those cells), with no sizing run (it would
 * double a minute-long section). Opt-in: `make bench BENCH_ONLY=families1m`;
 * BENCH_FAMILY=NAME runs that family only, BENCH_SIDE=MM on another block. The process's CPU time is
 * printed beside the wall time: on a shared machine it is the steadier. */
void bench_families_1m(void)
{
    const char *only = getenv("BENCH_FAMILY"), *side_mm = getenv("BENCH_SIDE");
    const double side = side_mm != NULL ? atof(side_mm) : 1000.0 * SPACING;
    int f;

    printf("families at 10^6: one run of qc_generate on a %.0f mm block (d = %g mm; goal "
           "<= 5000 ms, <= 1024 B/pt)\n",
           side, SPACING);
    for (f = QC_FAMILY_VINE; f < QC_FAMILY_COUNT; f++) {
        size_t points = 0, peak = 0;
        double deco = 0, t, cpu;
        clock_t c0;

        if (f == QC_FAMILY_MEANDER) /* bench_meander.c: the issue's own sizes */
            continue;
        if (only != NULL && strcmp(only, qc_family_name(f)) != 0)
            continue;
        c0 = clock();
        t = time_generate(f, side, 1, &points, &deco, &peak);
        cpu = (double)(clock() - c0) / CLOCKS_PER_SEC;
        if (peak == 0)
            continue; /* refused: time_generate said why */
        printf("%-10s points %7lu  generate %8.0f ms (cpu %6.0f)  decorate %8.0f ms (cpu %6.0f)"
               "  peak %6.0f B/pt\n",
               qc_family_name(f), (unsigned long)points, t * 1e3, cpu * 1e3, deco * 1e3,
               deco_cpu_last * 1e3,
               (double)peak / (points > 0 ? (double)points : side * side / (SPACING * SPACING)));
        fflush(stdout);
    }
}

void bench_families(void)
{
    static const size_t sizes[] = {1000, 100000};
    size_t k;
    int f;

    bench_families_1k();
    printf("families: best of a few runs of qc_generate (d = %g mm, largest-gap stat off)\n",
           SPACING);
    for (k = 0; k < sizeof sizes / sizeof *sizes; k++)
        for (f = QC_FAMILY_VINE; f < QC_FAMILY_COUNT; f++)
            if (f != QC_FAMILY_MEANDER) /* bench_meander.c: the issue's own sizes */
                run(f, sizes[k], sizes[k] > 10000 ? 2 : 10);
}
