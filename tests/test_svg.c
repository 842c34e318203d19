/*
 * SVG reader: every element kind with exact coordinates, units and viewBox,
 * transforms, arcs, path syntax (relative, implicit repeats, packed numbers
 * and flags), holes and fill rules, skipped elements, error paths (status
 * and message), limits, out-of-memory sweeps, a mutation fuzz loop and the
 * files in tests/fixtures/svg and tests/bad/svg. Run from the repository root.
 */
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
    TEST_ASSERT_FALSE(ta.size_mismatch);
}

/* One user unit is one mm, the document 100 mm tall: y_mm = 100 - y. */
#define DOC(body)                                                                        \
    "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"100mm\" height=\"100mm\" "        \
    "viewBox=\"0 0 100 100\">" body "</svg>"

static int region_of(const char *svg, qc_region *r)
{
    return qc_io_read_svg_region(&ctx, svg, strlen(svg), NULL, r);
}

static int path_of(const char *svg, qc_path *p)
{
    return qc_io_read_svg_path(&ctx, svg, strlen(svg), NULL, p);
}

static size_t ring_start(const qc_region *r, size_t k)
{
    return k ? r->ring_end[k - 1] : 0;
}

static double ring_area(const qc_region *r, size_t k)
{
    size_t s = ring_start(r, k), e = r->ring_end[k], i, j = e - 1;
    double a = 0;

    for (i = s; i < e; j = i++)
        a += r->v[j].x * r->v[i].y - r->v[i].x * r->v[j].y;
    return a / 2;
}

static void expect_point(double x, double y, qc_vec2 p, double tol)
{
    TEST_ASSERT_DOUBLE_WITHIN(tol, x, p.x);
    TEST_ASSERT_DOUBLE_WITHIN(tol, y, p.y);
}

static void expect_bbox(const qc_region *r, double x0, double y0, double x1, double y1, double tol)
{
    qc_bbox b = qc_region_bbox(r);

    expect_point(x0, y0, b.min, tol);
    expect_point(x1, y1, b.max, tol);
}

/* Reads svg as a region expecting one ring; returns its |area|. */
static double one_ring_area(const char *svg)
{
    qc_region r;
    double a;

    TEST_ASSERT_EQUAL_INT_MESSAGE(QC_OK, region_of(svg, &r), qc_errmsg(&ctx));
    TEST_ASSERT_EQUAL_size_t(1, r.nrings);
    a = fabs(ring_area(&r, 0));
    qc_region_free(&ctx, &r);
    return a;
}

/* Both readers fail with want and a message containing sub; nothing leaks
 * and the outputs are empty. path_want 0 skips the path reader. */
static void expect_fail(const char *svg, size_t len, int want, int path_want, const char *sub)
{
    qc_region r;
    qc_path p;
    int rc;

    rc = qc_io_read_svg_region(&ctx, svg, len, NULL, &r);
    TEST_ASSERT_EQUAL_INT_MESSAGE(want, rc, qc_errmsg(&ctx));
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(qc_errmsg(&ctx), sub), qc_errmsg(&ctx));
    TEST_ASSERT_EQUAL_size_t(0, r.nrings);
    TEST_ASSERT_NULL(r.v);
    if (path_want != 0) {
        rc = qc_io_read_svg_path(&ctx, svg, len, NULL, &p);
        TEST_ASSERT_EQUAL_INT_MESSAGE(path_want, rc, qc_errmsg(&ctx));
        if (path_want != QC_OK) {
            TEST_ASSERT_NOT_NULL_MESSAGE(strstr(qc_errmsg(&ctx), sub), qc_errmsg(&ctx));
            TEST_ASSERT_EQUAL_size_t(0, p.ncmd);
        }
        qc_path_free(&ctx, &p);
    }
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

static void expect_fail_str(const char *svg, int want, const char *sub)
{
    expect_fail(svg, strlen(svg), want, want, sub);
}

/* ---- elements ---- */

static void rect_should_read_exact_corners_in_mm(void)
{
    qc_region r;

    TEST_ASSERT_EQUAL_INT(QC_OK, region_of(DOC("<rect x=\"10\" y=\"20\" width=\"10\" height=\"20\"/>"), &r));
    TEST_ASSERT_EQUAL_size_t(1, r.nrings);
    TEST_ASSERT_EQUAL_size_t(4, r.nv);
    expect_point(10, 80, r.v[0], 0);
    expect_point(20, 80, r.v[1], 0);
    expect_point(20, 60, r.v[2], 0);
    expect_point(10, 60, r.v[3], 0);
    /* SVG's clockwise-on-screen becomes clockwise with y up too: negative */
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, -200.0, ring_area(&r, 0));
    qc_region_free(&ctx, &r);
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

static void rect_in_mm_units_should_have_area_200(void)
{
    qc_region r;

    /* no viewBox, no height: px user units, y simply negated */
    TEST_ASSERT_EQUAL_INT(QC_OK, region_of("<svg xmlns=\"http://www.w3.org/2000/svg\">"
                                           "<rect width=\"10mm\" height=\"20mm\"/></svg>",
                                           &r));
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 200.0, fabs(qc_region_area(&r)));
    expect_bbox(&r, 0, -20, 10, 0, 1e-12);
    qc_region_free(&ctx, &r);
}

static void rounded_rect_should_lose_the_corners(void)
{
    double a = one_ring_area(DOC("<rect x=\"10\" y=\"10\" width=\"40\" height=\"20\" rx=\"5\"/>"));
    double want = 800 - (4 - QC_PI) * 25, perim = 2 * (30 + 10) + 2 * QC_PI * 5;

    TEST_ASSERT_DOUBLE_WITHIN(perim * 0.06, want, a);
    TEST_ASSERT_TRUE(a < 800 - 1);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, a, one_ring_area(DOC("<rect x=\"10\" y=\"10\" width=\"40\" height=\"20\" "
                                                          "rx=\"auto\" ry=\"5\"/>")));
    /* ry alone is both radii, each clamped to half its side: an ellipse */
    a = one_ring_area(DOC("<rect width=\"40\" height=\"20\" ry=\"50\"/>"));
    TEST_ASSERT_DOUBLE_WITHIN(2 * QC_PI * 20 * 0.06, QC_PI * 20 * 10, a);
}

static void circle_and_ellipse_should_have_their_area(void)
{
    qc_region r;
    size_t i;

    TEST_ASSERT_EQUAL_INT(QC_OK, region_of(DOC("<circle cx=\"50\" cy=\"50\" r=\"20\"/>"), &r));
    TEST_ASSERT_DOUBLE_WITHIN(2 * QC_PI * 20 * 0.06, QC_PI * 400, fabs(qc_region_area(&r)));
    for (i = 0; i < r.nv; i++) {
        double d = qc_hypot(r.v[i].x - 50, r.v[i].y - 50);
        TEST_ASSERT_TRUE(d > 20 - 0.05 - 0.006 && d < 20 + 0.006);
    }
    qc_region_free(&ctx, &r);
    TEST_ASSERT_DOUBLE_WITHIN(QC_PI * 80 * 0.06, QC_PI * 300,
                              one_ring_area(DOC("<ellipse cx=\"50\" cy=\"50\" rx=\"30\" ry=\"10\"/>")));
    /* zero radius: nothing drawn */
    TEST_ASSERT_EQUAL_INT(QC_EEMPTY, region_of(DOC("<circle r=\"0\"/><ellipse rx=\"5\" ry=\"0\"/>"), &r));
}

static void polygon_should_close_and_polyline_line_should_be_open(void)
{
    qc_region r;
    qc_path p;

    TEST_ASSERT_EQUAL_INT(QC_OK, region_of(DOC("<polygon points=\"0,0 10,0 10,10\"/>"
                                               "<polyline points=\"0 0 50 50 0 50\"/>"
                                               "<line x1=\"0\" y1=\"0\" x2=\"5\" y2=\"5\"/>"),
                                           &r));
    TEST_ASSERT_EQUAL_size_t(1, r.nrings);
    TEST_ASSERT_EQUAL_size_t(3, r.nv);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 50, fabs(qc_region_area(&r)));
    qc_region_free(&ctx, &r);

    TEST_ASSERT_EQUAL_INT(QC_OK, path_of(DOC("<polygon points=\"0,0 10,0 10,10\"/>"
                                             "<polyline points=\"0 0 50 50 0 50\"/>"
                                             "<line x1=\"1\" y1=\"2\" x2=\"5\" y2=\"5\"/>"),
                                         &p));
    TEST_ASSERT_EQUAL_size_t(3, qc_path_pieces(&p));
    TEST_ASSERT_EQUAL_size_t(4 + 3 + 2, p.ncmd);
    expect_point(0, 100, p.pt[3], 0); /* polygon closed back to its start */
    expect_point(0, 50, p.pt[6], 0);  /* polyline ends where it ends */
    expect_point(1, 98, p.pt[7], 0);
    expect_point(5, 95, p.pt[8], 0);
    qc_path_free(&ctx, &p);
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

/* ---- units, viewBox ---- */

static void viewbox_should_scale_and_align(void)
{
    qc_region r;

    /* meet: 10 mm per unit, centred horizontally in 200 mm */
    TEST_ASSERT_EQUAL_INT(QC_OK, region_of("<svg width=\"200mm\" height=\"100mm\" viewBox=\"0 0 10 10\">"
                                           "<rect width=\"10\" height=\"10\"/></svg>",
                                           &r));
    expect_bbox(&r, 50, 0, 150, 100, 1e-9);
    qc_region_free(&ctx, &r);
    TEST_ASSERT_EQUAL_INT(QC_OK, region_of("<svg width=\"200mm\" height=\"100mm\" viewBox=\"0 0 10 10\" "
                                           "preserveAspectRatio=\"none\"><rect width=\"10\" height=\"10\"/></svg>",
                                           &r));
    expect_bbox(&r, 0, 0, 200, 100, 1e-9);
    qc_region_free(&ctx, &r);
    TEST_ASSERT_EQUAL_INT(QC_OK, region_of("<svg width=\"200mm\" height=\"100mm\" viewBox=\"0 0 10 10\" "
                                           "preserveAspectRatio=\"xMaxYMin slice\"><rect width=\"10\" height=\"10\"/></svg>",
                                           &r));
    expect_bbox(&r, 0, -100, 200, 100, 1e-9);
    qc_region_free(&ctx, &r);
    TEST_ASSERT_EQUAL_INT(QC_OK, region_of("<svg width=\"10mm\" height=\"10mm\" viewBox=\"-5 -5 10 10\">"
                                           "<rect x=\"-5\" y=\"-5\" width=\"10\" height=\"4\"/></svg>",
                                           &r));
    expect_bbox(&r, 0, 6, 10, 10, 1e-12);
    qc_region_free(&ctx, &r);
    /* only width: height follows the viewBox's aspect ratio */
    TEST_ASSERT_EQUAL_INT(QC_OK, region_of("<svg width=\"50mm\" viewBox=\"0 0 10 20\">"
                                           "<rect width=\"10\" height=\"20\"/></svg>",
                                           &r));
    expect_bbox(&r, 0, 0, 50, 100, 1e-9);
    qc_region_free(&ctx, &r);
}

