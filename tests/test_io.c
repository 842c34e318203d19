/*
 * Machine output: golden bytes per format on a small hand-built plan, the
 * PAT reader (round trip, strictness), names, errors. With QC_READERS_DIR
 * set, also writes a sample plan in every format plus sample.csv (the exact
 * points) there, for tests/check_readers.sh's independent readers.
 * With QC_UPDATE_GOLDEN=1 it rewrites tests/golden/ (review the diff!).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "quiltc.h"
#include "testalloc.h"
#include "testgeom.h"
#include "unity.h"
#include "../src/io/io_internal.h"

static testalloc ta;
static qc_ctx ctx;

typedef struct membuf {
    char *p;
    size_t n, cap;
    int fail_after; /* callback calls before failing; < 0 never */
} membuf;

void setUp(void)
{
    memset(&ta, 0, sizeof ta);
    qc_ctx_init(&ctx, testalloc_fn, &ta);
}

void tearDown(void)
{
}

static int mem_write(void *ud, const void *data, size_t len)
{
    membuf *m = (membuf *)ud;

    if (m->fail_after == 0)
        return -1;
    if (m->fail_after > 0)
        m->fail_after--;
    if (m->n + len > m->cap) {
        size_t cap = (m->n + len) * 2;
        char *p = (char *)realloc(m->p, cap);
        if (p == NULL)
            return -1;
        m->p = p;
        m->cap = cap;
    }
    memcpy(m->p + m->n, data, len);
    m->n += len;
    return 0;
}

static void push(qc_plan *plan, double x, double y, unsigned f)
{
    qc_vec2 p;

    p.x = x;
    p.y = y;
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_plan_push(&ctx, plan, p, f));
}

/* The golden plan: two pieces, a tie, a point that rounds onto its
 * predecessor at 0.001 in, and 9.008 in. */
static void golden_plan(qc_plan *plan)
{
    memset(plan, 0, sizeof *plan);
    push(plan, 0, 0, QC_ST_JUMP);
    push(plan, 12.7, 6.35, 0);
    push(plan, 12.7004, 6.35, 0);
    push(plan, 25.4, 1.0, 0);
    push(plan, 50.8, 25.4, QC_ST_JUMP);
    push(plan, 76.2, 12.7, QC_ST_TIE);
    push(plan, 101.6, 228.8032, 0);
}

static char *read_file(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    char *p;
    long n;

    if (f == NULL)
        return NULL;
    fseek(f, 0, SEEK_END);
    n = ftell(f);
    fseek(f, 0, SEEK_SET);
    p = (char *)malloc((size_t)n + 1);
    if (p != NULL && fread(p, 1, (size_t)n, f) != (size_t)n) {
        free(p);
        p = NULL;
    }
    fclose(f);
    if (p != NULL)
        *len = (size_t)n;
    return p;
}

static void write_file(const char *path, const char *p, size_t n)
{
    FILE *f = fopen(path, "wb");

    TEST_ASSERT_NOT_NULL_MESSAGE(f, path);
    TEST_ASSERT_EQUAL_size_t(n, fwrite(p, 1, n, f));
    fclose(f);
}

static void encode(int format, const qc_plan *plan, const qc_io_opts *opts, membuf *m)
{
    memset(m, 0, sizeof *m);
    m->fail_after = -1;
    TEST_ASSERT_EQUAL_INT_MESSAGE(QC_OK, qc_io_write(&ctx, format, plan, opts, mem_write, m),
                                  qc_errmsg(&ctx));
}

static void check_golden(int format, const qc_io_opts *opts, const char *file)
{
    char path[256], msg[300];
    const char *pname = path;
    qc_plan plan;
    membuf m;
    char *want;
    size_t wn = 0, i, base = ta.live_blocks;

    golden_plan(&plan);
    encode(format, &plan, opts, &m);
    snprintf(path, sizeof path, "tests/golden/%s", file);
    if (getenv("QC_UPDATE_GOLDEN") != NULL)
        write_file(path, m.p, m.n);
    want = read_file(path, &wn);
    TEST_ASSERT_NOT_NULL_MESSAGE(want, pname);
    for (i = 0; i < wn && i < m.n && want[i] == m.p[i]; i++)
        ;
    snprintf(msg, sizeof msg, "%s differs from the output at byte %lu", path,
             (unsigned long)i);
    TEST_ASSERT_EQUAL_size_t_MESSAGE(wn, m.n, msg);
    TEST_ASSERT_EQUAL_MEMORY_MESSAGE(want, m.p, wn, msg);
    free(want);
    free(m.p);
    qc_plan_free(&ctx, &plan);
    TEST_ASSERT_EQUAL_size_t(base, ta.live_blocks);
}

