/* Quilt tops: patches from real pieced blocks, overlaps, and one line sewn in the ditch. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "quiltc.h"
#include "testalloc.h"
#include "unity.h"

#define IN 25.4
#define SEAM_TOL 0.508 /* 0.02 in: a stitch this near a seam is in the ditch */

/* The farthest fabric from a stitch, in spacings (#16's measure): today's
 * worst on the nine-patch is packing's 1.59 d; the goal is 1.0 d. */
#define FARTHEST_BOUND 1.75

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

static char *slurp(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    char *buf;
    long n;

    TEST_ASSERT_NOT_NULL_MESSAGE(f, path);
    fseek(f, 0, SEEK_END);
    n = ftell(f);
    fseek(f, 0, SEEK_SET);
    buf = malloc((size_t)n + 1);
    TEST_ASSERT_NOT_NULL(buf);
    TEST_ASSERT_EQUAL_size_t((size_t)n, fread(buf, 1, (size_t)n, f));
    fclose(f);
    buf[n] = '\0';
    *len = (size_t)n;
    return buf;
}

static void read_top(const char *path, qc_patches *ps)
{
    size_t len;
    char *buf = slurp(path, &len);
    int rc = qc_io_read_svg_patches(&ctx, buf, len, NULL, ps);

    free(buf);
    TEST_ASSERT_EQUAL_INT_MESSAGE(QC_OK, rc, qc_errmsg(&ctx));
}

static void read_text(const char *svg, qc_patches *ps)
{
    int rc = qc_io_read_svg_patches(&ctx, svg, strlen(svg), NULL, ps);

    TEST_ASSERT_EQUAL_INT_MESSAGE(QC_OK, rc, qc_errmsg(&ctx));
}

/* Every patch with the same family at 0.5 in spacing. */
static void quilt_all(const qc_patches *ps, int family, int join, qc_params *p,
                      qc_quilt_result *res)
{
    qc_patch_job *jobs = calloc(ps->n, sizeof *jobs);
    qc_quilt_params qp;
    size_t i;
    int rc;

    memset(p, 0, sizeof *p);
    qc_params_set(&ctx, p, "family", family);
    qc_params_set(&ctx, p, "spacing", 0.5 * IN);
    for (i = 0; i < ps->n; i++)
        jobs[i].params = p;
    memset(&qp, 0, sizeof qp);
    qp.join = join;
    rc = qc_quilt(&ctx, ps, jobs, &qp, res);
    free(jobs);
    TEST_ASSERT_EQUAL_INT_MESSAGE(QC_OK, rc, qc_errmsg(&ctx));
}

static double boundary_dist(const qc_patches *ps, qc_vec2 q)
{
    double best = HUGE_VAL;
    size_t i;

    for (i = 0; i < ps->n; i++)
        best = fmin(best, qc_region_boundary_distance(&ps->p[i].region, q));
    return best;
}

static int in_some_patch(const qc_patches *ps, qc_vec2 q)
{
    size_t i;

    for (i = 0; i < ps->n; i++)
        if (qc_region_contains(&ps->p[i].region, q))
            return 1;
    return 0;
}

/* Every point of every sewn segment (sampled every 0.25 mm) lies inside a
 * patch or within 0.02 in of a seam. */
static void assert_sewn_inside(const qc_patches *ps, const qc_path *path)
{
    qc_points flat = {0};
    qc_order ends = {0};
    size_t piece, k = 0;

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_curve_flatten(&ctx, path, 0.05, &flat, &ends));
    for (piece = 0; piece < ends.n; piece++) {
        for (k++; k < ends.i[piece]; k++) {
            qc_vec2 a = flat.v[k - 1], b = flat.v[k];
            double len = qc_hypot(b.x - a.x, b.y - a.y);
            size_t steps = (size_t)(len / 0.25) + 1, s;

            for (s = 0; s <= steps; s++) {
                double t = (double)s / (double)steps;
                qc_vec2 q = {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};

                if (!in_some_patch(ps, q) && boundary_dist(ps, q) > SEAM_TOL) {
                    char msg[96];
                    snprintf(msg, sizeof msg, "(%.3f, %.3f) mm is outside every patch", q.x, q.y);
                    TEST_FAIL_MESSAGE(msg);
                }
            }
        }
    }
    qc_points_free(&ctx, &flat);
    qc_order_free(&ctx, &ends);
}

