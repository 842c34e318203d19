/* The pass that keeps a decorated path inside its region (src/curve/keep_inside.c). */
#include <math.h>
#include <string.h>

#include "quiltc.h"
#include "testalloc.h"
#include "testgeom.h"
#include "unity.h"
#include "../src/curve/keep_inside.h"

static testalloc ta;
static qc_ctx ctx;
static qc_region c_shape;

void setUp(void)
{
    qc_vec2 v[8];

    memset(&ta, 0, sizeof ta);
    qc_ctx_init(&ctx, testalloc_fn, &ta);
    memset(&c_shape, 0, sizeof c_shape); /* 60 mm square, a 40 x 20 notch from the right */
    v[0] = v2(0, 0); v[1] = v2(60, 0); v[2] = v2(60, 20); v[3] = v2(20, 20);
    v[4] = v2(20, 40); v[5] = v2(60, 40); v[6] = v2(60, 60); v[7] = v2(0, 60);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, &c_shape, v, 8));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_normalize(&ctx, &c_shape));
}

void tearDown(void)
{
    qc_region_free(&ctx, &c_shape);
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

static size_t outside(const qc_path *p)
{
    qc_points flat = {0};
    qc_order ends = {0};
    size_t n = 99;

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_curve_flatten(&ctx, p, 0.01, &flat, &ends));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_outside(&ctx, &c_shape, flat.v, flat.n, ends.i, ends.n,
                                                 QC__INSIDE_TOL_MM + 1e-9, 0.05, &n, NULL, NULL));
    qc_points_free(&ctx, &flat);
    qc_order_free(&ctx, &ends);
    return n;
}

/* Commands that come through before the first fix (moves, lines, cubics:
 * not stored as they pass) are all in the result, unchanged and in order,
 * ahead of the fixed one; a path with nothing to fix stays as it was. */
static void keep_inside_should_keep_every_command_before_a_late_fix(void)
{
    qc_path p = {0}, orig = {0};
    size_t fixed = 9, i, npt;

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_move_to(&ctx, &p, v2(5, 5)));
    for (i = 0; i < 20; i++) {
        double x = 5 + 2.0 * (double)i;
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_line_to(&ctx, &p, v2(x + 1, 8)));
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_cubic_to(&ctx, &p, v2(x + 1.3, 9), v2(x + 1.7, 9),
                                                      v2(x + 2, 5)));
    }
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_move_to(&ctx, &p, v2(10, 50)));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_line_to(&ctx, &p, v2(5, 55)));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_append(&ctx, &orig, &p, 0));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc__path_keep_inside(&ctx, &c_shape, "test", &p, &fixed));
    TEST_ASSERT_EQUAL_size_t(0, fixed); /* nothing to fix: the same path */
    TEST_ASSERT_EQUAL_size_t(orig.ncmd, p.ncmd);
    TEST_ASSERT_EQUAL_MEMORY(orig.cmd, p.cmd, orig.ncmd);
    TEST_ASSERT_EQUAL_MEMORY(orig.pt, p.pt, orig.npt * sizeof *orig.pt);
    npt = orig.npt;
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_line_to(&ctx, &p, v2(50, 10))); /* across the notch */
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_line_to(&ctx, &p, v2(50, 5))); /* then fine again */
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_cubic_to(&ctx, &p, v2(48, 3), v2(45, 3), v2(44, 6)));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_move_to(&ctx, &p, v2(10, 30)));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc__path_keep_inside(&ctx, &c_shape, "test", &p, &fixed));
    TEST_ASSERT_EQUAL_size_t(1, fixed);
    TEST_ASSERT_EQUAL_size_t(0, outside(&p));
    TEST_ASSERT_GREATER_THAN(orig.ncmd + 4, p.ncmd); /* routed round the corners */
    TEST_ASSERT_EQUAL_MEMORY(orig.cmd, p.cmd, orig.ncmd);
    TEST_ASSERT_EQUAL_MEMORY(orig.pt, p.pt, npt * sizeof *orig.pt);
    TEST_ASSERT_EQUAL_INT(QC_PATH_LINE, p.cmd[p.ncmd - 3]); /* the tail as it was */
    TEST_ASSERT_EQUAL_INT(QC_PATH_CUBIC, p.cmd[p.ncmd - 2]);
    TEST_ASSERT_EQUAL_INT(QC_PATH_MOVE, p.cmd[p.ncmd - 1]);
    TEST_ASSERT_EQUAL_DOUBLE(50.0, p.pt[p.npt - 5].x);
    TEST_ASSERT_EQUAL_DOUBLE(5.0, p.pt[p.npt - 5].y);
    TEST_ASSERT_EQUAL_DOUBLE(44.0, p.pt[p.npt - 2].x);
    TEST_ASSERT_EQUAL_DOUBLE(30.0, p.pt[p.npt - 1].y);
    qc_path_free(&ctx, &p);
    qc_path_free(&ctx, &orig);
}

