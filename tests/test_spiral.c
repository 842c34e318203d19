/* Spiral along the offset rings: one path inside the margin that never
 * crosses itself, never sews a place more than twice and runs over an
 * earlier pass nowhere (issue 16: it was 92% on a 0.75 in border, 43
 * passes); Archimedean turns d apart, Fermat turns adding pi d^2 each; it
 * starts near the farthest point or the given start; no gap much wider than
 * d; deterministic, errors, allocation failures, no leaks. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "quiltc.h"
#include "retrace.h"
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

enum { R_RECT, R_CIRCLE, R_STAR, R_HEART, R_HEXAGON, R_HOLE, R_HOLES, R_U, R_COUNT };

static const char *const region_names[R_COUNT] = {"rect", "circle", "star", "heart",
                                                   "hexagon", "hole", "holes", "U"};

/* Shapes size mm across (as in test_echo at size 200). */
static void make_region(int kind, double size, qc_region *r)
{
    static const char *const specs[] = {"rect:%gx%g", "circle:%g", "star:%g", "heart:%g",
                                        "hexagon:%g"};
    const double f = size / 200.0;
    qc_vec2 ring[8];
    char spec[64];

    memset(r, 0, sizeof *r);
    if (kind <= R_HEXAGON) {
        if (kind == R_RECT)
            sprintf(spec, specs[kind], size, 0.75 * size);
        else
            sprintf(spec, specs[kind], kind == R_STAR ? 1.1 * size : size);
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_shape(&ctx, spec, 1.0, r));
        return;
    }
    if (kind == R_U) {
        ring[0] = v2(0, 0); ring[1] = v2(200 * f, 0); ring[2] = v2(200 * f, 160 * f);
        ring[3] = v2(140 * f, 160 * f); ring[4] = v2(140 * f, 60 * f); ring[5] = v2(60 * f, 60 * f);
        ring[6] = v2(60 * f, 160 * f); ring[7] = v2(0, 160 * f);
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, r, ring, 8));
    } else {
        ring[0] = v2(0, 0); ring[1] = v2(200 * f, 0); ring[2] = v2(200 * f, 200 * f);
        ring[3] = v2(0, 200 * f);
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, r, ring, 4));
        if (kind == R_HOLE) {
            ring[0] = v2(70 * f, 70 * f); ring[1] = v2(130 * f, 70 * f);
            ring[2] = v2(130 * f, 130 * f); ring[3] = v2(70 * f, 130 * f);
            TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, r, ring, 4));
        } else {
            ring[0] = v2(30 * f, 30 * f); ring[1] = v2(90 * f, 30 * f);
            ring[2] = v2(90 * f, 90 * f); ring[3] = v2(30 * f, 90 * f);
            TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, r, ring, 4));
            ring[0] = v2(110 * f, 120 * f); ring[1] = v2(170 * f, 110 * f);
            ring[2] = v2(140 * f, 170 * f);
            TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, r, ring, 3));
        }
    }
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_normalize(&ctx, r));
}

static qc_params params(double d, double margin, int kind)
{
    qc_params p, r;

    memset(&p, 0, sizeof p);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "family", QC_FAMILY_SPIRAL));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "spacing", d));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "margin", margin));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "spiral", kind));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_resolve(&ctx, &p, &r));
    return r;
}

static qc_params params_at(double d, double margin, int kind, qc_vec2 start)
{
    qc_params p, r;

    memset(&p, 0, sizeof p);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "family", QC_FAMILY_SPIRAL));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "spacing", d));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "margin", margin));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "spiral", kind));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "start-x", start.x));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "start-y", start.y));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_resolve(&ctx, &p, &r));
    return r;
}

static int run_spiral(const qc_region *r, const qc_params *p, qc_path *out, qc_stats *st)
{
    qc_skeleton sk;

    memset(&sk, 0, sizeof sk);
    memset(out, 0, sizeof *out);
    if (st != NULL)
        memset(st, 0, sizeof *st);
    return qc_deco_spiral(&ctx, r, p, &sk, NULL, out, st);
}

static void assert_one_polyline(const qc_path *path)
{
    size_t c;

    TEST_ASSERT_GREATER_THAN(2, path->ncmd);
    TEST_ASSERT_EQUAL_INT(QC_PATH_MOVE, path->cmd[0]);
    for (c = 1; c < path->ncmd; c++)
        TEST_ASSERT_EQUAL_INT(QC_PATH_LINE, path->cmd[c]);
    TEST_ASSERT_EQUAL_UINT(1, qc_path_pieces(path));
}

