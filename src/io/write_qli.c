/*
 * Gammill Statler Stitcher .qli: a subset of the Galil DMC language. One
 * vector sequence (CS, VMXY, VP x,y ..., VE, BGS, AMS, EN) in integer
 * 0.001 in, y up, absolute from the plan's origin (the sequence starts
 * there: the CLI puts the block's lower-left corner at (0, 0)). Travel to
 * each piece's start is bracketed by NO NEEDLE OFF / NO NEEDLE ON. A point
 * that rounds onto the previous VP is dropped (no zero-length vector
 * segment for the controller). CRLF.
 */
#include "io_internal.h"

static void vp(qc__out *o, int64_t x, int64_t y)
{
    qc__out_str(o, "VP ");
    qc__out_int(o, x);
    qc__out_char(o, ',');
    qc__out_int(o, y);
    qc__out_str(o, "\r\n");
}

int qc__write_qli(qc_ctx *ctx, const qc_plan *plan, const qc_io_opts *opts,
                  qc__out *o)
{
    int64_t px = 0, py = 0;
    size_t i;

    (void)ctx;
    (void)opts;
    qc__out_str(o, "REM quiltc " QC_VERSION_STRING "\r\n#CAD2DMC\r\nCS\r\nVMXY\r\n");
    for (i = 0; i < plan->n; i++) {
        int64_t x = qc__mm_to_inch_units(plan->p[i].x, 1000);
        int64_t y = qc__mm_to_inch_units(plan->p[i].y, 1000);

        if (i > 0 && x == px && y == py)
            continue;
        if (i == 0 || (plan->flags[i] & QC_ST_JUMP)) {
            qc__out_str(o, "NO NEEDLE OFF\r\n");
            vp(o, x, y);
            qc__out_str(o, "NO NEEDLE ON\r\n");
        } else {
            vp(o, x, y);
        }
        px = x;
        py = y;
    }
    qc__out_str(o, "VE\r\nBGS\r\nAMS\r\nEN\r\n");
    return QC_OK;
}
