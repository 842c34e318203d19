/* qc_generate: the composition the CLI and the page share. */
#include <math.h>
#include <string.h>

#include "quiltc.h"
#include "testalloc.h"
#include "unity.h"

static testalloc ta;
static qc_ctx ctx;
static qc_region block;

void setUp(void)
{
    memset(&ta, 0, sizeof ta);
    qc_ctx_init(&ctx, testalloc_fn, &ta);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_shape(&ctx, "rect:120x90", 1.0, &block));
}

void tearDown(void)
{
    qc_region_free(&ctx, &block);
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

static void same_path(const qc_path *a, const qc_path *b)
{
    TEST_ASSERT_EQUAL_size_t(a->ncmd, b->ncmd);
    TEST_ASSERT_EQUAL_size_t(a->npt, b->npt);
    TEST_ASSERT_EQUAL_MEMORY(a->cmd, b->cmd, a->ncmd);
    TEST_ASSERT_EQUAL_MEMORY(a->pt, b->pt, a->npt * sizeof *a->pt);
}

/* The preview's shortcut changes nothing but the statistic. */
static void test_skipping_the_gap_stat_keeps_the_path(void)
{
    static const int families[] = {QC_FAMILY_STIPPLE, QC_FAMILY_FILL, QC_FAMILY_ECHO,
                                   QC_FAMILY_SPIRAL};
    size_t i;

    for (i = 0; i < sizeof families / sizeof families[0]; i++) {
        qc_params p;
        qc_result a, b;

        memset(&p, 0, sizeof p);
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "family", families[i]));
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_generate(&ctx, &block, &p, NULL, NULL, &a));
        p.skip_gap_stat = 1;
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_generate(&ctx, &block, &p, NULL, NULL, &b));
        same_path(&a.path, &b.path);
        TEST_ASSERT_GREATER_THAN_DOUBLE(0.0, a.stats.largest_gap_mm);
        TEST_ASSERT_EQUAL_DOUBLE(0.0, b.stats.largest_gap_mm);
        qc_result_free(&ctx, &a);
        qc_result_free(&ctx, &b);
    }
}

/* The root is the point nearest the requested start, else the block's corner. */
static void test_walk_starts_nearest_the_start_point(void)
{
    qc_params p;
    qc_result r;
    qc_vec2 want;

    memset(&p, 0, sizeof p);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "family", QC_FAMILY_VINE));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_generate(&ctx, &block, &p, NULL, NULL, &r));
    want.x = want.y = 0;
    TEST_ASSERT_EQUAL_UINT32(qc_nearest_point(r.points.v, r.points.n, want), r.order.i[0]);
    qc_result_free(&ctx, &r);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "start-x", 100.0));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "start-y", 80.0));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_generate(&ctx, &block, &p, NULL, NULL, &r));
    want.x = 100;
    want.y = 80;
    TEST_ASSERT_EQUAL_UINT32(qc_nearest_point(r.points.v, r.points.n, want), r.order.i[0]);
    TEST_ASSERT_EQUAL_UINT32(r.order.i[0], r.order.i[r.order.n - 1]);
    qc_result_free(&ctx, &r);
}

/* A caller's tour (ctx->tour): how it was asked, and what it answers. */
typedef struct hook_log {
    int calls, mode; /* mode 0: points in reverse; 1: a point twice; 2: fails */
    size_t n;
    double budget_ms;
} hook_log;

static int hook_tour(void *ud, const qc_vec2 *pts, size_t n, double budget_ms, qc_order *order)
{
    hook_log *h = (hook_log *)ud;
    size_t i;

    (void)pts;
    h->calls++;
    h->n = n;
    h->budget_ms = budget_ms;
    if (h->mode == 2)
        return QC_EUNSUPPORTED;
    for (i = 0; i < n; i++)
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_order_push(&ctx, order, (uint32_t)(n - 1 - i)));
    if (h->mode == 1)
        order->i[1] = order->i[0];
    return QC_OK;
}

/* The tour skeleton asks the caller's tour once, starts it at the root,
 * and refuses one that is not a permutation; a failure is passed on. */
