/*
 * The pattern readers of every machine format (qc_io_read): what each
 * writer writes reads back within the format's resolution with its jumps;
 * hand-written files in each dialect (arcs, bulges, splines, units,
 * relative moves, pen up) read as drawn; malformed files fail with a
 * message naming the line; every failed allocation is survived.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "quiltc.h"
#include "testalloc.h"
#include "testgeom.h"
#include "unity.h"

typedef struct buf {
    char *p;
    size_t n, cap;
} buf;

static int to_buf(void *ud, const void *data, size_t len)
{
    buf *b = ud;

    if (b->n + len > b->cap) {
        b->cap = (b->n + len) * 2;
        b->p = realloc(b->p, b->cap);
        TEST_ASSERT_NOT_NULL(b->p);
    }
    memcpy(b->p + b->n, data, len);
    b->n += len;
    return 0;
}

static qc_ctx ctx;

/* Two pieces: a zigzag and a square, the second reached by a jump. */
static void sample_plan(qc_plan *pl)
{
    int i;

    memset(pl, 0, sizeof *pl);
    for (i = 0; i < 40; i++)
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_plan_push(&ctx, pl, v2(3.0 + 2.5 * i, 10.0 + (i % 2) * 7.3 + 0.01 * i),
                                                  i == 0 ? QC_ST_JUMP : 0));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_plan_push(&ctx, pl, v2(50.3, 60.1), QC_ST_JUMP));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_plan_push(&ctx, pl, v2(80.7, 60.1), 0));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_plan_push(&ctx, pl, v2(80.7, 90.9), 0));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_plan_push(&ctx, pl, v2(50.3, 90.9), 0));
}

static buf encode(int format, const qc_plan *pl)
{
    buf b = {0};

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_io_write(&ctx, format, pl, NULL, to_buf, &b));
    return b;
}

/* Every writer's file reads back: same points within tol (mm), same jumps
 * (QCC has no travel: one piece, the jump sewn). */
static void round_trip(int format, double tol, int keeps_jumps)
{
    qc_plan in, out;
    buf b;
    size_t i;

    sample_plan(&in);
    b = encode(format, &in);
    TEST_ASSERT_EQUAL_INT_MESSAGE(QC_OK, qc_io_read(&ctx, format, b.p, b.n, &out), qc_errmsg(&ctx));
    TEST_ASSERT_EQUAL_size_t(in.n, out.n);
    for (i = 0; i < in.n; i++) {
        TEST_ASSERT_DOUBLE_WITHIN(tol, in.p[i].x, out.p[i].x);
        TEST_ASSERT_DOUBLE_WITHIN(tol, in.p[i].y, out.p[i].y);
        if (keeps_jumps || i == 0)
            TEST_ASSERT_EQUAL_INT(in.flags[i] & QC_ST_JUMP, out.flags[i] & QC_ST_JUMP);
        else
            TEST_ASSERT_EQUAL_INT(0, out.flags[i] & QC_ST_JUMP);
    }
    free(b.p);
    qc_plan_free(&ctx, &in);
    qc_plan_free(&ctx, &out);
}

static void test_every_writer_should_read_back_within_its_resolution(void)
{
    round_trip(QC_FORMAT_PAT, 0.0127, 1);
    round_trip(QC_FORMAT_QLI, 0.0127, 1);
    round_trip(QC_FORMAT_DXF, 0.0001, 1);
    round_trip(QC_FORMAT_HPGL, 0.0125, 1);
    round_trip(QC_FORMAT_QCC, 0.00127, 0);
    round_trip(QC_FORMAT_IQP, 0.0001, 1);
    round_trip(QC_FORMAT_BQM, 0.00127, 1);
    round_trip(QC_FORMAT_GCODE, 0.0005, 1);
}

static void read_text(int format, const char *text, qc_plan *out)
{
    int rc = qc_io_read(&ctx, format, text, strlen(text), out);

    TEST_ASSERT_EQUAL_INT_MESSAGE(QC_OK, rc, qc_errmsg(&ctx));
}

