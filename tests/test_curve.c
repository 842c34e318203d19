/* Curves: Catmull-Rom through every point without cusps, flattening within tolerance. */
#include <math.h>
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
}

static qc_vec2 bez(const qc_vec2 c[4], double t)
{
    double u = 1 - t, b0 = u * u * u, b1 = 3 * u * u * t, b2 = 3 * u * t * t,
           b3 = t * t * t;
    qc_vec2 r;

    r.x = b0 * c[0].x + b1 * c[1].x + b2 * c[2].x + b3 * c[3].x;
    r.y = b0 * c[0].y + b1 * c[1].y + b2 * c[2].y + b3 * c[3].y;
    return r;
}

static qc_vec2 bez_d(const qc_vec2 c[4], double t)
{
    double u = 1 - t;
    qc_vec2 r;

    r.x = 3 * (u * u * (c[1].x - c[0].x) + 2 * u * t * (c[2].x - c[1].x) +
               t * t * (c[3].x - c[2].x));
    r.y = 3 * (u * u * (c[1].y - c[0].y) + 2 * u * t * (c[2].y - c[1].y) +
               t * t * (c[3].y - c[2].y));
    return r;
}

/* The cubic ending at path command c (c >= 1), control points into q. */
static void cubic_at(const qc_path *p, size_t c, qc_vec2 q[4])
{
    size_t k = 0, i;

    for (i = 0; i < c; i++)
        k += qc_path_cmd_points(p->cmd[i]);
    q[0] = p->pt[k - 1];
    q[1] = p->pt[k];
    q[2] = p->pt[k + 1];
    q[3] = p->pt[k + 2];
}

/* Every segment's minimum |B'(t)| relative to its chord, sampled densely. */
static double min_speed_ratio(const qc_path *p)
{
    double worst = 1e300;
    size_t c;
    int s;

    for (c = 1; c < p->ncmd; c++) {
        qc_vec2 q[4];
        double chord;

        TEST_ASSERT_EQUAL_INT(QC_PATH_CUBIC, p->cmd[c]);
        cubic_at(p, c, q);
        chord = hypot(q[3].x - q[0].x, q[3].y - q[0].y);
        for (s = 0; s <= 1000; s++) {
            qc_vec2 d = bez_d(q, s / 1000.0);
            double r = hypot(d.x, d.y) / chord;
            if (r < worst)
                worst = r;
        }
    }
    return worst;
}

static void catmull_rom_should_pass_through_every_point(void)
{
    qc_vec2 pts[6] = {{0, 0}, {10, 0}, {10, 10}, {0, 10}, {5, 5}, {20, 3}};
    qc_path p = {0};
    size_t i;

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_curve_catmull_rom(&ctx, pts, 6, 0, &p));
    TEST_ASSERT_EQUAL_size_t(6, p.ncmd);
    TEST_ASSERT_EQUAL_INT(QC_PATH_MOVE, p.cmd[0]);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, p.pt[0].x);
    for (i = 1; i < 6; i++) {
        qc_vec2 e = p.pt[1 + 3 * (i - 1) + 2];
        TEST_ASSERT_EQUAL_DOUBLE(pts[i].x, e.x);
        TEST_ASSERT_EQUAL_DOUBLE(pts[i].y, e.y);
    }
    TEST_ASSERT_GREATER_THAN_DOUBLE(1e-3, min_speed_ratio(&p));
    qc_path_free(&ctx, &p);
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

static void catmull_rom_should_close_and_skip_coincident_points(void)
{
    qc_vec2 pts[7] = {{0, 0}, {0, 0}, {10, 0}, {10, 0}, {10, 10}, {0, 10}, {0, 0}};
    qc_path p = {0};

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_curve_catmull_rom(&ctx, pts, 7, 1, &p));
    /* 4 distinct points, closed: MOVE + 4 cubics, back at the start. */
    TEST_ASSERT_EQUAL_size_t(5, p.ncmd);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, qc_path_last(&p).x);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, qc_path_last(&p).y);
    TEST_ASSERT_GREATER_THAN_DOUBLE(1e-3, min_speed_ratio(&p));
    qc_path_free(&ctx, &p);
}

