/*
 * The caps of docs/limits.md: a request beyond one is refused with
 * QC_ELIMIT and a message naming the numbers, before any large allocation
 * (the counting allocator's peak stays small), so memory stays linear in
 * what is accepted.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "quiltc.h"
#include "testalloc.h"
#include "unity.h"

#define SMALL_PEAK ((size_t)1 << 20) /* 1 MiB: the inputs, nothing more */

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

static void assert_msg_has(const char *needle)
{
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(qc_errmsg(&ctx), needle), qc_errmsg(&ctx));
}

static void assert_clean(void)
{
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
    TEST_ASSERT_FALSE(ta.size_mismatch);
}

/* A square 100 m on a side (the largest built-in shape) at the smallest
 * spacing the table allows would be about 4.6e10 points: every family that
 * samples refuses before allocating; echo and spiral refuse before their
 * distance grid, which has its own cap. */
static void test_generate_should_refuse_ten_billion_points_before_allocating(void)
{
    int family, refused = 0;

    for (family = 1; family < QC_FAMILY_COUNT; family++) {
        qc_region r = {0};
        qc_params p;
        qc_result res;
        size_t before;
        int rc;

        setUp();
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_shape(&ctx, "rect:100000x100000", 1.0, &r));
        before = ta.peak_bytes;
        memset(&p, 0, sizeof p);
        qc_params_set(&ctx, &p, "family", family);
        qc_params_set(&ctx, &p, "spacing", 0.5);
        rc = qc_generate(&ctx, &r, &p, NULL, NULL, &res);
        if (rc == QC_EUNSUPPORTED) {
            qc_region_free(&ctx, &r);
            continue;
        }
        TEST_ASSERT_EQUAL_INT_MESSAGE(QC_ELIMIT, rc, qc_family_name(family));
        TEST_ASSERT_TRUE_MESSAGE(ta.peak_bytes - before < SMALL_PEAK, qc_family_name(family));
        if (family != QC_FAMILY_ECHO && family != QC_FAMILY_SPIRAL)
            assert_msg_has("exceed the limit of 4000000");
        else /* their distance grid is sized, and refused, before it is built */
            assert_msg_has("too fine for a region this size");
        refused++;
        qc_region_free(&ctx, &r);
        assert_clean();
    }
    TEST_ASSERT_TRUE(refused >= 7);
}

/* Every distribution at about 10^9 points: refused, peak small. */
static void test_sample_should_refuse_a_billion_points_for_every_kind(void)
{
    int kind;

    for (kind = QC_SAMPLE_TRIANGLE; kind <= QC_SAMPLE_POISSON; kind++) {
        qc_region r = {0};
        qc_points pts = {0};
        qc_sample_params sp;

        setUp();
        /* 31623 mm square at 1 mm: about 1e9 points */
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_shape(&ctx, "square:31623", 1.0, &r));
        memset(&sp, 0, sizeof sp);
        sp.kind = kind;
        sp.spacing = 1.0;
        TEST_ASSERT_TRUE(qc_sample_estimate(&r, &sp) > 7e8);
        TEST_ASSERT_EQUAL_INT(QC_ELIMIT, qc_sample(&ctx, &r, &sp, &pts));
        TEST_ASSERT_EQUAL_size_t(0, pts.n);
        TEST_ASSERT_TRUE(ta.peak_bytes < SMALL_PEAK);
        assert_msg_has("raise the spacing");
        qc_region_free(&ctx, &r);
        assert_clean();
    }
}

/* A sliver: small area (few points) but a huge box the lattice would walk. */
static void test_sample_should_refuse_a_sliver_whose_box_is_huge(void)
{
    static const qc_vec2 sliver[] = {{0, 0}, {90000, 90000}, {90000, 90000.05}};
    qc_region r = {0};
    qc_points pts = {0};
    qc_sample_params sp;

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, &r, sliver, 3));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_normalize(&ctx, &r));
    memset(&sp, 0, sizeof sp);
    sp.kind = QC_SAMPLE_SQUARE;
    sp.spacing = 0.5;
    TEST_ASSERT_TRUE(qc_sample_estimate(&r, &sp) < 1e5);
    TEST_ASSERT_EQUAL_INT(QC_ELIMIT, qc_sample(&ctx, &r, &sp, &pts));
    assert_msg_has("lattice sites");
    TEST_ASSERT_TRUE(ta.peak_bytes < SMALL_PEAK);
    qc_region_free(&ctx, &r);
    assert_clean();
}