static void pat_should_match_golden_bytes(void)
{
    check_golden(QC_FORMAT_PAT, NULL, "small.pat");
}

static void pat_should_use_the_exact_dialect(void)
{
    static const char want[] =
        "N1G00X0.000Y0.000\r\n"
        "N2G01X0.500Y0.250\r\n" /* 12.7004 mm rounds onto 0.500: dropped */
        "N3G01X1.000Y0.039\r\n"
        "N4G00X2.000Y1.000\r\n"
        "N5G01X3.000Y0.500\r\n"
        "N6G01X4.000Y9.008\r\n"
        "N7M02\r\n";
    qc_plan plan;
    membuf m;

    golden_plan(&plan);
    encode(QC_FORMAT_PAT, &plan, NULL, &m);
    TEST_ASSERT_EQUAL_size_t(sizeof want - 1, m.n);
    TEST_ASSERT_EQUAL_MEMORY(want, m.p, m.n);
    free(m.p);
    qc_plan_free(&ctx, &plan);
}

static void fmt(int64_t v, int dec, int trim, const char *want)
{
    membuf m;
    qc__out o;

    memset(&m, 0, sizeof m);
    m.fail_after = -1;
    qc__out_init(&o, &ctx, mem_write, &m);
    qc__out_fixed(&o, v, dec, trim);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc__out_finish(&o));
    TEST_ASSERT_EQUAL_size_t(strlen(want), m.n);
    TEST_ASSERT_EQUAL_MEMORY(want, m.p, m.n);
    free(m.p);
}

static void numbers_should_round_half_away_from_zero_and_format_exactly(void)
{
    qc_plan plan = {0};
    membuf m;

    TEST_ASSERT_EQUAL_INT64(1, qc__round(0.5));
    TEST_ASSERT_EQUAL_INT64(3, qc__round(2.5));
    TEST_ASSERT_EQUAL_INT64(2, qc__round(2.4999999));
    TEST_ASSERT_EQUAL_INT64(-1, qc__round(-0.5));
    TEST_ASSERT_EQUAL_INT64(-3, qc__round(-2.5));
    TEST_ASSERT_EQUAL_INT64(0, qc__round(-0.4));
    TEST_ASSERT_EQUAL_INT64(1000, qc__mm_to_inch_units(25.4, 1000));
    TEST_ASSERT_EQUAL_INT64(9008, qc__mm_to_inch_units(228.8032, 1000));
    fmt(0, 3, 0, "0.000");
    fmt(5, 3, 0, "0.005");
    fmt(-1250, 3, 0, "-1.250");
    fmt(-1250, 3, 1, "-1.25");
    fmt(3000, 3, 1, "3");
    fmt(-4, 3, 1, "-0.004");
    fmt(0, 4, 1, "0");
    fmt(1234567890123LL, 4, 0, "123456789.0123");
    fmt(-42, 0, 0, "-42");
    /* through a writer: 1000.4999 and 1000.5001 thousandths */
    push(&plan, 0.0254 * 1000.4999, 0.0254 * 1000.5001, QC_ST_JUMP);
    encode(QC_FORMAT_PAT, &plan, NULL, &m);
    TEST_ASSERT_EQUAL_MEMORY("N1G00X1.000Y1.001\r\n", m.p, 19);
    free(m.p);
    qc_plan_free(&ctx, &plan);
}

/* Every digit count, both signs, against printf: the formatter writes two
 * digits per step, so odd and even lengths and the padding of the
 * fraction's leading zeros each take their own way through it. */
