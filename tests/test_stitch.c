/* The stitch plan: merging, splitting, tie-offs, jumps, clipping, estimates. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "quiltc.h"
#include "testalloc.h"
#include "testgeom.h"
#include "unity.h"
#include "../src/curve/curve_internal.h"
#include "../src/stitch/stitch_internal.h"

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

static double orient(qc_vec2 a, qc_vec2 b, qc_vec2 c)
{
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

/* Whether segments ab and cd cross properly. */
static int segments_cross(qc_vec2 a, qc_vec2 b, qc_vec2 c, qc_vec2 d)
{
    return orient(a, b, c) * orient(a, b, d) < 0 && orient(c, d, a) * orient(c, d, b) < 0;
}

static double seg(const qc_plan *p, size_t i)
{
    return hypot(p->p[i].x - p->p[i - 1].x, p->p[i].y - p->p[i - 1].y);
}

static size_t visits(const qc_plan *plan, qc_vec2 p)
{
    size_t i, n = 0;

    for (i = 0; i < plan->n; i++)
        n += plan->p[i].x == p.x && plan->p[i].y == p.y;
    return n;
}

/* A first segment just longer than the minimum: an odd tie-off stopping
 * tie_length along it used to leave a stitch of 0.036-0.076 mm to its end.
 * Every stitch after the start tie is now at least the minimum, ties or
 * splits, for first segments from the minimum to twice the tie length past
 * it; and the corner stays when the tie stops 0.15 mm or more before it. */
static void plan_should_leave_no_short_stitch_after_a_tie_off(void)
{
    qc_stitch_params sp;
    int ties, k, split;

    memset(&sp, 0, sizeof sp);
    sp.tie_length = 0.5;
    for (split = 0; split <= 1; split++)
        for (ties = 1; ties <= 4; ties++)
            for (k = 0; k <= 20; k++) {
                qc_path path = {0};
                qc_plan plan;
                double first = 0.508 + 0.05 * k, tie;
                size_t i;

                sp.tie_stitches = ties;
                sp.max_segment = split ? 0.6 : 0;
                TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_move_to(&ctx, &path, v2(0, 0)));
                TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_line_to(&ctx, &path, v2(first, 0)));
                TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_line_to(&ctx, &path, v2(first, 5)));
                TEST_ASSERT_EQUAL_INT(QC_OK, qc_stitch_plan(&ctx, &path, NULL, &sp, &plan));
                /* the tie keeps its length, but for an odd one with the
                 * corner 0.15 to 0.508 mm past it: it runs to the corner,
                 * which stays (unless that tie stitch is longer than a split) */
                tie = (ties & 1) && first - 0.5 >= 0.15 && first - 0.5 < 0.508 &&
                      !(split && first > 0.6) ? first : 0.5;
                for (i = 1; i <= (size_t)ties; i++)
                    TEST_ASSERT_DOUBLE_WITHIN(1e-9, tie, seg(&plan, i));
                for (i = 1; i < plan.n; i++) {
                    TEST_ASSERT_GREATER_THAN_DOUBLE(0.0, seg(&plan, i));
                    if (!(plan.flags[i] & QC_ST_TIE)) /* a kept corner: 0.15 mm */
                        TEST_ASSERT_TRUE(seg(&plan, i) >= 0.15 - 1e-9 &&
                                         (split || seg(&plan, i) >= 0.508 - 1e-9));
                }
                if (first - 0.5 >= 0.15) /* the corner is sewn */
                    TEST_ASSERT_TRUE(visits(&plan, v2(first, 0)) >= 1);
                /* the piece still reaches its corner and its end */
                TEST_ASSERT_DOUBLE_WITHIN(1e-12, first, plan.p[plan.n - 1].x);
                qc_plan_free(&ctx, &plan);
                qc_path_free(&ctx, &path);
            }
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