/* The travel runs on seams: every point of it is on some patch's boundary. */
static void assert_ditch_on_seams(const qc_patches *ps, const qc_path *ditch)
{
    size_t i;

    for (i = 0; i < ditch->npt; i++)
        TEST_ASSERT_TRUE(boundary_dist(ps, ditch->pt[i]) <= 0.05);
}

/* One line, inside, every patch quilted with its gap within the family's
 * spacing. */
static void sew_top(const char *path, size_t npatches)
{
    qc_patches ps;
    qc_quilt_result res;
    qc_params p;
    size_t i;

    read_top(path, &ps);
    TEST_ASSERT_EQUAL_size_t(npatches, ps.n);
    TEST_ASSERT_EQUAL_INT(0, qc_patches_overlap(&ps, 0, NULL, NULL, NULL));
    quilt_all(&ps, QC_FAMILY_STIPPLE, QC_JOIN_DITCH, &p, &res);
    TEST_ASSERT_EQUAL_size_t(1, qc_path_pieces(&res.path));
    TEST_ASSERT_EQUAL_size_t(0, res.jumps);
    TEST_ASSERT_EQUAL_size_t(ps.n, res.norder);
    for (i = 0; i < ps.n; i++) {
        TEST_ASSERT_TRUE(res.patch[i].order < ps.n);
        TEST_ASSERT_EQUAL_INT(QC_FAMILY_STIPPLE, res.patch[i].family);
        TEST_ASSERT_TRUE(res.patch[i].length_mm > 0);
        TEST_ASSERT_TRUE(res.patch[i].largest_gap_mm > 0);
        TEST_ASSERT_TRUE(res.patch[i].largest_gap_mm <= 0.5 * IN);
    }
    TEST_ASSERT_TRUE(res.ditch_mm > 0);
    assert_sewn_inside(&ps, &res.path);
    assert_ditch_on_seams(&ps, &res.ditch);
    qc_quilt_result_free(&ctx, &res);
    qc_patches_free(&ctx, &ps);
}

static void test_nine_patch_should_be_nine_patches_where_drawn(void)
{
    qc_patches ps;
    size_t i, dark = 0;

    read_top("tests/data/quilt/nine-patch.svg", &ps);
    TEST_ASSERT_EQUAL_size_t(9, ps.n);
    for (i = 0; i < ps.n; i++) {
        qc_bbox b = qc_region_bbox(&ps.p[i].region);

        TEST_ASSERT_DOUBLE_WITHIN(1e-6, 16 * IN * IN, qc_region_area(&ps.p[i].region));
        TEST_ASSERT_EQUAL_size_t(i + 1, ps.p[i].element);
        TEST_ASSERT_TRUE(ps.p[i].has_fill);
        dark += strcmp(ps.p[i].cls, "dark") == 0;
        TEST_ASSERT_EQUAL_UINT32(strcmp(ps.p[i].cls, "dark") == 0 ? 0x1f3a93u : 0xf5f0e1u,
                                 ps.p[i].fill);
        /* p<row><col>, rows down the page from its top: y up from the bottom */
        TEST_ASSERT_DOUBLE_WITHIN(1e-6, (ps.p[i].id[2] - '0') * 4 * IN, b.min.x);
        TEST_ASSERT_DOUBLE_WITHIN(1e-6, (2 - (ps.p[i].id[1] - '0')) * 4 * IN, b.min.y);
    }
    TEST_ASSERT_EQUAL_size_t(5, dark);
    TEST_ASSERT_EQUAL_STRING("p00", ps.p[0].id);
    TEST_ASSERT_EQUAL_STRING("", ps.p[0].label);
    qc_patches_free(&ctx, &ps);
}