static void numbers_should_format_as_printf_at_every_length(void)
{
    static const uint64_t pow10[7] = {1, 10, 100, 1000, 10000, 100000, 1000000};
    uint64_t base = 1;
    int e, d, s, k;

    for (e = 0; e <= 18; e++, base *= 10) {
        for (k = -1; k <= 1; k++) {
            uint64_t u = base + (uint64_t)(int64_t)k;

            for (s = 0; s < 2; s++) {
                int64_t v = s ? -(int64_t)u : (int64_t)u;
                char want[64], buf[64], *end = buf + sizeof buf - 1, *got;

                *end = '\0';
                sprintf(want, "%lld", (long long)v);
                got = qc__fmt_int(end, v);
                TEST_ASSERT_EQUAL_STRING(want, got);
                for (d = 1; d <= 6; d++) {
                    sprintf(want, "%s%llu.%0*llu", s && u != 0 ? "-" : "",
                            (unsigned long long)(u / pow10[d]), d,
                            (unsigned long long)(u % pow10[d]));
                    got = qc__fmt_fixed(end, v, d, 0);
                    TEST_ASSERT_EQUAL_STRING(want, got);
                    if (d == 3 && !s) { /* the .pat writer's own way to the same text */
                        *qc__put_thousandths(buf, u) = '\0';
                        TEST_ASSERT_EQUAL_STRING(want, buf);
                    }
                }
            }
        }
    }
}

/* The .pat writer's numbers made by digit triples: every value up to and
 * past the last one of its fast way (999.999), against printf. */
static void thousandths_should_format_as_printf_for_every_value(void)
{
    uint64_t v;

    for (v = 0; v <= 1002000; v++) {
        char want[32], buf[40];

        sprintf(want, "%llu.%03llu", (unsigned long long)(v / 1000),
                (unsigned long long)(v % 1000));
        memset(buf, 'x', sizeof buf);
        *qc__put_thousandths(buf, v) = '\0';
        if (strcmp(want, buf) != 0)
            TEST_ASSERT_EQUAL_STRING(want, buf);
    }
}

/* The line number is counted up as text: every carry (9 to 10, 999 to
 * 1000) and the closing M02 line's number. */
static void pat_should_number_lines_across_every_carry(void)
{
    qc_plan plan = {0};
    membuf m;
    char want[32];
    size_t i, at = 0;

    for (i = 0; i < 10001; i++)
        push(&plan, 0.0254 * (double)i, 1, i == 0 ? QC_ST_JUMP : 0);
    encode(QC_FORMAT_PAT, &plan, NULL, &m);
    for (i = 1; i <= 10002; i++) {
        size_t len = (size_t)sprintf(want, i <= 10001 ? "N%luG0" : "N%luM02\r\n",
                                     (unsigned long)i);

        TEST_ASSERT_TRUE(at + len <= m.n);
        TEST_ASSERT_EQUAL_MEMORY(want, m.p + at, len);
        while (at < m.n && m.p[at] != '\n')
            at++;
        at++;
    }
    TEST_ASSERT_EQUAL_size_t(m.n, at);
    free(m.p);
    qc_plan_free(&ctx, &plan);
}

static void pat_should_refuse_negative_and_report_errors(void)
{
    qc_plan plan = {0}, empty = {0};
    membuf m;

    memset(&m, 0, sizeof m);
    m.fail_after = -1;
    push(&plan, 0, 0, QC_ST_JUMP);
    push(&plan, 5, -0.0001, 0); /* rounds to -0.000: fine */
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_io_write(&ctx, QC_FORMAT_PAT, &plan, NULL, mem_write, &m));
    push(&plan, 5, -1, 0);
    m.n = 0;
    TEST_ASSERT_EQUAL_INT(QC_ERANGE, qc_io_write(&ctx, QC_FORMAT_PAT, &plan, NULL, mem_write, &m));
    TEST_ASSERT_NOT_NULL(strstr(qc_errmsg(&ctx), "point 2"));
    TEST_ASSERT_EQUAL_size_t(0, m.n); /* nothing written */
    TEST_ASSERT_EQUAL_INT(QC_EEMPTY, qc_io_write(&ctx, QC_FORMAT_PAT, &empty, NULL, mem_write, &m));
    TEST_ASSERT_EQUAL_INT(QC_EINVAL, qc_io_write(&ctx, 0, &plan, NULL, mem_write, &m));
    TEST_ASSERT_EQUAL_INT(QC_EINVAL, qc_io_write(&ctx, QC_FORMAT_COUNT, &plan, NULL, mem_write, &m));
    plan.p[1].x = (double)NAN;
    TEST_ASSERT_EQUAL_INT(QC_ERANGE, qc_io_write(&ctx, QC_FORMAT_SVG, &plan, NULL, mem_write, &m));
    free(m.p);
    qc_plan_free(&ctx, &plan);
}

