/* Wanderer (§5.2): one closed piece, joins leaving and meeting the legs with
 * tangents l * |P0P3|, inside the region, deterministic, no leaks. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "quiltc.h"
#include "testalloc.h"
#include "testgeom.h"
#include "unity.h"
#include "../src/deco/family_wanderer.h"

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

/* A tour skeleton (caller frees p and order). */
typedef struct ttour {
    qc_vec2 *p;
    uint32_t *order;
    size_t n;
    qc_region r;
} ttour;

/* A square of side cols * d with a jittered grid and a Hamiltonian cycle:
 * row 0 and the serpentine over columns 1.., back down column 0. rows even. */
static void square_tour(int cols, int rows, double d, uint64_t seed, ttour *t)
{
    qc_vec2 sq[4];
    qc_rng rng;
    int r, c, k = 0;

    qc_rng_seed(&rng, seed);
    sq[0] = v2(0, 0);
    sq[1] = v2(cols * d, 0);
    sq[2] = v2(cols * d, rows * d);
    sq[3] = v2(0, rows * d);
    memset(&t->r, 0, sizeof t->r);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, &t->r, sq, 4));
    t->n = (size_t)(cols * rows);
    t->p = malloc(t->n * sizeof *t->p);
    t->order = malloc(t->n * sizeof *t->order);
    for (r = 0; r < rows; r++)
        for (c = 0; c < cols; c++) { /* y drawn first, as gcc drew the arguments */
            double y = (r + 0.5 + (qc_rng_unit(&rng) - 0.5) * 0.3) * d;

            t->p[r * cols + c] = v2((c + 0.5 + (qc_rng_unit(&rng) - 0.5) * 0.3) * d, y);
        }
    for (r = 0; r < rows; r++)
        for (c = 1; c < cols; c++)
            t->order[k++] = (uint32_t)(r * cols + ((r & 1) ? cols - c : c));
    for (r = rows - 1; r >= 0; r--)
        t->order[k++] = (uint32_t)(r * cols);
}

/* A disc of radius R with m points on a ring, toured round. */
static void circle_tour(double R, int m, ttour *t)
{
    qc_vec2 ring[64];
    int i;

    for (i = 0; i < 64; i++)
        ring[i] = v2(R * qc_cos(2 * QC_PI * i / 64), R * qc_sin(2 * QC_PI * i / 64));
    memset(&t->r, 0, sizeof t->r);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, &t->r, ring, 64));
    t->n = (size_t)m;
    t->p = malloc(t->n * sizeof *t->p);
    t->order = malloc(t->n * sizeof *t->order);
    for (i = 0; i < m; i++) {
        double a = 2 * QC_PI * i / m;
        t->p[i] = v2(0.7 * R * qc_cos(a), 0.7 * R * qc_sin(a));
        t->order[i] = (uint32_t)i;
    }
}

static void free_tour(ttour *t)
{
    free(t->p);
    free(t->order);
    qc_region_free(&ctx, &t->r);
}

static qc_skeleton as_skel(const ttour *t)
{
    qc_skeleton s;
    memset(&s, 0, sizeof s);
    s.p = t->p;
    s.n = t->n;
    s.order = t->order;
    s.norder = t->n;
    return s;
}

static qc_params params(double tangent)
{
    qc_params p;
    memset(&p, 0, sizeof p);
    p.seed = 1;
    p.spacing = 10;
    p.size = 5;
    p.tangent = tangent;
    return p;
}

static double cross(qc_vec2 a, qc_vec2 b)
{
    return a.x * b.y - a.y * b.x;
}

static qc_vec2 sub(qc_vec2 a, qc_vec2 b)
{
    return v2(a.x - b.x, a.y - b.y);
}