/* More given points than QC_MAX_POINTS: refused without copying them. */
static void test_generate_should_refuse_too_many_given_points(void)
{
    qc_region r = {0};
    qc_points given;
    qc_params p;
    qc_result res;
    size_t before;

    given.n = given.cap = (size_t)QC_MAX_POINTS + 1;
    given.v = calloc(given.n, sizeof *given.v); /* the caller's, not counted */
    TEST_ASSERT_NOT_NULL(given.v);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_shape(&ctx, "rect:100x100", 1.0, &r));
    before = ta.peak_bytes;
    memset(&p, 0, sizeof p);
    qc_params_set(&ctx, &p, "family", QC_FAMILY_VINE);
    qc_params_set(&ctx, &p, "points", QC_POINTS_GIVEN);
    TEST_ASSERT_EQUAL_INT(QC_ELIMIT, qc_generate(&ctx, &r, &p, &given, NULL, &res));
    assert_msg_has("4000001 points exceed the limit of 4000000");
    TEST_ASSERT_TRUE(ta.peak_bytes - before < SMALL_PEAK);
    free(given.v);
    qc_region_free(&ctx, &r);
    assert_clean();
}

/* An SVG larger than max_bytes (16 MiB by default) is refused unread. */
static void test_svg_should_refuse_more_than_16_MiB_before_reading(void)
{
    size_t n = ((size_t)16 << 20) + 1;
    char *big = malloc(n);
    qc_region r = {0};
    qc_path path = {0};
    qc_motif_set set = {0};
    qc_svg_opts o;

    TEST_ASSERT_NOT_NULL(big);
    memset(big, ' ', n);
    memcpy(big, "<svg>", 5);
    TEST_ASSERT_EQUAL_INT(QC_ELIMIT, qc_io_read_svg_region(&ctx, big, n, NULL, &r));
    assert_msg_has("16777217 bytes exceed the limit of 16777216");
    TEST_ASSERT_EQUAL_INT(QC_ELIMIT, qc_io_read_svg_path(&ctx, big, n, NULL, &path));
    TEST_ASSERT_EQUAL_INT(QC_ELIMIT, qc_motif_from_svg(&ctx, big, n, "big", &set));
    TEST_ASSERT_EQUAL_size_t(0, set.n);
    memset(&o, 0, sizeof o);
    o.max_bytes = 1000; /* a caller's own, smaller cap */
    TEST_ASSERT_EQUAL_INT(QC_ELIMIT, qc_io_read_svg_region(&ctx, big, 1001, &o, &r));
    TEST_ASSERT_EQUAL_size_t(0, ta.peak_bytes);
    free(big);
    assert_clean();
}

/* 10,001 tiny islands: refused by the SVG reader before normalizing (and
 * by qc_sample for a region built by hand), where they cost seconds. */
static void test_regions_should_refuse_more_rings_than_the_limit(void)
{
    size_t n = QC_MAX_REGION_RINGS + 1, i, at;
    char *svg = malloc(n * 40 + 200);
    qc_region r = {0};
    qc_points pts = {0};
    qc_sample_params sp;

    TEST_ASSERT_NOT_NULL(svg);
    at = (size_t)sprintf(svg, "<svg xmlns=\"http://www.w3.org/2000/svg\"><path d=\"");
    for (i = 0; i < n; i++)
        at += (size_t)sprintf(svg + at, "M%lu %luh0.5v0.5h-0.5z", (unsigned long)(i % 101),
                              (unsigned long)(i / 101));
    at += (size_t)sprintf(svg + at, "\"/></svg>");
    TEST_ASSERT_EQUAL_INT(QC_ELIMIT, qc_io_read_svg_region(&ctx, svg, at, NULL, &r));
    assert_msg_has("more than 10000 outlines and holes");
    qc_region_free(&ctx, &r);
    for (i = 0; i < n; i++) {
        qc_vec2 sq[4];
        sq[0].x = sq[3].x = (double)(i % 101);
        sq[1].x = sq[2].x = sq[0].x + 0.5;
        sq[0].y = sq[1].y = (double)(i / 101);
        sq[2].y = sq[3].y = sq[0].y + 0.5;
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, &r, sq, 4));
    }
    memset(&sp, 0, sizeof sp);
    sp.kind = QC_SAMPLE_POISSON;
    sp.spacing = 0.5;
    TEST_ASSERT_EQUAL_INT(QC_ELIMIT, qc_sample(&ctx, &r, &sp, &pts));
    assert_msg_has("10001 outlines and holes, over the limit of 10000");
    qc_region_free(&ctx, &r);
    qc_points_free(&ctx, &pts);
    free(svg);
    assert_clean();
}