/* Every point lies at r from c, within the arc's 0.05 mm flattening. */
static void assert_on_circle(const qc_plan *pl, size_t from, size_t to, qc_vec2 c, double r)
{
    size_t i;

    for (i = from; i < to; i++)
        TEST_ASSERT_DOUBLE_WITHIN(1e-6, r, hypot(pl->p[i].x - c.x, pl->p[i].y - c.y));
    for (i = from + 1; i < to; i++) {
        qc_vec2 m = v2((pl->p[i].x + pl->p[i - 1].x) / 2, (pl->p[i].y + pl->p[i - 1].y) / 2);

        TEST_ASSERT_TRUE(r - hypot(m.x - c.x, m.y - c.y) <= 0.05 + 1e-9);
    }
}

static void assert_point(qc_vec2 want, qc_vec2 got, double tol)
{
    TEST_ASSERT_DOUBLE_WITHIN(tol, want.x, got.x);
    TEST_ASSERT_DOUBLE_WITHIN(tol, want.y, got.y);
}

static void test_qli_arcs_and_needle_should_read_as_drawn(void)
{
    /* From (1, 0) in, a CCW quarter circle of radius 1 in about the origin,
     * then travel with the needle off and a stitched line. */
    qc_plan pl;

    read_text(QC_FORMAT_QLI, "#CAD2DMC\r\nCS\r\nVMXY\r\nNO NEEDLE OFF\r\nVP 1000,0\r\n"
                             "NO NEEDLE ON\r\nCR 1000,0,90\r\nNO NEEDLE OFF;VP 3000,3000\r\n"
                             "NO NEEDLE ON\r\nVP 4000,3000\r\nVE\r\nBGS\r\nAMS\r\nEN\r\n",
              &pl);
    TEST_ASSERT_TRUE(pl.n > 10);
    assert_point(v2(25.4, 0), pl.p[0], 1e-9);
    assert_on_circle(&pl, 0, pl.n - 2, v2(0, 0), 25.4);
    assert_point(v2(0, 25.4), pl.p[pl.n - 3], 1e-9);
    TEST_ASSERT_EQUAL_INT(QC_ST_JUMP, pl.flags[pl.n - 2]);
    assert_point(v2(76.2, 76.2), pl.p[pl.n - 2], 1e-9);
    assert_point(v2(101.6, 76.2), pl.p[pl.n - 1], 1e-9);
    qc_plan_free(&ctx, &pl);
}

static void test_dxf_entities_and_units_should_read_as_drawn(void)
{
    /* Inches: an LWPOLYLINE whose bulge 1 makes a CCW half circle from
     * (0, 0) to (2, 0) (centre (1, 0), below the chord), a LINE, a CIRCLE
     * mirrored by its extrusion, and a degree-1 SPLINE (its control
     * polygon). */
    static const char doc[] =
        "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n1\n0\nENDSEC\n"
        "0\nSECTION\n2\nENTITIES\n"
        "0\nLWPOLYLINE\n8\n0\n90\n2\n70\n0\n10\n0\n20\n0\n42\n1.0\n10\n2\n20\n0\n"
        "0\nLINE\n8\n0\n10\n2\n20\n0\n11\n2\n21\n3\n"
        "0\nCIRCLE\n10\n5.0\n20\n5.0\n40\n1.5E+0\n210\n0\n220\n0\n230\n-1\n"
        "0\nSPLINE\n70\n8\n71\n1\n72\n4\n73\n2\n40\n0\n40\n0\n40\n1\n40\n1\n"
        "10\n7\n20\n0\n10\n9\n20\n2\n"
        "0\nENDSEC\n0\nEOF\n";
    qc_plan pl;
    size_t i, circle_start = 0, spline_start = 0;

    read_text(QC_FORMAT_DXF, doc, &pl);
    for (i = 1; i < pl.n; i++)
        if (pl.flags[i] & QC_ST_JUMP) {
            if (circle_start == 0)
                circle_start = i;
            else
                spline_start = i;
        }
    TEST_ASSERT_TRUE(circle_start > 0 && spline_start > circle_start);
    /* The polyline and the line are one piece: the line starts where it ends. */
    assert_on_circle(&pl, 0, circle_start - 1, v2(25.4, 0), 25.4);
    for (i = 1; i + 1 < circle_start; i++)
        TEST_ASSERT_TRUE(pl.p[i].y <= 1e-9); /* CCW from (0,0) to (2,0): the lower half */
    assert_point(v2(50.8, 76.2), pl.p[circle_start - 1], 1e-9);
    /* Mirrored by extrusion (0, 0, -1): the centre is at x = -5 in. */
    assert_on_circle(&pl, circle_start, spline_start, v2(-127, 127), 38.1);
    assert_point(v2(7 * 25.4, 0), pl.p[spline_start], 1e-9);
    assert_point(v2(9 * 25.4, 2 * 25.4), pl.p[pl.n - 1], 1e-9);
    for (i = spline_start; i < pl.n; i++)
        TEST_ASSERT_DOUBLE_WITHIN(1e-9, pl.p[i].x - 7 * 25.4, pl.p[i].y);
    qc_plan_free(&ctx, &pl);
}

