/*
 * A small Unity-compatible harness: the subset of Unity's API that quiltc's
 * tests use, with the same names and the same summary line, so the tests
 * compile unchanged against ThrowTheSwitch's Unity (make UNITY_DIR=...).
 */
#ifndef UNITY_H
#define UNITY_H

#include <setjmp.h>
#include <stddef.h>
#include <stdint.h>

void setUp(void);
void tearDown(void);

void UnityBegin(const char *file);
int UnityEnd(void);
void UnityDefaultTestRun(void (*func)(void), const char *name, int line);
void UnityFail(const char *msg, int line);
void UnityIgnore(const char *msg, int line);
void UnityAssertInt(int64_t expected, int64_t actual, const char *msg, int line);
void UnityAssertUint(uint64_t expected, uint64_t actual, const char *msg, int line);
void UnityAssertCmp(double threshold, double actual, int op, const char *msg, int line);
void UnityAssertDoubleWithin(double delta, double expected, double actual,
                             const char *msg, int line);
void UnityAssertString(const char *expected, const char *actual, const char *msg, int line);
void UnityAssertMemory(const void *expected, const void *actual, size_t len,
                       const char *msg, int line);

#define UNITY_BEGIN() UnityBegin(__FILE__)
#define UNITY_END() UnityEnd()
#define RUN_TEST(func) UnityDefaultTestRun(func, #func, __LINE__)

#define TEST_FAIL_MESSAGE(m) UnityFail((m), __LINE__)
#define TEST_FAIL() UnityFail(NULL, __LINE__)
#define TEST_IGNORE_MESSAGE(m) UnityIgnore((m), __LINE__)
#define TEST_IGNORE() UnityIgnore(NULL, __LINE__)
#define TEST_PASS() ((void)0)
#define TEST_MESSAGE(m) ((void)(m))

#define TEST_ASSERT_MESSAGE(c, m) do { if (!(c)) UnityFail((m) ? (m) : "Expression Evaluated To FALSE", __LINE__); } while (0)
#define TEST_ASSERT(c) TEST_ASSERT_MESSAGE((c), "Expression Evaluated To FALSE")
#define TEST_ASSERT_TRUE(c) TEST_ASSERT_MESSAGE((c), "Expected TRUE Was FALSE")
#define TEST_ASSERT_TRUE_MESSAGE(c, m) TEST_ASSERT_MESSAGE((c), (m))
#define TEST_ASSERT_FALSE(c) TEST_ASSERT_MESSAGE(!(c), "Expected FALSE Was TRUE")
#define TEST_ASSERT_FALSE_MESSAGE(c, m) TEST_ASSERT_MESSAGE(!(c), (m))
#define TEST_ASSERT_NULL(p) TEST_ASSERT_MESSAGE((p) == NULL, "Expected NULL")
#define TEST_ASSERT_NULL_MESSAGE(p, m) TEST_ASSERT_MESSAGE((p) == NULL, (m))
#define TEST_ASSERT_NOT_NULL(p) TEST_ASSERT_MESSAGE((p) != NULL, "Expected Non-NULL")
#define TEST_ASSERT_NOT_NULL_MESSAGE(p, m) TEST_ASSERT_MESSAGE((p) != NULL, (m))

#define TEST_ASSERT_EQUAL_INT_MESSAGE(e, a, m) UnityAssertInt((int64_t)(e), (int64_t)(a), (m), __LINE__)
#define TEST_ASSERT_EQUAL_INT(e, a) TEST_ASSERT_EQUAL_INT_MESSAGE(e, a, NULL)
#define TEST_ASSERT_EQUAL(e, a) TEST_ASSERT_EQUAL_INT_MESSAGE(e, a, NULL)
#define TEST_ASSERT_EQUAL_MESSAGE(e, a, m) TEST_ASSERT_EQUAL_INT_MESSAGE(e, a, m)
#define TEST_ASSERT_EQUAL_INT8(e, a) TEST_ASSERT_EQUAL_INT(e, a)
#define TEST_ASSERT_EQUAL_INT16(e, a) TEST_ASSERT_EQUAL_INT(e, a)
#define TEST_ASSERT_EQUAL_INT32(e, a) TEST_ASSERT_EQUAL_INT(e, a)
#define TEST_ASSERT_EQUAL_INT64(e, a) TEST_ASSERT_EQUAL_INT(e, a)
#define TEST_ASSERT_EQUAL_UINT_MESSAGE(e, a, m) UnityAssertUint((uint64_t)(e), (uint64_t)(a), (m), __LINE__)
#define TEST_ASSERT_EQUAL_UINT(e, a) TEST_ASSERT_EQUAL_UINT_MESSAGE(e, a, NULL)
#define TEST_ASSERT_EQUAL_UINT8(e, a) TEST_ASSERT_EQUAL_UINT(e, a)
#define TEST_ASSERT_EQUAL_UINT16(e, a) TEST_ASSERT_EQUAL_UINT(e, a)
#define TEST_ASSERT_EQUAL_UINT32(e, a) TEST_ASSERT_EQUAL_UINT(e, a)
#define TEST_ASSERT_EQUAL_UINT64(e, a) TEST_ASSERT_EQUAL_UINT(e, a)
#define TEST_ASSERT_EQUAL_UINT32_MESSAGE(e, a, m) TEST_ASSERT_EQUAL_UINT_MESSAGE(e, a, m)
#define TEST_ASSERT_EQUAL_size_t(e, a) TEST_ASSERT_EQUAL_UINT(e, a)
#define TEST_ASSERT_EQUAL_size_t_MESSAGE(e, a, m) TEST_ASSERT_EQUAL_UINT_MESSAGE(e, a, m)
#define TEST_ASSERT_EQUAL_HEX8(e, a) TEST_ASSERT_EQUAL_UINT(e, a)
#define TEST_ASSERT_EQUAL_HEX32(e, a) TEST_ASSERT_EQUAL_UINT(e, a)
#define TEST_ASSERT_EQUAL_HEX64(e, a) TEST_ASSERT_EQUAL_UINT(e, a)
#define TEST_ASSERT_EQUAL_INT_ARRAY(e, a, n) TEST_ASSERT_EQUAL_MEMORY((e), (a), (n) * sizeof *(e))
#define TEST_ASSERT_EQUAL_UINT32_ARRAY(e, a, n) TEST_ASSERT_EQUAL_MEMORY((e), (a), (n) * sizeof *(e))