static void catmull_rom_should_have_no_cusp_on_adversarial_inputs(void)
{
    /* hairpins (exact reversals), near-duplicates, wildly uneven spacing */
    qc_vec2 a[] = {{0, 0}, {1, 0}, {0.5, 0}, {0.5, 1e-7}, {100, 0}, {100.001, 0},
                   {0, 0}, {0, 50}, {0, -50}, {3, 3}, {3, 3.0000001}, {-7, 2}};
    qc_vec2 b[] = {{0, 0}, {10, 0}};
    qc_rng rng;
    qc_vec2 r[40];
    qc_path p = {0};
    int trial, i;

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_curve_catmull_rom(&ctx, a, 12, 0, &p));
    TEST_ASSERT_GREATER_THAN_DOUBLE(1e-6, min_speed_ratio(&p));
    qc_path_free(&ctx, &p);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_curve_catmull_rom(&ctx, a, 12, 1, &p));
    TEST_ASSERT_GREATER_THAN_DOUBLE(1e-6, min_speed_ratio(&p));
    qc_path_free(&ctx, &p);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_curve_catmull_rom(&ctx, b, 2, 1, &p));
    TEST_ASSERT_EQUAL_size_t(3, p.ncmd);
    TEST_ASSERT_GREATER_THAN_DOUBLE(1e-6, min_speed_ratio(&p));
    qc_path_free(&ctx, &p);
    qc_rng_seed(&rng, 7);
    for (trial = 0; trial < 50; trial++) {
        for (i = 0; i < 40; i++) {
            /* a coarse grid makes repeats, reversals and collinear runs likely */
            r[i].x = (double)qc_rng_below(&rng, 4);
            r[i].y = (double)qc_rng_below(&rng, 3);
        }
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_curve_catmull_rom(&ctx, r, 40, trial & 1, &p));
        TEST_ASSERT_GREATER_THAN_DOUBLE(1e-6, min_speed_ratio(&p));
        qc_path_free(&ctx, &p);
    }
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

static void catmull_rom_should_continue_an_existing_path(void)
{
    qc_vec2 pts[3] = {{5, 0}, {6, 1}, {7, 0}};
    qc_vec2 o = {0, 0}, e = {5, 0};
    qc_path p = {0};

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_move_to(&ctx, &p, o));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_line_to(&ctx, &p, e));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_curve_catmull_rom(&ctx, pts, 3, 0, &p));
    TEST_ASSERT_EQUAL_size_t(4, p.ncmd);
    TEST_ASSERT_EQUAL_size_t(1, qc_path_pieces(&p));
    qc_path_free(&ctx, &p);
}

