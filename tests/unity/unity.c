/*
 * The harness behind tests/unity/unity.h: Unity's checks, lines and summary.
 * Each assert follows the function of the same name in ThrowTheSwitch's
 * unity.c (UNITY_INCLUDE_DOUBLE, UNITY_SUPPORT_64, default output).
 */
#include "unity.h"

#include <math.h>
#include <stdio.h>

jmp_buf UnityAbortFrame;

static struct {
    const char *file;
    const char *test;
    int test_line;
    int tests, failures, ignored;
    int failed, skipped;
} U;

static void fail_and_bail(void)
{
    U.failed = 1;
    fflush(stdout);
    TEST_ABORT();
}

/* An assert inside an already failed or ignored test ends it (tearDown too). */
static void return_if_fail_or_ignore(void)
{
    if (U.failed || U.skipped)
        TEST_ABORT();
}

/* Printable characters as is, CR and LF as \r \n, others as \xNN. */
static void print(const char *s)
{
    for (; s != NULL && *s != '\0'; s++) {
        if (*s >= 32 && *s <= 126)
            putchar(*s);
        else if (*s == 13)
            fputs("\\r", stdout);
        else if (*s == 10)
            fputs("\\n", stdout);
        else
            printf("\\x%02X", (unsigned)(unsigned char)*s);
    }
}

static void print_hex(uint64_t v, int nibbles)
{
    printf("0x");
    while (nibbles-- > 0)
        putchar("0123456789ABCDEF"[(v >> (nibbles * 4)) & 15]);
}

static void print_int(int64_t v, int style)
{
    if (style & UNITY_RANGE_INT)
        printf("%lld", (long long)v);
    else if (style & UNITY_RANGE_UINT)
        printf("%llu", (unsigned long long)(uint64_t)v);
    else
        print_hex((uint64_t)v, (style & 15) * 2);
}

/* UnityPrintFloat: 9 significant digits, trailing zeros dropped, |x| < 1e-12 is 0. */
static void print_float(double x)
{
    const int32_t min_scaled = 100000000, max_scaled = 1000000000;
    int32_t n_int = 0, n, two_trunc;
    int exponent = 0, decimals, digits;
    char buf[16];

    if (fabs(x) < 1e-12) {
        putchar('0');
        return;
    }
    if (isnan(x)) {
        printf("NaN");
        return;
    }
    if (isinf(x)) {
        printf(x < 0 ? "Negative Infinity" : "Infinity");
        return;
    }
    if (x < 0) {
        putchar('-');
        x = -x;
    }
    if (x < 1.0) {
        double factor = 1.0;
        while (x < (double)max_scaled / 1e10) { x *= 1e10; exponent -= 10; }
        while (x * factor < (double)min_scaled) { factor *= 10.0; exponent--; }
        x *= factor;
    } else if (x > (double)max_scaled) {
        double divisor = 1.0;
        while (x > (double)min_scaled * 1e10) { x /= 1e10; exponent += 10; }
        while (x / divisor > (double)max_scaled) { divisor *= 10.0; exponent++; }
        x /= divisor;
    } else {
        double factor = 1.0;
        n_int = (int32_t)x;
        x -= (double)n_int;
        while (n_int < min_scaled) { n_int *= 10; factor *= 10.0; exponent--; }
        x *= factor;
    }
    two_trunc = (int32_t)(x + x);
    n = (two_trunc + 1) / 2;
    if ((n & 1) && (two_trunc & 1) && !((double)two_trunc < x + x))
        n--; /* ties to even */
    n += n_int;
    if (n >= max_scaled) {
        n = min_scaled;
        exponent++;
    }
    decimals = (exponent <= 0 && exponent >= -(9 + 3)) ? -exponent : 9 - 1;
    exponent += decimals;
    while (decimals > 0 && n % 10 == 0) {
        n /= 10;
        decimals--;
    }
    digits = 0;
    while (n != 0 || digits <= decimals) {
        buf[digits++] = (char)('0' + n % 10);
        n /= 10;
    }
    while (digits > 0) {
        if (digits == decimals)
            putchar('.');
        putchar(buf[--digits]);
    }
    if (exponent != 0)
        printf("e%c%02d", exponent < 0 ? '-' : '+', exponent < 0 ? -exponent : exponent);
}

static void results_begin(int line)
{
    printf("%s:%d:", U.file, line);
    print(U.test);
    putchar(':');
}

static void fail_begin(int line)
{
    results_begin(line);
    printf("FAIL:");
}

static void add_msg(const char *msg)
{
    if (msg != NULL) {
        putchar(':');
        print(msg);
    }
}

void UnityBegin(const char *file)
{
    U.file = file;
    U.test = NULL;
    U.test_line = 0;
    U.tests = U.failures = U.ignored = 0;
    U.failed = U.skipped = 0;
}

void UnityFail(const char *msg, int line)
{
    return_if_fail_or_ignore();
    results_begin(line);
    printf("FAIL");
    add_msg(msg);
    fail_and_bail();
}

