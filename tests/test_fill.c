/* Fixed-width fill and stippling (§7.1): one closed simple loop at w/2
 * from the tree, tip circles, stipple without crossings and with small
 * gaps, deterministic, no leaks. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "quiltc.h"
#include "testalloc.h"
#include "testgeom.h"
#include "unity.h"

static testalloc ta;
static qc_ctx ctx;

void setUp(void)
{
    memset(&ta, 0, sizeof ta);
    qc_ctx_init(&ctx, testalloc_fn, &ta);
}

void tearDown(void)
{
}

enum { R_RECT, R_HOLES, R_U };

/* 120 x 100 mm shapes: a rectangle, one with two square holes, a U. */
static void make_region(int kind, qc_region *r)
{
    qc_vec2 rect[4], hole[4], u[8];

    memset(r, 0, sizeof *r);
    if (kind == R_U) {
        u[0] = v2(0, 0); u[1] = v2(120, 0); u[2] = v2(120, 100); u[3] = v2(85, 100);
        u[4] = v2(85, 35); u[5] = v2(35, 35); u[6] = v2(35, 100); u[7] = v2(0, 100);
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, r, u, 8));
        return;
    }
    rect[0] = v2(0, 0); rect[1] = v2(120, 0); rect[2] = v2(120, 100); rect[3] = v2(0, 100);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, r, rect, 4));
    if (kind == R_HOLES) { /* clockwise holes */
        hole[0] = v2(20, 20); hole[1] = v2(20, 50); hole[2] = v2(50, 50); hole[3] = v2(50, 20);
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, r, hole, 4));
        hole[0] = v2(70, 55); hole[1] = v2(75, 85); hole[2] = v2(100, 80); hole[3] = v2(95, 60);
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, r, hole, 4));
    }
}

enum { P_HEX, P_SQUARE, P_TRIANGLE, P_JITTER };

typedef struct tskel {
    qc_points pts;
    qc_edges edges;
} tskel;

/* Lattice points at spacing d kept 0.3 d inside r, and their MST. */
static void make_skeleton(const qc_region *r, int kind, double d, uint64_t seed, tskel *t)
{
    qc_bbox b = qc_region_bbox(r);
    qc_rng rng;
    double dy = kind == P_SQUARE ? d : d * sqrt(3.0) / 2.0;
    int row = 0;
    double y;

    qc_rng_seed(&rng, seed);
    memset(t, 0, sizeof *t);
    for (y = b.min.y; y <= b.max.y; y += dy, row++) {
        double x0 = b.min.x + ((kind == P_HEX || kind == P_JITTER) && (row & 1) ? d / 2 : 0);
        double x;
        for (x = x0; x <= b.max.x; x += d) {
            qc_vec2 p = v2(x, y);
            if (kind == P_TRIANGLE && ((int)floor((x - b.min.x) / d + 0.5) + row) % 3 == 0)
                continue; /* a kagome-like thinning: a different tree shape */
            if (kind == P_JITTER) {
                p.x += (qc_rng_unit(&rng) - 0.5) * 0.4 * d;
                p.y += (qc_rng_unit(&rng) - 0.5) * 0.4 * d;
            }
            if (qc_region_contains(r, p) && qc_region_boundary_distance(r, p) >= 0.3 * d)
                TEST_ASSERT_EQUAL_INT(QC_OK, qc_points_push(&ctx, &t->pts, p));
        }
    }
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_mst(&ctx, t->pts.v, t->pts.n, QC_MST_MODE_DELAUNAY, &t->edges));
}

static qc_skeleton as_skel(const tskel *t)
{
    qc_skeleton s;
    memset(&s, 0, sizeof s);
    s.p = t->pts.v;
    s.n = t->pts.n;
    s.edges = t->edges.e;
    s.nedges = t->edges.n;
    s.root = 0;
    return s;
}

static void free_skeleton(tskel *t)
{
    qc_points_free(&ctx, &t->pts);
    qc_edges_free(&ctx, &t->edges);
}

static qc_params params(int family, double d)
{
    qc_params p, r;
    memset(&p, 0, sizeof p);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "family", family));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "spacing", d));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_resolve(&ctx, &p, &r));
    return r;
}

static double tree_distance(const tskel *t, qc_vec2 q)
{
    double best = HUGE_VAL;
    size_t k;

    for (k = 0; k < t->edges.n; k++) {
        qc_vec2 a = t->pts.v[t->edges.e[k].a], b = t->pts.v[t->edges.e[k].b];
        double dx = b.x - a.x, dy = b.y - a.y, l2 = dx * dx + dy * dy;
        double s = l2 > 0 ? ((q.x - a.x) * dx + (q.y - a.y) * dy) / l2 : 0;
        s = s < 0 ? 0 : s > 1 ? 1 : s;
        best = fmin(best, qc_hypot(a.x + s * dx - q.x, a.y + s * dy - q.y));
    }
    return best;
}

