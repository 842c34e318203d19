/* Core: status codes, the context, allocation, arrays, paths, the PRNG, deterministic math. */
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
}

static void status_codes_should_have_names_and_texts(void)
{
    TEST_ASSERT_EQUAL_STRING("ENOMEM", qc_err_name(QC_ENOMEM));
    TEST_ASSERT_EQUAL_STRING("out of memory", qc_strerror(QC_ENOMEM));
    TEST_ASSERT_EQUAL_STRING("OK", qc_err_name(QC_OK));
    TEST_ASSERT_EQUAL_STRING("unknown error", qc_strerror(12345));
    TEST_ASSERT_EQUAL_STRING("EUNKNOWN", qc_err_name(-999));
    TEST_ASSERT_EQUAL_STRING(QC_VERSION_STRING, qc_version());
}

static void push_should_grow_and_free_without_leaks(void)
{
    qc_points pts = {0};
    qc_order ord = {0};
    qc_edges ed = {0};
    uint32_t i;

    for (i = 0; i < 1000; i++) {
        qc_vec2 p = {i, -(double)i};
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_points_push(&ctx, &pts, p));
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_order_push(&ctx, &ord, i));
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_edges_push(&ctx, &ed, i, i + 1));
    }
    TEST_ASSERT_EQUAL_size_t(1000, pts.n);
    TEST_ASSERT_EQUAL_DOUBLE(-999.0, pts.v[999].y);
    TEST_ASSERT_EQUAL_UINT32(1000, ed.e[999].b);
    qc_points_free(&ctx, &pts);
    qc_order_free(&ctx, &ord);
    qc_edges_free(&ctx, &ed);
    qc_points_free(&ctx, &pts); /* twice is harmless */
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
    TEST_ASSERT_FALSE(ta.size_mismatch);
}

static void push_should_report_enomem_and_keep_data(void)
{
    qc_points pts = {0};
    qc_vec2 p = {1, 2};
    int i, rc = QC_OK;

    ta.fail_at = 2; /* first growth succeeds, second fails */
    for (i = 0; i < 100 && rc == QC_OK; i++)
        rc = qc_points_push(&ctx, &pts, p);
    TEST_ASSERT_EQUAL_INT(QC_ENOMEM, rc);
    TEST_ASSERT_EQUAL_size_t(16, pts.n);
    TEST_ASSERT_EQUAL_INT(QC_ENOMEM, ctx.status);
    TEST_ASSERT_TRUE(strstr(qc_errmsg(&ctx), "out of memory") != NULL);
    qc_points_free(&ctx, &pts);
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

static void path_should_count_points_and_join_pieces(void)
{
    qc_path a = {0}, b = {0};
    qc_vec2 p0 = {0, 0}, p1 = {1, 0}, p2 = {2, 1}, p3 = {3, 3};

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_move_to(&ctx, &a, p0));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_cubic_to(&ctx, &a, p1, p2, p3));
    TEST_ASSERT_EQUAL_size_t(4, a.npt);
    TEST_ASSERT_EQUAL_DOUBLE(3.0, qc_path_last(&a).y);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_move_to(&ctx, &b, p3));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_line_to(&ctx, &b, p0));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_append(&ctx, &a, &b, 1));
    TEST_ASSERT_EQUAL_size_t(1, qc_path_pieces(&a));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_append(&ctx, &a, &b, 0));
    TEST_ASSERT_EQUAL_size_t(2, qc_path_pieces(&a));
    TEST_ASSERT_EQUAL_size_t(6, a.ncmd);
    qc_path_free(&ctx, &a);
    qc_path_free(&ctx, &b);
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

static void rng_should_repeat_for_a_seed_and_differ_across_seeds(void)
{
    qc_rng a, b, c;
    int i, same = 0;
    uint64_t counts[4] = {0, 0, 0, 0};

    qc_rng_seed(&a, 42);
    qc_rng_seed(&b, 42);
    qc_rng_seed(&c, 43);
    for (i = 0; i < 1000; i++) {
        uint64_t x = qc_rng_u64(&a);
        TEST_ASSERT_EQUAL_UINT64(x, qc_rng_u64(&b));
        same += x == qc_rng_u64(&c);
    }
    TEST_ASSERT_EQUAL_INT(0, same);
    for (i = 0; i < 40000; i++) {
        double u = qc_rng_unit(&a);
        TEST_ASSERT_TRUE(u >= 0.0 && u < 1.0);
        counts[qc_rng_below(&a, 4)]++;
    }
    for (i = 0; i < 4; i++)
        TEST_ASSERT_DOUBLE_WITHIN(500.0, 10000.0, (double)counts[i]);
    /* xoshiro256** reference value for splitmix64-seeded state from 0 */
    qc_rng_seed(&a, 0);
    TEST_ASSERT_EQUAL_HEX64(UINT64_C(0x99ec5f36cb75f2b4), qc_rng_u64(&a));
}

static void math_should_match_libm_closely(void)
{
    double x, worst = 0.0;

    for (x = -50.0; x <= 50.0; x += 0.01) {
        worst = fmax(worst, fabs(qc_sin(x) - sin(x)));
        worst = fmax(worst, fabs(qc_cos(x) - cos(x)));
        worst = fmax(worst, fabs(qc_atan2(x, 1.7) - atan2(x, 1.7)));
        worst = fmax(worst, fabs(qc_atan2(-1.3, x) - atan2(-1.3, x)));
    }
    TEST_ASSERT_LESS_THAN_DOUBLE(4e-15, worst);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, qc_atan2(0.0, 0.0));
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, QC_PI, qc_atan2(0.0, -1.0));
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, -QC_PI / 2, qc_atan2(-5.0, 0.0));
    TEST_ASSERT_TRUE(isnan(qc_sin((double)NAN)));
    TEST_ASSERT_EQUAL_DOUBLE(5.0, qc_hypot(3.0, 4.0));
}

/* An error message is one line whatever the quoted input held. */
static void errors_should_be_one_line(void)
{
    qc_region r;
    const char *m;

    TEST_ASSERT_EQUAL_INT(QC_EINVAL, qc_region_shape(&ctx, "blob\nsecond\rthird\tx:1", 1.0, &r));
    m = qc_errmsg(&ctx);
    TEST_ASSERT_NOT_NULL(strstr(m, "unknown shape 'blob second third x:1'"));
    for (; *m; m++)
        TEST_ASSERT_TRUE((unsigned char)*m >= 0x20);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(status_codes_should_have_names_and_texts);
    RUN_TEST(push_should_grow_and_free_without_leaks);
    RUN_TEST(push_should_report_enomem_and_keep_data);
    RUN_TEST(path_should_count_points_and_join_pieces);
    RUN_TEST(rng_should_repeat_for_a_seed_and_differ_across_seeds);
    RUN_TEST(math_should_match_libm_closely);
    RUN_TEST(errors_should_be_one_line);
    return UNITY_END();
}
