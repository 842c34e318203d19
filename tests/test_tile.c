/* Tiles (§7.1, Fig. 27): a tile runs from its left port to the mirrored
 * right port, copies join exactly into pantograph rows (one piece each,
 * alternating direction, odd rows offset), neighbouring copies do not touch. */
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

typedef struct ttile {
    qc_region r;
    qc_points pts;
    qc_edges edges;
} ttile;

/* A W x H rectangle at (10, 20) with jittered hex points 0.3 d inside. */
static void make_tile(double W, double H, double d, uint64_t seed, ttile *t)
{
    qc_vec2 rect[4];
    qc_rng rng;
    double y;
    int row = 0;

    memset(t, 0, sizeof *t);
    rect[0] = v2(10, 20); rect[1] = v2(10 + W, 20); rect[2] = v2(10 + W, 20 + H);
    rect[3] = v2(10, 20 + H);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, &t->r, rect, 4));
    qc_rng_seed(&rng, seed);
    for (y = 20; y <= 20 + H; y += d * 0.866, row++) {
        double x;
        for (x = 10 + (row & 1 ? d / 2 : 0); x <= 10 + W; x += d) {
            double py = y + (qc_rng_unit(&rng) - 0.5) * 0.4 * d; /* drawn first, as gcc did */
            qc_vec2 p = v2(x + (qc_rng_unit(&rng) - 0.5) * 0.4 * d, py);
            if (qc_region_contains(&t->r, p) && qc_region_boundary_distance(&t->r, p) >= 0.3 * d)
                TEST_ASSERT_EQUAL_INT(QC_OK, qc_points_push(&ctx, &t->pts, p));
        }
    }
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_mst(&ctx, t->pts.v, t->pts.n, QC_MST_MODE_DELAUNAY, &t->edges));
}

static void free_tile(ttile *t)
{
    qc_region_free(&ctx, &t->r);
    qc_points_free(&ctx, &t->pts);
    qc_edges_free(&ctx, &t->edges);
}

static qc_params params(int family, double d, int tile, int cols, int rows, int tip)
{
    qc_params p, r;
    memset(&p, 0, sizeof p);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "family", family));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "spacing", d));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "tile", tile));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "repeat-cols", cols));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "repeat-rows", rows));
    if (tip)
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "tip", QC_TIP_CIRCLE));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_resolve(&ctx, &p, &r));
    return r;
}

static int generate(int family, const ttile *t, const qc_params *par, qc_path *out)
{
    qc_skeleton s;

    memset(&s, 0, sizeof s);
    s.p = t->pts.v;
    s.n = t->pts.n;
    s.edges = t->edges.e;
    s.nedges = t->edges.n;
    return family == QC_FAMILY_FILL ? qc_deco_fill(&ctx, &t->r, par, &s, NULL, out, NULL)
                                    : qc_deco_stipple(&ctx, &t->r, par, &s, NULL, out, NULL);
}

static void flatten(const qc_path *p, qc_points *flat)
{
    qc_order ends = {0};
    memset(flat, 0, sizeof *flat);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_curve_flatten(&ctx, p, 0.01, flat, &ends));
    TEST_ASSERT_EQUAL_UINT(1, ends.n);
    qc_order_free(&ctx, &ends);
}

/* Self-crossings of each piece (a pantograph row), summed. */
static size_t crossings(const qc_path *p)
{
    qc_points flat = {0};
    qc_order ends = {0};
    size_t n, total = 0, k, start = 0;

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_curve_flatten(&ctx, p, 0.01, &flat, &ends));
    for (k = 0; k < ends.n; start = ends.i[k++]) {
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_self_crossings(&ctx, flat.v + start,
                                                            ends.i[k] - start, 0, &n));
        total += n;
    }
    qc_points_free(&ctx, &flat);
    qc_order_free(&ctx, &ends);
    return total;
}

