/* Point files: CSV and TSPLIB, exact numbers whatever the locale, errors
 * naming the line and text, limits, hostile mutations, OOM. */
#include <locale.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
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

static int read_str(const char *s, qc_points *out)
{
    return qc_io_read_points(&ctx, s, strlen(s), out);
}

static void assert_point(const qc_points *pts, size_t i, double x, double y)
{
    TEST_ASSERT_TRUE(i < pts->n);
    TEST_ASSERT_EQUAL_DOUBLE(x, pts->v[i].x);
    TEST_ASSERT_EQUAL_DOUBLE(y, pts->v[i].y);
}

/* Reading s[0..len) fails with status and a message holding each word. */
static void assert_error_n(const char *s, size_t len, int status, const char *w1, const char *w2)
{
    qc_points pts = {0};
    qc_vec2 keep = {42, 43};
    int rc;

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_points_push(&ctx, &pts, keep));
    rc = qc_io_read_points(&ctx, s, len, &pts);
    TEST_ASSERT_EQUAL_INT_MESSAGE(status, rc, s);
    if (w1 != NULL)
        TEST_ASSERT_NOT_NULL_MESSAGE(strstr(qc_errmsg(&ctx), w1), qc_errmsg(&ctx));
    if (w2 != NULL)
        TEST_ASSERT_NOT_NULL_MESSAGE(strstr(qc_errmsg(&ctx), w2), qc_errmsg(&ctx));
    TEST_ASSERT_EQUAL_size_t(1, pts.n); /* the output keeps what it had */
    assert_point(&pts, 0, 42, 43);
    qc_points_free(&ctx, &pts);
}

static void assert_error(const char *s, int status, const char *w1, const char *w2)
{
    assert_error_n(s, strlen(s), status, w1, w2);
}

static const char *const tsp_sample =
    "NAME : tiny\n"
    "COMMENT : three points\n"
    "TYPE : TSP\n"
    "DIMENSION: 3\n"
    "EDGE_WEIGHT_TYPE : EUC_2D\n"
    "NODE_COORD_SECTION\n"
    "1 1.5 2\n"
    "  2\t3e2   4\n"
    "3 -5 6.25\n"
    "EOF\n";

void csv_should_read_points_headers_comments_and_crlf(void)
{
    qc_points pts = {0};
    qc_vec2 first = {-1, -1};

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_points_push(&ctx, &pts, first));
    TEST_ASSERT_EQUAL_INT(QC_OK, read_str("\xEF\xBB\xBF"
                                          "x_mm,y_mm\r\n"
                                          "# a comment\r\n"
                                          "\r\n"
                                          "1,2\r\n"
                                          "  -3.5 ,\t4e2 \r\n"
                                          ".5,-.25 # trailing comment\n"
                                          "   # indented comment\n"
                                          "+7,8.",
                                          &pts));
    TEST_ASSERT_EQUAL_size_t(5, pts.n);
    assert_point(&pts, 0, -1, -1);
    assert_point(&pts, 1, 1, 2);
    assert_point(&pts, 2, -3.5, 400);
    assert_point(&pts, 3, 0.5, -0.25);
    assert_point(&pts, 4, 7, 8);
    qc_points_free(&ctx, &pts);

    TEST_ASSERT_EQUAL_INT(QC_OK, read_str("10,20\n30,40\n", &pts));
    TEST_ASSERT_EQUAL_size_t(2, pts.n);
    assert_point(&pts, 1, 30, 40);
    qc_points_free(&ctx, &pts);
    /* a header starting like a TSPLIB keyword is still a CSV header */
    TEST_ASSERT_EQUAL_INT(QC_OK, read_str("name,type\n1,1\n", &pts));
    TEST_ASSERT_EQUAL_size_t(1, pts.n);
    qc_points_free(&ctx, &pts);
}

