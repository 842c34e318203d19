/* Counting a plan: lengths, stitches, thread and time. */
#include <math.h>
#include <string.h>

#include "internal.h"

#define THREAD_FACTOR 1.1      /* take-up over the sewn length */
#define THREAD_PER_PIECE 150.0 /* mm: tails to tie and bury at each piece */
#define TRAVEL_SPEEDUP 4.0

void qc_plan_estimate_get(const qc_plan *plan, double spi, double speed_mm_s,
                          qc_plan_estimate *out)
{
    size_t i, pieces = 0;

    memset(out, 0, sizeof *out);
    /* out-of-range figures (NaN, inf, absurd) mean the defaults */
    if (!(spi > 0 && spi <= 1000))
        spi = 12;
    if (!(speed_mm_s > 0 && speed_mm_s <= 1e5))
        speed_mm_s = 25.4;
    for (i = 0; i < plan->n; i++) {
        qc_vec2 p = plan->p[i];
        unsigned f = plan->flags[i];

        if (i == 0) {
            out->bbox.min = out->bbox.max = p;
        } else {
            double d = qc_hypot(p.x - plan->p[i - 1].x, p.y - plan->p[i - 1].y);

            if (f & QC_ST_JUMP)
                out->travel_mm += d;
            else
                out->sewn_mm += d;
            out->bbox.min.x = fmin(out->bbox.min.x, p.x);
            out->bbox.min.y = fmin(out->bbox.min.y, p.y);
            out->bbox.max.x = fmax(out->bbox.max.x, p.x);
            out->bbox.max.y = fmax(out->bbox.max.y, p.y);
        }
        if (f & QC_ST_JUMP) {
            pieces++;
            if (i > 0)
                out->jumps++;
        }
        if (f & QC_ST_TIE)
            out->ties++;
    }
    out->points = plan->n;
    out->stitches = (size_t)floor(out->sewn_mm / 25.4 * spi + 0.5);
    out->thread_mm = out->sewn_mm * THREAD_FACTOR + THREAD_PER_PIECE * (double)pieces;
    out->seconds = out->sewn_mm / speed_mm_s +
                   out->travel_mm / (speed_mm_s * TRAVEL_SPEEDUP);
}
