/*
 * Gammill Statler Stitcher .qli: a subset of the Galil DMC language. One
 * vector sequence (CS, VMXY, VP x,y ..., VE, BGS, AMS, EN) in integer
 * 0.001 in, y up, absolute from the plan's origin (the sequence starts
 * there: the CLI puts the block's lower-left corner at (0, 0)). Travel to
 * each piece's start is bracketed by NO NEEDLE OFF / NO NEEDLE ON. CRLF.
 */
#include "io_internal.h"

static void vp(qc__out *o, qc_vec2 p)
{
    qc__out_str(o, "VP ");
    qc__out_int(o, qc__mm_to_inch_units(p.x, 1000));
    qc__out_char(o, ',');
    qc__out_int(o, qc__mm_to_inch_units(p.y, 1000));
    qc__out_str(o, "\r\n");
}

int qc__write_qli(qc_ctx *ctx, const qc_plan *plan, const qc_io_opts *opts,
                  qc__out *o)
{
    size_t i;

    (void)ctx;
    (void)opts;
    qc__out_str(o, "REM quiltc " QC_VERSION_STRING "\r\n#CAD2DMC\r\nCS\r\nVMXY\r\n");
    for (i = 0; i < plan->n; i++) {
        if (i == 0 || (plan->flags[i] & QC_ST_JUMP)) {
            qc__out_str(o, "NO NEEDLE OFF\r\n");
            vp(o, plan->p[i]);
            qc__out_str(o, "NO NEEDLE ON\r\n");
        } else {
            vp(o, plan->p[i]);
        }
    }
    qc__out_str(o, "VE\r\nBGS\r\nAMS\r\nEN\r\n");
    return QC_OK;
}
