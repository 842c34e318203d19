/*
 * Strict .pat reader: "N<k>G00X<i>.<ddd>Y<i>.<ddd>" or G01, k = line number
 * from 1, exactly 3 decimals, then "N<k>M02" and nothing after it. Lines end
 * in CRLF or LF (either, per line). G00 marks a jump (piece start).
 */
#include <string.h>

#include "io_internal.h"

#define PAT_MAX_INT_DIGITS 6 /* up to 999999.999 in */

typedef struct cursor {
    const char *s, *end;
} cursor;

static int lit(cursor *c, const char *w)
{
    size_t n = strlen(w);

    if ((size_t)(c->end - c->s) < n || memcmp(c->s, w, n) != 0)
        return 0;
    c->s += n;
    return 1;
}

/* Unsigned decimal integer of 1..maxd digits. */
static int uint_digits(cursor *c, int maxd, int64_t *v)
{
    int k = 0;

    *v = 0;
    while (c->s < c->end && *c->s >= '0' && *c->s <= '9') {
        if (++k > maxd)
            return 0;
        *v = *v * 10 + (*c->s++ - '0');
    }
    return k > 0;
}

/* [-]<digits>.<3 digits> as thousandths. */
static int coord(cursor *c, int64_t *v)
{
    int64_t ip, fp;
    int neg = lit(c, "-");
    const char *f;

    if (!uint_digits(c, PAT_MAX_INT_DIGITS, &ip) || !lit(c, "."))
        return 0;
    f = c->s;
    if (!uint_digits(c, 3, &fp) || c->s - f != 3)
        return 0;
    *v = (ip * 1000 + fp) * (neg ? -1 : 1);
    return 1;
}

/* Consumes the line terminator (CRLF or LF), or accepts the end of input
 * when last_ok. */
static int eol(cursor *c, int last_ok)
{
    if (lit(c, "\r\n") || lit(c, "\n"))
        return 1;
    return last_ok && c->s == c->end;
}

int qc_io_read_pat(qc_ctx *ctx, const char *buf, size_t len, qc_plan *out)
{
    cursor c;
    int64_t line = 1, k, x, y;
    int rc = QC_OK, ended = 0;

    memset(out, 0, sizeof *out);
    if (buf == NULL && len > 0)
        return qc__fail(ctx, QC_EINVAL, "pat: NULL buffer of %lu bytes",
                        (unsigned long)len);
    c.s = buf;
    c.end = buf + len;
    while (c.s < c.end && rc == QC_OK) {
        int jump;

        if (!lit(&c, "N") || !uint_digits(&c, 12, &k)) {
            rc = qc__fail(ctx, QC_EFORMAT, "pat line %lld: expected N%lld",
                          (long long)line, (long long)line);
            break;
        }
        if (k != line) {
            rc = qc__fail(ctx, QC_EFORMAT, "pat line %lld: numbered N%lld, expected N%lld",
                          (long long)line, (long long)k, (long long)line);
            break;
        }
        if (lit(&c, "M02")) {
            if (!eol(&c, 1) || c.s != c.end) {
                rc = qc__fail(ctx, QC_EFORMAT,
                              "pat line %lld: nothing may follow M02", (long long)line);
                break;
            }
            ended = 1;
            break;
        }
        if (lit(&c, "G00"))
            jump = 1;
        else if (lit(&c, "G01"))
            jump = 0;
        else {
            rc = qc__fail(ctx, QC_EFORMAT, "pat line %lld: expected G00, G01 or M02",
                          (long long)line);
            break;
        }
        if (!lit(&c, "X") || !coord(&c, &x) || !lit(&c, "Y") || !coord(&c, &y) ||
            !eol(&c, 0)) {
            rc = qc__fail(ctx, QC_EFORMAT,
                          "pat line %lld: expected X<in>.<3 digits>Y<in>.<3 digits> and a line end",
                          (long long)line);
            break;
        }
        {
            qc_vec2 p;

            p.x = (double)x / 1000 * QC__MM_PER_IN;
            p.y = (double)y / 1000 * QC__MM_PER_IN;
            rc = qc_plan_push(ctx, out, p, jump || out->n == 0 ? QC_ST_JUMP : 0);
        }
        line++;
    }
    if (rc == QC_OK && !ended)
        rc = qc__fail(ctx, QC_EFORMAT, "pat line %lld: missing N%lldM02 at the end",
                      (long long)line, (long long)line);
    if (rc == QC_OK && out->n == 0)
        rc = qc__fail(ctx, QC_EEMPTY, "pat: no point before M02");
    if (rc != QC_OK)
        qc_plan_free(ctx, out);
    return rc;
}
