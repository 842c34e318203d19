/* The MST's edge order (src/graph/edge_sort.c) against a plain sort by
 * exact comparisons: lattices whose thousands of equal lengths take the
 * integer keys, and crafted lengths for each of the keys' paths (ties in
 * the radix window that are not exact ties, keys too wide for 256 bits). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "quiltc.h"
#include "../src/graph/graph_internal.h"
#include "testalloc.h"
#include "testgeom.h"
#include "unity.h"

static testalloc ta;
static qc_ctx ctx;
static const qc_vec2 *ref_p; /* the points of ref_cmp */

void setUp(void)
{
    memset(&ta, 0, sizeof ta);
    qc_ctx_init(&ctx, testalloc_fn, &ta);
}

void tearDown(void)
{
}

/* (exact length, a, b), by qc__cmp_len2 alone. */
static int ref_cmp(const void *x, const void *y)
{
    const qc_edge *a = x, *b = y;
    int c = qc__cmp_len2(ref_p[a->a], ref_p[a->b], ref_p[b->a], ref_p[b->b]);

    if (c != 0)
        return c;
    if (a->a != b->a)
        return a->a < b->a ? -1 : 1;
    return (a->b > b->b) - (a->b < b->b);
}

/* qc__sort_edges gives the reference order; *ties counts adjacent edges
 * of exactly equal length (the tie-break by index at work). */
static void sort_check(const qc_vec2 *p, size_t n, const qc_edge *e, size_t m, size_t *ties)
{
    qc_edge *got = malloc(m * sizeof *got), *want = malloc(m * sizeof *want);
    size_t i;

    memcpy(got, e, m * sizeof *e);
    memcpy(want, e, m * sizeof *e);
    ref_p = p;
    qsort(want, m, sizeof *want, ref_cmp);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc__sort_edges(&ctx, p, n, got, m));
    TEST_ASSERT_EQUAL_MEMORY(want, got, m * sizeof *got);
    *ties = 0;
    for (i = 1; i < m; i++)
        *ties += qc__cmp_len2(p[got[i - 1].a], p[got[i - 1].b], p[got[i].a], p[got[i].b]) == 0;
    free(got);
    free(want);
}

/* A side x side block of kind at spacing 10, moved by (dx, dy). */
static qc_points sampled(int kind, double side, double dx, double dy)
{
    char spec[64];
    qc_region r = {0};
    qc_sample_params sp;
    qc_points pts = {0};
    size_t i;

    memset(&sp, 0, sizeof sp);
    sp.kind = kind;
    sp.spacing = 10;
    sprintf(spec, "rect:%gx%g", side, side);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_shape(&ctx, spec, 1.0, &r));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_sample(&ctx, &r, &sp, &pts));
    qc_region_free(&ctx, &r);
    for (i = 0; i < pts.n; i++) {
        pts.v[i].x += dx;
        pts.v[i].y += dy;
    }
    return pts;
}

/* The Delaunay edges of pts, sorted and checked. */
static size_t delaunay_check(qc_points *pts)
{
    qc_mesh mesh;
    size_t ties;

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_delaunay(&ctx, pts->v, pts->n, &mesh));
    sort_check(pts->v, pts->n, mesh.edges.e, mesh.edges.n, &ties);
    qc_mesh_free(&ctx, &mesh);
    qc_points_free(&ctx, pts);
    return ties;
}

/* Lattices far from the origin (exponents spanning more than 128-bit
 * coordinates allow), across it (coordinates rounded near zero), and on
 * integers (every equal length an exact tie). */
