/* qc_io_check_pat: every dialect fault reported, coordinates still read. */
#include <string.h>

#include "quiltc.h"
#include "testalloc.h"
#include "unity.h"

static qc_ctx ctx;
static testalloc ta;
static char kinds[1024];
static size_t first_line;

void setUp(void)
{
    memset(&ta, 0, sizeof ta);
    qc_ctx_init(&ctx, testalloc_fn, &ta);
    kinds[0] = '\0';
    first_line = 0;
}

void tearDown(void)
{
}

static void collect(void *ud, size_t line, const char *kind, const char *text)
{
    (void)ud;
    (void)text;
    if (first_line == 0)
        first_line = line;
    if (strlen(kinds) + strlen(kind) + 2 < sizeof kinds) {
        strcat(kinds, kind);
        strcat(kinds, " ");
    }
}

static size_t lint(const char *text, qc_plan *plan)
{
    size_t findings = 99;

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_io_check_pat(&ctx, text, strlen(text), collect, NULL,
                                                 plan, &findings));
    return findings;
}

static void good_file_should_have_no_findings(void)
{
    qc_plan plan;

    TEST_ASSERT_EQUAL_size_t(0, lint("N1G00X1.000Y2.000\r\nN2G01X1.500Y2.250\r\nN3M02\r\n", &plan));
    TEST_ASSERT_EQUAL_size_t(2, plan.n);
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 38.1, plan.p[1].x);
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 57.15, plan.p[1].y);
    TEST_ASSERT_EQUAL_INT(QC_ST_JUMP, plan.flags[0]);
    TEST_ASSERT_EQUAL_INT(0, plan.flags[1]);
    qc_plan_free(&ctx, &plan);
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

static void each_fault_should_be_reported(void)
{
    qc_plan plan;
    size_t n = lint("N1G00X1.000Y2.000\n"   /* LF */
                    "N3G01X1.5Y2.250\r\n"    /* numbering, decimals */
                    "N4G05X1.000Y1.000\r\n"  /* unknown command */
                    "N5G00X2.000Y2.000\r\n", /* a jump (geometry, not dialect) */
                    &plan);

    TEST_ASSERT_EQUAL_size_t(5, n);
    TEST_ASSERT_EQUAL_STRING("numbering decimals dialect line-ending dialect ", kinds);
    TEST_ASSERT_EQUAL_size_t(2, first_line);
    TEST_ASSERT_EQUAL_size_t(3, plan.n); /* the G05 line is not a point */
    TEST_ASSERT_EQUAL_INT(QC_ST_JUMP, plan.flags[2]);
    qc_plan_free(&ctx, &plan);
}

static void content_after_m02_and_garbage_should_be_reported(void)
{
    qc_plan plan;
    size_t n = lint("N1G00X1.000Y2.000\r\nN2M02\r\nN3G01X1.000Y1.000\r\n", &plan);

    TEST_ASSERT_EQUAL_size_t(1, n);
    qc_plan_free(&ctx, &plan);
    kinds[0] = '\0';
    n = lint("\x01\x02garbage\r\nhello", &plan);
    TEST_ASSERT_EQUAL_size_t(3, n); /* two malformed lines, no M02 */
    TEST_ASSERT_EQUAL_size_t(0, plan.n);
    qc_plan_free(&ctx, &plan);
}

/* What the strict reader (qc_io_read_pat) refuses is a finding here too:
 * a '+' sign, more than 6 integer digits, and a coordinate beyond the
 * writers' 1e6 mm (a 25 km stitch). */
static void what_the_reader_refuses_should_be_reported(void)
{
    static const char *const bad[] = {
        "N1G00X0.000Y0.000\r\nN2G01X+1.000Y0.000\r\nN3M02\r\n",
        "N1G00X0.000Y0.000\r\nN2G01X1234567.000Y0.000\r\nN3M02\r\n",
        "N1G00X0.000Y0.000\r\nN2G01X984252.000Y0.000\r\nN3M02\r\n",
    };
    static const char *const want[] = {"dialect ", "dialect range ", "range "};
    size_t i;

    for (i = 0; i < 3; i++) {
        qc_plan plan, strict = {0};
        kinds[0] = '\0';
        TEST_ASSERT_EQUAL_size_t(strlen(want[i]) / 6, lint(bad[i], &plan));
        TEST_ASSERT_EQUAL_STRING(want[i], kinds);
        TEST_ASSERT_TRUE(plan.p[1].x <= 1e6); /* measures stay finite and bounded */
        TEST_ASSERT_TRUE(qc_io_read_pat(&ctx, bad[i], strlen(bad[i]), &strict) < 0 ||
                         strict.p[1].x > 1e6);
        qc_plan_free(&ctx, &strict);
        qc_plan_free(&ctx, &plan);
    }
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

static void out_of_memory_should_leave_nothing(void)
{
    static const char text[] = "N1G00X1.000Y2.000\r\nN2G01X1.500Y2.250\r\nN3M02\r\n";
    size_t k, findings;
    qc_plan plan;
    int rc;

    for (k = 1; k < 20; k++) {
        memset(&ta, 0, sizeof ta);
        ta.fail_at = k;
        rc = qc_io_check_pat(&ctx, text, strlen(text), NULL, NULL, &plan, &findings);
        if (rc == QC_OK) {
            qc_plan_free(&ctx, &plan);
            break;
        }
        TEST_ASSERT_EQUAL_INT(QC_ENOMEM, rc);
        TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
    }
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(good_file_should_have_no_findings);
    RUN_TEST(each_fault_should_be_reported);
    RUN_TEST(content_after_m02_and_garbage_should_be_reported);
    RUN_TEST(what_the_reader_refuses_should_be_reported);
    RUN_TEST(out_of_memory_should_leave_nothing);
    return UNITY_END();
}
