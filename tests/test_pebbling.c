/* Pebbling (§5.3.1): pebbles never overlap, each touches the one it hangs
 * from, strict pebbles stay inside, growth leaves interior pebbles touching
 * three others, r_seed 1/2 on a lattice gives equal pebbles; the path is
 * one piece round each pebble once, inside the region, without crossing
 * itself; overgrow trims and joins along the boundary; errors; OOM. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "quiltc.h"
#include "testalloc.h"
#include "unity.h"
#include "../src/deco/pebble_internal.h"

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

enum { R_SQUARE, R_HOLE, R_CIRCLE, R_STAR, R_TRIANGLE };
enum { L_SQUARE, L_TRIANGLE, L_JITTER };

static void make_region(int kind, qc_region *r)
{
    qc_vec2 sq[4] = {{0, 0}, {100, 0}, {100, 100}, {0, 100}};
    qc_vec2 hole[4] = {{35, 35}, {35, 65}, {65, 65}, {65, 35}};

    memset(r, 0, sizeof *r);
    if (kind == R_TRIANGLE) { /* a half-square triangle: 90 and two 45 deg corners */
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, r, sq, 3));
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_normalize(&ctx, r));
        return;
    }
    if (kind == R_CIRCLE || kind == R_STAR) {
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_shape(&ctx, kind == R_CIRCLE ? "circle:100"
                                                                            : "star:120", 1, r));
        return;
    }
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, r, sq, 4));
    if (kind == R_HOLE)
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, r, hole, 4));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_normalize(&ctx, r));
}

/* A test skeleton: lattice points at least margin inside, their EMST and a
 * depth-first walk from point 0 (root first and last). */
typedef struct tskel {
    qc_points p;
    qc_edges e;
    qc_order order;
} tskel;

static void make_skeleton(const qc_region *r, double d, int lattice, uint64_t seed, tskel *t)
{
    qc_bbox b = qc_region_bbox(r);
    double x, y, dy = lattice == L_TRIANGLE ? d * sqrt(3.0) / 2 : d;
    size_t n, i, sp = 0, *first, *at;
    uint32_t *adj, *stack;
    unsigned char *seen;
    int row = 0;
    qc_rng rng;

    memset(t, 0, sizeof *t);
    qc_rng_seed(&rng, seed);
    for (y = b.min.y + d / 2; y < b.max.y; y += dy, row++)
        for (x = b.min.x + d / 2 + (lattice == L_TRIANGLE && (row & 1) ? d / 2 : 0); x < b.max.x;
             x += d) {
            qc_vec2 p;
            p.x = x;
            p.y = y;
            if (lattice == L_JITTER) {
                p.x += (qc_rng_unit(&rng) - 0.5) * d * 0.4;
                p.y += (qc_rng_unit(&rng) - 0.5) * d * 0.4;
            }
            if (qc_region_contains(r, p) && qc_region_boundary_distance(r, p) >= 0.3 * d)
                TEST_ASSERT_EQUAL_INT(QC_OK, qc_points_push(&ctx, &t->p, p));
        }
    n = t->p.n;
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_mst(&ctx, t->p.v, n, QC_MST_MODE_DELAUNAY, &t->e));
    first = calloc(n + 1, sizeof *first);
    at = malloc(n * sizeof *at);
    adj = malloc(2 * n * sizeof *adj);
    stack = malloc(n * sizeof *stack);
    seen = calloc(n, 1);
    for (i = 0; i < t->e.n; i++) {
        first[t->e.e[i].a + 1]++;
        first[t->e.e[i].b + 1]++;
    }
    for (i = 0; i < n; i++)
        first[i + 1] += first[i];
    for (i = 0; i < n; i++)
        at[i] = first[i];
    for (i = 0; i < t->e.n; i++) {
        adj[at[t->e.e[i].a]++] = t->e.e[i].b;
        adj[at[t->e.e[i].b]++] = t->e.e[i].a;
    }
    for (i = 0; i < n; i++)
        at[i] = first[i];
    stack[sp++] = 0;
    seen[0] = 1;
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_order_push(&ctx, &t->order, 0));
    while (sp > 0) {
        uint32_t u = stack[sp - 1];
        if (at[u] < first[u + 1]) {
            uint32_t v = adj[at[u]++];
            if (seen[v])
                continue;
            seen[v] = 1;
            stack[sp++] = v;
            TEST_ASSERT_EQUAL_INT(QC_OK, qc_order_push(&ctx, &t->order, v));
        } else if (--sp > 0) {
            TEST_ASSERT_EQUAL_INT(QC_OK, qc_order_push(&ctx, &t->order, stack[sp - 1]));
        }
    }
    TEST_ASSERT_EQUAL_UINT(2 * n - 1, t->order.n);
    free(first);
    free(at);
    free(adj);
    free(stack);
    free(seen);
}