/* The smallest distance from q to the plan's points, in mm. */
static double nearest(const qc_plan *pl, size_t from, qc_vec2 q)
{
    double best = HUGE_VAL;
    size_t i;

    for (i = from; i < pl->n; i++)
        best = fmin(best, qc_hypot(pl->p[i].x - q.x, pl->p[i].y - q.y));
    return best;
}

static void survive_oom(int format, const char *text, size_t len, size_t want);

/* The x where a DXF whose header is hdr draws LINE (0,0)-(1,0) ends, in mm. */
static double dxf_line_end(const char *hdr)
{
    char doc[512];
    qc_plan pl;
    double x;

    snprintf(doc, sizeof doc,
             "0\nSECTION\n2\nHEADER\n%s0\nENDSEC\n0\nSECTION\n2\nENTITIES\n"
             "0\nLINE\n10\n0\n20\n0\n11\n1\n21\n0\n0\nENDSEC\n0\nEOF\n", hdr);
    read_text(QC_FORMAT_DXF, doc, &pl);
    x = pl.p[pl.n - 1].x;
    qc_plan_free(&ctx, &pl);
    return x;
}

static void test_dxf_units_should_follow_insunits_then_measurement(void)
{
    TEST_ASSERT_EQUAL_DOUBLE(1.0, dxf_line_end(""));
    TEST_ASSERT_EQUAL_DOUBLE(25.4, dxf_line_end("9\n$MEASUREMENT\n70\n0\n"));
    TEST_ASSERT_EQUAL_DOUBLE(1.0, dxf_line_end("9\n$MEASUREMENT\n70\n1\n"));
    TEST_ASSERT_EQUAL_DOUBLE(25.4, dxf_line_end("9\n$INSUNITS\n70\n0\n9\n$MEASUREMENT\n70\n0\n"));
    TEST_ASSERT_EQUAL_DOUBLE(10.0, dxf_line_end("9\n$MEASUREMENT\n70\n0\n9\n$INSUNITS\n70\n5\n"));
    TEST_ASSERT_EQUAL_DOUBLE(1.0, dxf_line_end("9\n$INSUNITS\n70\n4\n9\n$MEASUREMENT\n70\n0\n"));
}

static void test_dxf_fit_point_spline_should_pass_its_points(void)
{
    /* mm: a curve through four fit points, then one leaving straight up
     * (start tangent 0,1) and arriving heading +x (end tangent 2,0) */
    static const char doc[] =
        "0\nSECTION\n2\nENTITIES\n"
        "0\nSPLINE\n70\n8\n71\n3\n74\n4\n"
        "11\n0\n21\n0\n11\n10\n21\n20\n11\n25\n21\n5\n11\n40\n21\n15\n"
        "0\nSPLINE\n70\n8\n71\n3\n74\n3\n12\n0\n22\n1\n13\n2\n23\n0\n"
        "11\n100\n21\n0\n11\n110\n21\n10\n11\n120\n21\n0\n"
        "0\nENDSEC\n0\nEOF\n";
    static const double fit[7][2] = {{0, 0}, {10, 20}, {25, 5}, {40, 15},
                                     {100, 0}, {110, 10}, {120, 0}};
    qc_plan pl;
    size_t i, second = 0, n;

    read_text(QC_FORMAT_DXF, doc, &pl);
    n = pl.n;
    for (i = 1; i < pl.n; i++)
        if (pl.flags[i] & QC_ST_JUMP)
            second = i;
    TEST_ASSERT_TRUE(second > 20 && pl.n - second > 20);
    for (i = 0; i < 7; i++)
        TEST_ASSERT_TRUE(nearest(&pl, 0, v2(fit[i][0], fit[i][1])) < 1e-9);
    assert_point(v2(0, 0), pl.p[0], 1e-9);
    assert_point(v2(100, 0), pl.p[second], 1e-9);
    assert_point(v2(120, 0), pl.p[pl.n - 1], 1e-9);
    /* the tangents: straight up out of (100, 0), level into (120, 0) (the
     * first stitch is a chord, 0.4 mm long; without them, 45 degrees) */
    TEST_ASSERT_DOUBLE_WITHIN(0.06, 0.0, (pl.p[second + 1].x - 100) / (pl.p[second + 1].y));
    TEST_ASSERT_DOUBLE_WITHIN(0.06, 0.0, pl.p[pl.n - 2].y / (120 - pl.p[pl.n - 2].x));
    /* no tangents: no curvature at the ends, so it leaves (0, 0) towards
     * the chord's side and is no straight line */
    TEST_ASSERT_TRUE(nearest(&pl, 0, v2(5, 10)) > 0.5);
    qc_plan_free(&ctx, &pl);
    survive_oom(QC_FORMAT_DXF, doc, sizeof doc - 1, n);
}