static void tile_should_run_from_port_to_mirrored_port(void)
{
    ttile t;
    qc_vec2 in, outp;
    int fam;

    make_tile(120, 80, 10, 1, &t);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_tile_ports(&ctx, &t.r, &in, &outp));
    TEST_ASSERT_EQUAL_DOUBLE(10.0, in.x);
    TEST_ASSERT_EQUAL_DOUBLE(60.0, in.y);
    TEST_ASSERT_EQUAL_DOUBLE(in.y, outp.y);
    TEST_ASSERT_EQUAL_DOUBLE(120.0, outp.x - in.x);
    for (fam = QC_FAMILY_FILL; fam <= QC_FAMILY_STIPPLE; fam++) {
        qc_params par = params(fam, 10, QC_TILE_EDGE_TO_EDGE, 1, 1, 0);
        qc_path p = {0};
        size_t i;

        TEST_ASSERT_EQUAL_INT(QC_OK, generate(fam, &t, &par, &p));
        TEST_ASSERT_EQUAL_UINT(1, qc_path_pieces(&p));
        TEST_ASSERT_EQUAL_MEMORY(&in, &p.pt[0], sizeof in);
        TEST_ASSERT_EQUAL_MEMORY(&outp, &p.pt[p.npt - 1], sizeof outp);
        for (i = 0; i < p.npt; i++)
            if (p.cmd[0] == QC_PATH_MOVE && fam == QC_FAMILY_FILL)
                TEST_ASSERT_TRUE(qc_region_contains(&t.r, p.pt[i]));
        TEST_ASSERT_EQUAL_UINT(0, crossings(&p));
        qc_path_free(&ctx, &p);
    }
    free_tile(&t);
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

/* A tile whose outline misses a side of its box at mid-height (a heart's
 * dip) would put its exit, where the next copy enters, outside itself: it
 * is refused with the spans; a circle touches both sides there and works. */
static void tile_ports_should_refuse_a_tile_short_of_its_sides(void)
{
    qc_region r = {0};
    qc_vec2 in, outp;

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_shape(&ctx, "heart:200", 1.0, &r));
    TEST_ASSERT_EQUAL_INT(QC_EINVAL, qc_tile_ports(&ctx, &r, &in, &outp));
    TEST_ASSERT_NOT_NULL(strstr(qc_errmsg(&ctx), "not its full width 0..200 mm"));
    qc_region_free(&ctx, &r);
    qc_clear_error(&ctx);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_shape(&ctx, "circle:200", 1.0, &r));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_tile_ports(&ctx, &r, &in, &outp));
    TEST_ASSERT_EQUAL_DOUBLE(200.0, outp.x - in.x);
    qc_region_free(&ctx, &r);
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

static void tile_repeat_should_join_copies_exactly(void)
{
    qc_path tile = {0}, out = {0};
    size_t c, k;

    /* entry (0, 0), exit (10, 0), one line and one cubic */
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_move_to(&ctx, &tile, v2(0, 0)));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_line_to(&ctx, &tile, v2(3, 2)));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_cubic_to(&ctx, &tile, v2(5, 4), v2(8, 1), v2(10, 0)));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_tile_repeat(&ctx, &tile, 10, 6, 3, 2, &out));
    TEST_ASSERT_EQUAL_UINT(1, qc_path_pieces(&out));
    /* MOVE, 3 x (line, cubic), row change, 3 x (cubic, line) reversed */
    TEST_ASSERT_EQUAL_UINT(1 + 6 + 1 + 6, out.ncmd);
    TEST_ASSERT_EQUAL_INT(QC_PATH_LINE, out.cmd[7]);
    k = 0;
    for (c = 0; c < out.ncmd; c++) { /* the end of every command is the start of the next */
        k += qc_path_cmd_points(out.cmd[c]);
        if (c + 1 < out.ncmd)
            TEST_ASSERT_TRUE(out.cmd[c + 1] != QC_PATH_MOVE);
    }
    TEST_ASSERT_EQUAL_UINT(out.npt, k);
    /* row 0 ends at (30, 0), steps down to (30, -6) and runs back reversed:
     * the cubic's controls swap */
    TEST_ASSERT_EQUAL_UINT(26, out.npt);
    TEST_ASSERT_EQUAL_DOUBLE(30.0, out.pt[12].x);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, out.pt[12].y);
    TEST_ASSERT_EQUAL_DOUBLE(30.0, out.pt[13].x);
    TEST_ASSERT_EQUAL_DOUBLE(-6.0, out.pt[13].y);
    TEST_ASSERT_EQUAL_DOUBLE(28.0, out.pt[14].x);
    TEST_ASSERT_EQUAL_DOUBLE(-5.0, out.pt[14].y);
    TEST_ASSERT_EQUAL_DOUBLE(23.0, out.pt[16].x);
    TEST_ASSERT_EQUAL_DOUBLE(-4.0, out.pt[16].y);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, out.pt[out.npt - 1].x);
    TEST_ASSERT_EQUAL_DOUBLE(-6.0, out.pt[out.npt - 1].y);
    TEST_ASSERT_EQUAL_INT(QC_EINVAL, qc_tile_repeat(&ctx, &tile, 10, 6, 0, 2, &out));
    qc_path_free(&ctx, &out);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_move_to(&ctx, &tile, v2(50, 50)));
    TEST_ASSERT_EQUAL_INT(QC_EINVAL, qc_tile_repeat(&ctx, &tile, 10, 6, 1, 1, &out));
    qc_path_free(&ctx, &tile);
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

