/* Echo: offset rings at spacing d from the margin in, on every shape (holes
 * and concave outlines too), joined into one path that stays inside, does
 * not cross itself and leaves no gap as wide as d; deterministic, errors,
 * allocation failures, no leaks. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "quiltc.h"
#include "testalloc.h"
#include "testgeom.h"
#include "unity.h"
#include "../src/deco/deco_internal.h"

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

enum { R_RECT, R_CIRCLE, R_STAR, R_HEART, R_HEXAGON, R_HOLE, R_HOLES, R_U, R_COUNT };

static const char *const region_names[R_COUNT] = {"rect", "circle", "star", "heart",
                                                   "hexagon", "hole", "holes", "U"};

/* Shapes about 200 mm across; R_HOLE: a square with a square hole; R_HOLES:
 * a rectangle with a square and a slanted hole; R_U: a concave U. */
static void make_region(int kind, qc_region *r)
{
    static const char *const specs[] = {"rect:200x150", "circle:200", "star:220", "heart:200",
                                        "hexagon:200"};
    qc_vec2 ring[8];

    memset(r, 0, sizeof *r);
    if (kind <= R_HEXAGON) {
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_shape(&ctx, specs[kind], 1.0, r));
        return;
    }
    if (kind == R_U) {
        ring[0] = v2(0, 0); ring[1] = v2(200, 0); ring[2] = v2(200, 160); ring[3] = v2(140, 160);
        ring[4] = v2(140, 60); ring[5] = v2(60, 60); ring[6] = v2(60, 160); ring[7] = v2(0, 160);
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, r, ring, 8));
    } else {
        ring[0] = v2(0, 0); ring[1] = v2(200, 0); ring[2] = v2(200, 200); ring[3] = v2(0, 200);
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, r, ring, 4));
        if (kind == R_HOLE) {
            ring[0] = v2(70, 70); ring[1] = v2(130, 70); ring[2] = v2(130, 130); ring[3] = v2(70, 130);
            TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, r, ring, 4));
        } else {
            ring[0] = v2(30, 30); ring[1] = v2(90, 30); ring[2] = v2(90, 90); ring[3] = v2(30, 90);
            TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, r, ring, 4));
            ring[0] = v2(110, 120); ring[1] = v2(170, 110); ring[2] = v2(140, 170);
            TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, r, ring, 3));
        }
    }
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_normalize(&ctx, r));
}

static qc_params params(double d, double margin, int join)
{
    qc_params p, r;

    memset(&p, 0, sizeof p);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "family", QC_FAMILY_ECHO));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "spacing", d));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "margin", margin));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "echo-join", join));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_resolve(&ctx, &p, &r));
    return r;
}

static int run_echo(const qc_region *r, const qc_params *p, qc_path *out, qc_stats *st)
{
    qc_skeleton sk;

    memset(&sk, 0, sizeof sk);
    memset(out, 0, sizeof *out);
    if (st != NULL)
        memset(st, 0, sizeof *st);
    return qc_deco_echo(&ctx, r, p, &sk, NULL, out, st);
}

/* The path is one MOVE then LINEs only. */
static void assert_one_polyline(const qc_path *path)
{
    size_t c;

    TEST_ASSERT_GREATER_THAN(2, path->ncmd);
    TEST_ASSERT_EQUAL_INT(QC_PATH_MOVE, path->cmd[0]);
    for (c = 1; c < path->ncmd; c++)
        TEST_ASSERT_EQUAL_INT(QC_PATH_LINE, path->cmd[c]);
    TEST_ASSERT_EQUAL_UINT(1, qc_path_pieces(path));
    TEST_ASSERT_EQUAL_UINT(path->ncmd, path->npt);
}

/* Distance of x to the nearest level margin + k d. */
static double level_error(double x, double margin, double d, int *k)
{
    double f = floor((x - margin) / d + 0.5);

    *k = (int)f;
    return fabs(x - (margin + f * d));
}