static void free_skeleton(tskel *t)
{
    qc_points_free(&ctx, &t->p);
    qc_edges_free(&ctx, &t->e);
    qc_order_free(&ctx, &t->order);
}

static qc_skeleton as_skel(const tskel *t)
{
    qc_skeleton s;
    s.p = t->p.v;
    s.n = t->p.n;
    s.edges = t->e.e;
    s.nedges = t->e.n;
    s.order = t->order.i;
    s.norder = t->order.n;
    s.root = 0;
    return s;
}

static qc_params base_params(double d, double r_seed, int edge)
{
    qc_params p;
    memset(&p, 0, sizeof p);
    p.seed = 1;
    p.spacing = d;
    p.r_seed = r_seed;
    p.edge = edge;
    return p;
}

static double gap_between(const qc__pebbles *pb, size_t i, size_t j)
{
    return qc_hypot(pb->c[i].x - pb->c[j].x, pb->c[i].y - pb->c[j].y) - pb->r[i] - pb->r[j];
}

/* Figures checked by check_pattern. */
typedef struct result {
    size_t pebbles, interior, interior3, crossing;
    double coverage;
} result;

/* Every invariant of a pebbling run; pebbles returned in *keep. */
static void check_pattern(const qc_region *r, const tskel *t, const qc_params *par, result *res)
{
    qc_skeleton sk = as_skel(t);
    qc__pebbles pb;
    qc_path out = {0};
    qc_stats st;
    qc_points flat = {0};
    double d = par->spacing, tol = 1e-9 * d, sum = 0, drawn = 0, rmin = 1e30, rmax = 0;
    int strict = par->edge != QC_EDGE_OVERGROW;
    size_t i, j, crossings = 99, under3 = 0;

    memset(&st, 0, sizeof st);
    memset(res, 0, sizeof *res);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc__pebbling_run(&ctx, r, par, &sk, &out, &st, &pb));
    TEST_ASSERT_EQUAL_UINT(pb.n, st.pebbles);
    TEST_ASSERT_GREATER_THAN_UINT(t->p.n / 2, pb.n);
    /* drawn into one reservation of 8 commands and 20 points a pebble (a
     * true bound), the path is held cut to size: no slack to the end */
    if (strict)
        TEST_ASSERT_TRUE(out.ncmd <= 8 * pb.n + 2 && out.npt <= 20 * pb.n + 2);
    TEST_ASSERT_EQUAL_size_t(out.npt, out.pt_cap);
    TEST_ASSERT_EQUAL_size_t(out.ncmd, out.cmd_cap);
    for (i = 0; i < pb.n; i++) {
        size_t touching = 0;
        double bd = qc_region_boundary_distance(r, pb.c[i]);
        TEST_ASSERT_TRUE(qc_region_contains(r, pb.c[i]));
        TEST_ASSERT_TRUE(pb.r[i] >= pb.r_min - tol);
        TEST_ASSERT_EQUAL_INT(0, pb.flags[i] & QC__PEB_BRIDGE);
        if (strict)
            TEST_ASSERT_TRUE(bd >= pb.r[i] - tol); /* inside the region */
        else
            TEST_ASSERT_TRUE(bd >= 0.5 * pb.r[i] - tol); /* centre well inside */
        res->crossing += bd < pb.r[i] - 1e-6 * d;
        if (i == 0)
            TEST_ASSERT_EQUAL_UINT(QC__PEB_NONE, pb.parent[0]);
        else /* touches the pebble it hangs from */
            TEST_ASSERT_DOUBLE_WITHIN(pb.touch, 0, gap_between(&pb, i, pb.parent[i]));
        for (j = 0; j < pb.n; j++) {
            if (j == i)
                continue;
            TEST_ASSERT_TRUE(gap_between(&pb, i, j) >= -tol); /* no overlap */
            touching += gap_between(&pb, i, j) <= pb.touch;
        }
        if (bd > pb.r[i] + d) { /* interior */
            res->interior++;
            res->interior3 += touching >= 3;
        }
        TEST_ASSERT_EQUAL_UINT(touching + (bd - pb.k * pb.r[i] <= pb.touch), pb.contacts[i]);
        under3 += pb.contacts[i] < 3;
        sum += 2 * QC_PI * pb.r[i];
        drawn += 2 * QC_PI * (pb.r[i] - pb.draw_in);
        rmin = fmin(rmin, pb.r[i]);
        rmax = fmax(rmax, pb.r[i]);
    }
    TEST_ASSERT_EQUAL_UINT(under3, st.pebbles_under3);
    TEST_ASSERT_EQUAL_DOUBLE(rmin, st.radius_min);
    TEST_ASSERT_EQUAL_DOUBLE(rmax, st.radius_max);
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, sum / (2 * QC_PI * (double)pb.n), st.radius_mean);
    TEST_ASSERT_TRUE(st.coverage > 0.5 && st.coverage <= 1);
    /* one piece, inside, never crossing itself */
    TEST_ASSERT_EQUAL_UINT(1, qc_path_pieces(&out));
    TEST_ASSERT_EQUAL_INT(QC_PATH_MOVE, out.cmd[0]);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_curve_flatten(&ctx, &out, 0.01, &flat, NULL));
    for (i = 0; i < flat.n; i++)
        TEST_ASSERT_TRUE(qc_region_contains(r, flat.v[i]) ||
                         qc_region_boundary_distance(r, flat.v[i]) < 1e-9);
    TEST_ASSERT_EQUAL_DOUBLE(flat.v[0].x, flat.v[flat.n - 1].x); /* closed */
    TEST_ASSERT_EQUAL_DOUBLE(flat.v[0].y, flat.v[flat.n - 1].y);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_self_crossings(&ctx, flat.v, flat.n, 0, &crossings));
    TEST_ASSERT_EQUAL_UINT(0, crossings);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, fmin(0.05, 0.01 * d), pb.draw_in);
    if (strict) /* round each pebble exactly once (cubic arcs a hair inside; each child
                 * joined at its parent's circle, up to 2 draw_in from its own) */
        TEST_ASSERT_DOUBLE_WITHIN(drawn * 2e-3 + 4 * pb.draw_in * (double)pb.n, drawn,
                                  qc_curve_length(&out, 0.001));
    res->pebbles = pb.n;
    res->coverage = st.coverage;
    qc_points_free(&ctx, &flat);
    qc_path_free(&ctx, &out);
    qc__pebbles_free(&ctx, &pb);
}