/* Radii (from c) where the path crosses the ray from c at angle a, sorted;
 * returns the count. */
static size_t ray_crossings(const qc_path *path, qc_vec2 c, double a, double *r, size_t max)
{
    qc_vec2 u = v2(cos(a), sin(a));
    size_t i, n = 0, k;

    for (i = 0; i + 1 < path->npt; i++) {
        qc_vec2 p = path->pt[i], q = path->pt[i + 1];
        double px = p.x - c.x, py = p.y - c.y, qx = q.x - c.x, qy = q.y - c.y;
        double sp = u.x * py - u.y * px, sq = u.x * qy - u.y * qx, t, rad;

        if ((sp > 0) == (sq > 0) || sp == sq)
            continue;
        t = sp / (sp - sq);
        rad = (px + t * (qx - px)) * u.x + (py + t * (qy - py)) * u.y;
        if (rad <= 0 || n == max)
            continue;
        for (k = n++; k > 0 && r[k - 1] > rad; k--)
            r[k] = r[k - 1];
        r[k] = rad;
    }
    return n;
}

static void spiral_should_be_one_path_inside_at_the_margin(void)
{
    int kind, sk;

    for (kind = 0; kind < R_COUNT; kind++)
        for (sk = QC_SPIRAL_ARCHIMEDEAN; sk <= QC_SPIRAL_FERMAT; sk++) {
            qc_region r;
            double d = sk == QC_SPIRAL_FERMAT ? 8 : 10; /* fermat: 100 mm regions */
            qc_params p = params(d, 3, sk);
            qc_path out;
            size_t i;

            make_region(kind, sk == QC_SPIRAL_FERMAT ? 100 : 200, &r);
            TEST_ASSERT_EQUAL_INT_MESSAGE(QC_OK, run_spiral(&r, &p, &out, NULL), region_names[kind]);
            assert_one_polyline(&out);
            for (i = 0; i < out.npt; i++) { /* the rings' chords: within 0.2% d */
                TEST_ASSERT_TRUE_MESSAGE(qc_region_contains(&r, out.pt[i]), region_names[kind]);
                TEST_ASSERT_GREATER_OR_EQUAL_DOUBLE_MESSAGE(3.0 - 0.0025 * d,
                                                            qc_region_boundary_distance(&r, out.pt[i]),
                                                            region_names[kind]);
            }
            qc_path_free(&ctx, &out);
            qc_region_free(&ctx, &r);
        }
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

static void spiral_should_not_cross_itself(void)
{
    int kind, sk;

    for (kind = 0; kind < R_COUNT; kind++)
        for (sk = QC_SPIRAL_ARCHIMEDEAN; sk <= QC_SPIRAL_FERMAT; sk++) {
            qc_region r;
            qc_params p = params(sk == QC_SPIRAL_FERMAT ? 9 : 7, 2.5, sk);
            qc_path out;
            qc_stats st;
            size_t n = 1;

            make_region(kind, sk == QC_SPIRAL_FERMAT ? 120 : 200, &r);
            TEST_ASSERT_EQUAL_INT(QC_OK, run_spiral(&r, &p, &out, &st));
            TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_self_crossings(&ctx, out.pt, out.npt, 0, &n));
            TEST_ASSERT_EQUAL_UINT_MESSAGE(0, n, region_names[kind]);
            TEST_ASSERT_EQUAL_UINT(0, st.joins_unfixed);
            qc_path_free(&ctx, &out);
            qc_region_free(&ctx, &r);
        }
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

/* Issue 16: thread over an earlier pass (within 0.01 in of the path more
 * than 0.3 in back) on at most 0.1% of the path, at most 2 passes over a
 * spot, on every shape and on the 0.75 x 30 in border at 0.35 and 0.6 in. */
static void spiral_should_not_retrace(void)
{
    int kind, sk;

    for (kind = 0; kind <= R_COUNT; kind++)
        for (sk = QC_SPIRAL_ARCHIMEDEAN; sk <= QC_SPIRAL_FERMAT; sk++) {
            const char *name = kind < R_COUNT ? region_names[kind] : "border";
            double d = kind < R_COUNT ? 9.0 : (sk == QC_SPIRAL_FERMAT ? 0.6 : 0.35) * 25.4;
            qc_params p = params(d, 2.0, sk);
            qc_region r;
            qc_path out;
            double share = 1.0;
            size_t passes = 99, n = 1;

            if (kind < R_COUNT)
                make_region(kind, 150, &r);
            else
                TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_shape(&ctx, "rect:762x19.05", 1.0, &r));
            TEST_ASSERT_EQUAL_INT_MESSAGE(QC_OK, run_spiral(&r, &p, &out, NULL), name);
            TEST_ASSERT_EQUAL_INT(0, retrace_measure(out.pt, out.npt, NULL, 0, &share, &passes));
            TEST_ASSERT_LESS_OR_EQUAL_DOUBLE_MESSAGE(0.001, share, name);
            TEST_ASSERT_LESS_OR_EQUAL_MESSAGE(2, passes, name);
            TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_self_crossings(&ctx, out.pt, out.npt, 0, &n));
            TEST_ASSERT_EQUAL_UINT_MESSAGE(0, n, name);
            qc_path_free(&ctx, &out);
            qc_region_free(&ctx, &r);
        }
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

