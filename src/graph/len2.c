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
#if defined(__SIZEOF_INT128__)
__extension__ typedef unsigned __int128 qc__u128; /* one multiply where the compiler has it */
#endif

static void mul_64(uint64_t a, uint64_t b, uint64_t *hi, uint64_t *lo)
{
#if defined(__SIZEOF_INT128__)
    qc__u128 r = (qc__u128)a * b;

    *hi = (uint64_t)(r >> 64);
    *lo = (uint64_t)r;
#else
    uint64_t a0 = a & 0xffffffffu, a1 = a >> 32, b0 = b & 0xffffffffu, b1 = b >> 32;
    uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
    uint64_t mid = (p00 >> 32) + (p01 & 0xffffffffu) + (p10 & 0xffffffffu);

    *lo = (mid << 32) | (p00 & 0xffffffffu);
    *hi = p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32);
#endif
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

/* ---- exact keys: 256 bits at a group's scale ---- */

/* A 128-bit magnitude. */
typedef struct u128 {
    uint64_t hi, lo;
} u128;

static u128 u128_shl(uint64_t m, unsigned s) /* m << s, for s < 128 - bitlen(m) */
{
    u128 r;

    r.hi = s == 0 ? 0 : s < 64 ? m >> (64 - s) : m << (s - 64);
    r.lo = s < 64 ? m << s : 0;
    return r;
}

static u128 u128_shl2(u128 x, unsigned s) /* x << s, no bit lost (caller checks) */
{
    if (s >= 64) {
        x.hi = x.lo << (s - 64);
        x.lo = 0;
    } else if (s > 0) {
        x.hi = x.hi << s | x.lo >> (64 - s);
        x.lo <<= s;
    }
    return x;
}

static int u128_less(u128 a, u128 b)
{
    return a.hi != b.hi ? a.hi < b.hi : a.lo < b.lo;
}

static u128 u128_add(u128 a, u128 b)
{
    a.lo += b.lo;
    a.hi += b.hi + (a.lo < b.lo);
    return a;
}

static u128 u128_sub(u128 a, u128 b) /* a >= b */
{
    u128 r;

    r.lo = a.lo - b.lo;
    r.hi = a.hi - b.hi - (a.lo < b.lo);
    return r;
}

static unsigned bitlen64(uint64_t x)
{
#if defined(__GNUC__)
    return x == 0 ? 0 : 64 - (unsigned)__builtin_clzll(x);
#else
    unsigned n = 0;

    if (x >> 32)
        n += 32, x >>= 32;
    if (x >> 16)
        n += 16, x >>= 16;
    if (x >> 8)
        n += 8, x >>= 8;
    if (x >> 4)
        n += 4, x >>= 4;
    if (x >> 2)
        n += 2, x >>= 2;
    if (x >> 1)
        n += 1, x >>= 1;
    return n + (unsigned)x;
#endif
}

static unsigned u128_bitlen(u128 x)
{
    return x.hi != 0 ? 64 + bitlen64(x.hi) : bitlen64(x.lo);
}

/* |x - y| exactly as an integer *d times 2^*e (*e the lower exponent of
 * x and y, *d zero when x == y); 0 if the exponents lie too far apart for
 * 128 bits, or a value is not finite. */
static int diff_int(double x, double y, u128 *d, int *e)
{
    ifloat fx, fy;
    u128 X, Y;

    if (!ifloat_of(x, &fx) || !ifloat_of(y, &fy))
        return 0;
    d->hi = d->lo = 0;
    *e = 0;
    if (fx.m == 0 && fy.m == 0)
        return 1;
    *e = fx.m == 0 ? fy.e : fy.m == 0 ? fx.e : fx.e < fy.e ? fx.e : fy.e;
    if ((fx.m != 0 && fx.e - *e > 74) || (fy.m != 0 && fy.e - *e > 74))
        return 0; /* a 53-bit mantissa shifted past 127 bits */
    X = u128_shl(fx.m, fx.m != 0 ? (unsigned)(fx.e - *e) : 0);
    Y = u128_shl(fy.m, fy.m != 0 ? (unsigned)(fy.e - *e) : 0);
    if (fx.neg != fy.neg)
        *d = u128_add(X, Y);
    else
        *d = u128_less(X, Y) ? u128_sub(Y, X) : u128_sub(X, Y);
    return 1;
}

/* Lowers *e to the exponent of x's last mantissa bit (x nonzero). */
static void scale_of(double x, int *e)
{
    ifloat f;

    if (ifloat_of(x, &f) && f.m != 0 && f.e < *e)
        *e = f.e;
}

void qc__len2_key_scale(qc_vec2 a, qc_vec2 b, int *e)
{
    scale_of(a.x, e);
    scale_of(a.y, e);
    scale_of(b.x, e);
    scale_of(b.y, e);
}

/* x^2 for x < 2^126, as w[0] 2^192 + w[1] 2^128 + w[2] 2^64 + w[3]. */
static void square_256(u128 x, uint64_t w[4])
{
    uint64_t hh, hl, mh, ml, lh, ll, c, carry;

    mul_64(x.hi, x.hi, &hh, &hl);
    mul_64(x.hi, x.lo, &mh, &ml);
    mul_64(x.lo, x.lo, &lh, &ll);
    /* 2 x.hi x.lo < 2^190: doubled without overflow */
    mh = mh << 1 | ml >> 63;
    ml <<= 1;
    w[3] = ll;
    w[2] = lh + ml;
    c = w[2] < ml;
    w[1] = hl + mh;
    carry = w[1] < mh;
    w[1] += c;
    carry += w[1] < c;
    w[0] = hh + carry;
}

int qc__len2_key(qc_vec2 a, qc_vec2 b, int e, uint64_t key[4])
{
    uint64_t sq[4], c = 0;
    u128 d;
    int k, i, de;

    key[0] = key[1] = key[2] = key[3] = 0;
    for (k = 0; k < 2; k++) {
        if (!diff_int(k ? a.y : a.x, k ? b.y : b.x, &d, &de))
            return 0;
        if (d.hi == 0 && d.lo == 0)
            continue;
        if (de < e || u128_bitlen(d) + (unsigned)(de - e) > 126)
            return 0; /* not an integer at 2^e, or too wide */
        square_256(u128_shl2(d, (unsigned)(de - e)), sq);
        for (i = 3, c = 0; i >= 0; i--) { /* two squares below 2^252: no carry out */
            uint64_t s = key[i] + sq[i];
            uint64_t c2 = s < sq[i];
            key[i] = s + c;
            c = c2 + (key[i] < c);
        }
    }
    return 1;
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