static void echo_should_be_one_path_inside_at_the_margin(void)
{
    int kind, join;

    for (kind = 0; kind < R_COUNT; kind++)
        for (join = QC_ECHO_SPIRAL; join <= QC_ECHO_RINGS; join++) {
            qc_region r;
            qc_params p = params(10, 3, join);
            qc_path out;
            size_t i;

            make_region(kind, &r);
            TEST_ASSERT_EQUAL_INT_MESSAGE(QC_OK, run_echo(&r, &p, &out, NULL), region_names[kind]);
            assert_one_polyline(&out);
            for (i = 0; i < out.npt; i++) {
                TEST_ASSERT_TRUE_MESSAGE(qc_region_contains(&r, out.pt[i]), region_names[kind]);
                TEST_ASSERT_GREATER_OR_EQUAL_DOUBLE_MESSAGE(3.0 - 1e-6,
                                                            qc_region_boundary_distance(&r, out.pt[i]),
                                                            region_names[kind]);
            }
            qc_path_free(&ctx, &out);
            qc_region_free(&ctx, &r);
        }
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

/* Every ring vertex lies on its level and every chord within 2% of d. */
static void echo_rings_should_keep_spacing(void)
{
    int kind;
    const double d = 10, m = 3;

    for (kind = 0; kind < R_COUNT; kind++) {
        qc_region r;
        qc__sdf s;
        qc__rings rings;
        qc_vec2 at;
        size_t k, levels = 0;

        make_region(kind, &r);
        memset(&rings, 0, sizeof rings);
        TEST_ASSERT_EQUAL_INT(QC_OK, qc__sdf_build(&ctx, &r, d / 4, &s));
        levels = (size_t)floor((qc__sdf_max(&s, &at) - m) / d) + 1;
        TEST_ASSERT_EQUAL_INT(QC_OK, qc__sdf_rings(&ctx, &s, m, d, levels, &rings));
        TEST_ASSERT_GREATER_OR_EQUAL(levels, rings.end.n);
        for (k = 0; k < rings.end.n; k++) {
            size_t b = k ? rings.end.i[k - 1] : 0, e = rings.end.i[k], i;
            double level = m + d * rings.level.i[k];

            TEST_ASSERT_GREATER_OR_EQUAL(3, e - b);
            for (i = b; i < e; i++) {
                qc_vec2 a = rings.pts.v[i], c = rings.pts.v[i + 1 < e ? i + 1 : b];
                int q;

                TEST_ASSERT_DOUBLE_WITHIN(1e-6, level, qc_region_boundary_distance(&r, a));
                for (q = 1; q < 4; q++) {
                    qc_vec2 x = v2(a.x + (c.x - a.x) * q / 4.0, a.y + (c.y - a.y) * q / 4.0);
                    TEST_ASSERT_DOUBLE_WITHIN(0.02 * d, level, qc_region_boundary_distance(&r, x));
                }
            }
        }
        qc__rings_free(&ctx, &rings);
        qc__sdf_free(&ctx, &s);
        qc_region_free(&ctx, &r);
    }
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

/* The distance grid's exact query (each edge's geometry cached once) gives
 * the boundary distance, signed by the side, at every grid node and at
 * points between them, on every shape, also far from the origin. */
static void sdf_exact_should_match_the_boundary_distance(void)
{
    int kind, far;

    for (kind = 0; kind < R_COUNT; kind++)
        for (far = 0; far < 2; far++) {
            qc_region r;
            qc__sdf s;
            size_t i, j, n = 0;

            make_region(kind, &r);
            if (far) /* coordinates of 10^5 mm: the cache keeps the same arithmetic */
                for (i = 0; i < r.nv; i++)
                    r.v[i] = v2(r.v[i].x + 1e5, r.v[i].y - 7e4);
            TEST_ASSERT_EQUAL_INT(QC_OK, qc__sdf_build(&ctx, &r, 2.5, &s));
            for (j = 0; j + 1 < s.ny; j += 3)
                for (i = 0; i + 1 < s.nx; i += 3) {
                    qc_vec2 p = v2(s.x0 + ((double)i + 0.37) * s.h, s.y0 + ((double)j + 0.61) * s.h);
                    double want = qc_region_boundary_distance(&r, p);
                    double got = qc__sdf_exact(&s, p, NULL);

                    TEST_ASSERT_DOUBLE_WITHIN(1e-9 * (1.0 + 1e5), want, fabs(got));
                    if (want > 1e-6)
                        TEST_ASSERT_EQUAL_INT(qc_region_contains(&r, p), got > 0.0);
                    n++;
                }
            TEST_ASSERT_GREATER_THAN(100, n);
            qc__sdf_free(&ctx, &s);
            qc_region_free(&ctx, &r);
        }
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

/* Whether path vertex i lies on a level margin + k d, k >= 0. */
static int on_level(const qc_region *r, const qc_path *out, size_t i, double margin, double d)
{
    int k;
    double e = level_error(qc_region_boundary_distance(r, out->pt[i]), margin, d, &k);

    return e < 1e-6 && k >= 0;
}

/* The centre of the cap whose vertices are pt[b..e): the midpoint of the
 * two farthest apart, which must be its diameter 0.1 d * 2 apart. */
static qc_vec2 cap_centre(const qc_vec2 *pt, size_t b, size_t e, double d)
{
    size_t i, k, bi = b, bk = b;
    double far = -1;
    qc_vec2 c;

    for (i = b; i < e; i++)
        for (k = i + 1; k < e; k++)
            if (qc_hypot(pt[i].x - pt[k].x, pt[i].y - pt[k].y) > far) {
                far = qc_hypot(pt[i].x - pt[k].x, pt[i].y - pt[k].y);
                bi = i;
                bk = k;
            }
    TEST_ASSERT_DOUBLE_WITHIN(1e-6, 0.2 * d, far);
    c.x = 0.5 * (pt[bi].x + pt[bk].x);
    c.y = 0.5 * (pt[bi].y + pt[bk].y);
    return c;
}

/* Every vertex of the joined path is a ring vertex: on a level, but for
 * the caps (shared_contour_caps.c): an octagon 0.1 d round a peak at least
 * 0.97 d from every vertex on a level, sewn whole by a spur (9 vertices in
 * a row, the first twice) or cut by a ladder (7). */
static void echo_path_vertices_should_lie_on_levels(void)
{
    int kind, join;
    const double d = 8, m = 2;

    for (kind = 0; kind < R_COUNT; kind++)
        for (join = QC_ECHO_SPIRAL; join <= QC_ECHO_RINGS; join++) {
            qc_region r;
            qc_params p = params(d, m, join);
            qc_path out;
            size_t i = 0, q, on = 0;

            make_region(kind, &r);
            TEST_ASSERT_EQUAL_INT(QC_OK, run_echo(&r, &p, &out, NULL));
            while (i < out.npt) {
                size_t b = i;
                qc_vec2 c;
                if (on_level(&r, &out, i, m, d)) {
                    i++;
                    on++;
                    continue;
                }
                while (i < out.npt && !on_level(&r, &out, i, m, d))
                    i++;
                TEST_ASSERT_TRUE_MESSAGE(i - b == 7 || i - b == 9, region_names[kind]);
                c = cap_centre(out.pt, b, i, d);
                for (q = b; q < i; q++)
                    TEST_ASSERT_DOUBLE_WITHIN(1e-6, 0.1 * d,
                                              qc_hypot(out.pt[q].x - c.x, out.pt[q].y - c.y));
                for (q = 0; q < out.npt; q++)
                    if (on_level(&r, &out, q, m, d))
                        TEST_ASSERT_GREATER_OR_EQUAL_DOUBLE(0.97 * d - 1e-6,
                                                            qc_hypot(out.pt[q].x - c.x,
                                                                     out.pt[q].y - c.y));
            }
            TEST_ASSERT_GREATER_THAN(out.npt / 2, on);
            qc_path_free(&ctx, &out);
            qc_region_free(&ctx, &r);
        }
}

static void echo_should_not_cross_itself(void)
{
    int kind, join;

    for (kind = 0; kind < R_COUNT; kind++)
        for (join = QC_ECHO_SPIRAL; join <= QC_ECHO_RINGS; join++) {
            double d;
            for (d = 6; d <= 24; d *= 2) {
                qc_region r;
                qc_params p = params(d, 0.3 * d, join);
                qc_path out;
                qc_stats st;
                size_t n = 1;

                make_region(kind, &r);
                TEST_ASSERT_EQUAL_INT(QC_OK, run_echo(&r, &p, &out, &st));
                TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_self_crossings(&ctx, out.pt, out.npt, 0, &n));
                TEST_ASSERT_EQUAL_UINT_MESSAGE(0, n, region_names[kind]);
                TEST_ASSERT_EQUAL_UINT_MESSAGE(0, st.joins_unfixed, region_names[kind]);
                qc_path_free(&ctx, &out);
                qc_region_free(&ctx, &r);
            }
        }
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

/* The largest empty circle: under d wherever every ring is traced; a
 * ridge's sliver above a level that is thinner than the grid (h = d/4) has
 * no ring, which can leave d + h/sqrt2 (the heart's saddle at d = 12). */
static void echo_gap_should_stay_under_d(void)
{
    int kind;
    double d;

    for (kind = 0; kind < R_COUNT; kind++)
        for (d = 7; d < 26; d *= 1.4) {
            qc_region r;
            qc_params p = params(d, 0.3 * d, QC_ECHO_RINGS);
            qc_path out;
            qc_stats st;
            double g;

            make_region(kind, &r);
            TEST_ASSERT_EQUAL_INT(QC_OK, run_echo(&r, &p, &out, &st));
            g = qc_largest_gap(&ctx, &r, out.pt, out.npt, d / 24, NULL);
            TEST_ASSERT_GREATER_THAN_DOUBLE(0.0, g);
            TEST_ASSERT_LESS_THAN_DOUBLE_MESSAGE((1.0 + 0.25 / sqrt(2.0)) * d, g, region_names[kind]);
            if (kind == R_HOLE || kind == R_HOLES || kind == R_CIRCLE)
                TEST_ASSERT_LESS_THAN_DOUBLE_MESSAGE(d, g, region_names[kind]);
            /* the stat: another lower bound, within 2.2 d/6 */
            TEST_ASSERT_GREATER_THAN_DOUBLE(0.0, st.largest_gap_mm);
            TEST_ASSERT_DOUBLE_WITHIN(2.2 * d / 6 + 2.2 * d / 24, g, st.largest_gap_mm);
            qc_path_free(&ctx, &out);
            qc_region_free(&ctx, &r);
        }
}

/* A circle: rings of radius R - m - k d; the path is their sum plus joins. */
static void echo_circle_length_should_match_the_rings(void)
{
    int join;

    for (join = QC_ECHO_SPIRAL; join <= QC_ECHO_RINGS; join++) {
        qc_region r;
        qc_params p = params(10, 3, join);
        qc_path out;
        qc_bbox b;
        double R, rk, sum = 0.0, len;
        int k = 0;

        make_region(R_CIRCLE, &r);
        b = qc_region_bbox(&r);
        R = qc_region_boundary_distance(&r, v2(0.5 * (b.min.x + b.max.x),
                                               0.5 * (b.min.y + b.max.y)));
        for (rk = R - 3; rk > 0; rk -= 10, k++)
            sum += 2 * QC_PI * rk;
        TEST_ASSERT_EQUAL_INT(10, k);
        TEST_ASSERT_EQUAL_INT(QC_OK, run_echo(&r, &p, &out, NULL));
        len = qc_curve_length(&out, 0.01);
        TEST_ASSERT_DOUBLE_WITHIN(0.10 * sum, sum, len);
        qc_path_free(&ctx, &out);
        qc_region_free(&ctx, &r);
    }
}

/* Spiral: the level never goes back out; rings: a closed loop. */
static void echo_joins_should_spiral_in_or_close(void)
{
    qc_region r;
    qc_params sp = params(10, 3, QC_ECHO_SPIRAL), rp = params(10, 3, QC_ECHO_RINGS);
    qc_path out;
    size_t i;
    int last = 0, k;

    make_region(R_CIRCLE, &r);
    TEST_ASSERT_EQUAL_INT(QC_OK, run_echo(&r, &sp, &out, NULL));
    for (i = 0; i < out.npt; i++) {
        level_error(qc_region_boundary_distance(&r, out.pt[i]), 3, 10, &k);
        TEST_ASSERT_GREATER_OR_EQUAL(last, k);
        last = k;
    }
    TEST_ASSERT_EQUAL_INT(9, last);
    qc_path_free(&ctx, &out);
    TEST_ASSERT_EQUAL_INT(QC_OK, run_echo(&r, &rp, &out, NULL));
    TEST_ASSERT_EQUAL_MEMORY(&out.pt[0], &out.pt[out.npt - 1], sizeof out.pt[0]);
    qc_path_free(&ctx, &out);
    qc_region_free(&ctx, &r);
}

static void echo_should_start_near_the_start_point(void)
{
    qc_region r;
    qc_params p, rp;
    qc_path out;

    make_region(R_RECT, &r);
    memset(&p, 0, sizeof p);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "family", QC_FAMILY_ECHO));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "spacing", 10));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "margin", 3));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "echo-join", QC_ECHO_RINGS));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "start-x", 100));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "start-y", 150));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_resolve(&ctx, &p, &rp));
    TEST_ASSERT_EQUAL_INT(QC_OK, run_echo(&r, &rp, &out, NULL));
    TEST_ASSERT_DOUBLE_WITHIN(1.5, 100.0, out.pt[0].x);
    TEST_ASSERT_DOUBLE_WITHIN(1e-6, 147.0, out.pt[0].y);
    qc_path_free(&ctx, &out);
    qc_region_free(&ctx, &r);
}

