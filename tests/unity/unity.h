/*
 * A small Unity-compatible harness: the subset of ThrowTheSwitch Unity's API
 * that quiltc's tests use, with Unity's semantics, so a test passes here
 * exactly when it passes against the real Unity (make UNITY_DIR=...; built
 * with UNITY_INCLUDE_DOUBLE and UNITY_SUPPORT_64). In particular:
 * - every integer assert (EQUAL_INT/UINT/size_t/HEX, GREATER_THAN, LESS_THAN,
 *   ..._OR_EQUAL) converts both sides to a 64-bit integer, as Unity's
 *   (UNITY_INT) cast does: TEST_ASSERT_LESS_THAN(4e-15, x) is `0 < (int)x`.
 *   The conversion is implicit here, so the tests' -Wfloat-conversion flags a
 *   double handed to an integer assert; use the _DOUBLE / _WITHIN asserts.
 * - EQUAL_DOUBLE is within |expected| * 1e-12, EQUAL_FLOAT within
 *   |expected| * 1e-5 in float; NaN equals NaN; same-signed infinities match.
 * - the output lines, the failure texts and the summary are Unity's.
 * tests/check_unity_agree.sh builds one file against both and diffs them.
 */
#ifndef UNITY_H
#define UNITY_H

#include <setjmp.h>
#include <stddef.h>
#include <stdint.h>

void setUp(void);
void tearDown(void);

/* How a number is narrowed and shown: the low nibble is the width in bytes. */
enum {
    UNITY_RANGE_INT = 0x10, UNITY_RANGE_UINT = 0x20, UNITY_RANGE_HEX = 0x40,
    UNITY_STYLE_INT = 8 | UNITY_RANGE_INT, UNITY_STYLE_INT8 = 1 | UNITY_RANGE_INT,
    UNITY_STYLE_INT16 = 2 | UNITY_RANGE_INT, UNITY_STYLE_INT32 = 4 | UNITY_RANGE_INT,
    UNITY_STYLE_UINT = 8 | UNITY_RANGE_UINT, UNITY_STYLE_UINT8 = 1 | UNITY_RANGE_UINT,
    UNITY_STYLE_UINT16 = 2 | UNITY_RANGE_UINT, UNITY_STYLE_UINT32 = 4 | UNITY_RANGE_UINT,
    UNITY_STYLE_HEX8 = 1 | UNITY_RANGE_HEX, UNITY_STYLE_HEX32 = 4 | UNITY_RANGE_HEX,
    UNITY_STYLE_HEX64 = 8 | UNITY_RANGE_HEX
};
/* Unity's comparison bits. */
enum { UNITY_EQUAL_TO = 1, UNITY_GREATER_THAN = 2, UNITY_SMALLER_THAN = 4 };

extern jmp_buf UnityAbortFrame;
#define TEST_PROTECT() (setjmp(UnityAbortFrame) == 0)
#define TEST_ABORT() longjmp(UnityAbortFrame, 1)

void UnityBegin(const char *file);
int UnityEnd(void);
void UnityDefaultTestRun(void (*func)(void), const char *name, int line);
void UnityFail(const char *msg, int line);
void UnityIgnore(const char *msg, int line);
void UnityMessage(const char *msg, int line);
void UnityAssertEqualIntNumber(int64_t expected, int64_t actual, const char *msg, int line,
                               int style);
void UnityAssertEqualUintNumber(uint64_t expected, uint64_t actual, const char *msg, int line,
                                int style);
void UnityAssertIntCompare(int64_t threshold, int64_t actual, int compare, const char *msg,
                           int line);
void UnityAssertUintCompare(uint64_t threshold, uint64_t actual, int compare, const char *msg,
                            int line);
void UnityAssertDoublesWithin(double delta, double expected, double actual, const char *msg,
                              int line);
void UnityAssertFloatsWithin(float delta, float expected, float actual, const char *msg,
                             int line);
void UnityAssertDoubleCompare(double threshold, double actual, int compare, const char *msg,
                              int line);
void UnityAssertEqualString(const char *expected, const char *actual, const char *msg, int line);
void UnityAssertEqualMemory(const void *expected, const void *actual, uint32_t len,
                            const char *msg, int line);