/* Started on the boundary (as a top enters a patch at a seam corner), the
 * spiral winds in on every other turn and back out between them, ending
 * exactly at the start: the line leaves by no link across its turns (one
 * crossed 8 turns on the sawtooth star). Still one polyline inside the
 * margin but for that last stitch out, crossing nowhere, at most 2 passes
 * and 5% retraced, no gap wider than the one-arm spiral's. Shapes whose
 * rings split (the U, the heart, holes) keep the one-arm spiral. */
static void spiral_should_wind_in_and_out_from_a_boundary_start(void)
{
    static const int nested[] = {R_RECT, R_CIRCLE, R_STAR, R_HEXAGON};
    const double d = 9.0;
    size_t k, i;

    for (k = 0; k < sizeof nested / sizeof nested[0]; k++) {
        const char *name = region_names[nested[k]];
        qc_params one_arm = params(d, 2.0, QC_SPIRAL_ARCHIMEDEAN), p;
        qc_region r;
        qc_path out, ref;
        qc_vec2 start;
        double share = 1.0, gap, ref_gap;
        size_t passes = 99, n = 1;

        make_region(nested[k], 150, &r);
        start = r.v[0]; /* a vertex of the outline */
        p = params_at(d, 2.0, QC_SPIRAL_ARCHIMEDEAN, start);
        TEST_ASSERT_EQUAL_INT_MESSAGE(QC_OK, run_spiral(&r, &p, &out, NULL), name);
        assert_one_polyline(&out);
        TEST_ASSERT_EQUAL_DOUBLE_MESSAGE(start.x, out.pt[out.npt - 1].x, name);
        TEST_ASSERT_EQUAL_DOUBLE_MESSAGE(start.y, out.pt[out.npt - 1].y, name);
        TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(0.05, 2.0, qc_region_boundary_distance(&r, out.pt[0]),
                                          name);
        for (i = 0; i + 1 < out.npt; i++)
            TEST_ASSERT_GREATER_OR_EQUAL_DOUBLE_MESSAGE(
                2.0 - 0.05, qc_region_boundary_distance(&r, out.pt[i]), name);
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_self_crossings(&ctx, out.pt, out.npt, 0, &n));
        TEST_ASSERT_EQUAL_UINT_MESSAGE(0, n, name);
        TEST_ASSERT_EQUAL_INT(0, retrace_measure(out.pt, out.npt, NULL, 0, &share, &passes));
        TEST_ASSERT_LESS_OR_EQUAL_DOUBLE_MESSAGE(0.05, share, name);
        TEST_ASSERT_LESS_OR_EQUAL_MESSAGE(2, passes, name);
        TEST_ASSERT_EQUAL_INT(QC_OK, run_spiral(&r, &one_arm, &ref, NULL));
        gap = qc_largest_gap(&ctx, &r, out.pt, out.npt, d / 6, NULL);
        ref_gap = qc_largest_gap(&ctx, &r, ref.pt, ref.npt, d / 6, NULL);
        TEST_ASSERT_LESS_OR_EQUAL_DOUBLE_MESSAGE(ref_gap + 0.05 * d, gap, name);
        qc_path_free(&ctx, &ref);
        qc_path_free(&ctx, &out);
        qc_region_free(&ctx, &r);
    }
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