void UnityIgnore(const char *msg, int line)
{
    return_if_fail_or_ignore();
    results_begin(line);
    printf("IGNORE");
    if (msg != NULL) {
        printf(": ");
        print(msg);
    }
    U.skipped = 1;
    fflush(stdout);
    TEST_ABORT();
}

void UnityMessage(const char *msg, int line)
{
    results_begin(line);
    printf("INFO");
    if (msg != NULL) {
        printf(": ");
        print(msg);
    }
    putchar('\n');
}

static void conclude_test(void)
{
    if (U.skipped) {
        U.ignored++;
    } else if (!U.failed) {
        results_begin(U.test_line);
        printf("PASS");
    } else {
        U.failures++;
    }
    U.failed = U.skipped = 0;
    putchar('\n');
    fflush(stdout);
}

void UnityDefaultTestRun(void (*func)(void), const char *name, int line)
{
    U.test = name;
    U.test_line = line;
    U.tests++;
    if (TEST_PROTECT()) {
        setUp();
        func();
    }
    if (TEST_PROTECT())
        tearDown();
    conclude_test();
}

int UnityEnd(void)
{
    printf("\n-----------------------\n%d Tests %d Failures %d Ignored \n%s\n", U.tests,
           U.failures, U.ignored, U.failures == 0 ? "OK" : "FAIL");
    fflush(stdout);
    return U.failures;
}

/* Sign-extends or zero-extends the low `style & 15` bytes, as Unity's casts do. */
static int64_t narrow(int64_t v, int style)
{
    int bytes = style & 15;
    uint64_t u = (uint64_t)v;

    if (bytes >= 8)
        return v;
    u &= ((uint64_t)1 << (bytes * 8)) - 1;
    if ((style & UNITY_RANGE_INT) && (u >> (bytes * 8 - 1)))
        u |= ~(((uint64_t)1 << (bytes * 8)) - 1);
    return (int64_t)u;
}

void UnityAssertEqualIntNumber(int64_t e, int64_t a, const char *msg, int line, int style)
{
    return_if_fail_or_ignore();
    e = narrow(e, style);
    a = narrow(a, style);
    if (e != a) {
        fail_begin(line);
        printf(" Expected ");
        print_int(e, style);
        printf(" Was ");
        print_int(a, style);
        add_msg(msg);
        fail_and_bail();
    }
}

void UnityAssertEqualUintNumber(uint64_t e, uint64_t a, const char *msg, int line, int style)
{
    UnityAssertEqualIntNumber((int64_t)e, (int64_t)a, msg, line, style);
}

static void print_compare(int compare)
{
    if (compare & UNITY_GREATER_THAN)
        printf(" to be greater than ");
    if (compare & UNITY_SMALLER_THAN)
        printf(" to be less than ");
    if (compare & UNITY_EQUAL_TO)
        printf("or equal to ");
}

static int compare_fails(int equal, int greater, int smaller, int compare)
{
    return (equal && !(compare & UNITY_EQUAL_TO)) ||
           (greater && (compare & UNITY_SMALLER_THAN)) ||
           (smaller && (compare & UNITY_GREATER_THAN));
}

void UnityAssertIntCompare(int64_t t, int64_t a, int compare, const char *msg, int line)
{
    return_if_fail_or_ignore();
    if (compare_fails(t == a, a > t, a < t, compare)) {
        fail_begin(line);
        printf(" Expected %lld", (long long)a);
        print_compare(compare);
        printf("%lld", (long long)t);
        add_msg(msg);
        fail_and_bail();
    }
}

void UnityAssertUintCompare(uint64_t t, uint64_t a, int compare, const char *msg, int line)
{
    return_if_fail_or_ignore();
    if (compare_fails(t == a, a > t, a < t, compare)) {
        fail_begin(line);
        printf(" Expected %llu", (unsigned long long)a);
        print_compare(compare);
        printf("%llu", (unsigned long long)t);
        add_msg(msg);
        fail_and_bail();
    }
}

/* UNITY_FLOAT_OR_DOUBLE_WITHIN: NaN equals NaN, infinities of one sign match. */
static int doubles_within(double delta, double e, double a)
{
    double diff;

    if (isinf(e) && isinf(a) && ((e < 0) == (a < 0)))
        return 1;
    if (isnan(e) && isnan(a))
        return 1;
    diff = fabs(a - e);
    delta = fabs(delta);
    return !(isnan(diff) || isinf(diff) || diff > delta);
}

static void fail_expected_was(double e, double a, const char *msg, int line)
{
    fail_begin(line);
    printf(" Expected ");
    print_float(e);
    printf(" Was ");
    print_float(a);
    add_msg(msg);
    fail_and_bail();
}

void UnityAssertDoublesWithin(double d, double e, double a, const char *msg, int line)
{
    return_if_fail_or_ignore();
    if (!doubles_within(d, e, a))
        fail_expected_was(e, a, msg, line);
}