static void writers_should_report_write_failure(void)
{
    qc_plan plan = {0};
    membuf m;
    int f, i;

    for (i = 0; i < 3000; i++)
        push(&plan, i * 0.1, i * 0.2, i == 0 ? QC_ST_JUMP : 0);
    for (f = 1; f < QC_FORMAT_COUNT; f++) {
        memset(&m, 0, sizeof m);
        m.fail_after = 1;
        TEST_ASSERT_EQUAL_INT(QC_EIO, qc_io_write(&ctx, f, &plan, NULL, mem_write, &m));
        TEST_ASSERT_EQUAL_INT(1, m.n > 0);
        free(m.p);
    }
    qc_plan_free(&ctx, &plan);
}

static void pat_should_round_trip_within_half_a_thousandth(void)
{
    qc_plan plan = {0}, back;
    qc_rng rng;
    membuf m;
    size_t i;

    qc_rng_seed(&rng, 42);
    for (i = 0; i < 500; i++) { /* drawn in the order gcc drew the arguments */
        int jump = i == 0 || qc_rng_below(&rng, 50) == 0;
        qc_vec2 p = rng_v2(&rng, 0, 900, 0, 900);

        push(&plan, p.x, p.y, jump ? QC_ST_JUMP : 0);
    }
    encode(QC_FORMAT_PAT, &plan, NULL, &m);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_io_read_pat(&ctx, m.p, m.n, &back));
    TEST_ASSERT_EQUAL_size_t(plan.n, back.n);
    for (i = 0; i < plan.n; i++) {
        TEST_ASSERT_DOUBLE_WITHIN(0.0005 * 25.4 + 1e-9, plan.p[i].x, back.p[i].x);
        TEST_ASSERT_DOUBLE_WITHIN(0.0005 * 25.4 + 1e-9, plan.p[i].y, back.p[i].y);
        TEST_ASSERT_EQUAL_INT(plan.flags[i] & QC_ST_JUMP, back.flags[i]);
    }
    qc_plan_free(&ctx, &back);
    free(m.p);
    qc_plan_free(&ctx, &plan);
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

static void read_pat_should_accept_lf_and_reject_malformed_lines(void)
{
    static const struct {
        const char *text, *err;
    } bad[] = {
        {"N1G00X1.000Y2.000\r\nN3G01X1.000Y2.000\r\nN3M02\r\n", "line 2: numbered N3"},
        {"N1G00X1.00Y2.000\r\nN2M02\r\n", "line 1"},
        {"N1G00X1.000Y2.0001\r\nN2M02\r\n", "line 1"},
        {"N1G02X1.000Y2.000\r\nN2M02\r\n", "line 1: expected G00"},
        {"N1G00X1.000Y2.000\r\n", "line 2: missing N2M02"},
        {"N1G00X1.000Y2.000\r\nN2M02\r\nN3G01X1.000Y2.000\r\n", "line 2: nothing may follow"},
        {"N1G00X1.000 Y2.000\r\nN2M02\r\n", "line 1"},
        {"G00X1.000Y2.000\r\nN2M02\r\n", "line 1: expected N1"},
        {"N1G00X1.000Y2.000N2M02\r\n", "line 1"},
        {"N1M02\r\n", "no point"},
    };
    static const char good[] = "N1G00X1.000Y2.000\nN2G01X0.000Y10.500\r\nN3G00X3.000Y0.001\nN4M02";
    qc_plan plan;
    size_t i;

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_io_read_pat(&ctx, good, sizeof good - 1, &plan));
    TEST_ASSERT_EQUAL_size_t(3, plan.n);
    TEST_ASSERT_EQUAL_INT(QC_ST_JUMP, plan.flags[0]);
    TEST_ASSERT_EQUAL_INT(0, plan.flags[1]);
    TEST_ASSERT_EQUAL_INT(QC_ST_JUMP, plan.flags[2]);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 10.5 * 25.4, plan.p[1].y);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 0.0254, plan.p[2].y);
    qc_plan_free(&ctx, &plan);
    for (i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        int rc = qc_io_read_pat(&ctx, bad[i].text, strlen(bad[i].text), &plan);
        TEST_ASSERT_TRUE_MESSAGE(rc == QC_EFORMAT || rc == QC_EEMPTY, bad[i].text);
        TEST_ASSERT_NOT_NULL_MESSAGE(strstr(qc_errmsg(&ctx), bad[i].err), qc_errmsg(&ctx));
        TEST_ASSERT_EQUAL_size_t(0, plan.n);
    }
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