void UnityAssertEqualIntArray(const void *expected, const void *actual, uint32_t n,
                              const char *msg, int line, int style);

#define UNITY_BEGIN() UnityBegin(__FILE__)
#define UNITY_END() UnityEnd()
#define RUN_TEST(func) UnityDefaultTestRun(func, #func, __LINE__)

#define TEST_FAIL_MESSAGE(m) UnityFail((m), __LINE__)
#define TEST_FAIL() UnityFail(NULL, __LINE__)
#define TEST_IGNORE_MESSAGE(m) UnityIgnore((m), __LINE__)
#define TEST_IGNORE() UnityIgnore(NULL, __LINE__)
#define TEST_PASS() TEST_ABORT()
#define TEST_MESSAGE(m) UnityMessage((m), __LINE__)

#define TEST_ASSERT_MESSAGE(c, m) do { if (c) { } else UnityFail((m), __LINE__); } while (0)
#define TEST_ASSERT(c) TEST_ASSERT_MESSAGE((c), " Expression Evaluated To FALSE")
#define TEST_ASSERT_TRUE(c) TEST_ASSERT_MESSAGE((c), " Expected TRUE Was FALSE")
#define TEST_ASSERT_TRUE_MESSAGE(c, m) TEST_ASSERT_MESSAGE((c), (m))
#define TEST_ASSERT_FALSE(c) TEST_ASSERT_MESSAGE(!(c), " Expected FALSE Was TRUE")
#define TEST_ASSERT_FALSE_MESSAGE(c, m) TEST_ASSERT_MESSAGE(!(c), (m))
#define TEST_ASSERT_NULL(p) TEST_ASSERT_MESSAGE((p) == NULL, " Expected NULL")
#define TEST_ASSERT_NULL_MESSAGE(p, m) TEST_ASSERT_MESSAGE((p) == NULL, (m))
#define TEST_ASSERT_NOT_NULL(p) TEST_ASSERT_MESSAGE((p) != NULL, " Expected Non-NULL")
#define TEST_ASSERT_NOT_NULL_MESSAGE(p, m) TEST_ASSERT_MESSAGE((p) != NULL, (m))

/* Integers: no casts, so a double argument warns under -Wfloat-conversion. */
#define UNITY_EQ_INT(e, a, m, s) UnityAssertEqualIntNumber((e), (a), (m), __LINE__, (s))
#define UNITY_EQ_UINT(e, a, m, s) UnityAssertEqualUintNumber((e), (a), (m), __LINE__, (s))
#define TEST_ASSERT_EQUAL_INT_MESSAGE(e, a, m) UNITY_EQ_INT(e, a, m, UNITY_STYLE_INT)
#define TEST_ASSERT_EQUAL_INT(e, a) UNITY_EQ_INT(e, a, NULL, UNITY_STYLE_INT)
#define TEST_ASSERT_EQUAL(e, a) UNITY_EQ_INT(e, a, NULL, UNITY_STYLE_INT)
#define TEST_ASSERT_EQUAL_MESSAGE(e, a, m) UNITY_EQ_INT(e, a, m, UNITY_STYLE_INT)
#define TEST_ASSERT_EQUAL_INT8(e, a) UNITY_EQ_INT(e, a, NULL, UNITY_STYLE_INT8)
#define TEST_ASSERT_EQUAL_INT16(e, a) UNITY_EQ_INT(e, a, NULL, UNITY_STYLE_INT16)
#define TEST_ASSERT_EQUAL_INT32(e, a) UNITY_EQ_INT(e, a, NULL, UNITY_STYLE_INT32)
#define TEST_ASSERT_EQUAL_INT64(e, a) UNITY_EQ_INT(e, a, NULL, UNITY_STYLE_INT)
#define TEST_ASSERT_EQUAL_UINT_MESSAGE(e, a, m) UNITY_EQ_UINT(e, a, m, UNITY_STYLE_UINT)
#define TEST_ASSERT_EQUAL_UINT(e, a) UNITY_EQ_UINT(e, a, NULL, UNITY_STYLE_UINT)
#define TEST_ASSERT_EQUAL_UINT8(e, a) UNITY_EQ_UINT(e, a, NULL, UNITY_STYLE_UINT8)
#define TEST_ASSERT_EQUAL_UINT16(e, a) UNITY_EQ_UINT(e, a, NULL, UNITY_STYLE_UINT16)
#define TEST_ASSERT_EQUAL_UINT32(e, a) UNITY_EQ_UINT(e, a, NULL, UNITY_STYLE_UINT32)
#define TEST_ASSERT_EQUAL_UINT32_MESSAGE(e, a, m) UNITY_EQ_UINT(e, a, m, UNITY_STYLE_UINT32)
#define TEST_ASSERT_EQUAL_UINT64(e, a) UNITY_EQ_UINT(e, a, NULL, UNITY_STYLE_UINT)
#define TEST_ASSERT_EQUAL_size_t(e, a) UNITY_EQ_UINT(e, a, NULL, UNITY_STYLE_UINT)
#define TEST_ASSERT_EQUAL_size_t_MESSAGE(e, a, m) UNITY_EQ_UINT(e, a, m, UNITY_STYLE_UINT)
#define TEST_ASSERT_EQUAL_HEX8(e, a) UNITY_EQ_UINT(e, a, NULL, UNITY_STYLE_HEX8)
#define TEST_ASSERT_EQUAL_HEX32(e, a) UNITY_EQ_UINT(e, a, NULL, UNITY_STYLE_HEX32)
#define TEST_ASSERT_EQUAL_HEX64(e, a) UNITY_EQ_UINT(e, a, NULL, UNITY_STYLE_HEX64)
#define TEST_ASSERT_EQUAL_INT_ARRAY(e, a, n) \
    UnityAssertEqualIntArray((e), (a), (uint32_t)(n), NULL, __LINE__, (int)sizeof(int) | UNITY_RANGE_INT)
