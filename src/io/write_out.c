/* The buffered writer and number formatting shared by every encoder. */
#include <math.h>
#include <string.h>

#include "io_internal.h"

void qc__out_init(qc__out *o, qc_ctx *ctx, qc_write_fn write, void *ud)
{
    o->ctx = ctx;
    o->write = write;
    o->ud = ud;
    o->status = QC_OK;
    o->n = 0;
    o->total = 0;
    o->lo.x = o->lo.y = 0;
}

void qc__out_flush(qc__out *o)
{
    if (o->status == QC_OK && o->n > 0 && o->write(o->ud, o->buf, o->n) != 0)
        o->status = qc__fail(o->ctx, QC_EIO,
                             "write callback failed after %llu bytes",
                             (unsigned long long)o->total);
    if (o->status == QC_OK)
        o->total += o->n;
    o->n = 0;
}

void qc__out_bytes(qc__out *o, const void *data, size_t len)
{
    const char *p = (const char *)data;

    while (len > 0 && o->status == QC_OK) {
        size_t k = QC__OUT_BUF - o->n;

        if (k == 0) {
            qc__out_flush(o);
            continue;
        }
        if (k > len)
            k = len;
        memcpy(o->buf + o->n, p, k);
        o->n += k;
        p += k;
        len -= k;
    }
}

void qc__out_str(qc__out *o, const char *s)
{
    qc__out_bytes(o, s, strlen(s));
}

void qc__out_char(qc__out *o, char c)
{
    if (o->n == QC__OUT_BUF)
        qc__out_flush(o);
    if (o->status == QC_OK)
        o->buf[o->n++] = c;
}

/* "00" to "99": digits() writes two digits per division, the writers'
 * hot loop (28 million points make 56 million coordinates at 10^6) */
const char qc__two_digits[201] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

/* Digits of v (>= 0) right-aligned in end[-k..0); at least min_digits. */
static char *digits(char *end, uint64_t v, int min_digits)
{
    char *pad = end - min_digits;

    while (v >= 100) {
        unsigned r = (unsigned)(v % 100);

        v /= 100;
        end -= 2;
        memcpy(end, qc__two_digits + 2 * r, 2);
    }
    if (v >= 10) {
        end -= 2;
        memcpy(end, qc__two_digits + 2 * v, 2);
    } else {
        *--end = (char)('0' + v);
    }
    while (end > pad)
        *--end = '0';
    return end;
}

char *qc__fmt_int(char *end, int64_t v)
{
    uint64_t u = v < 0 ? (uint64_t)0 - (uint64_t)v : (uint64_t)v;
    char *s = digits(end, u, 1);

    if (v < 0)
        *--s = '-';
    return s;
}

void qc__out_int(qc__out *o, int64_t v)
{
    char tmp[24], *end = tmp + sizeof tmp, *s = qc__fmt_int(end, v);

    qc__out_bytes(o, s, (size_t)(end - s));
}

#define D10(a, l) a "0" l a "1" l a "2" l a "3" l a "4" l \
                 a "5" l a "6" l a "7" l a "8" l a "9" l
#define D100(a) D10(a "0", "\3") D10(a "1", "\3") D10(a "2", "\3") D10(a "3", "\3") \
                D10(a "4", "\3") D10(a "5", "\3") D10(a "6", "\3") D10(a "7", "\3") \
                D10(a "8", "\3") D10(a "9", "\3")
const char qc__three_digits[4001] = D10("00", "\1") D10("01", "\2") D10("02", "\2")
    D10("03", "\2") D10("04", "\2") D10("05", "\2") D10("06", "\2") D10("07", "\2")
    D10("08", "\2") D10("09", "\2") D100("1") D100("2") D100("3") D100("4") D100("5")
    D100("6") D100("7") D100("8") D100("9");
#undef D100
#undef D100
#undef D10

char *qc__put_thousandths_long(char *s, uint64_t v)
{
    uint64_t ip = v / 1000;
    unsigned fp = (unsigned)(v - ip * 1000);
    char tmp[24], *end = tmp + sizeof tmp, *b = digits(end, ip, 1);

    memcpy(s, b, (size_t)(end - b));
    s += end - b;
    *s++ = '.';
    *s++ = (char)('0' + fp / 100);
    memcpy(s, qc__two_digits + 2 * (fp % 100), 2);
    return s + 2;
}

char *qc__fmt_fixed(char *end, int64_t v, int decimals, int trim)
{
    static const uint64_t pow10[10] = {1, 10, 100, 1000, 10000, 100000,
                                       1000000, 10000000, 100000000,
                                       1000000000};
    uint64_t u = v < 0 ? (uint64_t)0 - (uint64_t)v : (uint64_t)v;
    uint64_t ip = u / pow10[decimals], fp = u % pow10[decimals];
    char *s = end, *last = end;

    if (decimals > 0) {
        s = digits(end, fp, decimals);
        if (trim) { /* the text ends earlier: move it up to end */
            while (last > s && last[-1] == '0')
                last--;
            memmove(s + (end - last), s, (size_t)(last - s));
            s += end - last;
        }
        if (s < end)
            *--s = '.';
    }
    s = digits(s, ip, 1);
    if (v < 0 && !(trim && u == 0))
        *--s = '-';
    return s;
}

void qc__out_fixed(qc__out *o, int64_t v, int decimals, int trim)
{
    char tmp[40], *end = tmp + sizeof tmp, *s = qc__fmt_fixed(end, v, decimals, trim);

    qc__out_bytes(o, s, (size_t)(end - s));
}

int qc__out_finish(qc__out *o)
{
    qc__out_flush(o);
    return o->status;
}
