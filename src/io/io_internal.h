/*
 * Internals of io/: a buffered writer over qc_write_fn with hand-written
 * integer and fixed-point formatting (no printf: fast and the same bytes on
 * every platform), rounding to machine units, and the per-format encoders.
 */
#ifndef QC_IO_INTERNAL_H
#define QC_IO_INTERNAL_H

#include <string.h>

#include "internal.h"

#define QC__OUT_BUF 8192

typedef struct qc__out {
    qc_ctx *ctx;
    qc_write_fn write;
    void *ud;
    int status;       /* first failure; later calls do nothing */
    size_t n;         /* bytes pending in buf */
    uint64_t total;   /* bytes accepted so far */
    qc_vec2 lo;       /* the plan's least x and least y (set by qc_io_write) */
    char buf[QC__OUT_BUF];
} qc__out;

QC__HIDDEN void qc__out_init(qc__out *o, qc_ctx *ctx, qc_write_fn write, void *ud);
QC__HIDDEN void qc__out_bytes(qc__out *o, const void *data, size_t len);
QC__HIDDEN void qc__out_str(qc__out *o, const char *s);
QC__HIDDEN void qc__out_char(qc__out *o, char c);
/* Decimal integer, '-' when negative. */
QC__HIDDEN void qc__out_int(qc__out *o, int64_t v);
/* v / 10^decimals with exactly decimals digits after the point ("-1.250",
 * "0.005"); decimals 0..9. trim != 0 drops trailing zeros and a bare point
 * ("-1.25", "3"), and "-0" becomes "0". */
QC__HIDDEN void qc__out_fixed(qc__out *o, int64_t v, int decimals, int trim);
/* The same texts written backwards into a caller's buffer ending at end
 * (24 and 40 bytes suffice), returning where they start: an encoder can
 * make a whole line and write it at once. */
QC__HIDDEN char *qc__fmt_int(char *end, int64_t v);
QC__HIDDEN char *qc__fmt_fixed(char *end, int64_t v, int decimals, int trim);
/* "00" to "99", two characters each: the formatting's digit pairs. */
QC__HIDDEN extern const char qc__two_digits[201];
/* "000" to "999", four characters each: the number's three digits, then
 * how many of them it has without leading zeros (1 to 3, as a byte). */
QC__HIDDEN extern const char qc__three_digits[4001];
/* qc__put_thousandths past 999.999 (write_out.c). */
QC__HIDDEN char *qc__put_thousandths_long(char *s, uint64_t v);

/* v / 1000 (v >= 0) as qc__fmt_fixed(end, v, 3, 0) writes it, but forwards
 * from s, returning the end (at most 24 bytes; the 8 bytes from s may be
 * written past it, the caller's next bytes go over them): the .pat
 * writer's two numbers per line, made in place in the buffer. Inline, by
 * digit triples copied 4 bytes at a time, no division but the one by 1000
 * below 1000 (39 in at 1000 per inch: every pattern a machine holds). */
static inline char *qc__put_thousandths(char *s, uint64_t v)
{
    uint32_t u, ip, fp, len;

    if (v >= 1000000)
        return qc__put_thousandths_long(s, v);
    u = (uint32_t)v;
    ip = u / 1000;
    fp = u - ip * 1000;
    len = (uint32_t)qc__three_digits[4 * ip + 3];
    /* ip's len digits at s, what follows them in the table after (written
     * over by the point and the fraction) */
    memcpy(s, qc__three_digits + 4 * ip + 3 - len, 4);
    s += len;
    s[0] = '.';
    memcpy(s + 1, qc__three_digits + 4 * fp, 4);
    return s + 4;
}

/* Hands the buffered bytes to the callback (the first failure is kept). */
QC__HIDDEN void qc__out_flush(qc__out *o);
/* Room for len (<= QC__OUT_BUF) bytes at the end of o's buffer, flushed to
 * make it if need be: an encoder writes there, then adds what it wrote to
 * o->n. (After a failure the buffer only takes what is thrown away.)
 * Inline: the writers take room once per line. */
static inline char *qc__out_room(qc__out *o, size_t len)
{
    if (QC__OUT_BUF - o->n < len)
        qc__out_flush(o);
    return o->buf + o->n;
}
/* Flushes; returns QC_OK or the first failure (QC_EIO from the callback). */
QC__HIDDEN int qc__out_finish(qc__out *o);

/* Rounds half away from zero: floor(x + 0.5) for x >= 0, mirrored below.
 * The conversion truncates, which is floor for x + 0.5 >= 0: the same
 * values as floor() without a libm call per coordinate. Inline, as the
 * conversions below: the writers' loops take two per point. */
static inline int64_t qc__round(double x)
{
    return x >= 0 ? (int64_t)(x + 0.5) : -(int64_t)(-x + 0.5);
}

/* The unit conversions every encoder shares, rounding each absolute
 * coordinate on its own (no accumulated error). */
#define QC__MM_PER_IN 25.4
static inline int64_t qc__mm_to_units(double mm, double units_per_mm)
{
    return qc__round(mm * units_per_mm);
}

static inline int64_t qc__mm_to_inch_units(double mm, double units_per_inch)
{
    return qc__round(mm / QC__MM_PER_IN * units_per_inch);
}

/* Encoders, one per file: plan already checked (n > 0, coordinates finite,
 * within 1e6 mm). Each returns QC_OK or a format-specific error; the bytes
 * go to o, whose failure qc_io_write reports. */
QC__HIDDEN int qc__write_pat(qc_ctx *ctx, const qc_plan *plan, const qc_io_opts *opts, qc__out *o);
QC__HIDDEN int qc__write_qli(qc_ctx *ctx, const qc_plan *plan, const qc_io_opts *opts, qc__out *o);
QC__HIDDEN int qc__write_dxf(qc_ctx *ctx, const qc_plan *plan, const qc_io_opts *opts, qc__out *o);
QC__HIDDEN int qc__write_hpgl(qc_ctx *ctx, const qc_plan *plan, const qc_io_opts *opts, qc__out *o);
QC__HIDDEN int qc__write_qcc(qc_ctx *ctx, const qc_plan *plan, const qc_io_opts *opts, qc__out *o);
QC__HIDDEN int qc__write_iqp(qc_ctx *ctx, const qc_plan *plan, const qc_io_opts *opts, qc__out *o);
QC__HIDDEN int qc__write_bqm(qc_ctx *ctx, const qc_plan *plan, const qc_io_opts *opts, qc__out *o);
QC__HIDDEN int qc__write_gcode(qc_ctx *ctx, const qc_plan *plan, const qc_io_opts *opts, qc__out *o);
QC__HIDDEN int qc__write_svg(qc_ctx *ctx, const qc_plan *plan, const qc_io_opts *opts, qc__out *o);

#endif
