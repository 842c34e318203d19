/* The graph stage's input check: finite points whose coordinates the exact
 * predicates can multiply. */
#include <math.h>

#include "graph_internal.h"

/* The exact predicates multiply up to four coordinate differences: kept
 * between these magnitudes, no product underflows or overflows. */
static int coordinate_ok(double v)
{
    double a = fabs(v);

    return a == 0.0 || (a >= QC__COORD_MIN && a <= QC__COORD_MAX);
}

int qc__check_points(qc_ctx *ctx, const qc_vec2 *p, size_t n, const char *who)
{
    size_t i;

    if (n >= ((size_t)1 << 31))
        return qc__fail(ctx, QC_ELIMIT, "%s: %lu points, at most 2^31 - 1",
                        who, (unsigned long)n);
    for (i = 0; i < n; i++) {
        if (!isfinite(p[i].x) || !isfinite(p[i].y))
            return qc__fail(ctx, QC_ERANGE,
                            "%s: point %lu is not finite (%g, %g)", who,
                            (unsigned long)i, p[i].x, p[i].y);
        if (!coordinate_ok(p[i].x) || !coordinate_ok(p[i].y))
            return qc__fail(ctx, QC_ERANGE,
                            "%s: point %lu (%g, %g): a coordinate must be 0 or between "
                            "%g and %g mm in magnitude", who, (unsigned long)i, p[i].x,
                            p[i].y, QC__COORD_MIN, QC__COORD_MAX);
    }
    return QC_OK;
}