static int seg_cross(qc_vec2 a, qc_vec2 b, qc_vec2 c, qc_vec2 d)
{
    double d1 = cross(sub(b, a), sub(c, a)), d2 = cross(sub(b, a), sub(d, a));
    double d3 = cross(sub(d, c), sub(a, c)), d4 = cross(sub(d, c), sub(b, c));
    return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

/* Joins (flattened) that cross an earlier, non-adjacent join: each must be counted. */
static size_t crossing_joins(const qc_path *out, size_t n)
{
    enum { K = 32 };
    qc_vec2 *f = malloc(n * (K + 1) * sizeof *f);
    size_t a, b, i, j, count = 0;

    for (a = 0; a < n; a++) {
        const qc_vec2 *q = out->pt + 9 * a + 6;
        for (i = 0; i <= K; i++) {
            double t = (double)i / K, u = 1 - t;
            f[a * (K + 1) + i].x = u * u * u * q[0].x + 3 * u * u * t * q[1].x + 3 * u * t * t * q[2].x + t * t * t * q[3].x;
            f[a * (K + 1) + i].y = u * u * u * q[0].y + 3 * u * u * t * q[1].y + 3 * u * t * t * q[2].y + t * t * t * q[3].y;
        }
    }
    for (b = 1; b < n; b++) {
        int hit = 0;
        for (a = 0; a + 1 < b && !hit; a++) {
            if (a == 0 && b == n - 1)
                continue;
            for (i = 0; i < K && !hit; i++)
                for (j = 0; j < K && !hit; j++)
                    hit = seg_cross(f[a * (K + 1) + i], f[a * (K + 1) + i + 1], f[b * (K + 1) + j],
                                    f[b * (K + 1) + j + 1]);
        }
        count += hit;
    }
    free(f);
    return count;
}

/* With one loop variant the path is MOVE, then per point two body cubics and the join. */
static void check_joins(const ttour *t, double l, size_t max_unfixed)
{
    qc_skeleton sk = as_skel(t);
    qc_params par = params(l);
    qc_motif_set set = {0};
    qc_path out = {0};
    qc_stats st;
    qc_points flat = {0};
    size_t i;

    memset(&st, 0, sizeof st);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_motif_builtin(&ctx, "loop60", &set));
    TEST_ASSERT_EQUAL_INT(2, (int)set.m[0].path.ncmd - 1);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_deco_wanderer(&ctx, &t->r, &par, &sk, &set, &out, &st));
    TEST_ASSERT_EQUAL_UINT(1, qc_path_pieces(&out));
    TEST_ASSERT_EQUAL_UINT(1 + 3 * t->n, out.ncmd);
    TEST_ASSERT_EQUAL_UINT(t->n, st.motifs_placed);
    TEST_ASSERT_TRUE(st.joins_unfixed <= max_unfixed);
    TEST_ASSERT_TRUE(crossing_joins(&out, t->n) <= st.joins_unfixed);
    for (i = 0; i < t->n; i++) {
        const qc_vec2 *q = out.pt + 9 * i;
        qc_vec2 prev_c = q[5], p0 = q[6], p1 = q[7], p2 = q[8], p3 = q[9];
        qc_vec2 next_c = i + 1 < t->n ? q[10] : out.pt[1];
        double len = qc_hypot(p3.x - p0.x, p3.y - p0.y);
        double t0 = qc_hypot(p1.x - p0.x, p1.y - p0.y), t1 = qc_hypot(p3.x - p2.x, p3.y - p2.y);
        double ratio = l > 0 ? t0 / (l * len) : 0;
        TEST_ASSERT_EQUAL_INT(QC_PATH_CUBIC, out.cmd[3 + 3 * i]);
        if (i + 1 == t->n) /* the tour closes on the first primitive's entry */
            TEST_ASSERT_EQUAL_MEMORY(&out.pt[0], &p3, sizeof p3);
        TEST_ASSERT_DOUBLE_WITHIN(1e-9, t0, t1);
        /* the stated tangent, or a shorter one that cleared a crossing */
        TEST_ASSERT_TRUE(fabs(ratio - 1) < 1e-9 || fabs(ratio - 0.5) < 1e-9 ||
                         fabs(ratio - 0.25) < 1e-9 || t0 < 1e-12);
        if (t0 > 1e-12) { /* along the leg: the body's tangent continued */
            qc_vec2 a = sub(p1, p0), b = sub(p0, prev_c), c = sub(p3, p2), d = sub(next_c, p3);
            TEST_ASSERT_DOUBLE_WITHIN(1e-9, 0, cross(a, b) / (qc_hypot(a.x, a.y) * qc_hypot(b.x, b.y)));
            TEST_ASSERT_TRUE(a.x * b.x + a.y * b.y > 0);
            TEST_ASSERT_DOUBLE_WITHIN(1e-9, 0, cross(c, d) / (qc_hypot(c.x, c.y) * qc_hypot(d.x, d.y)));
            TEST_ASSERT_TRUE(c.x * d.x + c.y * d.y > 0);
        }
    }
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_curve_flatten(&ctx, &out, 0.01, &flat, NULL));
    for (i = 0; i < flat.n; i++)
        TEST_ASSERT_TRUE(qc_region_contains(&t->r, flat.v[i]));
    qc_points_free(&ctx, &flat);
    qc_path_free(&ctx, &out);
    qc_motif_set_free(&ctx, &set);
}