void numbers_should_round_correctly_in_any_locale(void)
{
    static const char *const nums[] = {
        "0.1", "0.3", "-2.675", "1e-7", "123456.789012345", "3.14159265358979323846264338327950288",
        "0.000000000000000000000000000000000000000000000000000000001234", "999999999.9999999999",
        "4.9406564584124654e-324", "2.2250738585072011e-308", "1.00000000000000011102230246251565404",
        "7e22", "7e23", "-0", "000000000000000000000000001.5", "1E+2", "5.e-1"};
    const char *comma = NULL; /* a locale with a decimal comma, if installed */
    size_t i, pass;

    if (setlocale(LC_NUMERIC, "de_DE.UTF-8") != NULL)
        comma = "de_DE.UTF-8";
    else if (setlocale(LC_NUMERIC, "fr_FR.UTF-8") != NULL)
        comma = "fr_FR.UTF-8";
    for (pass = 0; pass < 2; pass++) {
        if (pass == 1 && comma == NULL)
            break;
        for (i = 0; i < sizeof nums / sizeof *nums; i++) {
            char line[200];
            qc_points pts = {0};
            double want;

            setlocale(LC_NUMERIC, "C");
            want = strtod(nums[i], NULL); /* the correctly rounded value */
            if (pass == 1)
                setlocale(LC_NUMERIC, comma);
            if (fabs(want) > 1e9)
                continue;
            snprintf(line, sizeof line, "%s,%s\n", nums[i], nums[i]);
            TEST_ASSERT_EQUAL_INT_MESSAGE(QC_OK, read_str(line, &pts), nums[i]);
            TEST_ASSERT_EQUAL_MEMORY_MESSAGE(&want, &pts.v[0].x, sizeof want, nums[i]);
            TEST_ASSERT_EQUAL_MEMORY_MESSAGE(&want, &pts.v[0].y, sizeof want, nums[i]);
            qc_points_free(&ctx, &pts);
        }
    }
    setlocale(LC_NUMERIC, "C");
}

void tsplib_should_read_the_node_section(void)
{
    qc_points pts = {0};

    TEST_ASSERT_EQUAL_INT(QC_OK, read_str(tsp_sample, &pts));
    TEST_ASSERT_EQUAL_size_t(3, pts.n);
    assert_point(&pts, 0, 1.5, 2);
    assert_point(&pts, 1, 300, 4);
    assert_point(&pts, 2, -5, 6.25);
    qc_points_free(&ctx, &pts);
    /* CRLF, no EOF, keywords in any case, comment lines before */
    TEST_ASSERT_EQUAL_INT(QC_OK, read_str("# made by hand\r\nname: x\r\nDimension : 2\r\n"
                                          "EDGE_WEIGHT_TYPE: CEIL_2D\r\nNODE_COORD_SECTION\r\n"
                                          "1 0 0\r\n2 1.0e1 -1\r\n",
                                          &pts));
    TEST_ASSERT_EQUAL_size_t(2, pts.n);
    assert_point(&pts, 1, 10, -1);
    qc_points_free(&ctx, &pts);
    /* another section after the nodes ends the reading */
    TEST_ASSERT_EQUAL_INT(QC_OK, read_str("DIMENSION : 1\nNODE_COORD_SECTION\n1 5 5\n"
                                          "DISPLAY_DATA_SECTION\n1 0 0\n",
                                          &pts));
    TEST_ASSERT_EQUAL_size_t(1, pts.n);
    qc_points_free(&ctx, &pts);
}

void tsplib_files_should_match_their_dimension(void)
{
    FILE *f = fopen("tests/data/tsplib/a280.tsp", "rb");
    qc_points pts = {0};
    char *buf;
    long len;

    if (f == NULL)
        TEST_IGNORE_MESSAGE("tests/data/tsplib/a280.tsp is missing");
    fseek(f, 0, SEEK_END);
    len = ftell(f);
    fseek(f, 0, SEEK_SET);
    buf = malloc((size_t)len);
    TEST_ASSERT_EQUAL_size_t((size_t)len, fread(buf, 1, (size_t)len, f));
    fclose(f);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_io_read_points(&ctx, buf, (size_t)len, &pts));
    TEST_ASSERT_EQUAL_size_t(280, pts.n);
    assert_point(&pts, 0, 288, 149);
    assert_point(&pts, 279, 280, 133);
    qc_points_free(&ctx, &pts);
    free(buf);
}

