/* The parameter table and qc_params_resolve. */
#include <math.h>
#include <string.h>

#include "quiltc.h"
#include "unity.h"

static qc_ctx ctx;

void setUp(void)
{
    qc_ctx_init(&ctx, NULL, NULL);
}

void tearDown(void)
{
}

static void table_should_name_every_row_once_with_sane_ranges(void)
{
    size_t n, i, j;
    const qc_param_info *t = qc_param_table(&n);

    TEST_ASSERT_GREATER_THAN(15, n);
    TEST_ASSERT_LESS_OR_EQUAL(64, n); /* one bit each in qc_params.given */
    for (i = 0; i < n; i++) {
        TEST_ASSERT_NOT_NULL(t[i].name);
        TEST_ASSERT_NOT_NULL(t[i].help);
        TEST_ASSERT_TRUE(t[i].min <= t[i].max);
        TEST_ASSERT_TRUE(t[i].offset < sizeof(qc_params));
        TEST_ASSERT_TRUE(qc_param_find(t[i].name) == &t[i]);
        for (j = i + 1; j < n; j++)
            TEST_ASSERT_TRUE(strcmp(t[i].name, t[j].name) != 0);
    }
    TEST_ASSERT_NULL(qc_param_find("no-such"));
}

static void resolve_should_fill_defaults_from_a_zeroed_struct(void)
{
    qc_params p, r;

    memset(&p, 0, sizeof p);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_resolve(&ctx, &p, &r));
    TEST_ASSERT_EQUAL_INT(QC_FAMILY_STIPPLE, r.family);
    TEST_ASSERT_EQUAL_INT(QC_POINTS_POISSON, r.points);
    TEST_ASSERT_EQUAL_INT(QC_SKELETON_MST, r.skeleton);
    TEST_ASSERT_EQUAL_DOUBLE(12.7, r.spacing);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 12.7 / 3.0, r.width); /* stipple: w = d/3 */
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 0.3 * 12.7, r.margin);
    TEST_ASSERT_EQUAL_UINT64(1, r.seed);
}

static void resolve_should_derive_family_defaults(void)
{
    qc_params p, r;

    memset(&p, 0, sizeof p);
    p.family = QC_FAMILY_PEBBLING;
    p.spacing = 10.0;
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_resolve(&ctx, &p, &r));
    TEST_ASSERT_EQUAL_INT(QC_POINTS_SNUB, r.points);
    TEST_ASSERT_EQUAL_DOUBLE(0.7, r.r_seed);
    p.family = QC_FAMILY_WANDERER;
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_resolve(&ctx, &p, &r));
    TEST_ASSERT_EQUAL_INT(QC_SKELETON_TSP, r.skeleton);
    p.family = QC_FAMILY_FILL;
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_resolve(&ctx, &p, &r));
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 2.0, r.width); /* fill: w = d/5 */
}

static void set_should_keep_an_explicit_zero(void)
{
    qc_params p, r;

    memset(&p, 0, sizeof p);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "angle", 0.0));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "seed", 0.0));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_resolve(&ctx, &p, &r));
    TEST_ASSERT_EQUAL_DOUBLE(0.0, r.angle);
    TEST_ASSERT_EQUAL_UINT64(0, r.seed);
    memset(&p, 0, sizeof p);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_resolve(&ctx, &p, &r));
    TEST_ASSERT_EQUAL_DOUBLE(45.0, r.angle);
    TEST_ASSERT_EQUAL_INT(QC_EINVAL, qc_params_set(&ctx, &p, "bogus", 1.0));
    TEST_ASSERT_EQUAL_STRING("unknown parameter 'bogus'", qc_errmsg(&ctx));
}