static void wanderer_should_join_legs_with_stated_tangents_in_a_square(void)
{
    ttour t;
    square_tour(8, 6, 10, 3, &t);
    check_joins(&t, 0.5, 12); /* the U-turns at the row ends may stay crossed */
    check_joins(&t, 0.2, 12);
    check_joins(&t, 0, 12);
    free_tour(&t);
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

static void wanderer_should_join_legs_in_a_circle(void)
{
    ttour t;
    circle_tour(50, 12, &t);
    check_joins(&t, 0.5, 0); /* round a ring nothing crosses */
    free_tour(&t);
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

static void wanderer_should_choose_variants_and_repeat_for_a_seed(void)
{
    ttour t;
    qc_skeleton sk;
    qc_params par = params(0.5);
    qc_path a = {0}, b = {0};
    qc_stats st;

    square_tour(6, 4, 10, 5, &t);
    sk = as_skel(&t);
    memset(&st, 0, sizeof st);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_deco_wanderer(&ctx, &t.r, &par, &sk, NULL, &a, &st));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_deco_wanderer(&ctx, &t.r, &par, &sk, NULL, &b, NULL));
    TEST_ASSERT_EQUAL_UINT(1, qc_path_pieces(&a));
    TEST_ASSERT_EQUAL_UINT(a.ncmd, b.ncmd);
    TEST_ASSERT_EQUAL_MEMORY(a.cmd, b.cmd, a.ncmd);
    TEST_ASSERT_EQUAL_MEMORY(a.pt, b.pt, a.npt * sizeof *a.pt);
    TEST_ASSERT_EQUAL_UINT(t.n, st.motifs_placed);
    qc_path_free(&ctx, &a);
    qc_path_free(&ctx, &b);
    free_tour(&t);
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

static void wanderer_should_use_the_legged_variants_of_a_named_motif(void)
{
    ttour t;
    qc_skeleton sk;
    qc_params par = params(0.5);
    qc_motif_set set = {0};
    qc_path out = {0};

    square_tour(4, 2, 10, 4, &t);
    sk = as_skel(&t);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_motif_builtin(&ctx, "heart", &set));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_deco_wanderer(&ctx, &t.r, &par, &sk, &set, &out, NULL));
    /* heart60/heart90 bodies are four cubics, plus the join */
    TEST_ASSERT_EQUAL_UINT(1 + 5 * t.n, out.ncmd);
    qc_path_free(&ctx, &out);
    qc_motif_set_free(&ctx, &set);
    free_tour(&t);
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