void malformed_csv_should_name_the_line_and_text(void)
{
    assert_error("1,2\n3;4\n", QC_EFORMAT, "line 2", "\"3;4\"");
    assert_error("1,2\nabc,5\n", QC_EFORMAT, "line 2", "abc,5");
    assert_error("x,y\nx,y\n", QC_EFORMAT, "line 2", NULL);
    assert_error("1,2,3\n", QC_EFORMAT, "line 1", "1,2,3");
    assert_error("1 2\n", QC_EFORMAT, "line 1", NULL);
    assert_error("0x10,5\n", QC_EFORMAT, "line 1", "0x10,5");
    assert_error("1.2.3,4\n", QC_EFORMAT, "line 1", NULL);
    assert_error("1e,2\n", QC_EFORMAT, "line 1", NULL);
    assert_error("--1,2\n", QC_EFORMAT, "line 1", NULL);
    assert_error("1,\n", QC_EFORMAT, "line 1", NULL);
    assert_error("1,2\r\r\n", QC_EFORMAT, "line 1", NULL);
    assert_error("# c\n\n5,5\n6,6\x01\n", QC_EFORMAT, "line 4", "6,6?");
    assert_error_n("1,2\n3,4\0,5\n", 11, QC_EFORMAT, "line 2", "3,4?,5");
    assert_error("1,2\n3,4,5,6,7,8,9,10,11,12,13,14,15,16,17,18,19,20,21,22,23,24\n",
                 QC_EFORMAT, "line 2", "\"3,4,5,6,7,8,9,10,11,12,13,14,15,16,17,18...\"");
    assert_error("0.00000000000000000000000000000000000000000000000000000000000000000000"
                 "00000000000000000000000000000000000000000000000000000000000000000001,1\n",
                 QC_EFORMAT, "line 1", NULL); /* beyond 128 characters */
}

void out_of_range_numbers_should_be_erange(void)
{
    qc_points pts = {0};

    assert_error("1,nan\n", QC_ERANGE, "line 1", "nan");
    assert_error("0,0\n-INF,2\n", QC_ERANGE, "line 2", "-INF");
    assert_error("infinity,2\n", QC_ERANGE, "line 1", NULL);
    assert_error("1e10,0\n", QC_ERANGE, "line 1", "1e10");
    assert_error("0,-1000000000.5\n", QC_ERANGE, "line 1", NULL);
    assert_error("1e999,0\n", QC_ERANGE, "line 1", NULL);
    assert_error("DIMENSION : 1\nNODE_COORD_SECTION\n1 nan 0\n", QC_ERANGE, "line 3", NULL);
    TEST_ASSERT_EQUAL_INT(QC_OK, read_str("-1e9,1000000000\n1e-400,0\n", &pts));
    assert_point(&pts, 0, -1e9, 1e9);
    assert_point(&pts, 1, 0, 0);
    qc_points_free(&ctx, &pts);
}