static void test_sawtooth_star_should_keep_labels_and_fills(void)
{
    qc_patches ps;
    size_t i, points = 0;

    read_top("examples/sawtooth-star.svg", &ps);
    TEST_ASSERT_EQUAL_size_t(17, ps.n);
    for (i = 0; i < ps.n; i++)
        if (strcmp(ps.p[i].label, "Star point") == 0) {
            points++;
            TEST_ASSERT_EQUAL_STRING("point", ps.p[i].cls);
            TEST_ASSERT_EQUAL_UINT32(0xe67e22u, ps.p[i].fill);
            TEST_ASSERT_DOUBLE_WITHIN(1e-6, 4.5 * IN * IN, qc_region_area(&ps.p[i].region));
        }
    TEST_ASSERT_EQUAL_size_t(8, points);
    qc_patches_free(&ctx, &ps);
}

static void test_shape_of_separate_pieces_should_be_several_patches(void)
{
    static const char svg[] =
        "<svg xmlns='http://www.w3.org/2000/svg' width='100mm' height='100mm' "
        "viewBox='0 0 100 100'><g fill='rgb(10, 20, 30)'>"
        "<path id='two' d='M0,0h10v10h-10z M20,0h10v10h-10z'/>"
        "<path id='ring' fill-rule='evenodd' d='M40,0h30v30h-30z M45,5h10v10h-10z'/></g></svg>";
    qc_patches ps;

    read_text(svg, &ps);
    TEST_ASSERT_EQUAL_size_t(3, ps.n);
    TEST_ASSERT_EQUAL_STRING("two", ps.p[0].id);
    TEST_ASSERT_EQUAL_STRING("two", ps.p[1].id);
    TEST_ASSERT_EQUAL_size_t(1, ps.p[0].piece);
    TEST_ASSERT_EQUAL_size_t(2, ps.p[1].piece);
    TEST_ASSERT_EQUAL_size_t(1, ps.p[0].region.nrings);
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 100, qc_region_area(&ps.p[1].region));
    TEST_ASSERT_EQUAL_STRING("ring", ps.p[2].id);
    TEST_ASSERT_EQUAL_size_t(2, ps.p[2].region.nrings); /* its own hole */
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 800, qc_region_area(&ps.p[2].region));
    TEST_ASSERT_EQUAL_UINT32(0x0a141eu, ps.p[2].fill); /* inherited from the group */
    qc_patches_free(&ctx, &ps);
}

static void overlap_case(const char *shapes, int want, size_t wa, size_t wb)
{
    char svg[512];
    qc_patches ps;
    size_t a = 99, b = 99;
    qc_vec2 at;

    snprintf(svg, sizeof svg,
             "<svg xmlns='http://www.w3.org/2000/svg' width='100mm' height='100mm' "
             "viewBox='0 0 100 100'>%s</svg>", shapes);
    read_text(svg, &ps);
    TEST_ASSERT_EQUAL_INT_MESSAGE(want, qc_patches_overlap(&ps, 0, &a, &b, &at), shapes);
    if (want) {
        TEST_ASSERT_EQUAL_size_t(wa, a);
        TEST_ASSERT_EQUAL_size_t(wb, b);
        TEST_ASSERT_TRUE(qc_region_contains(&ps.p[a].region, at));
        TEST_ASSERT_TRUE(qc_region_contains(&ps.p[b].region, at));
    }
    qc_patches_free(&ctx, &ps);
}