static void units_should_convert_in_cm_pt_pc_px(void)
{
    const double in2 = 25.4 * 25.4;

    TEST_ASSERT_DOUBLE_WITHIN(1e-9, in2, one_ring_area("<svg width=\"2in\" height=\"1in\" viewBox=\"0 0 2 1\">"
                                                       "<rect width=\"1\" height=\"1\"/></svg>"));
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 100, one_ring_area("<svg width=\"10cm\" height=\"10cm\" viewBox=\"0 0 10 10\">"
                                                       "<rect width=\"1\" height=\"1\"/></svg>"));
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, in2, one_ring_area("<svg width=\"72pt\" height=\"72pt\" viewBox=\"0 0 1 1\">"
                                                       "<rect width=\"1\" height=\"1\"/></svg>"));
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, in2, one_ring_area("<svg width=\"6pc\" height=\"6pc\" viewBox=\"0 0 1 1\">"
                                                       "<rect width=\"1\" height=\"1\"/></svg>"));
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, in2, one_ring_area("<svg width=\"96px\" height=\"96\" viewBox=\"0 0 1 1\">"
                                                       "<rect width=\"1\" height=\"1\"/></svg>"));
    /* no size at all: user units are px at 96 per inch */
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, in2, one_ring_area("<svg><rect width=\"96\" height=\"96\"/></svg>"));
    /* % sizes are ignored: the viewBox in px */
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, in2, one_ring_area("<svg width=\"100%\" height=\"100%\" viewBox=\"0 0 96 96\">"
                                                       "<rect width=\"96\" height=\"96\"/></svg>"));
    /* lengths on shapes: in a user unit = 1 mm document "1in" is 96 units */
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 96 * 10, one_ring_area(DOC("<rect width=\"1in\" height=\"10\"/>")));
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 50 * 10, one_ring_area(DOC("<rect width=\"50%\" height=\"10%\"/>")));
}

/* ---- transforms ---- */

static void rotate_should_turn_about_a_point(void)
{
    qc_region r;

    TEST_ASSERT_EQUAL_INT(QC_OK, region_of(DOC("<rect x=\"10\" y=\"0\" width=\"10\" height=\"5\" "
                                               "transform=\"rotate(90 10 0)\"/>"),
                                           &r));
    TEST_ASSERT_EQUAL_size_t(4, r.nv);
    expect_point(10, 100, r.v[0], 1e-12);
    expect_point(10, 90, r.v[1], 1e-12);
    expect_point(5, 90, r.v[2], 1e-12);
    expect_point(5, 100, r.v[3], 1e-12);
    qc_region_free(&ctx, &r);
    /* any angle keeps the area */
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 50, one_ring_area(DOC("<rect width=\"10\" height=\"5\" "
                                                          "transform=\"rotate(33.3)\"/>")));
}

static void nested_groups_should_compose_transforms(void)
{
    static const char *const docs[] = {
        DOC("<g transform=\"translate(10,20)\"><g transform=\"scale(2)\">"
            "<rect x=\"1\" y=\"1\" width=\"5\" height=\"5\"/></g></g>"),
        DOC("<g transform=\"translate(10 20) scale(2)\"><rect x=\"1\" y=\"1\" width=\"5\" height=\"5\"/></g>"),
        DOC("<g transform=\"translate(10 20),scale(2 2)\"><rect x=\"1\" y=\"1\" width=\"5\" height=\"5\"/></g>"),
        DOC("<g transform=\" matrix(2,0,0,2,10,20) \"><rect x=\"1\" y=\"1\" width=\"5\" height=\"5\"/></g>"),
        DOC("<g transform=\"translate(10,20)\"><rect x=\"1\" y=\"1\" width=\"5\" height=\"5\" "
            "transform=\"scale(2)\"/></g>"),
    };
    size_t k;

    for (k = 0; k < sizeof docs / sizeof docs[0]; k++) {
        qc_region r;

        TEST_ASSERT_EQUAL_INT_MESSAGE(QC_OK, region_of(docs[k], &r), qc_errmsg(&ctx));
        expect_bbox(&r, 12, 68, 22, 78, 1e-12);
        qc_region_free(&ctx, &r);
    }
    {
        qc_region r;

        /* skewX(45): x += y, a parallelogram of the same area */
        TEST_ASSERT_EQUAL_INT(QC_OK, region_of(DOC("<rect width=\"10\" height=\"10\" transform=\"skewX(45)\"/>"), &r));
        expect_bbox(&r, 0, 90, 20, 100, 1e-12);
        TEST_ASSERT_DOUBLE_WITHIN(1e-9, 100, fabs(qc_region_area(&r)));
        qc_region_free(&ctx, &r);
        TEST_ASSERT_EQUAL_INT(QC_OK, region_of(DOC("<rect width=\"10\" height=\"10\" transform=\"skewY(45)\"/>"), &r));
        expect_bbox(&r, 0, 80, 10, 100, 1e-12);
        qc_region_free(&ctx, &r);
    }
    /* a nested <svg> is a viewport: x, y and its viewBox into width/height */
    {
        qc_region r;

        TEST_ASSERT_EQUAL_INT(QC_OK, region_of(DOC("<svg x=\"10\" y=\"10\" width=\"20\" height=\"20\" viewBox=\"0 0 10 10\">"
                                                   "<rect width=\"10\" height=\"10\"/></svg>"),
                                               &r));
        expect_bbox(&r, 10, 70, 30, 90, 1e-12);
        qc_region_free(&ctx, &r);
    }
}

/* ---- path data ---- */

static void arcs_should_make_a_circle_of_area_pi_r2(void)
{
    qc_region r;
    qc_svg_opts o;
    size_t i;
    const char *svg = DOC("<path d=\"M50 30 A20 20 0 1 0 50 70 A20 20 0 1 0 50 30Z\"/>");

    TEST_ASSERT_EQUAL_INT(QC_OK, region_of(svg, &r));
    TEST_ASSERT_EQUAL_size_t(1, r.nrings);
    TEST_ASSERT_DOUBLE_WITHIN(2 * QC_PI * 20 * (0.05 + 0.006), QC_PI * 400, fabs(ring_area(&r, 0)));
    for (i = 0; i < r.nv; i++) {
        double d = qc_hypot(r.v[i].x - 50, r.v[i].y - 50);
        TEST_ASSERT_TRUE(d > 20 - 0.056 && d < 20 + 0.006);
    }
    qc_region_free(&ctx, &r);
    /* a finer tolerance gets closer */
    memset(&o, 0, sizeof o);
    o.tolerance = 0.001;
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_io_read_svg_region(&ctx, svg, strlen(svg), &o, &r));
    TEST_ASSERT_DOUBLE_WITHIN(2 * QC_PI * 20 * 0.007, QC_PI * 400, fabs(ring_area(&r, 0)));
    qc_region_free(&ctx, &r);
    /* radii too small are scaled up: a half circle of radius 5 */
    TEST_ASSERT_EQUAL_INT(QC_OK, region_of(DOC("<path d=\"M0 50 A1 1 0 0 1 10 50 Z\"/>"), &r));
    TEST_ASSERT_DOUBLE_WITHIN(QC_PI * 5 * 0.06, QC_PI * 25 / 2, fabs(ring_area(&r, 0)));
    expect_bbox(&r, 0, 50, 10, 55, 0.01);
    qc_region_free(&ctx, &r);
}

static void arcs_should_take_flags_without_separators(void)
{
    qc_path a, b, c;

    TEST_ASSERT_EQUAL_INT(QC_OK, path_of(DOC("<path d=\"M0 0a1 1 0 00 1 1\"/>"), &a));
    TEST_ASSERT_EQUAL_INT(QC_OK, path_of(DOC("<path d=\"M 0,0 a 1,1 0 0,0 1,1\"/>"), &b));
    TEST_ASSERT_EQUAL_INT(QC_OK, path_of(DOC("<path d=\"M0 0a1,1,0,0,0,1,1\"/>"), &c));
    TEST_ASSERT_EQUAL_size_t(2, a.ncmd);
    TEST_ASSERT_EQUAL_INT(QC_PATH_CUBIC, a.cmd[1]);
    expect_point(1, 99, a.pt[3], 0);
    TEST_ASSERT_EQUAL_size_t(b.npt, a.npt);
    TEST_ASSERT_EQUAL_MEMORY(b.pt, a.pt, a.npt * sizeof *a.pt);
    TEST_ASSERT_EQUAL_MEMORY(c.pt, a.pt, a.npt * sizeof *a.pt);
    /* zero radius: a straight line; same end point: nothing */
    qc_path_free(&ctx, &a);
    TEST_ASSERT_EQUAL_INT(QC_OK, path_of(DOC("<path d=\"M0 0 A0 5 0 0 1 10 0 A5 5 0 0 1 10 0\"/>"), &a));
    TEST_ASSERT_EQUAL_size_t(2, a.ncmd);
    TEST_ASSERT_EQUAL_INT(QC_PATH_LINE, a.cmd[1]);
    qc_path_free(&ctx, &a);
    qc_path_free(&ctx, &b);
    qc_path_free(&ctx, &c);
}

static void relative_commands_and_repeats_should_agree(void)
{
    static const char *const docs[] = {
        DOC("<path d=\"M10 10 L30 10 L30 30 L10 30 Z\"/>"),
        DOC("<path d=\"m10 10 20 0 0 20 -20 0z\"/>"),
        DOC("<path d=\"M10,10 h20 v20 h-20 z\"/>"),
        DOC("<path d=\"M10 10 30 10 30 30 10 30z\"/>"),
        DOC("<path d=\"M10 10H30V30H10\"/>"), /* open: closed for the region */
        DOC("<path d=\"M 10 10 l 20,0 , 0 20 L10 30 Z\"/>"),
        DOC("<path d=\"M1e1 1E1 L3e+1 10 l0 2.e1 H.1e2z\"/>"),
    };
    size_t k;

    for (k = 0; k < sizeof docs / sizeof docs[0]; k++) {
        qc_region r;

        TEST_ASSERT_EQUAL_INT_MESSAGE(QC_OK, region_of(docs[k], &r), qc_errmsg(&ctx));
        TEST_ASSERT_EQUAL_size_t(1, r.nrings);
        TEST_ASSERT_EQUAL_size_t(4, r.nv);
        expect_point(10, 90, r.v[0], 0);
        expect_point(30, 90, r.v[1], 0);
        expect_point(30, 70, r.v[2], 0);
        expect_point(10, 70, r.v[3], 0);
        qc_region_free(&ctx, &r);
    }
}

static void numbers_should_split_where_svg_splits_them(void)
{
    qc_path p;

    TEST_ASSERT_EQUAL_INT(QC_OK, path_of(DOC("<path d=\"M1.5.5L-1-2l1e1-0.5e1 +.25-0\"/>"), &p));
    TEST_ASSERT_EQUAL_size_t(4, p.ncmd);
    expect_point(1.5, 99.5, p.pt[0], 0);
    expect_point(-1, 102, p.pt[1], 0);
    expect_point(9, 107, p.pt[2], 0);
    expect_point(9.25, 107, p.pt[3], 0);
    qc_path_free(&ctx, &p);
    /* Z then a drawing command: a new subpath from the closed one's start */
    TEST_ASSERT_EQUAL_INT(QC_OK, path_of(DOC("<path d=\"M0 0 L10 0 L10 10 Z L0 10 L0 20\"/>"), &p));
    TEST_ASSERT_EQUAL_size_t(2, qc_path_pieces(&p));
    TEST_ASSERT_EQUAL_size_t(7, p.ncmd);
    expect_point(0, 100, p.pt[3], 0);
    expect_point(0, 100, p.pt[4], 0);
    TEST_ASSERT_EQUAL_INT(QC_PATH_MOVE, p.cmd[4]);
    qc_path_free(&ctx, &p);
    /* a lone moveto draws nothing */
    TEST_ASSERT_EQUAL_INT(QC_OK, path_of(DOC("<path d=\"M5 5 M0 0 L1 1 M7 7\"/>"), &p));
    TEST_ASSERT_EQUAL_size_t(2, p.ncmd);
    expect_point(0, 100, p.pt[0], 0);
    qc_path_free(&ctx, &p);
}