static void plan_should_merge_short_and_split_long_segments(void)
{
    qc_path path = {0};
    qc_stitch_params sp;
    qc_plan plan;
    size_t i;
    int x;

    memset(&sp, 0, sizeof sp);
    sp.min_segment = 1.0;
    sp.max_segment = 3.0;
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_move_to(&ctx, &path, v2(0, 0)));
    for (x = 1; x <= 10; x++) /* 0.25 mm steps: merged to 1 mm ones */
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_line_to(&ctx, &path, v2(x * 0.25, 0)));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_line_to(&ctx, &path, v2(2.5, 10))); /* split into 4 */
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_stitch_plan(&ctx, &path, NULL, &sp, &plan));
    TEST_ASSERT_EQUAL_INT(QC_ST_JUMP, plan.flags[0]);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, plan.p[0].x);
    TEST_ASSERT_EQUAL_DOUBLE(2.5, plan.p[plan.n - 1].x); /* the last point stays */
    TEST_ASSERT_EQUAL_DOUBLE(10.0, plan.p[plan.n - 1].y);
    for (i = 1; i < plan.n; i++) {
        TEST_ASSERT_EQUAL_INT(0, plan.flags[i]);
        TEST_ASSERT_LESS_OR_EQUAL_DOUBLE(3.0 + 1e-12, seg(&plan, i));
        TEST_ASSERT_GREATER_OR_EQUAL_DOUBLE(1.0 - 1e-12, seg(&plan, i));
    }
    /* 0, 1, 2, then 2.5 replaces 2 ... or stays: then 4 parts of 2.5 mm */
    TEST_ASSERT_EQUAL_size_t(3 + 4, plan.n);
    qc_plan_free(&ctx, &plan);
    qc_path_free(&ctx, &path);
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

/* A stitch within a hair of max_seg either way: the plan skips the root
 * for a square under max_seg^2 (1 - 1e-9), and must split exactly where
 * the root says d > max_seg (ceil(d / max_seg) parts), for lengths on both
 * sides of that cut and of max_seg itself, diagonal and straight, with
 * ties (which count the points first) and without. */
static void plan_should_split_exactly_where_the_length_passes_the_maximum(void)
{
    static const double rel[] = {-1e-6, -2e-9, -1e-9, -5e-10, -1e-15, 0,
                                 1e-16, 1e-15, 5e-10, 1e-9, 2e-9, 1e-6, 1.0, 2.0};
    static const double maxes[] = {0.6, 2.1166666666666667, 3.0, 25.4 / 7};
    size_t a, b, i;
    int ties;

    for (a = 0; a < sizeof maxes / sizeof maxes[0]; a++)
        for (b = 0; b < sizeof rel / sizeof rel[0]; b++)
            for (ties = 0; ties <= 1; ties++) {
                double m = maxes[a], len = m * (1 + rel[b]);
                qc_vec2 ends[2][2] = {{{0, 0}, {len, 0}}, {{1, 2}, {1 + len * 0.6, 2 + len * 0.8}}};

                for (i = 0; i < 2; i++) {
                    qc_vec2 p = ends[i][0], q = ends[i][1];
                    double dx = q.x - p.x, dy = q.y - p.y;
                    double d = sqrt(dx * dx + dy * dy); /* qc_hypot's formula */
                    size_t parts = d > m ? (size_t)ceil(d / m) : 1;
                    qc_path path = {0};
                    qc_stitch_params sp;
                    qc_plan plan;

                    memset(&sp, 0, sizeof sp);
                    sp.min_segment = 0.1;
                    sp.max_segment = m;
                    sp.tie_stitches = ties ? 2 : 0;
                    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_move_to(&ctx, &path, p));
                    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_line_to(&ctx, &path, q));
                    TEST_ASSERT_EQUAL_INT(QC_OK, qc_stitch_plan(&ctx, &path, NULL, &sp, &plan));
                    TEST_ASSERT_EQUAL_size_t(1 + parts + (ties ? 4 : 0), plan.n);
                    qc_plan_free(&ctx, &plan);
                    qc_path_free(&ctx, &path);
                }
            }
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

/* The plan of the polyline pts[0..n) with default parameters. */
static void plan_of(const qc_vec2 *pts, size_t n, qc_plan *plan)
{
    qc_path path = {0};
    size_t i;

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_move_to(&ctx, &path, pts[0]));
    for (i = 1; i < n; i++)
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_line_to(&ctx, &path, pts[i]));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_stitch_plan(&ctx, &path, NULL, NULL, plan));
    qc_path_free(&ctx, &path);
}

/* A pebble ends 0.4 mm from a seam, a link runs to the seam, the ditch runs
 * on along it. The plain merge dropped the seam point (0.4 mm < 0.508), and
 * the stitch from the pebble's end to the far corner cut diagonally across
 * a pass lying 0.05 mm off the seam (check counted crossings the path does
 * not have). The corner stays now, as a short stitch. */