static size_t crossings(const qc_path *path, int closed)
{
    qc_points flat = {0};
    size_t n = 0;

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_curve_flatten(&ctx, path, 0.01, &flat, NULL));
    if (closed && flat.n > 1 && flat.v[0].x == flat.v[flat.n - 1].x &&
        flat.v[0].y == flat.v[flat.n - 1].y)
        flat.n--;
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_self_crossings(&ctx, flat.v, flat.n, closed, &n));
    qc_points_free(&ctx, &flat);
    return n;
}

static void check_fill(int region, int points, double d)
{
    qc_region r;
    tskel t;
    qc_skeleton sk;
    qc_params par = params(QC_FAMILY_FILL, d);
    qc_path out = {0};
    qc_stats st;
    size_t i;

    memset(&st, 0, sizeof st);
    make_region(region, &r);
    make_skeleton(&r, points, d, 3, &t);
    TEST_ASSERT_GREATER_THAN(10, t.pts.n);
    sk = as_skel(&t);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_deco_fill(&ctx, &r, &par, &sk, NULL, &out, &st));
    TEST_ASSERT_EQUAL_UINT(1, qc_path_pieces(&out));
    TEST_ASSERT_EQUAL_DOUBLE(out.pt[0].x, out.pt[out.npt - 1].x);
    TEST_ASSERT_EQUAL_DOUBLE(out.pt[0].y, out.pt[out.npt - 1].y);
    for (i = 0; i < out.npt; i++) {
        TEST_ASSERT_EQUAL_INT(i == 0 ? QC_PATH_MOVE : QC_PATH_LINE, out.cmd[i]);
        TEST_ASSERT_DOUBLE_WITHIN(1e-6, par.width / 2, tree_distance(&t, out.pt[i]));
        TEST_ASSERT_TRUE(qc_region_contains(&r, out.pt[i]));
    }
    TEST_ASSERT_EQUAL_UINT(0, crossings(&out, 1));
    TEST_ASSERT_GREATER_THAN_DOUBLE(0.0, st.largest_gap_mm);
    qc_path_free(&ctx, &out);
    free_skeleton(&t);
    qc_region_free(&ctx, &r);
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

static void fill_should_outline_the_tree_as_one_simple_loop(void)
{
    check_fill(R_RECT, P_HEX, 10);
    check_fill(R_RECT, P_SQUARE, 9);
    check_fill(R_HOLES, P_TRIANGLE, 8);
    check_fill(R_U, P_JITTER, 7);
    check_fill(R_HOLES, P_JITTER, 6);
}

static void fill_should_put_circles_at_the_tips(void)
{
    qc_region r;
    tskel t;
    qc_skeleton sk;
    qc_params par = params(QC_FAMILY_FILL, 10), plain = par;
    qc_path out = {0}, ref = {0};
    size_t i, leaves = 0, far = 0;

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &par, "tip", QC_TIP_CIRCLE));
    make_region(R_RECT, &r);
    make_skeleton(&r, P_JITTER, 10, 5, &t);
    sk = as_skel(&t);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_deco_fill(&ctx, &r, &par, &sk, NULL, &out, NULL));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_deco_fill(&ctx, &r, &plain, &sk, NULL, &ref, NULL));
    for (i = 0; i < out.npt; i++) {
        double dist = tree_distance(&t, out.pt[i]);
        TEST_ASSERT_GREATER_OR_EQUAL_DOUBLE(par.width / 2 - 1e-6, dist);
        far += dist > par.width; /* on a tip circle of radius 1.5 w */
    }
    for (i = 0; i < t.pts.n; i++) {
        size_t k, deg = 0;
        for (k = 0; k < t.edges.n; k++)
            deg += t.edges.e[k].a == i || t.edges.e[k].b == i;
        leaves += deg == 1;
    }
    TEST_ASSERT_GREATER_THAN(leaves * 8, far);
    TEST_ASSERT_GREATER_THAN_DOUBLE(qc_curve_length(&ref, 0), qc_curve_length(&out, 0));
    TEST_ASSERT_EQUAL_UINT(1, qc_path_pieces(&out));
    TEST_ASSERT_EQUAL_UINT(0, crossings(&out, 1));
    qc_path_free(&ctx, &out);
    qc_path_free(&ctx, &ref);
    free_skeleton(&t);
    qc_region_free(&ctx, &r);
}

static void check_stipple(int region, int points, double d, uint64_t seed)
{
    qc_region r;
    tskel t;
    qc_skeleton sk;
    qc_params par = params(QC_FAMILY_STIPPLE, d);
    qc_path out = {0};
    qc_stats st;

    memset(&st, 0, sizeof st);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, d / 3, par.width);
    make_region(region, &r);
    make_skeleton(&r, points, d, seed, &t);
    sk = as_skel(&t);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_deco_stipple(&ctx, &r, &par, &sk, NULL, &out, &st));
    TEST_ASSERT_EQUAL_UINT(1, qc_path_pieces(&out));
    TEST_ASSERT_EQUAL_INT(QC_PATH_CUBIC, out.cmd[1]);
    TEST_ASSERT_EQUAL_UINT(0, crossings(&out, 1));
    /* the meander leaves no hole wider than the point spacing */
    TEST_ASSERT_GREATER_THAN_DOUBLE(0.0, st.largest_gap_mm);
    TEST_ASSERT_LESS_OR_EQUAL_DOUBLE(d, st.largest_gap_mm);
    qc_path_free(&ctx, &out);
    free_skeleton(&t);
    qc_region_free(&ctx, &r);
}