static void test_a_callers_tour_is_used_once_and_checked(void)
{
    hook_log h;
    qc_params p;
    qc_result r;
    size_t i;

    memset(&h, 0, sizeof h);
    ctx.tour = hook_tour;
    ctx.tour_ud = &h;
    memset(&p, 0, sizeof p);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "family", QC_FAMILY_WANDERER));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "tsp-time", 250.0));
    TEST_ASSERT_EQUAL_INT_MESSAGE(QC_OK, qc_generate(&ctx, &block, &p, NULL, NULL, &r),
                                  qc_errmsg(&ctx));
    TEST_ASSERT_EQUAL_INT(1, h.calls);
    TEST_ASSERT_EQUAL_DOUBLE(250.0, h.budget_ms);
    TEST_ASSERT_EQUAL_size_t(r.points.n, h.n);
    TEST_ASSERT_EQUAL_size_t(r.points.n, r.order.n);
    for (i = 0; i + 1 < r.order.n; i++) /* the reverse order, rotated */
        TEST_ASSERT_EQUAL_UINT32((r.order.i[i] + r.points.n - 1) % r.points.n, r.order.i[i + 1]);
    TEST_ASSERT_GREATER_THAN_DOUBLE(0.0, r.stats.farthest_fabric_mm); /* measured as ever */
    qc_result_free(&ctx, &r);

    h.mode = 1;
    TEST_ASSERT_EQUAL_INT(QC_EINVAL, qc_generate(&ctx, &block, &p, NULL, NULL, &r));
    TEST_ASSERT_NOT_NULL(strstr(qc_errmsg(&ctx), "not a permutation"));
    TEST_ASSERT_EQUAL_size_t(0, r.path.ncmd);
    h.mode = 2;
    TEST_ASSERT_EQUAL_INT(QC_EUNSUPPORTED, qc_generate(&ctx, &block, &p, NULL, NULL, &r));
    /* tree skeletons never ask */
    h.calls = 0;
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "family", QC_FAMILY_VINE));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_generate(&ctx, &block, &p, NULL, NULL, &r));
    TEST_ASSERT_EQUAL_INT(0, h.calls);
    qc_result_free(&ctx, &r);
}

/* Given points are used as they are; an empty set is refused by name. */
static void test_given_points(void)
{
    qc_params p;
    qc_result r;
    qc_points given = {0};
    qc_vec2 v;
    int i, j;

    memset(&p, 0, sizeof p);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "points", QC_POINTS_GIVEN));
    TEST_ASSERT_EQUAL_INT(QC_EEMPTY, qc_generate(&ctx, &block, &p, &given, NULL, &r));
    TEST_ASSERT_NOT_NULL(strstr(qc_errmsg(&ctx), "no points were supplied"));
    for (j = 0; j < 3; j++)
        for (i = 0; i < 4; i++) {
            v.x = 20 + 25 * i;
            v.y = 20 + 25 * j;
            TEST_ASSERT_EQUAL_INT(QC_OK, qc_points_push(&ctx, &given, v));
        }
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_generate(&ctx, &block, &p, &given, NULL, &r));
    TEST_ASSERT_EQUAL_size_t(12, r.stats.points);
    TEST_ASSERT_EQUAL_MEMORY(given.v, r.points.v, 12 * sizeof *given.v);
    TEST_ASSERT_EQUAL_size_t(1, r.stats.pieces);
    qc_result_free(&ctx, &r);
    qc_points_free(&ctx, &given);
}

/* A given point beyond the block, or nearer its edge than the margin, is
 * refused by number: its decoration would be sewn outside the block. */
static void test_given_points_outside_the_region_are_refused(void)
{
    static const qc_vec2 far = {200, 40}, edge = {60, 1}, ok = {60, 45};
    const qc_vec2 *bad[2];
    qc_params p;
    qc_result r;
    int k;

    bad[0] = &far;
    bad[1] = &edge;
    for (k = 0; k < 2; k++) {
        qc_points given = {0};
        memset(&p, 0, sizeof p);
        qc_params_set(&ctx, &p, "points", QC_POINTS_GIVEN);
        qc_params_set(&ctx, &p, "margin", 2.0);
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_points_push(&ctx, &given, ok));
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_points_push(&ctx, &given, *bad[k]));
        TEST_ASSERT_EQUAL_INT(QC_ERANGE, qc_generate(&ctx, &block, &p, &given, NULL, &r));
        TEST_ASSERT_NOT_NULL(strstr(qc_errmsg(&ctx), "given point 2 ("));
        TEST_ASSERT_NOT_NULL(strstr(qc_errmsg(&ctx), "by the margin 2 mm"));
        TEST_ASSERT_EQUAL_size_t(0, r.path.npt);
        given.n = 1; /* the good point alone is accepted */
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_generate(&ctx, &block, &p, &given, NULL, &r));
        qc_result_free(&ctx, &r);
        qc_points_free(&ctx, &given);
    }
}

static void test_a_block_smaller_than_the_margin_is_refused(void)
{
    qc_region tiny;
    qc_params p;
    qc_result r;

    memset(&p, 0, sizeof p);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_shape(&ctx, "circle:3", 1.0, &tiny));
    TEST_ASSERT_EQUAL_INT(QC_EEMPTY, qc_generate(&ctx, &tiny, &p, NULL, NULL, &r));
    TEST_ASSERT_NOT_NULL(strstr(qc_errmsg(&ctx), "no point fits in the region at spacing 12.7 mm"));
    qc_region_free(&ctx, &tiny);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_skipping_the_gap_stat_keeps_the_path);
    RUN_TEST(test_walk_starts_nearest_the_start_point);
    RUN_TEST(test_a_callers_tour_is_used_once_and_checked);
    RUN_TEST(test_given_points);
    RUN_TEST(test_given_points_outside_the_region_are_refused);
    RUN_TEST(test_a_block_smaller_than_the_margin_is_refused);
    return UNITY_END();
}