static void read_pat_should_fail_cleanly_out_of_memory(void)
{
    qc_plan plan = {0}, back;
    membuf m;
    size_t i, k;
    int rc = QC_ENOMEM;

    for (i = 0; i < 100; i++)
        push(&plan, (double)i, (double)(i % 7), i == 0 ? QC_ST_JUMP : 0);
    encode(QC_FORMAT_PAT, &plan, NULL, &m);
    for (k = 1; rc == QC_ENOMEM; k++) {
        ta.fail_at = ta.allocs + k;
        rc = qc_io_read_pat(&ctx, m.p, m.n, &back);
        if (rc == QC_OK)
            break;
        TEST_ASSERT_EQUAL_INT(QC_ENOMEM, rc);
        TEST_ASSERT_EQUAL_size_t(2, ta.live_blocks); /* only the plan's */
    }
    ta.fail_at = 0;
    TEST_ASSERT_EQUAL_size_t(100, back.n);
    qc_plan_free(&ctx, &back);
    qc_plan_free(&ctx, &plan);
    free(m.p);
}

static void read_pat_should_survive_mutated_input(void)
{
    qc_plan plan, back;
    qc_rng rng;
    membuf m;
    char *buf;
    int iter, ok = 0;

    golden_plan(&plan);
    encode(QC_FORMAT_PAT, &plan, NULL, &m);
    buf = (char *)malloc(m.n);
    TEST_ASSERT_NOT_NULL(buf);
    qc_rng_seed(&rng, 99);
    for (iter = 0; iter < 3000; iter++) {
        size_t len = m.n, k, nmut = 1 + (size_t)qc_rng_below(&rng, 3);
        int rc;

        memcpy(buf, m.p, m.n);
        for (k = 0; k < nmut; k++) {
            size_t at = (size_t)qc_rng_below(&rng, len);
            static const char alphabet[] = "0123456789.-NGXYM\r\n ";
            switch (qc_rng_below(&rng, 3)) {
            case 0: buf[at] = alphabet[qc_rng_below(&rng, sizeof alphabet - 1)]; break;
            case 1: len = at; break; /* truncate */
            default: buf[at] = (char)qc_rng_below(&rng, 256); break;
            }
            if (len == 0)
                break;
        }
        rc = qc_io_read_pat(&ctx, buf, len, &back);
        TEST_ASSERT_TRUE(rc == QC_OK || rc == QC_EFORMAT || rc == QC_EEMPTY);
        if (rc == QC_OK) {
            ok++;
            TEST_ASSERT_TRUE(back.n > 0 && (back.flags[0] & QC_ST_JUMP));
        } else {
            TEST_ASSERT_EQUAL_size_t(0, back.n);
        }
        qc_plan_free(&ctx, &back);
    }
    TEST_ASSERT_GREATER_THAN(0, ok); /* some mutations stay valid (digit swaps) */
    TEST_ASSERT_EQUAL_size_t(2, ta.live_blocks); /* only the plan's */
    free(buf);
    free(m.p);
    qc_plan_free(&ctx, &plan);
}

static void svg_should_match_golden_bytes_in_mm_and_inches(void)
{
    qc_region reg = {0};
    qc_vec2 sq[4] = {{0, 0}, {110, 0}, {110, 230}, {0, 230}};
    qc_vec2 hole[3] = {{40, 100}, {60, 100}, {50, 120}};
    qc_io_opts o;

    memset(&o, 0, sizeof o);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, &reg, sq, 4));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, &reg, hole, 3));
    o.region = &reg;
    check_golden(QC_FORMAT_SVG, &o, "small.svg");
    o.svg_inches = 1;
    o.region = NULL;
    check_golden(QC_FORMAT_SVG, &o, "small-in.svg");
    qc_region_free(&ctx, &reg);
}