/* The path reader leaves out what quiltc's own preview draws but does not
 * sew: the layer with id="region" and dashed strokes (jumps), the dash
 * inherited from a group and cancelled by stroke-dasharray:none. */
static void path_should_skip_the_region_layer_and_dashed_jumps(void)
{
    qc_path p;

    TEST_ASSERT_EQUAL_INT(QC_OK,
                          path_of(DOC("<g id=\"region\"><path d=\"M0 0 H90 V90 Z\"/></g>"
                                      "<g id=\"path\"><path d=\"M10 10 L20 20\"/>"
                                      "<path stroke-dasharray=\"2 2\" d=\"M20 20 L50 50\"/>"
                                      "<g style=\"stroke-dasharray:1\"><path d=\"M1 1 L2 2\"/>"
                                      "<path stroke-dasharray=\"none\" d=\"M50 50 L60 70\"/>"
                                      "</g></g>"),
                                  &p));
    TEST_ASSERT_EQUAL_size_t(2, qc_path_pieces(&p));
    TEST_ASSERT_EQUAL_size_t(4, p.npt);
    expect_point(10, 90, p.pt[0], 0);
    expect_point(20, 80, p.pt[1], 0);
    expect_point(50, 50, p.pt[2], 0);
    expect_point(60, 30, p.pt[3], 0);
    qc_path_free(&ctx, &p);
}

static void curves_should_stay_cubics_in_the_path(void)
{
    qc_path p;

    TEST_ASSERT_EQUAL_INT(QC_OK,
                          path_of(DOC("<path d=\"M0 0 C10 0 20 10 20 20 S30 40 40 40 Q50 40 50 50 T60 60 "
                                      "s10 0 10 10 q0 10 10 10 t10 10\"/>"),
                                  &p));
    TEST_ASSERT_EQUAL_size_t(8, p.ncmd);
    TEST_ASSERT_EQUAL_size_t(1 + 7 * 3, p.npt);
    TEST_ASSERT_EQUAL_size_t(1, qc_path_pieces(&p));
    expect_point(0, 100, p.pt[0], 0);
    expect_point(10, 100, p.pt[1], 0);
    expect_point(20, 90, p.pt[2], 0);
    expect_point(20, 80, p.pt[3], 0);
    /* S reflects the previous second control point */
    expect_point(20, 70, p.pt[4], 0);
    expect_point(30, 60, p.pt[5], 0);
    expect_point(40, 60, p.pt[6], 0);
    /* Q becomes a cubic at 2/3 towards the control point */
    expect_point(40 + 20.0 / 3, 60, p.pt[7], 1e-12);
    expect_point(50, 50 + 20.0 / 3, p.pt[8], 1e-12);
    expect_point(50, 50, p.pt[9], 0);
    /* T reflects the quadratic control point (50, 40) about (50, 50) */
    expect_point(50, 50 - 20.0 / 3, p.pt[10], 1e-12);
    expect_point(60 - 20.0 / 3, 40, p.pt[11], 1e-12);
    expect_point(60, 40, p.pt[12], 0);
    /* s after T: no cubic to reflect, the first control is the current point */
    expect_point(60, 40, p.pt[13], 0);
    expect_point(70, 40, p.pt[14], 0);
    expect_point(70, 30, p.pt[15], 0);
    /* q, t relative */
    expect_point(70, 30 - 20.0 / 3, p.pt[16], 1e-12);
    expect_point(80 - 20.0 / 3, 20, p.pt[17], 1e-12);
    expect_point(80, 20, p.pt[18], 0);
    expect_point(80 + 20.0 / 3, 20, p.pt[19], 1e-12);
    expect_point(90, 10 + 20.0 / 3, p.pt[20], 1e-12);
    expect_point(90, 10, p.pt[21], 0);
    qc_path_free(&ctx, &p);
}

/* ---- holes and fill rules ---- */

static void square_with_square_hole_should_be_two_rings(void)
{
    qc_region r;

    TEST_ASSERT_EQUAL_INT(QC_OK, region_of(DOC("<path fill-rule=\"evenodd\" d=\"M0 0H100V100H0Z M30 30H70V70H30Z\"/>"), &r));
    TEST_ASSERT_EQUAL_size_t(2, r.nrings);
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, -10000, ring_area(&r, 0));
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, -1600, ring_area(&r, 1));
    TEST_ASSERT_TRUE(qc_region_contains(&r, (qc_vec2){10, 10}));
    TEST_ASSERT_FALSE(qc_region_contains(&r, (qc_vec2){50, 50}));
    TEST_ASSERT_EQUAL_INT_MESSAGE(QC_OK, qc_region_normalize(&ctx, &r), qc_errmsg(&ctx));
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 10000 - 1600, qc_region_area(&r));
    qc_region_free(&ctx, &r);
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

static size_t rings_of(const char *svg)
{
    qc_region r;
    size_t n;

    TEST_ASSERT_EQUAL_INT_MESSAGE(QC_OK, region_of(svg, &r), qc_errmsg(&ctx));
    n = r.nrings;
    qc_region_free(&ctx, &r);
    return n;
}

static void nonzero_should_fill_same_direction_inner_rings(void)
{
    qc_region r;

    /* same direction, nonzero (the default): the inner square is filled */
    TEST_ASSERT_EQUAL_size_t(1, rings_of(DOC("<path d=\"M0 0H100V100H0Z M30 30H70V70H30Z\"/>")));
    TEST_ASSERT_EQUAL_size_t(1, rings_of(DOC("<path fill-rule=\"nonzero\" d=\"M0 0H100V100H0Z M30 30H70V70H30Z\"/>")));
    /* opposite direction: a hole under either rule */
    TEST_ASSERT_EQUAL_INT(QC_OK, region_of(DOC("<path d=\"M0 0H100V100H0Z M30 30V70H70V30Z\"/>"), &r));
    TEST_ASSERT_EQUAL_size_t(2, r.nrings);
    TEST_ASSERT_EQUAL_INT_MESSAGE(QC_OK, qc_region_normalize(&ctx, &r), qc_errmsg(&ctx));
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 10000 - 1600, qc_region_area(&r));
    qc_region_free(&ctx, &r);
    /* evenodd from the attribute, the style, or inherited from a group */
    TEST_ASSERT_EQUAL_size_t(2, rings_of(DOC("<path fill-rule=\"evenodd\" d=\"M0 0H100V100H0Z M30 30H70V70H30Z\"/>")));
    TEST_ASSERT_EQUAL_size_t(2, rings_of(DOC("<path fill-rule=\"nonzero\" style=\"fill:red; fill-rule : evenodd\" "
                                             "d=\"M0 0H100V100H0Z M30 30H70V70H30Z\"/>")));
    TEST_ASSERT_EQUAL_size_t(2, rings_of(DOC("<g fill-rule=\"evenodd\"><g><path d=\"M0 0H100V100H0Z M30 30H70V70H30Z\"/></g></g>")));
    TEST_ASSERT_EQUAL_size_t(1, rings_of(DOC("<g style=\"fill-rule:evenodd\"><path style=\"fill-rule:nonzero\" "
                                             "d=\"M0 0H100V100H0Z M30 30H70V70H30Z\"/></g>")));
    /* outer, opposite hole, island inside the hole: all three stay */
    TEST_ASSERT_EQUAL_size_t(3, rings_of(DOC("<path d=\"M0 0H100V100H0Z M20 20V80H80V20Z M40 40H60V60H40Z\"/>")));
    /* a doubled ring under nonzero fills once */
    TEST_ASSERT_EQUAL_size_t(1, rings_of(DOC("<path d=\"M0 0H100V100H0Z M0 0H100V100H0Z\"/>")));
    /* separate shapes are not merged: the region's even-odd makes a hole */
    TEST_ASSERT_EQUAL_size_t(2, rings_of(DOC("<rect width=\"100\" height=\"100\"/><rect x=\"30\" y=\"30\" width=\"40\" height=\"40\"/>")));
}

static void degenerate_rings_should_be_dropped(void)
{
    qc_region r;

    TEST_ASSERT_EQUAL_INT(QC_OK, region_of(DOC("<path d=\"M0 0 L10 0 L20 0 Z M0 0 L0 0 L5 5 M1 1 L1 1 L1 1 L1 1\"/>"
                                               "<rect width=\"3\" height=\"3\"/>"),
                                           &r));
    TEST_ASSERT_EQUAL_size_t(1, r.nrings);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 9, fabs(qc_region_area(&r)));
    qc_region_free(&ctx, &r);
}

static void unfilled_open_subpaths_should_be_strokes_only(void)
{
    qc_path p;

    expect_fail(DOC("<path fill=\"none\" d=\"M0 0 L10 0 L10 10\"/>"),
                strlen(DOC("<path fill=\"none\" d=\"M0 0 L10 0 L10 10\"/>")), QC_EEMPTY, QC_OK,
                "1 unclosed subpaths with fill:none");
    /* closed with Z or back at the start: kept; open: left out */
    TEST_ASSERT_EQUAL_size_t(3, rings_of(DOC("<g fill=\"none\"><path d=\"M0 0 L10 0 L10 10 Z M20 20 L30 20 "
                                             "L30 30 M40 40 L50 40 L50 50 L40 40\"/><rect width=\"1\" "
                                             "height=\"1\" style=\"fill:none\"/></g>")));
    /* a fill on the shape overrides the group's none; inherit keeps it */
    TEST_ASSERT_EQUAL_size_t(2, rings_of(DOC("<g style=\"fill:none\"><path fill=\"red\" d=\"M0 0 L10 0 L10 10 "
                                             "M20 20 L30 20 L30 30\"/></g>")));
    TEST_ASSERT_EQUAL_size_t(1, rings_of(DOC("<g fill=\"none\"><path fill=\"inherit\" d=\"M0 0 L10 0 L10 10 "
                                             "M20 20 L30 20 L30 30 Z\"/></g>")));
    /* the path reader keeps everything */
    TEST_ASSERT_EQUAL_INT(QC_OK, path_of(DOC("<path fill=\"none\" d=\"M0 0 L10 0 L10 10\"/>"), &p));
    TEST_ASSERT_EQUAL_size_t(3, p.ncmd);
    qc_path_free(&ctx, &p);
}

static int mem_write(void *ud, const void *data, size_t len)
{
    char **m = (char **)ud;
    size_t n = *m != NULL ? strlen(*m) : 0;
    char *q = (char *)realloc(*m, n + len + 1);

    if (q == NULL)
        return -1;
    memcpy(q + n, data, len);
    q[n + len] = '\0';
    *m = q;
    return 0;
}

static void our_preview_should_read_back_as_its_region(void)
{
    qc_region src = {0}, back;
    qc_plan plan = {0};
    qc_io_opts io;
    qc_vec2 outer[4] = {{0, 0}, {110, 0}, {110, 230}, {0, 230}};
    qc_vec2 hole[3] = {{40, 100}, {60, 100}, {50, 120}};
    qc_vec2 pts[4] = {{5, 5}, {100, 10}, {50, 200}, {20, 220}};
    char *svg = NULL;
    qc_bbox a, b;
    size_t i;

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, &src, outer, 4));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, &src, hole, 3));
    for (i = 0; i < 4; i++)
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_plan_push(&ctx, &plan, pts[i], i == 0 || i == 2 ? QC_ST_JUMP : 0));
    memset(&io, 0, sizeof io);
    io.region = &src;
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_io_write(&ctx, QC_FORMAT_SVG, &plan, &io, mem_write, &svg));
    TEST_ASSERT_EQUAL_INT_MESSAGE(QC_OK, region_of(svg, &back), qc_errmsg(&ctx));
    TEST_ASSERT_EQUAL_size_t(2, back.nrings);
    TEST_ASSERT_EQUAL_size_t(7, back.nv);
    a = qc_region_bbox(&src);
    b = qc_region_bbox(&back);
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, a.max.x - a.min.x, b.max.x - b.min.x);
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, a.max.y - a.min.y, b.max.y - b.min.y);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_normalize(&ctx, &back));
    TEST_ASSERT_DOUBLE_WITHIN(1e-6, 110 * 230 - 200, qc_region_area(&back));
    qc_region_free(&ctx, &back);
    qc_region_free(&ctx, &src);
    qc_plan_free(&ctx, &plan);
    free(svg);
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