/* Smallest distance between the copies, away from the shared port. */
static double copy_clearance(const qc_points *a, const qc_points *b, qc_vec2 port, double skip)
{
    double best = HUGE_VAL;
    size_t i, j;

    for (i = 0; i < a->n; i++) {
        if (qc_hypot(a->v[i].x - port.x, a->v[i].y - port.y) < skip)
            continue;
        for (j = 0; j < b->n; j++) {
            if (qc_hypot(b->v[j].x - port.x, b->v[j].y - port.y) < skip)
                continue;
            best = fmin(best, qc_hypot(a->v[i].x - b->v[j].x, a->v[i].y - b->v[j].y));
        }
    }
    return best;
}

static void check_neighbours(int family, int mode, int tip)
{
    ttile t;
    qc_params one = params(family, 9, mode, 1, 1, tip);
    qc_params many = params(family, 9, mode, 3, 2, tip);
    qc_path p = {0}, all = {0};
    qc_points a, b;
    qc_vec2 in, outp;
    size_t i;

    make_tile(90, 60, 9, 4, &t);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_tile_ports(&ctx, &t.r, &in, &outp));
    TEST_ASSERT_EQUAL_INT(QC_OK, generate(family, &t, &one, &p));
    TEST_ASSERT_EQUAL_INT(QC_OK, generate(family, &t, &many, &all));
    TEST_ASSERT_EQUAL_UINT(2, qc_path_pieces(&all)); /* a row each */
    TEST_ASSERT_EQUAL_UINT(0, crossings(&all));
    TEST_ASSERT_DOUBLE_WITHIN(1e-6, 6.0 * qc_curve_length(&p, 0), qc_curve_length(&all, 0));
    flatten(&p, &a);
    flatten(&p, &b);
    for (i = 0; i < b.n; i++) /* the right-hand neighbour */
        b.v[i].x += 90;
    TEST_ASSERT_GREATER_THAN_DOUBLE(0.5, copy_clearance(&a, &b, outp, 3.0));
    if (mode == QC_TILE_ALL_OVER) {
        for (i = 0; i < b.n; i++) { /* the neighbour below */
            b.v[i].x -= 90;
            b.v[i].y -= 60;
        }
        TEST_ASSERT_GREATER_THAN_DOUBLE(0.5, copy_clearance(&a, &b, v2(-1e9, -1e9), 0.0));
    }
    qc_points_free(&ctx, &a);
    qc_points_free(&ctx, &b);
    qc_path_free(&ctx, &p);
    qc_path_free(&ctx, &all);
    free_tile(&t);
}

/* qc_tile_layout: each row its own piece (the row change is a jump), the
 * next row starting on the side where the last one ended, odd rows moved
 * right by offset tiles; within a row the copies join exactly. */