/* A line across the notch goes round its inner corners instead. */
static void keep_inside_should_route_a_chord_round_the_notch(void)
{
    qc_path p = {0};
    size_t fixed = 0;

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_move_to(&ctx, &p, v2(50, 10)));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_line_to(&ctx, &p, v2(50, 50)));
    TEST_ASSERT_EQUAL_size_t(1, outside(&p));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc__path_keep_inside(&ctx, &c_shape, "test", &p, &fixed));
    TEST_ASSERT_EQUAL_size_t(1, fixed);
    TEST_ASSERT_EQUAL_size_t(0, outside(&p));
    TEST_ASSERT_EQUAL_size_t(4, p.ncmd); /* move, the two inner corners, the end */
    TEST_ASSERT_EQUAL_DOUBLE(50.0, qc_path_last(&p).x);
    TEST_ASSERT_EQUAL_DOUBLE(50.0, qc_path_last(&p).y);
    TEST_ASSERT_TRUE(p.pt[1].x < 20 && p.pt[1].y < 20 && p.pt[2].x < 20 && p.pt[2].y > 40);
    qc_path_free(&ctx, &p);
}

/* A cubic that bulges over a seam is tightened, its end tangents kept. */
static void keep_inside_should_tighten_a_bulging_cubic(void)
{
    qc_path p = {0};
    size_t fixed = 0;
    qc_vec2 c1, c2;

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_move_to(&ctx, &p, v2(5, 55)));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_cubic_to(&ctx, &p, v2(5, 64), v2(15, 64), v2(15, 55)));
    TEST_ASSERT_TRUE(outside(&p) > 0);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc__path_keep_inside(&ctx, &c_shape, "test", &p, &fixed));
    TEST_ASSERT_EQUAL_size_t(1, fixed);
    TEST_ASSERT_EQUAL_size_t(0, outside(&p));
    TEST_ASSERT_EQUAL_size_t(2, p.ncmd);
    TEST_ASSERT_EQUAL_INT(QC_PATH_CUBIC, p.cmd[1]);
    c1 = p.pt[1], c2 = p.pt[2];
    TEST_ASSERT_EQUAL_DOUBLE(5.0, c1.x); /* same direction, shorter */
    TEST_ASSERT_TRUE(c1.y > 55 && c1.y < 64);
    TEST_ASSERT_EQUAL_DOUBLE(15.0, c2.x);
    qc_path_free(&ctx, &p);
}

/* An inside path comes back byte for byte; a point outside is an error
 * that names the family and the place in mm and inches. */
