/* The family registry (qc_family_info): every family registered once, its
 * name, flags and parameter scope true to what it does when it runs. */
#include <math.h>
#include <string.h>

#include "quiltc.h"
#include "testalloc.h"
#include "unity.h"

static testalloc ta;
static qc_ctx ctx;
static qc_region block;

void setUp(void)
{
    memset(&ta, 0, sizeof ta);
    qc_ctx_init(&ctx, testalloc_fn, &ta);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_shape(&ctx, "rect:60x45", 1.0, &block));
}

void tearDown(void)
{
    qc_region_free(&ctx, &block);
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

static int same_path(const qc_path *a, const qc_path *b)
{
    return a->ncmd == b->ncmd && a->npt == b->npt &&
           memcmp(a->cmd, b->cmd, a->ncmd) == 0 &&
           memcmp(a->pt, b->pt, a->npt * sizeof *a->pt) == 0;
}

static qc_params family_params(const qc_family_desc *f)
{
    qc_params p;

    memset(&p, 0, sizeof p);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "family", f->id));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "spacing", 6.0));
    return p;
}

/* Ids 1..QC_FAMILY_COUNT-1 in order, then NULL; names round-trip through
 * qc_family_name, qc_family_from_name and the family row's choices. */
static void test_every_family_is_listed_once_and_names_round_trip(void)
{
    const qc_param_info *row = qc_param_find("family");
    char choices[256] = "";
    size_t i;

    for (i = 0; i + 1 < QC_FAMILY_COUNT; i++) {
        const qc_family_desc *f = qc_family_info(i);

        TEST_ASSERT_NOT_NULL(f);
        TEST_ASSERT_EQUAL_INT((int)i + 1, f->id);
        TEST_ASSERT_NOT_NULL(f->run);
        TEST_ASSERT_TRUE(f->summary != NULL && f->summary[0] != '\0');
        TEST_ASSERT_EQUAL_STRING(f->name, qc_family_name(f->id));
        TEST_ASSERT_EQUAL_INT(f->id, qc_family_from_name(f->name));
        TEST_ASSERT_EQUAL_INT(f->id, qc_param_choice(row, f->name));
        if (i > 0)
            strcat(choices, "|");
        strcat(choices, f->name);
    }
    TEST_ASSERT_NULL(qc_family_info(QC_FAMILY_COUNT - 1));
    TEST_ASSERT_NULL(qc_family_info((size_t)-1));
    TEST_ASSERT_EQUAL_STRING(choices, row->choices);
    TEST_ASSERT_EQUAL_DOUBLE(QC_FAMILY_COUNT - 1, row->max);
    TEST_ASSERT_EQUAL_INT(-1, qc_family_from_name("no-such-family"));
    TEST_ASSERT_NULL(qc_family_name(QC_FAMILY_COUNT));
}

/* Each family generates one path on a block; it has points exactly when it
 * says it needs them. */
static void test_every_family_generates_and_needs_points_as_it_says(void)
{
    const qc_family_desc *f;
    size_t i;

    for (i = 0; (f = qc_family_info(i)) != NULL; i++) {
        qc_params p = family_params(f);
        qc_result r;

        TEST_ASSERT_EQUAL_INT_MESSAGE(QC_OK, qc_generate(&ctx, &block, &p, NULL, NULL, &r),
                                      f->name);
        TEST_ASSERT_TRUE_MESSAGE(r.path.ncmd > 0, f->name);
        TEST_ASSERT_EQUAL_size_t_MESSAGE(1, r.stats.pieces, f->name);
        TEST_ASSERT_EQUAL_INT_MESSAGE((f->needs & QC_FAMILY_NEEDS_POINTS) != 0, r.points.n > 0,
                                      f->name);
        TEST_ASSERT_EQUAL_INT(f->id, r.params.family);
        qc_result_free(&ctx, &r);
    }
}

/* A family that needs the tree refuses a tour skeleton; the others draw
 * one. */
static void test_tree_families_refuse_a_tour_and_only_they(void)
{
    const qc_family_desc *f;
    size_t i;

    for (i = 0; (f = qc_family_info(i)) != NULL; i++) {
        qc_params p = family_params(f);
        qc_result r;
        int rc;

        TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "skeleton", QC_SKELETON_TSP));
        rc = qc_generate(&ctx, &block, &p, NULL, NULL, &r);
        if (f->needs & QC_FAMILY_NEEDS_TREE) {
            TEST_ASSERT_EQUAL_INT_MESSAGE(QC_EINVAL, rc, f->name);
            TEST_ASSERT_NOT_NULL(strstr(qc_errmsg(&ctx), "spanning tree"));
        } else {
            TEST_ASSERT_EQUAL_INT_MESSAGE(QC_OK, rc, f->name);
            qc_result_free(&ctx, &r);
        }
    }
}

