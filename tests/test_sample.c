/* Sampling: lattice neighbourhoods, margins, Poisson spacing and maximality, limits. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "quiltc.h"
#include "testalloc.h"
#include "testgeom.h"
#include "unity.h"
#include "../sample/sample_internal.h"

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

static qc_sample_params params(int kind, double d, double margin)
{
    qc_sample_params sp;
    memset(&sp, 0, sizeof sp);
    sp.kind = kind;
    sp.spacing = d;
    sp.margin = margin;
    sp.seed = 1;
    return sp;
}

/* A 200 mm square with a 60 mm square hole in the middle. */
static void holed_square(qc_region *r)
{
    qc_vec2 hole[4];
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_shape(&ctx, "square:200", 1.0, r));
    hole[0] = v2(70, 70); hole[1] = v2(130, 70); hole[2] = v2(130, 130); hole[3] = v2(70, 130);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, r, hole, 4));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_normalize(&ctx, r));
}

static void assert_admissible(const qc_region *r, const qc_points *pts, double margin)
{
    size_t i;
    for (i = 0; i < pts->n; i++) {
        TEST_ASSERT_TRUE(qc_region_contains(r, pts->v[i]));
        TEST_ASSERT_GREATER_OR_EQUAL_DOUBLE(margin, qc_region_boundary_distance(r, pts->v[i]));
    }
}

/* Interior points of each tessellation have exactly k neighbours at d, none closer. */
static void test_tessellations_have_their_neighbourhoods(void)
{
    static const struct { int kind; size_t k; } cases[] = {
        {QC_SAMPLE_TRIANGLE, 6}, {QC_SAMPLE_SQUARE, 4}, {QC_SAMPLE_HEX, 3}, {QC_SAMPLE_SNUB, 5}};
    const double d = 7.0;
    size_t c;

    for (c = 0; c < 4; c++) {
        qc_region r;
        qc_points pts = {0};
        qc_sample_params sp = params(cases[c].kind, d, 1.0);
        size_t i, j, interior = 0;

        TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_shape(&ctx, "square:150", 1.0, &r));
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_sample(&ctx, &r, &sp, &pts));
        assert_admissible(&r, &pts, 1.0);
        for (i = 0; i < pts.n; i++) {
            size_t at_d = 0;
            if (qc_region_boundary_distance(&r, pts.v[i]) < 3 * d)
                continue;
            interior++;
            for (j = 0; j < pts.n; j++) {
                double dist = hypot(pts.v[i].x - pts.v[j].x, pts.v[i].y - pts.v[j].y);
                if (j == i)
                    continue;
                TEST_ASSERT_GREATER_THAN_DOUBLE(d * (1 - 1e-9), dist);
                if (dist < d * (1 + 1e-9))
                    at_d++;
            }
            TEST_ASSERT_EQUAL_size_t(cases[c].k, at_d);
        }
        TEST_ASSERT_GREATER_THAN_UINT(100, (unsigned)interior);
        /* the count matches the area estimate within the margin's loss */
        TEST_ASSERT_DOUBLE_WITHIN(0.12 * (double)pts.n, qc_sample_estimate(&r, &sp),
                                  (double)pts.n);
        qc_points_free(&ctx, &pts);
        qc_region_free(&ctx, &r);
    }
}

static void test_samples_avoid_holes_and_keep_the_margin(void)
{
    static const int kinds[] = {QC_SAMPLE_TRIANGLE, QC_SAMPLE_SQUARE, QC_SAMPLE_HEX,
                                QC_SAMPLE_SNUB, QC_SAMPLE_POISSON};
    size_t k;

    for (k = 0; k < 5; k++) {
        qc_region r;
        qc_points pts = {0};
        qc_sample_params sp = params(kinds[k], 6.0, 2.5);
        size_t i, near_hole = 0;

        holed_square(&r);
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_sample(&ctx, &r, &sp, &pts));
        assert_admissible(&r, &pts, 2.5);
        for (i = 0; i < pts.n; i++)
            if (fabs(pts.v[i].x - 100) < 40 && fabs(pts.v[i].y - 100) < 40)
                near_hole++;
        TEST_ASSERT_GREATER_THAN_UINT(10, (unsigned)near_hole); /* the ring round the hole */
        qc_points_free(&ctx, &pts);
        qc_region_free(&ctx, &r);
    }
}