static void plan_should_keep_a_corner_closer_than_the_minimum(void)
{
    const qc_vec2 pts[] = {{0, 5}, {10, 0.4}, {10, 0}, {40, 0}};
    qc_vec2 pass_a = v2(12, 0.05), pass_b = v2(38, 0.05); /* a pebble hugging the seam */
    qc_plan plan;
    size_t i;

    plan_of(pts, 4, &plan);
    TEST_ASSERT_EQUAL_size_t(4, plan.n);
    for (i = 0; i < 4; i++) {
        TEST_ASSERT_EQUAL_DOUBLE(pts[i].x, plan.p[i].x);
        TEST_ASSERT_EQUAL_DOUBLE(pts[i].y, plan.p[i].y);
    }
    for (i = 1; i < plan.n; i++) /* no stitch crosses the hugging pass */
        TEST_ASSERT_FALSE(segments_cross(plan.p[i - 1], plan.p[i], pass_a, pass_b));
    qc_plan_free(&ctx, &plan);
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

/* Short steps along a straight run or a gentle curve still merge; a step
 * too short to sew (0.05 mm, under check's 0.1 mm) merges even at a corner:
 * no stitch under 0.1 mm, and the path moves less than that step. */
static void plan_should_still_merge_straight_runs_and_tiny_corners(void)
{
    const qc_vec2 pts[] = {{0, 0}, {0.2, 0}, {0.4, 0}, {5, 0}, {5, 0.05}, {10, 0.05}};
    qc_plan plan;
    size_t i;

    plan_of(pts, 6, &plan);
    TEST_ASSERT_EQUAL_size_t(3, plan.n); /* (0,0), a corner by (5,0), (10,0.05) */
    for (i = 1; i < plan.n; i++)
        TEST_ASSERT_GREATER_OR_EQUAL_DOUBLE(0.1, seg(&plan, i));
    TEST_ASSERT_DOUBLE_WITHIN(0.05 + 1e-12, 5.0, plan.p[1].x);
    TEST_ASSERT_DOUBLE_WITHIN(0.05 + 1e-12, 0.0, plan.p[1].y);
    qc_plan_free(&ctx, &plan);
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

/* An echo's corner sewn out and back: out a -> p, on 0.08 mm straight to
 * q, then up (dropping q would stray 0.046 mm); back in to p from another
 * side, and on to a. Moving the out pass's corner from p onto q (p lies on
 * line a-q) left the back pass's turn at p a hair across a-q. A point the
 * piece passes twice stays. */
static void plan_should_keep_a_point_the_path_passes_twice(void)
{
    const qc_vec2 pts[] = {{0, 0}, {3, 3}, {3.06, 3.06}, {3.06, 3.28}, {3.06, 6}, {0, 6},
                           {0.5, 5.5}, {3, 3}, {0, 0}};
    qc_plan plan;

    plan_of(pts, 9, &plan);
    TEST_ASSERT_EQUAL_size_t(2, visits(&plan, v2(3, 3)));
    TEST_ASSERT_EQUAL_size_t(2, visits(&plan, v2(0, 0)));
    qc_plan_free(&ctx, &plan);
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

/* The same corner at the end of a long piece (4,040 points first, in rows
 * of 1 mm steps away from it): the merge's junction table is cut into
 * cells over the piece's box, and the two passes must meet in one. */
static void plan_should_keep_a_point_passed_twice_in_a_long_piece(void)
{
    const qc_vec2 tail[] = {{0, 0}, {3, 3}, {3.06, 3.06}, {3.06, 3.28}, {3.06, 6}, {0, 6},
                            {0.5, 5.5}, {3, 3}, {0, 0}};
    enum { ROWS = 40, ROW = 101 };
    static qc_vec2 pts[ROWS * ROW + 9];
    qc_plan plan;
    size_t r, i, n = 0;

    for (r = 0; r < ROWS; r++)
        for (i = 0; i < ROW; i++)
            pts[n++] = v2(10.0 + (double)(r % 2 ? ROW - 1 - i : i), 10.0 + (double)r);
    for (i = 0; i < 9; i++)
        pts[n++] = tail[i];
    plan_of(pts, n, &plan);
    TEST_ASSERT_EQUAL_size_t(2, visits(&plan, v2(3, 3)));
    TEST_ASSERT_EQUAL_size_t(2, visits(&plan, v2(0, 0)));
    TEST_ASSERT_EQUAL_size_t(1, visits(&plan, v2(60, 30)));
    qc_plan_free(&ctx, &plan);
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

static void plan_should_add_jumps_and_tie_offs_per_piece(void)
{
    qc_path path = {0};
    qc_stitch_params sp;
    qc_plan plan;
    qc_plan_estimate est;
    size_t i, jumps = 0, ties = 0;

    memset(&sp, 0, sizeof sp);
    sp.tie_stitches = 3;
    sp.tie_length = 0.4;
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_move_to(&ctx, &path, v2(0, 0)));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_line_to(&ctx, &path, v2(10, 0)));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_move_to(&ctx, &path, v2(20, 0)));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_line_to(&ctx, &path, v2(20, 10)));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_move_to(&ctx, &path, v2(50, 50))); /* lone point: dropped */
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_stitch_plan(&ctx, &path, NULL, &sp, &plan));
    /* per piece: start, 3 ties, end, 3 ties */
    TEST_ASSERT_EQUAL_size_t(16, plan.n);
    for (i = 0; i < plan.n; i++) {
        jumps += (plan.flags[i] & QC_ST_JUMP) != 0;
        ties += (plan.flags[i] & QC_ST_TIE) != 0;
    }
    TEST_ASSERT_EQUAL_size_t(2, jumps);
    TEST_ASSERT_EQUAL_size_t(12, ties);
    TEST_ASSERT_EQUAL_INT(QC_ST_JUMP, plan.flags[8]);
    TEST_ASSERT_EQUAL_DOUBLE(20.0, plan.p[8].x);
    /* start ties go forward along the path and back */
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 0.4, plan.p[1].x);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 0.0, plan.p[2].x);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 0.4, plan.p[3].x);
    /* end ties go back along the path */
    TEST_ASSERT_EQUAL_DOUBLE(10.0, plan.p[4].x);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 9.6, plan.p[5].x);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 9.6, plan.p[13].y);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 10.0, plan.p[14].y);
    qc_plan_estimate_get(&plan, 10, 10, &est);
    TEST_ASSERT_EQUAL_size_t(16, est.points);
    TEST_ASSERT_EQUAL_size_t(1, est.jumps);
    TEST_ASSERT_EQUAL_size_t(12, est.ties);
    /* per piece: 3 + 3 ties of 0.4 mm, the 3rd start tie ends 0.4 mm along
     * the 10 mm line; travel from the end tie (9.6, 0) to (20, 0) */
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 2 * (1.2 + 9.6 + 1.2), est.sewn_mm);
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 10.4, est.travel_mm);
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 24 * 1.1 + 300, est.thread_mm);
    TEST_ASSERT_EQUAL_size_t(9, est.stitches); /* 24 mm at 10 spi = 9.45 */
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 2.4 + 10.4 / 40, est.seconds);
    TEST_ASSERT_EQUAL_DOUBLE(20.0, est.bbox.max.x);
    qc_plan_free(&ctx, &plan);
    qc_path_free(&ctx, &path);
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

