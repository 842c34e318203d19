/* Branching tiles (§7.1, Fig. 27): the vine runs from the entry port to the
 * exit port, copies join exactly into one pantograph, motifs of neighbouring
 * copies do not touch across the seams, everything stays in the tiles. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "quiltc.h"
#include "testalloc.h"
#include "testgeom.h"
#include "unity.h"
#include "../src/deco/family_branching_tile.h"

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

/* A W x H rectangle at (X0, Y0) with jittered hex points 0.3 d inside, its
 * spanning tree and walk. */
#define X0 10.0
#define Y0 20.0

typedef struct ttile {
    qc_region r;
    qc_points pts;
    qc_edges edges;
    qc_order order;
    double w, h;
} ttile;

static void make_tile(double W, double H, double d, uint64_t seed, ttile *t)
{
    qc_vec2 rect[4];
    qc_rng rng;
    double y;
    int row = 0;

    memset(t, 0, sizeof *t);
    t->w = W;
    t->h = H;
    rect[0] = v2(X0, Y0); rect[1] = v2(X0 + W, Y0); rect[2] = v2(X0 + W, Y0 + H);
    rect[3] = v2(X0, Y0 + H);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, &t->r, rect, 4));
    qc_rng_seed(&rng, seed);
    for (y = Y0; y <= Y0 + H; y += d * 0.866, row++) {
        double x;
        for (x = X0 + (row & 1 ? d / 2 : 0); x <= X0 + W; x += d) {
            double py = y + (qc_rng_unit(&rng) - 0.5) * 0.4 * d; /* drawn first, as gcc did */
            qc_vec2 p = v2(x + (qc_rng_unit(&rng) - 0.5) * 0.4 * d, py);
            if (qc_region_contains(&t->r, p) && qc_region_boundary_distance(&t->r, p) >= 0.3 * d)
                TEST_ASSERT_EQUAL_INT(QC_OK, qc_points_push(&ctx, &t->pts, p));
        }
    }
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_mst(&ctx, t->pts.v, t->pts.n, QC_MST_MODE_DELAUNAY, &t->edges));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_tree_walk(&ctx, t->pts.v, t->pts.n, t->edges.e, t->edges.n,
                                              0, &t->order));
}

static void free_tile(ttile *t)
{
    qc_region_free(&ctx, &t->r);
    qc_points_free(&ctx, &t->pts);
    qc_edges_free(&ctx, &t->edges);
    qc_order_free(&ctx, &t->order);
}

static qc_skeleton skel_of(const ttile *t)
{
    qc_skeleton s;
    memset(&s, 0, sizeof s);
    s.p = t->pts.v;
    s.n = t->pts.n;
    s.edges = t->edges.e;
    s.nedges = t->edges.n;
    s.order = t->order.i;
    s.norder = t->order.n;
    return s;
}

/* Resolved branching parameters; size 0 keeps the default (d/2). */
static qc_params params(double d, int tile, int cols, int rows, double size, uint64_t seed)
{
    qc_params p, r;
    memset(&p, 0, sizeof p);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "family", QC_FAMILY_BRANCHING));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "spacing", d));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "tile", tile));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "repeat-cols", cols));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "repeat-rows", rows));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "seed", (double)seed));
    if (size > 0)
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "size", size));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_resolve(&ctx, &p, &r));
    return r;
}

static int run(const ttile *t, const qc_params *par, qc_path *out, qc__placement *pl)
{
    qc_skeleton s = skel_of(t);
    return qc__branching_run(&ctx, &t->r, par, &s, NULL, out, NULL, pl);
}

static void flatten(const qc_path *p, qc_points *flat)
{
    qc_order ends = {0};
    memset(flat, 0, sizeof *flat);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_curve_flatten(&ctx, p, 0.01, flat, &ends));
    TEST_ASSERT_TRUE(ends.n >= 1); /* a piece per pantograph row */
    qc_order_free(&ctx, &ends);
}

/* Largest distance by which the path leaves the box [x0, x1] x [y0, y1]. */
static double outside(const qc_path *p, double x0, double y0, double x1, double y1)
{
    qc_points flat;
    double worst = 0;
    size_t i;

    flatten(p, &flat);
    for (i = 0; i < flat.n; i++) {
        worst = fmax(worst, fmax(x0 - flat.v[i].x, flat.v[i].x - x1));
        worst = fmax(worst, fmax(y0 - flat.v[i].y, flat.v[i].y - y1));
    }
    qc_points_free(&ctx, &flat);
    return worst;
}

