/*
 * sin, cos and atan2 from +, -, *, / and sqrt only, so every platform
 * (glibc, musl, newlib, Emscripten) computes the same bits. Accuracy is a
 * few ulp, ample for geometry in millimetres.
 */
#include <math.h>

#include "internal.h"

/* pi/2 split in three parts (Cody-Waite) so the reduction stays exact. */
#define PIO2_1 1.57079632673412561417e+00
#define PIO2_2 6.07710050650619224932e-11
#define PIO2_3 2.02226624879595063154e-21

static double sin_poly(double x) /* |x| <= pi/4 */
{
    double x2 = x * x;
    double p = 1.0 / 355687428096000.0;         /* 1/17! */
    p = p * x2 - 1.0 / 1307674368000.0;         /* 1/15! */
    p = p * x2 + 1.0 / 6227020800.0;            /* 1/13! */
    p = p * x2 - 1.0 / 39916800.0;              /* 1/11! */
    p = p * x2 + 1.0 / 362880.0;                /* 1/9! */
    p = p * x2 - 1.0 / 5040.0;
    p = p * x2 + 1.0 / 120.0;
    p = p * x2 - 1.0 / 6.0;
    return x + x * x2 * p;
}

static double cos_poly(double x) /* |x| <= pi/4 */
{
    double x2 = x * x;
    double p = -1.0 / 6402373705728000.0;       /* -1/18! */
    p = p * x2 + 1.0 / 20922789888000.0;        /* 1/16! */
    p = p * x2 - 1.0 / 87178291200.0;           /* 1/14! */
    p = p * x2 + 1.0 / 479001600.0;             /* 1/12! */
    p = p * x2 - 1.0 / 3628800.0;               /* 1/10! */
    p = p * x2 + 1.0 / 40320.0;
    p = p * x2 - 1.0 / 720.0;
    p = p * x2 + 1.0 / 24.0;
    return 1.0 - 0.5 * x2 + x2 * x2 * p;
}

/* x = k*(pi/2) + r with |r| <= pi/4; returns k mod 4. Inputs beyond 1e9 lose accuracy. */
static int reduce(double x, double *r)
{
    double k = floor(x * (2.0 / QC_PI) + 0.5);
    /* the quadrant k mod 4: two's complement & 3 while k fits, fmod beyond */
    long q = fabs(k) < 4.0e18 ? (long)((long long)k & 3) : (long)fmod(k, 4.0);

    *r = ((x - k * PIO2_1) - k * PIO2_2) - k * PIO2_3;
    return (int)(q < 0 ? q + 4 : q);
}

double qc_sin(double x)
{
    double r;

    if (!isfinite(x))
        return x - x; /* NaN */
    switch (reduce(x, &r)) {
    case 0: return sin_poly(r);
    case 1: return cos_poly(r);
    case 2: return -sin_poly(r);
    default: return -cos_poly(r);
    }
}

double qc_cos(double x)
{
    double r;

    if (!isfinite(x))
        return x - x;
    switch (reduce(x, &r)) {
    case 0: return cos_poly(r);
    case 1: return -sin_poly(r);
    case 2: return -cos_poly(r);
    default: return sin_poly(r);
    }
}

void qc__sincos(double x, double *s, double *c)
{
    double r, sp, cp;
    int q;

    if (!isfinite(x)) {
        *s = *c = x - x;
        return;
    }
    q = reduce(x, &r);
    sp = sin_poly(r);
    cp = cos_poly(r);
    *s = q == 0 ? sp : q == 1 ? cp : q == 2 ? -sp : -cp;
    *c = q == 0 ? cp : q == 1 ? -sp : q == 2 ? -cp : sp;
}

static double atan_small(double u) /* |u| <= tan(pi/12) */
{
    /* the series' coefficients (-1)^j / (2j + 1), j = 13 down to 1 */
    static const double c[] = {-1.0 / 27, 1.0 / 25, -1.0 / 23, 1.0 / 21, -1.0 / 19,
                               1.0 / 17, -1.0 / 15, 1.0 / 13, -1.0 / 11, 1.0 / 9,
                               -1.0 / 7, 1.0 / 5, -1.0 / 3};
    double u2 = u * u, p = 0.0;
    size_t i;

    for (i = 0; i < sizeof c / sizeof c[0]; i++)
        p = p * u2 + c[i];
    return u + u * u2 * p;
}

static double atan_unit(double t) /* 0 <= t <= 1 */
{
    const double sqrt3 = 1.73205080756887729353;
    const double tan_pi12 = 0.26794919243112270647;

    if (t <= tan_pi12)
        return atan_small(t);
    return QC_PI / 6.0 + atan_small((t * sqrt3 - 1.0) / (sqrt3 + t));
}

double qc_atan2(double y, double x)
{
    double ax = fabs(x), ay = fabs(y), a;

    if (isnan(x) || isnan(y))
        return x + y;
    if (ax == 0.0 && ay == 0.0)
        return 0.0;
    if (isinf(ax) || isinf(ay)) {
        if (isinf(ax) && isinf(ay))
            a = QC_PI / 4.0;
        else
            a = isinf(ay) ? QC_PI / 2.0 : 0.0;
    } else if (ay <= ax) {
        a = atan_unit(ay / ax);
    } else {
        a = QC_PI / 2.0 - atan_unit(ax / ay);
    }
    if (x < 0.0)
        a = QC_PI - a;
    return y < 0.0 ? -a : a;
}

double qc_hypot(double x, double y)
{
    return qc__hypot(x, y);
}
