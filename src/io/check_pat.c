/*
 * Lenient .pat linter for `quiltc check`: reads what it can, reports every
 * deviation from the AutoPilot dialect (see read_pat.c for the strict form)
 * through a callback, and collects the coordinates into a plan so the
 * caller can check the geometry too.
 */
#include <stdarg.h>
#include <stdio.h>
#include <math.h>
#include <string.h>

#include "io_internal.h"

typedef struct linter {
    qc_ctx *ctx;
    qc_finding_fn report;
    void *ud;
    size_t findings;
} linter;

static void finding(linter *l, size_t line, const char *kind, const char *fmt, ...)
    QC__PRINTF(4, 5);

static void finding(linter *l, size_t line, const char *kind, const char *fmt, ...)
{
    char text[160];
    va_list ap;

    va_start(ap, fmt);
    vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    l->findings++;
    if (l->report != NULL)
        l->report(l->ud, line, kind, text);
}

/* A printable excerpt of a line for messages. */
static void excerpt(const char *s, size_t n, char *out, size_t cap)
{
    size_t i, k = 0;

    for (i = 0; i < n && k + 4 < cap; i++)
        out[k++] = s[i] >= 32 && s[i] < 127 ? s[i] : '?';
    if (i < n)
        out[k++] = '.', out[k++] = '.', out[k++] = '.';
    out[k] = '\0';
}

/* A number [-]digits[.digits]: value in thousandths-exact double, decimals
 * counted; *form gets NUM_PLUS for a '+' sign and NUM_LONG for more integer
 * digits than the strict reader takes (read_pat.c), so either is a finding. */
#define NUM_PLUS 1
#define NUM_LONG 2
#define PAT_INT_DIGITS 6
#define PAT_MAX_MM 1e6 /* the writers' and the library's coordinate limit */
static const char *number(const char *s, const char *end, double *v, int *decimals, int *form)
{
    const char *p = s;
    double ip = 0.0, frac = 0.0, scale = 1.0;
    int neg = 0, digits = 0;

    *decimals = -1;
    if (p < end && *p == '+')
        *form |= NUM_PLUS;
    if (p < end && (*p == '-' || *p == '+'))
        neg = *p++ == '-';
    while (p < end && *p >= '0' && *p <= '9' && digits < 12) {
        ip = ip * 10.0 + (*p++ - '0');
        digits++;
    }
    if (p < end && *p == '.') {
        p++;
        *decimals = 0;
        while (p < end && *p >= '0' && *p <= '9' && *decimals < 12) {
            scale /= 10.0;
            frac += (*p++ - '0') * scale;
            (*decimals)++;
        }
    } else {
        *decimals = 0;
    }
    if (digits == 0 && *decimals <= 0)
        return NULL;
    if (digits > PAT_INT_DIGITS)
        *form |= NUM_LONG;
    *v = (ip + frac) * (neg ? -1.0 : 1.0);
    return p;
}

static int lint_line(linter *l, size_t line, const char *s, const char *end,
                     int64_t *expect_n, int *ended, qc_plan *out)
{
    char ex[48];
    const char *p = s;
    int64_t n = 0;
    int digits = 0;

    excerpt(s, (size_t)(end - s), ex, sizeof ex);
    if (*ended) {
        finding(l, line, "dialect", "content after M02: '%s'", ex);
        return QC_OK;
    }
    if (p == end || *p != 'N') {
        finding(l, line, "dialect", "malformed line '%s' (expected N<k>G01X...Y...)", ex);
        return QC_OK;
    }
    for (p++; p < end && *p >= '0' && *p <= '9' && digits < 12; p++, digits++)
        n = n * 10 + (*p - '0');
    if (digits == 0) {
        finding(l, line, "dialect", "malformed line '%s' (no line number)", ex);
        return QC_OK;
    }
    if (n != *expect_n)
        finding(l, line, "numbering", "N%lld where N%lld was expected", (long long)n,
                (long long)*expect_n);
    *expect_n = n + 1;
    if (end - p == 3 && memcmp(p, "M02", 3) == 0) {
        *ended = 1;
        return QC_OK;
    }
    if (end - p >= 3 && (memcmp(p, "G00", 3) == 0 || memcmp(p, "G01", 3) == 0)) {
        int jump = p[2] == '0', dx, dy, form = 0;
        double x, y;
        const char *q = p + 3;

        if (q < end && *q == 'X' && (q = number(q + 1, end, &x, &dx, &form)) != NULL && q < end &&
            *q == 'Y' && (q = number(q + 1, end, &y, &dy, &form)) != NULL && q == end) {
            qc_vec2 v;

            if (dx != 3 || dy != 3)
                finding(l, line, "decimals", "X has %d and Y %d decimals, expected 3", dx, dy);
            if (form & NUM_PLUS)
                finding(l, line, "dialect", "a '+' sign in '%s' (readers take only '-')", ex);
            if (form & NUM_LONG)
                finding(l, line, "dialect", "more than %d integer digits in '%s'", PAT_INT_DIGITS,
                        ex);
            v.x = x * 25.4;
            v.y = y * 25.4;
            if (!(fabs(v.x) <= PAT_MAX_MM && fabs(v.y) <= PAT_MAX_MM)) {
                finding(l, line, "range", "(%g, %g) in is beyond 1e6 mm (39370 in) of the origin",
                        x, y);
                v.x = fmax(-PAT_MAX_MM, fmin(PAT_MAX_MM, v.x)); /* kept finite for the measures */
                v.y = fmax(-PAT_MAX_MM, fmin(PAT_MAX_MM, v.y));
            }
            return qc_plan_push(l->ctx, out, v, jump || out->n == 0 ? QC_ST_JUMP : 0);
        }
        finding(l, line, "dialect", "malformed move '%s'", ex);
        return QC_OK;
    }
    finding(l, line, "dialect", "unknown command '%.*s'", (int)(end - p > 8 ? 8 : end - p), p);
    return QC_OK;
}

int qc_io_check_pat(qc_ctx *ctx, const char *buf, size_t len, qc_finding_fn report,
                    void *ud, qc_plan *out, size_t *findings)
{
    linter l;
    const char *s = buf, *end = buf + len;
    int64_t expect_n = 1;
    size_t line = 0, lf_lines = 0, first_lf = 0;
    int ended = 0, rc = QC_OK;

    memset(out, 0, sizeof *out);
    l.ctx = ctx;
    l.report = report;
    l.ud = ud;
    l.findings = 0;
    while (s < end && rc == QC_OK) {
        const char *nl = memchr(s, '\n', (size_t)(end - s));
        const char *e = nl != NULL ? nl : end;

        line++;
        if (e > s && e[-1] == '\r')
            e--;
        else if (nl != NULL && lf_lines++ == 0)
            first_lf = line;
        if (e > s || nl != NULL)
            rc = e > s ? lint_line(&l, line, s, e, &expect_n, &ended, out) : QC_OK;
        if (e == s && nl != NULL && !ended)
            finding(&l, line, "dialect", "empty line");
        s = nl != NULL ? nl + 1 : end;
    }
    if (rc == QC_OK && lf_lines > 0)
        finding(&l, first_lf, "line-ending", "%lu lines end in LF only, expected CRLF",
                (unsigned long)lf_lines);
    if (rc == QC_OK && !ended)
        finding(&l, line, "dialect", "missing the final M02 line");
    if (rc < 0)
        qc_plan_free(ctx, out);
    *findings = l.findings;
    return rc;
}