static void plan_should_flatten_curves_within_tolerance(void)
{
    qc_path path = {0};
    qc_plan plan;
    size_t i;

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_move_to(&ctx, &path, v2(0, 0)));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_cubic_to(&ctx, &path, v2(0, 50), v2(50, 50), v2(50, 0)));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_stitch_plan(&ctx, &path, NULL, NULL, &plan));
    TEST_ASSERT_GREATER_THAN(10, plan.n);
    for (i = 1; i < plan.n; i++) {
        /* every point on the curve's arch: between the chord and the top */
        TEST_ASSERT_TRUE(plan.p[i].y >= -1e-9 && plan.p[i].y <= 37.5 + 1e-9);
        TEST_ASSERT_GREATER_OR_EQUAL_DOUBLE(0.508 - 1e-9, seg(&plan, i));
    }
    qc_plan_free(&ctx, &plan);
    qc_path_free(&ctx, &path);
}

static void plan_should_clip_to_region(void)
{
    qc_region reg = {0};
    qc_vec2 sq[4] = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
    qc_path path = {0};
    qc_stitch_params sp;
    qc_plan plan;
    size_t i, jumps = 0;

    memset(&sp, 0, sizeof sp);
    sp.clip = 1;
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, &reg, sq, 4));
    /* a zigzag leaving the square twice through the right edge */
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_move_to(&ctx, &path, v2(5, 1)));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_line_to(&ctx, &path, v2(15, 3)));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_line_to(&ctx, &path, v2(5, 5)));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_line_to(&ctx, &path, v2(15, 7)));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_line_to(&ctx, &path, v2(5, 9)));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_stitch_plan(&ctx, &path, &reg, &sp, &plan));
    for (i = 0; i < plan.n; i++) {
        TEST_ASSERT_TRUE(qc_region_contains(&reg, plan.p[i]));
        jumps += (plan.flags[i] & QC_ST_JUMP) != 0;
    }
    TEST_ASSERT_EQUAL_size_t(3, jumps);
    TEST_ASSERT_EQUAL_size_t(7, plan.n);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 10.0, plan.p[1].x); /* cut on the edge */
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 2.0, plan.p[1].y);
    qc_plan_free(&ctx, &plan);
    /* all outside: nothing to sew */
    qc_region_translate(&reg, 100, 100);
    TEST_ASSERT_EQUAL_INT(QC_EEMPTY, qc_stitch_plan(&ctx, &path, &reg, &sp, &plan));
    TEST_ASSERT_EQUAL_size_t(0, plan.n);
    qc_region_free(&ctx, &reg);
    qc_path_free(&ctx, &path);
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

