/* Regions: built-in shapes, normalize's validation and orientation, the boundary index. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "quiltc.h"
#include "testalloc.h"
#include "testgeom.h"
#include "unity.h"
#include "region_index.h"

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

static void square_ring(qc_region *r, double x0, double y0, double s, int ccw)
{
    qc_vec2 v[4];
    v[0] = v2(x0, y0);
    v[1] = ccw ? v2(x0 + s, y0) : v2(x0, y0 + s);
    v[2] = v2(x0 + s, y0 + s);
    v[3] = ccw ? v2(x0, y0 + s) : v2(x0 + s, y0);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, r, v, 4));
}

static double ring_signed_area(const qc_region *r, size_t k)
{
    size_t s = k ? r->ring_end[k - 1] : 0, e = r->ring_end[k], i, j = e - 1;
    double a = 0;
    for (i = s; i < e; j = i++)
        a += r->v[j].x * r->v[i].y - r->v[i].x * r->v[j].y;
    return a / 2;
}

static void expect_error(int rc, int status, const char *needle)
{
    TEST_ASSERT_EQUAL_INT_MESSAGE(status, rc, qc_errmsg(&ctx));
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(qc_errmsg(&ctx), needle), qc_errmsg(&ctx));
}

static void test_rect_in_inches_is_exact(void)
{
    qc_region r;
    qc_bbox b;

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_shape(&ctx, "rect:8x6", 25.4, &r));
    b = qc_region_bbox(&r);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, b.min.x);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, b.min.y);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 203.2, b.max.x);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 152.4, b.max.y);
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 203.2 * 152.4, qc_region_area(&r));
    qc_region_free(&ctx, &r);
}

/* Every built-in: bbox at the origin, counter-clockwise, the expected area. */
static void test_shapes_are_normalized_with_expected_areas(void)
{
    static const struct { const char *spec; double area; double tol; } cases[] = {
        {"square:100", 10000.0, 1e-9},
        {"circle:100", -1.0, 1e-9}, /* the inscribed polygon's area */
        {"hexagon:100", 6495.190528383290, 1e-6},     /* 3 sqrt3 / 2 r^2 */
        {"star:100", 2806.424853622408, 1e-6}, /* 10 triangles R r sin 36 / 2, r = (3 - sqrt5)/2 R */
        {"heart:100", 0.0, 0.0},
    };
    size_t i;

    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        qc_region r;
        qc_bbox b;

        TEST_ASSERT_EQUAL_INT_MESSAGE(QC_OK, qc_region_shape(&ctx, cases[i].spec, 1.0, &r),
                                      cases[i].spec);
        b = qc_region_bbox(&r);
        TEST_ASSERT_DOUBLE_WITHIN(1e-9, 0.0, b.min.x);
        TEST_ASSERT_DOUBLE_WITHIN(1e-9, 0.0, b.min.y);
        TEST_ASSERT_GREATER_THAN_DOUBLE(0.0, ring_signed_area(&r, 0));
        if (cases[i].area < 0) /* n/2 r^2 sin(2 pi / n), within 0.03% of pi r^2 */
            TEST_ASSERT_DOUBLE_WITHIN(2.5, 7853.981633974483, qc_region_area(&r));
        if (cases[i].area < 0)
            TEST_ASSERT_DOUBLE_WITHIN(1e-6, r.nv / 2.0 * 2500.0 * sin(2 * QC_PI / r.nv),
                                      qc_region_area(&r));
        else if (cases[i].tol > 0)
            TEST_ASSERT_DOUBLE_WITHIN(cases[i].tol, cases[i].area, qc_region_area(&r));
        else /* the heart is D wide */
            TEST_ASSERT_DOUBLE_WITHIN(1e-6, 100.0, b.max.x);
        qc_region_free(&ctx, &r);
    }
}

static void test_circle_polygon_stays_near_the_circle(void)
{
    qc_region r;
    size_t i;

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_shape(&ctx, "circle:200", 1.0, &r));
    for (i = 0; i < r.nv; i++) {
        qc_vec2 a = r.v[i], b = r.v[(i + 1) % r.nv];
        qc_vec2 m = v2((a.x + b.x) / 2 - 100, (a.y + b.y) / 2 - 100);
        TEST_ASSERT_DOUBLE_WITHIN(1e-9, 100.0, hypot(a.x - 100, a.y - 100));
        TEST_ASSERT_LESS_OR_EQUAL_DOUBLE(0.0101, 100.0 - hypot(m.x, m.y));
    }
    qc_region_free(&ctx, &r);
}

