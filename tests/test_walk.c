/* Tree walk (paper Fig. 5): counter-clockwise child order, every edge twice, errors. */
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
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
    TEST_ASSERT_FALSE(ta.size_mismatch);
}

static qc_edge edge(uint32_t a, uint32_t b)
{
    qc_edge e;
    e.a = a;
    e.b = b;
    return e;
}

static void assert_walk(const qc_vec2 *p, size_t n, const qc_edge *e, uint32_t root,
                        const uint32_t *want, size_t nwant)
{
    qc_order w = {0};
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_tree_walk(&ctx, p, n, e, n - 1, root, &w));
    TEST_ASSERT_EQUAL_size_t(nwant, w.n);
    TEST_ASSERT_EQUAL_UINT32_ARRAY(want, w.i, nwant);
    qc_order_free(&ctx, &w);
}

/* The root's children start from +x and go counter-clockwise. */
static void test_root_children_counter_clockwise_from_east(void)
{
    qc_vec2 p[5];
    qc_edge e[4];
    static const uint32_t want[] = {0, 2, 0, 4, 0, 1, 0, 3, 0};

    p[0] = v2(0, 0); p[1] = v2(-1, 0); p[2] = v2(1, 0); p[3] = v2(0, -1); p[4] = v2(0, 1);
    e[0] = edge(0, 1); e[1] = edge(3, 0); e[2] = edge(0, 2); e[3] = edge(4, 0);
    assert_walk(p, 5, e, 0, want, 9);
}

/* Below the root, children start from the parent's direction (Fig. 5). */
static void test_children_start_from_the_parent_direction(void)
{
    qc_vec2 p[5];
    qc_edge e[4];
    /* from 1 the parent lies west: counter-clockwise come south (4), east (2), north (3) */
    static const uint32_t want[] = {0, 1, 4, 1, 2, 1, 3, 1, 0};

    p[0] = v2(0, 0); p[1] = v2(1, 0); p[2] = v2(2, 0); p[3] = v2(1, 1); p[4] = v2(1, -1);
    e[0] = edge(0, 1); e[1] = edge(1, 2); e[2] = edge(1, 3); e[3] = edge(4, 1);
    assert_walk(p, 5, e, 0, want, 9);
}

static void test_single_point_walk_is_the_root(void)
{
    qc_vec2 p = v2(3, 4);
    static const uint32_t want[] = {0};
    qc_order w = {0};

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_tree_walk(&ctx, &p, 1, NULL, 0, 0, &w));
    TEST_ASSERT_EQUAL_UINT32_ARRAY(want, w.i, 1);
    qc_order_free(&ctx, &w);
}

/* On an EMST of random points: 2(n-1)+1 entries, each tree edge once each way,
 * and the walk turns consistently: it is the tree's outline (no step crosses
 * between different sides of an edge). */
static void test_emst_walk_uses_every_edge_twice(void)
{
    enum { N = 2000 };
    qc_vec2 *p = malloc(N * sizeof *p);
    qc_edges t = {0};
    qc_order w = {0};
    unsigned char *seen = calloc((size_t)N * 4, 1);
    qc_rng rng;
    size_t i, k;

    qc_rng_seed(&rng, 3);
    for (i = 0; i < N; i++)
        p[i] = rng_v2(&rng, 0, 100, 0, 100);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_mst(&ctx, p, N, QC_MST_MODE_DELAUNAY, &t));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_tree_walk(&ctx, p, N, t.e, t.n, 17, &w));
    TEST_ASSERT_EQUAL_size_t(2 * (N - 1) + 1, w.n);
    TEST_ASSERT_EQUAL_UINT32(17, w.i[0]);
    TEST_ASSERT_EQUAL_UINT32(17, w.i[w.n - 1]);
    for (i = 0; i + 1 < w.n; i++) {
        uint32_t a = w.i[i], b = w.i[i + 1];
        int found = 0;
        for (k = 0; k < t.n && !found; k++) {
            if (t.e[k].a == a && t.e[k].b == b) {
                TEST_ASSERT_EQUAL_UINT8(0, seen[2 * k]);
                seen[2 * k] = 1;
                found = 1;
            } else if (t.e[k].a == b && t.e[k].b == a) {
                TEST_ASSERT_EQUAL_UINT8(0, seen[2 * k + 1]);
                seen[2 * k + 1] = 1;
                found = 1;
            }
        }
        TEST_ASSERT_TRUE(found);
    }
    qc_edges_free(&ctx, &t);
    qc_order_free(&ctx, &w);
    free(p);
    free(seen);
}

static void expect_error(const qc_vec2 *p, size_t n, const qc_edge *e, size_t m, uint32_t root,
                         const char *needle)
{
    qc_order w = {0};
    TEST_ASSERT_EQUAL_INT_MESSAGE(QC_EINVAL, qc_tree_walk(&ctx, p, n, e, m, root, &w),
                                  qc_errmsg(&ctx));
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(qc_errmsg(&ctx), needle), qc_errmsg(&ctx));
    qc_order_free(&ctx, &w);
}

static void test_non_trees_are_refused(void)
{
    qc_vec2 p[4];
    qc_edge e[3];

    p[0] = v2(0, 0); p[1] = v2(1, 0); p[2] = v2(1, 1); p[3] = v2(5, 5);
    e[0] = edge(0, 1); e[1] = edge(1, 2); e[2] = edge(2, 0);
    expect_error(p, 4, e, 3, 0, "cycle"); /* a triangle and a lone point */
    expect_error(p, 4, e, 2, 0, "2 edges for 4 points");
    expect_error(p, 4, e, 3, 4, "root 4 is not one of 4 points");
    e[2] = edge(2, 9);
    expect_error(p, 4, e, 3, 0, "edge 2 (2, 9)");
    e[2] = edge(3, 3);
    expect_error(p, 4, e, 3, 0, "edge 2 (3, 3)");
    e[2] = edge(1, 2); /* a doubled edge leaves 3 unreached */
    expect_error(p, 4, e, 3, 0, "cycle");
    expect_error(p, 4, e, 3, 3, "the edges reach 1 of 4 points");
}