static void test_hpgl_relative_moves_and_pen_should_read_as_drawn(void)
{
    qc_plan pl;

    read_text(QC_FORMAT_HPGL, "IN;SP1;PU400,400;PD800,400,800,800;PR;PU400,0;PD0,-400;PA;PU0,0;SP0;", &pl);
    TEST_ASSERT_EQUAL_size_t(5, pl.n);
    assert_point(v2(10, 10), pl.p[0], 1e-12);
    assert_point(v2(20, 20), pl.p[2], 1e-12);
    TEST_ASSERT_EQUAL_INT(QC_ST_JUMP, pl.flags[3]);
    assert_point(v2(30, 20), pl.p[3], 1e-12);
    assert_point(v2(30, 10), pl.p[4], 1e-12);
    qc_plan_free(&ctx, &pl);
}

static void test_gcode_units_arcs_and_pen_up_should_read_as_drawn(void)
{
    qc_plan pl;

    /* Inches, a clockwise half circle (I, J relative), relative moves, and
     * a pen-up G1 that travels. */
    read_text(QC_FORMAT_GCODE, "%\n(test) G20 G90\nG0 X1 Y0\nG2 X3 Y0 I1 J0 F100 ; half\n"
                               "G91\nG1 Z5\nG1 X1\nG1 Z0\nG1 Y1\nM2\n",
              &pl);
    assert_point(v2(25.4, 0), pl.p[0], 1e-9);
    assert_on_circle(&pl, 0, pl.n - 2, v2(50.8, 0), 25.4);
    TEST_ASSERT_TRUE(pl.p[1].y > 0); /* clockwise from the left: over the top */
    TEST_ASSERT_EQUAL_INT(QC_ST_JUMP, pl.flags[pl.n - 2]);
    assert_point(v2(101.6, 0), pl.p[pl.n - 2], 1e-9);
    assert_point(v2(101.6, 25.4), pl.p[pl.n - 1], 1e-9);
    qc_plan_free(&ctx, &pl);

    /* BQM: arcs with absolute centres, N numbers, inches by default. */
    read_text(QC_FORMAT_BQM, "N10G00X2.0000Y1.0000\nN11G03X1.0000Y2.0000I1.0000J1.0000\nN12M02\n", &pl);
    assert_on_circle(&pl, 0, pl.n, v2(25.4, 25.4), 25.4);
    assert_point(v2(25.4, 50.8), pl.p[pl.n - 1], 1e-9);
    qc_plan_free(&ctx, &pl);
}

static void test_qcc_and_iqp_should_read_as_drawn(void)
{
    static const unsigned char iqp[] = {
        'S', 't', 'i', 't', 'c', 'h', 'V', '2', ' ', ' ', ' ', ' ', ' ', ' ', ' ', ' ',
        0, 0, 0, 0, 0, 0, 0, 0,
        8, 0, 0, 0, 3, 0, 0, 0, 'a', 'b', 'c',            /* a text record */
        7, 0, 0, 0, 8, 0, 0, 0,                            /* two points */
        0, 0, 0x80, 0x3f, 0, 0, 0, 0x40, 0, 0, 0x40, 0x40, 0, 0, 0x80, 0x40, /* (1,2) (3,4) */
        2, 0, 0, 0};
    qc_plan pl;

    read_text(QC_FORMAT_QCC, "c s\np X1.0000 Y2.0000\np X1.5000 Y2.0000\n", &pl);
    TEST_ASSERT_EQUAL_size_t(2, pl.n);
    assert_point(v2(38.1, 50.8), pl.p[1], 1e-9);
    qc_plan_free(&ctx, &pl);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_io_read(&ctx, QC_FORMAT_IQP, (const char *)iqp, sizeof iqp, &pl));
    TEST_ASSERT_EQUAL_size_t(2, pl.n);
    assert_point(v2(25.4, 50.8), pl.p[0], 1e-9);
    assert_point(v2(76.2, 101.6), pl.p[1], 1e-9);
    qc_plan_free(&ctx, &pl);
}

