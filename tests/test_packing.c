/* Shape Packing (§5.3.2): each motif lies in its pebble (its minimum
 * bounding circle), so motifs never overlap; each faces the pebble it hangs
 * from; one piece inside the region; seeded choice; errors; OOM. */
#include <math.h>
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

static void make_region(int hole, qc_region *r)
{
    qc_vec2 sq[4] = {{0, 0}, {120, 0}, {120, 100}, {0, 100}};
    qc_vec2 h[4] = {{40, 30}, {40, 70}, {80, 70}, {80, 30}};

    memset(r, 0, sizeof *r);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, r, sq, 4));
    if (hole)
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, r, h, 4));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_normalize(&ctx, r));
}

/* Jittered lattice points at least 0.3 d inside, a chain through them
 * (each row left to right, then back: a tour skeleton with no edges). */
typedef struct tskel {
    qc_points p;
    qc_order order;
} tskel;

static void make_skeleton(const qc_region *r, double d, uint64_t seed, tskel *t)
{
    qc_bbox b = qc_region_bbox(r);
    qc_rng rng;
    double x, y;
    size_t i;

    memset(t, 0, sizeof *t);
    qc_rng_seed(&rng, seed);
    for (y = b.min.y + d / 2; y < b.max.y; y += d)
        for (x = b.min.x + d / 2; x < b.max.x; x += d) {
            qc_vec2 p;
            p.x = x + (qc_rng_unit(&rng) - 0.5) * 0.4 * d;
            p.y = y + (qc_rng_unit(&rng) - 0.5) * 0.4 * d;
            if (qc_region_contains(r, p) && qc_region_boundary_distance(r, p) >= 0.3 * d)
                TEST_ASSERT_EQUAL_INT(QC_OK, qc_points_push(&ctx, &t->p, p));
        }
    for (i = 0; i < t->p.n; i++)
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_order_push(&ctx, &t->order, (uint32_t)i));
}

static void free_skeleton(tskel *t)
{
    qc_points_free(&ctx, &t->p);
    qc_order_free(&ctx, &t->order);
}

static qc_skeleton as_skel(const tskel *t)
{
    qc_skeleton s;
    memset(&s, 0, sizeof s);
    s.p = t->p.v;
    s.n = t->p.n;
    s.order = t->order.i;
    s.norder = t->order.n;
    return s;
}

static qc_params base_params(int edge, uint64_t seed)
{
    qc_params p;
    memset(&p, 0, sizeof p);
    p.seed = seed;
    p.spacing = 10;
    p.r_seed = 0.7;
    p.edge = edge;
    return p;
}

