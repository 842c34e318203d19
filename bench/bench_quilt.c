/* A whole quilt top through qc_quilt: 60 x 80 in of 192 patches (5 in
 * squares, 12 x 16), stippled at 0.5 in and sewn as one line in the ditch. The goal: under 1 s for the whole top.
 * Reported: reading the SVG, the quilt, time and peak library bytes per
 * patch, ditch travel. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"

#define IN 25.4
#define COLS 12
#define ROWS 16
#define SIDE 5.0

static char *top_svg(size_t *len)
{
    size_t cap = 256 + (size_t)COLS * ROWS * 128, n = 0;
    char *s = malloc(cap);
    int r, c;

    if (s == NULL)
        return NULL;
    n += (size_t)snprintf(s + n, cap - n,
                          "<svg xmlns='http://www.w3.org/2000/svg' width='%gin' height='%gin' "
                          "viewBox='0 0 %g %g'>\n", COLS * SIDE, ROWS * SIDE, COLS * SIDE,
                          ROWS * SIDE);
    for (r = 0; r < ROWS; r++)
        for (c = 0; c < COLS; c++)
            n += (size_t)snprintf(s + n, cap - n,
                                  "<rect id='b%d-%d' x='%g' y='%g' width='%g' height='%g'/>\n", r,
                                  c, c * SIDE, r * SIDE, SIDE, SIDE);
    n += (size_t)snprintf(s + n, cap - n, "</svg>\n");
    *len = n;
    return s;
}

static void run(int gap_stat)
{
    qc_ctx ctx;
    bench_meter m = {0, 0};
    qc_patches ps;
    qc_params p;
    qc_patch_job *jobs;
    qc_quilt_result res;
    size_t len, i;
    char *svg = top_svg(&len);
    double t0, t1, t2;

    qc_ctx_init(&ctx, bench_meter_alloc, &m);
    if (svg == NULL)
        return;
    t0 = bench_now();
    if (qc_io_read_svg_patches(&ctx, svg, len, NULL, &ps) != QC_OK) {
        printf("quilt: %s\n", qc_errmsg(&ctx));
        free(svg);
        return;
    }
    t1 = bench_now();
    memset(&p, 0, sizeof p);
    qc_params_set(&ctx, &p, "family", QC_FAMILY_STIPPLE);
    qc_params_set(&ctx, &p, "spacing", 0.5 * IN);
    p.skip_gap_stat = !gap_stat;
    jobs = calloc(ps.n, sizeof *jobs);
    for (i = 0; jobs != NULL && i < ps.n; i++)
        jobs[i].params = &p;
    m.peak = m.live;
    if (jobs != NULL && qc_patches_overlap(&ps, 0, NULL, NULL, NULL) == 0 &&
        qc_quilt(&ctx, &ps, jobs, NULL, &res) == QC_OK) {
        t2 = bench_now();
        printf("quilt: %lu patches of %g in at 0.5 in, %s: read %.1f ms, overlap+quilt %.1f ms "
               "(%.2f ms per patch), peak %.2f MiB (%.1f KiB per patch), %lu piece, ditch "
               "%.0f in\n",
               (unsigned long)ps.n, SIDE, gap_stat ? "with gap stat" : "no gap stat",
               (t1 - t0) * 1e3, (t2 - t1) * 1e3, (t2 - t1) * 1e3 / (double)ps.n,
               (double)m.peak / 1048576.0, (double)m.peak / 1024.0 / (double)ps.n,
               (unsigned long)qc_path_pieces(&res.path), res.ditch_mm / IN);
        qc_quilt_result_free(&ctx, &res);
    } else
        printf("quilt: failed: %s\n", qc_errmsg(&ctx));
    free(jobs);
    qc_patches_free(&ctx, &ps);
    free(svg);
}

void bench_quilt(void)
{
    run(0);
    run(1);
}