static void resolve_should_refuse_out_of_range_values_by_name(void)
{
    qc_params p, r;

    memset(&p, 0, sizeof p);
    p.spacing = 0.01;
    TEST_ASSERT_EQUAL_INT(QC_ERANGE, qc_params_resolve(&ctx, &p, &r));
    TEST_ASSERT_EQUAL_STRING("spacing 0.01 mm out of range [0.5, 1000] mm", qc_errmsg(&ctx));
    memset(&p, 0, sizeof p);
    p.r_seed = 2.0;
    TEST_ASSERT_EQUAL_INT(QC_ERANGE, qc_params_resolve(&ctx, &p, &r));
    TEST_ASSERT_TRUE(strstr(qc_errmsg(&ctx), "r-seed 2") != NULL);
    memset(&p, 0, sizeof p);
    p.family = 42;
    TEST_ASSERT_EQUAL_INT(QC_EINVAL, qc_params_resolve(&ctx, &p, &r));
    memset(&p, 0, sizeof p);
    p.repeat_cols = 2.5;
    TEST_ASSERT_EQUAL_INT(QC_ERANGE, qc_params_resolve(&ctx, &p, &r));
}

static void names_should_map_both_ways(void)
{
    int f;

    for (f = 1; f < QC_FAMILY_COUNT; f++)
        TEST_ASSERT_EQUAL_INT(f, qc_family_from_name(qc_family_name(f)));
    TEST_ASSERT_EQUAL_INT(-1, qc_family_from_name("plaid"));
    TEST_ASSERT_EQUAL_INT(QC_POINTS_SNUB, qc_param_choice(qc_param_find("points"), "snub"));
    TEST_ASSERT_EQUAL_INT(-1, qc_param_choice(qc_param_find("points"), "sn"));
}

/* Enum rows are ints: NaN, inf and huge values are refused when set, by name. */
static void set_should_refuse_enum_values_no_int_holds(void)
{
    qc_params p;
    static const double bad[] = {(double)NAN, (double)INFINITY, -(double)INFINITY, 1e300, 0.5e10, 0.0, 99.0};
    size_t i;

    memset(&p, 0, sizeof p);
    for (i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        TEST_ASSERT_EQUAL_INT(QC_EINVAL, qc_params_set(&ctx, &p, "family", bad[i]));
        TEST_ASSERT_NOT_NULL(strstr(qc_errmsg(&ctx), "is not one of vine|branching"));
    }
    TEST_ASSERT_EQUAL_INT(0, p.family);
    TEST_ASSERT_EQUAL_UINT64(0, p.given);
}

/* Ids are unique, below 64 and findable; the bit a setter marks is the
 * row's id, not its place in the table. */
static void given_should_follow_the_parameter_id_not_the_row(void)
{
    size_t n, i, j;
    const qc_param_info *t = qc_param_table(&n);

    TEST_ASSERT_EQUAL_size_t(QC_PARAM_ID_COUNT, n);
    TEST_ASSERT_TRUE(QC_PARAM_ID_COUNT <= 64);
    for (i = 0; i < n; i++) {
        qc_params p;
        double v = t[i].type == QC_PARAM_ENUM ? 1.0 : t[i].min;

        TEST_ASSERT_TRUE(qc_param_by_id((int)t[i].id) == &t[i]);
        for (j = i + 1; j < n; j++)
            TEST_ASSERT_TRUE(t[i].id != t[j].id);
        memset(&p, 0, sizeof p);
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, t[i].name, v));
        TEST_ASSERT_EQUAL_UINT64(QC_PARAM_BIT(t[i].id), p.given);
        TEST_ASSERT_TRUE(qc_params_given(&p, (int)t[i].id));
    }
    TEST_ASSERT_NULL(qc_param_by_id(QC_PARAM_ID_COUNT));
    TEST_ASSERT_NULL(qc_param_by_id(-1));
    TEST_ASSERT_FALSE(qc_params_given(&(qc_params){0}, 64));
    /* the ids are ABI: a program built against an older header marks the
     * same bits (these were the table's row numbers when ids arrived) */
    TEST_ASSERT_EQUAL_INT(0, QC_PARAM_ID_FAMILY);
    TEST_ASSERT_EQUAL_INT(10, QC_PARAM_ID_SEED);
    TEST_ASSERT_EQUAL_INT(11, QC_PARAM_ID_SPACING);
    TEST_ASSERT_EQUAL_INT(23, QC_PARAM_ID_START_Y);
    TEST_ASSERT_TRUE(qc_param_find("start-y")->id == QC_PARAM_ID_START_Y);
    TEST_ASSERT_TRUE(qc_param_find("width")->id == QC_PARAM_ID_WIDTH);
}

