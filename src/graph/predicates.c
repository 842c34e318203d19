/*
 * Adaptive exact orient2d/incircle after Shewchuk (1997): a floating-point
 * filter with his error bounds, then exact expansion arithmetic when the
 * filter cannot decide. The constants are literals for IEEE double (no
 * exactinit() state). Relies on -ffp-contract=off (no FMA) and round to
 * nearest; exact unless an intermediate product overflows or underflows.
 */
#include <math.h>

#include "graph_internal.h"

#define EPS 0x1p-53 /* half an ulp of 1 */
#define SPLITTER 134217729.0 /* 2^27 + 1 */
#define CCW_ERR_A ((3.0 + 16.0 * EPS) * EPS)
#define ICC_ERR_A ((10.0 + 96.0 * EPS) * EPS)

/* x + y == a + b exactly, x = fl(a + b). */
static void two_sum(double a, double b, double *x, double *y)
{
    double s = a + b, bv = s - a, av = s - bv;

    *x = s;
    *y = (a - av) + (b - bv);
}

/* x + y == a - b exactly. */
/* x + y == a + b exactly, given |a| >= |b| or a == 0. */
static void fast_two_sum(double a, double b, double *x, double *y)
{
    double s = a + b;

    *x = s;
    *y = b - (s - a);
}

static void two_diff(double a, double b, double *x, double *y)
{
    double s = a - b, bv = a - s, av = s + bv;

    *x = s;
    *y = (a - av) + (bv - b);
}

static void split(double a, double *hi, double *lo)
{
    double c = SPLITTER * a, big = c - a;

    *hi = c - big;
    *lo = a - *hi;
}

/* x + y == a * b exactly (b pre-split). */
static void two_product_presplit(double a, double b, double bhi, double blo,
                                 double *x, double *y)
{
    double p = a * b, ahi, alo, e1, e2, e3;

    split(a, &ahi, &alo);
    e1 = p - ahi * bhi;
    e2 = e1 - alo * bhi;
    e3 = e2 - ahi * blo;
    *x = p;
    *y = alo * blo - e3;
}

/* h = e + f; zero components dropped; at least one component out. */
static int sum_zeroelim(int elen, const double *e, int flen, const double *f,
                        double *h)
{
    double q, qn, hh;
    int ei = 0, fi = 0, hi = 0;

    if ((f[0] > e[0]) == (f[0] > -e[0]))
        q = e[ei++];
    else
        q = f[fi++];
    while (ei < elen && fi < flen) {
        if ((f[fi] > e[ei]) == (f[fi] > -e[ei]))
            two_sum(q, e[ei++], &qn, &hh);
        else
            two_sum(q, f[fi++], &qn, &hh);
        q = qn;
        if (hh != 0.0)
            h[hi++] = hh;
    }
    while (ei < elen) {
        two_sum(q, e[ei++], &qn, &hh);
        q = qn;
        if (hh != 0.0)
            h[hi++] = hh;
    }
    while (fi < flen) {
        two_sum(q, f[fi++], &qn, &hh);
        q = qn;
        if (hh != 0.0)
            h[hi++] = hh;
    }
    if (q != 0.0 || hi == 0)
        h[hi++] = q;
    return hi;
}

/* h = e * b; up to 2 * elen components. */
static int scale_zeroelim(int elen, const double *e, double b, double *h)
{
    double bhi, blo, q, hh, p1, p0, s;
    int i, hi = 0;

    split(b, &bhi, &blo);
    two_product_presplit(e[0], b, bhi, blo, &q, &hh);
    if (hh != 0.0)
        h[hi++] = hh;
    for (i = 1; i < elen; i++) {
        two_product_presplit(e[i], b, bhi, blo, &p1, &p0);
        two_sum(q, p0, &s, &hh);
        if (hh != 0.0)
            h[hi++] = hh;
        fast_two_sum(p1, s, &q, &hh);
        if (hh != 0.0)
            h[hi++] = hh;
    }
    if (q != 0.0 || hi == 0)
        h[hi++] = q;
    return hi;
}

/* h = e * f: up to 2 * elen * flen components; tmp holds 2 * elen, acc
 * scratch as large as h. */
static int mul(int elen, const double *e, int flen, const double *f,
               double *h, double *tmp, double *acc)
{
    int i, hl, tl;

    hl = scale_zeroelim(elen, e, f[0], h);
    for (i = 1; i < flen; i++) {
        int k;

        tl = scale_zeroelim(elen, e, f[i], tmp);
        hl = sum_zeroelim(hl, h, tl, tmp, acc);
        for (k = 0; k < hl; k++)
            h[k] = acc[k];
    }
    return hl;
}