static void clip_should_keep_exactly_the_inside_length(void)
{
    qc_region reg = {0};
    qc_vec2 outer[5] = {{0, 0}, {100, 0}, {100, 60}, {50, 100}, {0, 60}};
    qc_vec2 hole[4] = {{30, 30}, {30, 50}, {70, 50}, {70, 30}}; /* clockwise */
    qc_path path = {0};
    qc_stitch_params sp;
    qc_plan plan;
    qc_rng rng;
    double inside_len = 0, sewn = 0;
    size_t i;
    int k, s;

    memset(&sp, 0, sizeof sp);
    sp.clip = 1;
    sp.min_segment = -1;
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, &reg, outer, 5));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, &reg, hole, 4));
    qc_rng_seed(&rng, 3);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_move_to(&ctx, &path, v2(-10, -10)));
    for (k = 0; k < 60; k++) {
        qc_vec2 a = qc_path_last(&path), b = rng_v2(&rng, -15, 130, -15, 130);
        /* brute force: the inside share of the segment by dense sampling */
        for (s = 0; s < 4000; s++) {
            double t = (s + 0.5) / 4000;
            if (qc_region_contains(&reg, v2(a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t)))
                inside_len += hypot(b.x - a.x, b.y - a.y) / 4000;
        }
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_line_to(&ctx, &path, b));
    }
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_stitch_plan(&ctx, &path, &reg, &sp, &plan));
    for (i = 1; i < plan.n; i++) {
        qc_vec2 m = v2(0.5 * (plan.p[i].x + plan.p[i - 1].x), 0.5 * (plan.p[i].y + plan.p[i - 1].y));
        if (plan.flags[i] & QC_ST_JUMP)
            continue;
        TEST_ASSERT_TRUE(qc_region_contains(&reg, m));
        sewn += seg(&plan, i);
    }
    TEST_ASSERT_DOUBLE_WITHIN(0.002 * inside_len, inside_len, sewn);
    qc_plan_free(&ctx, &plan);
    qc_path_free(&ctx, &path);
    qc_region_free(&ctx, &reg);
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

static void plan_should_reject_bad_params_and_survive_oom(void)
{
    qc_path path = {0};
    qc_stitch_params sp;
    qc_plan plan;
    size_t k, base;
    int rc = QC_ENOMEM;

    TEST_ASSERT_EQUAL_INT(QC_EEMPTY, qc_stitch_plan(&ctx, &path, NULL, NULL, &plan));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_move_to(&ctx, &path, v2(0, 0)));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_cubic_to(&ctx, &path, v2(0, 50), v2(50, 50), v2(50, 0)));
    memset(&sp, 0, sizeof sp);
    sp.tolerance = -1;
    TEST_ASSERT_EQUAL_INT(QC_ERANGE, qc_stitch_plan(&ctx, &path, NULL, &sp, &plan));
    TEST_ASSERT_TRUE(strstr(qc_errmsg(&ctx), "-1") != NULL);
    sp.tolerance = 0;
    sp.max_segment = 0.2; /* below the default minimum */
    TEST_ASSERT_EQUAL_INT(QC_ERANGE, qc_stitch_plan(&ctx, &path, NULL, &sp, &plan));
    sp.max_segment = 2;
    sp.tie_stitches = -2;
    TEST_ASSERT_EQUAL_INT(QC_ERANGE, qc_stitch_plan(&ctx, &path, NULL, &sp, &plan));
    sp.tie_stitches = 2;
    base = ta.live_blocks; /* the path */
    for (k = 1; rc == QC_ENOMEM && k < 200; k++) {
        ta.fail_at = ta.allocs + k;
        rc = qc_stitch_plan(&ctx, &path, NULL, &sp, &plan);
        if (rc == QC_ENOMEM)
            TEST_ASSERT_EQUAL_size_t(0, plan.n);
        qc_plan_free(&ctx, &plan);
        TEST_ASSERT_EQUAL_size_t(base, ta.live_blocks);
    }
    TEST_ASSERT_EQUAL_INT(QC_OK, rc);
    ta.fail_at = 0;
    qc_plan_free(&ctx, &plan);
    /* the clipping path too: a region cutting the arch in two */
    {
        qc_region reg = {0};
        qc_vec2 band[4] = {{-1, -1}, {51, -1}, {51, 20}, {-1, 20}};

        TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, &reg, band, 4));
        sp.clip = 1;
        base = ta.live_blocks;
        rc = QC_ENOMEM;
        for (k = 1; rc == QC_ENOMEM && k < 200; k++) {
            ta.fail_at = ta.allocs + k;
            rc = qc_stitch_plan(&ctx, &path, &reg, &sp, &plan);
            if (rc == QC_ENOMEM)
                TEST_ASSERT_EQUAL_size_t(0, plan.n);
            qc_plan_free(&ctx, &plan);
            TEST_ASSERT_EQUAL_size_t(base, ta.live_blocks);
        }
        TEST_ASSERT_EQUAL_INT(QC_OK, rc);
        ta.fail_at = 0;
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_stitch_plan(&ctx, &path, &reg, &sp, &plan));
        for (k = 0, rc = 0; k < plan.n; k++)
            rc += (plan.flags[k] & QC_ST_JUMP) != 0;
        TEST_ASSERT_EQUAL_INT(2, rc); /* two legs of the arch */
        qc_plan_free(&ctx, &plan);
        qc_region_free(&ctx, &reg);
    }
    TEST_ASSERT_FALSE(ta.size_mismatch);
    qc_path_free(&ctx, &path);
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