static void other_formats_should_match_golden_bytes(void)
{
    qc_io_opts o;

    memset(&o, 0, sizeof o);
    check_golden(QC_FORMAT_QLI, NULL, "small.qli");
    check_golden(QC_FORMAT_DXF, NULL, "small.dxf");
    check_golden(QC_FORMAT_HPGL, NULL, "small.plt");
    check_golden(QC_FORMAT_QCC, NULL, "small.qcc");
    check_golden(QC_FORMAT_IQP, NULL, "small.iqp");
    check_golden(QC_FORMAT_BQM, NULL, "small.bqm");
    check_golden(QC_FORMAT_GCODE, NULL, "small.gcode");
    o.feed_mm_min = 2400.5;
    check_golden(QC_FORMAT_GCODE, &o, "small-feed.gcode");
    o.pen_up = "M5";
    o.pen_down = "M3 S1000";
    check_golden(QC_FORMAT_GCODE, &o, "small-pen-m3.gcode");
    o.pen_up = o.pen_down = "";
    check_golden(QC_FORMAT_GCODE, &o, "small-no-pen.gcode");
    o.pen_up = "G0 Z5\nG28"; /* a command must stay one line */
    {
        qc_plan plan;
        membuf m;

        memset(&m, 0, sizeof m);
        m.fail_after = -1;
        golden_plan(&plan);
        TEST_ASSERT_EQUAL_INT(QC_EINVAL, qc_io_write(&ctx, QC_FORMAT_GCODE, &plan, &o, mem_write, &m));
        TEST_ASSERT_EQUAL_size_t(0, m.n);
        qc_plan_free(&ctx, &plan);
        free(m.p);
    }
    o.pen_up = o.pen_down = NULL;
    o.feed_mm_min = -1;
    {
        qc_plan plan;
        membuf m;

        memset(&m, 0, sizeof m);
        m.fail_after = -1;
        golden_plan(&plan);
        TEST_ASSERT_EQUAL_INT(QC_ERANGE, qc_io_write(&ctx, QC_FORMAT_GCODE, &plan, &o, mem_write, &m));
        qc_plan_free(&ctx, &plan);
        free(m.p);
    }
}

/* A pen plotter's G-code (the default pen lines, or M5/M3) reads back with
 * every jump a jump and every point where it was. */
static void gcode_pen_lines_should_keep_jumps_on_reading(void)
{
    static const char *const ups[] = {NULL, "M5"}, *const downs[] = {NULL, "M3"};
    size_t k, i;

    for (k = 0; k < 2; k++) {
        qc_plan plan, back = {0};
        qc_io_opts o;
        membuf m;

        memset(&o, 0, sizeof o);
        o.pen_up = ups[k];
        o.pen_down = downs[k];
        golden_plan(&plan);
        encode(QC_FORMAT_GCODE, &plan, &o, &m);
        TEST_ASSERT_EQUAL_INT(0, mem_write(&m, "", 1)); /* a NUL for strstr */
        m.n--;
        TEST_ASSERT_NOT_NULL(strstr(m.p, k == 0 ? "G0 Z5\nG0 X50.800 Y25.400\nG1 Z0\n"
                                                : "M5\nG0 X50.800 Y25.400\nM3\n"));
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_io_read(&ctx, QC_FORMAT_GCODE, m.p, m.n, &back));
        TEST_ASSERT_EQUAL_size_t(plan.n, back.n);
        for (i = 0; i < plan.n; i++) {
            TEST_ASSERT_DOUBLE_WITHIN(0.0006, plan.p[i].x, back.p[i].x);
            TEST_ASSERT_DOUBLE_WITHIN(0.0006, plan.p[i].y, back.p[i].y);
            TEST_ASSERT_EQUAL_INT(plan.flags[i] & QC_ST_JUMP, back.flags[i] & QC_ST_JUMP);
        }
        qc_plan_free(&ctx, &back);
        qc_plan_free(&ctx, &plan);
        free(m.p);
    }
}

static void format_names_should_round_trip(void)
{
    int f;

    for (f = 1; f < QC_FORMAT_COUNT; f++) {
        TEST_ASSERT_EQUAL_INT(f, qc_format_from_name(qc_format_name(f)));
        TEST_ASSERT_EQUAL_INT(f, qc_format_from_name(qc_format_ext(f)));
    }
    TEST_ASSERT_EQUAL_INT(QC_FORMAT_PAT, qc_format_from_name("PAT"));
    TEST_ASSERT_EQUAL_INT(QC_FORMAT_PAT, qc_format_from_name("design.Pat"));
    TEST_ASSERT_EQUAL_INT(QC_FORMAT_HPGL, qc_format_from_name("plt"));
    TEST_ASSERT_EQUAL_INT(QC_FORMAT_HPGL, qc_format_from_name("hpgl"));
    TEST_ASSERT_EQUAL_INT(QC_FORMAT_GCODE, qc_format_from_name("nc"));
    TEST_ASSERT_EQUAL_INT(QC_FORMAT_GCODE, qc_format_from_name(".gcode"));
    TEST_ASSERT_EQUAL_STRING(".plt", qc_format_ext(QC_FORMAT_HPGL));
    TEST_ASSERT_EQUAL_STRING("pat", qc_format_name(QC_FORMAT_PAT));
    TEST_ASSERT_EQUAL_INT(-1, qc_format_from_name("pa"));
    TEST_ASSERT_EQUAL_INT(-1, qc_format_from_name("patx"));
    TEST_ASSERT_EQUAL_INT(-1, qc_format_from_name(""));
    TEST_ASSERT_EQUAL_INT(-1, qc_format_from_name(NULL));
    TEST_ASSERT_NULL(qc_format_name(0));
    TEST_ASSERT_NULL(qc_format_ext(99));
}