static void run_case(int region, int lattice, double d, double r_seed, int edge, result *res)
{
    qc_region r;
    tskel t;
    qc_params par = base_params(d, r_seed, edge);

    make_region(region, &r);
    make_skeleton(&r, d, lattice, 7, &t);
    check_pattern(&r, &t, &par, res);
    free_skeleton(&t);
    qc_region_free(&ctx, &r);
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
    TEST_ASSERT_FALSE(ta.size_mismatch);
}

static void pebbling_should_pack_a_square(void)
{
    result res;

    run_case(R_SQUARE, L_JITTER, 8, 0.7, QC_EDGE_STRICT, &res);
    TEST_ASSERT_GREATER_THAN_UINT(20, res.interior);
    TEST_ASSERT_TRUE(res.interior3 >= 0.95 * (double)res.interior);
    TEST_ASSERT_EQUAL_UINT(0, res.crossing);
    run_case(R_SQUARE, L_SQUARE, 10, 0.8, QC_EDGE_STRICT, &res);
    TEST_ASSERT_TRUE(res.interior3 >= 0.95 * (double)res.interior);
}

static void pebbling_should_keep_out_of_a_hole(void)
{
    result res;

    run_case(R_HOLE, L_SQUARE, 10, 0.7, QC_EDGE_STRICT, &res);
    run_case(R_HOLE, L_TRIANGLE, 6, 0.6, QC_EDGE_STRICT, &res);
    TEST_ASSERT_TRUE(res.interior3 >= 0.95 * (double)res.interior);
}

static void pebbling_should_fill_a_circle_and_a_star(void)
{
    result res;

    run_case(R_CIRCLE, L_TRIANGLE, 7, 0.5, QC_EDGE_STRICT, &res);
    run_case(R_STAR, L_JITTER, 6, 0.75, QC_EDGE_STRICT, &res);
}

static void pebbling_should_overgrow_and_trim_to_the_boundary(void)
{
    result strict, over;

    run_case(R_HOLE, L_JITTER, 8, 0.7, QC_EDGE_STRICT, &strict);
    run_case(R_HOLE, L_JITTER, 8, 0.7, QC_EDGE_OVERGROW, &over);
    TEST_ASSERT_GREATER_THAN_UINT(5, over.crossing); /* border pebbles overhang, trimmed */
    TEST_ASSERT_TRUE(over.coverage > strict.coverage);
    run_case(R_STAR, L_SQUARE, 10, 0.8, QC_EDGE_OVERGROW, &over);
    TEST_ASSERT_GREATER_THAN_UINT(3, over.crossing);
}

