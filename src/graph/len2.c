/*
 * Exact comparison of squared lengths, the MST's edge order: a float
 * filter, then integers. Every finite double is an integer times a power of
 * two, so the coordinates of two edges, scaled by their lowest exponent,
 * are integers and the squared lengths integers too: in 128 bits when the
 * exponents lie within QC__INT_SPAN of each other (the points of one
 * pattern), else in a big integer wide enough for any doubles (2^-1074 next
 * to 2^1023). No rounding, no underflow, no overflow anywhere.
 */
#include <limits.h>
#include <string.h>

#include "graph_internal.h"

#define EPS 0x1p-53 /* half an ulp of 1 */
/* Bits of a difference of two doubles scaled by 2^-1074: 2^1024 / 2^-1074,
 * plus a sign's carry; its square twice that, plus one for the sum. */
#define BIG_WORDS 133 /* 32-bit words: 4256 bits */

/* x = +-m 2^e, m an integer below 2^53 (0 for zero), subnormals included;
 * 0 for infinities and NaN. */
typedef struct ifloat {
    uint64_t m;
    int e, neg;
} ifloat;

static int ifloat_of(double x, ifloat *f)
{
    uint64_t u;
    int be;

    memcpy(&u, &x, sizeof u);
    be = (int)(u >> 52 & 0x7ff);
    f->m = (u & 0xfffffffffffffULL) | (be != 0 ? (uint64_t)1 << 52 : 0);
    f->e = (be != 0 ? be : 1) - 1075;
    f->neg = (int)(u >> 63);
    return be != 0x7ff;
}

/* Lowest and highest exponent of the nonzero values of f[0..n). */
static void span_of(const ifloat *f, size_t n, int *lo, int *hi)
{
    size_t i;

    *lo = INT_MAX;
    *hi = INT_MIN;
    for (i = 0; i < n; i++)
        if (f[i].m != 0) {
            *lo = f[i].e < *lo ? f[i].e : *lo;
            *hi = f[i].e > *hi ? f[i].e : *hi;
        }
}

/* ---- 128 bits: exponents within QC__INT_SPAN ---- */

/* f as an integer times 2^e (e at most f's exponent, within the span). */
static int64_t ifloat_at(const ifloat *f, int e)
{
    int64_t m = f->m == 0 ? 0 : (int64_t)(f->m << (f->e - e));

    return f->neg ? -m : m;
}

/* a * b as hi * 2^64 + lo. */
static void mul_64(uint64_t a, uint64_t b, uint64_t *hi, uint64_t *lo)
{
    uint64_t a0 = a & 0xffffffffu, a1 = a >> 32, b0 = b & 0xffffffffu, b1 = b >> 32;
    uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
    uint64_t mid = (p00 >> 32) + (p01 & 0xffffffffu) + (p10 & 0xffffffffu);

    *lo = (mid << 32) | (p00 & 0xffffffffu);
    *hi = p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32);
}

/* dx^2 + dy^2 for integer differences below 2^63 in magnitude. */
static void len2_u128(int64_t dx, int64_t dy, uint64_t *hi, uint64_t *lo)
{
    uint64_t ux = dx < 0 ? (uint64_t)0 - (uint64_t)dx : (uint64_t)dx;
    uint64_t uy = dy < 0 ? (uint64_t)0 - (uint64_t)dy : (uint64_t)dy;
    uint64_t h2, l2;

    mul_64(ux, ux, hi, lo);
    mul_64(uy, uy, &h2, &l2);
    *lo += l2;
    *hi += h2 + (*lo < l2);
}

int qc__int_span_add(double x, int *lo, int *hi)
{
    ifloat f;

    if (!ifloat_of(x, &f))
        return 0;
    if (f.m != 0) {
        *lo = f.e < *lo ? f.e : *lo;
        *hi = f.e > *hi ? f.e : *hi;
    }
    return 1;
}

void qc__len2_int(qc_vec2 a, qc_vec2 b, int e, uint64_t *hi, uint64_t *lo)
{
    ifloat f[4];

    ifloat_of(a.x, &f[0]);
    ifloat_of(a.y, &f[1]);
    ifloat_of(b.x, &f[2]);
    ifloat_of(b.y, &f[3]);
    len2_u128(ifloat_at(&f[0], e) - ifloat_at(&f[2], e), ifloat_at(&f[1], e) - ifloat_at(&f[3], e),
              hi, lo);
}

/* ---- big integers: any exponents ---- */

/* A magnitude in 32-bit words, least significant first. */
typedef struct big {
    uint32_t w[BIG_WORDS];
    size_t n; /* words in use */
} big;

static void big_of(const ifloat *f, int e, big *b)
{
    unsigned s = (unsigned)(f->e - e), k = s / 32, r = s % 32;

    memset(b, 0, sizeof *b);
    if (f->m == 0)
        return;
    /* m < 2^53 shifted by r < 32 bits: three words at k */
    b->w[k] = (uint32_t)(f->m << r);
    b->w[k + 1] = (uint32_t)((f->m << r) >> 32);
    b->w[k + 2] = r ? (uint32_t)(f->m >> (64 - r)) : 0;
    b->n = k + 3;
    while (b->n > 0 && b->w[b->n - 1] == 0)
        b->n--;
}

static int big_cmp(const big *a, const big *b)
{
    size_t i = a->n > b->n ? a->n : b->n;

    while (i-- > 0) {
        uint32_t x = i < a->n ? a->w[i] : 0, y = i < b->n ? b->w[i] : 0;
        if (x != y)
            return x < y ? -1 : 1;
    }
    return 0;
}