static int is_edge(const qc_skeleton *s, uint32_t a, uint32_t b)
{
    size_t k;
    for (k = 0; k < s->nedges; k++)
        if ((s->edges[k].a == a && s->edges[k].b == b) ||
            (s->edges[k].a == b && s->edges[k].b == a))
            return 1;
    return 0;
}

static void tile_walk_should_run_from_port_to_port(void)
{
    int mode;

    for (mode = QC_TILE_EDGE_TO_EDGE; mode <= QC_TILE_ALL_OVER; mode++) {
        ttile t;
        qc_skeleton s = {0}, w = {0};
        qc__btile bt;
        qc_vec2 in, out;
        size_t n, i, k, *times, on_path = 0;
        unsigned char *seen;

        make_tile(120, 80, 10, 3, &t);
        s = skel_of(&t);
        n = s.n;
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_tile_ports(&ctx, &t.r, &in, &out));
        TEST_ASSERT_EQUAL_INT(QC_OK, qc__btile_make(&ctx, &t.r, &s, mode == QC_TILE_ALL_OVER,
                                                    &bt, &w));
        TEST_ASSERT_EQUAL_UINT(mode == QC_TILE_ALL_OVER ? 8 : 2, bt.nshift);
        TEST_ASSERT_EQUAL_DOUBLE(120.0, bt.dx);
        TEST_ASSERT_EQUAL_DOUBLE(80.0, bt.dy);
        TEST_ASSERT_EQUAL_UINT(n + 2, w.n);
        TEST_ASSERT_EQUAL_UINT(n + 1, w.nedges);
        TEST_ASSERT_EQUAL_UINT(n, w.root);
        TEST_ASSERT_EQUAL_MEMORY(&in, &w.p[n], sizeof in);
        TEST_ASSERT_EQUAL_MEMORY(&out, &w.p[n + 1], sizeof out);
        TEST_ASSERT_EQUAL_UINT(n, w.order[0]);
        TEST_ASSERT_EQUAL_UINT(n + 1, w.order[w.norder - 1]);
        /* every step is a tree edge; the ports are visited once */
        times = calloc(w.nedges, sizeof *times);
        seen = calloc(w.n, 1);
        for (i = 0; i < w.norder; i++) {
            seen[w.order[i]] = 1;
            if (i > 0 && i + 1 < w.norder)
                TEST_ASSERT_TRUE(w.order[i] < n);
            if (i == 0)
                continue;
            TEST_ASSERT_TRUE(is_edge(&w, w.order[i - 1], w.order[i]));
            for (k = 0; k < w.nedges; k++)
                if ((w.edges[k].a == w.order[i - 1] && w.edges[k].b == w.order[i]) ||
                    (w.edges[k].b == w.order[i - 1] && w.edges[k].a == w.order[i]))
                    times[k]++;
        }
        for (i = 0; i < w.n; i++)
            TEST_ASSERT_TRUE(seen[i]);
        /* the entry-exit path once, every other edge down and back */
        for (k = 0; k < w.nedges; k++) {
            TEST_ASSERT_TRUE(times[k] == 1 || times[k] == 2);
            on_path += times[k] == 1;
        }
        TEST_ASSERT_TRUE(times[n - 1] == 1 && times[n] == 1); /* the stubs */
        TEST_ASSERT_EQUAL_UINT(2 * w.nedges - on_path + 1, w.norder);
        /* the stubs cross no tree edge */
        for (i = n - 1; i <= n; i++)
            for (k = 0; k + 1 < n; k++) {
                qc_vec2 a = w.p[w.edges[i].a], b = w.p[w.edges[i].b];
                qc_vec2 c = w.p[w.edges[k].a], d = w.p[w.edges[k].b];
                if (w.edges[k].a == w.edges[i].a || w.edges[k].b == w.edges[i].a)
                    continue;
                TEST_ASSERT_FALSE(qc_orient2d(a, b, c) * qc_orient2d(a, b, d) < 0 &&
                                  qc_orient2d(c, d, a) * qc_orient2d(c, d, b) < 0);
            }
        free(times);
        free(seen);
        qc__btile_free(&ctx, &bt);
        free_tile(&t);
        TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
    }
}