static void echo_should_be_deterministic(void)
{
    int join;

    for (join = QC_ECHO_SPIRAL; join <= QC_ECHO_RINGS; join++) {
        qc_region r;
        qc_params p = params(9, 3, join);
        qc_path a, b;

        make_region(R_HOLES, &r);
        TEST_ASSERT_EQUAL_INT(QC_OK, run_echo(&r, &p, &a, NULL));
        TEST_ASSERT_EQUAL_INT(QC_OK, run_echo(&r, &p, &b, NULL));
        TEST_ASSERT_EQUAL_UINT(a.npt, b.npt);
        TEST_ASSERT_EQUAL_MEMORY(a.pt, b.pt, a.npt * sizeof *a.pt);
        qc_path_free(&ctx, &a);
        qc_path_free(&ctx, &b);
        qc_region_free(&ctx, &r);
    }
}

/* Through qc_generate: one piece, the gap in the stats. */
static void echo_should_run_through_generate(void)
{
    qc_region r;
    qc_params p;
    qc_result res;

    make_region(R_HOLE, &r);
    memset(&p, 0, sizeof p);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "family", QC_FAMILY_ECHO));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "spacing", 10));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_generate(&ctx, &r, &p, NULL, NULL, &res));
    TEST_ASSERT_EQUAL_UINT(1, res.stats.pieces);
    TEST_ASSERT_EQUAL_UINT(0, res.points.n);
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 3.0, res.params.margin); /* default 0.3 d */
    TEST_ASSERT_GREATER_THAN_DOUBLE(0.0, res.stats.largest_gap_mm);
    TEST_ASSERT_LESS_THAN_DOUBLE(10.0, res.stats.largest_gap_mm);
    TEST_ASSERT_GREATER_THAN_DOUBLE(1000.0, res.stats.length_mm);
    qc_result_free(&ctx, &res);
    qc_region_free(&ctx, &r);
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