/* qc_stitch_plan_taking: the same plan as qc_stitch_plan (the in-place
 * plan of one untied piece, ties, splits, clipped pieces), the path freed
 * and zeroed whatever the outcome, a lower peak (the path is gone before
 * the merge), no block left behind when an allocation fails. */
static void plan_taking_should_match_and_free_the_path(void)
{
    qc_path path = {0}, copy = {0};
    qc_region reg = {0};
    qc_vec2 band[4] = {{-1, -1}, {301, -1}, {301, 20}, {-1, 20}};
    qc_stitch_params sp;
    qc_plan want, got;
    size_t i, k, base, peak_plain, peak_taking;
    int c, rc;

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_move_to(&ctx, &path, v2(0, 0)));
    for (i = 0; i < 30; i++) {
        double x = 10.0 * (double)i;
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_cubic_to(&ctx, &path, v2(x, 40), v2(x + 10, 40),
                                                      v2(x + 10, 0)));
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_line_to(&ctx, &path, v2(x + 10.2, 0.1)));
    }
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, &reg, band, 4));
    for (c = 0; c < 4; c++) {
        memset(&sp, 0, sizeof sp);
        sp.tie_stitches = c == 1 ? 3 : 0;
        sp.max_segment = c == 2 ? 2.0 : 0.0;
        sp.clip = c == 3;
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_append(&ctx, &copy, &path, 0));
        ta.peak_bytes = ta.live_bytes;
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_stitch_plan(&ctx, &path, &reg, &sp, &want));
        peak_plain = ta.peak_bytes;
        qc_plan_free(&ctx, &want);
        ta.peak_bytes = ta.live_bytes;
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_stitch_plan_taking(&ctx, &copy, &reg, &sp, &got));
        peak_taking = ta.peak_bytes;
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_stitch_plan(&ctx, &path, &reg, &sp, &want));
        TEST_ASSERT_TRUE(peak_taking < peak_plain);
        TEST_ASSERT_TRUE(copy.pt == NULL && copy.cmd == NULL && copy.npt == 0);
        TEST_ASSERT_TRUE(want.n > 100);
        TEST_ASSERT_EQUAL_size_t(want.n, got.n);
        TEST_ASSERT_EQUAL_MEMORY(want.p, got.p, want.n * sizeof *want.p);
        TEST_ASSERT_EQUAL_MEMORY(want.flags, got.flags, want.n);
        qc_plan_free(&ctx, &want);
        qc_plan_free(&ctx, &got);
    }
    /* refused before the flattening: the path is freed all the same */
    memset(&sp, 0, sizeof sp);
    sp.tolerance = -1;
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_append(&ctx, &copy, &path, 0));
    TEST_ASSERT_EQUAL_INT(QC_ERANGE, qc_stitch_plan_taking(&ctx, &copy, NULL, &sp, &got));
    TEST_ASSERT_TRUE(copy.pt == NULL && got.n == 0);
    sp.tolerance = 0;
    base = ta.live_blocks; /* the path and the region */
    rc = QC_ENOMEM;
    for (k = 1; rc == QC_ENOMEM && k < 200; k++) {
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_append(&ctx, &copy, &path, 0));
        ta.fail_at = ta.allocs + k;
        rc = qc_stitch_plan_taking(&ctx, &copy, NULL, &sp, &got);
        ta.fail_at = 0;
        TEST_ASSERT_TRUE(copy.pt == NULL);
        if (rc == QC_ENOMEM)
            TEST_ASSERT_EQUAL_size_t(0, got.n);
        qc_plan_free(&ctx, &got);
        TEST_ASSERT_EQUAL_size_t(base, ta.live_blocks);
    }
    TEST_ASSERT_EQUAL_INT(QC_OK, rc);
    TEST_ASSERT_FALSE(ta.size_mismatch);
    qc_path_free(&ctx, &path);
    qc_region_free(&ctx, &reg);
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

