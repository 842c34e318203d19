/* Branching (§5.1): one piece, hulls clear of each other, the vine and the
 * boundary, inside the region, deterministic, no leaks on failure. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "quiltc.h"
#include "testalloc.h"
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

enum { R_SQUARE, R_HOLE, R_CIRCLE };

static void make_region(int kind, qc_region *r)
{
    qc_vec2 sq[4] = {{0, 0}, {100, 0}, {100, 100}, {0, 100}};
    qc_vec2 hole[4] = {{35, 35}, {35, 65}, {65, 65}, {65, 35}};
    qc_vec2 circ[64];
    int i;

    memset(r, 0, sizeof *r);
    if (kind == R_CIRCLE) {
        for (i = 0; i < 64; i++) {
            double a = 2 * QC_PI * i / 64;
            circ[i].x = 50 + 50 * qc_cos(a);
            circ[i].y = 50 + 50 * qc_sin(a);
        }
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, r, circ, 64));
        return;
    }
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, r, sq, 4));
    if (kind == R_HOLE)
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, r, hole, 4));
}

/* A test skeleton: jittered grid points away from the boundary, Prim's
 * tree, its depth-first walk (root first and last). Caller frees. */
typedef struct tskel {
    qc_vec2 *p;
    size_t n;
    qc_edge *e;
    uint32_t *order;
    size_t norder;
} tskel;

static void make_skeleton(const qc_region *r, double d, uint64_t seed, tskel *t)
{
    qc_rng rng;
    size_t i, j, cap = 4096;
    double x, y, *best;
    uint32_t *from, *stack, *next_child;
    unsigned char *in;
    size_t sp = 0;

    qc_rng_seed(&rng, seed);
    t->p = malloc(cap * sizeof *t->p);
    t->n = 0;
    for (y = d / 2; y < 100; y += d)
        for (x = d / 2; x < 100; x += d) {
            qc_vec2 p;
            p.x = x + (qc_rng_unit(&rng) - 0.5) * d * 0.5;
            p.y = y + (qc_rng_unit(&rng) - 0.5) * d * 0.5;
            if (qc_region_contains(r, p) && qc_region_boundary_distance(r, p) > d * 0.6 &&
                t->n < cap)
                t->p[t->n++] = p;
        }
    t->e = malloc(t->n * sizeof *t->e);
    best = malloc(t->n * sizeof *best);
    from = malloc(t->n * sizeof *from);
    in = calloc(t->n, 1);
    for (i = 0; i < t->n; i++) {
        best[i] = 1e300;
        from[i] = 0;
    }
    best[0] = 0;
    for (i = 0; i < t->n; i++) { /* O(n^2) Prim: test sizes only */
        size_t u = t->n;
        for (j = 0; j < t->n; j++)
            if (!in[j] && (u == t->n || best[j] < best[u]))
                u = j;
        in[u] = 1;
        if (i > 0) {
            t->e[i - 1].a = from[u];
            t->e[i - 1].b = (uint32_t)u;
        }
        for (j = 0; j < t->n; j++) {
            double dd = qc_hypot(t->p[j].x - t->p[u].x, t->p[j].y - t->p[u].y);
            if (!in[j] && dd < best[j]) {
                best[j] = dd;
                from[j] = (uint32_t)u;
            }
        }
    }
    /* Depth-first walk over the tree (children in edge order). */
    t->order = malloc((2 * t->n + 1) * sizeof *t->order);
    stack = malloc((t->n + 1) * sizeof *stack);
    next_child = calloc(t->n, sizeof *next_child);
    t->norder = 0;
    stack[sp++] = 0;
    t->order[t->norder++] = 0;
    while (sp > 0) {
        uint32_t u = stack[sp - 1];
        size_t k = next_child[u];
        while (k < t->n - 1 && !(t->e[k].a == u))
            k++;
        next_child[u] = (uint32_t)(k + 1);
        if (k < t->n - 1) {
            stack[sp++] = t->e[k].b;
            t->order[t->norder++] = t->e[k].b;
        } else {
            sp--;
            if (sp > 0)
                t->order[t->norder++] = stack[sp - 1];
        }
    }
    free(best);
    free(from);
    free(in);
    free(stack);
    free(next_child);
}

static void free_skeleton(tskel *t)
{
    free(t->p);
    free(t->e);
    free(t->order);
}

static qc_skeleton as_skel(const tskel *t)
{
    qc_skeleton s;
    s.p = t->p;
    s.n = t->n;
    s.edges = t->e;
    s.nedges = t->n - 1;
    s.order = t->order;
    s.norder = t->norder;
    s.root = 0;
    return s;
}

static qc_params base_params(uint64_t seed)
{
    qc_params p;
    memset(&p, 0, sizeof p);
    p.seed = seed;
    p.spacing = 10;
    p.size = 6;
    p.gap = 1;
    p.angle = 45;
    return p;
}