static void test_shape_errors_name_the_value(void)
{
    qc_region r;

    expect_error(qc_region_shape(&ctx, "blob:5", 1.0, &r), QC_EINVAL, "unknown shape 'blob:5'");
    expect_error(qc_region_shape(&ctx, "rect:8", 1.0, &r), QC_EINVAL, "expected WxH");
    expect_error(qc_region_shape(&ctx, "rect:0x5", 1.0, &r), QC_ERANGE, "size 0 mm");
    expect_error(qc_region_shape(&ctx, "circle:-3", 1.0, &r), QC_ERANGE, "size -3 mm");
    expect_error(qc_region_shape(&ctx, "circle:nan", 1.0, &r), QC_EINVAL, "at 'nan'");
    expect_error(qc_region_shape(&ctx, "circle:3x10", 1.0, &r), QC_EINVAL, "unexpected 'x10'");
    expect_error(qc_region_shape(&ctx, "circle:1e300", 1.0, &r), QC_ERANGE, "outside");
    expect_error(qc_region_shape(&ctx, "circle:abc", 1.0, &r), QC_EINVAL, "expected a number");
    expect_error(qc_region_shape(&ctx, "circle:5mm", 1.0, &r), QC_EINVAL, "unexpected 'mm'");
    expect_error(qc_region_shape(&ctx, "circle:5", 0.0, &r), QC_ERANGE, "unit");
}

static void test_normalize_orients_outer_ccw_holes_cw_islands_ccw(void)
{
    qc_region r = {0};

    square_ring(&r, 0, 0, 100, 0);  /* outer given clockwise */
    square_ring(&r, 20, 20, 60, 1); /* hole given counter-clockwise */
    square_ring(&r, 40, 40, 20, 0); /* island in the hole given clockwise */
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_normalize(&ctx, &r));
    TEST_ASSERT_GREATER_THAN_DOUBLE(0.0, ring_signed_area(&r, 0));
    TEST_ASSERT_LESS_THAN_DOUBLE(0.0, ring_signed_area(&r, 1));
    TEST_ASSERT_GREATER_THAN_DOUBLE(0.0, ring_signed_area(&r, 2));
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 10000.0 - 3600.0 + 400.0, qc_region_area(&r));
    TEST_ASSERT_TRUE(qc_region_contains(&r, v2(10, 10)));
    TEST_ASSERT_FALSE(qc_region_contains(&r, v2(30, 30)));
    TEST_ASSERT_TRUE(qc_region_contains(&r, v2(50, 50)));
    qc_region_free(&ctx, &r);
}

static void test_normalize_drops_repeated_vertices(void)
{
    qc_region r = {0};
    qc_vec2 v[7];

    v[0] = v2(0, 0); v[1] = v2(0, 0); v[2] = v2(10, 0); v[3] = v2(10, 10);
    v[4] = v2(10, 10); v[5] = v2(0, 10); v[6] = v2(0, 0);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, &r, v, 7));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_normalize(&ctx, &r));
    TEST_ASSERT_EQUAL_size_t(4, r.nv);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 100.0, qc_region_area(&r));
    qc_region_free(&ctx, &r);
}

static void test_normalize_rejects_bad_regions(void)
{
    qc_region r = {0};
    qc_vec2 bow[4], line[3], spike[5];

    expect_error(qc_region_normalize(&ctx, &r), QC_EEMPTY, "no outline");

    bow[0] = v2(0, 0); bow[1] = v2(10, 10); bow[2] = v2(10, 0); bow[3] = v2(0, 20);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, &r, bow, 4));
    expect_error(qc_region_normalize(&ctx, &r), QC_EINTERSECT, "ring 1 crosses itself");
    qc_region_free(&ctx, &r);

    square_ring(&r, 0, 0, 10, 1);
    square_ring(&r, 5, 5, 10, 1);
    expect_error(qc_region_normalize(&ctx, &r), QC_EINTERSECT, "ring 1 touches or crosses ring 2");
    qc_region_free(&ctx, &r);

    square_ring(&r, 0, 0, 10, 1);
    square_ring(&r, 10, 0, 10, 1); /* shares an edge */
    expect_error(qc_region_normalize(&ctx, &r), QC_EINTERSECT, "touches");
    qc_region_free(&ctx, &r);

    line[0] = v2(0, 0); line[1] = v2(5, 5); line[2] = v2(10, 10);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, &r, line, 3));
    expect_error(qc_region_normalize(&ctx, &r), QC_EDEGENERATE, "ring 1 has zero area");
    qc_region_free(&ctx, &r);

    /* a spike folding back along itself */
    spike[0] = v2(0, 0); spike[1] = v2(10, 0); spike[2] = v2(20, 0); spike[3] = v2(5, 0);
    spike[4] = v2(0, 10);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, &r, spike, 5));
    expect_error(qc_region_normalize(&ctx, &r), QC_EINTERSECT, "crosses itself");
    qc_region_free(&ctx, &r);

    square_ring(&r, 0, 0, 10, 1);
    r.v[2].x = (double)NAN;
    expect_error(qc_region_normalize(&ctx, &r), QC_ERANGE, "ring 1 vertex 3 is (nan");
    qc_region_free(&ctx, &r);

    square_ring(&r, 0, 0, 10, 1);
    r.v[1].x = 5e6;
    expect_error(qc_region_normalize(&ctx, &r), QC_ERANGE, "within 1e+06 mm");
    qc_region_free(&ctx, &r);
}