static void tile_should_start_at_entry_and_end_at_exit(void)
{
    int mode;
    uint64_t seed;

    for (mode = QC_TILE_EDGE_TO_EDGE; mode <= QC_TILE_ALL_OVER; mode++)
        for (seed = 1; seed <= 4; seed++) {
            ttile t;
            qc_params par = params(10, mode, 1, 1, 0, seed);
            qc_path p = {0};
            qc_vec2 in, out;
            size_t c;

            make_tile(120, 80, 10, seed, &t);
            TEST_ASSERT_EQUAL_INT(QC_OK, qc_tile_ports(&ctx, &t.r, &in, &out));
            TEST_ASSERT_EQUAL_INT(QC_OK, run(&t, &par, &p, NULL));
            TEST_ASSERT_EQUAL_UINT(1, qc_path_pieces(&p));
            TEST_ASSERT_EQUAL_INT(QC_PATH_MOVE, p.cmd[0]);
            for (c = 1; c < p.ncmd; c++)
                TEST_ASSERT_TRUE(p.cmd[c] != QC_PATH_MOVE);
            TEST_ASSERT_EQUAL_MEMORY(&in, &p.pt[0], sizeof in);
            TEST_ASSERT_EQUAL_MEMORY(&out, &p.pt[p.npt - 1], sizeof out);
            /* horizontal at both ports, so copies join smoothly */
            TEST_ASSERT_EQUAL_INT(QC_PATH_CUBIC, p.cmd[1]);
            TEST_ASSERT_EQUAL_INT(QC_PATH_CUBIC, p.cmd[p.ncmd - 1]);
            TEST_ASSERT_EQUAL_DOUBLE(in.y, p.pt[1].y);
            TEST_ASSERT_TRUE(p.pt[1].x > in.x);
            TEST_ASSERT_EQUAL_DOUBLE(out.y, p.pt[p.npt - 2].y);
            TEST_ASSERT_TRUE(p.pt[p.npt - 2].x < out.x);
            TEST_ASSERT_EQUAL_DOUBLE(0.0, outside(&p, X0, Y0, X0 + 120, Y0 + 80));
            qc_path_free(&ctx, &p);
            free_tile(&t);
            TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
        }
}

/* The 3x2 layout is the tile copied: row 0 left to right, row 1 reversed,
 * each copy starting exactly where the previous one ends; each row is its
 * own piece (the row change is a jump). */
static void copies_should_join_exactly(void)
{
    int mode;

    for (mode = QC_TILE_EDGE_TO_EDGE; mode <= QC_TILE_ALL_OVER; mode++) {
        ttile t;
        qc_params one = params(10, mode, 1, 1, 0, 7), many = params(10, mode, 3, 2, 0, 7);
        qc_path p = {0}, all = {0};
        size_t m, c, k, at;
        double H = 80, W = 120;

        make_tile(W, H, 10, 7, &t);
        TEST_ASSERT_EQUAL_INT(QC_OK, run(&t, &one, &p, NULL));
        TEST_ASSERT_EQUAL_INT(QC_OK, run(&t, &many, &all, NULL));
        TEST_ASSERT_EQUAL_UINT(2, qc_path_pieces(&all));
        m = p.npt - 1; /* points per copy after its first */
        TEST_ASSERT_EQUAL_UINT(1 + 6 * (p.ncmd - 1) + 1, all.ncmd);
        TEST_ASSERT_EQUAL_UINT(1 + 6 * m + 1, all.npt);
        /* row 0 sits a tile height up; it starts at the entry port */
        TEST_ASSERT_EQUAL_DOUBLE(p.pt[0].x, all.pt[0].x);
        TEST_ASSERT_EQUAL_DOUBLE(p.pt[0].y + H, all.pt[0].y);
        for (c = 0; c < 3; c++) {
            for (k = 1; k <= m; k++) {
                at = 1 + c * m + (k - 1);
                TEST_ASSERT_DOUBLE_WITHIN(1e-9, p.pt[k].x + (double)c * W, all.pt[at].x);
                TEST_ASSERT_DOUBLE_WITHIN(1e-9, p.pt[k].y + H, all.pt[at].y);
            }
            /* the end of copy c is the start of copy c + 1 */
            at = 1 + c * m + (m - 1);
            TEST_ASSERT_DOUBLE_WITHIN(1e-9, p.pt[0].x + (double)(c + 1) * W, all.pt[at].x);
            TEST_ASSERT_DOUBLE_WITHIN(1e-9, p.pt[0].y + H, all.pt[at].y);
        }
        /* a jump down the outer edge to row 1, which runs back reversed */
        at = 1 + 3 * m;
        TEST_ASSERT_EQUAL_INT(QC_PATH_MOVE, all.cmd[1 + 3 * (p.ncmd - 1)]);
        TEST_ASSERT_EQUAL_DOUBLE(all.pt[at - 1].x, all.pt[at].x);
        TEST_ASSERT_DOUBLE_WITHIN(1e-9, p.pt[m].y, all.pt[at].y);
        for (c = 0; c < 3; c++)
            for (k = 0; k < m; k++) { /* copy col 2 - c, point m - 1 - k of the tile */
                at = 1 + 3 * m + 1 + c * m + k;
                TEST_ASSERT_DOUBLE_WITHIN(1e-9, p.pt[m - 1 - k].x + (double)(2 - c) * W,
                                          all.pt[at].x);
                TEST_ASSERT_DOUBLE_WITHIN(1e-9, p.pt[m - 1 - k].y, all.pt[at].y);
            }
        TEST_ASSERT_EQUAL_DOUBLE(p.pt[0].x, all.pt[all.npt - 1].x);
        TEST_ASSERT_EQUAL_DOUBLE(p.pt[0].y, all.pt[all.npt - 1].y);
        /* inside the union of the six tiles */
        TEST_ASSERT_EQUAL_DOUBLE(0.0, outside(&all, X0, Y0, X0 + 3 * W, Y0 + 2 * H));
        TEST_ASSERT_DOUBLE_WITHIN(1e-6, 6.0 * qc_curve_length(&p, 0), /* the jump not sewn */
                                  qc_curve_length(&all, 0));
        qc_path_free(&ctx, &p);
        qc_path_free(&ctx, &all);
        free_tile(&t);
        TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
    }
}