static void wanderer_should_shrink_primitives_that_reach_the_boundary(void)
{
    ttour t;
    qc_skeleton sk;
    qc_params par = params(0.3);
    qc_path out = {0};
    qc_stats st;

    square_tour(4, 2, 10, 6, &t);
    sk = as_skel(&t);
    memset(&st, 0, sizeof st);
    par.size = 9; /* radius 4.5 mm, points about 5 mm from the edge */
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_deco_wanderer(&ctx, &t.r, &par, &sk, NULL, &out, &st));
    TEST_ASSERT_GREATER_THAN_UINT(0, st.motifs_shrunk);
    TEST_ASSERT_EQUAL_UINT(1, qc_path_pieces(&out));
    qc_path_free(&ctx, &out);
    free_tour(&t);
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

static void wanderer_should_refuse_empty_tours_and_handle_one_point(void)
{
    ttour t;
    qc_skeleton sk;
    qc_params par = params(0.5);
    qc_path out = {0};

    square_tour(2, 2, 10, 1, &t);
    sk = as_skel(&t);
    sk.norder = 0;
    TEST_ASSERT_EQUAL_INT(QC_EEMPTY, qc_deco_wanderer(&ctx, &t.r, &par, &sk, NULL, &out, NULL));
    sk.norder = 1;
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_deco_wanderer(&ctx, &t.r, &par, &sk, NULL, &out, NULL));
    TEST_ASSERT_EQUAL_UINT(1, qc_path_pieces(&out));
    qc_path_free(&ctx, &out);
    free_tour(&t);
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

static void wanderer_should_free_everything_when_allocation_fails(void)
{
    ttour t;
    qc_skeleton sk;
    qc_params par = params(0.5);
    size_t k;
    int rc = QC_ENOMEM;

    square_tour(4, 2, 10, 2, &t);
    sk = as_skel(&t);
    for (k = 1; rc == QC_ENOMEM && k < 5000; k++) {
        qc_path out = {0};
        size_t base = ta.live_blocks;
        ta.allocs = 0;
        ta.fail_at = k;
        rc = qc_deco_wanderer(&ctx, &t.r, &par, &sk, NULL, &out, NULL);
        ta.fail_at = 0;
        qc_path_free(&ctx, &out);
        TEST_ASSERT_EQUAL_UINT(base, ta.live_blocks);
    }
    TEST_ASSERT_EQUAL_INT(QC_OK, rc);
    TEST_ASSERT_FALSE(ta.size_mismatch);
    free_tour(&t);
}

/* FNV-1a over a path's commands and points: its bytes in one number. */
static uint64_t path_hash(const qc_path *p)
{
    const unsigned char *b[2];
    size_t len[2], k, i;
    uint64_t h = 14695981039346656037u;

    b[0] = (const unsigned char *)p->cmd;
    len[0] = p->ncmd * sizeof *p->cmd;
    b[1] = (const unsigned char *)p->pt;
    len[1] = p->npt * sizeof *p->pt;
    for (k = 0; k < 2; k++)
        for (i = 0; i < len[k]; i++)
            h = (h ^ b[k][i]) * 1099511628211u;
    return h;
}

/* The speedups (the join sewn last tested first, variants turned down
 * before their hull's query, the first look's placements reused by the
 * second) choose exactly what the plain search chose: the bytes and counts
 * recorded before them (commit c265654), with joins that clear, that need
 * another rung or variant, and that fail all, and the tours of two and
 * three points, whose neighbours wrap round. */