/* A family that draws motifs draws the ones it is given (one named motif
 * instead of the library); the others give the same bytes either way. */
static void test_motif_families_use_the_motifs_and_only_they(void)
{
    const qc_family_desc *f;
    size_t i;

    for (i = 0; (f = qc_family_info(i)) != NULL; i++) {
        qc_params p = family_params(f);
        qc_motif_set one;
        qc_result a, b;
        int rc;

        memset(&one, 0, sizeof one);
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_motif_builtin(&ctx, f->id == QC_FAMILY_WANDERER
                                                                ? "loop90" : "circle", &one));
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_generate(&ctx, &block, &p, NULL, NULL, &a));
        rc = qc_generate(&ctx, &block, &p, NULL, &one, &b);
        TEST_ASSERT_EQUAL_INT_MESSAGE(QC_OK, rc, f->name);
        TEST_ASSERT_EQUAL_INT_MESSAGE((f->needs & QC_FAMILY_NEEDS_MOTIFS) == 0,
                                      same_path(&a.path, &b.path), f->name);
        qc_result_free(&ctx, &a);
        qc_result_free(&ctx, &b);
        qc_motif_set_free(&ctx, &one);
    }
}

/* A value other than the row's resolved one, inside its range. */
static double other_value(const qc_param_info *row, double resolved)
{
    if (row->type == QC_PARAM_ENUM)
        return resolved == 1.0 ? 2.0 : 1.0;
    if (row->type == QC_PARAM_INT)
        return resolved < row->max ? resolved + 1.0 : resolved - 1.0;
    return resolved + 0.37 * (fmin(row->max, resolved * 2.0 + 1.0) - resolved);
}

/* The parameter scope (qc_param_families, from the descriptors) is honest:
 * a parameter outside a family's scope, set to another value, leaves its
 * path unchanged (the CLI's --help and the page hide exactly those). */
static void test_parameters_outside_a_family_change_nothing(void)
{
    size_t nrows, k, i, checked = 0;
    const qc_param_info *t = qc_param_table(&nrows);
    const qc_family_desc *f;

    for (i = 0; (f = qc_family_info(i)) != NULL; i++) {
        qc_params p = family_params(f), resolved;
        qc_result a;

        TEST_ASSERT_EQUAL_INT(QC_OK, qc_generate(&ctx, &block, &p, NULL, NULL, &a));
        resolved = a.params;
        for (k = 0; k < nrows; k++) {
            qc_params q = p;
            qc_result b;

            if (qc_param_families(&t[k]) & (1u << f->id))
                continue;
            TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &q, t[k].name,
                                                       other_value(&t[k],
                                                                   qc_params_get(&resolved,
                                                                                 &t[k]))));
            TEST_ASSERT_EQUAL_INT_MESSAGE(QC_OK, qc_generate(&ctx, &block, &q, NULL, NULL, &b),
                                          t[k].name);
            TEST_ASSERT_TRUE_MESSAGE(same_path(&a.path, &b.path), t[k].name);
            qc_result_free(&ctx, &b);
            checked++;
        }
        qc_result_free(&ctx, &a);
    }
    TEST_ASSERT_TRUE(checked > 40); /* echo and spiral alone ignore the skeleton's rows */
}

/* Every family takes the common rows; only point families the skeleton's. */
static void test_common_and_skeleton_rows_reach_the_right_families(void)
{
    const qc_family_desc *f;
    size_t i;

    for (i = 0; (f = qc_family_info(i)) != NULL; i++) {
        uint32_t bit = 1u << f->id;

        TEST_ASSERT_TRUE(qc_param_families(qc_param_find("spacing")) & bit);
        TEST_ASSERT_TRUE(qc_param_families(qc_param_find("seed")) & bit);
        TEST_ASSERT_EQUAL_INT((f->needs & QC_FAMILY_NEEDS_POINTS) != 0,
                              (qc_param_families(qc_param_find("points")) & bit) != 0);
    }
    TEST_ASSERT_EQUAL_UINT32(1u << QC_FAMILY_SPIRAL, qc_param_families(qc_param_find("spiral")));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_every_family_is_listed_once_and_names_round_trip);
    RUN_TEST(test_every_family_generates_and_needs_points_as_it_says);
    RUN_TEST(test_tree_families_refuse_a_tour_and_only_they);
    RUN_TEST(test_motif_families_use_the_motifs_and_only_they);
    RUN_TEST(test_parameters_outside_a_family_change_nothing);
    RUN_TEST(test_common_and_skeleton_rows_reach_the_right_families);
    return UNITY_END();
}
