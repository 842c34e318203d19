/* Measures: the largest empty circle a path leaves, and proper self-crossings. */
#include <math.h>
#include <stdlib.h>
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
}

static void square(qc_region *r, double side, int hole)
{
    qc_vec2 sq[4], h[4];

    memset(r, 0, sizeof *r);
    sq[0] = v2(0, 0); sq[1] = v2(side, 0); sq[2] = v2(side, side); sq[3] = v2(0, side);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, r, sq, 4));
    if (hole) { /* the middle fifth, clockwise */
        h[0] = v2(0.4 * side, 0.4 * side); h[1] = v2(0.4 * side, 0.6 * side);
        h[2] = v2(0.6 * side, 0.6 * side); h[3] = v2(0.6 * side, 0.4 * side);
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, r, h, 4));
    }
}

static void largest_gap_should_find_the_inscribed_circle(void)
{
    qc_region r;
    qc_vec2 c;
    double g;

    square(&r, 100, 0);
    g = qc_largest_gap(&ctx, &r, NULL, 0, 1.0, &c);
    TEST_ASSERT_LESS_OR_EQUAL_DOUBLE(50.0, g);
    TEST_ASSERT_GREATER_OR_EQUAL_DOUBLE(50.0 - 2.2, g);
    TEST_ASSERT_DOUBLE_WITHIN(2.0, 50.0, c.x);
    TEST_ASSERT_DOUBLE_WITHIN(2.0, 50.0, c.y);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, g, qc_region_boundary_distance(&r, c));
    qc_region_free(&ctx, &r);
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

static void largest_gap_should_shrink_with_the_path(void)
{
    qc_region r;
    qc_vec2 cross[5], c;
    double g;

    square(&r, 100, 0);
    /* a plus through the middle leaves four 50 mm squares: radius 25 */
    cross[0] = v2(0, 50); cross[1] = v2(100, 50); cross[2] = v2(50, 50);
    cross[3] = v2(50, 0); cross[4] = v2(50, 100);
    g = qc_largest_gap(&ctx, &r, cross, 5, 0.5, &c);
    TEST_ASSERT_LESS_OR_EQUAL_DOUBLE(25.0, g);
    TEST_ASSERT_GREATER_OR_EQUAL_DOUBLE(25.0 - 1.1, g);
    /* a single point in the middle: the corners win, radius 100 / (2 + sqrt 2) */
    g = qc_largest_gap(&ctx, &r, cross + 2, 1, 0.5, NULL);
    TEST_ASSERT_DOUBLE_WITHIN(1.1, 100.0 / (2.0 + sqrt(2.0)), g);
    qc_region_free(&ctx, &r);
}

static void largest_gap_should_respect_holes(void)
{
    qc_region r;
    qc_vec2 c;
    double g;

    /* a 100 mm square with the middle 20 mm square cut out: the circle
     * touching two sides and the hole's corner is the largest */
    square(&r, 100, 1);
    g = qc_largest_gap(&ctx, &r, NULL, 0, 0.5, &c);
    TEST_ASSERT_TRUE(qc_region_contains(&r, c));
    TEST_ASSERT_LESS_THAN_DOUBLE(40.0, g);
    TEST_ASSERT_GREATER_THAN_DOUBLE(20.0, g);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, g, qc_region_boundary_distance(&r, c));
    qc_region_free(&ctx, &r);
}

static void largest_gap_should_measure_path_pieces_apart(void)
{
    qc_region r;
    qc_path p = {0};
    double g;

    square(&r, 100, 0);
    /* two short strokes in opposite corners: the jump between them is not sewn */
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_move_to(&ctx, &p, v2(1, 1)));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_line_to(&ctx, &p, v2(2, 2)));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_move_to(&ctx, &p, v2(98, 98)));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_line_to(&ctx, &p, v2(99, 99)));
    g = qc_path_largest_gap(&ctx, &r, &p, 1.0, NULL);
    TEST_ASSERT_GREATER_THAN_DOUBLE(47.0, g);
    qc_path_free(&ctx, &p);
    qc_region_free(&ctx, &r);
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

static void largest_gap_should_reject_bad_input(void)
{
    qc_region r, empty;
    qc_vec2 bad = v2((double)NAN, 0);

    memset(&empty, 0, sizeof empty);
    square(&r, 10, 0);
    TEST_ASSERT_EQUAL_DOUBLE((double)QC_EINVAL, qc_largest_gap(&ctx, &r, NULL, 0, 0.0, NULL));
    TEST_ASSERT_EQUAL_DOUBLE((double)QC_EINVAL, qc_largest_gap(&ctx, &empty, NULL, 0, 1.0, NULL));
    TEST_ASSERT_EQUAL_DOUBLE((double)QC_EINVAL, qc_largest_gap(&ctx, &r, NULL, 3, 1.0, NULL));
    TEST_ASSERT_EQUAL_DOUBLE((double)QC_ERANGE, qc_largest_gap(&ctx, &r, &bad, 1, 1.0, NULL));
    qc_region_free(&ctx, &r);
}