/* Every motif is sewn from its attachment: the vine is split there, so
 * each attachment is the end of a vine piece in the path. The spots are
 * taken in the vine's order (tips and spots along it merged): one taken
 * out of order would not split the vine, one past a cubic's end would be
 * lost, and its attachment would be missing here. */
static void assert_sewn_at_attachments(const qc_path *out, const qc__placement *pl)
{
    size_t a, c, k;

    for (a = 0; a < pl->attach.n; a++) {
        qc_vec2 at = pl->attach.v[a];
        int found = 0;

        for (c = 0, k = 0; c < out->ncmd && !found; c++) {
            size_t nk = out->cmd[c] == QC_PATH_CUBIC ? 3 : 1;
            qc_vec2 e = out->pt[k + nk - 1];

            found = fabs(e.x - at.x) < 1e-6 && fabs(e.y - at.y) < 1e-6;
            k += nk;
        }
        TEST_ASSERT_TRUE_MESSAGE(found, "an attachment the path does not reach");
    }
}

static void check_pattern(int region_kind, uint64_t seed, const char *motif_names)
{
    qc_region r;
    tskel t;
    qc_skeleton sk;
    qc_params par = base_params(seed);
    qc_motif_set set = {0};
    qc__placement pl;
    qc_path out = {0};
    qc_stats st;
    qc_points flat = {0};
    size_t i, j, k, nm;

    memset(&pl, 0, sizeof pl);
    memset(&st, 0, sizeof st);
    make_region(region_kind, &r);
    make_skeleton(&r, par.spacing, seed, &t);
    sk = as_skel(&t);
    TEST_ASSERT_GREATER_THAN_UINT(10, t.n);
    TEST_ASSERT_EQUAL_UINT(2 * t.n - 1, t.norder);
    if (motif_names != NULL)
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_motif_builtin(&ctx, motif_names, &set));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc__branching_run(&ctx, &r, &par, &sk,
                                                   motif_names ? &set : NULL, &out, &st, &pl));
    TEST_ASSERT_EQUAL_UINT(1, qc_path_pieces(&out));
    TEST_ASSERT_EQUAL_INT(QC_PATH_MOVE, out.cmd[0]);
    nm = pl.full_end.n;
    TEST_ASSERT_EQUAL_UINT(st.motifs_placed, nm);
    TEST_ASSERT_GREATER_THAN_UINT(t.n / 2, nm);
    TEST_ASSERT_TRUE(st.motifs_shrunk <= nm && st.motifs_rotated <= nm && st.motifs_flipped <= nm);
    for (i = 0; i < nm; i++) {
        size_t a0 = i ? pl.full_end.i[i - 1] : 0, a1 = pl.full_end.i[i];
        size_t b0 = i ? pl.body_end.i[i - 1] : 0, b1 = pl.body_end.i[i];
        size_t ring;
        for (j = i + 1; j < nm; j++) { /* no two hulls touch */
            size_t c0 = pl.full_end.i[j - 1], c1 = pl.full_end.i[j];
            TEST_ASSERT_FALSE(qc__convex_touch(pl.full.v + a0, a1 - a0, pl.full.v + c0, c1 - c0, 0));
        }
        for (k = 0; k + 1 < pl.vine.n; k++) /* the body keeps off the vine */
            TEST_ASSERT_FALSE(qc__convex_touch(pl.body.v + b0, b1 - b0, pl.vine.v + k, 2, 0));
        for (ring = 0; ring < r.nrings; ring++) { /* and off the boundary */
            size_t lo = ring ? r.ring_end[ring - 1] : 0, hi = r.ring_end[ring];
            for (k = lo; k < hi; k++) {
                qc_vec2 e[2];
                e[0] = r.v[k];
                e[1] = r.v[k + 1 < hi ? k + 1 : lo];
                TEST_ASSERT_FALSE(qc__convex_touch(pl.full.v + a0, a1 - a0, e, 2, 0));
            }
        }
    }
    assert_sewn_at_attachments(&out, &pl);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_curve_flatten(&ctx, &out, 0.01, &flat, NULL));
    for (i = 0; i < flat.n; i++)
        TEST_ASSERT_TRUE(qc_region_contains(&r, flat.v[i]) ||
                         qc_region_boundary_distance(&r, flat.v[i]) < 0.05);
    qc_points_free(&ctx, &flat);
    qc_path_free(&ctx, &out);
    qc__placement_free(&ctx, &pl);
    qc_motif_set_free(&ctx, &set);
    qc_region_free(&ctx, &r);
    free_skeleton(&t);
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

static void branching_should_keep_motifs_clear_in_a_square(void)
{
    check_pattern(R_SQUARE, 1, NULL);
    check_pattern(R_SQUARE, 2, "leaf,heart,teardrop");
}

