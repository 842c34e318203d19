/* The farthest fabric from a stitch, bare seams, corners, stitches outside. */
#include <math.h>
#include <string.h>

#include "quiltc.h"
#include "testalloc.h"
#include "testgeom.h"
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
}

static void ring(qc_region *r, const qc_vec2 *v, size_t n)
{
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, r, v, n));
}

static void square(qc_region *r, double side)
{
    qc_vec2 sq[4];

    memset(r, 0, sizeof *r);
    sq[0] = v2(0, 0); sq[1] = v2(side, 0); sq[2] = v2(side, side); sq[3] = v2(0, side);
    ring(r, sq, 4);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_normalize(&ctx, r));
}

/* A C: 60 mm square, a 40 x 20 notch cut from the right. */
static void c_shape(qc_region *r)
{
    qc_vec2 v[8];

    memset(r, 0, sizeof *r);
    v[0] = v2(0, 0); v[1] = v2(60, 0); v[2] = v2(60, 20); v[3] = v2(20, 20);
    v[4] = v2(20, 40); v[5] = v2(60, 40); v[6] = v2(60, 60); v[7] = v2(0, 60);
    ring(r, v, 8);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_normalize(&ctx, r));
}

/* One stitch in the middle: the corners are the farthest fabric, and every
 * corner is the same distance away; all the seam is bare. */
static void fabric_should_reach_the_corners(void)
{
    qc_region r;
    qc_vec2 mid = v2(50, 50);
    double corner[4];
    qc_fabric f;
    size_t i;

    square(&r, 100);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_fabric_measure(&ctx, &r, &mid, 1, NULL, 0, 1.0, 0, corner, &f));
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 50 * sqrt(2.0), f.farthest_mm);
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 50 * sqrt(2.0), f.worst_corner_mm);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 1.0, f.seam_bare);
    for (i = 0; i < 4; i++) {
        TEST_ASSERT_DOUBLE_WITHIN(1e-9, 50 * sqrt(2.0), corner[i]);
        TEST_ASSERT_DOUBLE_WITHIN(1e-9, 90.0, qc_region_corner_angle(&r, i));
    }
    TEST_ASSERT_TRUE(fabs(f.farthest_at.x - 50) > 49 && fabs(f.farthest_at.y - 50) > 49);
    qc_region_free(&ctx, &r);
}

/* A path round the seam 2 mm in: the centre is the farthest fabric (48 mm,
 * within the raster's 1.5 cells), no seam is bare, and the largest empty
 * circle agrees in the middle of a square. */
static void fabric_should_find_the_interior_gap(void)
{
    qc_region r;
    qc_vec2 loop[5];
    qc_fabric f;

    square(&r, 100);
    loop[0] = v2(2, 2); loop[1] = v2(98, 2); loop[2] = v2(98, 98); loop[3] = v2(2, 98);
    loop[4] = loop[0];
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_fabric_measure(&ctx, &r, loop, 5, NULL, 0, 0.5, 0, NULL, &f));
    TEST_ASSERT_TRUE(f.farthest_mm <= 48.0 + 1e-9);
    TEST_ASSERT_TRUE(f.farthest_mm >= 48.0 - 0.75);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 0.0, f.seam_bare);
    TEST_ASSERT_DOUBLE_WITHIN(2 * sqrt(2.0) + 1e-9, 2 * sqrt(2.0), f.worst_corner_mm);
    qc_region_free(&ctx, &r);
}

/* A bare star point: the largest empty circle wedged in a 30 deg tip is
 * small, yet the tip itself lies far from the nearest stitch. */
static void fabric_should_see_a_bare_star_point(void)
{
    qc_region r;
    qc_vec2 tri[3], line[2];
    double corner[3], h = 40.0 / tan(15.0 * 3.14159265358979323846 / 180.0);
    qc_fabric f;
    double gap;

    memset(&r, 0, sizeof r);
    tri[0] = v2(0, 0); tri[1] = v2(80, 0); tri[2] = v2(40, h);
    ring(&r, tri, 3);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_normalize(&ctx, &r));
    line[0] = v2(10, 5); line[1] = v2(70, 5); /* stitches only near the base */
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_fabric_measure(&ctx, &r, line, 2, NULL, 0, 0.5, 0, corner, &f));
    TEST_ASSERT_DOUBLE_WITHIN(1e-6, h - 5, f.farthest_mm);
    TEST_ASSERT_DOUBLE_WITHIN(1e-6, h - 5, corner[2]);
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 30.0, qc_region_corner_angle(&r, 2));
    gap = qc_largest_gap(&ctx, &r, line, 2, 0.5, NULL);
    TEST_ASSERT_TRUE(gap < 0.5 * f.farthest_mm);
    qc_region_free(&ctx, &r);
}

/* Pieces are measured apart: the jump between them is not a stitch. */
static void fabric_should_not_count_jumps(void)
{
    qc_region r;
    qc_vec2 p[2];
    uint32_t ends[2] = {1, 2};
    qc_fabric one, two;

    square(&r, 100);
    p[0] = v2(0, 50); p[1] = v2(100, 50);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_fabric_measure(&ctx, &r, p, 2, NULL, 0, 0.5, 0, NULL, &one));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_fabric_measure(&ctx, &r, p, 2, ends, 2, 0.5, 0, NULL, &two));
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 50.0, one.farthest_mm);
    TEST_ASSERT_DOUBLE_WITHIN(0.2, 50 * sqrt(2.0), two.farthest_mm); /* at (50, 0) and (50, 100), sampled */
    qc_region_free(&ctx, &r);
}