/* A malformed file fails with status and a message that contains want. */
static void refuses(int format, const char *text, size_t len, int status, const char *want)
{
    qc_plan pl;
    int rc = qc_io_read(&ctx, format, text, len, &pl);

    TEST_ASSERT_EQUAL_INT_MESSAGE(status, rc, qc_errmsg(&ctx));
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(qc_errmsg(&ctx), want), qc_errmsg(&ctx));
    TEST_ASSERT_EQUAL_size_t(0, pl.n);
    TEST_ASSERT_NULL(pl.p);
}

#define REFUSES(f, text, status, want) refuses(f, text, sizeof text - 1, status, want)

static void test_malformed_files_should_fail_naming_the_line(void)
{
    REFUSES(QC_FORMAT_QLI, "CS\nVP 1,2\nVP 1;2\n", QC_EFORMAT, "qli line 3");
    REFUSES(QC_FORMAT_QLI, "CS\nXQ 5\n", QC_EFORMAT, "unknown command");
    REFUSES(QC_FORMAT_QLI, "VP 1,1\nVP 99999999999,0\n", QC_ERANGE, "qli line 2");
    REFUSES(QC_FORMAT_QLI, "CS\nVE\nEN\n", QC_EEMPTY, "no move");
    REFUSES(QC_FORMAT_HPGL, "IN;\nSC0,100,0,100;PD1,1;", QC_EFORMAT, "hpgl line 2: SC");
    REFUSES(QC_FORMAT_HPGL, "IN;PU1,1;PD5;", QC_EFORMAT, "y coordinate");
    REFUSES(QC_FORMAT_QCC, "p X1 Y1\n", QC_EFORMAT, "qcc line 1");
    REFUSES(QC_FORMAT_QCC, "c s\np X1 Y\n", QC_EFORMAT, "qcc line 2");
    REFUSES(QC_FORMAT_GCODE, "G1 X1 Y1\nG1 X2\nG28 X0\n", QC_EFORMAT, "gcode line 3: unsupported G");
    REFUSES(QC_FORMAT_GCODE, "G1 X1 X2\n", QC_EFORMAT, "given twice");
    REFUSES(QC_FORMAT_GCODE, "G1 X1 Y1\nG1 X1..2 Y0\n", QC_EFORMAT, "gcode line 2");
    REFUSES(QC_FORMAT_GCODE, "G1 X1 Y1\nG1 X2\nM2\nG1 X3\n", QC_EFORMAT, "after the program's end");
    REFUSES(QC_FORMAT_BQM, "N10G00X0Y0\nN11G02X1Y1R0.1\n", QC_EFORMAT, "bqm line 2");
    REFUSES(QC_FORMAT_DXF, "0\nSECTION\n2\nENTITIES\n0\nINSERT\n2\nblk\n0\nENDSEC\n0\nEOF\n",
            QC_EFORMAT, "INSERT");
    REFUSES(QC_FORMAT_DXF, "0\nSECTION\n2\nENTITIES\n0\nLINE\n10\nabc\n", QC_EFORMAT, "dxf line 8");
    REFUSES(QC_FORMAT_DXF, "0\nSECTION\n2\nENTITIES\n0\nLINE\n10\n0\n20\n0\n11\n1\n21\n1\n",
            QC_EFORMAT, "without EOF");
    REFUSES(QC_FORMAT_DXF, "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n9\n0\nENDSEC\n0\nEOF\n",
            QC_EFORMAT, "$INSUNITS");
    REFUSES(QC_FORMAT_DXF, "0\nSECTION\n2\nENTITIES\n0\nSPLINE\n71\n3\n11\n1\n21\n1\n0\nENDSEC\n0\nEOF\n",
            QC_EFORMAT, "two or more fit points");
    REFUSES(QC_FORMAT_DXF, "0\nSECTION\n2\nHEADER\n9\n$MEASUREMENT\n70\n2\n0\nENDSEC\n0\nEOF\n",
            QC_EFORMAT, "$MEASUREMENT");
    REFUSES(QC_FORMAT_IQP, "StitchV2        \0\0\0\0\0\0\0\0\7\0\0\0\100\0\0\0", QC_EFORMAT,
            "longer than the file");
    REFUSES(QC_FORMAT_IQP, "StitchV1", QC_EFORMAT, "StitchV2");
    REFUSES(QC_FORMAT_IQP, "StitchV2        \0\0\0\0\0\0\0\0\7\0\0\0\4\0\0\0\377\377\377\177\0\0\0\0\2\0\0\0",
            QC_ERANGE, "iqp byte 24: point");
    REFUSES(QC_FORMAT_IQP, "StitchV2        \0\0\0\0\0\0\0\0\2\0\0\0x", QC_EFORMAT,
            "after the end record");
}