static void tile_layout_should_sew_rows_as_pieces(void)
{
    qc_path tile = {0}, out = {0};
    size_t c, moves = 0;

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_move_to(&ctx, &tile, v2(0, 0)));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_line_to(&ctx, &tile, v2(3, 2)));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_cubic_to(&ctx, &tile, v2(5, 4), v2(8, 1), v2(10, 0)));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_tile_layout(&ctx, &tile, 10, 6, 3, 3, 0.5, &out));
    TEST_ASSERT_EQUAL_UINT(3, qc_path_pieces(&out));
    TEST_ASSERT_EQUAL_UINT(3 * (1 + 6), out.ncmd);
    for (c = 0; c < out.ncmd; c++)
        if (out.cmd[c] == QC_PATH_MOVE) {
            TEST_ASSERT_EQUAL_UINT(moves * 7, c); /* a MOVE starts each row, nothing else */
            moves++;
        }
    TEST_ASSERT_EQUAL_UINT(3, moves);
    /* row 0: 0..30 at y 0, ending at (30, 0) */
    TEST_ASSERT_EQUAL_DOUBLE(30.0, out.pt[12].x);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, out.pt[12].y);
    /* row 1 jumps to (35, -6): the right side again, half a tile over, and
     * runs back reversed to (5, -6) */
    TEST_ASSERT_EQUAL_DOUBLE(35.0, out.pt[13].x);
    TEST_ASSERT_EQUAL_DOUBLE(-6.0, out.pt[13].y);
    TEST_ASSERT_EQUAL_DOUBLE(33.0, out.pt[14].x); /* the cubic's controls swap */
    TEST_ASSERT_EQUAL_DOUBLE(-5.0, out.pt[14].y);
    TEST_ASSERT_EQUAL_DOUBLE(5.0, out.pt[25].x);
    TEST_ASSERT_EQUAL_DOUBLE(-6.0, out.pt[25].y);
    /* row 2 starts on the left, not offset */
    TEST_ASSERT_EQUAL_DOUBLE(0.0, out.pt[26].x);
    TEST_ASSERT_EQUAL_DOUBLE(-12.0, out.pt[26].y);
    TEST_ASSERT_EQUAL_DOUBLE(30.0, out.pt[out.npt - 1].x);
    /* the old layout is one piece with the row change sewn down the edge */
    qc_path_free(&ctx, &out);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_tile_repeat(&ctx, &tile, 10, 6, 3, 3, &out));
    TEST_ASSERT_EQUAL_UINT(1, qc_path_pieces(&out));
    qc_path_free(&ctx, &out);
    TEST_ASSERT_EQUAL_INT(QC_EINVAL, qc_tile_layout(&ctx, &tile, 10, 6, 3, 2, 1.0, &out));
    TEST_ASSERT_EQUAL_INT(QC_EINVAL, qc_tile_layout(&ctx, &tile, 10, 6, 3, 2, -0.1, &out));
    TEST_ASSERT_EQUAL_UINT(0, out.ncmd);
    qc_path_free(&ctx, &tile);
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

/* The offset parameter: read by the families whose tiles are laid out by
 * qc_tile_layout; rows offset by half a tile keep clear of each other. */