static void check_packing(int hole, int edge, const char *names)
{
    qc_region r;
    tskel t;
    qc_skeleton sk;
    qc_params par = base_params(edge, 5);
    qc_motif_set set = {0};
    const qc_motif_set *use = NULL;
    qc__pebbles pb;
    qc_path out = {0};
    qc_points flat = {0}, mf = {0};
    qc_stats st;
    size_t i, j, k;
    double tol = 1e-9 * par.spacing;

    make_region(hole, &r);
    make_skeleton(&r, par.spacing, 11, &t);
    sk = as_skel(&t);
    if (names != NULL) {
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_motif_builtin(&ctx, names, &set));
        use = &set;
    }
    memset(&st, 0, sizeof st);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc__packing_run(&ctx, &r, &par, &sk, use, &out, &st, &pb));
    TEST_ASSERT_EQUAL_UINT(pb.n, st.motifs_placed);
    TEST_ASSERT_EQUAL_UINT(pb.n, st.pebbles);
    TEST_ASSERT_GREATER_THAN_UINT(t.p.n / 2, pb.n);
    for (i = 0; i < pb.n; i++) {
        const qc_motif *m = use != NULL ? &use->m[pb.motif[i]] : NULL;
        qc_vec2 e;
        if (use != NULL)
            TEST_ASSERT_TRUE(pb.motif[i] < use->n);
        for (j = i + 1; j < pb.n; j++) /* pebbles apart */
            TEST_ASSERT_TRUE(qc_hypot(pb.c[i].x - pb.c[j].x, pb.c[i].y - pb.c[j].y) >=
                             pb.r[i] + pb.r[j] - tol);
        if (m == NULL)
            continue;
        /* the motif lies in its pebble, so motifs never overlap */
        mf.n = 0;
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_curve_flatten(&ctx, &m->path, 1e-4, &mf, NULL));
        for (k = 0; k < mf.n; k++) {
            qc_vec2 q = qc__xf_apply(&pb.xf[i], mf.v[k]);
            TEST_ASSERT_TRUE(qc_hypot(q.x - pb.c[i].x, q.y - pb.c[i].y) <= pb.r[i] * (1 + 1e-9));
        }
        /* its start faces the pebble it hangs from */
        e = qc__xf_apply(&pb.xf[i], m->entry);
        if (pb.parent[i] != QC__PEB_NONE && qc_hypot(m->entry.x, m->entry.y) > 0.1) {
            qc_vec2 pp = pb.c[pb.parent[i]];
            double ax = e.x - pb.c[i].x, ay = e.y - pb.c[i].y;
            double bx = pp.x - pb.c[i].x, by = pp.y - pb.c[i].y;
            TEST_ASSERT_DOUBLE_WITHIN(1e-9, 0, (ax * by - ay * bx) / (qc_hypot(ax, ay) * qc_hypot(bx, by)));
            TEST_ASSERT_TRUE(ax * bx + ay * by > 0);
        }
    }
    if (use != NULL && edge == QC_EDGE_STRICT) { /* drawn straight into out */
        /* reserved once, before drawing, for at most the up-front bound (a
         * 10^6-point packing's path is hundreds of MB, so a doubling would
         * cost up to half of it again), then cut to size */
        size_t want_pt = 1, want_cmd = 1; /* the first stitch */
        for (i = 0; i < pb.n; i++) { /* a motif, its closing and return stitches;
                                      * its split parent command and stitch out */
            const qc_path *mp = &use->m[pb.motif[i]].path;
            want_pt += mp->npt + 1 + (pb.parent[i] != QC__PEB_NONE ? 4 : 0);
            want_cmd += mp->ncmd + 1 + (pb.parent[i] != QC__PEB_NONE ? 2 : 0);
        }
        TEST_ASSERT_TRUE(out.npt <= want_pt && out.ncmd <= want_cmd);
        TEST_ASSERT_EQUAL_size_t(out.npt, out.pt_cap);
        TEST_ASSERT_EQUAL_size_t(out.ncmd, out.cmd_cap);
    }
    TEST_ASSERT_EQUAL_UINT(1, qc_path_pieces(&out));
    TEST_ASSERT_EQUAL_INT(QC_PATH_MOVE, out.cmd[0]);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_curve_flatten(&ctx, &out, 0.01, &flat, NULL));
    for (i = 0; i < flat.n; i++)
        TEST_ASSERT_TRUE(qc_region_contains(&r, flat.v[i]) ||
                         qc_region_boundary_distance(&r, flat.v[i]) < 1e-9);
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, flat.v[0].x, flat.v[flat.n - 1].x); /* closed */
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, flat.v[0].y, flat.v[flat.n - 1].y);
    qc_points_free(&ctx, &flat);
    qc_points_free(&ctx, &mf);
    qc_path_free(&ctx, &out);
    qc__pebbles_free(&ctx, &pb);
    qc_motif_set_free(&ctx, &set);
    free_skeleton(&t);
    qc_region_free(&ctx, &r);
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
    TEST_ASSERT_FALSE(ta.size_mismatch);
}

static void packing_should_fit_each_motif_in_its_pebble(void)
{
    check_packing(0, QC_EDGE_STRICT, "heart");
    check_packing(0, QC_EDGE_STRICT, "teardrop,flower,star");
}

static void packing_should_keep_out_of_a_hole(void)
{
    check_packing(1, QC_EDGE_STRICT, "heart,leaf");
    check_packing(1, QC_EDGE_STRICT, NULL); /* the default: hearts */
}

static void packing_should_trim_overgrown_motifs(void)
{
    check_packing(1, QC_EDGE_OVERGROW, "circle,spiral");
}

static void packing_should_bring_open_motifs_back(void)
{
    check_packing(0, QC_EDGE_STRICT, "loop60"); /* a Wanderer primitive only */
}

