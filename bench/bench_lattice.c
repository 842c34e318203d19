/* Lattice EMST against a baseline carried here: our Delaunay triangulation,
 * then a plain Kruskal (qsort of the float lengths, union-find), the way a
 * peer builds an EMST (CGAL DT + Kruskal). qc_mst orders its edges exactly
 * (ties by index); the goal is that lattices, full of equal lengths, cost
 * no more than uniform points: within 1.2x of the baseline at 10^6 points.
 * CPU time; rounds interleave the two so the shared machine's load hits
 * both alike. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "bench.h"

#define GOAL 1.2

typedef struct wedge {
    double len2;
    uint32_t a, b;
} wedge;

static int wedge_cmp(const void *x, const void *y)
{
    const wedge *a = x, *b = y;

    return (a->len2 > b->len2) - (a->len2 < b->len2);
}

static uint32_t root(uint32_t *parent, uint32_t x)
{
    while (parent[x] != x)
        x = parent[x] = parent[parent[x]];
    return x;
}

/* The baseline: its tree's weight, or -1 on failure. */
static double baseline(qc_ctx *ctx, const qc_vec2 *p, size_t n)
{
    qc_mesh mesh;
    wedge *w = NULL;
    uint32_t *parent = NULL, *size = NULL;
    double weight = -1;
    size_t m, i, got = 0;

    if (qc_delaunay(ctx, p, n, &mesh) != QC_OK)
        goto out;
    m = mesh.edges.n;
    w = malloc((m ? m : 1) * sizeof *w);
    parent = malloc(n * sizeof *parent);
    size = malloc(n * sizeof *size);
    if (w == NULL || parent == NULL || size == NULL)
        goto out;
    for (i = 0; i < m; i++) {
        qc_vec2 a = p[mesh.edges.e[i].a], b = p[mesh.edges.e[i].b];
        w[i].len2 = (a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y);
        w[i].a = mesh.edges.e[i].a;
        w[i].b = mesh.edges.e[i].b;
    }
    qsort(w, m, sizeof *w, wedge_cmp);
    for (i = 0; i < n; i++)
        parent[i] = (uint32_t)i, size[i] = 1;
    weight = 0;
    for (i = 0; i < m && got + 1 < n; i++) {
        uint32_t ra = root(parent, w[i].a), rb = root(parent, w[i].b), t;

        if (ra == rb)
            continue;
        if (size[ra] < size[rb])
            t = ra, ra = rb, rb = t;
        parent[rb] = ra;
        size[ra] += size[rb];
        weight += sqrt(w[i].len2);
        got++;
    }
out:
    qc_mesh_free(ctx, &mesh);
    free(w);
    free(parent);
    free(size);
    return weight;
}

static double emst(qc_ctx *ctx, const qc_vec2 *p, size_t n)
{
    qc_edges e = {0};
    double weight = 0;
    size_t i;

    if (qc_mst(ctx, p, n, QC_MST_MODE_DELAUNAY, &e) != QC_OK)
        return -1;
    for (i = 0; i < e.n; i++)
        weight += qc_hypot(p[e.e[i].a].x - p[e.e[i].b].x, p[e.e[i].a].y - p[e.e[i].b].y);
    qc_edges_free(ctx, &e);
    return weight;
}

/* A side x side block sampled by kind at spacing d (offset from 0 as a
 * pattern's block is: the lattice is centred on the block). */
static int sample(qc_ctx *ctx, int kind, double d, double side, qc_points *out)
{
    char spec[64];
    qc_region r = {0};
    qc_sample_params sp = {0};
    int rc;

    snprintf(spec, sizeof spec, "rect:%.3fx%.3f", side, side);
    sp.kind = kind;
    sp.spacing = d;
    sp.seed = 1;
    rc = qc_region_shape(ctx, spec, 1.0, &r);
    if (rc == QC_OK)
        rc = qc_sample(ctx, &r, &sp, out);
    qc_region_free(ctx, &r);
    return rc;
}

static void run(const char *name, int kind, double d, double cell, size_t target, int rounds)
{
    qc_ctx ctx;
    qc_points pts = {0};
    double tb = 1e30, tq = 1e30, wb = 0, wq = 0, side = d * sqrt(cell * (double)target);
    int r;

    qc_ctx_init(&ctx, NULL, NULL);
    if (kind == 0) {
        qc_vec2 *p = bench_uniform(target, side, 99);
        size_t i;
        for (i = 0; p != NULL && i < target; i++)
            qc_points_push(&ctx, &pts, p[i]);
        free(p);
    } else if (sample(&ctx, kind, d, side, &pts) != QC_OK) {
        printf("%s: %s\n", name, qc_errmsg(&ctx));
        return;
    }
    for (r = 0; r < rounds; r++) {
        double t0 = bench_cpu(), t1, t2;
        wb = baseline(&ctx, pts.v, pts.n);
        t1 = bench_cpu();
        wq = emst(&ctx, pts.v, pts.n);
        t2 = bench_cpu();
        tb = fmin(tb, t1 - t0);
        tq = fmin(tq, t2 - t1);
    }
    printf("%-12s n=%8lu  qc_mst %8.1f ms  baseline DT+qsort Kruskal %8.1f ms  ratio %.2f "
           "(goal <= %.1f at 10^6)%s\n",
           name, (unsigned long)pts.n, tq * 1e3, tb * 1e3, tq / tb, GOAL,
           fabs(wq - wb) > 1e-9 * wb ? "  WEIGHTS DIFFER" : "");
    qc_points_free(&ctx, &pts);
}

void bench_lattice(void)
{
    static const size_t sizes[] = {100000, 1000000};
    size_t k;

    printf("lattice emst: CPU time, best of interleaved rounds, d = 10 mm, block sized for n points\n");
    for (k = 0; k < sizeof sizes / sizeof *sizes; k++) {
        int rounds = sizes[k] > 100000 ? 2 : 3;
        run("uniform", 0, 10.0, 1.0, sizes[k], rounds);
        run("hex", QC_SAMPLE_HEX, 10.0, 1.299038105676658, sizes[k], rounds);
        run("snub", QC_SAMPLE_SNUB, 10.0, 0.9330127018922193, sizes[k], rounds);
        run("grid", QC_SAMPLE_SQUARE, 10.0, 1.0, sizes[k], rounds);
    }
}