static void test_overlapping_patches_should_be_found_touching_ones_not(void)
{
    overlap_case("<rect x='0' y='0' width='10' height='10'/>"
                 "<rect x='10' y='0' width='10' height='10'/>"
                 "<rect x='0' y='10' width='20' height='5'/>"
                 "<rect x='20' y='15' width='5' height='5'/>", 0, 0, 0); /* seams, T, corner */
    overlap_case("<rect x='0' y='0' width='10' height='10'/>"
                 "<rect x='5' y='5' width='10' height='10'/>", 1, 0, 1);
    overlap_case("<rect x='0' y='0' width='10' height='10'/>"
                 "<rect x='30' y='0' width='10' height='10'/>"
                 "<rect x='30' y='0' width='10' height='10'/>", 1, 1, 2); /* drawn twice */
    overlap_case("<rect x='0' y='0' width='30' height='30'/>"
                 "<rect x='10' y='10' width='5' height='5'/>", 1, 0, 1); /* one on another */
    overlap_case("<rect x='0' y='10' width='30' height='5'/>"
                 "<rect x='10' y='0' width='5' height='30'/>", 1, 0, 1); /* crossed strips */
}

static void test_nine_patch_should_be_sewn_as_one_line_in_the_ditch(void)
{
    sew_top("tests/data/quilt/nine-patch.svg", 9);
}

static void test_sawtooth_star_should_be_sewn_as_one_line_in_the_ditch(void)
{
    sew_top("examples/sawtooth-star.svg", 17);
}

static void test_log_cabin_should_be_sewn_as_one_line_in_the_ditch(void)
{
    sew_top("tests/data/quilt/log-cabin.svg", 21);
}

static void test_drunkards_path_curved_seams_should_be_sewn_as_one_line(void)
{
    sew_top("tests/data/quilt/drunkards-path.svg", 8);
}

static void test_sashing_and_border_should_be_sewn_as_one_line(void)
{
    sew_top("tests/data/quilt/sashing.svg", 43);
}

/* Proper self-crossings of the whole sewn line, flattened as the tests do. */
static size_t line_crossings(const qc_path *path)
{
    qc_points flat = {0};
    qc_order ends = {0};
    size_t n = 0;

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_curve_flatten(&ctx, path, 0.05, &flat, &ends));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_self_crossings(&ctx, flat.v, flat.n, 0, &n));
    qc_points_free(&ctx, &flat);
    qc_order_free(&ctx, &ends);
    return n;
}

/* A vine running along a seam, or a pebble hugging it, lies between the
 * piece's end and its nearest seam point: the straight link in or out
 * must reach the seam elsewhere rather than cross the pattern (on main,
 * log-cabin crossed itself 2 times with vine and 4 with pebbling). */
static void test_links_to_the_seams_should_not_cross_the_pattern(void)
{
    static const int family[] = {QC_FAMILY_VINE, QC_FAMILY_PEBBLING};
    qc_patches ps;
    qc_quilt_result res;
    qc_params p;
    size_t f;

    read_top("tests/data/quilt/log-cabin.svg", &ps);
    for (f = 0; f < sizeof family / sizeof family[0]; f++) {
        quilt_all(&ps, family[f], QC_JOIN_DITCH, &p, &res);
        TEST_ASSERT_EQUAL_size_t(1, qc_path_pieces(&res.path));
        TEST_ASSERT_EQUAL_size_t(0, line_crossings(&res.path));
        assert_sewn_inside(&ps, &res.path);
        qc_quilt_result_free(&ctx, &res);
    }
    qc_patches_free(&ctx, &ps);
}

static void test_join_jump_should_start_a_piece_per_patch(void)
{
    qc_patches ps;
    qc_quilt_result res;
    qc_params p;

    read_top("tests/data/quilt/nine-patch.svg", &ps);
    quilt_all(&ps, QC_FAMILY_STIPPLE, QC_JOIN_JUMP, &p, &res);
    TEST_ASSERT_EQUAL_size_t(9, qc_path_pieces(&res.path));
    TEST_ASSERT_EQUAL_size_t(0, res.ditch.ncmd);
    TEST_ASSERT_EQUAL_INT(0, res.ditch_mm == 0 ? 0 : 1);
    assert_sewn_inside(&ps, &res.path);
    qc_quilt_result_free(&ctx, &res);
    qc_patches_free(&ctx, &ps);
}

