/*
 * The core's one number reader (qc__scan_number, src/core/number.c): its
 * spans, correct rounding, and that the shape specs, point files and SVG
 * all read through it, whatever LC_NUMERIC says (a host program may call
 * setlocale; the core must not care).
 */
#include <locale.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "internal.h"
#include "quiltc.h"
#include "testalloc.h"
#include "unity.h"

static testalloc ta;
static qc_ctx ctx;
static const char *comma_locale; /* a decimal-comma locale, when installed */

void setUp(void)
{
    memset(&ta, 0, sizeof ta);
    qc_ctx_init(&ctx, testalloc_fn, &ta);
}

void tearDown(void)
{
    setlocale(LC_NUMERIC, "C");
    TEST_ASSERT_EQUAL_size_t(0, ta.live_bytes);
}

/* The C locale's strtod: the correctly rounded value. */
static double c_strtod(const char *s)
{
    double v;

    setlocale(LC_NUMERIC, "C");
    v = strtod(s, NULL);
    return v;
}

static void spans_should_be_strict(void)
{
    static const struct {
        const char *in;
        int found;
        size_t len;
        double v;
    } cases[] = {
        {"8.5x2", 1, 3, 8.5},    {"-.5,", 1, 3, -0.5},     {"+7", 1, 2, 7.0},
        {"1.", 1, 2, 1.0},       {"1e5x", 1, 3, 1e5},      {"1e", 1, 1, 1.0},
        {"1e+", 1, 1, 1.0},      {"2E-3 ", 1, 4, 2e-3},    {"0x5", 1, 1, 0.0},
        {".", 0, 0, 0},          {"-", 0, 0, 0},           {"nan", 0, 0, 0},
        {"inf", 0, 0, 0},        {"", 0, 0, 0},            {"1.5.5", 1, 3, 1.5},
        {"8,5", 1, 1, 8.0},      {"-0", 1, 2, -0.0},       {"1e400", 1, 5, HUGE_VAL},
    };
    size_t i;

    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        size_t pos = 0;
        double v = 12345;
        int found = qc__scan_number(cases[i].in, strlen(cases[i].in), &pos, &v);

        TEST_ASSERT_EQUAL_INT_MESSAGE(cases[i].found, found, cases[i].in);
        TEST_ASSERT_EQUAL_size_t_MESSAGE(cases[i].len, pos, cases[i].in);
        if (found)
            TEST_ASSERT_EQUAL_MEMORY_MESSAGE(&cases[i].v, &v, sizeof v, cases[i].in);
    }
    /* n bounds the scan: "12" of "123" */
    {
        size_t pos = 0;
        double v;

        TEST_ASSERT_EQUAL_INT(1, qc__scan_number("123", 2, &pos, &v));
        TEST_ASSERT_EQUAL_DOUBLE(12.0, v);
    }
}

static void values_should_round_correctly_in_any_locale(void)
{
    static const char *const nums[] = {
        "0.1", "0.3", "-2.675", "1e-7", "8.5", "123456.789012345", "12.345678901234567",
        "3.14159265358979323846264338327950288", "999999999.9999999999", "4.9406564584124654e-324",
        "2.2250738585072011e-308", "1.00000000000000011102230246251565404", "7e22", "7e23",
        "000000000000000000000000001.5", "0.000000000000000000000000000000000000000001234"};
    size_t i, pass;

    for (pass = 0; pass < 2; pass++) {
        if (pass == 1 && comma_locale == NULL)
            break;
        for (i = 0; i < sizeof nums / sizeof *nums; i++) {
            double want = c_strtod(nums[i]), got = 0;
            size_t pos = 0;

            if (pass == 1)
                setlocale(LC_NUMERIC, comma_locale);
            TEST_ASSERT_EQUAL_INT_MESSAGE(1, qc__scan_number(nums[i], strlen(nums[i]), &pos, &got),
                                          nums[i]);
            TEST_ASSERT_EQUAL_size_t_MESSAGE(strlen(nums[i]), pos, nums[i]);
            TEST_ASSERT_EQUAL_MEMORY_MESSAGE(&want, &got, sizeof want, nums[i]);
        }
    }
}

/* The bug this parser fixed: strtod under de_DE read "rect:8.5x2" as 8 mm wide. */
static void shape_sizes_should_ignore_the_locale(void)
{
    size_t pass;

    for (pass = 0; pass < 2; pass++) {
        qc_region r = {0};
        qc_bbox b;

        if (pass == 1) {
            if (comma_locale == NULL)
                TEST_IGNORE_MESSAGE("no de_DE.UTF-8 or fr_FR.UTF-8 locale (.ci/run generates one)");
            setlocale(LC_NUMERIC, comma_locale);
        }
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_shape(&ctx, "rect:8.5x2.25", 1.0, &r));
        b = qc_region_bbox(&r);
        TEST_ASSERT_EQUAL_DOUBLE(8.5, b.max.x - b.min.x);
        TEST_ASSERT_EQUAL_DOUBLE(2.25, b.max.y - b.min.y);
        qc_region_free(&ctx, &r);
    }
}

/* One reader: a 17-digit value has the same bits from a shape spec, a point
 * file and an SVG document in mm, and they are strtod's in the C locale. */
static void every_reader_should_read_the_same_bits(void)
{
    static const char num[] = "12.345678901234567";
    const double want = c_strtod(num);
    char spec[64], csv[64], svg[256];
    qc_region r = {0};
    qc_points pts = {0};
    qc_path p = {0};
    qc_bbox b;

    if (comma_locale != NULL)
        setlocale(LC_NUMERIC, comma_locale);
    snprintf(spec, sizeof spec, "square:%s", num);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_shape(&ctx, spec, 1.0, &r));
    b = qc_region_bbox(&r);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, b.min.x);
    TEST_ASSERT_EQUAL_MEMORY(&want, &b.max.x, sizeof want);
    qc_region_free(&ctx, &r);

    snprintf(csv, sizeof csv, "%s,1\n", num);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_io_read_points(&ctx, csv, strlen(csv), &pts));
    TEST_ASSERT_EQUAL_MEMORY(&want, &pts.v[0].x, sizeof want);
    qc_points_free(&ctx, &pts);

    snprintf(svg, sizeof svg,
             "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"100mm\" height=\"100mm\" "
             "viewBox=\"0 0 100 100\"><path d=\"M %s 50 L 60 50\"/></svg>", num);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_io_read_svg_path(&ctx, svg, strlen(svg), NULL, &p));
    TEST_ASSERT_TRUE(p.npt >= 2);
    TEST_ASSERT_EQUAL_MEMORY(&want, &p.pt[0].x, sizeof want);
    qc_path_free(&ctx, &p);
}

int main(void)
{
    if (setlocale(LC_NUMERIC, "de_DE.UTF-8") != NULL)
        comma_locale = "de_DE.UTF-8";
    else if (setlocale(LC_NUMERIC, "fr_FR.UTF-8") != NULL)
        comma_locale = "fr_FR.UTF-8";
    setlocale(LC_NUMERIC, "C");
    UNITY_BEGIN();
    RUN_TEST(spans_should_be_strict);
    RUN_TEST(values_should_round_correctly_in_any_locale);
    RUN_TEST(shape_sizes_should_ignore_the_locale);
    RUN_TEST(every_reader_should_read_the_same_bits);
    return UNITY_END();
}