/* Default centre: the point farthest from the boundary; the path starts on
 * the innermost ring, which lies within d of it. */
static void spiral_should_start_near_the_farthest_point(void)
{
    int kind;

    for (kind = 0; kind < R_COUNT; kind++) {
        qc_region r;
        qc_params p = params(10, 3, QC_SPIRAL_ARCHIMEDEAN);
        qc_path out;
        qc_vec2 c;
        double R;

        make_region(kind, 200, &r);
        R = qc_largest_gap(&ctx, &r, NULL, 0, 0.25, &c); /* the inscribed circle */
        TEST_ASSERT_GREATER_THAN_DOUBLE(0.0, R);
        TEST_ASSERT_EQUAL_INT(QC_OK, run_spiral(&r, &p, &out, NULL));
        TEST_ASSERT_GREATER_OR_EQUAL_DOUBLE_MESSAGE(R - 10.0 - 1.0,
                                                    qc_region_boundary_distance(&r, out.pt[0]),
                                                    region_names[kind]);
        qc_path_free(&ctx, &out);
        qc_region_free(&ctx, &r);
    }
}

/* Archimedean: along any ray from the centre of a circle the turns are d
 * apart, the outermost at the margin (a ray through the short gap where a
 * turn steps on to the next sees one turn fewer there); the path is about
 * the rings' sum. */
static void archimedean_turns_should_be_d_apart(void)
{
    qc_region r;
    qc_vec2 c = v2(100, 100);
    qc_params p = params(10, 3, QC_SPIRAL_ARCHIMEDEAN);
    qc_path out;
    double rad[64], a, len = 0.0, R = 100.0 - 3.0;
    int rays_even = 0, rays = 0;

    make_region(R_CIRCLE, 200, &r);
    TEST_ASSERT_EQUAL_INT(QC_OK, run_spiral(&r, &p, &out, NULL));
    for (a = 0.5; a < 6.2; a += 0.7, rays++) {
        size_t n = ray_crossings(&out, c, a, rad, 64), k;
        int even = 1;
        TEST_ASSERT_GREATER_OR_EQUAL(8, n);
        TEST_ASSERT_DOUBLE_WITHIN(0.01 * 10, R, rad[n - 1]);
        for (k = 1; k < n; k++)
            if (fabs(rad[k] - rad[k - 1] - 10.0) > 0.01 * 10) {
                TEST_ASSERT_LESS_THAN_DOUBLE(2.0 * 10.0 + 0.1, rad[k] - rad[k - 1]);
                even = 0;
            }
        rays_even += even;
    }
    TEST_ASSERT_GREATER_OR_EQUAL(rays - 2, rays_even);
    for (a = R; a > 0; a -= 10)
        len += 2 * QC_PI * a;
    TEST_ASSERT_DOUBLE_WITHIN(0.03 * len, len, qc_curve_length(&out, 0.01));
    qc_path_free(&ctx, &out);
    qc_region_free(&ctx, &r);
}

/* Fermat: the k-th turn in from the outermost (the margin, 47 mm from the
 * centre) lies s_k = d (u - sqrt(u^2 - k)) further in, so on a disc every
 * turn adds pi d^2: every crossing of a ray from the centre lies where
 * 2 u s / d - (s / d)^2 is a whole k, u fitted from the second turn (a ray
 * through the short gap where a turn steps on sees one turn fewer), so
 * the turns close in outward. */
static void fermat_turns_should_add_equal_areas(void)
{
    qc_region r;
    qc_vec2 c = v2(50, 50);
    qc_params p = params(10, 3, QC_SPIRAL_FERMAT);
    qc_path out;
    double rad[128], a, d = 10.0;

    make_region(R_CIRCLE, 100, &r);
    TEST_ASSERT_EQUAL_INT(QC_OK, run_spiral(&r, &p, &out, NULL));
    for (a = 0.2; a < 6.2; a += 0.9) {
        size_t n = ray_crossings(&out, c, a, rad, 128), k;
        double s1, u, last = 0.0;

        TEST_ASSERT_GREATER_OR_EQUAL(20, n);
        TEST_ASSERT_DOUBLE_WITHIN(0.1, 47.0, rad[n - 1]);
        TEST_ASSERT_LESS_OR_EQUAL_DOUBLE(d + 0.25 * d, rad[0]); /* d + the grid */
        s1 = (47.0 - rad[n - 2]) / d;
        u = (1.0 + s1 * s1) / (2.0 * s1);
        for (k = n - 1; k-- > 0;) {
            double s = (47.0 - rad[k]) / d, kk = 2.0 * u * s - s * s, K = floor(kk + 0.5);
            TEST_ASSERT_DOUBLE_WITHIN(0.05 + 0.02 * K, K, kk);
            TEST_ASSERT_GREATER_THAN_DOUBLE(last, K);
            last = K;
            TEST_ASSERT_LESS_THAN_DOUBLE(2.0 * d, rad[k + 1] - rad[k]);
        }
    }
    qc_path_free(&ctx, &out);
    qc_region_free(&ctx, &r);
}