#define TEST_ASSERT_EQUAL_UINT32_ARRAY(e, a, n) \
    UnityAssertEqualIntArray((e), (a), (uint32_t)(n), NULL, __LINE__, UNITY_STYLE_UINT32)

/* (threshold, actual): GREATER_THAN passes when actual > threshold. */
#define UNITY_CMP_INT(t, a, c, m) UnityAssertIntCompare((t), (a), (c), (m), __LINE__)
#define UNITY_CMP_UINT(t, a, c, m) UnityAssertUintCompare((t), (a), (c), (m), __LINE__)
#define UNITY_GE (UNITY_GREATER_THAN | UNITY_EQUAL_TO)
#define UNITY_LE (UNITY_SMALLER_THAN | UNITY_EQUAL_TO)
#define TEST_ASSERT_GREATER_THAN(t, a) UNITY_CMP_INT(t, a, UNITY_GREATER_THAN, NULL)
#define TEST_ASSERT_GREATER_OR_EQUAL(t, a) UNITY_CMP_INT(t, a, UNITY_GE, NULL)
#define TEST_ASSERT_LESS_THAN(t, a) UNITY_CMP_INT(t, a, UNITY_SMALLER_THAN, NULL)
#define TEST_ASSERT_LESS_OR_EQUAL(t, a) UNITY_CMP_INT(t, a, UNITY_LE, NULL)
#define TEST_ASSERT_GREATER_THAN_MESSAGE(t, a, m) UNITY_CMP_INT(t, a, UNITY_GREATER_THAN, m)
#define TEST_ASSERT_GREATER_OR_EQUAL_MESSAGE(t, a, m) UNITY_CMP_INT(t, a, UNITY_GE, m)
#define TEST_ASSERT_LESS_THAN_MESSAGE(t, a, m) UNITY_CMP_INT(t, a, UNITY_SMALLER_THAN, m)
#define TEST_ASSERT_LESS_OR_EQUAL_MESSAGE(t, a, m) UNITY_CMP_INT(t, a, UNITY_LE, m)
#define TEST_ASSERT_GREATER_THAN_INT(t, a) UNITY_CMP_INT(t, a, UNITY_GREATER_THAN, NULL)
#define TEST_ASSERT_LESS_THAN_INT(t, a) UNITY_CMP_INT(t, a, UNITY_SMALLER_THAN, NULL)
#define TEST_ASSERT_GREATER_OR_EQUAL_INT(t, a) UNITY_CMP_INT(t, a, UNITY_GE, NULL)
#define TEST_ASSERT_LESS_OR_EQUAL_INT(t, a) UNITY_CMP_INT(t, a, UNITY_LE, NULL)
#define TEST_ASSERT_GREATER_THAN_UINT(t, a) UNITY_CMP_UINT(t, a, UNITY_GREATER_THAN, NULL)
#define TEST_ASSERT_LESS_THAN_UINT(t, a) UNITY_CMP_UINT(t, a, UNITY_SMALLER_THAN, NULL)
#define TEST_ASSERT_GREATER_OR_EQUAL_UINT(t, a) UNITY_CMP_UINT(t, a, UNITY_GE, NULL)
#define TEST_ASSERT_LESS_OR_EQUAL_UINT(t, a) UNITY_CMP_UINT(t, a, UNITY_LE, NULL)

