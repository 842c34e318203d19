/* The harness behind tests/unity/unity.h; prints Unity's lines and summary. */
#include "unity.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

static struct {
    const char *file;
    const char *test;
    int tests, failures, ignored;
    int failed, skipped;
    jmp_buf jump;
} U;

void UnityBegin(const char *file)
{
    memset(&U, 0, sizeof U);
    U.file = file;
}

static void report(const char *kind, const char *msg, int line)
{
    printf("%s:%d:%s:%s", U.file, line, U.test ? U.test : "?", kind);
    if (msg != NULL)
        printf(": %s", msg);
    printf("\n");
}

void UnityFail(const char *msg, int line)
{
    report("FAIL", msg, line);
    U.failed = 1;
    longjmp(U.jump, 1);
}

void UnityIgnore(const char *msg, int line)
{
    report("IGNORE", msg, line);
    U.skipped = 1;
    longjmp(U.jump, 1);
}

void UnityDefaultTestRun(void (*func)(void), const char *name, int line)
{
    U.test = name;
    U.failed = U.skipped = 0;
    U.tests++;
    if (setjmp(U.jump) == 0) {
        setUp();
        func();
    }
    if (setjmp(U.jump) == 0)
        tearDown();
    if (U.failed)
        U.failures++;
    else if (U.skipped)
        U.ignored++;
    else
        printf("%s:%d:%s:PASS\n", U.file, line, name);
    fflush(stdout);
}

int UnityEnd(void)
{
    printf("\n-----------------------\n%d Tests %d Failures %d Ignored\n%s\n",
           U.tests, U.failures, U.ignored, U.failures ? "FAIL" : "OK");
    fflush(stdout);
    return U.failures;
}

static void failf(const char *user, int line, const char *fmt, ...)
{
    char buf[512];
    va_list ap;
    size_t k;

    va_start(ap, fmt);
    vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    k = strlen(buf);
    if (user != NULL && k < sizeof buf - 4)
        snprintf(buf + k, sizeof buf - k, ". %s", user);
    UnityFail(buf, line);
}

void UnityAssertInt(int64_t e, int64_t a, const char *msg, int line)
{
    if (e != a)
        failf(msg, line, "Expected %lld Was %lld", (long long)e, (long long)a);
}

void UnityAssertUint(uint64_t e, uint64_t a, const char *msg, int line)
{
    if (e != a)
        failf(msg, line, "Expected %llu Was %llu", (unsigned long long)e,
              (unsigned long long)a);
}

void UnityAssertCmp(double t, double a, int op, const char *msg, int line)
{
    static const char *const what[] = {"greater than", "greater or equal to",
                                       "less than", "less or equal to"};
    int ok = op == 0 ? a > t : op == 1 ? a >= t : op == 2 ? a < t : a <= t;

    if (!ok)
        failf(msg, line, "Expected %s %.17g Was %.17g", what[op], t, a);
}

void UnityAssertDoubleWithin(double d, double e, double a, const char *msg, int line)
{
    if (isnan(e) && isnan(a))
        return;
    if (!(fabs(e - a) <= d) && !(e == a))
        failf(msg, line, "Expected %.17g Was %.17g (within %g)", e, a, d);
}

void UnityAssertString(const char *e, const char *a, const char *msg, int line)
{
    if (e == NULL || a == NULL) {
        if (e != a)
            failf(msg, line, "Expected '%s' Was '%s'", e ? e : "(null)", a ? a : "(null)");
        return;
    }
    if (strcmp(e, a) != 0)
        failf(msg, line, "Expected '%s' Was '%s'", e, a);
}

void UnityAssertMemory(const void *e, const void *a, size_t n, const char *msg, int line)
{
    size_t i;
    const unsigned char *pe = e, *pa = a;

    for (i = 0; i < n; i++)
        if (pe[i] != pa[i])
            failf(msg, line, "Memory Mismatch at byte %lu: expected 0x%02x was 0x%02x",
                  (unsigned long)i, pe[i], pa[i]);
}