/* A start outside the region: the spiral begins on the ring nearest it. */
static void spiral_should_start_anywhere(void)
{
    qc_region r;
    qc_params p = params_at(10, 3, QC_SPIRAL_ARCHIMEDEAN, v2(-40, 100));
    qc_path out;
    size_t i;

    make_region(R_HOLE, 200, &r);
    TEST_ASSERT_EQUAL_INT(QC_OK, run_spiral(&r, &p, &out, NULL));
    assert_one_polyline(&out);
    TEST_ASSERT_DOUBLE_WITHIN(0.025, 3.0, qc_region_boundary_distance(&r, out.pt[0]));
    TEST_ASSERT_LESS_THAN_DOUBLE(10.0, out.pt[0].x); /* entered on the left */
    for (i = 0; i < out.npt; i++)
        TEST_ASSERT_GREATER_OR_EQUAL_DOUBLE(3.0 - 0.025, qc_region_boundary_distance(&r, out.pt[i]));
    TEST_ASSERT_LESS_THAN_DOUBLE(10.0, qc_largest_gap(&ctx, &r, out.pt, out.npt, 10.0 / 24, NULL));
    qc_path_free(&ctx, &out);
    qc_region_free(&ctx, &r);
}

/* No gap much wider than d (as echo: corners of a level set leave up to
 * d (1 + 0.25 / sqrt 2)). */
static void spiral_gap_should_stay_near_d(void)
{
    int kind, sk;

    for (kind = 0; kind < R_COUNT; kind++)
        for (sk = QC_SPIRAL_ARCHIMEDEAN; sk <= QC_SPIRAL_FERMAT; sk++) {
            qc_region r;
            double d = 12;
            qc_params p = params(d, 0.3 * d, sk);
            qc_path out;
            qc_stats st;
            double g;

            make_region(kind, sk == QC_SPIRAL_FERMAT ? 120 : 200, &r);
            TEST_ASSERT_EQUAL_INT(QC_OK, run_spiral(&r, &p, &out, &st));
            g = qc_largest_gap(&ctx, &r, out.pt, out.npt, d / 24, NULL);
            TEST_ASSERT_GREATER_THAN_DOUBLE(0.0, g);
            TEST_ASSERT_LESS_THAN_DOUBLE_MESSAGE((1.0 + 0.25 / sqrt(2.0)) * d, g, region_names[kind]);
            TEST_ASSERT_GREATER_THAN_DOUBLE(0.0, st.largest_gap_mm);
            TEST_ASSERT_DOUBLE_WITHIN(2.2 * d / 6 + 2.2 * d / 24, g, st.largest_gap_mm);
            qc_path_free(&ctx, &out);
            qc_region_free(&ctx, &r);
        }
}

static void spiral_should_be_deterministic(void)
{
    int sk;

    for (sk = QC_SPIRAL_ARCHIMEDEAN; sk <= QC_SPIRAL_FERMAT; sk++) {
        qc_region r;
        qc_params p = params(9, 3, sk);
        qc_path a, b;

        make_region(R_HOLES, 120, &r);
        TEST_ASSERT_EQUAL_INT(QC_OK, run_spiral(&r, &p, &a, NULL));
        TEST_ASSERT_EQUAL_INT(QC_OK, run_spiral(&r, &p, &b, NULL));
        TEST_ASSERT_EQUAL_UINT(a.npt, b.npt);
        TEST_ASSERT_EQUAL_MEMORY(a.pt, b.pt, a.npt * sizeof *a.pt);
        qc_path_free(&ctx, &a);
        qc_path_free(&ctx, &b);
        qc_region_free(&ctx, &r);
    }
}