static void sort_edges_should_order_lattices_exactly(void)
{
    static const int kinds[] = {QC_SAMPLE_HEX, QC_SAMPLE_SNUB, QC_SAMPLE_SQUARE,
                                QC_SAMPLE_TRIANGLE};
    size_t k;

    for (k = 0; k < sizeof kinds / sizeof *kinds; k++) {
        qc_points a = sampled(kinds[k], 400, 1e4, 3), b = sampled(kinds[k], 400, -200, -200);
        TEST_ASSERT_TRUE(a.n > 1000);
        delaunay_check(&a);
        delaunay_check(&b);
    }
    {
        qc_points g = sampled(QC_SAMPLE_SQUARE, 400, 5, 5);
        TEST_ASSERT_TRUE(delaunay_check(&g) > 1000); /* integer lengths: exact ties */
    }
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

/* A lattice with one coordinate near 5e-11 (keys near 190 bits, spread
 * past 128), and one with a coordinate 1e-38 (keys too wide: compared). */
static void sort_edges_should_order_tiny_coordinates_exactly(void)
{
    static const double tiny[] = {5e-11, 1e-38};
    size_t k;

    for (k = 0; k < 2; k++) {
        qc_points g = sampled(QC_SAMPLE_SNUB, 300, 0, 0);
        size_t i, best = 0;
        for (i = 1; i < g.n; i++)
            if (fabs(g.v[i].x) < fabs(g.v[best].x))
                best = i;
        g.v[best].x = tiny[k]; /* the point nearest the y axis onto it */
        delaunay_check(&g);
    }
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

/* Crafted near ties: (0,0), (2^-70, 0) and (0, 2^-60) to Q_k = (10 + k
 * ulp, 0), and mirrored -Q_k: lengths a few ulps apart chain into one
 * group, some differ only far below the radix window, -Q_k ties Q_k
 * exactly; then with a zero-length edge, 2^-130 for 2^-70 (keys too wide)
 * and all at a 2^-1000 scale. */
static void sort_edges_should_break_crafted_ties_exactly(void)
{
    qc_vec2 p[3 + 2 * 41];
    qc_edge e[6 * 41 + 1];
    size_t n = 3, m = 0, k, ties;

    p[0] = v2(0, 0);
    p[1] = v2(0x1p-70, 0);
    p[2] = v2(0, 0x1p-60);
    for (k = 0; k <= 40; k++) {
        p[n] = v2(10 + (double)k * 0x1p-49, 0);
        p[n + 1] = v2(-p[n].x, 0);
        e[m].a = 0, e[m++].b = (uint32_t)n;
        e[m].a = 1, e[m++].b = (uint32_t)n;
        e[m].a = 2, e[m++].b = (uint32_t)n;
        e[m].a = 0, e[m++].b = (uint32_t)n + 1;
        e[m].a = 1, e[m++].b = (uint32_t)n + 1;
        e[m].a = 2, e[m++].b = (uint32_t)n + 1;
        n += 2;
    }
    sort_check(p, n, e, m, &ties);
    TEST_ASSERT_TRUE(ties >= 40);
    e[m].a = 0, e[m++].b = 0; /* a zero length sorts first */
    sort_check(p, n, e, m, &ties);
    p[1].x = 0x1p-130; /* 2^-130 beside 10: keys past 256 bits, compared */
    sort_check(p, n, e, m, &ties);
    for (k = 0; k < n; k++) { /* all lengths near 2^-996: squares near underflow */
        p[k].x *= 0x1p-1000;
        p[k].y *= 0x1p-1000;
    }
    sort_check(p, n, e, m, &ties);
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

/* Integer lengths (coordinates in [2^52, 2^53): the keys are the squared
 * lengths themselves) from (2^51 + i)^2, one chained group spread past
 * 2^64, with lengths one unit longer beside some: ties of the radix window
 * that only the low bits order. */
static void sort_edges_should_order_window_ties_by_low_bits(void)
{
    enum { N = 8192 };
    qc_vec2 *p = malloc((2 * N + 1) * sizeof *p);
    qc_edge *e = malloc(2 * N * sizeof *e);
    size_t n = 1, m = 0, i, ties;

    p[0] = v2(0x1p52, 0x1p52);
    for (i = 0; i < N; i++) {
        if (i % 7 == 0) { /* the longer one first: index order is not length order */
            p[n] = v2(0x1p52 + 0x1p51 + (double)i, 0x1p52 + 1);
            e[m].a = 0, e[m++].b = (uint32_t)n++;
        }
        p[n] = v2(0x1p52 + 0x1p51 + (double)i, 0x1p52);
        e[m].a = 0, e[m++].b = (uint32_t)n++;
    }
    sort_check(p, n, e, m, &ties);
    free(p);
    free(e);
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

/* Allocation failures anywhere in the keyed sort are reported, not
 * hidden, and leak nothing. */
static void sort_edges_should_survive_out_of_memory(void)
{
    qc_points g = sampled(QC_SAMPLE_HEX, 200, 0, 0);
    qc_mesh mesh;
    size_t k;
    int done = 0;

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_delaunay(&ctx, g.v, g.n, &mesh));
    for (k = 1; !done && k < 400; k++) {
        qc_edge *e = malloc(mesh.edges.n * sizeof *e);
        int rc;

        memcpy(e, mesh.edges.e, mesh.edges.n * sizeof *e);
        ta.fail_at = ta.allocs + k;
        rc = qc__sort_edges(&ctx, g.v, g.n, e, mesh.edges.n);
        ta.fail_at = 0;
        TEST_ASSERT_TRUE(rc == QC_OK || rc == QC_ENOMEM);
        done = rc == QC_OK;
        free(e);
    }
    TEST_ASSERT_TRUE(done && k > 3);
    qc_mesh_free(&ctx, &mesh);
    qc_points_free(&ctx, &g);
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
    TEST_ASSERT_FALSE(ta.size_mismatch);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(sort_edges_should_order_lattices_exactly);
    RUN_TEST(sort_edges_should_order_tiny_coordinates_exactly);
    RUN_TEST(sort_edges_should_break_crafted_ties_exactly);
    RUN_TEST(sort_edges_should_order_window_ties_by_low_bits);
    RUN_TEST(sort_edges_should_survive_out_of_memory);
    return UNITY_END();
}