static void largest_gap_should_survive_allocation_failures(void)
{
    qc_region r;
    qc_vec2 seg[2];
    size_t k, base;
    double g = QC_ENOMEM;

    square(&r, 50, 1);
    base = ta.live_blocks;
    seg[0] = v2(0, 25);
    seg[1] = v2(50, 25);
    for (k = 1; g == QC_ENOMEM && k < 100; k++) {
        ta.allocs = 0;
        ta.fail_at = k;
        g = qc_largest_gap(&ctx, &r, seg, 2, 0.5, NULL);
        ta.fail_at = 0;
        TEST_ASSERT_EQUAL_UINT(base, ta.live_blocks);
    }
    TEST_ASSERT_GREATER_THAN_DOUBLE(0.0, g);
    TEST_ASSERT_GREATER_THAN(2, k);
    qc_region_free(&ctx, &r);
}

static size_t brute_crossings(const qc_vec2 *p, size_t n, int closed)
{
    size_t ns = closed ? n : n - 1, i, j, c = 0;

    for (i = 0; i < ns; i++)
        for (j = i + 2; j < ns; j++) {
            qc_vec2 a = p[i], b = p[(i + 1) % n], d = p[j], e = p[(j + 1) % n];
            double o1, o2, o3, o4;
            if (closed && i == 0 && j == ns - 1)
                continue;
            o1 = qc_orient2d(a, b, d);
            o2 = qc_orient2d(a, b, e);
            o3 = qc_orient2d(d, e, a);
            o4 = qc_orient2d(d, e, b);
            c += o1 * o2 < 0 && o3 * o4 < 0;
        }
    return c;
}

static void self_crossings_should_count_proper_crossings(void)
{
    qc_vec2 star[5], eight[4], touch[5], rnd[300];
    qc_rng rng;
    size_t i, n;

    for (i = 0; i < 5; i++) /* a pentagram: 5 crossings */
        star[i] = v2(qc_cos(i * 4 * QC_PI / 5), qc_sin(i * 4 * QC_PI / 5));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_self_crossings(&ctx, star, 5, 1, &n));
    TEST_ASSERT_EQUAL_UINT(5, n);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_self_crossings(&ctx, star, 5, 0, &n));
    TEST_ASSERT_EQUAL_UINT(3, n);
    eight[0] = v2(0, 0); eight[1] = v2(1, 1); eight[2] = v2(1, 0); eight[3] = v2(0, 1);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_self_crossings(&ctx, eight, 4, 1, &n));
    TEST_ASSERT_EQUAL_UINT(1, n);
    /* a vertex on another segment touches, it does not cross */
    touch[0] = v2(0, 0); touch[1] = v2(2, 0); touch[2] = v2(2, 2);
    touch[3] = v2(1, 0); touch[4] = v2(0, 2);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_self_crossings(&ctx, touch, 5, 0, &n));
    TEST_ASSERT_EQUAL_UINT(0, n);
    qc_rng_seed(&rng, 9);
    for (i = 0; i < 300; i++)
        rnd[i] = rng_v2(&rng, 0, 100, 0, 30);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_self_crossings(&ctx, rnd, 300, 1, &n));
    TEST_ASSERT_EQUAL_UINT(brute_crossings(rnd, 300, 1), n);
    TEST_ASSERT_GREATER_THAN(1000, n);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_self_crossings(&ctx, rnd, 1, 1, &n));
    TEST_ASSERT_EQUAL_UINT(0, n);
    TEST_ASSERT_EQUAL_INT(QC_EINVAL, qc_path_self_crossings(&ctx, NULL, 3, 1, &n));
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

/* Hostile check inputs: stitches repeated on one spot are free (zero-length
 * segments are skipped); segments all through one spot are refused before
 * the quadratic pair loop. */
static void self_crossings_should_refuse_piles_and_skip_repeats(void)
{
    size_t n = 8000, i, count = 7;
    qc_vec2 *p = malloc(100000 * sizeof *p);

    TEST_ASSERT_NOT_NULL(p);
    for (i = 0; i < 100000; i++)
        p[i] = v2(5, 5);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_self_crossings(&ctx, p, 100000, 0, &count));
    TEST_ASSERT_EQUAL_UINT(0, count);
    for (i = 0; i < n; i++) { /* chords through the centre of a circle */
        double t = (double)i * QC_PI * (1 + 0.37 / (double)n);
        p[i] = v2(5 + 4 * qc_cos(t), 5 + 4 * qc_sin(t));
    }
    TEST_ASSERT_EQUAL_INT(QC_ELIMIT, qc_path_self_crossings(&ctx, p, n, 0, &count));
    TEST_ASSERT_NOT_NULL(strstr(qc_errmsg(&ctx), "over the limit of 20000000"));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_self_crossings(&ctx, p, 200, 0, &count));
    TEST_ASSERT_EQUAL_UINT(brute_crossings(p, 200, 0), count);
    free(p);
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(largest_gap_should_find_the_inscribed_circle);
    RUN_TEST(largest_gap_should_shrink_with_the_path);
    RUN_TEST(largest_gap_should_respect_holes);
    RUN_TEST(largest_gap_should_measure_path_pieces_apart);
    RUN_TEST(largest_gap_should_reject_bad_input);
    RUN_TEST(largest_gap_should_survive_allocation_failures);
    RUN_TEST(self_crossings_should_count_proper_crossings);
    RUN_TEST(self_crossings_should_refuse_piles_and_skip_repeats);
    return UNITY_END();
}
