/* Delaunay and EMST timings: uniform points 10^3..10^6 and a hex lattice. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "bench.h"

static void run(const char *name, const qc_vec2 *p, size_t n, int reps)
{
    qc_ctx ctx;
    bench_meter m = {0, 0};
    double td = 1e30, tm = 1e30, w = 0;
    size_t ntri = 0, i;
    int r;

    qc_ctx_init(&ctx, bench_meter_alloc, &m);
    for (r = 0; r < reps; r++) {
        qc_mesh mesh;
        qc_edges e = {0};
        double t0 = bench_now(), t1, t2;

        if (qc_delaunay(&ctx, p, n, &mesh) != QC_OK) {
            printf("%s: %s\n", name, qc_errmsg(&ctx));
            return;
        }
        t1 = bench_now();
        ntri = mesh.ntri;
        qc_mesh_free(&ctx, &mesh);
        t2 = bench_now();
        if (qc_mst(&ctx, p, n, QC_MST_MODE_DELAUNAY, &e) != QC_OK) {
            printf("%s: %s\n", name, qc_errmsg(&ctx));
            return;
        }
        tm = fmin(tm, bench_now() - t2);
        td = fmin(td, t1 - t0);
        w = 0;
        for (i = 0; i < e.n; i++)
            w += qc_hypot(p[e.e[i].a].x - p[e.e[i].b].x, p[e.e[i].a].y - p[e.e[i].b].y);
        qc_edges_free(&ctx, &e);
    }
    printf("%-14s n=%8lu  delaunay %9.3f ms (%lu tri)  delaunay+emst %9.3f ms  "
           "lib peak %6.1f B/pt  emst weight %.6g\n",
           name, (unsigned long)n, td * 1e3, (unsigned long)ntri, tm * 1e3,
           (double)m.peak / (double)n, w);
}

void bench_graph(void)
{
    static const size_t sizes[] = {1000, 10000, 100000, 1000000};
    size_t k, n;
    qc_vec2 *p;

    printf("graph: best of a few runs; times include the library's allocations\n");
    for (k = 0; k < sizeof sizes / sizeof *sizes; k++) {
        char name[32];

        p = bench_uniform(sizes[k], 1000.0, 42 + k);
        if (p == NULL)
            return;
        snprintf(name, sizeof name, "uniform");
        run(name, p, sizes[k], sizes[k] <= 10000 ? 5 : sizes[k] <= 100000 ? 3 : 1);
        free(p);
    }
    p = bench_hex(100000, &n);
    if (p != NULL)
        run("hex lattice", p, n, 3);
    free(p);
    printf("graph: process peak RSS %.1f MB\n", (double)bench_peak_rss() / 1e6);
}