static void catmull_rom_should_fail_cleanly_out_of_memory(void)
{
    qc_vec2 pts[5] = {{0, 0}, {1, 2}, {3, 1}, {4, 4}, {0, 7}};
    qc_vec2 bad[2] = {{0, 0}, {(double)NAN, 1}};
    qc_path p = {0};
    size_t k;
    int rc = QC_ENOMEM;

    for (k = 1; rc == QC_ENOMEM && k < 20; k++) {
        ta.fail_at = ta.allocs + 1 + (k - 1);
        rc = qc_curve_catmull_rom(&ctx, pts, 5, 0, &p);
        if (rc == QC_ENOMEM)
            TEST_ASSERT_EQUAL_size_t(0, p.ncmd);
        qc_path_free(&ctx, &p);
        TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
    }
    TEST_ASSERT_EQUAL_INT(QC_OK, rc);
    ta.fail_at = 0;
    TEST_ASSERT_EQUAL_INT(QC_ERANGE, qc_curve_catmull_rom(&ctx, bad, 2, 0, &p));
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

/* Distance from p to the polyline v[0..n). */
static double poly_dist(const qc_vec2 *v, size_t n, qc_vec2 p)
{
    double best = 1e300;
    size_t i;

    for (i = 0; i + 1 < n; i++) {
        double dx = v[i + 1].x - v[i].x, dy = v[i + 1].y - v[i].y;
        double l2 = dx * dx + dy * dy, t = 0, ex, ey, d;
        if (l2 > 0)
            t = ((p.x - v[i].x) * dx + (p.y - v[i].y) * dy) / l2;
        t = t < 0 ? 0 : t > 1 ? 1 : t;
        ex = v[i].x + t * dx - p.x;
        ey = v[i].y + t * dy - p.y;
        d = sqrt(ex * ex + ey * ey);
        if (d < best)
            best = d;
    }
    return best;
}

static void flatten_should_respect_tolerance(void)
{
    qc_vec2 pts[8] = {{0, 0}, {30, 5}, {32, 40}, {-10, 20}, {5, -3}, {5, -2.9}, {60, 60}, {0, 1}};
    double tols[3] = {1.0, 0.127, 0.01};
    qc_path p = {0};
    int t;

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_curve_catmull_rom(&ctx, pts, 8, 0, &p));
    for (t = 0; t < 3; t++) {
        qc_points out = {0};
        qc_order ends = {0};
        double worst = 0;
        size_t c, s;

        TEST_ASSERT_EQUAL_INT(QC_OK, qc_curve_flatten(&ctx, &p, tols[t], &out, &ends));
        TEST_ASSERT_EQUAL_size_t(1, ends.n);
        TEST_ASSERT_EQUAL_UINT32(out.n, ends.i[0]);
        TEST_ASSERT_EQUAL_DOUBLE(pts[7].x, out.v[out.n - 1].x);
        for (c = 1; c < p.ncmd; c++) {
            qc_vec2 q[4];
            cubic_at(&p, c, q);
            for (s = 0; s <= 400; s++) {
                double d = poly_dist(out.v, out.n, bez(q, s / 400.0));
                if (d > worst)
                    worst = d;
            }
        }
        TEST_ASSERT_LESS_OR_EQUAL_DOUBLE(tols[t], worst);
        qc_points_free(&ctx, &out);
        qc_order_free(&ctx, &ends);
    }
    qc_path_free(&ctx, &p);
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

static void flatten_should_split_pieces_and_measure(void)
{
    qc_path p = {0};
    qc_points out = {0};
    qc_order ends = {0};
    qc_vec2 a = {0, 0}, b = {3, 4}, c = {10, 10}, d = {10, 12}, c1 = {0, 1}, c2 = {1, 1}, e = {1, 0};
    qc_bbox box;

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_move_to(&ctx, &p, a));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_line_to(&ctx, &p, b));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_move_to(&ctx, &p, c));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_line_to(&ctx, &p, d));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_curve_flatten(&ctx, &p, 0.1, &out, &ends));
    TEST_ASSERT_EQUAL_size_t(4, out.n);
    TEST_ASSERT_EQUAL_size_t(2, ends.n);
    TEST_ASSERT_EQUAL_UINT32(2, ends.i[0]);
    TEST_ASSERT_EQUAL_UINT32(4, ends.i[1]);
    /* the jump between pieces is not length */
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 7.0, qc_curve_length(&p, 0.1));
    box = qc_curve_bbox(&p, 0.1);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, box.min.x);
    TEST_ASSERT_EQUAL_DOUBLE(12.0, box.max.y);
    TEST_ASSERT_EQUAL_INT(QC_ERANGE, qc_curve_flatten(&ctx, &p, 0, &out, &ends));
    TEST_ASSERT_EQUAL_INT(QC_ERANGE, qc_curve_flatten(&ctx, &p, (double)NAN, &out, &ends));
    p.pt[1].y = (double)NAN;
    TEST_ASSERT_EQUAL_INT(QC_ERANGE, qc_curve_flatten(&ctx, &p, 0.1, &out, &ends));
    TEST_ASSERT_EQUAL_size_t(4, out.n); /* nothing appended */
    qc_path_free(&ctx, &p);
    qc_points_free(&ctx, &out);
    qc_order_free(&ctx, &ends);
    /* a quarter-circle-like cubic: length close to the true arc length */
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_move_to(&ctx, &p, a));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_cubic_to(&ctx, &p, c1, c2, e));
    TEST_ASSERT_DOUBLE_WITHIN(1e-3, qc_curve_length(&p, 1e-4), qc_curve_length(&p, 1e-3));
    box = qc_curve_bbox(&p, 1e-4);
    TEST_ASSERT_DOUBLE_WITHIN(1e-3, 0.75, box.max.y); /* control points excluded */
    {   /* qc_curve_measure: both at once, the arc's (flattening falls just short) */
        double len;
        qc_bbox both;
        qc_curve_measure(&p, 1e-4, &len, &both);
        TEST_ASSERT_DOUBLE_WITHIN(1e-6, qc_curve_length(&p, 1e-6), len);
        TEST_ASSERT_DOUBLE_WITHIN(1e-6, 0.75, both.max.y);
        TEST_ASSERT_DOUBLE_WITHIN(1e-4, box.max.y, both.max.y);
        TEST_ASSERT_TRUE(both.max.y >= box.max.y);
    }
    qc_path_free(&ctx, &p);
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