static void test_each_patch_should_get_its_own_family_and_none_stays_empty(void)
{
    static const int fam[9] = {QC_FAMILY_STIPPLE, QC_FAMILY_PEBBLING, QC_FAMILY_ECHO,
                               QC_FAMILY_SPIRAL, -1, QC_FAMILY_WANDERER,
                               QC_FAMILY_BRANCHING, QC_FAMILY_FILL, QC_FAMILY_PACKING};
    qc_patches ps;
    qc_quilt_result res;
    qc_params p[9];
    qc_patch_job jobs[9];
    qc_points flat = {0};
    size_t i;

    read_top("tests/data/quilt/nine-patch.svg", &ps);
    memset(jobs, 0, sizeof jobs);
    for (i = 0; i < 9; i++) {
        memset(&p[i], 0, sizeof p[i]);
        qc_params_set(&ctx, &p[i], "spacing", 0.5 * IN);
        if (fam[i] > 0) {
            qc_params_set(&ctx, &p[i], "family", fam[i]);
            jobs[i].params = &p[i];
        }
    }
    TEST_ASSERT_EQUAL_INT_MESSAGE(QC_OK, qc_quilt(&ctx, &ps, jobs, NULL, &res), qc_errmsg(&ctx));
    for (i = 0; i < 9; i++) {
        if (fam[i] > 0) {
            char msg[64];

            snprintf(msg, sizeof msg, "%s: farthest fabric %.2f mm",
                     qc_family_name(fam[i]), res.patch[i].farthest_fabric_mm);
            TEST_ASSERT_EQUAL_INT(fam[i], res.patch[i].family);
            TEST_ASSERT_TRUE(res.patch[i].order < 8);
            /* every family's own coverage of its patch, pebbles included */
            TEST_ASSERT_TRUE_MESSAGE(res.patch[i].farthest_fabric_mm > 0.1 * IN, msg);
            TEST_ASSERT_TRUE_MESSAGE(res.patch[i].farthest_fabric_mm <= FARTHEST_BOUND * 0.5 * IN,
                                     msg);
        } else
            TEST_ASSERT_EQUAL_size_t(SIZE_MAX, res.patch[i].order);
    }
    TEST_ASSERT_EQUAL_size_t(8, res.norder);
    TEST_ASSERT_EQUAL_size_t(1, qc_path_pieces(&res.path));
    assert_sewn_inside(&ps, &res.path);
    /* the line may run along the empty patch's seams, never into it */
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_curve_flatten(&ctx, &res.path, 0.05, &flat, NULL));
    for (i = 0; i < flat.n; i++)
        TEST_ASSERT_FALSE(qc_region_contains(&ps.p[4].region, flat.v[i]) &&
                          qc_region_boundary_distance(&ps.p[4].region, flat.v[i]) > SEAM_TOL);
    qc_points_free(&ctx, &flat);
    qc_quilt_result_free(&ctx, &res);
    qc_patches_free(&ctx, &ps);
}

static void test_same_seed_should_give_the_same_line(void)
{
    qc_patches ps;
    qc_quilt_result a, b;
    qc_params p;

    read_top("examples/sawtooth-star.svg", &ps);
    quilt_all(&ps, QC_FAMILY_STIPPLE, QC_JOIN_DITCH, &p, &a);
    quilt_all(&ps, QC_FAMILY_STIPPLE, QC_JOIN_DITCH, &p, &b);
    TEST_ASSERT_EQUAL_size_t(a.path.npt, b.path.npt);
    TEST_ASSERT_EQUAL_size_t(a.path.ncmd, b.path.ncmd);
    TEST_ASSERT_EQUAL_INT(0, memcmp(a.path.pt, b.path.pt, a.path.npt * sizeof *a.path.pt));
    TEST_ASSERT_EQUAL_INT(0, memcmp(a.order, b.order, a.norder * sizeof *a.order));
    qc_quilt_result_free(&ctx, &a);
    qc_quilt_result_free(&ctx, &b);
    qc_patches_free(&ctx, &ps);
}

