/*
 * Innova AutoPilot .pat: "N1G00X1.000Y9.008" CRLF, N consecutive from 1,
 * G00 for each piece start (JUMP), G01 otherwise, inches with exactly 3
 * decimals, y up, no header, last line "N<k>M02". Points that round to the
 * previous line's position are dropped; negative positions are refused.
 */
#include "io_internal.h"

int qc__write_pat(qc_ctx *ctx, const qc_plan *plan, const qc_io_opts *opts,
                  qc__out *o)
{
    int64_t px = -1, py = -1, line = 1;
    size_t i;

    (void)opts;
    for (i = 0; i < plan->n; i++) {
        int64_t x, y;

        if (plan->p[i].x >= 0 && plan->p[i].y >= 0)
            continue; /* rounds to >= 0: converted once, below */
        x = qc__mm_to_inch_units(plan->p[i].x, 1000);
        y = qc__mm_to_inch_units(plan->p[i].y, 1000);
        if (x < 0 || y < 0)
            return qc__fail(ctx, QC_ERANGE,
                            "pat: point %lu (%.3f, %.3f) mm is negative; move the "
                            "pattern so its bounding box starts at (0, 0)",
                            (unsigned long)i, plan->p[i].x, plan->p[i].y);
    }
    for (i = 0; i < plan->n; i++) {
        int64_t x = qc__mm_to_inch_units(plan->p[i].x, 1000);
        int64_t y = qc__mm_to_inch_units(plan->p[i].y, 1000);

        if (x == px && y == py)
            continue;
        qc__out_char(o, 'N');
        qc__out_int(o, line++);
        qc__out_str(o, i == 0 || (plan->flags[i] & QC_ST_JUMP) ? "G00X" : "G01X");
        qc__out_fixed(o, x, 3, 0);
        qc__out_char(o, 'Y');
        qc__out_fixed(o, y, 3, 0);
        qc__out_bytes(o, "\r\n", 2);
        px = x;
        py = y;
    }
    qc__out_char(o, 'N');
    qc__out_int(o, line);
    qc__out_bytes(o, "M02\r\n", 5);
    return QC_OK;
}