static int diff_exp(double a, double b, double *h)
{
    double x, y;

    two_diff(a, b, &x, &y);
    if (y == 0.0) {
        h[0] = x;
        return 1;
    }
    h[0] = y;
    h[1] = x;
    return 2;
}

static void negate(int n, double *e)
{
    int i;

    for (i = 0; i < n; i++)
        e[i] = -e[i];
}

/* e*f - g*h for expansions of at most 2 components each: up to 16 out. */
static int cross2(int el, const double *e, int fl, const double *f, int gl,
                  const double *g, int hl, const double *h, double *out)
{
    double p[8], q[8], tmp[4], acc[8];
    int pl = mul(el, e, fl, f, p, tmp, acc);
    int ql = mul(gl, g, hl, h, q, tmp, acc);

    negate(ql, q);
    return sum_zeroelim(pl, p, ql, q, out);
}

static double orient_exact(qc_vec2 a, qc_vec2 b, qc_vec2 c)
{
    double acx[2], acy[2], bcx[2], bcy[2], det[16];
    int l1 = diff_exp(a.x, c.x, acx), l2 = diff_exp(b.y, c.y, bcy);
    int l3 = diff_exp(a.y, c.y, acy), l4 = diff_exp(b.x, c.x, bcx);
    int n = cross2(l1, acx, l2, bcy, l3, acy, l4, bcx, det);

    return det[n - 1];
}

double qc_orient2d(qc_vec2 a, qc_vec2 b, qc_vec2 c)
{
    double l = (a.x - c.x) * (b.y - c.y), r = (a.y - c.y) * (b.x - c.x);
    double det = l - r, sum;

    if (l > 0.0) {
        if (r <= 0.0)
            return det;
        sum = l + r;
    } else if (l < 0.0) {
        if (r >= 0.0)
            return det;
        sum = -l - r;
    } else {
        return det;
    }
    if (det >= CCW_ERR_A * sum || -det >= CCW_ERR_A * sum)
        return det;
    return orient_exact(a, b, c);
}

/* lift * (e*f - g*h) with lift = x^2 + y^2: up to 512 components. */
static int lifted_term(int xl, const double *x, int yl, const double *y,
                       int el, const double *e, int fl, const double *f,
                       int gl, const double *g, int hl, const double *h,
                       double *out)
{
    double xx[8], yy[8], lift[16], c[16], tmp[32], acc[512];
    double t4[4], a8[8];
    int xxl = mul(xl, x, xl, x, xx, t4, a8);
    int yyl = mul(yl, y, yl, y, yy, t4, a8);
    int ll = sum_zeroelim(xxl, xx, yyl, yy, lift);
    int cl = cross2(el, e, fl, f, gl, g, hl, h, c);

    return mul(ll, lift, cl, c, out, tmp, acc);
}

static double incircle_exact(qc_vec2 a, qc_vec2 b, qc_vec2 c, qc_vec2 d)
{
    double adx[2], ady[2], bdx[2], bdy[2], cdx[2], cdy[2];
    double ta[512], tb[512], tc[512], ab[1024], det[1536];
    int adxl = diff_exp(a.x, d.x, adx), adyl = diff_exp(a.y, d.y, ady);
    int bdxl = diff_exp(b.x, d.x, bdx), bdyl = diff_exp(b.y, d.y, bdy);
    int cdxl = diff_exp(c.x, d.x, cdx), cdyl = diff_exp(c.y, d.y, cdy);
    int la = lifted_term(adxl, adx, adyl, ady, bdxl, bdx, cdyl, cdy, cdxl, cdx,
                         bdyl, bdy, ta);
    int lb = lifted_term(bdxl, bdx, bdyl, bdy, cdxl, cdx, adyl, ady, adxl, adx,
                         cdyl, cdy, tb);
    int lc = lifted_term(cdxl, cdx, cdyl, cdy, adxl, adx, bdyl, bdy, bdxl, bdx,
                         adyl, ady, tc);
    int lab = sum_zeroelim(la, ta, lb, tb, ab);
    int n = sum_zeroelim(lab, ab, lc, tc, det);

    return det[n - 1];
}

/* A double-double (hi + lo) approximation of an exact value, and whether
 * every error-free transform on the way had a zero tail (then hi + lo is
 * exactly the value and lo == 0). */