static void test_patches_apart_should_be_joined_by_a_jump(void)
{
    static const char svg[] =
        "<svg xmlns='http://www.w3.org/2000/svg' width='200mm' height='100mm' "
        "viewBox='0 0 200 100'><rect x='0' y='0' width='60' height='60'/>"
        "<rect x='100' y='0' width='60' height='60'/></svg>";
    qc_patches ps;
    qc_quilt_result res;
    qc_params p;

    read_text(svg, &ps);
    quilt_all(&ps, QC_FAMILY_STIPPLE, QC_JOIN_DITCH, &p, &res);
    TEST_ASSERT_EQUAL_size_t(2, qc_path_pieces(&res.path));
    TEST_ASSERT_EQUAL_size_t(1, res.jumps);
    assert_sewn_inside(&ps, &res.path);
    qc_quilt_result_free(&ctx, &res);
    qc_patches_free(&ctx, &ps);
}

/* 1 when some point of the path is within 0.01 mm of q. */
static int path_visits(const qc_path *path, qc_vec2 q)
{
    size_t i;

    for (i = 0; i < path->npt; i++)
        if (qc_hypot(path->pt[i].x - q.x, path->pt[i].y - q.y) < 0.01)
            return 1;
    return 0;
}

static void test_patch_too_small_should_be_sewn_round_in_the_ditch(void)
{
    /* a 5 mm square and a 3 mm strip beside a block, at 0.5 in spacing:
     * no point fits in either; the line goes round them on their seams */
    static const char svg[] =
        "<svg xmlns='http://www.w3.org/2000/svg' width='110mm' height='100mm' "
        "viewBox='0 0 110 100'><rect id='big' x='0' y='0' width='100' height='100'/>"
        "<rect id='tiny' x='100' y='0' width='5' height='5'/>"
        "<rect id='strip' x='100' y='5' width='3' height='95'/></svg>";
    static const qc_vec2 tiny[4] = {{100, 95}, {105, 95}, {105, 100}, {100, 100}};
    qc_patches ps;
    qc_quilt_result res;
    qc_params p;
    size_t i;

    read_text(svg, &ps);
    TEST_ASSERT_EQUAL_size_t(3, ps.n);
    quilt_all(&ps, QC_FAMILY_STIPPLE, QC_JOIN_DITCH, &p, &res);
    TEST_ASSERT_EQUAL_size_t(1, qc_path_pieces(&res.path));
    TEST_ASSERT_EQUAL_size_t(0, res.jumps);
    TEST_ASSERT_EQUAL_size_t(3, res.norder);
    TEST_ASSERT_EQUAL_INT(0, res.patch[0].ditch_only);
    TEST_ASSERT_EQUAL_INT(1, res.patch[1].ditch_only);
    TEST_ASSERT_EQUAL_INT(1, res.patch[2].ditch_only);
    TEST_ASSERT_EQUAL_INT(QC_FAMILY_STIPPLE, res.patch[1].family);
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 20.0, res.patch[1].length_mm);
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 196.0, res.patch[2].length_mm);
    for (i = 0; i < 4; i++) /* y up: the SVG's top right corner is y 95..100 */
        TEST_ASSERT_TRUE(path_visits(&res.path, tiny[i]));
    assert_sewn_inside(&ps, &res.path);
    assert_ditch_on_seams(&ps, &res.ditch);
    qc_quilt_result_free(&ctx, &res);
    qc_patches_free(&ctx, &ps);
}

/* Sews a top with every allocation failing in turn (every k-th): each
 * failure is QC_ENOMEM and leaks nothing; one run gets through. */
