/* Pebbling and Shape Packing timings on 10^3 and 10^5 skeleton points:
 * a jittered square lattice (d = 10 mm) in a square, its EMST and a
 * depth-first walk made here; the family call alone is timed. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"

typedef struct bskel {
    qc_points pts;
    qc_edges edges;
    qc_order order;
    qc_region region;
} bskel;

/* Depth-first walk from point 0 (children in edge order), root first and last. */
static int walk(qc_ctx *ctx, bskel *s)
{
    size_t n = s->pts.n, i, sp = 0;
    size_t *first = calloc(n + 1, sizeof *first), *at = malloc(n * sizeof *at);
    uint32_t *adj = malloc(2 * s->edges.n * sizeof *adj + 1), *stack = malloc(n * sizeof *stack);
    unsigned char *seen = calloc(n, 1);
    int rc = QC_ENOMEM;

    if (first == NULL || at == NULL || adj == NULL || stack == NULL || seen == NULL)
        goto out;
    for (i = 0; i < s->edges.n; i++) {
        first[s->edges.e[i].a + 1]++;
        first[s->edges.e[i].b + 1]++;
    }
    for (i = 0; i < n; i++)
        first[i + 1] += first[i];
    for (i = 0; i < n; i++)
        at[i] = first[i];
    for (i = 0; i < s->edges.n; i++) {
        adj[at[s->edges.e[i].a]++] = s->edges.e[i].b;
        adj[at[s->edges.e[i].b]++] = s->edges.e[i].a;
    }
    for (i = 0; i < n; i++)
        at[i] = first[i];
    stack[sp++] = 0;
    seen[0] = 1;
    rc = qc_order_push(ctx, &s->order, 0);
    while (sp > 0 && rc == QC_OK) {
        uint32_t u = stack[sp - 1];
        if (at[u] < first[u + 1]) {
            uint32_t v = adj[at[u]++];
            if (seen[v])
                continue;
            seen[v] = 1;
            stack[sp++] = v;
            rc = qc_order_push(ctx, &s->order, v);
        } else if (--sp > 0) {
            rc = qc_order_push(ctx, &s->order, stack[sp - 1]);
        }
    }
out:
    free(first);
    free(at);
    free(adj);
    free(stack);
    free(seen);
    return rc;
}

static int make(qc_ctx *ctx, size_t n, double d, bskel *s)
{
    size_t side = (size_t)ceil(sqrt((double)n)), i, j;
    double w = (double)side * d;
    qc_vec2 sq[4];
    qc_rng rng;

    memset(s, 0, sizeof *s);
    qc_rng_seed(&rng, 7);
    for (j = 0; j < side; j++)
        for (i = 0; i < side && s->pts.n < n; i++) {
            qc_vec2 p;
            p.x = ((double)i + 0.5 + 0.3 * (qc_rng_unit(&rng) - 0.5)) * d;
            p.y = ((double)j + 0.5 + 0.3 * (qc_rng_unit(&rng) - 0.5)) * d;
            if (qc_points_push(ctx, &s->pts, p) != QC_OK)
                return QC_ENOMEM;
        }
    sq[0].x = 0; sq[0].y = 0;
    sq[1].x = w; sq[1].y = 0;
    sq[2].x = w; sq[2].y = w;
    sq[3].x = 0; sq[3].y = w;
    if (qc_region_add_ring(ctx, &s->region, sq, 4) != QC_OK ||
        qc_region_normalize(ctx, &s->region) != QC_OK ||
        qc_mst(ctx, s->pts.v, s->pts.n, QC_MST_MODE_DELAUNAY, &s->edges) != QC_OK)
        return QC_ENOMEM;
    return walk(ctx, s);
}

static void drop(qc_ctx *ctx, bskel *s)
{
    qc_points_free(ctx, &s->pts);
    qc_edges_free(ctx, &s->edges);
    qc_order_free(ctx, &s->order);
    qc_region_free(ctx, &s->region);
}

static void run(const char *name, qc_family_fn fn, int edge, const bskel *s, int reps)
{
    qc_ctx ctx;
    qc_skeleton sk;
    qc_params par;
    double best = 1e30;
    qc_stats st;
    size_t ncmd = 0;
    int r;

    qc_ctx_init(&ctx, NULL, NULL);
    memset(&sk, 0, sizeof sk);
    sk.p = s->pts.v;
    sk.n = s->pts.n;
    sk.edges = s->edges.e;
    sk.nedges = s->edges.n;
    sk.order = s->order.i;
    sk.norder = s->order.n;
    memset(&par, 0, sizeof par);
    par.seed = 1;
    par.spacing = 10;
    par.r_seed = 0.7;
    par.edge = edge;
    for (r = 0; r < reps; r++) {
        qc_path out = {0};
        double t0;
        memset(&st, 0, sizeof st);
        t0 = bench_now();
        if (fn(&ctx, &s->region, &par, &sk, NULL, &out, &st) != QC_OK) {
            printf("%s: %s\n", name, qc_errmsg(&ctx));
            return;
        }
        best = fmin(best, bench_now() - t0);
        ncmd = out.ncmd;
        qc_path_free(&ctx, &out);
    }
    printf("%-18s points %7lu  %9.2f ms  pebbles %7lu  under3 %5.2f%%  r %.2f/%.2f/%.2f mm  "
           "coverage %.3f  %lu commands\n",
           name, (unsigned long)s->pts.n, best * 1e3, (unsigned long)st.pebbles,
           100.0 * (double)st.pebbles_under3 / (double)(st.pebbles ? st.pebbles : 1),
           st.radius_min, st.radius_mean, st.radius_max, st.coverage, (unsigned long)ncmd);
}

void bench_pebbling(void)
{
    static const size_t sizes[] = {1000, 100000};
    size_t k;

    printf("pebbling/packing: best of a few runs, the family call alone (d = 10 mm, r_seed 0.7)\n");
    for (k = 0; k < sizeof sizes / sizeof *sizes; k++) {
        qc_ctx ctx;
        bskel s;
        int reps = sizes[k] > 10000 ? 2 : 10;

        qc_ctx_init(&ctx, NULL, NULL);
        if (make(&ctx, sizes[k], 10, &s) != QC_OK) {
            printf("pebbling: skeleton failed: %s\n", qc_errmsg(&ctx));
            drop(&ctx, &s);
            return;
        }
        run("pebbling strict", qc_deco_pebbling, QC_EDGE_STRICT, &s, reps);
        run("pebbling overgrow", qc_deco_pebbling, QC_EDGE_OVERGROW, &s, reps);
        run("packing (heart)", qc_deco_packing, QC_EDGE_STRICT, &s, reps);
        drop(&ctx, &s);
    }
}