/* ---- what is skipped ---- */

static void hidden_and_non_rendered_elements_should_be_skipped(void)
{
    qc_region r;
    qc_path p;
    const char *svg =
        DOC("<defs><rect width=\"50\" height=\"50\"/></defs>"
            "<symbol id=\"s\"><rect width=\"50\" height=\"50\"/></symbol>"
            "<clipPath id=\"c\"><rect width=\"50\" height=\"50\"/></clipPath>"
            "<mask id=\"m\"><rect width=\"50\" height=\"50\"/></mask>"
            "<marker id=\"k\"><rect width=\"50\" height=\"50\"/></marker>"
            "<pattern id=\"p\"><rect width=\"50\" height=\"50\"/></pattern>"
            "<rect style=\"display:none\" width=\"50\" height=\"50\"/>"
            "<rect display=\"none\" width=\"50\" height=\"50\"/>"
            "<g style=\"fill:red;display : none !important\"><rect width=\"50\" height=\"50\"/></g>"
            "<text x=\"1\" y=\"1\">hello <tspan>there</tspan> &amp; you</text>"
            "<image width=\"50\" height=\"50\"/>"
            "<foreign:rect xmlns:foreign=\"urn:example\" width=\"50\" height=\"50\"/>"
            "<style><![CDATA[ rect { fill: <red> } ]]></style>"
            "<a href=\"x\"><switch><rect x=\"1\" y=\"1\" width=\"2\" height=\"3\"/></switch></a>");

    TEST_ASSERT_EQUAL_INT_MESSAGE(QC_OK, region_of(svg, &r), qc_errmsg(&ctx));
    TEST_ASSERT_EQUAL_size_t(1, r.nrings);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 6, fabs(qc_region_area(&r)));
    qc_region_free(&ctx, &r);
    TEST_ASSERT_EQUAL_INT(QC_OK, path_of(svg, &p));
    TEST_ASSERT_EQUAL_size_t(1, qc_path_pieces(&p));
    qc_path_free(&ctx, &p);
}

static void xml_features_should_be_understood(void)
{
    const char *svg =
        "\xEF\xBB\xBF<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        "<!DOCTYPE svg PUBLIC \"-//W3C//DTD SVG 1.1//EN\" \"http://www.w3.org/Graphics/SVG/1.1/DTD/svg11.dtd\">\n"
        "<!-- a comment with <tags> & stuff -->\n"
        "<?some-pi data?>\n"
        "<svg:svg xmlns:svg='http://www.w3.org/2000/svg' width='100mm' height = '100mm' viewBox='0 0 100 100'>"
        "<svg:path d='M0&#x20;0 L10&#32;0 L10 10Z' id='a&amp;b&lt;&gt;&quot;&apos;&#x1F600;'/>"
        "<svg:g\n\ttransform=\"translate(50 0)\"\r\n><svg:rect width=\"1\" height=\"1\"></svg:rect></svg:g >"
        "</svg:svg>\n<!-- trailing comment -->\n";
    qc_region r;

    TEST_ASSERT_EQUAL_INT_MESSAGE(QC_OK, region_of(svg, &r), qc_errmsg(&ctx));
    TEST_ASSERT_EQUAL_size_t(2, r.nrings);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 50, fabs(ring_area(&r, 0)));
    expect_point(50, 100, r.v[3], 0);
    qc_region_free(&ctx, &r);
    /* no xmlns at all: taken as SVG */
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 1, one_ring_area("<svg viewBox=\"0 0 1 1\" width=\"1mm\" height=\"1mm\">"
                                                      "<rect width=\"1\" height=\"1\"/></svg>"));
}

static void the_motif_example_should_read_as_one_closed_piece(void)
{
    /* docs/motifs.md: a branching leaf, start and end at the bottom */
    qc_path p;
    qc_vec2 a, b;

    TEST_ASSERT_EQUAL_INT(QC_OK, path_of("<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"-10 -30 20 32\">\n"
                                         "  <path d=\"M0 0 C6 -6 11 -16 0 -29 C-11 -16 -6 -6 0 0\"/>\n</svg>",
                                         &p));
    TEST_ASSERT_EQUAL_size_t(3, p.ncmd);
    TEST_ASSERT_EQUAL_size_t(1, qc_path_pieces(&p));
    a = p.pt[0];
    b = qc_path_last(&p);
    expect_point(a.x, a.y, b, 0);
    /* 20 x 32 px: x = (0 + 10) px, y = (32 - 30) px, in mm */
    expect_point(10 * 25.4 / 96, 2 * 25.4 / 96, a, 1e-12);
    qc_path_free(&ctx, &p);
}

/* ---- errors ---- */

static void malformed_xml_should_fail_with_where(void)
{
    expect_fail_str("<svg><rect x='1'></svg>", QC_EFORMAT, "</svg> does not close <rect> of line 1");
    expect_fail_str("<svg>\n<g>\n", QC_EFORMAT, "<g> of line 2 is not closed");
    expect_fail_str("<svg><rect x='1' x='2'/></svg>", QC_EFORMAT, "duplicate attribute");
    expect_fail_str("<svg><rect x=1/></svg>", QC_EFORMAT, "quoted attribute value");
    expect_fail_str("<svg><rect x='1'y='2'/></svg>", QC_EFORMAT, "white space before");
    expect_fail_str("<svg><rect x='a<b'/></svg>", QC_EFORMAT, "'<' inside");
    expect_fail_str("<svg><rect x='&foo;'/></svg>", QC_EFORMAT, "undeclared entity &foo;");
    expect_fail_str("<svg><rect x='&#0;'/></svg>", QC_EFORMAT, "forbids");
    expect_fail_str("<svg><rect x='a & b'/></svg>", QC_EFORMAT, "'&' must start");
    expect_fail_str("<svg>&bar;</svg>", QC_EFORMAT, "undeclared entity &bar;");
    expect_fail_str("hello <svg/>", QC_EFORMAT, "text before the root");
    expect_fail_str("<svg/><svg/>", QC_EFORMAT, "after the root");
    expect_fail_str("<svg/>junk", QC_EFORMAT, "text after the root");
    expect_fail_str("<svg><!-- open", QC_EFORMAT, "unterminated comment");
    expect_fail_str("<svg><rect", QC_EFORMAT, "unterminated <rect> tag");
    expect_fail_str("<svg>< rect/></svg>", QC_EFORMAT, "not followed by a name");
    expect_fail_str("</svg>", QC_EFORMAT, "end tag without");
    expect_fail_str("<html xmlns=\"http://www.w3.org/1999/xhtml\"><svg/></html>", QC_EFORMAT,
                    "root element is <html>");
    expect_fail_str("<svg xmlns=\"http://www.w3.org/1999/xhtml\"/>", QC_EFORMAT,
                    "the root element <svg> is not in the SVG namespace");
    expect_fail_str("<!-- only a comment -->", QC_EFORMAT, "no root element");
    expect_fail_str("<svg>\n\n<rect x='1' \x01/></svg>", QC_EFORMAT, "svg line 3 (byte 19): control character 0x01");
    expect_fail("\xFF\xFE<\0s\0v\0g\0/\0>\0", 14, QC_EFORMAT, QC_EFORMAT, "UTF-16");
}

static void bad_path_data_should_name_the_character(void)
{
    expect_fail_str(DOC("<path d=\"M 10\"/>"), QC_EFORMAT,
                    "<path d> char 5 (byte 104): expected a number, found the end of the value");
    expect_fail_str(DOC("<path d=\"M 1 2 L x\"/>"), QC_EFORMAT,
                    "<path d> char 9 (byte 108): expected a number, found \"x\"");
    expect_fail_str(DOC("<path d=\"L 1 2\"/>"), QC_EFORMAT, "must start with M or m, found \"L 1 2\"");
    expect_fail_str(DOC("<path d=\"M1 2 X3 4\"/>"), QC_EFORMAT, "expected a path command letter, found \"X3 4\"");
    expect_fail_str(DOC("<path d=\"M1 2 L3 4,\"/>"), QC_EFORMAT, "expected a number after ','");
    expect_fail_str(DOC("<path d=\"M1 2 Z 3 4\"/>"), QC_EFORMAT, "command letter, found \"3 4\"");
    expect_fail_str(DOC("<path d=\"M0 0 A1 1 0 2 0 5 5\"/>"), QC_EFORMAT, "arc flag 0 or 1");
    expect_fail_str(DOC("<path d=\"M0 0 L NaN 5\"/>"), QC_EFORMAT, "found \"NaN 5\"");
    /* with an entity in the value the document offset is not exact: left out */
    expect_fail_str(DOC("<path d=\"M0&#32;0 L x\"/>"), QC_EFORMAT, "<path d> char 8: expected a number, found \"x\"");
    expect_fail_str(DOC("<path d=\"M0 0 L 1e 5\"/>"), QC_EFORMAT, "expected a number, found \"e 5\"");
    expect_fail_str(DOC("\n<polygon points=\"1 2 3\"/>"), QC_EFORMAT, "svg line 2, <polygon points>");
    expect_fail_str(DOC("\n<rect width='1' height='1'/><g>\n</g>\n<rect\nwidth='x'/>"), QC_EFORMAT,
                    "svg line 4, <rect width> char 1 (byte 142): expected a length");
    expect_fail_str(DOC("<rect width=\"10em\" height=\"1\"/>"), QC_EFORMAT, "expected a unit");
    expect_fail_str(DOC("<rect width=\"1\" height=\"1\" transform=\"rotate(1 2)\"/>"), QC_EFORMAT,
                    "wrong number of arguments");
    expect_fail_str(DOC("<g transform=\"translat(1)\"><rect width=\"1\" height=\"1\"/></g>"), QC_EFORMAT,
                    "<g transform> char 1 (byte 105): expected matrix");
    expect_fail_str(DOC("<g transform=\"scale(1 2\"/>"), QC_EFORMAT, "expected ')'");
    expect_fail_str("<svg viewBox=\"0 0 10\"/>", QC_EFORMAT, "<svg viewBox>");
    expect_fail_str("<svg viewBox=\"0 0 10 10\" preserveAspectRatio=\"xMidYMiddle\"/>", QC_EFORMAT,
                    "preserveAspectRatio");
}

