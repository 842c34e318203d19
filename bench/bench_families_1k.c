/* Every family at about 10^3 points (d = 10 mm), beside issue 21's goals:
 * qc_generate <= 5 ms (its figures off, as bench_families runs it), and the
 * whole `quiltc generate ... -o x.pat` <= 15 ms, here in process: generate,
 * the stitch plan and the .pat bytes (into memory), as the CLI runs it
 * (without the figures, which it measures only for --stats) and with the
 * figures on (largest gap, farthest fabric: `--stats`). Best of a few runs
 * per stage, the stages named by the context's trace hook, in CPU time (the
 * machine is shared: waiting for a core is not the library's time). The process
 * adds its start and the file (about 1 ms): `quiltc generate --stats`
 * prints its own stage split. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "bench.h"

#define SPACING 10.0
#define TARGET 1000
#define REPS 15
#define GOAL_GENERATE_MS 5.0
#define GOAL_PROCESS_MS 15.0

enum { ST_SAMPLE, ST_GRAPH, ST_TOUR, ST_DECORATE, ST_MEASURE, ST_PLAN, ST_WRITE, ST_COUNT };
static const char *const stage_name[ST_COUNT] = {"sample",  "graph", "tour", "decorate",
                                                 "measure", "plan",  "write"};

/* One run's stage clock: the trace hook closes the running stage and opens
 * the named one. */
typedef struct stage_run {
    double ms[ST_COUNT];
    int open;
    double from;
} stage_run;

static void stage_to(stage_run *s, int next)
{
    double now = bench_cpu();

    if (s->open >= 0)
        s->ms[s->open] += (now - s->from) * 1e3;
    s->open = next;
    s->from = now;
}

static void on_trace(void *ud, const char *stage)
{
    int k;

    for (k = 0; k < ST_COUNT; k++)
        if (strcmp(stage, stage_name[k]) == 0)
            break;
    stage_to(ud, k < ST_COUNT ? k : -1); /* "done" closes the last */
}

static int count_bytes(void *ud, const void *data, size_t len)
{
    (void)data;
    *(size_t *)ud += len;
    return 0;
}

/* One run: generate (figures on or off), and for the process-like run the
 * plan and the .pat. Total ms, or a negative status. */
static double one_run(qc_ctx *ctx, const qc_region *region, const qc_params *p, int process,
                      stage_run *s, size_t *points)
{
    qc_result res;
    qc_plan plan = {0};
    size_t bytes = 0;
    double t0;
    int rc;

    memset(s, 0, sizeof *s);
    s->open = -1;
    ctx->trace = on_trace;
    ctx->trace_ud = s;
    t0 = bench_cpu();
    rc = qc_generate(ctx, region, p, NULL, NULL, &res);
    stage_to(s, -1);
    if (rc != QC_OK)
        return rc;
    *points = res.stats.points;
    if (process) {
        stage_to(s, ST_PLAN);
        rc = qc_stitch_plan(ctx, &res.path, region, NULL, &plan);
        stage_to(s, ST_WRITE);
        if (rc == QC_OK)
            rc = qc_io_write(ctx, QC_FORMAT_PAT, &plan, NULL, count_bytes, &bytes);
        stage_to(s, -1);
        qc_plan_free(ctx, &plan);
    }
    t0 = bench_cpu() - t0;
    qc_result_free(ctx, &res);
    ctx->trace = NULL;
    return rc == QC_OK ? t0 * 1e3 : rc;
}

/* Best of REPS: the total and each stage's own best. */
static double best_of(qc_ctx *ctx, const qc_region *region, const qc_params *p, int process,
                      double *stage_ms, size_t *points)
{
    double best = HUGE_VAL;
    int r, k;

    for (k = 0; k < ST_COUNT; k++)
        stage_ms[k] = HUGE_VAL;
    for (r = 0; r < REPS; r++) {
        stage_run s;
        double t = one_run(ctx, region, p, process, &s, points);
        if (t < 0)
            return t;
        best = fmin(best, t);
        for (k = 0; k < ST_COUNT; k++)
            stage_ms[k] = fmin(stage_ms[k], s.ms[k]);
    }
    return best;
}

