/*
 * QuiltEZ .qcc: a header line "c s", then "p X1.2345 Y0.5000" per point,
 * inches with 4 decimals, y up, LF. The format has no travel move: pieces
 * are joined by straight lines (plan pieces should be joined or sewn).
 */
#include "io_internal.h"

int qc__write_qcc(qc_ctx *ctx, const qc_plan *plan, const qc_io_opts *opts,
                  qc__out *o)
{
    size_t i;

    (void)ctx;
    (void)opts;
    qc__out_str(o, "c s\n");
    for (i = 0; i < plan->n; i++) {
        qc__out_str(o, "p X");
        qc__out_fixed(o, qc__mm_to_inch_units(plan->p[i].x, 10000), 4, 0);
        qc__out_str(o, " Y");
        qc__out_fixed(o, qc__mm_to_inch_units(plan->p[i].y, 10000), 4, 0);
        qc__out_char(o, '\n');
    }
    return QC_OK;
}