/* The largest-gap raster is capped at 2^22 cells (9 bytes each), however
 * fine the resolution asked for. */
static void test_largest_gap_should_cap_its_raster(void)
{
    qc_region r = {0};
    qc_vec2 pts[2] = {{10, 10}, {900, 900}};
    double g;

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_shape(&ctx, "rect:1000x1000", 1.0, &r));
    g = qc_largest_gap(&ctx, &r, pts, 2, 1e-6, NULL);
    TEST_ASSERT_TRUE(g > 0);
    TEST_ASSERT_TRUE(ta.peak_bytes < ((size_t)9 << 22) + SMALL_PEAK);
    qc_region_free(&ctx, &r);
    assert_clean();
}

/* The complete-graph MST refuses more than 20000 points before its O(n)
 * arrays; the fuzz-sized limits of the SVG tokenizer are tested in
 * test_svg.c. */
static void test_complete_mst_should_refuse_above_twenty_thousand_points(void)
{
    size_t n = 20001;
    qc_vec2 *p = calloc(n, sizeof *p);
    qc_edges e = {0};
    size_t i;

    TEST_ASSERT_NOT_NULL(p);
    for (i = 0; i < n; i++) {
        p[i].x = (double)(i % 200);
        p[i].y = (double)(i / 200);
    }
    TEST_ASSERT_EQUAL_INT(QC_ELIMIT, qc_mst(&ctx, p, n, QC_MST_MODE_COMPLETE, &e));
    TEST_ASSERT_EQUAL_size_t(0, ta.peak_bytes);
    free(p);
}

/* A stitch plan split so finely that it would pass QC_MAX_PLAN_POINTS (a
 * 1 km line at 0.01 mm is 10^8 points) is refused before it grows; just
 * under the cap it would be accepted, so the count is what decides. */
static void test_stitch_plan_should_refuse_too_many_splits_before_growing(void)
{
    static const qc_vec2 a = {0, 0}, b = {1e6, 0};
    qc_path path = {0};
    qc_stitch_params sp;
    qc_plan plan = {0};
    size_t before;

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_move_to(&ctx, &path, a));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_line_to(&ctx, &path, b));
    memset(&sp, 0, sizeof sp);
    sp.max_segment = 0.01;
    sp.min_segment = -1; /* keep all */
    before = ta.peak_bytes;
    TEST_ASSERT_EQUAL_INT(QC_ELIMIT, qc_stitch_plan(&ctx, &path, NULL, &sp, &plan));
    assert_msg_has("would have 1e+08 points, more than the limit of 50000000");
    TEST_ASSERT_TRUE(ta.peak_bytes - before < SMALL_PEAK);
    TEST_ASSERT_EQUAL_size_t(0, plan.n);
    sp.max_segment = 1e6 / (QC_MAX_PLAN_POINTS / 100); /* 5e5 points: fine */
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_stitch_plan(&ctx, &path, NULL, &sp, &plan));
    TEST_ASSERT_EQUAL_size_t(QC_MAX_PLAN_POINTS / 100 + 1, plan.n);
    qc_plan_free(&ctx, &plan);
    qc_path_free(&ctx, &path);
    assert_clean();
}

/* Shapes: sizes up to 1e5 mm; circles at most 4096 segments. */
static void test_shapes_should_cap_size_and_segments(void)
{
    qc_region r = {0};

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_shape(&ctx, "circle:100000", 1.0, &r));
    TEST_ASSERT_TRUE(r.nv <= 4096);
    qc_region_free(&ctx, &r);
    memset(&r, 0, sizeof r);
    TEST_ASSERT_TRUE(qc_region_shape(&ctx, "circle:100001", 1.0, &r) < 0);
    TEST_ASSERT_TRUE(qc_region_shape(&ctx, "rect:1e300x5", 1.0, &r) < 0);
    TEST_ASSERT_EQUAL_size_t(0, r.nv);
    assert_clean();
}

/* Generation is linear-memory, so the point cap bounds memory too: peak
 * bytes per point at about 8000 points stay within twice those at about
 * 2000, and under 4 KiB (docs/limits.md lists each family's figure). */