static void out_of_range_numbers_should_fail(void)
{
    expect_fail_str(DOC("<path d=\"M0 0 L1e999 0 L5 5Z\"/>"), QC_ERANGE, "number \"1e999 0 L5 5Z\" is beyond");
    expect_fail_str(DOC("<path d=\"M0 0 L10000001 0 L5 5Z\"/>"), QC_ERANGE, "beyond 1e+07 user units");
    expect_fail_str(DOC("<rect width=\"1e8\" height=\"1\"/>"), QC_ERANGE, "<rect width>");
    expect_fail_str(DOC("<g transform=\"scale(1e7)\"><g transform=\"scale(1e7)\"><rect width=\"1\" height=\"1\"/></g></g>"),
                    QC_ERANGE, "after transforms is beyond");
    expect_fail_str("<svg width=\"0mm\" height=\"1mm\"/>", QC_ERANGE, "must be > 0");
    expect_fail_str("<svg viewBox=\"0 0 -1 10\"/>", QC_ERANGE, "must be > 0");
    expect_fail_str(DOC("<rect width=\"1\" height=\"1\" transform=\"skewX(90)\"/>"), QC_ERANGE, "skew angle 90");
}

static void limits_should_hold(void)
{
    char *deep;
    size_t n = 0, k;
    qc_svg_opts o;
    qc_region r;
    const char *svg = DOC("<rect width=\"1\" height=\"1\"/>");

    /* depth bomb */
    deep = (char *)malloc(300 * 8 + 64);
    TEST_ASSERT_NOT_NULL(deep);
    n += (size_t)sprintf(deep + n, "<svg>");
    for (k = 0; k < 300; k++)
        n += (size_t)sprintf(deep + n, "<g>");
    expect_fail(deep, n, QC_ELIMIT, QC_ELIMIT, "nested more than 256 deep");
    free(deep);
    /* 256 deep is fine */
    {
        char buf[256 * 8 + 64];

        n = (size_t)sprintf(buf, "<svg>");
        for (k = 1; k < 255; k++)
            n += (size_t)sprintf(buf + n, "<g>");
        n += (size_t)sprintf(buf + n, "<rect width='1' height='1'/>");
        for (k = 1; k < 255; k++)
            n += (size_t)sprintf(buf + n, "</g>");
        n += (size_t)sprintf(buf + n, "</svg>");
        TEST_ASSERT_EQUAL_INT_MESSAGE(QC_OK, qc_io_read_svg_region(&ctx, buf, n, NULL, &r), qc_errmsg(&ctx));
        qc_region_free(&ctx, &r);
    }
    /* too big */
    memset(&o, 0, sizeof o);
    o.max_bytes = 20;
    TEST_ASSERT_EQUAL_INT(QC_ELIMIT, qc_io_read_svg_region(&ctx, svg, strlen(svg), &o, &r));
    TEST_ASSERT_NOT_NULL(strstr(qc_errmsg(&ctx), "exceed the limit of 20"));
    o.max_bytes = strlen(svg);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_io_read_svg_region(&ctx, svg, strlen(svg), &o, &r));
    qc_region_free(&ctx, &r);
    /* too many vertices: four quarter circles of 1 m at 1e-9 mm */
    o.max_bytes = 0;
    o.tolerance = 1e-9;
    {
        const char *big = DOC("<circle r=\"1000\"/>");
        qc_path p;

        TEST_ASSERT_EQUAL_INT(QC_ELIMIT, qc_io_read_svg_region(&ctx, big, strlen(big), &o, &r));
        TEST_ASSERT_NOT_NULL_MESSAGE(strstr(qc_errmsg(&ctx), "more than 4000000 vertices"), qc_errmsg(&ctx));
        TEST_ASSERT_EQUAL_size_t(0, r.nv);
        /* the path keeps the curves: 4 cubics */
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_io_read_svg_path(&ctx, big, strlen(big), &o, &p));
        TEST_ASSERT_EQUAL_size_t(5, p.ncmd);
        qc_path_free(&ctx, &p);
    }
    /* too many namespace declarations in scope */
    {
        char *buf = (char *)malloc(130 * 24 + 64);

        TEST_ASSERT_NOT_NULL(buf);
        n = (size_t)sprintf(buf, "<svg");
        for (k = 0; k < 130; k++)
            n += (size_t)sprintf(buf + n, " xmlns:p%lu='urn:x'", (unsigned long)k);
        n += (size_t)sprintf(buf + n, "/>");
        expect_fail(buf, n, QC_ELIMIT, QC_ELIMIT, "more than 128 namespace declarations");
        free(buf);
    }
    /* too many attributes on one element */
    {
        char *buf = (char *)malloc(300 * 12 + 64);

        TEST_ASSERT_NOT_NULL(buf);
        n = (size_t)sprintf(buf, "<svg");
        for (k = 0; k < 300; k++)
            n += (size_t)sprintf(buf + n, " a%lu='1'", (unsigned long)k);
        n += (size_t)sprintf(buf + n, "/>");
        expect_fail(buf, n, QC_ELIMIT, QC_ELIMIT, "more than 256 attributes");
        free(buf);
    }
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

static void entity_declarations_should_be_refused(void)
{
    expect_fail_str("<?xml version=\"1.0\"?>\n<!DOCTYPE svg [\n <!ENTITY lol \"lol\">\n"
                    " <!ENTITY lol2 \"&lol;&lol;&lol;&lol;\">\n]>\n<svg>&lol2;</svg>",
                    QC_EFORMAT, "svg line 3 (byte 39): the DOCTYPE declares an entity");
    expect_fail_str("<!DOCTYPE svg [ <!ENTITY x SYSTEM \"file:///etc/passwd\"> ]><svg>&x;</svg>", QC_EFORMAT,
                    "entity declarations are refused");
    /* an internal subset without entities is skipped */
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 1, one_ring_area("<!DOCTYPE svg [ <!-- <!ENTITY no> --> <!ATTLIST svg a CDATA \"]>\"> ]>"
                                                      "<svg width=\"1mm\" height=\"1mm\" viewBox=\"0 0 1 1\">"
                                                      "<rect width=\"1\" height=\"1\"/></svg>"));
    expect_fail_str("<svg><!DOCTYPE svg></svg>", QC_EFORMAT, "DOCTYPE after the root");
}

static void empty_and_open_only_documents_should_be_eempty(void)
{
    qc_path p;

    expect_fail("", 0, QC_EEMPTY, QC_EEMPTY, "empty");
    expect_fail(NULL, 0, QC_EEMPTY, QC_EEMPTY, "empty");
    expect_fail_str(" \r\n\t", QC_EEMPTY, "the document is empty");
    expect_fail_str("<svg/>", QC_EEMPTY, "no");
    expect_fail(DOC("<polyline points=\"0,0 10,0 10,10 0,10\"/><line x2=\"5\" y2=\"5\"/>"),
                strlen(DOC("<polyline points=\"0,0 10,0 10,10 0,10\"/><line x2=\"5\" y2=\"5\"/>")),
                QC_EEMPTY, QC_OK, "no closed shape with an area (ignored: 2 polyline or line shapes, 0 unclosed");
    TEST_ASSERT_EQUAL_INT(QC_OK, path_of(DOC("<polyline points=\"0,0 10,0 10,10 0,10\"/>"), &p));
    TEST_ASSERT_EQUAL_size_t(4, p.ncmd);
    qc_path_free(&ctx, &p);
}