void malformed_tsplib_should_name_the_line(void)
{
    assert_error("NAME : x\nNODE_COORD_SECTION\n1 0 0\n", QC_EFORMAT, "line 2",
                 "before DIMENSION");
    assert_error("DIMENSION : 2\nNODE_COORD_SECTION\n2 0 0\n1 0 0\n", QC_EFORMAT, "line 3",
                 "expected node 1");
    assert_error("DIMENSION : 3\nNODE_COORD_SECTION\n1 0 0\n2 1 1\n", QC_EFORMAT, "2 of", "3");
    assert_error("DIMENSION : 3\nNODE_COORD_SECTION\n1 0 0\n2 1 1\nEOF\n", QC_EFORMAT, "line 5",
                 "EOF");
    assert_error("DIMENSION : 1\nNODE_COORD_SECTION\n1 0 0\n2 1 1\n", QC_EFORMAT, "line 4",
                 "more nodes");
    assert_error("DIMENSION : 1\nEDGE_WEIGHT_TYPE : GEO\nNODE_COORD_SECTION\n1 0 0\n",
                 QC_EFORMAT, "line 2", "GEO");
    assert_error("TYPE : ATSP\nDIMENSION : 1\n", QC_EFORMAT, "line 1", "TYPE");
    assert_error("DIMENSION : many\n", QC_EFORMAT, "line 1", "whole number");
    assert_error("DIMENSION : 0\nNODE_COORD_SECTION\n", QC_EEMPTY, "line 1", NULL);
    assert_error("DIMENSION : 4000001\nNODE_COORD_SECTION\n", QC_ELIMIT, "4000001", NULL);
    assert_error("DIMENSION : 99999999999999999999\n", QC_ELIMIT, NULL, NULL);
    assert_error("DIMENSION : 1\nEDGE_WEIGHT_SECTION\n", QC_EFORMAT, "line 2", NULL);
    assert_error("DIMENSION : 1\n", QC_EFORMAT, "ends before", NULL);
    assert_error("NAME : x\n!!\n", QC_EFORMAT, "line 2", "!!");
    assert_error("DIMENSION : 1\nNODE_COORD_SECTION\n1 0\n", QC_EFORMAT, "line 3", NULL);
    assert_error("DIMENSION : 1\nNODE_COORD_SECTION\n1 0 0 0\n", QC_EFORMAT, "line 3", NULL);
    assert_error("DIMENSION : 1\nNODE_COORD_SECTION\n1,0,0\n", QC_EFORMAT, "line 3", NULL);
}

void empty_input_should_be_eempty(void)
{
    qc_points pts = {0};

    assert_error("", QC_EEMPTY, NULL, NULL);
    assert_error("x,y\n", QC_EEMPTY, NULL, NULL);
    assert_error("# nothing\n\n  \r\n", QC_EEMPTY, NULL, NULL);
    TEST_ASSERT_EQUAL_INT(QC_EINVAL, qc_io_read_points(&ctx, NULL, 5, &pts));
    TEST_ASSERT_EQUAL_INT(QC_EINVAL, qc_io_read_points(&ctx, "1,2", 3, NULL));
    TEST_ASSERT_EQUAL_INT(QC_EEMPTY, qc_io_read_points(&ctx, NULL, 0, &pts));
}

void too_many_points_should_be_elimit(void)
{
    size_t n = (size_t)QC_MAX_POINTS + 1, i;
    char *buf = malloc(4 * n);
    qc_points pts = {0};

    for (i = 0; i < n; i++)
        memcpy(buf + 4 * i, "0,1\n", 4);
    TEST_ASSERT_EQUAL_INT(QC_ELIMIT, qc_io_read_points(&ctx, buf, 4 * n, &pts));
    TEST_ASSERT_NOT_NULL(strstr(qc_errmsg(&ctx), "line 4000001"));
    TEST_ASSERT_EQUAL_size_t(0, pts.n);
    qc_points_free(&ctx, &pts);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_io_read_points(&ctx, buf, 4 * (n - 1), &pts));
    TEST_ASSERT_EQUAL_size_t(n - 1, pts.n);
    qc_points_free(&ctx, &pts);
    free(buf);
}

/* Flips, inserts, deletes and repeats bytes of a valid file. */
static size_t mutate(qc_rng *r, const char *src, size_t n, char *dst, size_t cap)
{
    static const char alphabet[] = "0123456789-+.eE,#\n\r \t:xnaNIF\0\xff";
    size_t len = n, k, edits = 1 + (size_t)qc_rng_below(r, 6);

    memcpy(dst, src, n);
    for (k = 0; k < edits; k++) {
        size_t at = len ? (size_t)qc_rng_below(r, len) : 0;
        char c = alphabet[qc_rng_below(r, sizeof alphabet - 1)];

        switch (qc_rng_below(r, 5)) {
        case 0:
            if (len)
                dst[at] = c;
            break;
        case 1:
            if (len < cap) {
                memmove(dst + at + 1, dst + at, len - at);
                dst[at] = c;
                len++;
            }
            break;
        case 2:
            if (len) {
                memmove(dst + at, dst + at + 1, len - at - 1);
                len--;
            }
            break;
        case 3: { /* repeat a chunk */
            size_t m = 1 + (size_t)qc_rng_below(r, 12);
            if (at + m <= len && len + m <= cap) {
                memmove(dst + at + m, dst + at, len - at);
                len += m;
            }
            break;
        }
        default:
            len = at; /* truncate */
        }
    }
    return len;
}