/* A walk to an end point: at each node on the way, the branch towards the
 * end comes last and is not walked back, so the walk ends there; every
 * other edge is walked twice, the path's edges once. */
static void test_walk_to_ends_at_the_end_after_every_detour(void)
{
    qc_vec2 p[6];
    qc_edge e[5];
    qc_order w = {0};
    /* the path 0 - 1 - 2 - 5 (end), with 3 north and 4 south of 1: from 1
     * (parent west) counter-clockwise come 4 (south), 2 (east: towards the
     * end, so deferred), 3 (north) */
    static const uint32_t want[] = {0, 1, 4, 1, 3, 1, 2, 5, 2};
    static const uint32_t whole[] = {0, 1, 4, 1, 2, 5, 2, 1, 3, 1, 0};
    size_t f;

    p[0] = v2(0, 0); p[1] = v2(1, 0); p[2] = v2(2, 0); p[3] = v2(1, 1); p[4] = v2(1, -1);
    p[5] = v2(3, -1);
    e[0] = edge(0, 1); e[1] = edge(1, 2); e[2] = edge(1, 3); e[3] = edge(4, 1);
    e[4] = edge(2, 5);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_tree_walk_to(&ctx, p, 6, e, 5, 0, 5, &w));
    TEST_ASSERT_EQUAL_size_t(2 * 5 + 1 - 3, w.n); /* end at depth 3 */
    TEST_ASSERT_EQUAL_UINT32_ARRAY(want, w.i, w.n);
    qc_order_free(&ctx, &w);
    /* end == root is the plain walk */
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_tree_walk_to(&ctx, p, 6, e, 5, 0, 0, &w));
    TEST_ASSERT_EQUAL_size_t(11, w.n);
    TEST_ASSERT_EQUAL_UINT32_ARRAY(whole, w.i, 11);
    qc_order_free(&ctx, &w);
    TEST_ASSERT_EQUAL_INT(QC_EINVAL, qc_tree_walk_to(&ctx, p, 6, e, 5, 0, 6, &w));
    TEST_ASSERT_NOT_NULL(strstr(qc_errmsg(&ctx), "end 6 is not one of 6 points"));
    e[4] = edge(1, 0); /* a cycle 0-1-0 and 5 cut off */
    TEST_ASSERT_EQUAL_INT(QC_EINVAL, qc_tree_walk_to(&ctx, p, 6, e, 5, 0, 2, &w));
    qc_order_free(&ctx, &w);
    e[4] = edge(2, 5);
    for (f = 1;; f++) { /* every allocation failure: ENOMEM, nothing leaked */
        int rc;
        ta.fail_at = ta.allocs + f;
        rc = qc_tree_walk_to(&ctx, p, 6, e, 5, 0, 5, &w);
        qc_order_free(&ctx, &w);
        TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
        if (rc == QC_OK)
            break;
        TEST_ASSERT_EQUAL_INT(QC_ENOMEM, rc);
    }
    TEST_ASSERT_GREATER_THAN_UINT(5, (unsigned)f);
}

static void test_nearest_point_prefers_the_lowest_index_on_ties(void)
{
    qc_vec2 p[4];

    p[0] = v2(5, 5); p[1] = v2(1, 0); p[2] = v2(-1, 0); p[3] = v2(0, 1);
    TEST_ASSERT_EQUAL_UINT32(1, qc_nearest_point(p, 4, v2(0, 0)));
    TEST_ASSERT_EQUAL_UINT32(3, qc_nearest_point(p, 4, v2(0, 0.9)));
    TEST_ASSERT_EQUAL_UINT32(0, qc_nearest_point(p, 0, v2(0, 0)));
}

static void test_out_of_memory_is_reported_and_leaks_nothing(void)
{
    qc_vec2 p[5];
    qc_edge e[4];
    size_t f;

    p[0] = v2(0, 0); p[1] = v2(1, 0); p[2] = v2(2, 0); p[3] = v2(1, 1); p[4] = v2(1, -1);
    e[0] = edge(0, 1); e[1] = edge(1, 2); e[2] = edge(1, 3); e[3] = edge(4, 1);
    for (f = 1;; f++) {
        qc_order w = {0};
        int rc;
        ta.fail_at = ta.allocs + f;
        rc = qc_tree_walk(&ctx, p, 5, e, 4, 0, &w);
        qc_order_free(&ctx, &w);
        TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
        if (rc == QC_OK)
            break;
        TEST_ASSERT_EQUAL_INT(QC_ENOMEM, rc);
    }
    TEST_ASSERT_GREATER_THAN_UINT(3, (unsigned)f);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_root_children_counter_clockwise_from_east);
    RUN_TEST(test_children_start_from_the_parent_direction);
    RUN_TEST(test_single_point_walk_is_the_root);
    RUN_TEST(test_emst_walk_uses_every_edge_twice);
    RUN_TEST(test_non_trees_are_refused);
    RUN_TEST(test_walk_to_ends_at_the_end_after_every_detour);
    RUN_TEST(test_nearest_point_prefers_the_lowest_index_on_ties);
    RUN_TEST(test_out_of_memory_is_reported_and_leaks_nothing);
    return UNITY_END();
}