/* Poisson: every pair at least d apart, and maximal: no admissible spot is 2d from all. */
static void test_poisson_is_spaced_and_maximal_in_every_part(void)
{
    qc_region r;
    qc_points pts = {0};
    qc_sample_params sp = params(QC_SAMPLE_POISSON, 5.0, 1.0);
    qc_vec2 island[4];
    size_t i, j, in_island = 0;
    double x, y;

    holed_square(&r);
    /* an island inside the hole, reachable only by a fresh seed */
    island[0] = v2(85, 85); island[1] = v2(115, 85); island[2] = v2(115, 115);
    island[3] = v2(85, 115);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, &r, island, 4));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_normalize(&ctx, &r));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_sample(&ctx, &r, &sp, &pts));
    assert_admissible(&r, &pts, 1.0);
    for (i = 0; i < pts.n; i++) {
        for (j = i + 1; j < pts.n; j++)
            TEST_ASSERT_GREATER_OR_EQUAL_DOUBLE(5.0, hypot(pts.v[i].x - pts.v[j].x,
                                                           pts.v[i].y - pts.v[j].y));
        if (pts.v[i].x > 85 && pts.v[i].x < 115 && pts.v[i].y > 85 && pts.v[i].y < 115)
            in_island++;
    }
    TEST_ASSERT_GREATER_THAN_UINT(10, (unsigned)in_island);
    for (y = 0.5; y < 200; y += 1.0)
        for (x = 0.5; x < 200; x += 1.0) {
            double best = 1e9;
            qc_vec2 q = v2(x, y);
            if (!qc_region_contains(&r, q) || qc_region_boundary_distance(&r, q) < 1.0)
                continue;
            for (i = 0; i < pts.n; i++)
                best = fmin(best, hypot(pts.v[i].x - x, pts.v[i].y - y));
            TEST_ASSERT_LESS_THAN_DOUBLE(10.0, best);
        }
    qc_points_free(&ctx, &pts);
    qc_region_free(&ctx, &r);
}

/* The Poisson cover marks a square only when it lies wholly nearer than d
 * to the point placed (so the sampler's shortcut never turns down a spot
 * the distance test would take), and marks every square well inside the
 * disk: near the origin and far from it (where rounding is coarser). */
static void test_cover_marks_squares_wholly_inside_the_disk(void)
{
    static const double base[2] = {0.0, 1e5};
    const double d = 7.0;
    int b, t;

    for (b = 0; b < 2; b++)
        for (t = 0; t < 20; t++) {
            qc_bbox box = {{base[b], base[b]}, {base[b] + 60.0, base[b] + 50.0}};
            qc__cover c;
            qc_vec2 q = v2(base[b] + 1.0 + 2.9 * t, base[b] + 0.5 + 2.45 * t);
            size_t i, j, marked = 0;

            TEST_ASSERT_EQUAL_INT(QC_OK, qc__cover_init(&ctx, &c, box, d, d / 2.8284));
            qc__cover_mark(&c, q);
            for (j = 0; j < c.ny; j++)
                for (i = 0; i < c.nx; i++) {
                    double x0 = c.x0 + (double)i * c.side, y0 = c.y0 + (double)j * c.side;
                    double fx = fmax(fabs(x0 - q.x), fabs(x0 + c.side - q.x));
                    double fy = fmax(fabs(y0 - q.y), fabs(y0 + c.side - q.y));
                    int in_box = x0 + c.side <= box.max.x && y0 + c.side <= box.max.y;
                    if (c.dead[j * c.nx + i]) {
                        TEST_ASSERT_LESS_THAN_DOUBLE(d, hypot(fx, fy));
                        TEST_ASSERT_TRUE(qc__cover_holds(&c, v2(x0 + 0.5 * c.side,
                                                                y0 + 0.5 * c.side)));
                        marked++;
                    } else if (in_box) {
                        TEST_ASSERT_GREATER_THAN_DOUBLE(d - 1e-4, hypot(fx, fy));
                    }
                }
            TEST_ASSERT_GREATER_THAN_UINT(0, (unsigned)marked);
            qc__cover_free(&ctx, &c);
        }
}

/* A seed's bucketed distance is every cell's nearest seed's, checked
 * against all seeds, buckets of 1 to 9 cells, seeds clustered and lone. */
