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

#endif