/* r_seed = 1/2 on a lattice: every pebble clear of the boundary is d/2. */
static void pebbling_should_give_equal_pebbles_for_half_r_seed(void)
{
    static const int lattices[] = {L_SQUARE, L_TRIANGLE};
    qc_region r;
    size_t li, i, equal = 0, interior = 0;

    make_region(R_SQUARE, &r);
    for (li = 0; li < 2; li++) {
        tskel t;
        qc_skeleton sk;
        qc_params par = base_params(10, 0.5, QC_EDGE_STRICT);
        qc__pebbles pb;
        qc_path out = {0};

        make_skeleton(&r, 10, lattices[li], 1, &t);
        sk = as_skel(&t);
        TEST_ASSERT_EQUAL_INT(QC_OK, qc__pebbling_run(&ctx, &r, &par, &sk, &out, NULL, &pb));
        for (i = 0; i < pb.n; i++) {
            TEST_ASSERT_EQUAL_INT(0, pb.flags[i] & QC__PEB_FILLER);
            if (qc_region_boundary_distance(&r, pb.c[i]) > 0.75 * 10) {
                interior++;
                equal += fabs(pb.r[i] - 5) < 1e-9;
            }
        }
        qc_path_free(&ctx, &out);
        qc__pebbles_free(&ctx, &pb);
        free_skeleton(&t);
    }
    TEST_ASSERT_GREATER_THAN_UINT(80, interior);
    TEST_ASSERT_EQUAL_UINT(interior, equal);
    qc_region_free(&ctx, &r);
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

/* r_seed = 0.7 on a square lattice: 0.7 d and 0.3 d alternate, grown after. */
static void pebbling_should_vary_sizes_with_r_seed(void)
{
    qc_region r;
    tskel t;
    qc_skeleton sk;
    qc_params par = base_params(10, 0.7, QC_EDGE_STRICT);
    qc_stats st;
    qc_path out = {0};

    make_region(R_SQUARE, &r);
    make_skeleton(&r, 10, L_SQUARE, 1, &t);
    sk = as_skel(&t);
    memset(&st, 0, sizeof st);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_deco_pebbling(&ctx, &r, &par, &sk, NULL, &out, &st));
    TEST_ASSERT_TRUE(st.radius_min <= 3 + 1e-9);
    TEST_ASSERT_TRUE(st.radius_max >= 7 - 1e-9);
    TEST_ASSERT_TRUE(st.radius_max <= 1.5 * 7 + 1e-9); /* growth cap */
    qc_path_free(&ctx, &out);
    free_skeleton(&t);
    qc_region_free(&ctx, &r);
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

static void pebbling_should_repeat_for_a_seed(void)
{
    qc_region r;
    tskel t;
    qc_skeleton sk;
    int edge;

    make_region(R_HOLE, &r);
    make_skeleton(&r, 8, L_JITTER, 3, &t);
    sk = as_skel(&t);
    for (edge = QC_EDGE_STRICT; edge <= QC_EDGE_OVERGROW; edge++) {
        qc_params par = base_params(8, 0.65, edge);
        qc_path a = {0}, b = {0};
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_deco_pebbling(&ctx, &r, &par, &sk, NULL, &a, NULL));
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_deco_pebbling(&ctx, &r, &par, &sk, NULL, &b, NULL));
        TEST_ASSERT_EQUAL_UINT(a.ncmd, b.ncmd);
        TEST_ASSERT_EQUAL_UINT(a.npt, b.npt);
        TEST_ASSERT_EQUAL_MEMORY(a.cmd, b.cmd, a.ncmd);
        TEST_ASSERT_EQUAL_MEMORY(a.pt, b.pt, a.npt * sizeof *a.pt);
        qc_path_free(&ctx, &a);
        qc_path_free(&ctx, &b);
    }
    free_skeleton(&t);
    qc_region_free(&ctx, &r);
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

/* Distance from x to the nearest pebble's edge. */
static double to_pebbles(const qc__pebbles *pb, qc_vec2 x)
{
    double best = HUGE_VAL;
    size_t i;

    for (i = 0; i < pb->n; i++)
        best = fmin(best, qc_hypot(x.x - pb->c[i].x, x.y - pb->c[i].y) - pb->r[i]);
    return best;
}

/* Phase 3: every corner sharper than 150 deg has a pebble within 1 d of its
 * tip (0.8 d already, or one put there at the radius that brings it 1 d
 * from the tip), and the seams, looked at every d / 10, lie at most 0.35 d
 * from a pebble but where none fits (asserted: 93% of them; measured 97%,
 * 97% and 99% on the triangle, the star and the square with a hole; the
 * triangle 85%, its 45 deg corners 1.07 d from a pebble, without phase 3);
 * the invariants (no overlap, tangent to the parent, one path that never
 * crosses) hold with the pebbles phase 3 adds (check_pattern). */