/* qc__curve_flatten_taking: the points and piece ends of qc_curve_flatten
 * to the bit (pieces after MOVEs, two MOVEs in a row, a path that starts
 * without one, lines and cubics), the path freed, and a lower peak than
 * the path and its points together (the path shrinks behind the walk). */
static void flatten_taking_should_match_the_forward_flatten(void)
{
    int shape;

    for (shape = 0; shape < 3; shape++) {
        qc_path path = {0}, copy = {0};
        qc_points want = {0}, got = {0};
        qc_order wend = {0}, gend = {0};
        size_t i, before, peak;
        qc_rng rng;

        qc_rng_seed(&rng, 5 + (uint64_t)shape);
        if (shape != 1) /* shape 1 starts at (0, 0), without a MOVE */
            TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_move_to(&ctx, &path, v2(1, 2)));
        for (i = 0; i < 3000; i++) {
            double x = (double)qc_rng_below(&rng, 1000) / 7.0;
            double y = (double)qc_rng_below(&rng, 1000) / 9.0;
            uint64_t r = qc_rng_below(&rng, 40);

            if (r == 0 || (shape == 2 && r < 3)) /* shape 2: MOVEs in a row too */
                TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_move_to(&ctx, &path, v2(x, y)));
            else if (r < 10)
                TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_line_to(&ctx, &path, v2(x, y)));
            else
                TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_cubic_to(&ctx, &path, v2(y, x),
                                                              v2(x + 3, y - 2), v2(x, y)));
        }
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_curve_flatten(&ctx, &path, 0.01, &want, &wend));
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_append(&ctx, &copy, &path, 0));
        before = ta.live_bytes;
        ta.peak_bytes = before;
        TEST_ASSERT_EQUAL_INT(QC_OK, qc__curve_flatten_taking(&ctx, &copy, 0.01, &got, &gend));
        peak = ta.peak_bytes;
        TEST_ASSERT_TRUE(copy.pt == NULL && copy.cmd == NULL);
        TEST_ASSERT_TRUE(want.n > 10 * path.npt / 3);
        TEST_ASSERT_EQUAL_size_t(want.n, got.n);
        TEST_ASSERT_EQUAL_MEMORY(want.v, got.v, want.n * sizeof *want.v);
        TEST_ASSERT_TRUE(wend.n > 10);
        TEST_ASSERT_EQUAL_size_t(wend.n, gend.n);
        TEST_ASSERT_EQUAL_MEMORY(wend.i, gend.i, wend.n * sizeof *wend.i);
        /* the path is most of what was live before: the peak stays under
         * it and the points side by side */
        TEST_ASSERT_TRUE(peak < before + got.cap * sizeof *got.v - path.npt * sizeof *path.pt / 2);
        qc_points_free(&ctx, &want);
        qc_points_free(&ctx, &got);
        qc_order_free(&ctx, &wend);
        qc_order_free(&ctx, &gend);
        qc_path_free(&ctx, &path);
        TEST_ASSERT_FALSE(ta.size_mismatch);
        TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
    }
}

/* Junctions by a sort, for comparison: the least index of each place
 * visited again other than as a repeat of the point before. */
static const qc_vec2 *sort_v;

static int cmp_place(const void *pa, const void *pb)
{
    size_t a = *(const size_t *)pa, b = *(const size_t *)pb;
    qc_vec2 p = sort_v[a], q = sort_v[b];

    if (p.x != q.x)
        return p.x < q.x ? -1 : 1;
    if (p.y != q.y)
        return p.y < q.y ? -1 : 1;
    return a < b ? -1 : a > b;
}

