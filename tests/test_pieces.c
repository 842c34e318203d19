/* Regions of separate pieces: split into pieces, sewn piece by piece with
 * a jump between, and stitched segments leaving a region found. */
#include <math.h>
#include <string.h>

#include "quiltc.h"
#include "testalloc.h"
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
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
    TEST_ASSERT_FALSE(ta.size_mismatch);
}

static void square(qc_region *r, double x0, double y0, double s, int ccw)
{
    qc_vec2 v[4];

    v[0].x = x0, v[0].y = y0;
    v[1].x = x0 + s, v[1].y = y0;
    v[2].x = x0 + s, v[2].y = y0 + s;
    v[3].x = x0, v[3].y = y0 + s;
    if (!ccw) {
        qc_vec2 t = v[1];
        v[1] = v[3];
        v[3] = t;
    }
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, r, v, 4));
}

/* "O" and "B" as squares with square holes, and an island in the O's hole. */
static void ob_region(qc_region *r)
{
    memset(r, 0, sizeof *r);
    square(r, 0, 0, 60, 1);      /* O */
    square(r, 15, 15, 30, 1);    /* its hole (orientation fixed by normalize) */
    square(r, 25, 25, 10, 1);    /* an island in the hole */
    square(r, 80, 0, 60, 1);     /* B */
    square(r, 90, 10, 15, 1);    /* its two holes */
    square(r, 90, 35, 15, 1);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_normalize(&ctx, r));
}

static void test_pieces_should_keep_each_outline_with_its_own_holes(void)
{
    qc_region r, *pieces;
    size_t n, k;
    double sum = 0;

    ob_region(&r);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_pieces(&ctx, &r, &pieces, &n));
    TEST_ASSERT_EQUAL_size_t(3, n);
    TEST_ASSERT_EQUAL_size_t(2, pieces[0].nrings); /* O and its hole */
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 3600 - 900, qc_region_area(&pieces[0]));
    TEST_ASSERT_EQUAL_size_t(1, pieces[1].nrings); /* the island */
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 100, qc_region_area(&pieces[1]));
    TEST_ASSERT_EQUAL_size_t(3, pieces[2].nrings); /* B and its two holes */
    for (k = 0; k < n; k++)
        sum += qc_region_area(&pieces[k]);
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, qc_region_area(&r), sum);
    qc_region_pieces_free(&ctx, pieces, n);
    qc_region_free(&ctx, &r);
}

/* Every sewn segment of path (flattened, jumps excluded) stays in r. */
static void assert_segments_inside(const qc_region *r, const qc_path *path)
{
    qc_plan plan = {0};
    size_t out = 99;
    qc_vec2 at;
    qc_stitch_params sp;

    memset(&sp, 0, sizeof sp);
    sp.min_segment = -1;
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_stitch_plan(&ctx, path, NULL, &sp, &plan));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_plan_segments_outside(r, &plan, 0.05, &out, &at));
    TEST_ASSERT_EQUAL_size_t(0, out);
    qc_plan_free(&ctx, &plan);
}

static void test_generate_should_sew_each_piece_and_jump_between(void)
{
    static const int fam[] = {QC_FAMILY_STIPPLE, QC_FAMILY_PEBBLING, QC_FAMILY_ECHO,
                              QC_FAMILY_SPIRAL, QC_FAMILY_BRANCHING};
    qc_region r;
    size_t f;

    ob_region(&r);
    for (f = 0; f < sizeof fam / sizeof fam[0]; f++) {
        qc_params p;
        qc_result res;

        memset(&p, 0, sizeof p);
        qc_params_set(&ctx, &p, "family", fam[f]);
        qc_params_set(&ctx, &p, "spacing", 4);
        TEST_ASSERT_EQUAL_INT_MESSAGE(QC_OK, qc_generate(&ctx, &r, &p, NULL, NULL, &res),
                                      qc_errmsg(&ctx));
        TEST_ASSERT_TRUE_MESSAGE(qc_path_pieces(&res.path) >= 3, qc_family_name(fam[f]));
        TEST_ASSERT_EQUAL_size_t(qc_path_pieces(&res.path), res.stats.pieces);
        TEST_ASSERT_TRUE(res.stats.length_mm > 0);
        assert_segments_inside(&r, &res.path);
        qc_result_free(&ctx, &res);
    }
    qc_region_free(&ctx, &r);
}

static void test_given_points_should_go_to_their_piece(void)
{
    qc_region r = {0};
    qc_points given = {0};
    qc_params p;
    qc_result res;
    size_t i;

    square(&r, 0, 0, 40, 1);
    square(&r, 60, 0, 40, 1);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_normalize(&ctx, &r));
    for (i = 0; i < 8; i++) {
        qc_vec2 a = {5 + 4.0 * (double)i, 10 + (double)(i % 3) * 8};
        qc_vec2 b = {65 + 4.0 * (double)i, 12 + (double)(i % 2) * 9};
        qc_points_push(&ctx, &given, a);
        qc_points_push(&ctx, &given, b);
    }
    memset(&p, 0, sizeof p);
    qc_params_set(&ctx, &p, "points", QC_POINTS_GIVEN);
    qc_params_set(&ctx, &p, "family", QC_FAMILY_VINE);
    TEST_ASSERT_EQUAL_INT_MESSAGE(QC_OK, qc_generate(&ctx, &r, &p, &given, NULL, &res),
                                  qc_errmsg(&ctx));
    TEST_ASSERT_EQUAL_size_t(2, qc_path_pieces(&res.path));
    TEST_ASSERT_EQUAL_size_t(16, res.points.n);
    TEST_ASSERT_EQUAL_size_t(14, res.edges.n); /* a tree per piece */
    assert_segments_inside(&r, &res.path);
    qc_result_free(&ctx, &res);
    qc_points_free(&ctx, &given);
    qc_region_free(&ctx, &r);
}

static void test_segment_across_the_gap_should_be_found(void)
{
    qc_region r = {0};
    qc_plan plan = {0};
    size_t n = 0;
    qc_vec2 at = {0, 0};

    square(&r, 0, 0, 40, 1);
    square(&r, 60, 0, 40, 1);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_normalize(&ctx, &r));
    qc_plan_push(&ctx, &plan, (qc_vec2){10, 10}, QC_ST_JUMP);
    qc_plan_push(&ctx, &plan, (qc_vec2){30, 30}, 0);   /* inside */
    qc_plan_push(&ctx, &plan, (qc_vec2){70, 30}, 0);   /* both ends in, crosses the gap */
    qc_plan_push(&ctx, &plan, (qc_vec2){20, 5}, QC_ST_JUMP); /* a jump is not sewn */
    qc_plan_push(&ctx, &plan, (qc_vec2){40, 5}, 0);    /* along the edge: inside */
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_plan_segments_outside(&r, &plan, 0.05, &n, &at));
    TEST_ASSERT_EQUAL_size_t(1, n);
    TEST_ASSERT_TRUE(at.x > 40 && at.x < 60);
    qc_plan_free(&ctx, &plan);
    qc_region_free(&ctx, &r);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_pieces_should_keep_each_outline_with_its_own_holes);
    RUN_TEST(test_generate_should_sew_each_piece_and_jump_between);
    RUN_TEST(test_given_points_should_go_to_their_piece);
    RUN_TEST(test_segment_across_the_gap_should_be_found);
    return UNITY_END();
}