/* The index answers exactly as the brute-force queries, on a heart with a hole. */
static void test_index_agrees_with_brute_force(void)
{
    qc_region r;
    qc__rindex ix;
    qc_rng rng;
    qc_vec2 hole[4];
    size_t i;

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_shape(&ctx, "heart:120", 1.0, &r));
    hole[0] = v2(50, 40); hole[1] = v2(70, 40); hole[2] = v2(70, 60); hole[3] = v2(50, 60);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, &r, hole, 4));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_normalize(&ctx, &r));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc__rindex_build(&ctx, &r, &ix));
    qc_rng_seed(&rng, 7);
    for (i = 0; i < 20000; i++) {
        qc_vec2 p = rng_v2(&rng, -10, 140, -10, 140);
        double d = qc_region_boundary_distance(&r, p);
        TEST_ASSERT_EQUAL_INT(qc_region_contains(&r, p), qc__rindex_contains(&ix, p));
        TEST_ASSERT_EQUAL_INT(d < 3.0, qc__rindex_near(&ix, p, 3.0));
    }
    /* vertices and edge midpoints are on the boundary: inside */
    for (i = 0; i < r.nv; i++)
        TEST_ASSERT_TRUE(qc__rindex_contains(&ix, r.v[i]));
    TEST_ASSERT_TRUE(qc__rindex_contains(&ix, v2(60, 40)));
    qc__rindex_free(&ctx, &ix);
    qc_region_free(&ctx, &r);
}

/* Every query where the index's raster answers at once (rings of empty
 * cells round the point, and its side) or cuts the ray short gives the
 * brute-force answer: a circle with a round hole (many edges: the raster
 * is built), points at random and on the raster's cell corners and
 * centres, distances at several radii and admissions at several margins. */
static void check_point(const qc_region *r, const qc__rindex *ix, qc_vec2 p)
{
    static const double radius[] = {0.0, 0.4, 2.5, 7.0, 19.0};
    double d = qc_region_boundary_distance(r, p);
    int in = qc_region_contains(r, p);
    size_t k;

    TEST_ASSERT_EQUAL_INT(in, qc__rindex_contains(ix, p));
    for (k = 1; k < sizeof radius / sizeof *radius; k++) {
        TEST_ASSERT_EQUAL_INT(d < radius[k], qc__rindex_near(ix, p, radius[k]));
        TEST_ASSERT_EQUAL_INT(in && !(d < radius[k]), qc__rindex_admits(ix, p, radius[k]));
    }
    TEST_ASSERT_EQUAL_INT(in, qc__rindex_admits(ix, p, radius[0]));
}

static void test_index_raster_answers_as_brute_force(void)
{
    qc_region r, hole;
    qc__rindex ix;
    qc_rng rng;
    size_t i, j, far = 0;

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_shape(&ctx, "circle:160", 1.0, &r));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_shape(&ctx, "circle:50", 1.0, &hole));
    for (i = 0; i < hole.nv; i++) /* off centre (normalize makes it a hole) */
        hole.v[i] = v2(hole.v[i].x + 65.0, hole.v[i].y + 45.0);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, &r, hole.v, hole.nv));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_normalize(&ctx, &r));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc__rindex_build(&ctx, &r, &ix));
    TEST_ASSERT_NOT_NULL(ix.info);
    for (i = 0; i < ix.fnx * ix.fny; i++)
        far += (ix.info[i] & QC__RINDEX_RINGS) >= 2 && (ix.info[i] & QC__RINDEX_INSIDE);
    TEST_ASSERT_TRUE(far > ix.fnx * ix.fny / 4); /* most of the disc is answered at once */
    qc_rng_seed(&rng, 5);
    for (i = 0; i < 20000; i++)
        check_point(&r, &ix, rng_v2(&rng, -10, 170, -10, 170));
    for (j = 0; j <= 2 * ix.fny; j++) /* cell corners and centres */
        for (i = 0; i <= 2 * ix.fnx; i += 3)
            check_point(&r, &ix, v2(ix.box.min.x + 0.5 * (double)i * ix.fcell,
                                    ix.box.min.y + 0.5 * (double)j * ix.fcell));
    for (i = 0; i < r.nv; i++) /* vertices are on the boundary: inside */
        TEST_ASSERT_TRUE(qc__rindex_contains(&ix, r.v[i]));
    qc__rindex_free(&ctx, &ix);
    qc_region_free(&ctx, &hole);
    qc_region_free(&ctx, &r);
}

