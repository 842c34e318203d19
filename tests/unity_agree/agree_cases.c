/*
 * Known passing, failing and ignored cases for tests/check_unity_agree.sh,
 * built against tests/unity/ and against a real Unity: both must print the
 * same lines. A case's name ends in its expected outcome (_passes, _fails,
 * _ignored); the script checks that too. Doubles reach the integer asserts
 * through variables on purpose: that is the conversion under test.
 */
#include <math.h>
#include <stddef.h>
#include <stdint.h>

#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

static double tiny = 4e-15, small = 1e-16, two_and_half = 2.5, two_and_tenth = 2.1;

static void int_less_than_truncates_doubles_fails(void) { TEST_ASSERT_LESS_THAN(tiny, small); }
static void int_greater_than_truncates_doubles_fails(void) { TEST_ASSERT_GREATER_THAN(two_and_tenth, two_and_half); }
static void int_or_equal_truncated_passes(void) { TEST_ASSERT_GREATER_OR_EQUAL(two_and_half, two_and_tenth); }
static void double_less_than_passes(void) { TEST_ASSERT_LESS_THAN_DOUBLE(tiny, small); }
static void double_greater_than_fails(void) { TEST_ASSERT_GREATER_THAN_DOUBLE(2.5, 2.5); }
static void double_or_equal_within_1e12_passes(void) { TEST_ASSERT_LESS_OR_EQUAL_DOUBLE(1.0, 1.0 + 1e-13); }
static void double_or_equal_beyond_fails(void) { TEST_ASSERT_LESS_OR_EQUAL_DOUBLE(1.0, 1.0 + 1e-9); }
static void double_less_than_nan_fails(void) { TEST_ASSERT_LESS_THAN_DOUBLE(1.0, nan("")); }
static void equal_double_relative_passes(void) { TEST_ASSERT_EQUAL_DOUBLE(1e6, 1e6 + 1e-7); }
static void equal_double_relative_fails(void) { TEST_ASSERT_EQUAL_DOUBLE(1.5, 1.5 + 1e-9); }
static void equal_double_nan_nan_passes(void) { TEST_ASSERT_EQUAL_DOUBLE(nan(""), nan("")); }
static void equal_double_inf_passes(void) { TEST_ASSERT_EQUAL_DOUBLE(INFINITY, INFINITY); }
static void equal_double_neg_inf_fails(void) { TEST_ASSERT_EQUAL_DOUBLE(INFINITY, -INFINITY); }
static void double_within_negative_delta_passes(void) { TEST_ASSERT_DOUBLE_WITHIN(-0.5, 1.0, 1.25); }
static void double_within_message_fails(void) { TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(0.01, 123456.789, 0.000123, "ctx"); }
static void double_prints_exponent_fails(void) { TEST_ASSERT_EQUAL_DOUBLE(1.25e-30, -3.5e+20); }
static void float_within_passes(void) { TEST_ASSERT_FLOAT_WITHIN(1e-3, 2.0, 2.0005); }
static void equal_float_fails(void) { TEST_ASSERT_EQUAL_FLOAT(1.0, 1.001); }
static void equal_int_fails(void) { TEST_ASSERT_EQUAL_INT(-3, 4); }
static void equal_int_message_fails(void) { TEST_ASSERT_EQUAL_INT_MESSAGE(1, 2, "the message"); }
static void equal_int8_wraps_passes(void) { TEST_ASSERT_EQUAL_INT8(-1, 255); }
static void equal_uint8_fails(void) { TEST_ASSERT_EQUAL_UINT8(1, 2); }
static void equal_uint16_wraps_passes(void) { TEST_ASSERT_EQUAL_UINT16(65537, 1); }
static void equal_uint_fails(void) { TEST_ASSERT_EQUAL_UINT(-1, 0); }
static void equal_size_t_fails(void) { TEST_ASSERT_EQUAL_size_t((size_t)7, (size_t)8); }
static void equal_uint64_fails(void) { TEST_ASSERT_EQUAL_UINT64(UINT64_MAX, 0); }
static void equal_int64_passes(void) { TEST_ASSERT_EQUAL_INT64(INT64_MIN, INT64_MIN); }
static void equal_hex8_fails(void) { TEST_ASSERT_EQUAL_HEX8(0xab, 0x1cd); }
static void equal_hex32_fails(void) { TEST_ASSERT_EQUAL_HEX32(0xdeadbeef, 0); }
static void equal_hex64_fails(void) { TEST_ASSERT_EQUAL_HEX64(0x0123456789abcdefULL, 1); }
static void uint_less_than_wraps_fails(void) { TEST_ASSERT_LESS_THAN_UINT(5, -1); }
static void int_less_or_equal_passes(void) { TEST_ASSERT_LESS_OR_EQUAL(5, 5); }
static void int_greater_than_message_fails(void) { TEST_ASSERT_GREATER_THAN_MESSAGE(5, 5, "five"); }
static void true_fails(void) { TEST_ASSERT_TRUE(1 == 2); }
static void false_fails(void) { TEST_ASSERT_FALSE(1); }
static void assert_fails(void) { TEST_ASSERT(0); }
static void assert_message_fails(void) { TEST_ASSERT_MESSAGE(0, "said why"); }
static void null_fails(void) { TEST_ASSERT_NULL(&tiny); }
static void not_null_fails(void) { TEST_ASSERT_NOT_NULL(NULL); }
static void string_fails(void) { TEST_ASSERT_EQUAL_STRING("abc\n", "abd"); }
static void string_null_fails(void) { TEST_ASSERT_EQUAL_STRING(NULL, "x"); }
static void string_both_null_passes(void) { TEST_ASSERT_EQUAL_STRING(NULL, NULL); }
static void memory_fails(void) { TEST_ASSERT_EQUAL_MEMORY("abcd", "abzd", 4); }
static void memory_zero_length_fails(void) { TEST_ASSERT_EQUAL_MEMORY("a", "b", 0); }
static void int_array_fails(void)
{
    int e[3] = {1, 2, 3}, a[3] = {1, 2, -4};
    TEST_ASSERT_EQUAL_INT_ARRAY(e, a, 3);
}
static void uint32_array_fails(void)
{
    uint32_t e[2] = {1, 0xffffffffu}, a[2] = {1, 2};
    TEST_ASSERT_EQUAL_UINT32_ARRAY(e, a, 2);
}
static void fail_message_fails(void) { TEST_FAIL_MESSAGE("explicit"); }
static void fail_fails(void) { TEST_FAIL(); }
static void ignore_ignored(void) { TEST_IGNORE(); }
static void ignore_message_ignored(void) { TEST_IGNORE_MESSAGE("later"); }
static void pass_stops_the_test_passes(void)
{
    TEST_PASS();
    TEST_FAIL_MESSAGE("not reached");
}
static void first_failure_ends_the_test_fails(void)
{
    TEST_ASSERT_EQUAL_INT(1, 2);
    TEST_ASSERT_EQUAL_INT(3, 4);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(int_less_than_truncates_doubles_fails);
    RUN_TEST(int_greater_than_truncates_doubles_fails);
    RUN_TEST(int_or_equal_truncated_passes);
    RUN_TEST(double_less_than_passes);
    RUN_TEST(double_greater_than_fails);
    RUN_TEST(double_or_equal_within_1e12_passes);
    RUN_TEST(double_or_equal_beyond_fails);
    RUN_TEST(double_less_than_nan_fails);
    RUN_TEST(equal_double_relative_passes);
    RUN_TEST(equal_double_relative_fails);
    RUN_TEST(equal_double_nan_nan_passes);
    RUN_TEST(equal_double_inf_passes);
    RUN_TEST(equal_double_neg_inf_fails);
    RUN_TEST(double_within_negative_delta_passes);
    RUN_TEST(double_within_message_fails);
    RUN_TEST(double_prints_exponent_fails);
    RUN_TEST(float_within_passes);
    RUN_TEST(equal_float_fails);
    RUN_TEST(equal_int_fails);
    RUN_TEST(equal_int_message_fails);
    RUN_TEST(equal_int8_wraps_passes);
    RUN_TEST(equal_uint8_fails);
    RUN_TEST(equal_uint16_wraps_passes);
    RUN_TEST(equal_uint_fails);
    RUN_TEST(equal_size_t_fails);
    RUN_TEST(equal_uint64_fails);
    RUN_TEST(equal_int64_passes);
    RUN_TEST(equal_hex8_fails);
    RUN_TEST(equal_hex32_fails);
    RUN_TEST(equal_hex64_fails);
    RUN_TEST(uint_less_than_wraps_fails);
    RUN_TEST(int_less_or_equal_passes);
    RUN_TEST(int_greater_than_message_fails);
    RUN_TEST(true_fails);
    RUN_TEST(false_fails);
    RUN_TEST(assert_fails);
    RUN_TEST(assert_message_fails);
    RUN_TEST(null_fails);
    RUN_TEST(not_null_fails);
    RUN_TEST(string_fails);
    RUN_TEST(string_null_fails);
    RUN_TEST(string_both_null_passes);
    RUN_TEST(memory_fails);
    RUN_TEST(memory_zero_length_fails);
    RUN_TEST(int_array_fails);
    RUN_TEST(uint32_array_fails);
    RUN_TEST(fail_message_fails);
    RUN_TEST(fail_fails);
    RUN_TEST(ignore_ignored);
    RUN_TEST(ignore_message_ignored);
    RUN_TEST(pass_stops_the_test_passes);
    RUN_TEST(first_failure_ends_the_test_fails);
    (void)UNITY_END(); /* failures are expected: the script reads the lines */
    return 0;
}