static void test_generate_should_use_memory_linear_in_the_points(void)
{
    int family, measured = 0;

    for (family = 1; family < QC_FAMILY_COUNT; family++) {
        double per_point[2];
        int k, skip = 0;

        if (family == QC_FAMILY_ECHO || family == QC_FAMILY_SPIRAL || family == QC_FAMILY_MEANDER)
            continue; /* no points: their grid is capped on its own (meander: test_meander) */
        for (k = 0; k < 2 && !skip; k++) {
            qc_region r = {0};
            qc_params p;
            qc_result res;
            int rc;

            setUp();
            TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_shape(&ctx, k ? "square:1000" : "square:500",
                                                         1.0, &r));
            memset(&p, 0, sizeof p);
            qc_params_set(&ctx, &p, "family", family);
            qc_params_set(&ctx, &p, "spacing", 10);
            rc = qc_generate(&ctx, &r, &p, NULL, NULL, &res);
            if (rc == QC_EUNSUPPORTED) {
                skip = 1;
            } else {
                TEST_ASSERT_EQUAL_INT_MESSAGE(QC_OK, rc, qc_family_name(family));
                TEST_ASSERT_TRUE(res.points.n > (k ? 6000u : 1500u));
                per_point[k] = (double)ta.peak_bytes / (double)res.points.n;
            }
            qc_result_free(&ctx, &res);
            qc_region_free(&ctx, &r);
            assert_clean();
        }
        if (skip)
            continue;
        if (getenv("QC_LIMITS_PRINT"))
            printf("%s: %.0f %.0f B/point\n", qc_family_name(family), per_point[0], per_point[1]);
        TEST_ASSERT_TRUE_MESSAGE(per_point[1] < 2.0 * per_point[0], qc_family_name(family));
        TEST_ASSERT_TRUE_MESSAGE(per_point[1] < 4096.0, qc_family_name(family));
        measured++;
    }
    TEST_ASSERT_TRUE(measured >= 5);
}

/* Packing's copies budget grows with the block (issue 21): a heart packing
 * of the 10^6-point blocks (10 m at d = 10 mm and 3 m at 3 mm, on the
 * default snub lattice) fits it, where the fixed 4e6 cap refused it, and a
 * 60,000-point motif is still refused there. The pebbles per point come
 * from a real packing of a small block, the count from the sampler's
 * estimate: no 10^6 run in the suite. */
static void test_packing_budget_should_admit_a_million_point_block(void)
{
    static const struct {
        const char *shape;
        double d;
    } block[] = {{"square:10000", 10}, {"square:3000", 3}};
    qc_region r = {0};
    qc_params p;
    qc_result res;
    qc_motif_set heart = {0};
    double per_point, copy;
    size_t k;

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_motif_builtin(&ctx, "heart", &heart));
    copy = (double)heart.m[0].path.npt;
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_shape(&ctx, "square:500", 1.0, &r));
    memset(&p, 0, sizeof p);
    qc_params_set(&ctx, &p, "family", QC_FAMILY_PACKING);
    qc_params_set(&ctx, &p, "spacing", 10);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_generate(&ctx, &r, &p, NULL, &heart, &res));
    per_point = (double)res.stats.pebbles / (double)res.points.n;
    TEST_ASSERT_TRUE(per_point > 1.0 && per_point < 1.6);
    qc_result_free(&ctx, &res);
    qc_region_free(&ctx, &r);
    for (k = 0; k < sizeof block / sizeof *block; k++) {
        qc_sample_params sp = {QC_SAMPLE_SNUB, 0, 0, 0, 0, 0};
        double n, need;
        memset(&r, 0, sizeof r);
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_shape(&ctx, block[k].shape, 1.0, &r));
        sp.spacing = block[k].d;
        sp.margin = 0.3 * block[k].d;
        n = qc_sample_estimate(&r, &sp);
        TEST_ASSERT_TRUE(n > 9e5 && n < (double)QC_MAX_POINTS);
        need = 1.1 * n * per_point * copy; /* 10% over: the big block's own ratio */
        TEST_ASSERT_TRUE(need > (double)QC_MAX_PACKED_POINTS); /* the old cap's refusal */
        TEST_ASSERT_TRUE(need <= QC_PACKED_POINTS_BUDGET(n));
        TEST_ASSERT_TRUE(n * per_point * 60001.0 > QC_PACKED_POINTS_BUDGET(n));
        /* and memory stays within the goal: a motif point costs well under
         * 1 KB / QC_PACKED_POINTS_PER_POINT bytes downstream */
        TEST_ASSERT_TRUE(QC_PACKED_POINTS_BUDGET(n) / n * 17.0 * 2 < 1024.0);
        qc_region_free(&ctx, &r);
    }
    qc_motif_set_free(&ctx, &heart);
    assert_clean();
}