static void fabric_should_reject_bad_input_and_survive_oom(void)
{
    qc_region r, empty = {0};
    qc_vec2 p = v2(50, 50), bad = v2((double)NAN, 1);
    qc_fabric f;
    size_t k, base;
    int rc = QC_ENOMEM;

    square(&r, 100);
    TEST_ASSERT_EQUAL_INT(QC_EINVAL, qc_fabric_measure(&ctx, &r, &p, 1, NULL, 0, 0.0, 0, NULL, &f));
    TEST_ASSERT_EQUAL_INT(QC_EINVAL, qc_fabric_measure(&ctx, &r, NULL, 0, NULL, 0, 1.0, 0, NULL, &f));
    TEST_ASSERT_EQUAL_INT(QC_EINVAL, qc_fabric_measure(&ctx, &empty, &p, 1, NULL, 0, 1.0, 0, NULL, &f));
    TEST_ASSERT_EQUAL_INT(QC_ERANGE, qc_fabric_measure(&ctx, &r, &bad, 1, NULL, 0, 1.0, 0, NULL, &f));
    base = ta.live_blocks;
    for (k = 1; rc == QC_ENOMEM && k < 100; k++) {
        ta.allocs = 0;
        ta.fail_at = k;
        rc = qc_fabric_measure(&ctx, &r, &p, 1, NULL, 0, 1.0, 0, NULL, &f);
        ta.fail_at = 0;
        TEST_ASSERT_EQUAL_size_t(base, ta.live_blocks);
    }
    TEST_ASSERT_EQUAL_INT(QC_OK, rc);
    TEST_ASSERT_TRUE(k > 3);
    qc_region_free(&ctx, &r);
}

/* A stitch between two inside points that jumps the C's notch is outside
 * though both its ends are in; stitches along a seam or 0.3 mm over it are
 * not (0.02 in = 0.508 mm allowed). */
static void outside_should_flag_segments_not_only_points(void)
{
    qc_region r;
    qc_vec2 jump[2], seam[3], near[2];
    size_t n = 99;
    double worst = -1;
    qc_vec2 first;

    c_shape(&r);
    jump[0] = v2(50, 10); jump[1] = v2(50, 50);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_outside(&ctx, &r, jump, 2, NULL, 0, 0.508, 0, &n, &worst, &first));
    TEST_ASSERT_EQUAL_size_t(1, n);
    TEST_ASSERT_DOUBLE_WITHIN(0.3, 10.0, worst);
    TEST_ASSERT_TRUE(first.y > 20 && first.y < 21);
    seam[0] = v2(60, 0); seam[1] = v2(60, 20); seam[2] = v2(20, 20);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_outside(&ctx, &r, seam, 3, NULL, 0, 0.508, 0, &n, NULL, NULL));
    TEST_ASSERT_EQUAL_size_t(0, n);
    near[0] = v2(30, 20.3); near[1] = v2(50, 20.3);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_outside(&ctx, &r, near, 2, NULL, 0, 0.508, 0, &n, NULL, NULL));
    TEST_ASSERT_EQUAL_size_t(0, n);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_outside(&ctx, &r, near, 2, NULL, 0, 0.2, 0, &n, NULL, NULL));
    TEST_ASSERT_EQUAL_size_t(1, n);
    TEST_ASSERT_EQUAL_INT(QC_EINVAL, qc_path_outside(&ctx, &r, near, 2, NULL, 0, -1, 0, &n, NULL, NULL));
    qc_region_free(&ctx, &r);
}

/* qc_generate's figure is the measure of its path, for every family. */
static void generate_should_report_the_farthest_fabric(void)
{
    qc_region r;
    int fam;

    square(&r, 100);
    for (fam = 1; fam < QC_FAMILY_COUNT; fam++) {
        qc_params p;
        qc_result res;
        qc_fabric f;

        memset(&p, 0, sizeof p);
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "family", fam));
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_generate(&ctx, &r, &p, NULL, NULL, &res));
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_fabric(&ctx, &r, &res.path, res.params.spacing / 10,
                                                    0, NULL, &f));
        TEST_ASSERT_TRUE(res.stats.farthest_fabric_mm > 0);
        TEST_ASSERT_DOUBLE_WITHIN(1e-9, f.farthest_mm, res.stats.farthest_fabric_mm);
        TEST_ASSERT_DOUBLE_WITHIN(1e-9, f.seam_bare, res.stats.seam_bare);
        qc_result_free(&ctx, &res);
    }
    qc_region_free(&ctx, &r);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(fabric_should_reach_the_corners);
    RUN_TEST(fabric_should_find_the_interior_gap);
    RUN_TEST(fabric_should_see_a_bare_star_point);
    RUN_TEST(fabric_should_not_count_jumps);
    RUN_TEST(fabric_should_reject_bad_input_and_survive_oom);
    RUN_TEST(outside_should_flag_segments_not_only_points);
    RUN_TEST(generate_should_report_the_farthest_fabric);
    return UNITY_END();
}