/* A box the index calls inside holds only inside points, none on the
 * boundary; boxes round the hole, across the outline or outside are not. */
static void test_index_box_inside_is_never_wrong(void)
{
    qc_region r;
    qc__rindex ix;
    qc_rng rng;
    qc_vec2 hole[4];
    qc_bbox b;
    size_t i, yes = 0, a, c;

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_shape(&ctx, "heart:120", 1.0, &r));
    hole[0] = v2(50, 40); hole[1] = v2(70, 40); hole[2] = v2(70, 60); hole[3] = v2(50, 60);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, &r, hole, 4));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_normalize(&ctx, &r));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc__rindex_build(&ctx, &r, &ix));
    qc_rng_seed(&rng, 11);
    for (i = 0; i < 3000; i++) {
        double w = qc_rng_unit(&rng) * 12, h = qc_rng_unit(&rng) * 12;
        b.min = rng_v2(&rng, -10, 140, -10, 140);
        b.max = v2(b.min.x + w, b.min.y + h);
        if (!qc__rindex_box_inside(&ix, b))
            continue;
        yes++;
        for (a = 0; a <= 8; a++)
            for (c = 0; c <= 8; c++) {
                qc_vec2 p = v2(b.min.x + w * (double)a / 8, b.min.y + h * (double)c / 8);
                TEST_ASSERT_TRUE(qc_region_contains(&r, p));
                TEST_ASSERT_TRUE(qc_region_boundary_distance(&r, p) > 0.0);
            }
    }
    TEST_ASSERT_TRUE(yes > 300); /* the fast path does answer inside the heart */
    b.min = v2(45, 35), b.max = v2(75, 65); /* holds the hole */
    TEST_ASSERT_FALSE(qc__rindex_box_inside(&ix, b));
    b.min = v2(52, 42), b.max = v2(68, 58); /* inside the hole */
    TEST_ASSERT_FALSE(qc__rindex_box_inside(&ix, b));
    b.min = v2(-5, -5), b.max = v2(-1, -1); /* outside */
    TEST_ASSERT_FALSE(qc__rindex_box_inside(&ix, b));
    b.min = v2(-5, 50), b.max = v2(20, 52); /* across the outline */
    TEST_ASSERT_FALSE(qc__rindex_box_inside(&ix, b));
    qc__rindex_free(&ctx, &ix);
    qc_region_free(&ctx, &r);
}

/* A comb of 20000 thin teeth would make the crossing check quadratic
 * (minutes): it is refused at once, by name. */
static void test_dense_comb_is_refused_in_bounded_time(void)
{
    enum { N = 20000 };
    qc_region r = {0};
    qc_vec2 *v = malloc((4 * N + 2) * sizeof *v);
    size_t i, n = 0;

    for (i = 0; i < N; i++) {
        double x = (double)i / N;
        v[n++] = v2(x, 0);
        v[n++] = v2(x, 10);
        v[n++] = v2(x + 0.5 / N, 10);
        v[n++] = v2(x + 0.5 / N, 0);
    }
    v[n++] = v2(1, -1);
    v[n++] = v2(0, -1);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, &r, v, n));
    expect_error(qc_region_normalize(&ctx, &r), QC_ELIMIT, "too dense to check for crossings");
    qc_region_free(&ctx, &r);
    free(v);
}

/* Rings given in either direction, islands side by side and holes in an
 * outer ring: each comes out by its nesting (islands and outers
 * counter-clockwise, holes clockwise), whatever rings were turned before
 * it. A fuzz finding: reversing a ring in place left the index's bands
 * stale, so a later island (two clockwise triangles, the second beside the
 * first) was taken for a hole. */