/* qc_params_set_seed keeps all 64 bits (a double keeps 53) and marks the seed
 * given, so an explicit 0 stays 0; two seeds a double cannot tell apart give
 * two different patterns. */
static void set_seed_should_keep_all_64_bits(void)
{
    const uint64_t big = 18446744073709551557u, next = big - 1;
    qc_params p, r;
    qc_region block;
    qc_result a, b;

    TEST_ASSERT_TRUE((double)big == (double)next);
    memset(&p, 0, sizeof p);
    qc_params_set_seed(&p, big);
    TEST_ASSERT_EQUAL_UINT64(QC_PARAM_BIT(QC_PARAM_ID_SEED), p.given);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_resolve(&ctx, &p, &r));
    TEST_ASSERT_TRUE(r.seed == big);
    memset(&p, 0, sizeof p);
    qc_params_set_seed(&p, 0);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_resolve(&ctx, &p, &r));
    TEST_ASSERT_TRUE(r.seed == 0);

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_shape(&ctx, "rect:60x60", 1.0, &block));
    memset(&p, 0, sizeof p);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "spacing", 6.0));
    qc_params_set_seed(&p, big);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_generate(&ctx, &block, &p, NULL, NULL, &a));
    qc_params_set_seed(&p, next);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_generate(&ctx, &block, &p, NULL, NULL, &b));
    TEST_ASSERT_TRUE(a.points.n != b.points.n ||
                     memcmp(a.points.v, b.points.v, a.points.n * sizeof *a.points.v) != 0);
    qc_result_free(&ctx, &a);
    qc_result_free(&ctx, &b);
    qc_region_free(&ctx, &block);
}

/* The skeleton's choices are the stages' own enums, so qc_generate passes
 * them on with no table in between. */
static void skeleton_choices_should_be_the_stage_enums(void)
{
    static const struct { const char *row, *choice; int value; } cases[] = {
        {"points", "triangle", QC_SAMPLE_TRIANGLE}, {"points", "square", QC_SAMPLE_SQUARE},
        {"points", "hex", QC_SAMPLE_HEX},           {"points", "snub", QC_SAMPLE_SNUB},
        {"points", "poisson", QC_SAMPLE_POISSON},   {"points", "given", QC_POINTS_GIVEN},
        {"mst", "delaunay", QC_MST_MODE_DELAUNAY},  {"mst", "complete", QC_MST_MODE_COMPLETE},
        {"tsp", "greedy", QC_TSP_METHOD_GREEDY},    {"tsp", "2opt", QC_TSP_METHOD_2OPT},
        {"tsp", "oropt", QC_TSP_METHOD_OROPT},      {"tsp", "or3opt", QC_TSP_METHOD_OR3OPT}};
    qc_params p, r;
    size_t i;

    for (i = 0; i < sizeof cases / sizeof cases[0]; i++)
        TEST_ASSERT_EQUAL_INT_MESSAGE(cases[i].value,
                                      qc_param_choice(qc_param_find(cases[i].row), cases[i].choice),
                                      cases[i].choice);
    memset(&p, 0, sizeof p);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_resolve(&ctx, &p, &r));
    TEST_ASSERT_EQUAL_INT(QC_MST_MODE_DELAUNAY, r.mst);
    TEST_ASSERT_EQUAL_INT(QC_TSP_METHOD_OR3OPT, r.tsp);
    TEST_ASSERT_EQUAL_INT(QC_SAMPLE_POISSON, r.points);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(table_should_name_every_row_once_with_sane_ranges);
    RUN_TEST(resolve_should_fill_defaults_from_a_zeroed_struct);
    RUN_TEST(resolve_should_derive_family_defaults);
    RUN_TEST(set_should_keep_an_explicit_zero);
    RUN_TEST(resolve_should_refuse_out_of_range_values_by_name);
    RUN_TEST(names_should_map_both_ways);
    RUN_TEST(set_should_refuse_enum_values_no_int_holds);
    RUN_TEST(given_should_follow_the_parameter_id_not_the_row);
    RUN_TEST(set_seed_should_keep_all_64_bits);
    RUN_TEST(skeleton_choices_should_be_the_stage_enums);
    return UNITY_END();
}