static const char *verdict(double ms, double goal)
{
    return ms <= goal ? "met" : "over";
}

static void print_split(const double *ms)
{
    int k;

    for (k = 0; k < ST_COUNT; k++)
        if (ms[k] > 0.0)
            printf(" %s %.2f", stage_name[k], ms[k]);
    printf("\n");
}

/* The side of the square block holding about TARGET of the family's points
 * (echo, spiral and meander have none: stipple's block). */
static double block_side(qc_ctx *ctx, int family)
{
    int sizer = family == QC_FAMILY_ECHO || family == QC_FAMILY_SPIRAL ||
                        family == QC_FAMILY_MEANDER
                    ? QC_FAMILY_STIPPLE
                    : family;
    double side = sqrt((double)TARGET) * SPACING;
    char spec[64];
    qc_region region = {0};
    qc_params p;
    qc_result res;

    snprintf(spec, sizeof spec, "rect:%.3fx%.3f", side, side);
    memset(&p, 0, sizeof p);
    qc_params_set(ctx, &p, "family", sizer);
    qc_params_set(ctx, &p, "spacing", SPACING);
    p.skip_gap_stat = 1;
    if (qc_region_shape(ctx, spec, 1.0, &region) == QC_OK &&
        qc_generate(ctx, &region, &p, NULL, NULL, &res) == QC_OK) {
        if (res.stats.points > 0)
            side *= sqrt((double)TARGET / (double)res.stats.points);
        qc_result_free(ctx, &res);
    }
    qc_region_free(ctx, &region);
    return side;
}

static void run_family(int family)
{
    qc_ctx ctx;
    qc_region region = {0};
    qc_params p;
    char spec[64];
    double gen_ms[ST_COUNT], plain_ms[ST_COUNT], proc_ms[ST_COUNT], gen, plain, proc, side;
    size_t points = 0;

    qc_ctx_init(&ctx, NULL, NULL);
    side = block_side(&ctx, family);
    snprintf(spec, sizeof spec, "rect:%.3fx%.3f", side, side);
    memset(&p, 0, sizeof p);
    qc_params_set(&ctx, &p, "family", family);
    qc_params_set(&ctx, &p, "spacing", SPACING);
    if (qc_region_shape(&ctx, spec, 1.0, &region) != QC_OK) {
        printf("%-10s %s\n", qc_family_name(family), qc_errmsg(&ctx));
        return;
    }
    p.skip_gap_stat = 1;
    gen = best_of(&ctx, &region, &p, 0, gen_ms, &points);
    plain = gen < 0 ? gen : best_of(&ctx, &region, &p, 1, plain_ms, &points);
    p.skip_gap_stat = 0;
    proc = plain < 0 ? plain : best_of(&ctx, &region, &p, 1, proc_ms, &points);
    if (gen < 0 || plain < 0 || proc < 0) {
        printf("%-10s %s\n", qc_family_name(family), qc_errmsg(&ctx));
    } else {
        printf("%-10s %4.0f mm %5lu pts  generate %6.2f ms (goal %.0f: %s)  process-like "
               "%6.2f ms, with --stats figures %6.2f ms (goal %.0f: %s, %s)\n",
               qc_family_name(family), side, (unsigned long)points, gen, GOAL_GENERATE_MS,
               verdict(gen, GOAL_GENERATE_MS), plain, proc, GOAL_PROCESS_MS,
               verdict(plain, GOAL_PROCESS_MS), verdict(proc, GOAL_PROCESS_MS));
        printf("           generate:       ");
        print_split(gen_ms);
        printf("           process:        ");
        print_split(plain_ms);
        printf("           process --stats:");
        print_split(proc_ms);
    }
    qc_region_free(&ctx, &region);
}

void bench_families_1k(void)
{
    int f;

    printf("families at 10^3 points (d = %g mm), best of %d, CPU ms; process-like = generate "
           "+ plan + .pat in memory (as quiltc generate), and with the --stats figures\n",
           SPACING, REPS);
    for (f = QC_FAMILY_VINE; f < QC_FAMILY_COUNT; f++)
        run_family(f);
}
