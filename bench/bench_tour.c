/* TSP timings and quality: uniform points 10^3..10^6 against the MST weight
 * (a lower bound) and 0.7124 sqrt(n A) (the asymptotic optimum), the
 * perturbation rate, and the gap to the proven optimum of each TSPLIB
 * instance found in ../shared/data/tsplib/ (also alone: the tsplib section). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"

#define TSPLIB_DIR "../shared/data/tsplib/"
#define KICKS 20000

/* Best time of reps runs of one method, by clock; the tour's length in *len. */
static double time_tsp(qc_ctx *ctx, const qc_vec2 *p, size_t n, int method, uint64_t kicks,
                       int reps, double *len, double (*measure)(const qc_vec2 *, const uint32_t *,
                                                                size_t),
                       double (*clock)(void))
{
    double best = 1e30;
    int r;

    for (r = 0; r < reps; r++) {
        qc_tsp_params tp;
        qc_order o = {0};
        double t0;

        memset(&tp, 0, sizeof tp);
        tp.method = method;
        tp.perturb_iterations = kicks;
        tp.seed = 1;
        t0 = clock();
        if (qc_tsp(ctx, p, n, &tp, &o) != QC_OK) {
            printf("tsp: %s\n", qc_errmsg(ctx));
            return -1;
        }
        best = fmin(best, clock() - t0);
        *len = measure(p, o.i, o.n);
        qc_order_free(ctx, &o);
    }
    return best;
}

static double euclid_length(const qc_vec2 *p, const uint32_t *t, size_t n)
{
    return qc_tour_length(p, t, n, 1);
}

/* TSPLIB's length: each edge nint(Euclidean distance). */
static double tsplib_length(const qc_vec2 *p, const uint32_t *t, size_t n)
{
    double len = 0;
    size_t i;

    for (i = 0; i < n; i++) {
        qc_vec2 a = p[t[i]], b = p[t[(i + 1) % n]];
        len += floor(sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y)) + 0.5);
    }
    return len;
}

/* CPU seconds of one run; the tour's TSPLIB length in *len. */
static double cpu_tsp(qc_ctx *ctx, const qc_vec2 *p, size_t n, int method, uint64_t kicks,
                      double *len)
{
    return time_tsp(ctx, p, n, method, kicks, 1, len, tsplib_length, bench_cpu);
}

static void uniform(size_t n, int reps, int all_methods)
{
    static const char *const names[] = {"greedy", "+2-opt", "+Or-opt", "default"};
    qc_vec2 *p = bench_uniform(n, 1000.0, 7 + n);
    bench_meter m = {0, 0};
    qc_edges e = {0};
    qc_ctx ctx;
    double w = 0, bhh = 0.7124 * sqrt((double)n * 1e6), len, t;
    size_t i;
    int k;

    if (p == NULL)
        return;
    qc_ctx_init(&ctx, bench_meter_alloc, &m);
    if (qc_mst(&ctx, p, n, QC_MST_MODE_DELAUNAY, &e) == QC_OK)
        for (i = 0; i < e.n; i++)
            w += qc_hypot(p[e.e[i].a].x - p[e.e[i].b].x, p[e.e[i].a].y - p[e.e[i].b].y);
    qc_edges_free(&ctx, &e);
    for (k = all_methods ? 0 : 2; k < 4; k++) {
        m.peak = 0;
        t = time_tsp(&ctx, p, n, QC_TSP_METHOD_GREEDY + k, 0, reps, &len, euclid_length, bench_now);
        if (t < 0)
            break;
        printf("uniform n=%-8lu %-8s %9.2f ms  tour/MST %.4f  tour/(0.7124 sqrt(nA)) %.4f"
               "  lib peak %5.1f B/pt\n",
               (unsigned long)n, names[k], t * 1e3, len / w, len / bhh,
               (double)m.peak / (double)n);
    }
    if (n <= 100000) { /* the budget's round rate (QC_TSP_ROUNDS_PER_MS) */
        double t0 = time_tsp(&ctx, p, n, QC_TSP_METHOD_DEFAULT, 0, 1, &len, euclid_length,
                             bench_now);
        double len1, t1 = time_tsp(&ctx, p, n, QC_TSP_METHOD_DEFAULT, KICKS, 1, &len1,
                                   euclid_length, bench_now);
        printf("uniform n=%-8lu +%d kicks %7.2f ms (%.0f rounds/ms)  tour/(0.7124 sqrt(nA)) "
               "%.4f\n",
               (unsigned long)n, KICKS, (t1 - t0) * 1e3, KICKS / ((t1 - t0) * 1e3), len1 / bhh);
    }
    free(p);
}

static char *slurp(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    char *buf = NULL;
    long n;

    if (f == NULL)
        return NULL;
    if (fseek(f, 0, SEEK_END) == 0 && (n = ftell(f)) >= 0 && fseek(f, 0, SEEK_SET) == 0) {
        buf = malloc((size_t)n + 1);
        if (buf != NULL && fread(buf, 1, (size_t)n, f) != (size_t)n) {
            free(buf);
            buf = NULL;
        }
        *len = (size_t)n;
    }
    fclose(f);
    return buf;
}

/* Issue 21's table: per TSPLIB instance, the old default (Or-opt), the
 * default (Or-3opt and its kicks) and the default with a 1000 ms budget
 * (qc_tsp_rounds_for_ms: a round count, not a clock) up to 2000 points. */