void hostile_inputs_should_fail_cleanly(void)
{
    static const char *const samples[] = {"x,y\n1.5,2\n-3,4e1\n# c\n.5,6\r\n7,8", NULL};
    char buf[600];
    qc_rng r;
    size_t s, it, ok = 0, failed = 0;

    qc_rng_seed(&r, 2024);
    for (s = 0; s < 2; s++) {
        const char *src = samples[s] ? samples[s] : tsp_sample;
        for (it = 0; it < 4000; it++) {
            size_t len = mutate(&r, src, strlen(src), buf, sizeof buf), i;
            qc_points pts = {0};
            qc_vec2 keep = {1, 2};
            int rc;

            TEST_ASSERT_EQUAL_INT(QC_OK, qc_points_push(&ctx, &pts, keep));
            rc = qc_io_read_points(&ctx, buf, len, &pts);
            if (rc == QC_OK) {
                ok++;
                TEST_ASSERT_TRUE(pts.n > 1);
                for (i = 0; i < pts.n; i++)
                    TEST_ASSERT_TRUE(fabs(pts.v[i].x) <= 1e9 && fabs(pts.v[i].y) <= 1e9);
            } else {
                failed++;
                TEST_ASSERT_TRUE(rc == QC_EFORMAT || rc == QC_ERANGE || rc == QC_EEMPTY ||
                                 rc == QC_ELIMIT);
                TEST_ASSERT_TRUE(qc_errmsg(&ctx)[0] != '\0');
                TEST_ASSERT_EQUAL_size_t(1, pts.n);
            }
            qc_points_free(&ctx, &pts);
            TEST_ASSERT_EQUAL_size_t(0, ta.live_bytes);
        }
    }
    TEST_ASSERT_TRUE(ok > 100 && failed > 100); /* both outcomes exercised */
}

void reading_should_fail_cleanly_out_of_memory(void)
{
    char buf[4000];
    size_t w = 0, k;
    int i, done = 0;

    for (i = 0; i < 200; i++)
        w += (size_t)snprintf(buf + w, sizeof buf - w, "%d.25,%d\n", i, -i);
    for (k = 1; k < 100 && !done; k++) {
        qc_points pts = {0};
        qc_vec2 keep = {1, 2};
        int rc;

        TEST_ASSERT_EQUAL_INT(QC_OK, qc_points_push(&ctx, &pts, keep));
        ta.fail_at = ta.allocs + k;
        rc = qc_io_read_points(&ctx, buf, w, &pts);
        ta.fail_at = 0;
        if (rc == QC_OK) {
            done = 1;
            TEST_ASSERT_EQUAL_size_t(201, pts.n);
            assert_point(&pts, 200, 199.25, -199);
        } else {
            TEST_ASSERT_EQUAL_INT(QC_ENOMEM, rc);
            TEST_ASSERT_EQUAL_size_t(1, pts.n);
        }
        qc_points_free(&ctx, &pts);
        TEST_ASSERT_EQUAL_size_t(0, ta.live_bytes);
    }
    TEST_ASSERT_TRUE(done);
    TEST_ASSERT_GREATER_THAN(1, k);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(csv_should_read_points_headers_comments_and_crlf);
    RUN_TEST(numbers_should_round_correctly_in_any_locale);
    RUN_TEST(tsplib_should_read_the_node_section);
    RUN_TEST(tsplib_files_should_match_their_dimension);
    RUN_TEST(malformed_csv_should_name_the_line_and_text);
    RUN_TEST(out_of_range_numbers_should_be_erange);
    RUN_TEST(malformed_tsplib_should_name_the_line);
    RUN_TEST(empty_input_should_be_eempty);
    RUN_TEST(too_many_points_should_be_elimit);
    RUN_TEST(hostile_inputs_should_fail_cleanly);
    RUN_TEST(reading_should_fail_cleanly_out_of_memory);
    return UNITY_END();
}