static void hull(const qc_points *v, const qc_order *end, size_t i, qc_vec2 shift, qc_vec2 *out,
                 size_t *n)
{
    size_t a = i ? end->i[i - 1] : 0, b = end->i[i], k;
    for (k = a; k < b; k++)
        out[k - a] = v2(v->v[k].x + shift.x, v->v[k].y + shift.y);
    *n = b - a;
}

/* Two copies side by side (and above for all-over): no motif of one
 * touches a motif or the vine of the other. Returns the pairs of hulls
 * whose boxes come within s of each other across the seams. */
static size_t check_seams(const ttile *t, int mode, double size, uint64_t seed)
{
    qc_params par = params(10, mode, 1, 1, size, seed);
    qc__placement pl;
    qc_path p = {0};
    qc_vec2 shifts[4], a[512], b[512];
    size_t ns = mode == QC_TILE_ALL_OVER ? 4 : 1, si, i, j, k, na, nb, near = 0, nm;
    size_t left = 0, right = 0;

    memset(&pl, 0, sizeof pl);
    shifts[0] = v2(t->w, 0);
    shifts[1] = v2(0, t->h);
    shifts[2] = v2(t->w, t->h);
    shifts[3] = v2(-t->w, t->h);
    TEST_ASSERT_EQUAL_INT(QC_OK, run(t, &par, &p, &pl));
    nm = pl.full_end.n;
    TEST_ASSERT_GREATER_THAN_UINT(20, nm);
    for (i = 0; i < nm; i++) {
        hull(&pl.full, &pl.full_end, i, v2(0, 0), a, &na);
        TEST_ASSERT_TRUE(na <= 512);
        for (k = 0; k < na; k++) {
            left += a[k].x < X0 + par.size;
            right += a[k].x > X0 + t->w - par.size;
        }
    }
    TEST_ASSERT_TRUE(left > 0 && right > 0); /* motifs crowd both seams */
    for (si = 0; si < ns; si++)
        for (i = 0; i < nm; i++) {
            hull(&pl.full, &pl.full_end, i, v2(0, 0), a, &na);
            for (j = 0; j < nm; j++) { /* every pair: the far copy's motif j */
                double ax0 = HUGE_VAL, ax1 = -HUGE_VAL, bx0 = HUGE_VAL, bx1 = -HUGE_VAL;
                double ay0 = HUGE_VAL, ay1 = -HUGE_VAL, by0 = HUGE_VAL, by1 = -HUGE_VAL;
                hull(&pl.full, &pl.full_end, j, shifts[si], b, &nb);
                TEST_ASSERT_FALSE(qc__convex_touch(a, na, b, nb, 0));
                for (k = 0; k < na; k++) {
                    ax0 = fmin(ax0, a[k].x); ax1 = fmax(ax1, a[k].x);
                    ay0 = fmin(ay0, a[k].y); ay1 = fmax(ay1, a[k].y);
                }
                for (k = 0; k < nb; k++) {
                    bx0 = fmin(bx0, b[k].x); bx1 = fmax(bx1, b[k].x);
                    by0 = fmin(by0, b[k].y); by1 = fmax(by1, b[k].y);
                }
                near += ax1 + par.size > bx0 && bx1 + par.size > ax0 &&
                        ay1 + par.size > by0 && by1 + par.size > ay0;
            }
            /* each copy's motif bodies keep off the other's vine, both ways */
            hull(&pl.body, &pl.body_end, i, v2(0, 0), a, &na);
            hull(&pl.body, &pl.body_end, i, shifts[si], b, &nb);
            for (k = 0; k + 1 < pl.vine.n; k++) {
                qc_vec2 e[2], f[2];
                e[0] = v2(pl.vine.v[k].x + shifts[si].x, pl.vine.v[k].y + shifts[si].y);
                e[1] = v2(pl.vine.v[k + 1].x + shifts[si].x, pl.vine.v[k + 1].y + shifts[si].y);
                f[0] = v2(pl.vine.v[k].x, pl.vine.v[k].y);
                f[1] = v2(pl.vine.v[k + 1].x, pl.vine.v[k + 1].y);
                TEST_ASSERT_FALSE(qc__convex_touch(a, na, e, 2, 0));
                TEST_ASSERT_FALSE(qc__convex_touch(b, nb, f, 2, 0));
            }
        }
    qc_path_free(&ctx, &p);
    qc__placement_free(&ctx, &pl);
    return near;
}