static void keep_inside_should_keep_good_paths_and_name_bad_ones(void)
{
    qc_path p = {0};
    size_t fixed = 9, k;
    int rc = QC_ENOMEM;

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_move_to(&ctx, &p, v2(5, 5)));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_cubic_to(&ctx, &p, v2(10, 15), v2(15, 5), v2(10, 50)));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc__path_keep_inside(&ctx, &c_shape, "test", &p, &fixed));
    TEST_ASSERT_EQUAL_size_t(0, fixed);
    TEST_ASSERT_EQUAL_size_t(2, p.ncmd);
    TEST_ASSERT_EQUAL_DOUBLE(15.0, p.pt[2].x);
    /* an end over the seam moves in: 0.5 mm inside, the nearest place */
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_line_to(&ctx, &p, v2(70, 50)));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc__path_keep_inside(&ctx, &c_shape, "test", &p, &fixed));
    TEST_ASSERT_EQUAL_size_t(1, fixed);
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 59.5, qc_path_last(&p).x);
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 50.0, qc_path_last(&p).y);
    TEST_ASSERT_EQUAL_size_t(0, outside(&p));
    qc_path_free(&ctx, &p);
    { /* islands: no stitch can join them, and the error says who and where */
        qc_region two = {0};
        qc_vec2 a[4], b[4];
        a[0] = v2(0, 0); a[1] = v2(10, 0); a[2] = v2(10, 10); a[3] = v2(0, 10);
        b[0] = v2(20, 0); b[1] = v2(30, 0); b[2] = v2(30, 10); b[3] = v2(20, 10);
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, &two, a, 4));
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, &two, b, 4));
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_normalize(&ctx, &two));
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_move_to(&ctx, &p, v2(5, 5)));
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_line_to(&ctx, &p, v2(25, 5)));
        TEST_ASSERT_EQUAL_INT(QC_ERANGE, qc__path_keep_inside(&ctx, &two, "wanderer", &p, &fixed));
        TEST_ASSERT_NOT_NULL(strstr(ctx.msg, "the wanderer family cannot keep its path inside"));
        TEST_ASSERT_NOT_NULL(strstr(ctx.msg, "(30.0 x 10.0 mm, 1.18 x 0.39 in)"));
        TEST_ASSERT_NOT_NULL(strstr(ctx.msg, "(15.00, 5.00) mm = (0.591, 0.197) in, 5.00 mm"));
        TEST_ASSERT_EQUAL_size_t(2, p.ncmd);
        qc_path_free(&ctx, &p);
        qc_region_free(&ctx, &two);
    }
    /* out of memory at every allocation of a routing run: no leak, path intact */
    for (k = 1; rc == QC_ENOMEM && k < 200; k++) {
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_move_to(&ctx, &p, v2(50, 10)));
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_line_to(&ctx, &p, v2(50, 50)));
        ta.allocs = 0;
        ta.fail_at = k;
        rc = qc__path_keep_inside(&ctx, &c_shape, "test", &p, NULL);
        ta.fail_at = 0;
        TEST_ASSERT_EQUAL_size_t(rc == QC_OK ? 4 : 2, p.ncmd);
        qc_path_free(&ctx, &p);
    }
    TEST_ASSERT_EQUAL_INT(QC_OK, rc);
    TEST_ASSERT_TRUE(k > 3);
}

/* A stretch found clear of the boundary vouches only for what lies in it:
 * a cubic whose ends lie there but whose bulge crosses the seam is still
 * caught, and a line from there across the notch still routed round it. */
static void keep_inside_should_check_what_leaves_a_clear_stretch(void)
{
    qc_path p = {0};
    size_t fixed = 0;

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_move_to(&ctx, &p, v2(10, 45)));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_line_to(&ctx, &p, v2(10, 46))); /* clear round here */
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_cubic_to(&ctx, &p, v2(10, 70), v2(12, 70), v2(12, 47)));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_line_to(&ctx, &p, v2(11, 47)));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_line_to(&ctx, &p, v2(50, 50))); /* across no notch */
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_line_to(&ctx, &p, v2(50, 10))); /* across the notch */
    TEST_ASSERT_TRUE(outside(&p) > 0);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc__path_keep_inside(&ctx, &c_shape, "test", &p, &fixed));
    TEST_ASSERT_EQUAL_size_t(2, fixed);
    TEST_ASSERT_EQUAL_size_t(0, outside(&p));
    TEST_ASSERT_EQUAL_INT(QC_PATH_MOVE, p.cmd[0]); /* what came before the first fix, kept */
    TEST_ASSERT_EQUAL_INT(QC_PATH_LINE, p.cmd[1]);
    TEST_ASSERT_EQUAL_DOUBLE(45.0, p.pt[0].y);
    TEST_ASSERT_EQUAL_DOUBLE(46.0, p.pt[1].y);
    TEST_ASSERT_EQUAL_INT(QC_PATH_CUBIC, p.cmd[2]);
    TEST_ASSERT_TRUE(p.pt[2].y < 70.0 && p.pt[3].y < 70.0); /* tightened */
    TEST_ASSERT_EQUAL_DOUBLE(47.0, p.pt[4].y);
    TEST_ASSERT_EQUAL_INT(QC_PATH_LINE, p.cmd[3]); /* and between the fixes */
    TEST_ASSERT_EQUAL_DOUBLE(11.0, p.pt[5].x);
    TEST_ASSERT_EQUAL_DOUBLE(50.0, qc_path_last(&p).x);
    TEST_ASSERT_EQUAL_DOUBLE(10.0, qc_path_last(&p).y);
    qc_path_free(&ctx, &p);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(keep_inside_should_route_a_chord_round_the_notch);
    RUN_TEST(keep_inside_should_tighten_a_bulging_cubic);
    RUN_TEST(keep_inside_should_keep_good_paths_and_name_bad_ones);
    RUN_TEST(keep_inside_should_check_what_leaves_a_clear_stretch);
    RUN_TEST(keep_inside_should_keep_every_command_before_a_late_fix);
    return UNITY_END();
}