static void pebbling_should_reach_into_corners_and_along_seams(void)
{
    static const int regions[] = {R_TRIANGLE, R_STAR, R_HOLE};
    size_t k;

    for (k = 0; k < 3; k++) {
        qc_region r;
        tskel t;
        qc_skeleton sk;
        qc_params par = base_params(10, 0.7, QC_EDGE_STRICT);
        qc__pebbles pb;
        qc_path out = {0};
        result res;
        size_t i, ring, samples = 0, near = 0, corners = 0;

        make_region(regions[k], &r);
        make_skeleton(&r, 10, L_JITTER, 3, &t);
        check_pattern(&r, &t, &par, &res);
        sk = as_skel(&t);
        TEST_ASSERT_EQUAL_INT(QC_OK, qc__pebbling_run(&ctx, &r, &par, &sk, &out, NULL, &pb));
        for (ring = 0; ring < r.nrings; ring++) {
            size_t lo = ring ? r.ring_end[ring - 1] : 0, hi = r.ring_end[ring];
            for (i = lo; i < hi; i++) {
                qc_vec2 a = r.v[i], b = r.v[i + 1 < hi ? i + 1 : lo];
                double len = qc_hypot(b.x - a.x, b.y - a.y), at;
                if (qc_region_corner_angle(&r, i) < 150) {
                    corners++;
                    TEST_ASSERT_TRUE(to_pebbles(&pb, a) <= 10 * (1 + 1e-9));
                }
                for (at = 0.5; at < len; at += 1) {
                    qc_vec2 x = {a.x + (b.x - a.x) * at / len, a.y + (b.y - a.y) * at / len};
                    samples++;
                    near += to_pebbles(&pb, x) <= 3.5 * (1 + 1e-9);
                }
            }
        }
        TEST_ASSERT_TRUE(corners >= 3);
        TEST_ASSERT_TRUE(near >= 0.93 * (double)samples);
        qc_path_free(&ctx, &out);
        qc__pebbles_free(&ctx, &pb);
        free_skeleton(&t);
        qc_region_free(&ctx, &r);
    }
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

/* A lone point: one circle, r_seed d unless the boundary is nearer. */
static void pebbling_should_draw_a_lone_point_as_one_circle(void)
{
    qc_region r;
    qc_skeleton sk;
    qc_params par = base_params(10, 0.8, QC_EDGE_STRICT);
    qc_vec2 p = {50, 50};
    uint32_t o = 0;
    qc_path out = {0};
    qc_stats st;

    make_region(R_SQUARE, &r);
    memset(&sk, 0, sizeof sk);
    sk.p = &p;
    sk.n = 1;
    sk.order = &o;
    sk.norder = 1;
    memset(&st, 0, sizeof st);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_deco_pebbling(&ctx, &r, &par, &sk, NULL, &out, &st));
    TEST_ASSERT_EQUAL_UINT(1, st.pebbles);
    TEST_ASSERT_EQUAL_DOUBLE(8, st.radius_max);
    TEST_ASSERT_EQUAL_UINT(5, out.ncmd); /* MOVE and four quarter arcs */
    TEST_ASSERT_DOUBLE_WITHIN(2e-3 * 2 * QC_PI * 8, 2 * QC_PI * (8 - 0.05),
                              qc_curve_length(&out, 0.001));
    qc_path_free(&ctx, &out);
    qc_region_free(&ctx, &r);
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

/* A tour skeleton (no edges): each point hangs from the one before. */
static void pebbling_should_follow_a_tour(void)
{
    qc_region r;
    qc_vec2 p[40];
    uint32_t o[40];
    qc_skeleton sk;
    qc_params par = base_params(10, 0.6, QC_EDGE_STRICT);
    qc__pebbles pb;
    qc_path out = {0};
    size_t i;

    make_region(R_SQUARE, &r);
    for (i = 0; i < 40; i++) { /* a zigzag of 4 rows of 10 */
        size_t row = i / 10, col = row & 1 ? 9 - i % 10 : i % 10;
        p[i].x = 5 + 10.0 * (double)col;
        p[i].y = 5 + 10.0 * (double)row;
        o[i] = (uint32_t)i;
    }
    memset(&sk, 0, sizeof sk);
    sk.p = p;
    sk.n = 40;
    sk.order = o;
    sk.norder = 40;
    TEST_ASSERT_EQUAL_INT(QC_OK, qc__pebbling_run(&ctx, &r, &par, &sk, &out, NULL, &pb));
    TEST_ASSERT_TRUE(pb.n >= 40);
    TEST_ASSERT_EQUAL_UINT(1, qc_path_pieces(&out));
    for (i = 1; i < pb.n; i++)
        TEST_ASSERT_DOUBLE_WITHIN(pb.touch, 0, gap_between(&pb, i, pb.parent[i]));
    qc_path_free(&ctx, &out);
    qc__pebbles_free(&ctx, &pb);
    qc_region_free(&ctx, &r);
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

static void pebbling_should_refuse_empty_tiny_and_bad_input(void)
{
    qc_region r, tiny;
    qc_skeleton sk;
    qc_params par = base_params(10, 0.7, QC_EDGE_STRICT);
    qc_vec2 p = {0.75, 0.75}, sq[4] = {{0, 0}, {1.5, 0}, {1.5, 1.5}, {0, 1.5}};
    uint32_t o[2] = {0, 5};
    qc_path out = {0};

    make_region(R_SQUARE, &r);
    memset(&tiny, 0, sizeof tiny);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, &tiny, sq, 4));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_normalize(&ctx, &tiny));
    memset(&sk, 0, sizeof sk);
    TEST_ASSERT_EQUAL_INT(QC_EEMPTY, qc_deco_pebbling(&ctx, &r, &par, &sk, NULL, &out, NULL));
    TEST_ASSERT_EQUAL_STRING("pebbling needs at least one point", qc_errmsg(&ctx));
    sk.p = &p;
    sk.n = 1;
    sk.order = o;
    sk.norder = 1;
    /* a 1.5 mm square holds no pebble of d/10 = 1 mm */
    TEST_ASSERT_EQUAL_INT(QC_EEMPTY, qc_deco_pebbling(&ctx, &tiny, &par, &sk, NULL, &out, NULL));
    TEST_ASSERT_NOT_NULL(strstr(qc_errmsg(&ctx), "no pebble of radius 1 mm"));
    TEST_ASSERT_EQUAL_UINT(0, out.ncmd);
    par.r_seed = 0.3;
    TEST_ASSERT_EQUAL_INT(QC_ERANGE, qc_deco_pebbling(&ctx, &r, &par, &sk, NULL, &out, NULL));
    TEST_ASSERT_EQUAL_STRING("r-seed 0.3 ratio out of range [0.5, 1] ratio", qc_errmsg(&ctx));
    par.r_seed = 0.7;
    par.spacing = 0;
    TEST_ASSERT_EQUAL_INT(QC_ERANGE, qc_deco_pebbling(&ctx, &r, &par, &sk, NULL, &out, NULL));
    /* the table's range, the one qc_params_resolve applies (no second copy) */
    par.spacing = 0.4;
    TEST_ASSERT_EQUAL_INT(QC_ERANGE, qc_deco_pebbling(&ctx, &r, &par, &sk, NULL, &out, NULL));
    TEST_ASSERT_EQUAL_STRING("spacing 0.4 mm out of range [0.5, 1000] mm", qc_errmsg(&ctx));
    par.spacing = 1001;
    TEST_ASSERT_EQUAL_INT(QC_ERANGE, qc_deco_pebbling(&ctx, &r, &par, &sk, NULL, &out, NULL));
    par.spacing = 10;
    sk.norder = 2;
    TEST_ASSERT_EQUAL_INT(QC_EINVAL, qc_deco_pebbling(&ctx, &r, &par, &sk, NULL, &out, NULL));
    TEST_ASSERT_EQUAL_STRING("skeleton order entry 1 is 5, beyond 1 points", qc_errmsg(&ctx));
    TEST_ASSERT_EQUAL_UINT(0, out.ncmd);
    qc_region_free(&ctx, &r);
    qc_region_free(&ctx, &tiny);
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