static void test_seed_buckets_give_the_nearest_seed(void)
{
    const size_t nx = 41, ny = 29;
    size_t cell[60], n = 0, k;
    long b, i, j;

    for (k = 0; k < 40; k++) /* a cluster in a corner, a scatter, one far cell */
        cell[n++] = (k < 12) ? (k % 4) * nx + k / 4 : (k * 7919u) % (nx * ny);
    cell[n++] = nx * ny - 1;
    for (b = 1; b <= 9; b += 4) {
        qc__seed_buckets sb;
        TEST_ASSERT_EQUAL_INT(QC_OK, qc__seed_buckets_build(&ctx, nx, ny, cell, n, b, &sb));
        for (j = 0; j < (long)ny; j++)
            for (i = 0; i < (long)nx; i++) {
                double best = HUGE_VAL;
                for (k = 0; k < n; k++) {
                    double dx = (double)(long)(cell[k] % nx) - (double)i;
                    double dy = (double)(long)(cell[k] / nx) - (double)j;
                    best = fmin(best, dx * dx + dy * dy);
                }
                TEST_ASSERT_EQUAL_DOUBLE(best, qc__seed_dist2(&sb, i, j));
            }
        qc__seed_buckets_free(&ctx, &sb);
    }
}

/* The holes pass leaves no place well inside farther than the gap from
 * every point (give or take its d / 8 raster): after a sparse start (many
 * holes: one transform of the raster) and after a Poisson fill (a few:
 * each hole cell's nearest point looked up among the points round it). */
static void test_fill_holes_leaves_no_place_beyond_the_gap(void)
{
    static const char *const shapes[2] = {"holed", "heart:150"};
    const double d = 8.0, margin = 1.0, gap = 0.95 * d, h = d / 8.0;
    int s, sparse;

    for (s = 0; s < 2; s++)
        for (sparse = 0; sparse < 2; sparse++) {
            qc_region r;
            qc_points pts = {0};
            qc_sample_params sp = params(QC_SAMPLE_POISSON, sparse ? 5.0 * d : d, margin);
            qc_bbox box;
            size_t n0, i;
            double x, y;

            if (s == 0)
                holed_square(&r);
            else
                TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_shape(&ctx, shapes[s], 1.0, &r));
            TEST_ASSERT_EQUAL_INT(QC_OK, qc_sample(&ctx, &r, &sp, &pts));
            n0 = pts.n;
            TEST_ASSERT_EQUAL_INT(QC_OK, qc__sample_fill_holes(&ctx, &r, d, margin, gap, &pts));
            TEST_ASSERT_GREATER_THAN_UINT((unsigned)n0, (unsigned)pts.n); /* Bridson leaves some */
            assert_admissible(&r, &pts, margin);
            box = qc_region_bbox(&r);
            for (y = box.min.y + 0.3; y < box.max.y; y += d / 3.0)
                for (x = box.min.x + 0.2; x < box.max.x; x += d / 3.0) {
                    double best = 1e9;
                    qc_vec2 q = v2(x, y);
                    if (!qc_region_contains(&r, q) ||
                        qc_region_boundary_distance(&r, q) < margin + h)
                        continue;
                    for (i = 0; i < pts.n; i++)
                        best = fmin(best, hypot(pts.v[i].x - x, pts.v[i].y - y));
                    TEST_ASSERT_LESS_THAN_DOUBLE(gap + 1.5 * h, best);
                }
            qc_points_free(&ctx, &pts);
            qc_region_free(&ctx, &r);
        }
}

static void test_same_seed_same_points_other_seed_other_points(void)
{
    qc_region r;
    qc_points a = {0}, b = {0}, c = {0};
    qc_sample_params sp = params(QC_SAMPLE_POISSON, 8.0, 2.0);

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_shape(&ctx, "heart:150", 1.0, &r));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_sample(&ctx, &r, &sp, &a));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_sample(&ctx, &r, &sp, &b));
    sp.seed = 2;
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_sample(&ctx, &r, &sp, &c));
    TEST_ASSERT_EQUAL_size_t(a.n, b.n);
    TEST_ASSERT_EQUAL_MEMORY(a.v, b.v, a.n * sizeof *a.v);
    TEST_ASSERT_TRUE(a.n != c.n || memcmp(a.v, c.v, a.n * sizeof *a.v) != 0);
    qc_points_free(&ctx, &a);
    qc_points_free(&ctx, &b);
    qc_points_free(&ctx, &c);
    qc_region_free(&ctx, &r);
}