/* Every failed allocation reading text gives QC_ENOMEM, an empty plan
 * and no leak; the run that fails nothing reads want points. */
static void survive_oom(int format, const char *text, size_t len, size_t want)
{
    size_t k;

    for (k = 1;; k++) {
        testalloc t;
        qc_ctx c;
        qc_plan out;
        int rc;

        memset(&t, 0, sizeof t);
        t.fail_at = k;
        qc_ctx_init(&c, testalloc_fn, &t);
        rc = qc_io_read(&c, format, text, len, &out);
        TEST_ASSERT_FALSE(t.size_mismatch);
        if (rc == QC_OK) {
            TEST_ASSERT_EQUAL_size_t(want, out.n);
            qc_plan_free(&c, &out);
            TEST_ASSERT_EQUAL_size_t(0, t.live_blocks);
            return;
        }
        TEST_ASSERT_EQUAL_INT(QC_ENOMEM, rc);
        TEST_ASSERT_EQUAL_size_t(0, out.n);
        TEST_ASSERT_EQUAL_size_t(0, t.live_blocks);
    }
}

static void test_readers_should_survive_every_failed_allocation(void)
{
    static const int formats[] = {QC_FORMAT_QLI, QC_FORMAT_DXF, QC_FORMAT_HPGL, QC_FORMAT_QCC,
                                  QC_FORMAT_IQP, QC_FORMAT_BQM, QC_FORMAT_GCODE};
    /* A rational spline: knots, weights before the control points. */
    static const char spline[] =
        "0\nSECTION\n2\nENTITIES\n0\nSPLINE\n70\n8\n71\n2\n72\n6\n73\n3\n"
        "40\n0\n40\n0\n40\n0\n40\n1\n40\n1\n40\n1\n41\n1\n41\n2\n41\n1\n"
        "10\n0\n20\n0\n10\n50\n20\n80\n10\n100\n20\n0\n0\nENDSEC\n0\nEOF\n";
    qc_plan in, sp;
    size_t f;

    sample_plan(&in);
    for (f = 0; f < sizeof formats / sizeof formats[0]; f++) {
        buf b = encode(formats[f], &in);

        survive_oom(formats[f], b.p, b.n, in.n);
        free(b.p);
    }
    read_text(QC_FORMAT_DXF, spline, &sp);
    TEST_ASSERT_TRUE(sp.n > 100);
    survive_oom(QC_FORMAT_DXF, spline, sizeof spline - 1, sp.n);
    qc_plan_free(&ctx, &sp);
    qc_plan_free(&ctx, &in);
}

void setUp(void)
{
    qc_ctx_init(&ctx, NULL, NULL);
}

void tearDown(void)
{
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_every_writer_should_read_back_within_its_resolution);
    RUN_TEST(test_qli_arcs_and_needle_should_read_as_drawn);
    RUN_TEST(test_dxf_entities_and_units_should_read_as_drawn);
    RUN_TEST(test_dxf_fit_point_spline_should_pass_its_points);
    RUN_TEST(test_dxf_units_should_follow_insunits_then_measurement);
    RUN_TEST(test_hpgl_relative_moves_and_pen_should_read_as_drawn);
    RUN_TEST(test_gcode_units_arcs_and_pen_up_should_read_as_drawn);
    RUN_TEST(test_qcc_and_iqp_should_read_as_drawn);
    RUN_TEST(test_malformed_files_should_fail_naming_the_line);
    RUN_TEST(test_readers_should_survive_every_failed_allocation);
    return UNITY_END();
}