static void pebbling_should_free_everything_when_allocation_fails(void)
{
    qc_region r;
    tskel t;
    qc_skeleton sk;
    int edge;

    make_region(R_HOLE, &r);
    make_skeleton(&r, 14, L_JITTER, 9, &t);
    sk = as_skel(&t);
    for (edge = QC_EDGE_STRICT; edge <= QC_EDGE_OVERGROW; edge++) {
        qc_params par = base_params(14, 0.7, edge);
        size_t k;
        int rc = QC_ENOMEM;
        for (k = 1; rc == QC_ENOMEM && k < 5000; k++) {
            qc_path out = {0};
            qc_stats st;
            size_t base = ta.live_blocks;
            memset(&st, 0, sizeof st);
            ta.allocs = 0;
            ta.fail_at = k;
            rc = qc_deco_pebbling(&ctx, &r, &par, &sk, NULL, &out, &st);
            ta.fail_at = 0;
            qc_path_free(&ctx, &out);
            TEST_ASSERT_EQUAL_UINT(base, ta.live_blocks);
        }
        TEST_ASSERT_EQUAL_INT(QC_OK, rc);
        TEST_ASSERT_GREATER_THAN_UINT(10, k);
    }
    TEST_ASSERT_FALSE(ta.size_mismatch);
    free_skeleton(&t);
    qc_region_free(&ctx, &r);
}