void UnityAssertFloatsWithin(float d, float e, float a, const char *msg, int line)
{
    float diff;

    return_if_fail_or_ignore();
    if (isinf(e) && isinf(a) && ((e < 0) == (a < 0)))
        return;
    if (isnan(e) && isnan(a))
        return;
    diff = a - e;
    if (diff < 0)
        diff = -diff;
    if (d < 0)
        d = -d;
    if (isnan(diff) || isinf(diff) || diff > d)
        fail_expected_was((double)e, (double)a, msg, line);
}

void UnityAssertDoubleCompare(double t, double a, int compare, const char *msg, int line)
{
    int failed = 0;

    return_if_fail_or_ignore();
    /* "not success" rather than failure, so NaN fails */
    if (!(a < t) && (compare & UNITY_SMALLER_THAN))
        failed = 1;
    if (!(a > t) && (compare & UNITY_GREATER_THAN))
        failed = 1;
    if ((compare & UNITY_EQUAL_TO) && doubles_within(t * 1e-12, t, a))
        failed = 0;
    if (failed) {
        fail_begin(line);
        printf(" Expected ");
        print_float(a);
        print_compare(compare);
        print_float(t);
        add_msg(msg);
        fail_and_bail();
    }
}

static void print_char(char c)
{
    char s[2] = {c, '\0'};

    putchar('\'');
    print(s);
    putchar('\'');
}

static void print_quoted(const char *s)
{
    if (s == NULL) {
        printf("NULL");
        return;
    }
    putchar('\'');
    print(s);
    putchar('\'');
}

void UnityAssertEqualString(const char *e, const char *a, const char *msg, int line)
{
    uint32_t i = 0;
    int differ = 0;

    return_if_fail_or_ignore();
    if (e != NULL && a != NULL) {
        for (i = 0; e[i] || a[i]; i++)
            if (e[i] != a[i]) {
                differ = 1;
                break;
            }
    } else {
        differ = e != a;
    }
    if (differ) {
        fail_begin(line);
        printf(" Expected ");
        print_quoted(e);
        printf(" Was ");
        print_quoted(a);
        if (e != NULL && a != NULL) {
            printf(" Character %lu Expected ", (unsigned long)i);
            print_char(e[i]);
            printf(" Was ");
            print_char(a[i]);
        }
        add_msg(msg);
        fail_and_bail();
    }
}

static void pointless(const char *msg, int line)
{
    fail_begin(line);
    printf(" You Asked Me To Compare Nothing, Which Was Pointless.");
    add_msg(msg);
    fail_and_bail();
}

/* Both NULL or the same pointer pass; one NULL fails. */
static int same_or_one_null(const void *e, const void *a, const char *msg, int line)
{
    if (e == a)
        return 1;
    if (e == NULL || a == NULL) {
        fail_begin(line);
        printf(e == NULL ? " Expected pointer to be NULL" : " Actual pointer was NULL");
        add_msg(msg);
        fail_and_bail();
    }
    return 0;
}

void UnityAssertEqualMemory(const void *e, const void *a, uint32_t n, const char *msg, int line)
{
    const unsigned char *pe = e, *pa = a;
    uint32_t i;

    return_if_fail_or_ignore();
    if (n == 0)
        pointless(msg, line);
    if (same_or_one_null(e, a, msg, line))
        return;
    for (i = 0; i < n; i++)
        if (pe[i] != pa[i]) {
            fail_begin(line);
            printf(" Memory Mismatch. Byte %lu Expected ", (unsigned long)i);
            print_hex(pe[i], 2);
            printf(" Was ");
            print_hex(pa[i], 2);
            add_msg(msg);
            fail_and_bail();
        }
}

static int64_t element(const unsigned char *p, int bytes, int style)
{
    int64_t v = 0;

    if (bytes == 1)
        v = *(const int8_t *)p;
    else if (bytes == 2)
        v = *(const int16_t *)(const void *)p;
    else if (bytes == 4)
        v = *(const int32_t *)(const void *)p;
    else
        v = *(const int64_t *)(const void *)p;
    return (style & UNITY_RANGE_INT) ? v : narrow(v, (style & 15) | UNITY_RANGE_UINT);
}

void UnityAssertEqualIntArray(const void *e, const void *a, uint32_t n, const char *msg,
                              int line, int style)
{
    const unsigned char *pe = e, *pa = a;
    int bytes = style & 15;
    uint32_t i;

    return_if_fail_or_ignore();
    if (n == 0)
        pointless(msg, line);
    if (same_or_one_null(e, a, msg, line))
        return;
    for (i = 0; i < n; i++, pe += bytes, pa += bytes) {
        int64_t ev = element(pe, bytes, style), av = element(pa, bytes, style);
        if (ev != av) {
            fail_begin(line);
            printf(" Element %lu Expected ", (unsigned long)i);
            print_int(ev, style);
            printf(" Was ");
            print_int(av, style);
            add_msg(msg);
            fail_and_bail();
        }
    }
}