static void test_orientation_does_not_depend_on_earlier_reversals(void)
{
    static const qc_vec2 a[3] = {{0, 0}, {11.425571068894483, 19.042618448157469},
                                 {30.468189517051954, 19.042618448157469}};
    static const qc_vec2 b[3] = {{0, 1.9042618448157471}, {7.6170473792629885, 26.659665827420461},
                                 {15.234094758525977, 26.659665827420461}};
    qc_region r = {0};
    qc_rng rng;
    size_t i, j, k;
    int outer;

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, &r, a, 3));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, &r, b, 3));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_normalize(&ctx, &r));
    TEST_ASSERT_GREATER_THAN_DOUBLE(0.0, ring_signed_area(&r, 0));
    TEST_ASSERT_GREATER_THAN_DOUBLE(0.0, ring_signed_area(&r, 1));
    qc_region_free(&ctx, &r);
    qc_rng_seed(&rng, 5);
    for (outer = 0; outer < 2; outer++) {
        memset(&r, 0, sizeof r);
        if (outer)
            square_ring(&r, -1, -1, 102, (int)qc_rng_below(&rng, 2));
        for (j = 0; j < 10; j++) /* slanted neighbours, 10 x 10, random directions */
            for (i = 0; i < 10; i++) {
                qc_vec2 t[3];
                t[0] = v2(10.0 * i, 10.0 * j);
                t[1] = v2(10.0 * i + 9.0, 10.0 * j + 0.5 + 0.4 * (double)(i % 3));
                t[2] = v2(10.0 * i + 1.0, 10.0 * j + 9.5);
                if (qc_rng_below(&rng, 2)) {
                    qc_vec2 x = t[0];
                    t[0] = t[2];
                    t[2] = x;
                }
                TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, &r, t, 3));
            }
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_normalize(&ctx, &r));
        for (k = 0; k < r.nrings; k++) {
            int hole = outer && k > 0;
            TEST_ASSERT_TRUE_MESSAGE((ring_signed_area(&r, k) < 0) == hole, "orientation");
        }
        qc_region_free(&ctx, &r);
    }
}

/* 900 holes, each given counter-clockwise, become clockwise (depth from the index). */
static void test_many_holes_are_oriented(void)
{
    qc_region r = {0};
    size_t i, j, k;

    square_ring(&r, 0, 0, 310, 0);
    for (j = 0; j < 30; j++)
        for (i = 0; i < 30; i++)
            square_ring(&r, 5 + 10.0 * i, 5 + 10.0 * j, 5, 1);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_normalize(&ctx, &r));
    TEST_ASSERT_GREATER_THAN_DOUBLE(0.0, ring_signed_area(&r, 0));
    for (k = 1; k < r.nrings; k++)
        TEST_ASSERT_LESS_THAN_DOUBLE(0.0, ring_signed_area(&r, k));
    TEST_ASSERT_DOUBLE_WITHIN(1e-6, 310.0 * 310.0 - 900 * 25.0, qc_region_area(&r));
    qc_region_free(&ctx, &r);
}

static void test_out_of_memory_is_reported_and_leaks_nothing(void)
{
    size_t k;

    for (k = 1;; k++) {
        qc_region r;
        int rc;

        memset(&ta, 0, sizeof ta);
        ta.fail_at = k;
        rc = qc_region_shape(&ctx, "heart:80", 1.0, &r);
        TEST_ASSERT_EQUAL_size_t(0, rc == QC_OK ? 0 : ta.live_blocks);
        if (rc == QC_OK) {
            qc_region_free(&ctx, &r);
            break;
        }
        TEST_ASSERT_EQUAL_INT(QC_ENOMEM, rc);
    }
    TEST_ASSERT_GREATER_THAN_UINT(2, (unsigned)k);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_rect_in_inches_is_exact);
    RUN_TEST(test_shapes_are_normalized_with_expected_areas);
    RUN_TEST(test_circle_polygon_stays_near_the_circle);
    RUN_TEST(test_shape_errors_name_the_value);
    RUN_TEST(test_normalize_orients_outer_ccw_holes_cw_islands_ccw);
    RUN_TEST(test_normalize_drops_repeated_vertices);
    RUN_TEST(test_normalize_rejects_bad_regions);
    RUN_TEST(test_index_agrees_with_brute_force);
    RUN_TEST(test_index_raster_answers_as_brute_force);
    RUN_TEST(test_dense_comb_is_refused_in_bounded_time);
    RUN_TEST(test_many_holes_are_oriented);
    RUN_TEST(test_index_box_inside_is_never_wrong);
    RUN_TEST(test_orientation_does_not_depend_on_earlier_reversals);
    RUN_TEST(test_out_of_memory_is_reported_and_leaks_nothing);
    return UNITY_END();
}