void bench_tsplib(void)
{
    size_t len;
    char *list = slurp(TSPLIB_DIR "optima.txt", &len), *line, *save = NULL;
    double sum[3] = {0, 0, 0}, tsum[3] = {0, 0, 0}, fl1577 = -1, small = 0;
    double at1s = 0, at10s = 0;
    int count = 0, nbudget = 0, nlong = 0;
    uint64_t budget = qc_tsp_rounds_for_ms(1000.0), budget10 = qc_tsp_rounds_for_ms(10000.0);

    if (list == NULL) {
        printf("tour: no %soptima.txt, TSPLIB skipped\n", TSPLIB_DIR);
        return;
    }
    list[len] = '\0';
    printf("tsplib: %% above the proven optimum (nint lengths), CPU time of each run (best of 5 "
           "alternating runs up to 5000 points, else 3); +1000 ms = %llu more rounds, up to 2000 points\n",
           (unsigned long long)budget);
    for (line = strtok_r(list, "\n", &save); line != NULL; line = strtok_r(NULL, "\n", &save)) {
        char name[64], path[256];
        double opt, gap[3] = {0, 0, 0}, t[3] = {0, 0, 0}, l;
        qc_points pts = {0};
        qc_ctx ctx;
        char *buf;
        size_t n;
        int k, r, reps;

        if (sscanf(line, "%63s : %lf", name, &opt) != 2)
            continue;
        snprintf(path, sizeof path, TSPLIB_DIR "%s.tsp", name);
        buf = slurp(path, &n);
        if (buf == NULL)
            continue;
        qc_ctx_init(&ctx, NULL, NULL);
        if (qc_io_read_points(&ctx, buf, n, &pts) != QC_OK) {
            printf("%s: %s\n", name, qc_errmsg(&ctx));
            free(buf);
            continue;
        }
        free(buf);
        /* the two methods alternate, best CPU time of each: the machine's
         * load disturbs a ratio least that way */
        reps = pts.n <= 5000 ? 5 : 3;
        t[0] = t[1] = 1e30;
        for (r = 0; r < reps; r++)
            for (k = 0; k < 2; k++)
                t[k] = fmin(t[k], cpu_tsp(&ctx, pts.v, pts.n,
                                          k == 0 ? QC_TSP_METHOD_OROPT : QC_TSP_METHOD_DEFAULT, 0,
                                          &gap[k]));
        if (pts.n <= 2000)
            t[2] = cpu_tsp(&ctx, pts.v, pts.n, QC_TSP_METHOD_DEFAULT, budget, &gap[2]);
        for (k = 0; k < 3; k++) {
            gap[k] = 100 * (gap[k] / opt - 1);
            sum[k] += pts.n <= 2000 || k < 2 ? gap[k] : 0;
            tsum[k] += t[k];
        }
        count++;
        if (pts.n <= 2000) {
            nbudget++;
            small += gap[1];
        }
        if (strcmp(name, "fl1577") == 0)
            fl1577 = gap[1];
        printf("%-9s n=%-6lu Or-opt %5.2f%% %7.2f ms  default %5.2f%% %7.2f ms (%.1fx)", name,
               (unsigned long)pts.n, gap[0], t[0] * 1e3, gap[1], t[1] * 1e3, t[1] / t[0]);
        if (pts.n <= 2000)
            printf("  +1000 ms %5.2f%% %7.1f ms", gap[2], t[2] * 1e3);
        if (strcmp(name, "d1291") == 0 || strcmp(name, "pcb1173") == 0 ||
            strcmp(name, "pr1002") == 0) { /* the slowest to converge: 10 s */
            double t10 = cpu_tsp(&ctx, pts.v, pts.n, QC_TSP_METHOD_DEFAULT, budget10, &l);
            printf("  +10 s %5.2f%% %7.1f ms", 100 * (l / opt - 1), t10 * 1e3);
            at1s += gap[2];
            at10s += 100 * (l / opt - 1);
            nlong++;
        }
        printf("\n");
        qc_points_free(&ctx, &pts);
    }
    if (count > 0) /* issue 21's goals */
        printf("tsplib mean of %d: Or-opt %.2f%% %.1f ms, default %.2f%% (goal <= 2%%) %.1f ms "
               "(%.2fx, goal <= 3x), fl1577 %.2f%% (goal <= 5%%)\n",
               count, sum[0] / count, tsum[0] * 1e3, sum[1] / count, tsum[1] * 1e3,
               tsum[1] / tsum[0], fl1577);
    if (nbudget > 0)
        printf("tsplib mean of the %d up to 2000 points: default %.2f%%, +1000 ms %.2f%% "
               "(goal <= 0.2%%)\n",
               nbudget, small / nbudget, sum[2] / nbudget);
    if (nlong > 0)
        printf("tsplib d1291, pcb1173, pr1002: +1000 ms %.2f%%, +10 s %.2f%% (goal: still "
               "improving at 10 s: %s)\n",
               at1s / nlong, at10s / nlong, at10s < at1s ? "yes" : "NO");
    free(list);
}

void bench_tour(void)
{
    printf("tour: best of a few runs; each method includes the ones before it\n");
    uniform(1000, 5, 1);
    uniform(10000, 3, 1);
    uniform(100000, 2, 1);
    uniform(1000000, 1, 0);
    printf("tour: process peak RSS %.1f MB\n", (double)bench_peak_rss() / 1e6);
}