static void wanderer_should_keep_its_bytes_through_the_speedups(void)
{
    static const struct {
        const char *motifs;
        double l;
        size_t unfixed;
        uint64_t hash;
    } want[] = {
        {NULL, 0.5, 16, 0x573110792a53bdfbu},
        {NULL, 0, 18, 0x73215b1491e5a91fu},
        {"heart", 0.5, 2, 0xa8e0605d7e5e504fu},
    };
    ttour t;
    size_t k;

    square_tour(16, 12, 10, 7, &t);
    for (k = 0; k < sizeof want / sizeof want[0]; k++) {
        qc_skeleton sk = as_skel(&t);
        qc_params par = params(want[k].l);
        qc_motif_set set = {0};
        qc_path out = {0};
        qc_stats st;

        memset(&st, 0, sizeof st);
        par.size = 8;
        if (want[k].motifs != NULL)
            TEST_ASSERT_EQUAL_INT(QC_OK, qc_motif_builtin(&ctx, want[k].motifs, &set));
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_deco_wanderer(&ctx, &t.r, &par, &sk,
                                                      want[k].motifs != NULL ? &set : NULL,
                                                      &out, &st));
        TEST_ASSERT_EQUAL_UINT(want[k].unfixed, st.joins_unfixed);
        TEST_ASSERT_TRUE(want[k].hash == path_hash(&out));
        qc_path_free(&ctx, &out);
        qc_motif_set_free(&ctx, &set);
    }
    free_tour(&t);
    for (k = 2; k <= 3; k++) { /* the shortest tours: each neighbour is the other */
        static const uint64_t small[] = {0x88e25f9d772a47bcu, 0xa25f01156a2a48fau};
        qc_skeleton sk;
        qc_params par = params(0.5);
        qc_path out = {0};

        circle_tour(30, (int)k, &t);
        sk = as_skel(&t);
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_deco_wanderer(&ctx, &t.r, &par, &sk, NULL, &out, NULL));
        TEST_ASSERT_TRUE(small[k - 2] == path_hash(&out));
        qc_path_free(&ctx, &out);
        free_tour(&t);
    }
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

/* Exempts segments 2 and 3 of a query (those that meet at its point 3). */
static int skip_third(void *ud, size_t k)
{
    (void)ud;
    return k == 2 || k == 3;
}

static int skip_third_seg(void *ud, unsigned kind, uint32_t id, size_t k)
{
    (void)kind;
    (void)id;
    return skip_third(ud, k);
}

/* The kept chain reports a hit only where the collision grid holding that
 * chain finds one too (the shortcut may stop a query, never change it), and
 * on these random wiggles finds every one. */