/* FNV-1a over a path's commands and point bits. */
static uint64_t path_digest(const qc_path *p)
{
    uint64_t h = 1469598103934665603ull;
    size_t i, k;

    for (i = 0; i < p->ncmd; i++)
        h = (h ^ p->cmd[i]) * 1099511628211ull;
    for (i = 0; i < p->npt; i++) {
        const unsigned char *b = (const unsigned char *)&p->pt[i];
        for (k = 0; k < sizeof p->pt[i]; k++)
            h = (h ^ b[k]) * 1099511628211ull;
    }
    return h;
}

/* The speedups of issue 21 (a pair search asking the pebbles gathered once,
 * packing's nearest motif point skipping far cubics, its path reserved
 * once, keep-inside's deferred sample count) change no byte: pebbling and
 * packing on a star and a circle, strict and overgrown, on the lattices
 * and Poisson points, hash to what the code before them drew. */
static void pebbling_and_packing_should_draw_the_same_bytes_as_before_the_speedups(void)
{
    static const struct {
        int family, points, edge;
        const char *shape;
        uint64_t digest;
    } run[] = {
        {QC_FAMILY_PEBBLING, QC_POINTS_SNUB, QC_EDGE_STRICT, "star:250",
         0x7ba7078e434b7ba4ull},
        {QC_FAMILY_PEBBLING, QC_POINTS_HEX, QC_EDGE_OVERGROW, "circle:200",
         0xbb8275b2b57b70b3ull},
        {QC_FAMILY_PEBBLING, QC_POINTS_POISSON, QC_EDGE_STRICT, "heart:220",
         0x275b5505c857510dull},
        {QC_FAMILY_PACKING, QC_POINTS_SNUB, QC_EDGE_STRICT, "star:250",
         0x716523c716f550a9ull},
        {QC_FAMILY_PACKING, QC_POINTS_SQUARE, QC_EDGE_OVERGROW, "circle:200",
         0xd999e212c62f871cull},
        {QC_FAMILY_PACKING, QC_POINTS_POISSON, QC_EDGE_STRICT, "heart:220",
         0xbdfc9ee3df7703b6ull},
    };
    size_t k;

    for (k = 0; k < sizeof run / sizeof *run; k++) {
        qc_region r = {0};
        qc_params p;
        qc_result res;
        uint64_t h;
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_shape(&ctx, run[k].shape, 1.0, &r));
        memset(&p, 0, sizeof p);
        qc_params_set(&ctx, &p, "family", run[k].family);
        qc_params_set(&ctx, &p, "points", run[k].points);
        qc_params_set(&ctx, &p, "edge", run[k].edge);
        qc_params_set(&ctx, &p, "spacing", 8);
        qc_params_set(&ctx, &p, "seed", 7);
        p.skip_gap_stat = 1;
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_generate(&ctx, &r, &p, NULL, NULL, &res));
        h = path_digest(&res.path);
        if (getenv("QC_DIGEST_PRINT"))
            printf("%lu: 0x%016llxull (%lu points)\n", (unsigned long)k, (unsigned long long)h,
                   (unsigned long)res.path.npt);
        TEST_ASSERT_TRUE(res.path.npt > 1000);
        TEST_ASSERT_TRUE_MESSAGE(h == run[k].digest, run[k].shape);
        qc_result_free(&ctx, &res);
        qc_region_free(&ctx, &r);
    }
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

/* Packing keeps only the root's starting angle: qc__pebbles_start_angle,
 * from the root's children alone, gives the bits qc__pebbles_children
 * gives after keying and sorting every pebble's children (a root with many
 * children, with one, and with none); an allocation failure is reported. */