static void neighbours_should_not_touch_across_the_seams(void)
{
    ttile t;
    size_t near = 0;

    make_tile(90, 60, 9, 4, &t);
    near += check_seams(&t, QC_TILE_EDGE_TO_EDGE, 0, 1);
    near += check_seams(&t, QC_TILE_EDGE_TO_EDGE, 7, 2);
    near += check_seams(&t, QC_TILE_ALL_OVER, 0, 3);
    near += check_seams(&t, QC_TILE_ALL_OVER, 8, 4);
    TEST_ASSERT_GREATER_THAN_UINT(10, near); /* the test met close pairs */
    free_tile(&t);
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

/* The grid sees an item also where it sits in the neighbouring tiles. */
static void collision_grid_should_wrap(void)
{
    int mode;

    for (mode = QC_TILE_EDGE_TO_EDGE; mode <= QC_TILE_ALL_OVER; mode++) {
        ttile t;
        qc_skeleton s, w;
        qc__btile bt;
        qc__cgrid g;
        qc_bbox box;
        qc_vec2 sq[4], q[4];
        int k;

        make_tile(90, 60, 15, 1, &t);
        s = skel_of(&t);
        TEST_ASSERT_EQUAL_INT(QC_OK, qc__btile_make(&ctx, &t.r, &s, mode == QC_TILE_ALL_OVER,
                                                    &bt, &w));
        box = qc_region_bbox(&t.r);
        box.min.x -= 5; box.min.y -= 5; box.max.x += 5; box.max.y += 5;
        TEST_ASSERT_EQUAL_INT(QC_OK, qc__cgrid_init(&ctx, &g, box, 5, 4096));
        /* a square in the top right corner, 1 mm in from both edges */
        sq[0] = v2(X0 + 87, Y0 + 57); sq[1] = v2(X0 + 89, Y0 + 57);
        sq[2] = v2(X0 + 89, Y0 + 59); sq[3] = v2(X0 + 87, Y0 + 59);
        TEST_ASSERT_EQUAL_INT(QC_OK, qc__btile_grid_add(&ctx, &bt, &g, sq, 4, 2, 7));
        /* probes overlapping its copies: left (x - 90), below (y - 60), diagonal */
        for (k = 0; k < 4; k++)
            q[k] = v2(sq[k].x - 90 + 0.5, sq[k].y);
        TEST_ASSERT_TRUE(qc__cgrid_hit(&g, q, 4, 1u << 2, NULL, NULL));
        TEST_ASSERT_FALSE(qc__cgrid_hit(&g, q, 4, 1u << 1, NULL, NULL)); /* kinds kept */
        for (k = 0; k < 4; k++)
            q[k] = v2(sq[k].x + 0.5, sq[k].y - 60);
        TEST_ASSERT_EQUAL_INT(mode == QC_TILE_ALL_OVER, qc__cgrid_hit(&g, q, 4, 1u << 2, NULL, NULL));
        for (k = 0; k < 4; k++)
            q[k] = v2(sq[k].x - 90 + 0.5, sq[k].y - 60 + 0.5);
        TEST_ASSERT_EQUAL_INT(mode == QC_TILE_ALL_OVER, qc__cgrid_hit(&g, q, 4, 1u << 2, NULL, NULL));
        for (k = 0; k < 4; k++) /* well away from every copy */
            q[k] = v2(sq[k].x - 45, sq[k].y - 30);
        TEST_ASSERT_FALSE(qc__cgrid_hit(&g, q, 4, 1u << 2, NULL, NULL));
        /* copies beyond the grid are not stored: the middle square has none */
        {
            size_t before = g.nitem;
            for (k = 0; k < 4; k++)
                q[k] = v2(sq[k].x - 45, sq[k].y - 30);
            TEST_ASSERT_EQUAL_INT(QC_OK, qc__btile_grid_add(&ctx, &bt, &g, q, 4, 2, 8));
            TEST_ASSERT_EQUAL_UINT(before + 1, g.nitem);
        }
        qc__cgrid_free(&ctx, &g);
        qc__btile_free(&ctx, &bt);
        free_tile(&t);
        TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
    }
}

static void tile_should_be_deterministic(void)
{
    ttile t;
    qc_params par = params(10, QC_TILE_ALL_OVER, 2, 3, 0, 11);
    qc_path a = {0}, b = {0};

    make_tile(100, 70, 10, 11, &t);
    TEST_ASSERT_EQUAL_INT(QC_OK, run(&t, &par, &a, NULL));
    TEST_ASSERT_EQUAL_INT(QC_OK, run(&t, &par, &b, NULL));
    TEST_ASSERT_EQUAL_UINT(a.ncmd, b.ncmd);
    TEST_ASSERT_EQUAL_UINT(a.npt, b.npt);
    TEST_ASSERT_EQUAL_MEMORY(a.cmd, b.cmd, a.ncmd);
    TEST_ASSERT_EQUAL_MEMORY(a.pt, b.pt, a.npt * sizeof *a.pt);
    qc_path_free(&ctx, &a);
    qc_path_free(&ctx, &b);
    free_tile(&t);
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

static void expect_error(const ttile *t, const qc_skeleton *s, int status, const char *needle)
{
    qc_params par = params(10, QC_TILE_EDGE_TO_EDGE, 2, 1, 0, 1);
    qc_path p = {0};

    TEST_ASSERT_EQUAL_INT(status, qc__branching_run(&ctx, &t->r, &par, s, NULL, &p, NULL, NULL));
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(qc_errmsg(&ctx), needle), qc_errmsg(&ctx));
    TEST_ASSERT_EQUAL_UINT(0, p.ncmd);
    qc_path_free(&ctx, &p);
}

static void tile_should_refuse_a_skeleton_without_a_tree(void)
{
    ttile t;
    qc_skeleton s;
    qc_edge e;

    make_tile(90, 60, 15, 2, &t);
    s = skel_of(&t);
    s.edges = NULL; /* a tour */
    s.nedges = 0;
    expect_error(&t, &s, QC_EINVAL, "spanning tree (skeleton mst)");
    s = skel_of(&t);
    s.nedges--; /* one edge short */
    expect_error(&t, &s, QC_EINVAL, "got");
    s = skel_of(&t);
    e = t.edges.e[0];
    t.edges.e[0] = t.edges.e[1]; /* an edge twice, one point cut off */
    expect_error(&t, &s, QC_EINVAL, "cycle");
    t.edges.e[0] = e;
    t.edges.e[0].b = (uint32_t)t.pts.n; /* out of range */
    expect_error(&t, &s, QC_EINVAL, "is not an edge");
    t.edges.e[0] = e;
    free_tile(&t);
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

/* One point: entry, the point, exit. */
static void tile_of_one_point_should_run_port_to_port(void)
{
    ttile t;
    qc_vec2 one = {40, 50}, in, out;
    qc_skeleton s;
    uint32_t root = 0;
    qc_params par = params(10, QC_TILE_EDGE_TO_EDGE, 2, 1, 0, 1);
    qc_path p = {0};

    make_tile(60, 40, 30, 1, &t);
    memset(&s, 0, sizeof s);
    s.p = &one;
    s.n = 1;
    s.order = &root;
    s.norder = 1;
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_tile_ports(&ctx, &t.r, &in, &out));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc__branching_run(&ctx, &t.r, &par, &s, NULL, &p, NULL, NULL));
    TEST_ASSERT_EQUAL_UINT(1, qc_path_pieces(&p));
    TEST_ASSERT_EQUAL_MEMORY(&in, &p.pt[0], sizeof in);
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, out.x + 60, p.pt[p.npt - 1].x);
    TEST_ASSERT_EQUAL_DOUBLE(out.y, p.pt[p.npt - 1].y);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, outside(&p, X0, Y0, X0 + 120, Y0 + 40));
    qc_path_free(&ctx, &p);
    free_tile(&t);
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