static void bad_arguments_should_fail(void)
{
    qc_region r;
    qc_path p;
    qc_svg_opts o;
    const char *svg = DOC("<rect width=\"1\" height=\"1\"/>");

    TEST_ASSERT_EQUAL_INT(QC_EINVAL, qc_io_read_svg_region(&ctx, NULL, 5, NULL, &r));
    TEST_ASSERT_EQUAL_INT(QC_EINVAL, qc_io_read_svg_region(&ctx, svg, strlen(svg), NULL, NULL));
    TEST_ASSERT_EQUAL_INT(QC_EINVAL, qc_io_read_svg_path(&ctx, svg, strlen(svg), NULL, NULL));
    memset(&o, 0, sizeof o);
    o.tolerance = -1;
    TEST_ASSERT_EQUAL_INT(QC_ERANGE, qc_io_read_svg_region(&ctx, svg, strlen(svg), &o, &r));
    TEST_ASSERT_NOT_NULL(strstr(qc_errmsg(&ctx), "tolerance -1"));
    o.tolerance = (double)NAN;
    TEST_ASSERT_EQUAL_INT(QC_ERANGE, qc_io_read_svg_path(&ctx, svg, strlen(svg), &o, &p));
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

/* ---- robustness ---- */

static const char complex_svg[] =
    "<?xml version=\"1.0\"?>\n"
    "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:i=\"http://www.inkscape.org/namespaces/inkscape\" "
    "width=\"120mm\" height=\"90mm\" viewBox=\"0 0 240 180\">\n"
    "<i:namedview i:zoom=\"1\"/>\n"
    "<g transform=\"translate(10 10) rotate(5)\" style=\"fill-rule:nonzero\">\n"
    " <path d=\"M0 0H200V150H0Z M20 20V60H60V20Z M100 20 H140 V60 H100 Z M120 30 a5 5 0 1 0 0.1 0z\"/>\n"
    " <rect x=\"150\" y=\"100\" width=\"30\" height=\"20\" rx=\"4\" transform=\"skewX(10)\"/>\n"
    " <circle cx=\"80\" cy=\"110\" r=\"15\"/><ellipse cx=\"40\" cy=\"110\" rx=\"10\" ry=\"5\"/>\n"
    " <polygon points=\"160,20 190,20 175,50\"/><polyline points=\"0,0 5,5 10,0\"/>\n"
    " <path d=\"M170 60 q10 -10 20 0 t20 0 c0 10 -10 20 -20 20 s-20 -10 -20 -20z\"/>\n"
    "</g>\n</svg>\n";

/* ---- Inkscape files as drawn: clones, style sheets, hidden layers, warnings ---- */

static struct {
    char line[64][320];
    size_t n;
} warned;

static void collect_warning(void *ud, const char *text)
{
    (void)ud;
    TEST_ASSERT_NULL(strchr(text, '\n'));
    if (warned.n < 64)
        snprintf(warned.line[warned.n], sizeof warned.line[0], "%s", text);
    warned.n++;
}

/* Reads svg as a region with warnings collected into warned. */
static int region_warned(const char *svg, qc_region *r)
{
    qc_svg_opts o;

    memset(&o, 0, sizeof o);
    o.warn = collect_warning;
    warned.n = 0;
    return qc_io_read_svg_region(&ctx, svg, strlen(svg), &o, r);
}

/* Whether some warning contains every one of the (up to 3) texts. */
static int warned_about(const char *a, const char *b, const char *c)
{
    size_t i;

    for (i = 0; i < warned.n && i < 64; i++)
        if (strstr(warned.line[i], a) != NULL && (b == NULL || strstr(warned.line[i], b) != NULL) &&
            (c == NULL || strstr(warned.line[i], c) != NULL))
            return 1;
    return 0;
}

static void use_should_clone_with_x_y_and_transform(void)
{
    qc_region r;
    /* the first clone comes before its source: the index finds it anyway */
    const char *svg =
        DOC("<use href=\"#r\" x=\"20\" y=\"30\"/>"
            "<defs><rect id=\"r\" width=\"10\" height=\"10\"/></defs>"
            "<use xlink:href=\"#r\" transform=\"translate(50,0) scale(2)\" x=\"1\"/>");

    TEST_ASSERT_EQUAL_INT_MESSAGE(QC_OK, region_warned(svg, &r), qc_errmsg(&ctx));
    TEST_ASSERT_EQUAL_size_t(0, warned.n);
    TEST_ASSERT_EQUAL_size_t(2, r.nrings);
    TEST_ASSERT_EQUAL_size_t(8, r.nv);
    expect_point(20, 70, r.v[0], 1e-12); /* (20, 30) user -> y_mm 100 - 30 */
    expect_point(30, 60, r.v[2], 1e-12);
    expect_point(52, 100, r.v[4], 1e-12); /* translate(50) scale(2) of x = 1 */
    expect_point(72, 80, r.v[6], 1e-12);
    qc_region_free(&ctx, &r);
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

static void nested_use_and_symbols_should_compose(void)
{
    qc_region r;
    qc_path p;
    const char *svg =
        DOC("<defs><rect id=\"r\" width=\"10\" height=\"10\"/>"
            "<g id=\"pair\" transform=\"translate(0,5)\"><use href=\"#r\"/><use href=\"#r\" x=\"20\"/></g>"
            "<symbol id=\"s\" viewBox=\"0 0 1 1\" width=\"4\" height=\"4\"><circle cx=\".5\" cy=\".5\" r=\".5\"/></symbol></defs>"
            "<use href=\"#pair\" y=\"50\"/><use href=\"#pair\" x=\"40\" y=\"50\"/>"
            "<g style=\"fill:none\"><use href=\"#pair\" x=\"80\"/></g>" /* guides: left out */
            "<use href=\"#s\" x=\"0\" y=\"80\"/>");

    TEST_ASSERT_EQUAL_INT_MESSAGE(QC_OK, region_warned(svg, &r), qc_errmsg(&ctx));
    TEST_ASSERT_EQUAL_size_t(5, r.nrings);
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 400, fabs(ring_area(&r, 0)) + fabs(ring_area(&r, 1)) +
                                            fabs(ring_area(&r, 2)) + fabs(ring_area(&r, 3)));
    TEST_ASSERT_DOUBLE_WITHIN(0.3, 3.14159265 * 4, fabs(ring_area(&r, 4))); /* r = 2 mm */
    expect_point(10, 45, r.v[1], 1e-12); /* (10, 55): pair's y 5 + use's 50 */
    TEST_ASSERT_TRUE(warned_about("fill:none", "left out", NULL));
    qc_region_free(&ctx, &r);
    /* the path reader sees the same clones */
    TEST_ASSERT_EQUAL_INT(QC_OK, path_of(svg, &p));
    TEST_ASSERT_EQUAL_size_t(7, qc_path_pieces(&p));
    qc_path_free(&ctx, &p);
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

/* Appends to buf a "billion laughs" of uses: levels of 10 clones each. */
static char *use_bomb(int levels)
{
    size_t cap = 4096 + (size_t)levels * 512, n = 0;
    char *b = (char *)malloc(cap);
    int l, k;

    if (b == NULL) {
        TEST_FAIL_MESSAGE("out of memory");
        return NULL;
    }
    /* the leaf draws nothing: only the clone budget can stop the walk */
    n += (size_t)snprintf(b + n, cap - n, "<svg xmlns=\"http://www.w3.org/2000/svg\"><defs>"
                                          "<g id=\"l0\"><rect width=\"1\" height=\"0\"/></g>");
    for (l = 1; l <= levels; l++) {
        n += (size_t)snprintf(b + n, cap - n, "<g id=\"l%d\">", l);
        for (k = 0; k < 10; k++)
            n += (size_t)snprintf(b + n, cap - n, "<use href=\"#l%d\"/>", l - 1);
        n += (size_t)snprintf(b + n, cap - n, "</g>");
    }
    n += (size_t)snprintf(b + n, cap - n, "</defs><use href=\"#l%d\"/></svg>", levels);
    TEST_ASSERT_TRUE(n < cap);
    return b;
}

static void use_budget_should_refuse_hostile_files(void)
{
    char *bomb = use_bomb(9), *deep;
    size_t n = 0, cap = 8192;
    int l;

    /* 10^9 rectangles: refused by the clone budget, not expanded */
    expect_fail_str(bomb, QC_ELIMIT, "a budget against hostile files");
    free(bomb);
    bomb = use_bomb(3); /* 1110 clones are fine (and draw nothing) */
    expect_fail(bomb, strlen(bomb), QC_EEMPTY, 0, "no closed shape");
    free(bomb);
    /* clones of clones 12 deep */
    deep = (char *)malloc(cap);
    if (deep == NULL) {
        TEST_FAIL_MESSAGE("out of memory");
        return;
    }
    n += (size_t)snprintf(deep + n, cap - n, "<svg xmlns=\"http://www.w3.org/2000/svg\"><defs>"
                                             "<rect id=\"u0\" width=\"1\" height=\"1\"/>");
    for (l = 1; l <= 12; l++)
        n += (size_t)snprintf(deep + n, cap - n, "<use id=\"u%d\" href=\"#u%d\"/>", l, l - 1);
    n += (size_t)snprintf(deep + n, cap - n, "</defs><use href=\"#u12\"/></svg>");
    TEST_ASSERT_TRUE(n < cap);
    expect_fail_str(deep, QC_ELIMIT, "nested more than 10 deep");
    free(deep);
    /* a use inside what it clones, and one cloning itself */
    expect_fail_str(DOC("<g id=\"a\"><rect width=\"1\" height=\"1\"/><use href=\"#a\"/></g>"),
                    QC_EFORMAT, "reference cycle");
    expect_fail_str(DOC("<use id=\"u\" href=\"#u\"/>"), QC_EFORMAT, "svg line 1: <use> href \"#u\"");
}

static void style_sheets_and_classes_should_cascade(void)
{
    qc_region r;
    const char *svg =
        DOC("<style type=\"text/css\"><![CDATA[\n"
            "/* Inkscape writes these */ .guide { fill : none } #gone{display:none}\n"
            "rect { fill: red } .ghost, .also { visibility: hidden }\n"
            "#keep { display: inline } .hole-in { fill-rule: evenodd }\n"
            "]]></style>"
            "<rect class=\"guide\" width=\"90\" height=\"90\"/>"         /* a guide */
            "<rect id=\"gone\" x=\"1\" width=\"2\" height=\"2\"/>"        /* display:none */
            "<rect class=\"x ghost\" x=\"5\" width=\"2\" height=\"2\"/>"  /* hidden */
            "<g class=\"also\"><rect x=\"10\" width=\"2\" height=\"2\"/>"
            "<rect visibility=\"visible\" x=\"20\" y=\"20\" width=\"3\" height=\"2\"/></g>"
            "<rect id=\"keep\" class=\"guide\" style=\"fill:blue\" x=\"30\" y=\"30\" width=\"4\" "
            "height=\"2\"/>"                                            /* style wins */
            "<path class=\"hole-in\" d=\"M50 50h20v20h-20z M55 55h5v5h-5z\"/>");

    TEST_ASSERT_EQUAL_INT_MESSAGE(QC_OK, region_warned(svg, &r), qc_errmsg(&ctx));
    TEST_ASSERT_EQUAL_size_t(4, r.nrings); /* 3x2, 4x2, the square and its hole */
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 6, fabs(ring_area(&r, 0)));
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 8, fabs(ring_area(&r, 1)));
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 25, fabs(ring_area(&r, 3))); /* evenodd from the class */
    TEST_ASSERT_TRUE(warned_about("1 closed shapes with fill:none", "the first: shape 1, line 5", NULL));
    qc_region_free(&ctx, &r);
    /* an attribute loses to a rule; unsupported selectors and at-rules are warned about */
    TEST_ASSERT_EQUAL_INT_MESSAGE(
        QC_OK,
        region_warned(DOC("<style>g rect { fill: none } @media print { rect { fill: none } } "
                          "rect[x] { display: none } .on { fill: black }</style>"
                          "<rect class=\"on\" fill=\"none\" width=\"3\" height=\"3\"/>"),
                      &r),
        qc_errmsg(&ctx));
    TEST_ASSERT_EQUAL_size_t(1, r.nrings);
    TEST_ASSERT_TRUE(warned_about("selector \"g rect\" is not read", NULL, NULL));
    TEST_ASSERT_TRUE(warned_about("\"@media print\"", "at-rule", NULL));
    TEST_ASSERT_TRUE(warned_about("selector \"rect[x]\"", NULL, NULL));
    qc_region_free(&ctx, &r);
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

static void hidden_layers_should_be_left_out(void)
{
    qc_region r;
    const char *svg =
        "<svg xmlns=\"http://www.w3.org/2000/svg\" "
        "xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\" width=\"100mm\" "
        "height=\"100mm\" viewBox=\"0 0 100 100\">"
        "<g inkscape:groupmode=\"layer\" inkscape:label=\"Sketch\" style=\"display:none\">"
        "<rect width=\"50\" height=\"50\"/><text>draft</text></g>"
        "<g inkscape:groupmode=\"layer\" inkscape:label=\"Block\" style=\"display:inline\">"
        "<g style=\"visibility:hidden\"><rect width=\"40\" height=\"40\"/>"
        "<g><rect style=\"visibility:visible\" x=\"60\" y=\"60\" width=\"10\" height=\"10\"/></g></g>"
        "</g></svg>";

    TEST_ASSERT_EQUAL_INT_MESSAGE(QC_OK, region_warned(svg, &r), qc_errmsg(&ctx));
    TEST_ASSERT_EQUAL_size_t(1, r.nrings);
    expect_bbox(&r, 60, 30, 70, 40, 1e-12);
    TEST_ASSERT_EQUAL_size_t(0, warned.n); /* the hidden text is not worth a word */
    qc_region_free(&ctx, &r);
}

static void unhonoured_constructs_should_warn_naming_the_element(void)
{
    qc_region r;
    qc_svg_opts o;
    char many[8192];
    size_t n = 0;
    int i;
    const char *svg =
        DOC("<clipPath id=\"c\"><circle r=\"5\"/></clipPath>\n"
            "<rect id=\"clipped\" clip-path=\"url(#c)\" width=\"10\" height=\"10\"/>\n"
            "<g mask=\"url(#m)\"><rect x=\"20\" width=\"10\" height=\"10\"/></g>\n"
            "<text x=\"1\" y=\"1\">label</text>\n"
            "<image id=\"photo\" width=\"5\" height=\"5\"/>\n"
            "<use href=\"#nowhere\"/>\n"
            "<use id=\"ext\" href=\"other.svg#a\"/>\n"
            "<symbol id=\"s\"><rect x=\"40\" width=\"1\" height=\"1\"/></symbol><use href=\"#s\" width=\"5\"/>");

    TEST_ASSERT_EQUAL_INT_MESSAGE(QC_OK, region_warned(svg, &r), qc_errmsg(&ctx));
    TEST_ASSERT_EQUAL_size_t(3, r.nrings); /* read unclipped, and said so */
    TEST_ASSERT_EQUAL_size_t(7, warned.n);
    TEST_ASSERT_TRUE(warned_about("svg line 2, <rect id=\"clipped\">", "clip-path url(#c) is not applied (only a clip of one convex shape", NULL));
    TEST_ASSERT_TRUE(warned_about("svg line 3, <g> (element 5)", "mask url(#m) is not applied", NULL));
    TEST_ASSERT_TRUE(warned_about("svg line 4, <text> (element 7)", "text is not read", "Object to Path"));
    TEST_ASSERT_TRUE(warned_about("svg line 5, <image id=\"photo\">", "images are not read", NULL));
    TEST_ASSERT_TRUE(warned_about("svg line 6, <use>", "\"#nowhere\" names no element", NULL));
    TEST_ASSERT_TRUE(warned_about("svg line 7, <use id=\"ext\">", "not in this file", NULL));
    TEST_ASSERT_TRUE(warned_about("svg line 8, <symbol id=\"s\"> (cloned by the <use> of line 8)",
                                  "width and height are not applied", NULL));
    qc_region_free(&ctx, &r);
    /* without a callback the same file reads the same, silently */
    TEST_ASSERT_EQUAL_INT(QC_OK, region_of(svg, &r));
    TEST_ASSERT_EQUAL_size_t(3, r.nrings);
    qc_region_free(&ctx, &r);
    /* a flood of warnings stops at 50, then says how many more */
    n += (size_t)snprintf(many + n, sizeof many - n, "%s",
                          "<svg xmlns=\"http://www.w3.org/2000/svg\"><rect width=\"1\" height=\"1\"/>");
    for (i = 0; i < 60; i++)
        n += (size_t)snprintf(many + n, sizeof many - n, "<text>%d</text>", i);
    n += (size_t)snprintf(many + n, sizeof many - n, "</svg>");
    memset(&o, 0, sizeof o);
    o.warn = collect_warning;
    warned.n = 0;
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_io_read_svg_region(&ctx, many, n, &o, &r));
    TEST_ASSERT_EQUAL_size_t(51, warned.n);
    TEST_ASSERT_EQUAL_STRING("svg: 10 more warnings not shown", warned.line[50]);
    qc_region_free(&ctx, &r);
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