static void branching_should_respect_a_hole(void)
{
    check_pattern(R_HOLE, 3, NULL);
    check_pattern(R_HOLE, 4, "flower,star,circle");
}

static void branching_should_fill_a_circle(void)
{
    check_pattern(R_CIRCLE, 5, "loop,spiral,leaf");
    check_pattern(R_CIRCLE, 6, "swirl45"); /* an open primitive comes back in a line */
}

static void branching_should_repeat_for_a_seed(void)
{
    qc_region r;
    tskel t;
    qc_skeleton sk;
    qc_params par = base_params(7);
    qc_motif_set set = {0};
    qc_path a = {0}, b = {0}, c = {0};

    make_region(R_SQUARE, &r);
    make_skeleton(&r, par.spacing, 7, &t);
    sk = as_skel(&t);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_motif_builtin(&ctx, "leaf,heart", &set));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_deco_branching(&ctx, &r, &par, &sk, &set, &a, NULL));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_deco_branching(&ctx, &r, &par, &sk, &set, &b, NULL));
    TEST_ASSERT_EQUAL_UINT(a.ncmd, b.ncmd);
    TEST_ASSERT_EQUAL_UINT(a.npt, b.npt);
    TEST_ASSERT_EQUAL_MEMORY(a.cmd, b.cmd, a.ncmd);
    TEST_ASSERT_EQUAL_MEMORY(a.pt, b.pt, a.npt * sizeof *a.pt);
    par.seed = 8; /* another seed picks other motifs */
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_deco_branching(&ctx, &r, &par, &sk, &set, &c, NULL));
    TEST_ASSERT_TRUE(c.npt != a.npt || memcmp(c.pt, a.pt, a.npt * sizeof *a.pt) != 0);
    qc_path_free(&ctx, &a);
    qc_path_free(&ctx, &b);
    qc_path_free(&ctx, &c);
    qc_motif_set_free(&ctx, &set);
    qc_region_free(&ctx, &r);
    free_skeleton(&t);
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

static void branching_should_refuse_empty_skeletons_and_bad_size(void)
{
    qc_region r;
    qc_skeleton sk;
    qc_params par = base_params(1);
    qc_path out = {0};
    qc_vec2 p = {50, 50};
    uint32_t o = 0;

    make_region(R_SQUARE, &r);
    memset(&sk, 0, sizeof sk);
    TEST_ASSERT_EQUAL_INT(QC_EEMPTY, qc_deco_branching(&ctx, &r, &par, &sk, NULL, &out, NULL));
    sk.p = &p;
    sk.n = 1;
    sk.order = &o;
    sk.norder = 1;
    par.size = -1;
    TEST_ASSERT_EQUAL_INT(QC_ERANGE, qc_deco_branching(&ctx, &r, &par, &sk, NULL, &out, NULL));
    par.size = 6; /* a lone point still gets its motif, in one piece */
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_deco_branching(&ctx, &r, &par, &sk, NULL, &out, NULL));
    TEST_ASSERT_EQUAL_UINT(1, qc_path_pieces(&out));
    TEST_ASSERT_GREATER_THAN_UINT(2, out.ncmd);
    qc_path_free(&ctx, &out);
    qc_region_free(&ctx, &r);
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

static void branching_should_free_everything_when_allocation_fails(void)
{
    qc_region r;
    tskel t;
    qc_skeleton sk;
    qc_params par = base_params(9);
    size_t k;
    int rc = QC_ENOMEM;

    make_region(R_SQUARE, &r);
    par.spacing = 25;
    make_skeleton(&r, par.spacing, 9, &t);
    sk = as_skel(&t);
    for (k = 1; rc == QC_ENOMEM && k < 20000; k++) {
        qc_path out = {0};
        qc__placement pl;
        size_t base;
        memset(&pl, 0, sizeof pl);
        base = ta.live_blocks;
        ta.allocs = 0;
        ta.fail_at = k;
        rc = qc__branching_run(&ctx, &r, &par, &sk, NULL, &out, NULL, &pl);
        ta.fail_at = 0;
        qc_path_free(&ctx, &out);
        qc__placement_free(&ctx, &pl);
        TEST_ASSERT_EQUAL_UINT(base, ta.live_blocks);
    }
    TEST_ASSERT_EQUAL_INT(QC_OK, rc);
    TEST_ASSERT_FALSE(ta.size_mismatch);
    qc_region_free(&ctx, &r);
    free_skeleton(&t);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(branching_should_keep_motifs_clear_in_a_square);
    RUN_TEST(branching_should_respect_a_hole);
    RUN_TEST(branching_should_fill_a_circle);
    RUN_TEST(branching_should_repeat_for_a_seed);
    RUN_TEST(branching_should_refuse_empty_skeletons_and_bad_size);
    RUN_TEST(branching_should_free_everything_when_allocation_fails);
    return UNITY_END();
}