static void quilt_under_oom(const char *top, int family, double spacing, size_t step)
{
    qc_patches ps;
    qc_quilt_result res;
    qc_params p;
    qc_patch_job *jobs;
    size_t k, i, ok = 0;

    read_top(top, &ps);
    jobs = calloc(ps.n, sizeof *jobs);
    TEST_ASSERT_NOT_NULL(jobs);
    memset(&p, 0, sizeof p);
    qc_params_set(&ctx, &p, "family", family);
    qc_params_set(&ctx, &p, "spacing", spacing);
    for (i = 0; i < ps.n; i++)
        jobs[i].params = &p;
    for (k = 1; k < 5000 && !ok; k += step) {
        int rc;
        ta.fail_at = ta.allocs + k;
        rc = qc_quilt(&ctx, &ps, jobs, NULL, &res);
        ta.fail_at = 0;
        if (rc == QC_OK) {
            ok = 1;
            qc_quilt_result_free(&ctx, &res);
        } else
            TEST_ASSERT_EQUAL_INT(QC_ENOMEM, rc);
    }
    TEST_ASSERT_TRUE(ok);
    free(jobs);
    qc_patches_free(&ctx, &ps);
}

static void test_seams_drawn_slightly_apart_should_still_be_one_seam(void)
{
    /* the second square drawn 0.04 mm right of and 0.03 mm above the seam,
     * as an export rounding to 0.1 mm leaves it */
    static const char svg[] =
        "<svg xmlns='http://www.w3.org/2000/svg' width='200mm' height='100mm' "
        "viewBox='0 0 200 100'><rect x='0' y='0' width='100' height='100'/>"
        "<rect x='100.04' y='0.03' width='99.96' height='99.97'/></svg>";
    qc_patches ps;
    qc_quilt_result res;
    qc_quilt_params qp;
    qc_patch_job jobs[2];
    qc_params p;

    read_text(svg, &ps);
    quilt_all(&ps, QC_FAMILY_STIPPLE, QC_JOIN_DITCH, &p, &res);
    TEST_ASSERT_EQUAL_size_t(1, qc_path_pieces(&res.path));
    TEST_ASSERT_EQUAL_size_t(0, res.jumps);
    assert_sewn_inside(&ps, &res.path);
    qc_quilt_result_free(&ctx, &res);
    /* a tolerance below the gap keeps them apart: a jump */
    memset(&qp, 0, sizeof qp);
    qp.seam_tol = 0.01;
    jobs[0].params = jobs[1].params = &p;
    jobs[0].motifs = jobs[1].motifs = NULL;
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_quilt(&ctx, &ps, jobs, &qp, &res));
    TEST_ASSERT_EQUAL_size_t(1, res.jumps);
    qc_quilt_result_free(&ctx, &res);
    qp.seam_tol = QC_QUILT_MAX_SEAM_TOL * 1.01;
    TEST_ASSERT_EQUAL_INT(QC_EINVAL, qc_quilt(&ctx, &ps, jobs, &qp, &res));
    qc_patches_free(&ctx, &ps);
}

static void test_quilt_should_free_everything_when_memory_runs_out(void)
{
    quilt_under_oom("tests/data/quilt/nine-patch.svg", QC_FAMILY_ECHO, 1.5 * IN, 7);
    /* and where patches are sewn round in the ditch */
    quilt_under_oom("tests/data/quilt/tiny-patches.svg", QC_FAMILY_ECHO, 0.5 * IN, 1);
}

static void test_colours_should_parse_as_css_writes_them(void)
{
    uint32_t c = 0;

    TEST_ASSERT_TRUE(qc_color_parse("#c0392b", &c));
    TEST_ASSERT_EQUAL_UINT32(0xc0392bu, c);
    TEST_ASSERT_TRUE(qc_color_parse(" #FfF ", &c));
    TEST_ASSERT_EQUAL_UINT32(0xffffffu, c);
    TEST_ASSERT_TRUE(qc_color_parse("rgb(255, 0, 10)", &c));
    TEST_ASSERT_EQUAL_UINT32(0xff000au, c);
    TEST_ASSERT_TRUE(qc_color_parse("rgb(100%,50%,0%)", &c));
    TEST_ASSERT_EQUAL_UINT32(0xff8000u, c);
    TEST_ASSERT_TRUE(qc_color_parse("Navy", &c));
    TEST_ASSERT_EQUAL_UINT32(0x000080u, c);
    TEST_ASSERT_FALSE(qc_color_parse("#12345", &c));
    TEST_ASSERT_FALSE(qc_color_parse("#ggg", &c));
    TEST_ASSERT_FALSE(qc_color_parse("rgb(256, 0, 0)", &c));
    TEST_ASSERT_FALSE(qc_color_parse("rgb(1, 2)", &c));
    TEST_ASSERT_FALSE(qc_color_parse("url(#grad)", &c));
    TEST_ASSERT_FALSE(qc_color_parse("", &c));
    TEST_ASSERT_FALSE(qc_color_parse(NULL, &c));
}