static void pebbles_start_angle_should_match_the_children_walk(void)
{
    const int regions[] = {R_SQUARE, R_HOLE, R_STAR, R_TRIANGLE};
    const int lattices[] = {L_SQUARE, L_TRIANGLE, L_JITTER};
    size_t k, l, checked = 0;

    for (k = 0; k < sizeof regions / sizeof *regions; k++)
        for (l = 0; l < sizeof lattices / sizeof *lattices; l++) {
            qc_region r;
            tskel t;
            qc_skeleton sk;
            qc_params par = base_params(8, l == 1 ? 0.5 : 0.7, QC_EDGE_STRICT);
            qc__pebbles pb;
            qc_path out = {0};
            uint32_t *first = NULL, *kids = NULL;
            double a0 = 0, b0 = 1, c0;
            size_t n, saved;

            make_region(regions[k], &r);
            make_skeleton(&r, 8, lattices[l], 5 + k, &t);
            sk = as_skel(&t);
            TEST_ASSERT_EQUAL_INT(QC_OK, qc__pebbling_run(&ctx, &r, &par, &sk, &out, NULL, &pb));
            n = pb.n;
            TEST_ASSERT_EQUAL_INT(QC_OK, qc__pebbles_children(&ctx, &pb, &first, &kids, &a0,
                                                               NULL));
            TEST_ASSERT_EQUAL_INT(QC_OK, qc__pebbles_start_angle(&ctx, &pb, &b0));
            TEST_ASSERT_TRUE(memcmp(&a0, &b0, sizeof a0) == 0);
            TEST_ASSERT_TRUE(first[1] - first[0] >= 1);
            checked++;
            /* the root with a single child, then with none */
            saved = pb.n;
            if (saved >= 2 && pb.parent[1] == 0) { /* pebble 1 hangs from the root */
                pb.n = 2;
                uint32_t *f2 = NULL, *k2 = NULL;
                TEST_ASSERT_EQUAL_INT(QC_OK, qc__pebbles_children(&ctx, &pb, &f2, &k2, &a0, NULL));
                TEST_ASSERT_EQUAL_INT(QC_OK, qc__pebbles_start_angle(&ctx, &pb, &b0));
                TEST_ASSERT_TRUE(memcmp(&a0, &b0, sizeof a0) == 0);
                qc__free(&ctx, f2, 3 * sizeof *f2);
                qc__free(&ctx, k2, 2 * sizeof *k2);
            }
            pb.n = 1;
            TEST_ASSERT_EQUAL_INT(QC_OK, qc__pebbles_start_angle(&ctx, &pb, &c0));
            TEST_ASSERT_EQUAL_DOUBLE(-QC_PI / 2, c0);
            pb.n = saved;
            ta.fail_at = ta.allocs + 1;
            TEST_ASSERT_EQUAL_INT(QC_ENOMEM, qc__pebbles_start_angle(&ctx, &pb, &c0));
            ta.fail_at = 0;
            qc__free(&ctx, first, (n + 1) * sizeof *first);
            qc__free(&ctx, kids, n * sizeof *kids);
            qc__pebbles_free(&ctx, &pb);
            qc_path_free(&ctx, &out);
            free_skeleton(&t);
            qc_region_free(&ctx, &r);
        }
    TEST_ASSERT_EQUAL_UINT(12, checked);
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

/* The arcs take sine and cosine from one reduction (qc__sincos): the very
 * bits qc_sin and qc_cos give, in every quadrant, at the quadrant edges,
 * for a negative zero, far out, and NaN for what is not finite. */
static void sincos_should_give_the_bits_of_sin_and_cos(void)
{
    const double edge[] = {0.0, -0.0, QC_PI / 4, QC_PI / 2, QC_PI, 1.5 * QC_PI, 2 * QC_PI,
                           -QC_PI / 4, -QC_PI, 1e6 + 0.3, -7e8};
    double x, s, c, zs, zc;
    size_t k;

    for (k = 0; k < 2000 + sizeof edge / sizeof *edge; k++) {
        double sn, cs;
        x = k < 2000 ? -20.0 + 0.0201 * (double)k : edge[k - 2000];
        s = qc_sin(x);
        c = qc_cos(x);
        qc__sincos(x, &sn, &cs);
        TEST_ASSERT_EQUAL_MEMORY(&s, &sn, sizeof s);
        TEST_ASSERT_EQUAL_MEMORY(&c, &cs, sizeof c);
    }
    qc__sincos((double)NAN, &zs, &zc);
    TEST_ASSERT_TRUE(isnan(zs) && isnan(zc));
    qc__sincos((double)INFINITY, &zs, &zc);
    TEST_ASSERT_TRUE(isnan(zs) && isnan(zc));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(pebbling_should_pack_a_square);
    RUN_TEST(pebbling_should_keep_out_of_a_hole);
    RUN_TEST(pebbling_should_fill_a_circle_and_a_star);
    RUN_TEST(pebbling_should_overgrow_and_trim_to_the_boundary);
    RUN_TEST(pebbling_should_give_equal_pebbles_for_half_r_seed);
    RUN_TEST(pebbling_should_vary_sizes_with_r_seed);
    RUN_TEST(pebbling_should_repeat_for_a_seed);
    RUN_TEST(pebbling_should_reach_into_corners_and_along_seams);
    RUN_TEST(pebbling_should_draw_a_lone_point_as_one_circle);
    RUN_TEST(pebbling_should_follow_a_tour);
    RUN_TEST(pebbling_should_refuse_empty_tiny_and_bad_input);
    RUN_TEST(pebbling_should_free_everything_when_allocation_fails);
    RUN_TEST(pebbling_and_packing_should_draw_the_same_bytes_as_before_the_speedups);
    RUN_TEST(sincos_should_give_the_bits_of_sin_and_cos);
    RUN_TEST(pebbles_start_angle_should_match_the_children_walk);
    return UNITY_END();
}