/* A cubic's point, tangent and split agree with each other. */
static void cubic_point_tangent_and_split_should_agree(void)
{
    qc_vec2 q[4], l[4], r[4], p, a, b, tg;
    double t = 0.3, h = 1e-6;

    q[0].x = 0; q[0].y = 0; q[1].x = 1; q[1].y = 3; q[2].x = 4; q[2].y = -2; q[3].x = 5; q[3].y = 1;
    p = qc_cubic_point(q, 0);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, p.x);
    p = qc_cubic_point(q, 1);
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 5.0, p.x);
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 1.0, p.y);
    a = qc_cubic_point(q, t - h);
    b = qc_cubic_point(q, t + h);
    tg = qc_cubic_tangent(q, t);
    TEST_ASSERT_DOUBLE_WITHIN(1e-6, (b.x - a.x) / (2 * h), tg.x);
    TEST_ASSERT_DOUBLE_WITHIN(1e-6, (b.y - a.y) / (2 * h), tg.y);
    qc_cubic_split(q, t, l, r);
    p = qc_cubic_point(q, t);
    TEST_ASSERT_EQUAL_DOUBLE(p.x, l[3].x);
    TEST_ASSERT_EQUAL_DOUBLE(p.y, r[0].y);
    /* the halves trace the same curve: left at 0.5 is q at t/2, right at 0.5 is q at (1+t)/2 */
    a = qc_cubic_point(l, 0.5);
    b = qc_cubic_point(q, t / 2);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, b.x, a.x);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, b.y, a.y);
    a = qc_cubic_point(r, 0.5);
    b = qc_cubic_point(q, (1 + t) / 2);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, b.x, a.x);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, b.y, a.y);
    qc_cubic_split(q, t, l, q); /* r may alias q */
    TEST_ASSERT_EQUAL_DOUBLE(r[1].x, q[1].x);
    TEST_ASSERT_EQUAL_DOUBLE(r[3].y, q[3].y);
}

/* A random control point: mostly a few mm apart, sometimes on top of another
 * (cusps, zero-length legs, loops). */
static qc_vec2 random_point(qc_rng *rng, qc_vec2 near)
{
    qc_vec2 p;

    if (qc_rng_below(rng, 8) == 0)
        return near;
    p.x = near.x + (double)qc_rng_below(rng, 2001) / 100 - 10;
    p.y = near.y + (double)qc_rng_below(rng, 2001) / 100 - 10;
    return p;
}

/* The measure without flattening: on random cubics (loops, cusps, lines)
 * its length is the arc's, as a flattening 500,000 times finer than the
 * stats' gives it, and never below the stats' old flattening; its box
 * holds every flattened point and the curve, and reaches no further than
 * the curve does (a fine flattening's box). */
static void measure_should_match_fine_flattening_on_random_cubics(void)
{
    qc_rng rng;
    int trial;
    double worst = 0;

    qc_rng_seed(&rng, 21);
    for (trial = 0; trial < 400; trial++) {
        qc_path p = {0};
        qc_vec2 q[4];
        qc_bbox box, fine, coarse;
        double len, ref, old;
        int k;

        q[0].x = 0;
        q[0].y = 0;
        for (k = 1; k < 4; k++)
            q[k] = random_point(&rng, q[k - 1]);
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_move_to(&ctx, &p, q[0]));
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_cubic_to(&ctx, &p, q[1], q[2], q[3]));
        qc_curve_measure(&p, 0.05, &len, &box);
        ref = qc_curve_length(&p, 1e-7);
        old = qc_curve_length(&p, 0.05);
        fine = qc_curve_bbox(&p, 5e-5);
        coarse = qc_curve_bbox(&p, 0.05);
        TEST_ASSERT_DOUBLE_WITHIN(1e-5 * ref + 1e-9, ref, len);
        TEST_ASSERT_TRUE(len >= old - 1e-9);
        if (len - old > worst)
            worst = len - old;
        TEST_ASSERT_TRUE(box.min.x <= coarse.min.x && box.min.y <= coarse.min.y);
        TEST_ASSERT_TRUE(box.max.x >= coarse.max.x && box.max.y >= coarse.max.y);
        TEST_ASSERT_DOUBLE_WITHIN(5e-5, fine.min.x, box.min.x);
        TEST_ASSERT_DOUBLE_WITHIN(5e-5, fine.min.y, box.min.y);
        TEST_ASSERT_DOUBLE_WITHIN(5e-5, fine.max.x, box.max.x);
        TEST_ASSERT_DOUBLE_WITHIN(5e-5, fine.max.y, box.max.y);
        qc_path_free(&ctx, &p);
    }
    TEST_ASSERT_TRUE(worst > 0); /* the old flattening did fall short somewhere */
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