/* out = a + b (out may alias a). */
static void big_add(const big *a, const big *b, big *out)
{
    size_t n = a->n > b->n ? a->n : b->n, i;
    uint64_t c = 0;

    for (i = 0; i < n; i++) {
        c += (uint64_t)(i < a->n ? a->w[i] : 0) + (i < b->n ? b->w[i] : 0);
        out->w[i] = (uint32_t)c;
        c >>= 32;
    }
    out->n = n;
    if (c != 0)
        out->w[out->n++] = (uint32_t)c;
}

/* out = a - b for a >= b. */
static void big_sub(const big *a, const big *b, big *out)
{
    size_t i;
    int64_t c = 0;

    for (i = 0; i < a->n; i++) {
        c += (int64_t)a->w[i] - (i < b->n ? b->w[i] : 0);
        out->w[i] = (uint32_t)c;
        c = c < 0 ? -1 : 0;
    }
    out->n = a->n;
    while (out->n > 0 && out->w[out->n - 1] == 0)
        out->n--;
}

/* |x - y| for signed values x, y given as magnitudes and signs. */
static void big_absdiff(const big *x, int xneg, const big *y, int yneg, big *out)
{
    if (xneg != yneg)
        big_add(x, y, out);
    else if (big_cmp(x, y) >= 0)
        big_sub(x, y, out);
    else
        big_sub(y, x, out);
}

/* out = a * a. */
static void big_square(const big *a, big *out)
{
    size_t i, j;

    memset(out, 0, sizeof *out);
    for (i = 0; i < a->n; i++) {
        uint64_t c = 0;
        for (j = 0; j < a->n; j++) {
            c += (uint64_t)a->w[i] * a->w[j] + out->w[i + j];
            out->w[i + j] = (uint32_t)c;
            c >>= 32;
        }
        out->w[i + a->n] = (uint32_t)c;
    }
    out->n = 2 * a->n;
    while (out->n > 0 && out->w[out->n - 1] == 0)
        out->n--;
}

/* |ab|^2 / 2^(2e) as a big integer; f: a.x, a.y, b.x, b.y. */
static void len2_big(const ifloat *f, int e, big *out)
{
    big x, y, d, sq;

    big_of(&f[0], e, &x);
    big_of(&f[2], e, &y);
    big_absdiff(&x, f[0].neg, &y, f[2].neg, &d);
    big_square(&d, out);
    big_of(&f[1], e, &x);
    big_of(&f[3], e, &y);
    big_absdiff(&x, f[1].neg, &y, f[3].neg, &d);
    big_square(&d, &sq);
    big_add(out, &sq, out);
}

/* The comparison in big integers, for f = the 8 coordinates decoded and lo
 * their lowest exponent. */
static int cmp_big(const ifloat *f, int lo)
{
    big l1, l2;

    len2_big(f, lo, &l1);
    len2_big(f + 4, lo, &l2);
    return big_cmp(&l1, &l2);
}

/* The 8 coordinates of ab and cd decoded; their exponents' span in *lo,
 * *hi (hi INT_MIN: all zero). 0 if one is not finite. */
static int decode(qc_vec2 a, qc_vec2 b, qc_vec2 c, qc_vec2 d, ifloat *f, int *lo, int *hi)
{
    const double v[8] = {a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y};
    int i;

    for (i = 0; i < 8; i++)
        if (!ifloat_of(v[i], &f[i]))
            return 0;
    span_of(f, 8, lo, hi);
    return 1;
}

int qc__cmp_len2_big(qc_vec2 a, qc_vec2 b, qc_vec2 c, qc_vec2 d)
{
    ifloat f[8];
    int lo, hi;

    if (!decode(a, b, c, d, f, &lo, &hi) || hi == INT_MIN)
        return 0; /* not finite (callers check points first), or all zero */
    return cmp_big(f, lo);
}

int qc__cmp_len2(qc_vec2 a, qc_vec2 b, qc_vec2 c, qc_vec2 d)
{
    double ax = a.x - b.x, ay = a.y - b.y, cx = c.x - d.x, cy = c.y - d.y;
    double l1 = ax * ax + ay * ay, l2 = cx * cx + cy * cy;
    uint64_t h1, w1, h2, w2;
    ifloat f[8];
    int lo, hi;

    /* each computed value is within 4 ulps of its exact value, unless a
     * square underflowed: a length under 2^-900 goes the exact way */
    if (l1 - l2 > 8.0 * EPS * (l1 + l2) && l1 > 0x1p-900)
        return 1;
    if (l2 - l1 > 8.0 * EPS * (l1 + l2) && l2 > 0x1p-900)
        return -1;
    if (!decode(a, b, c, d, f, &lo, &hi) || hi == INT_MIN)
        return 0;
    if (hi - lo > QC__INT_SPAN)
        return cmp_big(f, lo);
    len2_u128(ifloat_at(&f[0], lo) - ifloat_at(&f[2], lo),
              ifloat_at(&f[1], lo) - ifloat_at(&f[3], lo), &h1, &w1);
    len2_u128(ifloat_at(&f[4], lo) - ifloat_at(&f[6], lo),
              ifloat_at(&f[5], lo) - ifloat_at(&f[7], lo), &h2, &w2);
    return h1 != h2 ? (h1 > h2) - (h1 < h2) : (w1 > w2) - (w1 < w2);
}