static void test_reading_a_top_should_survive_running_out_of_memory(void)
{
    size_t len, k;
    char *buf = slurp("examples/sawtooth-star.svg", &len);
    int ok = 0;

    for (k = 1; k < 20000 && !ok; k += 3) {
        qc_patches ps;
        int rc;

        ta.fail_at = ta.allocs + k;
        rc = qc_io_read_svg_patches(&ctx, buf, len, NULL, &ps);
        ta.fail_at = 0;
        if (rc == QC_OK) {
            TEST_ASSERT_EQUAL_size_t(17, ps.n);
            qc_patches_free(&ctx, &ps);
            ok = 1;
        } else {
            TEST_ASSERT_EQUAL_INT(QC_ENOMEM, rc);
            TEST_ASSERT_EQUAL_size_t(0, ps.n);
        }
    }
    free(buf);
    TEST_ASSERT_TRUE(ok);
}

static void test_shape_crossing_itself_should_be_named(void)
{
    static const char svg[] =
        "<svg xmlns='http://www.w3.org/2000/svg' width='100mm' height='100mm' "
        "viewBox='0 0 100 100'>\n<rect id='ok' width='10' height='10'/>\n"
        "<path id='bow' d='M20,0 L40,10 L40,0 L20,20 Z'/></svg>";
    qc_patches ps;

    TEST_ASSERT_EQUAL_INT(QC_EINTERSECT,
                          qc_io_read_svg_patches(&ctx, svg, strlen(svg), NULL, &ps));
    TEST_ASSERT_EQUAL_size_t(0, ps.n);
    TEST_ASSERT_NOT_NULL(strstr(qc_errmsg(&ctx), "svg line 3, <id=\"bow\">"));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_nine_patch_should_be_nine_patches_where_drawn);
    RUN_TEST(test_sawtooth_star_should_keep_labels_and_fills);
    RUN_TEST(test_shape_of_separate_pieces_should_be_several_patches);
    RUN_TEST(test_overlapping_patches_should_be_found_touching_ones_not);
    RUN_TEST(test_nine_patch_should_be_sewn_as_one_line_in_the_ditch);
    RUN_TEST(test_sawtooth_star_should_be_sewn_as_one_line_in_the_ditch);
    RUN_TEST(test_log_cabin_should_be_sewn_as_one_line_in_the_ditch);
    RUN_TEST(test_drunkards_path_curved_seams_should_be_sewn_as_one_line);
    RUN_TEST(test_sashing_and_border_should_be_sewn_as_one_line);
    RUN_TEST(test_links_to_the_seams_should_not_cross_the_pattern);
    RUN_TEST(test_join_jump_should_start_a_piece_per_patch);
    RUN_TEST(test_each_patch_should_get_its_own_family_and_none_stays_empty);
    RUN_TEST(test_same_seed_should_give_the_same_line);
    RUN_TEST(test_patches_apart_should_be_joined_by_a_jump);
    RUN_TEST(test_patch_too_small_should_be_sewn_round_in_the_ditch);
    RUN_TEST(test_seams_drawn_slightly_apart_should_still_be_one_seam);
    RUN_TEST(test_quilt_should_free_everything_when_memory_runs_out);
    RUN_TEST(test_colours_should_parse_as_css_writes_them);
    RUN_TEST(test_reading_a_top_should_survive_running_out_of_memory);
    RUN_TEST(test_shape_crossing_itself_should_be_named);
    return UNITY_END();
}