static void spiral_should_run_through_generate(void)
{
    qc_region r;
    qc_params p;
    qc_result res;

    make_region(R_HOLES, 200, &r);
    memset(&p, 0, sizeof p);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "family", QC_FAMILY_SPIRAL));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "spacing", 10));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_generate(&ctx, &r, &p, NULL, NULL, &res));
    TEST_ASSERT_EQUAL_INT(QC_SPIRAL_ARCHIMEDEAN, res.params.spiral);
    TEST_ASSERT_EQUAL_UINT(1, res.stats.pieces);
    TEST_ASSERT_EQUAL_UINT(0, res.points.n);
    TEST_ASSERT_GREATER_THAN_DOUBLE(0.0, res.stats.largest_gap_mm);
    TEST_ASSERT_LESS_THAN_DOUBLE(10.0, res.stats.largest_gap_mm);
    qc_result_free(&ctx, &res);
    qc_region_free(&ctx, &r);
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

static void spiral_should_report_errors(void)
{
    qc_region r, empty;
    qc_params p = params(10, 3, QC_SPIRAL_ARCHIMEDEAN);
    qc_path out;

    make_region(R_RECT, 200, &r);
    memset(&empty, 0, sizeof empty);
    TEST_ASSERT_EQUAL_INT(QC_EEMPTY, run_spiral(&empty, &p, &out, NULL));
    TEST_ASSERT_TRUE(strstr(qc_errmsg(&ctx), "no outline") != NULL);
    p.margin = 80; /* the rectangle reaches 75 mm from its boundary */
    TEST_ASSERT_EQUAL_INT(QC_EEMPTY, run_spiral(&r, &p, &out, NULL));
    TEST_ASSERT_TRUE(strstr(qc_errmsg(&ctx), "spiral: no ring fits inside the margin of 80 mm") != NULL);
    TEST_ASSERT_EQUAL_UINT(0, out.ncmd);
    p.margin = 3;
    p.spacing = -1;
    TEST_ASSERT_EQUAL_INT(QC_ERANGE, run_spiral(&r, &p, &out, NULL));
    TEST_ASSERT_TRUE(strstr(qc_errmsg(&ctx), "spacing -1 mm") != NULL);
    p = params(1, 0.5, QC_SPIRAL_FERMAT); /* 74.5 mm deep at 1 mm: 5550 rings */
    TEST_ASSERT_EQUAL_INT(QC_ELIMIT, run_spiral(&r, &p, &out, NULL));
    TEST_ASSERT_TRUE(strstr(qc_errmsg(&ctx), "5551 equal-area rings") != NULL);
    TEST_ASSERT_EQUAL_UINT(0, out.ncmd);
    qc_region_free(&ctx, &r);
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

static void spiral_should_survive_allocation_failures(void)
{
    int sk;

    for (sk = QC_SPIRAL_ARCHIMEDEAN; sk <= QC_SPIRAL_FERMAT; sk++) {
        qc_region r;
        qc_params p = params(12, 4, sk);
        size_t k, base;
        int rc = QC_ENOMEM;

        make_region(R_HOLES, 100, &r);
        base = ta.live_blocks;
        for (k = 1; rc == QC_ENOMEM && k < 5000; k++) {
            qc_path out;
            qc_stats st;

            ta.allocs = 0;
            ta.fail_at = k;
            rc = run_spiral(&r, &p, &out, &st);
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
    RUN_TEST(spiral_should_be_one_path_inside_at_the_margin);
    RUN_TEST(spiral_should_not_cross_itself);
    RUN_TEST(spiral_should_not_retrace);
    RUN_TEST(spiral_should_start_near_the_farthest_point);
    RUN_TEST(archimedean_turns_should_be_d_apart);
    RUN_TEST(fermat_turns_should_add_equal_areas);
    RUN_TEST(spiral_should_start_anywhere);
    RUN_TEST(spiral_gap_should_stay_near_d);
    RUN_TEST(spiral_should_be_deterministic);
    RUN_TEST(spiral_should_wind_in_and_out_from_a_boundary_start);
    RUN_TEST(spiral_should_run_through_generate);
    RUN_TEST(spiral_should_report_errors);
    RUN_TEST(spiral_should_survive_allocation_failures);
    return UNITY_END();
}