/* Through qc_generate: one piece per row inside the union of the tiles. */
static void generate_should_lay_out_tiles(void)
{
    qc_region r = {0};
    qc_vec2 rect[4];
    qc_params p;
    qc_result res;

    rect[0] = v2(0, 0); rect[1] = v2(100, 0); rect[2] = v2(100, 100); rect[3] = v2(0, 100);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, &r, rect, 4));
    memset(&p, 0, sizeof p);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "family", QC_FAMILY_BRANCHING));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "spacing", 15));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "tile", QC_TILE_ALL_OVER));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "repeat-cols", 2));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "repeat-rows", 2));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_generate(&ctx, &r, &p, NULL, NULL, &res));
    TEST_ASSERT_EQUAL_UINT(2, res.stats.pieces);
    TEST_ASSERT_GREATER_THAN_UINT(10, res.stats.motifs_placed);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, res.path.pt[0].x);
    TEST_ASSERT_EQUAL_DOUBLE(150.0, res.path.pt[0].y);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, outside(&res.path, 0, 0, 200, 200));
    qc_result_free(&ctx, &res);
    qc_region_free(&ctx, &r);
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

static void tile_should_survive_allocation_failures(void)
{
    int mode;

    for (mode = QC_TILE_EDGE_TO_EDGE; mode <= QC_TILE_ALL_OVER; mode++) {
        ttile t;
        qc_params par = params(20, mode, 2, 2, 0, 5);
        qc__placement pl;
        size_t k, base;
        int rc = QC_ENOMEM;

        make_tile(80, 60, 20, 2, &t);
        base = ta.live_blocks;
        for (k = 1; rc == QC_ENOMEM && k < 5000; k++) {
            qc_path out = {0};
            memset(&pl, 0, sizeof pl);
            ta.allocs = 0;
            ta.fail_at = k;
            rc = run(&t, &par, &out, &pl);
            ta.fail_at = 0;
            if (rc == QC_ENOMEM)
                TEST_ASSERT_EQUAL_UINT(0, out.ncmd);
            qc_path_free(&ctx, &out);
            qc__placement_free(&ctx, &pl);
            TEST_ASSERT_EQUAL_UINT(base, ta.live_blocks);
        }
        TEST_ASSERT_EQUAL_INT(QC_OK, rc);
        TEST_ASSERT_GREATER_THAN_UINT(20, k); /* the sweep failed many allocations */
        TEST_ASSERT_FALSE(ta.size_mismatch);
        free_tile(&t);
        TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(tile_walk_should_run_from_port_to_port);
    RUN_TEST(tile_should_start_at_entry_and_end_at_exit);
    RUN_TEST(copies_should_join_exactly);
    RUN_TEST(neighbours_should_not_touch_across_the_seams);
    RUN_TEST(collision_grid_should_wrap);
    RUN_TEST(tile_should_be_deterministic);
    RUN_TEST(tile_should_refuse_a_skeleton_without_a_tree);
    RUN_TEST(tile_of_one_point_should_run_port_to_port);
    RUN_TEST(generate_should_lay_out_tiles);
    RUN_TEST(tile_should_survive_allocation_failures);
    return UNITY_END();
}