/* op: 0 greater than, 1 greater or equal, 2 less than, 3 less or equal (actual vs threshold) */
#define TEST_ASSERT_GREATER_THAN(t, a) UnityAssertCmp((double)(t), (double)(a), 0, NULL, __LINE__)
#define TEST_ASSERT_GREATER_OR_EQUAL(t, a) UnityAssertCmp((double)(t), (double)(a), 1, NULL, __LINE__)
#define TEST_ASSERT_LESS_THAN(t, a) UnityAssertCmp((double)(t), (double)(a), 2, NULL, __LINE__)
#define TEST_ASSERT_LESS_OR_EQUAL(t, a) UnityAssertCmp((double)(t), (double)(a), 3, NULL, __LINE__)
#define TEST_ASSERT_GREATER_THAN_MESSAGE(t, a, m) UnityAssertCmp((double)(t), (double)(a), 0, (m), __LINE__)
#define TEST_ASSERT_GREATER_OR_EQUAL_MESSAGE(t, a, m) UnityAssertCmp((double)(t), (double)(a), 1, (m), __LINE__)
#define TEST_ASSERT_LESS_THAN_MESSAGE(t, a, m) UnityAssertCmp((double)(t), (double)(a), 2, (m), __LINE__)
#define TEST_ASSERT_LESS_OR_EQUAL_MESSAGE(t, a, m) UnityAssertCmp((double)(t), (double)(a), 3, (m), __LINE__)
#define TEST_ASSERT_GREATER_THAN_INT(t, a) TEST_ASSERT_GREATER_THAN(t, a)
#define TEST_ASSERT_LESS_THAN_INT(t, a) TEST_ASSERT_LESS_THAN(t, a)
#define TEST_ASSERT_GREATER_OR_EQUAL_INT(t, a) TEST_ASSERT_GREATER_OR_EQUAL(t, a)
#define TEST_ASSERT_LESS_OR_EQUAL_INT(t, a) TEST_ASSERT_LESS_OR_EQUAL(t, a)
#define TEST_ASSERT_GREATER_THAN_UINT(t, a) TEST_ASSERT_GREATER_THAN(t, a)
#define TEST_ASSERT_LESS_THAN_UINT(t, a) TEST_ASSERT_LESS_THAN(t, a)
#define TEST_ASSERT_GREATER_OR_EQUAL_UINT(t, a) TEST_ASSERT_GREATER_OR_EQUAL(t, a)
#define TEST_ASSERT_LESS_OR_EQUAL_UINT(t, a) TEST_ASSERT_LESS_OR_EQUAL(t, a)
#define TEST_ASSERT_GREATER_THAN_DOUBLE(t, a) TEST_ASSERT_GREATER_THAN(t, a)
#define TEST_ASSERT_LESS_THAN_DOUBLE(t, a) TEST_ASSERT_LESS_THAN(t, a)
#define TEST_ASSERT_GREATER_OR_EQUAL_DOUBLE(t, a) TEST_ASSERT_GREATER_OR_EQUAL(t, a)
#define TEST_ASSERT_LESS_OR_EQUAL_DOUBLE(t, a) TEST_ASSERT_LESS_OR_EQUAL(t, a)

#define TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(d, e, a, m) UnityAssertDoubleWithin((d), (e), (a), (m), __LINE__)
#define TEST_ASSERT_DOUBLE_WITHIN(d, e, a) TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(d, e, a, NULL)
#define TEST_ASSERT_FLOAT_WITHIN(d, e, a) TEST_ASSERT_DOUBLE_WITHIN(d, e, a)
#define TEST_ASSERT_EQUAL_DOUBLE(e, a) UnityAssertDoubleWithin(0.0, (e), (a), NULL, __LINE__)
#define TEST_ASSERT_EQUAL_DOUBLE_MESSAGE(e, a, m) UnityAssertDoubleWithin(0.0, (e), (a), (m), __LINE__)
#define TEST_ASSERT_EQUAL_FLOAT(e, a) UnityAssertDoubleWithin(1e-6, (e), (a), NULL, __LINE__)

#define TEST_ASSERT_EQUAL_STRING(e, a) UnityAssertString((e), (a), NULL, __LINE__)
#define TEST_ASSERT_EQUAL_STRING_MESSAGE(e, a, m) UnityAssertString((e), (a), (m), __LINE__)
#define TEST_ASSERT_EQUAL_MEMORY(e, a, n) UnityAssertMemory((e), (a), (n), NULL, __LINE__)
#define TEST_ASSERT_EQUAL_MEMORY_MESSAGE(e, a, n, m) UnityAssertMemory((e), (a), (n), (m), __LINE__)

#endif