static void clip_path_should_cut_where_exact(void)
{
    qc_region r;
    qc_path p;
    const char *svg =
        DOC("<style>.clipped { clip-path: url('#c') }</style>\n"
            "<defs><clipPath id=\"c\"><rect width=\"5\" height=\"5\"/></clipPath></defs>\n"
            "<rect clip-path=\"url(#c)\" width=\"10\" height=\"10\"/>\n"          /* cut to 5x5 */
            "<rect clip-path=\"url(#c)\" x=\"50\" width=\"10\" height=\"10\"/>\n" /* clipped away */
            "<circle clip-path=\"url(#c)\" cx=\"2\" cy=\"2\" r=\"1\"/>\n"         /* wholly inside */
            "<polygon class=\"clipped\" transform=\"translate(20,0)\" points=\"-5,1 3,1 3,3 -5,3\"/>\n"
            "<path clip-path=\"url(#c)\" d=\"M1 1h8v8h-2v-6h-6z\"/>\n");          /* concave: said */

    TEST_ASSERT_EQUAL_INT_MESSAGE(QC_OK, region_warned(svg, &r), qc_errmsg(&ctx));
    TEST_ASSERT_EQUAL_size_t(4, r.nrings);
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 25, fabs(ring_area(&r, 0)));
    expect_point(0, 100, r.v[0], 1e-12);
    TEST_ASSERT_DOUBLE_WITHIN(0.1, 3.14159265, fabs(ring_area(&r, 1)));
    /* the clip is in the polygon's own user space: x 20..23 of 15..23 */
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 6, fabs(ring_area(&r, 2)));
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 28, fabs(ring_area(&r, 3))); /* unclipped */
    TEST_ASSERT_EQUAL_size_t(1, warned.n);
    TEST_ASSERT_TRUE(warned_about("svg line 7, <path> (element 10)",
                                  "not applied to a curved or concave shape", NULL));
    {
        qc_region one = r;
        qc_bbox b;

        one.nrings = 1;
        one.nv = r.ring_end[0];
        b = qc_region_bbox(&one);
        expect_point(0, 95, b.min, 1e-12);
        expect_point(5, 100, b.max, 1e-12);
    }
    qc_region_free(&ctx, &r);
    /* the path reader sees the same cut */
    TEST_ASSERT_EQUAL_INT(QC_OK, path_of(svg, &p));
    TEST_ASSERT_EQUAL_size_t(4, qc_path_pieces(&p));
    qc_path_free(&ctx, &p);
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

static void group_and_nested_clips_should_intersect(void)
{
    qc_region r;
    const char *svg =
        DOC("<clipPath id=\"c2\"><rect x=\"30\" width=\"5\" height=\"50\"/></clipPath>"
            "<clipPath id=\"c3\" transform=\"translate(0,1)\"><polygon points=\"0,0 100,0 100,2 0,2\"/></clipPath>"
            "<g clip-path=\"url(#c2)\"><rect x=\"28\" width=\"10\" height=\"10\"/>"   /* 5 x 10 */
            "<rect clip-path=\"url(#c3)\" x=\"28\" y=\"20\" width=\"10\" height=\"10\"/>" /* away */
            "<rect clip-path=\"url(#c3)\" x=\"28\" width=\"10\" height=\"10\"/></g>"  /* 5 x 2 */
            "<rect x=\"28\" y=\"60\" width=\"10\" height=\"10\"/>"                    /* after the group: whole */
            "<defs><rect id=\"sq\" width=\"10\" height=\"10\"/></defs>"
            "<use href=\"#sq\" clip-path=\"url(#c2)\" x=\"31\" y=\"30\"/>");          /* 4 x 10 */

    TEST_ASSERT_EQUAL_INT_MESSAGE(QC_OK, region_warned(svg, &r), qc_errmsg(&ctx));
    TEST_ASSERT_EQUAL_size_t(0, warned.n);
    TEST_ASSERT_EQUAL_size_t(4, r.nrings);
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 50, fabs(ring_area(&r, 0)));
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 10, fabs(ring_area(&r, 1)));
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 100, fabs(ring_area(&r, 2)));
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 40, fabs(ring_area(&r, 3)));
    expect_point(30, 99, r.v[r.ring_end[0]], 1e-12); /* c3 moved down 1 */
    qc_region_free(&ctx, &r);
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

static void preview_origin_should_undo_the_margin(void)
{
    qc_region r;
    qc_path p;
    const char *svg =
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"24mm\" height=\"14mm\" "
        "viewBox=\"0 0 24 14\" data-quiltc-origin-mm=\"-3 2.5\">"
        "<rect x=\"2\" y=\"2\" width=\"20\" height=\"10\"/><path fill=\"none\" d=\"M2 12L22 2\"/></svg>";

    TEST_ASSERT_EQUAL_INT_MESSAGE(QC_OK, region_of(svg, &r), qc_errmsg(&ctx));
    expect_bbox(&r, 5, -0.5, 25, 9.5, 1e-12); /* page (2, 2)..(22, 12) less the origin */
    qc_region_free(&ctx, &r);
    TEST_ASSERT_EQUAL_INT(QC_OK, path_of(svg, &p));
    expect_point(5, -0.5, p.pt[p.npt - 2], 1e-12);
    qc_path_free(&ctx, &p);
    expect_fail_str("<svg xmlns=\"http://www.w3.org/2000/svg\" data-quiltc-origin-mm=\"1\">"
                    "<rect width=\"1\" height=\"1\"/></svg>",
                    QC_EFORMAT, "data-quiltc-origin-mm");
}

static void clones_and_sheets_should_survive_out_of_memory(void)
{
    const char *svg =
        DOC("<style>.a{fill:red} #b{display:none} rect{fill-rule:evenodd}</style>"
            "<defs><rect id=\"r\" class=\"a\" width=\"10\" height=\"10\"/>"
            "<g id=\"g\"><use href=\"#r\"/><use href=\"#r\" x=\"20\"/></g></defs>"
            "<use href=\"#g\"/><use href=\"#g\" y=\"40\"/><rect id=\"b\" width=\"5\" height=\"5\"/>"
            "<clipPath id=\"c\"><rect x=\"60\" width=\"5\" height=\"5\"/></clipPath>"
            "<rect clip-path=\"url(#c)\" x=\"59\" width=\"3\" height=\"3\"/>");
    qc_region ref, r;
    size_t k;
    int rc;

    TEST_ASSERT_EQUAL_INT_MESSAGE(QC_OK, region_of(svg, &ref), qc_errmsg(&ctx));
    TEST_ASSERT_EQUAL_size_t(5, ref.nrings);
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 6, fabs(ring_area(&ref, 4)));
    for (k = 1;; k++) {
        ta.fail_at = k;
        ta.allocs = 0;
        rc = region_of(svg, &r);
        ta.fail_at = 0;
        if (rc == QC_OK)
            break;
        TEST_ASSERT_EQUAL_INT(QC_ENOMEM, rc);
        TEST_ASSERT_NULL(r.v);
        TEST_ASSERT_EQUAL_size_t(2, ta.live_blocks); /* ref's */
    }
    TEST_ASSERT_TRUE(k > 8);
    TEST_ASSERT_EQUAL_size_t(ref.nv, r.nv);
    TEST_ASSERT_EQUAL_MEMORY(ref.v, r.v, r.nv * sizeof *r.v);
    qc_region_free(&ctx, &r);
    qc_region_free(&ctx, &ref);
}