static void packing_should_repeat_for_a_seed(void)
{
    qc_region r;
    tskel t;
    qc_skeleton sk;
    qc_params par = base_params(QC_EDGE_STRICT, 3);
    qc_motif_set set = {0};
    qc_path a = {0}, b = {0}, c = {0};

    make_region(1, &r);
    make_skeleton(&r, 10, 4, &t);
    sk = as_skel(&t);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_motif_builtin(&ctx, "heart,teardrop", &set));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_deco_packing(&ctx, &r, &par, &sk, &set, &a, NULL));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_deco_packing(&ctx, &r, &par, &sk, &set, &b, NULL));
    TEST_ASSERT_EQUAL_UINT(a.ncmd, b.ncmd);
    TEST_ASSERT_EQUAL_UINT(a.npt, b.npt);
    TEST_ASSERT_EQUAL_MEMORY(a.cmd, b.cmd, a.ncmd);
    TEST_ASSERT_EQUAL_MEMORY(a.pt, b.pt, a.npt * sizeof *a.pt);
    par.seed = 4; /* another seed picks other motifs */
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_deco_packing(&ctx, &r, &par, &sk, &set, &c, NULL));
    TEST_ASSERT_TRUE(c.npt != a.npt || memcmp(c.pt, a.pt, a.npt * sizeof *a.pt) != 0);
    qc_path_free(&ctx, &a);
    qc_path_free(&ctx, &b);
    qc_path_free(&ctx, &c);
    qc_motif_set_free(&ctx, &set);
    free_skeleton(&t);
    qc_region_free(&ctx, &r);
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

static void packing_should_refuse_empty_and_tiny(void)
{
    qc_region r, tiny;
    qc_skeleton sk;
    qc_params par = base_params(QC_EDGE_STRICT, 1);
    qc_vec2 p = {0.75, 0.75}, sq[4] = {{0, 0}, {1.5, 0}, {1.5, 1.5}, {0, 1.5}};
    uint32_t o = 0;
    qc_path out = {0};

    make_region(0, &r);
    memset(&tiny, 0, sizeof tiny);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, &tiny, sq, 4));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_normalize(&ctx, &tiny));
    memset(&sk, 0, sizeof sk);
    TEST_ASSERT_EQUAL_INT(QC_EEMPTY, qc_deco_packing(&ctx, &r, &par, &sk, NULL, &out, NULL));
    TEST_ASSERT_EQUAL_STRING("packing needs at least one point", qc_errmsg(&ctx));
    sk.p = &p;
    sk.n = 1;
    sk.order = &o;
    sk.norder = 1;
    TEST_ASSERT_EQUAL_INT(QC_EEMPTY, qc_deco_packing(&ctx, &tiny, &par, &sk, NULL, &out, NULL));
    TEST_ASSERT_NOT_NULL(strstr(qc_errmsg(&ctx), "no pebble of radius"));
    par.r_seed = 1.5;
    TEST_ASSERT_EQUAL_INT(QC_ERANGE, qc_deco_packing(&ctx, &r, &par, &sk, NULL, &out, NULL));
    TEST_ASSERT_EQUAL_UINT(0, out.ncmd);
    qc_region_free(&ctx, &r);
    qc_region_free(&ctx, &tiny);
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

static void packing_should_free_everything_when_allocation_fails(void)
{
    qc_region r;
    tskel t;
    qc_skeleton sk;
    qc_motif_set set = {0};
    int edge;

    make_region(1, &r);
    make_skeleton(&r, 16, 9, &t);
    sk = as_skel(&t);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_motif_builtin(&ctx, "heart,teardrop", &set));
    for (edge = QC_EDGE_STRICT; edge <= QC_EDGE_OVERGROW; edge++) {
        qc_params par = base_params(edge, 2);
        size_t k;
        int rc = QC_ENOMEM;
        par.spacing = 16;
        for (k = 1; rc == QC_ENOMEM && k < 5000; k++) {
            qc_path out = {0};
            qc_stats st;
            size_t base = ta.live_blocks;
            memset(&st, 0, sizeof st);
            ta.allocs = 0;
            ta.fail_at = k;
            /* the built-in default set is allocated inside too */
            rc = qc_deco_packing(&ctx, &r, &par, &sk, k & 1 ? &set : NULL, &out, &st);
            ta.fail_at = 0;
            qc_path_free(&ctx, &out);
            TEST_ASSERT_EQUAL_UINT(base, ta.live_blocks);
        }
        TEST_ASSERT_EQUAL_INT(QC_OK, rc);
        TEST_ASSERT_GREATER_THAN_UINT(10, k);
    }
    TEST_ASSERT_FALSE(ta.size_mismatch);
    qc_motif_set_free(&ctx, &set);
    free_skeleton(&t);
    qc_region_free(&ctx, &r);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(packing_should_fit_each_motif_in_its_pebble);
    RUN_TEST(packing_should_keep_out_of_a_hole);
    RUN_TEST(packing_should_trim_overgrown_motifs);
    RUN_TEST(packing_should_bring_open_motifs_back);
    RUN_TEST(packing_should_repeat_for_a_seed);
    RUN_TEST(packing_should_refuse_empty_and_tiny);
    RUN_TEST(packing_should_free_everything_when_allocation_fails);
    return UNITY_END();
}