static void expect_error(const qc_region *r, qc_sample_params sp, int status, const char *needle)
{
    qc_points pts = {0};
    TEST_ASSERT_EQUAL_INT_MESSAGE(status, qc_sample(&ctx, r, &sp, &pts), qc_errmsg(&ctx));
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(qc_errmsg(&ctx), needle), qc_errmsg(&ctx));
    TEST_ASSERT_EQUAL_size_t(0, pts.n);
    qc_points_free(&ctx, &pts);
}

static void test_bad_requests_are_refused_before_allocating(void)
{
    qc_region r, empty = {0};
    qc_sample_params sp;

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_shape(&ctx, "square:1000", 1.0, &r));
    expect_error(&r, params(QC_SAMPLE_SQUARE, 0.0, 1.0), QC_ERANGE, "spacing 0 mm");
    expect_error(&r, params(QC_SAMPLE_SQUARE, (double)NAN, 1.0), QC_ERANGE, "spacing nan mm");
    expect_error(&r, params(QC_SAMPLE_SQUARE, 5.0, -1.0), QC_ERANGE, "margin -1 mm");
    expect_error(&r, params(99, 5.0, 1.0), QC_EINVAL, "unknown point distribution 99");
    expect_error(&empty, params(QC_SAMPLE_SQUARE, 5.0, 1.0), QC_EEMPTY, "no outline");
    ta.allocs = 0;
    expect_error(&r, params(QC_SAMPLE_POISSON, 0.01, 1.0), QC_ELIMIT, "exceed the limit of 4000000");
    TEST_ASSERT_EQUAL_size_t(0, ta.allocs);
    sp = params(QC_SAMPLE_TRIANGLE, 10.0, 1.0);
    sp.max_points = 100;
    expect_error(&r, sp, QC_ELIMIT, "about 11547 points at spacing 10 mm exceed the limit of 100");
    qc_region_free(&ctx, &r);
}

static void test_margin_wider_than_region_gives_no_points(void)
{
    qc_region r;
    qc_points pts = {0};
    qc_sample_params sp = params(QC_SAMPLE_POISSON, 5.0, 30.0);

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_shape(&ctx, "rect:100x50", 1.0, &r));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_sample(&ctx, &r, &sp, &pts));
    TEST_ASSERT_EQUAL_size_t(0, pts.n);
    qc_points_free(&ctx, &pts);
    qc_region_free(&ctx, &r);
}

static void test_out_of_memory_is_reported_and_leaks_nothing(void)
{
    static const int kinds[] = {QC_SAMPLE_HEX, QC_SAMPLE_POISSON};
    qc_region r;
    size_t k, f;
    testalloc keep;

    for (k = 0; k < 2; k++) {
        qc_sample_params sp = params(kinds[k], 10.0, 2.0);
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_shape(&ctx, "circle:120", 1.0, &r));
        keep = ta;
        for (f = 1;; f++) {
            qc_points pts = {0};
            int rc;
            ta.fail_at = ta.allocs + f;
            rc = qc_sample(&ctx, &r, &sp, &pts);
            qc_points_free(&ctx, &pts);
            TEST_ASSERT_EQUAL_size_t(keep.live_blocks, ta.live_blocks);
            if (rc == QC_OK)
                break;
            TEST_ASSERT_EQUAL_INT(QC_ENOMEM, rc);
        }
        ta.fail_at = 0;
        TEST_ASSERT_GREATER_THAN_UINT(3, (unsigned)f);
        qc_region_free(&ctx, &r);
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_tessellations_have_their_neighbourhoods);
    RUN_TEST(test_samples_avoid_holes_and_keep_the_margin);
    RUN_TEST(test_poisson_is_spaced_and_maximal_in_every_part);
    RUN_TEST(test_cover_marks_squares_wholly_inside_the_disk);
    RUN_TEST(test_seed_buckets_give_the_nearest_seed);
    RUN_TEST(test_fill_holes_leaves_no_place_beyond_the_gap);
    RUN_TEST(test_same_seed_same_points_other_seed_other_points);
    RUN_TEST(test_bad_requests_are_refused_before_allocating);
    RUN_TEST(test_margin_wider_than_region_gives_no_points);
    RUN_TEST(test_out_of_memory_is_reported_and_leaks_nothing);
    return UNITY_END();
}