/* Moves are not sewn, lines are exact, a path may start without a move,
 * and a non-finite cubic ends (as its chord) instead of subdividing forever. */
static void measure_should_skip_moves_and_survive_nan(void)
{
    qc_path p = {0};
    qc_vec2 a = {3, 4}, b = {3, 0}, c = {10, 10}, d = {10, 12};
    qc_bbox box;
    double len;

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_line_to(&ctx, &p, a)); /* from (0, 0) */
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_line_to(&ctx, &p, b));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_move_to(&ctx, &p, c));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_line_to(&ctx, &p, d));
    qc_curve_measure(&p, 0.05, &len, &box);
    TEST_ASSERT_EQUAL_DOUBLE(11.0, len);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, box.min.x);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, box.min.y);
    TEST_ASSERT_EQUAL_DOUBLE(10.0, box.max.x);
    TEST_ASSERT_EQUAL_DOUBLE(12.0, box.max.y);
    a.x = (double)NAN;
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_cubic_to(&ctx, &p, a, b, c));
    qc_curve_measure(&p, 0.05, &len, &box);
    TEST_ASSERT_TRUE(len > 11.0);
    qc_path_free(&ctx, &p);
    memset(&box, 0xff, sizeof box);
    qc_curve_measure(&p, 0.05, &len, &box); /* empty: all zero */
    TEST_ASSERT_EQUAL_DOUBLE(0.0, len);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, box.max.x);
}

/* On real patterns the stats' length is the arc length: within 1e-5 of a
 * flattening 5,000 times finer (which falls short by about tol / 3R), at
 * or above the old 0.05 mm flattening that it replaces, by that
 * flattening's own shortfall; the box within the finer one's tolerance. */
static void generate_stats_should_measure_the_arc(void)
{
    static const int fam[] = {QC_FAMILY_BRANCHING, QC_FAMILY_PEBBLING, QC_FAMILY_VINE,
                              QC_FAMILY_SPIRAL, QC_FAMILY_WANDERER};
    qc_region r = {0};
    size_t f;

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_shape(&ctx, "heart:8", 25.4, &r));
    for (f = 0; f < sizeof fam / sizeof fam[0]; f++) {
        qc_params p;
        qc_result res;
        double ref, old;
        qc_bbox fine;

        memset(&p, 0, sizeof p);
        qc_params_set(&ctx, &p, "family", fam[f]);
        qc_params_set(&ctx, &p, "spacing", 12);
        TEST_ASSERT_EQUAL_INT_MESSAGE(QC_OK, qc_generate(&ctx, &r, &p, NULL, NULL, &res),
                                      qc_errmsg(&ctx));
        ref = qc_curve_length(&res.path, 1e-5);
        old = qc_curve_length(&res.path, 0.05);
        fine = qc_curve_bbox(&res.path, 1e-5);
        TEST_ASSERT_TRUE(res.stats.length_mm >= ref);
        TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(1e-5 * ref, ref, res.stats.length_mm,
                                          qc_family_name(fam[f]));
        /* the old figure fell 0.06-0.17% short (chords are shorter than arcs) */
        TEST_ASSERT_TRUE(res.stats.length_mm >= old);
        TEST_ASSERT_TRUE(res.stats.length_mm - old <= 2e-3 * old);
        TEST_ASSERT_DOUBLE_WITHIN(1e-4, fine.min.x, res.stats.bbox.min.x);
        TEST_ASSERT_DOUBLE_WITHIN(1e-4, fine.max.y, res.stats.bbox.max.y);
        qc_result_free(&ctx, &res);
    }
    qc_region_free(&ctx, &r);
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(catmull_rom_should_pass_through_every_point);
    RUN_TEST(catmull_rom_should_close_and_skip_coincident_points);
    RUN_TEST(catmull_rom_should_have_no_cusp_on_adversarial_inputs);
    RUN_TEST(catmull_rom_should_continue_an_existing_path);
    RUN_TEST(catmull_rom_should_fail_cleanly_out_of_memory);
    RUN_TEST(flatten_should_respect_tolerance);
    RUN_TEST(flatten_should_split_pieces_and_measure);
    RUN_TEST(cubic_point_tangent_and_split_should_agree);
    RUN_TEST(measure_should_match_fine_flattening_on_random_cubics);
    RUN_TEST(measure_should_skip_moves_and_survive_nan);
    RUN_TEST(generate_stats_should_measure_the_arc);
    return UNITY_END();
}