/* For tests/check_readers.sh: a plan of three pieces (a spiral, a zigzag, a
 * wave) in every format, and its points. */
static void write_reader_samples(const char *dir)
{
    qc_plan plan = {0};
    char path[512];
    FILE *f;
    size_t i;
    int fmt;

    for (i = 0; i < 200; i++) {
        double a = (double)i * 0.1, r = 10 + (double)i * 0.2;
        push(&plan, 60 + r * qc_cos(a), 60 + r * qc_sin(a), i == 0 ? QC_ST_JUMP : 0);
    }
    for (i = 0; i < 40; i++)
        push(&plan, 130 + (double)i * 1.37, 10 + (i & 1) * 7.77, i == 0 ? QC_ST_JUMP : 0);
    for (i = 0; i < 100; i++)
        push(&plan, 130 + (double)i * 0.61, 80 + 9.3 * qc_sin((double)i * 0.2),
             i == 0 ? QC_ST_JUMP : i < 4 ? QC_ST_TIE : 0);
    for (fmt = 1; fmt < QC_FORMAT_COUNT; fmt++) {
        membuf m;

        qc_io_opts o;

        /* pystitch (an embroidery reader) takes a Z-only G1 for a stitch: no pen lines */
        memset(&o, 0, sizeof o);
        o.pen_up = o.pen_down = "";
        encode(fmt, &plan, &o, &m);
        snprintf(path, sizeof path, "%s/sample%s", dir, qc_format_ext(fmt));
        write_file(path, m.p, m.n);
        free(m.p);
    }
    snprintf(path, sizeof path, "%s/sample.csv", dir);
    f = fopen(path, "w");
    TEST_ASSERT_NOT_NULL(f);
    fprintf(f, "x_mm,y_mm,jump\n");
    for (i = 0; i < plan.n; i++)
        fprintf(f, "%.17g,%.17g,%d\n", plan.p[i].x, plan.p[i].y,
                (plan.flags[i] & QC_ST_JUMP) != 0);
    fclose(f);
    qc_plan_free(&ctx, &plan);
}

static void reader_samples_should_be_written_when_asked(void)
{
    const char *dir = getenv("QC_READERS_DIR");

    if (dir == NULL)
        TEST_IGNORE_MESSAGE("QC_READERS_DIR not set (tests/check_readers.sh sets it)");
    write_reader_samples(dir);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(pat_should_match_golden_bytes);
    RUN_TEST(pat_should_use_the_exact_dialect);
    RUN_TEST(numbers_should_round_half_away_from_zero_and_format_exactly);
    RUN_TEST(numbers_should_format_as_printf_at_every_length);
    RUN_TEST(thousandths_should_format_as_printf_for_every_value);
    RUN_TEST(pat_should_number_lines_across_every_carry);
    RUN_TEST(pat_should_refuse_negative_and_report_errors);
    RUN_TEST(writers_should_report_write_failure);
    RUN_TEST(pat_should_round_trip_within_half_a_thousandth);
    RUN_TEST(read_pat_should_accept_lf_and_reject_malformed_lines);
    RUN_TEST(read_pat_should_fail_cleanly_out_of_memory);
    RUN_TEST(read_pat_should_survive_mutated_input);
    RUN_TEST(svg_should_match_golden_bytes_in_mm_and_inches);
    RUN_TEST(other_formats_should_match_golden_bytes);
    RUN_TEST(gcode_pen_lines_should_keep_jumps_on_reading);
    RUN_TEST(format_names_should_round_trip);
    if (getenv("QC_READERS_DIR") != NULL)
        RUN_TEST(reader_samples_should_be_written_when_asked);
    return UNITY_END();
}