static void junctions_by_sort(const qc_vec2 *v, size_t n, size_t *ref, size_t *ord)
{
    size_t i, j, k;

    for (i = 0; i < n; i++)
        ord[i] = i;
    sort_v = v;
    qsort(ord, n, sizeof *ord, cmp_place);
    for (i = 0; i < n; i = j) {
        int again = 0;
        for (j = i + 1; j < n && v[ord[j]].x == v[ord[i]].x && v[ord[j]].y == v[ord[i]].y; j++)
            again |= !(v[ord[j] - 1].x == v[ord[j]].x && v[ord[j] - 1].y == v[ord[j]].y);
        for (k = i; k < j; k++)
            ref[ord[k]] = again ? ord[i] : (size_t)QC__NOT_JOINT;
    }
}

/* The merge's junction marks (a hash table cut by a grid of cells over
 * the piece) are those a sort finds, at any piece length: a walk on a
 * small lattice (revisits, runs of one point, -0 and +0, a far outlier
 * that stretches the grid, an infinity). */
static void junctions_should_be_those_a_sort_finds(void)
{
    static const size_t sizes[] = {5000, 70000, 300000};
    size_t z;

    for (z = 0; z < sizeof sizes / sizeof *sizes; z++) {
        size_t n = sizes[z], i, joints = 0;
        qc_vec2 *v = malloc(n * sizeof *v);
        size_t *ref = malloc(n * sizeof *ref), *ord = malloc(n * sizeof *ord);
        qc__merge mg;
        qc_rng rng;

        TEST_ASSERT_NOT_NULL(v);
        TEST_ASSERT_NOT_NULL(ref);
        TEST_ASSERT_NOT_NULL(ord);
        TEST_ASSERT_EQUAL_INT(QC_OK, qc__merge_init(&ctx, &mg, n));
        qc_rng_seed(&rng, 21 + z);
        v[0].x = 0.0;
        v[0].y = 0.0;
        for (i = 1; i < n; i++) {
            uint64_t r = qc_rng_below(&rng, 10);
            v[i] = v[i - 1];
            if (r < 2) /* a repeat of the point before */
                continue;
            v[i].x += r < 6 ? (r < 4 ? 0.5 : -0.5) : 0.0;
            v[i].y += r >= 6 ? (r < 8 ? 0.5 : -0.5) : 0.0;
            v[i].x = fabs(v[i].x) > 40.0 ? 0.0 : v[i].x;
            v[i].y = fabs(v[i].y) > 40.0 ? 0.0 : v[i].y;
            if (v[i].x == 0.0 && (i & 1))
                v[i].x = -0.0; /* the same place as +0 */
        }
        v[n / 2].x = z == 1 ? 1e6 : 200.0;
        v[n / 3].y = HUGE_VAL;
        qc__merge_junctions(&mg, v, n);
        junctions_by_sort(v, n, ref, ord);
        for (i = 0; i < n; i++) {
            TEST_ASSERT_EQUAL_size_t(ref[i], mg.place[i]);
            joints += mg.place[i] != QC__NOT_JOINT;
        }
        TEST_ASSERT_TRUE(joints > n / 2 && joints < n); /* real junctions, and not all */
        qc__merge_free(&ctx, &mg);
        free(v);
        free(ref);
        free(ord);
    }
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(plan_should_merge_short_and_split_long_segments);
    RUN_TEST(plan_should_split_exactly_where_the_length_passes_the_maximum);
    RUN_TEST(plan_should_keep_a_corner_closer_than_the_minimum);
    RUN_TEST(plan_should_still_merge_straight_runs_and_tiny_corners);
    RUN_TEST(plan_should_keep_a_point_the_path_passes_twice);
    RUN_TEST(plan_should_keep_a_point_passed_twice_in_a_long_piece);
    RUN_TEST(plan_should_add_jumps_and_tie_offs_per_piece);
    RUN_TEST(plan_should_leave_no_short_stitch_after_a_tie_off);
    RUN_TEST(plan_should_flatten_curves_within_tolerance);
    RUN_TEST(plan_should_clip_to_region);
    RUN_TEST(clip_should_keep_exactly_the_inside_length);
    RUN_TEST(plan_should_reject_bad_params_and_survive_oom);
    RUN_TEST(plan_taking_should_match_and_free_the_path);
    RUN_TEST(flatten_taking_should_match_the_forward_flatten);
    RUN_TEST(junctions_should_be_those_a_sort_finds);
    return UNITY_END();
}