/* Packing refuses a motif too detailed for the block from the skeleton's
 * points and the motif's vertices, before the pebbles are packed: the
 * refused call allocates nothing (packing the 2,500 pebbles first, as the
 * exact count after placement needs, allocates their grid and arrays). */
static void test_packing_should_refuse_a_detailed_motif_before_packing(void)
{
    enum { SIDES = 2000, PER_ROW = 50 };
    static char svg[SIDES * 40 + 128];
    qc_motif_set set = {0};
    qc_region r = {0};
    qc_points pts = {0};
    qc_order order = {0};
    qc_skeleton sk;
    qc_params p;
    qc_path out = {0};
    size_t k, at, allocs, peak;

    at = (size_t)sprintf(svg, "<svg xmlns=\"http://www.w3.org/2000/svg\"><polygon points=\"");
    for (k = 0; k < SIDES; k++) /* a circle of SIDES straight sides */
        at += (size_t)sprintf(svg + at, "%.4f,%.4f ", 50 + 40 * cos(6.283185307 * k / SIDES),
                              50 + 40 * sin(6.283185307 * k / SIDES));
    sprintf(svg + at, "\"/></svg>");
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_motif_from_svg(&ctx, svg, strlen(svg), "ring", &set));
    TEST_ASSERT_TRUE(set.m[0].path.npt >= SIDES);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_shape(&ctx, "square:500", 1.0, &r));
    for (k = 0; k < PER_ROW * PER_ROW; k++) { /* a 10 mm lattice, one row after another */
        qc_vec2 v = {5.0 + 10.0 * (double)(k % PER_ROW), 5.0 + 10.0 * (double)(k / PER_ROW)};
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_points_push(&ctx, &pts, v));
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_order_push(&ctx, &order, (uint32_t)k));
    }
    TEST_ASSERT_TRUE((double)pts.n * (double)set.m[0].path.npt > QC_PACKED_POINTS_BUDGET(pts.n));
    memset(&sk, 0, sizeof sk);
    sk.p = pts.v;
    sk.n = pts.n;
    sk.order = order.i;
    sk.norder = order.n;
    memset(&p, 0, sizeof p);
    p.spacing = 10;
    p.r_seed = 0.7;
    allocs = ta.allocs;
    peak = ta.peak_bytes;
    TEST_ASSERT_EQUAL_INT(QC_ELIMIT, qc_deco_packing(&ctx, &r, &p, &sk, &set, &out, NULL));
    TEST_ASSERT_EQUAL_size_t(allocs, ta.allocs); /* refused before any work */
    TEST_ASSERT_EQUAL_size_t(peak, ta.peak_bytes);
    TEST_ASSERT_EQUAL_size_t(0, out.ncmd);
    TEST_ASSERT_NULL(strchr(qc_errmsg(&ctx), '\n'));
    assert_msg_has("spacing 10 mm");
    assert_msg_has("motif ring");
    assert_msg_has("exceed the limit of 4000000");
    qc_points_free(&ctx, &pts);
    qc_order_free(&ctx, &order);
    qc_region_free(&ctx, &r);
    qc_motif_set_free(&ctx, &set);
    assert_clean();
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_generate_should_refuse_ten_billion_points_before_allocating);
    RUN_TEST(test_sample_should_refuse_a_billion_points_for_every_kind);
    RUN_TEST(test_sample_should_refuse_a_sliver_whose_box_is_huge);
    RUN_TEST(test_generate_should_refuse_too_many_given_points);
    RUN_TEST(test_svg_should_refuse_more_than_16_MiB_before_reading);
    RUN_TEST(test_regions_should_refuse_more_rings_than_the_limit);
    RUN_TEST(test_largest_gap_should_cap_its_raster);
    RUN_TEST(test_complete_mst_should_refuse_above_twenty_thousand_points);
    RUN_TEST(test_stitch_plan_should_refuse_too_many_splits_before_growing);
    RUN_TEST(test_shapes_should_cap_size_and_segments);
    RUN_TEST(test_generate_should_use_memory_linear_in_the_points);
    RUN_TEST(test_packing_budget_should_admit_a_million_point_block);
    RUN_TEST(test_packing_should_refuse_a_detailed_motif_before_packing);
    return UNITY_END();
}