typedef struct dd {
    double hi, lo;
    int exact;
} dd;

static void two_product(double a, double b, double *x, double *y)
{
    double bhi, blo;

    split(b, &bhi, &blo);
    two_product_presplit(a, b, bhi, blo, x, y);
}

/* a*b + sign*(c*d), sign = +-1: |error| <= 4.001 eps^2 (|ab| + |cd|). */
static dd dd_two_products(double a, double b, double c, double d, double sign)
{
    double p1, e1, p2, e2, s, t;
    dd r;

    two_product(a, b, &p1, &e1);
    two_product(c, d, &p2, &e2);
    two_sum(p1, sign * p2, &s, &t);
    r.hi = s;
    r.lo = (t + e1) + sign * e2;
    r.exact = t == 0.0 && e1 == 0.0 && e2 == 0.0;
    return r;
}

/* lift * cross: |error| <= 24.01 eps^2 (|lift| * (|c1| + |c2|)). */
static dd dd_term(dd lift, dd cross)
{
    double p, e;
    dd r;

    two_product(lift.hi, cross.hi, &p, &e);
    r.hi = p;
    r.lo = e + (lift.hi * cross.lo + lift.lo * cross.hi);
    r.exact = lift.exact && cross.exact && e == 0.0;
    return r;
}

/* The in-circle determinant from exact differences in double-double, error
 * under 52.1 eps^2 perm (perm: the filter's permanent); its sign when that
 * decides it (or it is exact), else 0 and *decided = 0. Most near-cocircular
 * lattice points end here, at a tenth of the expansions' cost. */
static double incircle_dd(const double *dx, const double *dy, double perm,
                          int *decided)
{
    dd t[3];
    double x, y, z, w, rest, det;
    int i, exact = 1;

    for (i = 0; i < 3; i++) {
        int j = (i + 1) % 3, k = (i + 2) % 3;

        t[i] = dd_term(dd_two_products(dx[i], dx[i], dy[i], dy[i], 1.0),
                       dd_two_products(dx[j], dy[k], dx[k], dy[j], -1.0));
        exact = exact && t[i].exact;
    }
    two_sum(t[0].hi, t[1].hi, &x, &y);
    two_sum(x, t[2].hi, &z, &w);
    rest = ((y + w) + (t[0].lo + t[1].lo)) + t[2].lo;
    det = z + rest;
    if (exact && y == 0.0 && w == 0.0) {
        *decided = 1;
        return z;
    }
    *decided = det > 128.0 * EPS * EPS * perm || -det > 128.0 * EPS * EPS * perm;
    return det;
}

/* The six differences of a, b, c from d, when all are exact. */
static int exact_diffs(qc_vec2 a, qc_vec2 b, qc_vec2 c, qc_vec2 d, double *dx,
                       double *dy)
{
    const qc_vec2 v[3] = {a, b, c};
    int i, exact = 1;

    for (i = 0; i < 3; i++) {
        double tx, ty;

        two_diff(v[i].x, d.x, &dx[i], &tx);
        two_diff(v[i].y, d.y, &dy[i], &ty);
        exact = exact && tx == 0.0 && ty == 0.0;
    }
    return exact;
}

double qc_incircle(qc_vec2 a, qc_vec2 b, qc_vec2 c, qc_vec2 d)
{
    double adx = a.x - d.x, bdx = b.x - d.x, cdx = c.x - d.x;
    double ady = a.y - d.y, bdy = b.y - d.y, cdy = c.y - d.y;
    double bc1 = bdx * cdy, bc2 = cdx * bdy, al = adx * adx + ady * ady;
    double ca1 = cdx * ady, ca2 = adx * cdy, bl = bdx * bdx + bdy * bdy;
    double ab1 = adx * bdy, ab2 = bdx * ady, cl = cdx * cdx + cdy * cdy;
    double det = al * (bc1 - bc2) + bl * (ca1 - ca2) + cl * (ab1 - ab2);
    double perm = (fabs(bc1) + fabs(bc2)) * al + (fabs(ca1) + fabs(ca2)) * bl +
                  (fabs(ab1) + fabs(ab2)) * cl;

    double dx[3], dy[3];
    int decided = 0;

    if (det > ICC_ERR_A * perm || -det > ICC_ERR_A * perm)
        return det;
    if (exact_diffs(a, b, c, d, dx, dy)) {
        det = incircle_dd(dx, dy, perm, &decided);
        if (decided)
            return det;
    }
    return incircle_exact(a, b, c, d);
}