static void out_of_memory_should_fail_cleanly(void)
{
    qc_region ref, r;
    qc_path pref, p;
    size_t k;
    int rc;

    TEST_ASSERT_EQUAL_INT_MESSAGE(QC_OK, region_of(complex_svg, &ref), qc_errmsg(&ctx));
    TEST_ASSERT_EQUAL_INT(QC_OK, path_of(complex_svg, &pref));
    /* nonzero: the path's same-direction square and the dot inside it are
     * filled over, so 2 rings of the path, then 5 other closed shapes */
    TEST_ASSERT_EQUAL_size_t(7, ref.nrings);
    TEST_ASSERT_EQUAL_size_t(10, qc_path_pieces(&pref));
    for (k = 1;; k++) {
        ta.fail_at = k;
        ta.allocs = 0;
        rc = region_of(complex_svg, &r);
        ta.fail_at = 0;
        if (rc == QC_OK)
            break;
        TEST_ASSERT_EQUAL_INT(QC_ENOMEM, rc);
        TEST_ASSERT_EQUAL_size_t(0, r.nv);
        TEST_ASSERT_NULL(r.v);
        TEST_ASSERT_EQUAL_size_t(4, ta.live_blocks); /* ref's 2 and pref's 2 */
    }
    TEST_ASSERT_TRUE(k > 5);
    TEST_ASSERT_EQUAL_size_t(ref.nv, r.nv);
    TEST_ASSERT_EQUAL_MEMORY(ref.v, r.v, r.nv * sizeof *r.v);
    qc_region_free(&ctx, &r);
    for (k = 1;; k++) {
        ta.fail_at = k;
        ta.allocs = 0;
        rc = path_of(complex_svg, &p);
        ta.fail_at = 0;
        if (rc == QC_OK)
            break;
        TEST_ASSERT_EQUAL_INT(QC_ENOMEM, rc);
        TEST_ASSERT_EQUAL_size_t(0, p.ncmd);
        TEST_ASSERT_EQUAL_size_t(4, ta.live_blocks);
    }
    TEST_ASSERT_EQUAL_size_t(pref.npt, p.npt);
    TEST_ASSERT_EQUAL_MEMORY(pref.pt, p.pt, p.npt * sizeof *p.pt);
    qc_path_free(&ctx, &p);
    qc_path_free(&ctx, &pref);
    qc_region_free(&ctx, &ref);
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

static void reading_should_be_deterministic(void)
{
    qc_region a, b;

    TEST_ASSERT_EQUAL_INT(QC_OK, region_of(complex_svg, &a));
    TEST_ASSERT_EQUAL_INT(QC_OK, region_of(complex_svg, &b));
    TEST_ASSERT_EQUAL_size_t(a.nv, b.nv);
    TEST_ASSERT_EQUAL_MEMORY(a.v, b.v, a.nv * sizeof *a.v);
    TEST_ASSERT_EQUAL_MEMORY(a.ring_end, b.ring_end, a.nrings * sizeof *a.ring_end);
    qc_region_free(&ctx, &a);
    qc_region_free(&ctx, &b);
}

static void readers_should_survive_mutated_input(void)
{
    static const char alphabet[] = "<>/=\"' &;#x0123456789.-+eEMmLlCcAaZzHhVv,()!?[]-:";
    size_t base = sizeof complex_svg - 1;
    char *buf = (char *)malloc(base + 16);
    qc_rng rng;
    int iter, ok = 0, failed = 0;

    TEST_ASSERT_NOT_NULL(buf);
    qc_rng_seed(&rng, 2024);
    for (iter = 0; iter < 3000; iter++) {
        size_t len = base, k, nmut = 1 + (size_t)qc_rng_below(&rng, 4);
        qc_region r;
        qc_path p;
        int rc;

        memcpy(buf, complex_svg, base);
        for (k = 0; k < nmut && len > 0; k++) {
            size_t at = (size_t)qc_rng_below(&rng, len);

            switch (qc_rng_below(&rng, 5)) {
            case 0: buf[at] = alphabet[qc_rng_below(&rng, sizeof alphabet - 1)]; break;
            case 1: buf[at] = (char)qc_rng_below(&rng, 256); break;
            case 2: len = at; break; /* truncate */
            case 3: memmove(buf + at, buf + at + 1, len - at - 1); len--; break;
            default: /* duplicate a byte */
                memmove(buf + at + 1, buf + at, len - at);
                len++;
                break;
            }
        }
        rc = qc_io_read_svg_region(&ctx, buf, len, NULL, &r);
        TEST_ASSERT_TRUE_MESSAGE(rc == QC_OK || rc == QC_EFORMAT || rc == QC_EEMPTY ||
                                     rc == QC_ERANGE || rc == QC_ELIMIT,
                                 qc_errmsg(&ctx));
        if (rc == QC_OK) {
            ok++;
            TEST_ASSERT_TRUE(r.nrings > 0);
        } else {
            failed++;
            TEST_ASSERT_EQUAL_size_t(0, r.nrings);
            TEST_ASSERT_TRUE(strlen(qc_errmsg(&ctx)) > 0);
        }
        qc_region_free(&ctx, &r);
        rc = qc_io_read_svg_path(&ctx, buf, len, NULL, &p);
        TEST_ASSERT_TRUE(rc == QC_OK || rc == QC_EFORMAT || rc == QC_EEMPTY || rc == QC_ERANGE ||
                         rc == QC_ELIMIT);
        if (rc != QC_OK)
            TEST_ASSERT_EQUAL_size_t(0, p.ncmd);
        qc_path_free(&ctx, &p);
        TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
    }
    TEST_ASSERT_GREATER_THAN(100, ok);
    TEST_ASSERT_GREATER_THAN(100, failed);
    free(buf);
}

/* ---- files ---- */

static char *slurp(const char *path, size_t *len)
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

static void files_should_read_with_the_expected_status(void)
{
    static const struct {
        const char *file;
        int region, path;
        const char *msg; /* in the region reader's message when it fails */
    } files[] = {
        {"tests/fixtures/svg/block_with_hole.svg", QC_OK, QC_OK, NULL},
        {"tests/fixtures/svg/heart.svg", QC_OK, QC_OK, NULL},
        {"tests/fixtures/svg/inkscape_like.svg", QC_OK, QC_OK, NULL},
        {"tests/bad/svg/bad_path_data.svg", QC_EFORMAT, QC_EFORMAT, "svg line 2, <path d> char 24 (byte 97): expected a number, found the end"},
        {"tests/bad/svg/billion_laughs.svg", QC_EFORMAT, QC_EFORMAT, "declares an entity"},
        {"tests/bad/svg/binary_garbage.svg", QC_EFORMAT, QC_EFORMAT, "control character"},
        {"tests/bad/svg/deep_nesting.svg", QC_ELIMIT, QC_ELIMIT, "nested more than 256"},
        {"tests/bad/svg/empty.svg", QC_EEMPTY, QC_EEMPTY, "empty"},
        {"tests/bad/svg/external_entity.svg", QC_EFORMAT, QC_EFORMAT, "declares an entity"},
        {"tests/bad/svg/huge_number.svg", QC_ERANGE, QC_ERANGE, "1e999"},
        {"tests/bad/svg/huge_transform.svg", QC_ERANGE, QC_ERANGE, "after transforms"},
        {"tests/bad/svg/nan_path.svg", QC_EFORMAT, QC_EFORMAT, "found \"NaN 5"},
        {"tests/bad/svg/no_closed_shape.svg", QC_EEMPTY, QC_OK, "no closed shape"},
        {"tests/bad/svg/not_svg.svg", QC_EFORMAT, QC_EFORMAT, "root element is <html>"},
        {"tests/bad/svg/unclosed.svg", QC_EFORMAT, QC_EFORMAT, "</svg> does not close <g> of line 2"},
        {"tests/bad/svg/use_bomb.svg", QC_ELIMIT, QC_ELIMIT, "svg line 6: more than 20000 <use> clones"},
        {"tests/bad/svg/use_cycle.svg", QC_EFORMAT, QC_EFORMAT, "svg line 4: <use> href \"#b\" clones an element that contains the use"},
    };
    size_t k;

    for (k = 0; k < sizeof files / sizeof files[0]; k++) {
        size_t len = 0;
        char *buf = slurp(files[k].file, &len);
        qc_region r;
        qc_path p;
        int rc;

        TEST_ASSERT_NOT_NULL_MESSAGE(buf, files[k].file);
        rc = qc_io_read_svg_region(&ctx, buf, len, NULL, &r);
        TEST_ASSERT_EQUAL_INT_MESSAGE(files[k].region, rc, files[k].file);
        if (files[k].msg != NULL)
            TEST_ASSERT_NOT_NULL_MESSAGE(strstr(qc_errmsg(&ctx), files[k].msg), qc_errmsg(&ctx));
        qc_region_free(&ctx, &r);
        rc = qc_io_read_svg_path(&ctx, buf, len, NULL, &p);
        TEST_ASSERT_EQUAL_INT_MESSAGE(files[k].path, rc, files[k].file);
        qc_path_free(&ctx, &p);
        free(buf);
    }
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

static void fixtures_should_have_their_geometry(void)
{
    size_t len = 0;
    char *buf;
    qc_region r;
    qc_path p;

    /* 120 mm block with a 40 mm window */
    buf = slurp("tests/fixtures/svg/block_with_hole.svg", &len);
    TEST_ASSERT_NOT_NULL(buf);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_io_read_svg_region(&ctx, buf, len, NULL, &r));
    TEST_ASSERT_EQUAL_size_t(2, r.nrings);
    expect_bbox(&r, 0, 0, 120, 120, 1e-12);
    TEST_ASSERT_EQUAL_INT_MESSAGE(QC_OK, qc_region_normalize(&ctx, &r), qc_errmsg(&ctx));
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 120 * 120 - 40 * 40, qc_region_area(&r));
    qc_region_free(&ctx, &r);
    free(buf);

    /* the Inkscape layer: a 100 mm square moved by (-10, -20), a separate
     * 40 mm window shape, hidden things left out; page 297 mm tall */
    buf = slurp("tests/fixtures/svg/inkscape_like.svg", &len);
    TEST_ASSERT_NOT_NULL(buf);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_io_read_svg_region(&ctx, buf, len, NULL, &r));
    TEST_ASSERT_EQUAL_size_t(2, r.nrings);
    expect_bbox(&r, 20, 177, 120, 277, 1e-9);
    TEST_ASSERT_EQUAL_INT_MESSAGE(QC_OK, qc_region_normalize(&ctx, &r), qc_errmsg(&ctx));
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 100 * 100 - 40 * 40, qc_region_area(&r));
    TEST_ASSERT_FALSE(qc_region_contains(&r, (qc_vec2){70, 227}));
    qc_region_free(&ctx, &r);
    free(buf);

    /* heart: 200 x 180 units in 400 x 360 px; arcs and cubics kept */
    buf = slurp("tests/fixtures/svg/heart.svg", &len);
    TEST_ASSERT_NOT_NULL(buf);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_io_read_svg_path(&ctx, buf, len, NULL, &p));
    TEST_ASSERT_EQUAL_size_t(1, qc_path_pieces(&p));
    TEST_ASSERT_EQUAL_INT(QC_PATH_CUBIC, p.cmd[1]);
    /* the tip (100, 170) units = (200, 340) px; page height 360 px */
    expect_point(200 * 25.4 / 96, 20 * 25.4 / 96, p.pt[0], 1e-12);
    qc_path_free(&ctx, &p);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_io_read_svg_region(&ctx, buf, len, NULL, &r));
    TEST_ASSERT_EQUAL_size_t(1, r.nrings);
    TEST_ASSERT_EQUAL_INT_MESSAGE(QC_OK, qc_region_normalize(&ctx, &r), qc_errmsg(&ctx));
    TEST_ASSERT_TRUE(qc_region_area(&r) > 0);
    qc_region_free(&ctx, &r);
    free(buf);
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(rect_should_read_exact_corners_in_mm);
    RUN_TEST(rect_in_mm_units_should_have_area_200);
    RUN_TEST(rounded_rect_should_lose_the_corners);
    RUN_TEST(circle_and_ellipse_should_have_their_area);
    RUN_TEST(polygon_should_close_and_polyline_line_should_be_open);
    RUN_TEST(viewbox_should_scale_and_align);
    RUN_TEST(units_should_convert_in_cm_pt_pc_px);
    RUN_TEST(rotate_should_turn_about_a_point);
    RUN_TEST(nested_groups_should_compose_transforms);
    RUN_TEST(arcs_should_make_a_circle_of_area_pi_r2);
    RUN_TEST(arcs_should_take_flags_without_separators);
    RUN_TEST(relative_commands_and_repeats_should_agree);
    RUN_TEST(numbers_should_split_where_svg_splits_them);
    RUN_TEST(curves_should_stay_cubics_in_the_path);
    RUN_TEST(square_with_square_hole_should_be_two_rings);
    RUN_TEST(nonzero_should_fill_same_direction_inner_rings);
    RUN_TEST(degenerate_rings_should_be_dropped);
    RUN_TEST(unfilled_open_subpaths_should_be_strokes_only);
    RUN_TEST(our_preview_should_read_back_as_its_region);
    RUN_TEST(hidden_and_non_rendered_elements_should_be_skipped);
    RUN_TEST(xml_features_should_be_understood);
    RUN_TEST(the_motif_example_should_read_as_one_closed_piece);
    RUN_TEST(malformed_xml_should_fail_with_where);
    RUN_TEST(bad_path_data_should_name_the_character);
    RUN_TEST(out_of_range_numbers_should_fail);
    RUN_TEST(limits_should_hold);
    RUN_TEST(entity_declarations_should_be_refused);
    RUN_TEST(empty_and_open_only_documents_should_be_eempty);
    RUN_TEST(bad_arguments_should_fail);
    RUN_TEST(out_of_memory_should_fail_cleanly);
    RUN_TEST(reading_should_be_deterministic);
    RUN_TEST(path_should_skip_the_region_layer_and_dashed_jumps);
    RUN_TEST(readers_should_survive_mutated_input);
    RUN_TEST(files_should_read_with_the_expected_status);
    RUN_TEST(fixtures_should_have_their_geometry);
    RUN_TEST(use_should_clone_with_x_y_and_transform);
    RUN_TEST(nested_use_and_symbols_should_compose);
    RUN_TEST(use_budget_should_refuse_hostile_files);
    RUN_TEST(style_sheets_and_classes_should_cascade);
    RUN_TEST(hidden_layers_should_be_left_out);
    RUN_TEST(unhonoured_constructs_should_warn_naming_the_element);
    RUN_TEST(clip_path_should_cut_where_exact);
    RUN_TEST(group_and_nested_clips_should_intersect);
    RUN_TEST(preview_origin_should_undo_the_margin);
    RUN_TEST(clones_and_sheets_should_survive_out_of_memory);
    return UNITY_END();
}