static void echo_should_report_errors(void)
{
    qc_region r, empty;
    qc_params p = params(10, 3, QC_ECHO_RINGS);
    qc_path out;

    make_region(R_RECT, &r);
    memset(&empty, 0, sizeof empty);
    TEST_ASSERT_EQUAL_INT(QC_EEMPTY, run_echo(&empty, &p, &out, NULL));
    TEST_ASSERT_TRUE(strstr(qc_errmsg(&ctx), "no outline") != NULL);
    p.margin = 80; /* the rectangle reaches 75 mm from its boundary */
    TEST_ASSERT_EQUAL_INT(QC_EEMPTY, run_echo(&r, &p, &out, NULL));
    TEST_ASSERT_TRUE(strstr(qc_errmsg(&ctx), "margin of 80 mm") != NULL);
    TEST_ASSERT_EQUAL_UINT(0, out.ncmd);
    p.margin = 3;
    p.spacing = 0;
    TEST_ASSERT_EQUAL_INT(QC_ERANGE, run_echo(&r, &p, &out, NULL));
    TEST_ASSERT_TRUE(strstr(qc_errmsg(&ctx), "spacing 0 mm") != NULL);
    qc_region_free(&ctx, &r);
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

/* The distance grid's size is decided before it is built: a quilter's
 * largest block (3.5 m at d = 2 mm) and the bench's 10 m block at d = 10 mm
 * fit within the d / 2 grid echo accepts; a 100 m block at 0.5 mm does not. */
static void echo_grid_should_admit_a_quilters_largest_block(void)
{
    static const struct {
        const char *spec;
        double d;
        int fits;
    } cases[] = {{"square:3500", 2.0, 1}, {"square:10000", 10.0, 1}, {"square:100000", 0.5, 0}};
    size_t k;

    for (k = 0; k < sizeof cases / sizeof *cases; k++) {
        qc_region r = {0};
        double h;

        TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_shape(&ctx, cases[k].spec, 1.0, &r));
        h = qc__sdf_step(&r, cases[k].d / 4);
        TEST_ASSERT_TRUE(h >= cases[k].d / 4);
        TEST_ASSERT_EQUAL_INT_MESSAGE(cases[k].fits, h <= cases[k].d / 2, cases[k].spec);
        qc_region_free(&ctx, &r);
    }
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

/* A zero margin puts the outermost ring on the outline. */
static void echo_zero_margin_should_follow_the_outline(void)
{
    qc_region r;
    qc_params p = params(10, 0, QC_ECHO_RINGS);
    qc_path out;
    size_t i;
    double lo = HUGE_VAL;

    make_region(R_HEXAGON, &r);
    TEST_ASSERT_EQUAL_INT(QC_OK, run_echo(&r, &p, &out, NULL));
    for (i = 0; i < out.npt; i++)
        lo = fmin(lo, qc_region_boundary_distance(&r, out.pt[i]));
    TEST_ASSERT_DOUBLE_WITHIN(0.02, 0.0, lo);
    qc_path_free(&ctx, &out);
    qc_region_free(&ctx, &r);
}

static void echo_should_survive_allocation_failures(void)
{
    int join;

    for (join = QC_ECHO_SPIRAL; join <= QC_ECHO_RINGS; join++) {
        qc_region r;
        qc_params p = params(15, 4, join);
        size_t k, base;
        int rc = QC_ENOMEM;

        make_region(R_HOLES, &r);
        base = ta.live_blocks;
        for (k = 1; rc == QC_ENOMEM && k < 5000; k++) {
            qc_path out;
            qc_stats st;

            ta.allocs = 0;
            ta.fail_at = k;
            rc = run_echo(&r, &p, &out, &st);
            ta.fail_at = 0;
            if (rc == QC_ENOMEM)
                TEST_ASSERT_EQUAL_UINT(0, out.ncmd);
            qc_path_free(&ctx, &out);
            TEST_ASSERT_EQUAL_UINT(base, ta.live_blocks);
        }
        TEST_ASSERT_EQUAL_INT(QC_OK, rc);
        TEST_ASSERT_GREATER_THAN(10, k);
        TEST_ASSERT_FALSE(ta.size_mismatch);
        qc_region_free(&ctx, &r);
    }
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(echo_should_be_one_path_inside_at_the_margin);
    RUN_TEST(echo_rings_should_keep_spacing);
    RUN_TEST(echo_path_vertices_should_lie_on_levels);
    RUN_TEST(echo_should_not_cross_itself);
    RUN_TEST(echo_gap_should_stay_under_d);
    RUN_TEST(echo_circle_length_should_match_the_rings);
    RUN_TEST(echo_joins_should_spiral_in_or_close);
    RUN_TEST(echo_should_start_near_the_start_point);
    RUN_TEST(echo_should_be_deterministic);
    RUN_TEST(echo_should_run_through_generate);
    RUN_TEST(echo_should_report_errors);
    RUN_TEST(echo_grid_should_admit_a_quilters_largest_block);
    RUN_TEST(sdf_exact_should_match_the_boundary_distance);
    RUN_TEST(echo_zero_margin_should_follow_the_outline);
    RUN_TEST(echo_should_survive_allocation_failures);
    return UNITY_END();
}