static void offset_rows_should_stay_clear(void)
{
    const qc_param_info *row = qc_param_find("offset");
    uint32_t fams;
    int family;

    TEST_ASSERT_NOT_NULL(row);
    TEST_ASSERT_EQUAL_INT(QC_PARAM_ID_ROW_OFFSET, row->id);
    fams = qc_param_families(row);
    TEST_ASSERT_TRUE(fams & (1u << QC_FAMILY_STIPPLE));
    TEST_ASSERT_TRUE(fams & (1u << QC_FAMILY_FILL));
    TEST_ASSERT_TRUE(fams & (1u << QC_FAMILY_BRANCHING));
    TEST_ASSERT_FALSE(fams & (1u << QC_FAMILY_VINE));
    for (family = QC_FAMILY_FILL; family <= QC_FAMILY_STIPPLE; family++) {
        ttile t;
        qc_params one = params(family, 9, QC_TILE_ALL_OVER, 1, 1, 0);
        qc_params many = params(family, 9, QC_TILE_ALL_OVER, 3, 2, 0);
        qc_path p = {0}, all = {0};
        qc_points a, b;
        qc_bbox box;
        size_t i;

        many.row_offset = 0.5;
        make_tile(90, 60, 9, 4, &t);
        TEST_ASSERT_EQUAL_INT(QC_OK, generate(family, &t, &one, &p));
        TEST_ASSERT_EQUAL_INT(QC_OK, generate(family, &t, &many, &all));
        TEST_ASSERT_EQUAL_UINT(2, qc_path_pieces(&all));
        TEST_ASSERT_EQUAL_UINT(0, crossings(&all));
        TEST_ASSERT_DOUBLE_WITHIN(1e-6, 6.0 * qc_curve_length(&p, 0), qc_curve_length(&all, 0));
        box = qc_curve_bbox(&all, 0.01); /* the lower row reaches half a tile further */
        TEST_ASSERT_TRUE(box.max.x > 10 + 3 * 90 + 0.4 * 90);
        TEST_ASSERT_TRUE(box.max.x <= 10 + 3.5 * 90 + 1e-9);
        flatten(&p, &a);
        flatten(&p, &b);
        for (i = 0; i < b.n; i++) { /* the neighbour below, half a tile over */
            b.v[i].x += 45;
            b.v[i].y -= 60;
        }
        TEST_ASSERT_GREATER_THAN_DOUBLE(0.5, copy_clearance(&a, &b, v2(-1e9, -1e9), 0.0));
        qc_points_free(&ctx, &a);
        qc_points_free(&ctx, &b);
        qc_path_free(&ctx, &p);
        qc_path_free(&ctx, &all);
        free_tile(&t);
    }
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

static void tiles_side_by_side_should_not_touch(void)
{
    check_neighbours(QC_FAMILY_FILL, QC_TILE_EDGE_TO_EDGE, 0);
    check_neighbours(QC_FAMILY_FILL, QC_TILE_EDGE_TO_EDGE, 1);
    check_neighbours(QC_FAMILY_STIPPLE, QC_TILE_EDGE_TO_EDGE, 0);
    check_neighbours(QC_FAMILY_STIPPLE, QC_TILE_ALL_OVER, 1);
    check_neighbours(QC_FAMILY_FILL, QC_TILE_ALL_OVER, 0);
}

static void tile_should_survive_allocation_failures(void)
{
    ttile t;
    qc_params par = params(QC_FAMILY_STIPPLE, 20, QC_TILE_ALL_OVER, 2, 2, 1);
    size_t k, base;
    int rc = QC_ENOMEM;

    make_tile(80, 60, 20, 2, &t);
    base = ta.live_blocks;
    for (k = 1; rc == QC_ENOMEM && k < 5000; k++) {
        qc_path out = {0};
        ta.allocs = 0;
        ta.fail_at = k;
        rc = generate(QC_FAMILY_STIPPLE, &t, &par, &out);
        ta.fail_at = 0;
        qc_path_free(&ctx, &out);
        TEST_ASSERT_EQUAL_UINT(base, ta.live_blocks);
    }
    TEST_ASSERT_EQUAL_INT(QC_OK, rc);
    TEST_ASSERT_FALSE(ta.size_mismatch);
    free_tile(&t);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(tile_should_run_from_port_to_mirrored_port);
    RUN_TEST(tile_ports_should_refuse_a_tile_short_of_its_sides);
    RUN_TEST(tile_repeat_should_join_copies_exactly);
    RUN_TEST(tiles_side_by_side_should_not_touch);
    RUN_TEST(tile_layout_should_sew_rows_as_pieces);
    RUN_TEST(offset_rows_should_stay_clear);
    RUN_TEST(tile_should_survive_allocation_failures);
    return UNITY_END();
}