static void wanderer_chain_should_agree_with_the_collision_grid(void)
{
    enum { NP = 17 };
    qc_rng rng;
    qc_vec2 c[NP], q[NP];
    qc__wchain kept;
    size_t trial, k, hits = 0, clear = 0;

    qc_rng_seed(&rng, 11);
    for (trial = 0; trial < 400; trial++) {
        qc__cgrid g;
        qc_bbox box;
        int fast, grid;

        qc_vec2 at = v2(20 * qc_rng_unit(&rng) - 4, 14 * qc_rng_unit(&rng) - 7);

        for (k = 0; k < NP; k++) { /* a wave, and a short wiggle somewhere near it */
            c[k] = v2(k * 1.0, 3 * qc_sin(k * 0.7 + trial) + qc_rng_unit(&rng));
            q[k] = v2(at.x + k * 0.25, at.y + 1.5 * qc_rng_unit(&rng));
        }
        if (trial % 5 == 0) /* touching at the exempt segments' joint */
            q[3] = c[5];
        box.min = v2(-10, -10);
        box.max = v2(30, 10);
        TEST_ASSERT_EQUAL_INT(QC_OK, qc__cgrid_init(&ctx, &g, box, 2, 4096));
        TEST_ASSERT_EQUAL_INT(QC_OK, qc__cgrid_add_chain(&ctx, &g, c, NP, 2, 9));
        qc__wchain_set(&kept, c, NP);
        TEST_ASSERT_EQUAL_UINT(NP, kept.n);
        fast = qc__wchain_touch(&kept, q, NP, skip_third, NULL);
        grid = qc__cgrid_hit_polyline(&g, q, NP, 1u << 2, skip_third_seg, NULL);
        TEST_ASSERT_EQUAL_INT(grid, fast);
        hits += fast != 0;
        clear += fast == 0;
        qc__cgrid_free(&ctx, &g);
    }
    TEST_ASSERT_GREATER_THAN_UINT(20, hits); /* both answers were exercised */
    TEST_ASSERT_GREATER_THAN_UINT(20, clear);
    qc__wchain_set(&kept, c, 1); /* too short to keep: never a hit */
    TEST_ASSERT_EQUAL_UINT(0, kept.n);
    TEST_ASSERT_FALSE(qc__wchain_touch(&kept, q, NP, skip_third, NULL));
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

/* A chain is filed once under every cell its segments' boxes meet, and
 * under no other: one that runs round the grid's rim twice in short steps
 * (a cell met again some 70 segments later) leaves one entry per cell. */
static void collision_grid_should_file_a_chain_once_per_cell(void)
{
    enum { SIDE = 18, NP = 8 * SIDE + 1 }; /* 0.5 mm steps, 4 sides, twice */
    qc_vec2 c[NP];
    qc__cgrid g;
    qc_bbox box;
    size_t k, cell, filed = 0;
    uint32_t x, y;
    unsigned char want[10 * 10];

    for (k = 0; k < NP; k++) { /* round (0.5, 0.5)-(9.5, 9.5), anticlockwise */
        double t = 0.5 * (double)(k % SIDE);
        size_t side = k / SIDE % 4;
        c[k] = side == 0 ? v2(0.5 + t, 0.5) : side == 1 ? v2(9.5, 0.5 + t)
             : side == 2 ? v2(9.5 - t, 9.5) : v2(0.5, 9.5 - t);
    }
    box.min = v2(0, 0);
    box.max = v2(9.99, 9.99);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc__cgrid_init(&ctx, &g, box, 1, 4096));
    TEST_ASSERT_EQUAL_UINT(10, g.nx);
    TEST_ASSERT_EQUAL_UINT(10, g.ny);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc__cgrid_add_chain(&ctx, &g, c, NP, 2, 9));
    memset(want, 0, sizeof want);
    for (k = 0; k + 1 < NP; k++) { /* the cells each segment's box meets */
        uint32_t x0 = (uint32_t)fmin(c[k].x, c[k + 1].x), x1 = (uint32_t)fmax(c[k].x, c[k + 1].x);
        uint32_t y0 = (uint32_t)fmin(c[k].y, c[k + 1].y), y1 = (uint32_t)fmax(c[k].y, c[k + 1].y);
        for (y = y0; y <= y1; y++)
            for (x = x0; x <= x1; x++)
                want[y * 10 + x] = 1;
    }
    for (cell = 0; cell < 100; cell++) {
        size_t n = 0;
        uint32_t e;
        for (e = g.head[cell]; e != UINT32_MAX; e = g.ent[e].next)
            n++;
        TEST_ASSERT_EQUAL_UINT(want[cell], n);
        filed += n;
    }
    TEST_ASSERT_EQUAL_UINT(filed, g.nent);
    TEST_ASSERT_EQUAL_UINT(36, filed); /* the rim's cells */
    qc__cgrid_free(&ctx, &g);
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(wanderer_should_join_legs_with_stated_tangents_in_a_square);
    RUN_TEST(wanderer_should_join_legs_in_a_circle);
    RUN_TEST(wanderer_should_choose_variants_and_repeat_for_a_seed);
    RUN_TEST(wanderer_should_use_the_legged_variants_of_a_named_motif);
    RUN_TEST(wanderer_should_shrink_primitives_that_reach_the_boundary);
    RUN_TEST(wanderer_should_refuse_empty_tours_and_handle_one_point);
    RUN_TEST(wanderer_should_free_everything_when_allocation_fails);
    RUN_TEST(wanderer_should_keep_its_bytes_through_the_speedups);
    RUN_TEST(wanderer_chain_should_agree_with_the_collision_grid);
    RUN_TEST(collision_grid_should_file_a_chain_once_per_cell);
    return UNITY_END();
}
