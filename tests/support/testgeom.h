/* Geometry shorthand shared by the tests. */
#ifndef TESTGEOM_H
#define TESTGEOM_H

#include "quiltc.h"

static inline qc_vec2 v2(double x, double y)
{
    qc_vec2 p;

    p.x = x;
    p.y = y;
    return p;
}

/* A random point (x0 + u sx, y0 + u sy). The two draws are sequenced here:
 * as two arguments of one call their order is unspecified (gcc draws y
 * first, clang x), and the tests saw other points under clang. y comes
 * first, as gcc drew it when the tests were written. */
static inline qc_vec2 rng_v2(qc_rng *r, double x0, double sx, double y0, double sy)
{
    double y = y0 + qc_rng_unit(r) * sy;

    return v2(x0 + qc_rng_unit(r) * sx, y);
}

#endif