static void stipple_should_meander_without_crossing(void)
{
    check_stipple(R_RECT, P_HEX, 10, 1);
    check_stipple(R_RECT, P_SQUARE, 8, 1);
    check_stipple(R_HOLES, P_TRIANGLE, 7, 1);
    check_stipple(R_HOLES, P_JITTER, 6, 2);
    check_stipple(R_U, P_JITTER, 5, 3);
}

static void fill_should_be_deterministic(void)
{
    qc_region r;
    tskel t;
    qc_skeleton sk;
    qc_params par = params(QC_FAMILY_STIPPLE, 9);
    qc_path a = {0}, b = {0};

    make_region(R_HOLES, &r);
    make_skeleton(&r, P_JITTER, 9, 7, &t);
    sk = as_skel(&t);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_deco_stipple(&ctx, &r, &par, &sk, NULL, &a, NULL));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_deco_stipple(&ctx, &r, &par, &sk, NULL, &b, NULL));
    TEST_ASSERT_EQUAL_UINT(a.npt, b.npt);
    TEST_ASSERT_EQUAL_MEMORY(a.pt, b.pt, a.npt * sizeof *a.pt);
    TEST_ASSERT_EQUAL_MEMORY(a.cmd, b.cmd, a.ncmd);
    qc_path_free(&ctx, &a);
    qc_path_free(&ctx, &b);
    free_skeleton(&t);
    qc_region_free(&ctx, &r);
}

static void fill_should_circle_a_lone_point_and_reject_tours(void)
{
    qc_region r;
    qc_vec2 p = v2(50, 50);
    qc_skeleton sk;
    qc_params par = params(QC_FAMILY_FILL, 10);
    qc_path out = {0};
    uint32_t order[1] = {0};
    size_t i;

    make_region(R_RECT, &r);
    memset(&sk, 0, sizeof sk);
    sk.p = &p;
    sk.n = 1;
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_deco_fill(&ctx, &r, &par, &sk, NULL, &out, NULL));
    TEST_ASSERT_GREATER_THAN(8, out.npt);
    for (i = 0; i < out.npt; i++)
        TEST_ASSERT_DOUBLE_WITHIN(1e-9, par.width / 2, qc_hypot(out.pt[i].x - 50, out.pt[i].y - 50));
    qc_path_free(&ctx, &out);
    sk.n = 0;
    TEST_ASSERT_EQUAL_INT(QC_EEMPTY, qc_deco_fill(&ctx, &r, &par, &sk, NULL, &out, NULL));
    {
        qc_vec2 two[2];
        two[0] = v2(10, 10);
        two[1] = v2(30, 10);
        sk.p = two;
        sk.n = 2;
        sk.order = order;
        sk.norder = 1;
        TEST_ASSERT_EQUAL_INT(QC_EINVAL, qc_deco_stipple(&ctx, &r, &par, &sk, NULL, &out, NULL));
    }
    TEST_ASSERT_EQUAL_UINT(0, out.ncmd);
    qc_region_free(&ctx, &r);
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

static void fill_should_survive_allocation_failures(void)
{
    qc_region r;
    tskel t;
    qc_skeleton sk;
    qc_params par = params(QC_FAMILY_STIPPLE, 25);
    size_t k, base;
    int rc = QC_ENOMEM;

    make_region(R_HOLES, &r);
    make_skeleton(&r, P_HEX, 25, 1, &t);
    sk = as_skel(&t);
    base = ta.live_blocks;
    for (k = 1; rc == QC_ENOMEM && k < 5000; k++) {
        qc_path out = {0};
        qc_stats st;
        memset(&st, 0, sizeof st);
        ta.allocs = 0;
        ta.fail_at = k;
        rc = qc_deco_stipple(&ctx, &r, &par, &sk, NULL, &out, &st);
        ta.fail_at = 0;
        qc_path_free(&ctx, &out);
        TEST_ASSERT_EQUAL_UINT(base, ta.live_blocks);
    }
    TEST_ASSERT_EQUAL_INT(QC_OK, rc);
    TEST_ASSERT_GREATER_THAN(3, k);
    TEST_ASSERT_FALSE(ta.size_mismatch);
    free_skeleton(&t);
    qc_region_free(&ctx, &r);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(fill_should_outline_the_tree_as_one_simple_loop);
    RUN_TEST(fill_should_put_circles_at_the_tips);
    RUN_TEST(stipple_should_meander_without_crossing);
    RUN_TEST(fill_should_be_deterministic);
    RUN_TEST(fill_should_circle_a_lone_point_and_reject_tours);
    RUN_TEST(fill_should_survive_allocation_failures);
    return UNITY_END();
}