/* Doubles: "or equal" means within |threshold| * 1e-12, as in Unity. */
#define UNITY_CMP_DOUBLE(t, a, c, m) UnityAssertDoubleCompare((double)(t), (double)(a), (c), (m), __LINE__)
#define TEST_ASSERT_GREATER_THAN_DOUBLE(t, a) UNITY_CMP_DOUBLE(t, a, UNITY_GREATER_THAN, NULL)
#define TEST_ASSERT_GREATER_OR_EQUAL_DOUBLE(t, a) UNITY_CMP_DOUBLE(t, a, UNITY_GE, NULL)
#define TEST_ASSERT_LESS_THAN_DOUBLE(t, a) UNITY_CMP_DOUBLE(t, a, UNITY_SMALLER_THAN, NULL)
#define TEST_ASSERT_LESS_OR_EQUAL_DOUBLE(t, a) UNITY_CMP_DOUBLE(t, a, UNITY_LE, NULL)
#define TEST_ASSERT_GREATER_THAN_DOUBLE_MESSAGE(t, a, m) UNITY_CMP_DOUBLE(t, a, UNITY_GREATER_THAN, m)
#define TEST_ASSERT_GREATER_OR_EQUAL_DOUBLE_MESSAGE(t, a, m) UNITY_CMP_DOUBLE(t, a, UNITY_GE, m)
#define TEST_ASSERT_LESS_THAN_DOUBLE_MESSAGE(t, a, m) UNITY_CMP_DOUBLE(t, a, UNITY_SMALLER_THAN, m)
#define TEST_ASSERT_LESS_OR_EQUAL_DOUBLE_MESSAGE(t, a, m) UNITY_CMP_DOUBLE(t, a, UNITY_LE, m)

#define TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(d, e, a, m) \
    UnityAssertDoublesWithin((double)(d), (double)(e), (double)(a), (m), __LINE__)
#define TEST_ASSERT_DOUBLE_WITHIN(d, e, a) TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(d, e, a, NULL)
#define TEST_ASSERT_EQUAL_DOUBLE_MESSAGE(e, a, m) \
    TEST_ASSERT_DOUBLE_WITHIN_MESSAGE((double)(e) * 1e-12, e, a, m)
#define TEST_ASSERT_EQUAL_DOUBLE(e, a) TEST_ASSERT_EQUAL_DOUBLE_MESSAGE(e, a, NULL)
#define TEST_ASSERT_FLOAT_WITHIN(d, e, a) \
    UnityAssertFloatsWithin((float)(d), (float)(e), (float)(a), NULL, __LINE__)
#define TEST_ASSERT_EQUAL_FLOAT(e, a) \
    UnityAssertFloatsWithin((float)(e) * 0.00001f, (float)(e), (float)(a), NULL, __LINE__)

#define TEST_ASSERT_EQUAL_STRING(e, a) UnityAssertEqualString((e), (a), NULL, __LINE__)
#define TEST_ASSERT_EQUAL_STRING_MESSAGE(e, a, m) UnityAssertEqualString((e), (a), (m), __LINE__)
#define TEST_ASSERT_EQUAL_MEMORY(e, a, n) UnityAssertEqualMemory((e), (a), (uint32_t)(n), NULL, __LINE__)
#define TEST_ASSERT_EQUAL_MEMORY_MESSAGE(e, a, n, m) \
    UnityAssertEqualMemory((e), (a), (uint32_t)(n), (m), __LINE__)

#endif
