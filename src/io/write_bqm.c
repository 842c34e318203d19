/*
 * Bernina Q-matic .bqm: G-code lines numbered from N10 up by one,
 * "N10G00X1.0000Y2.0000", G00 to each piece's start, G01 for sewn points,
 * inches with 4 decimals, y up, "N<k>M02" last, LF. (The format also has
 * G02/G03 arcs; a flattened plan needs none.)
 */
#include "io_internal.h"

int qc__write_bqm(qc_ctx *ctx, const qc_plan *plan, const qc_io_opts *opts,
                  qc__out *o)
{
    int64_t line = 10;
    size_t i;

    (void)ctx;
    (void)opts;
    for (i = 0; i < plan->n; i++) {
        qc__out_char(o, 'N');
        qc__out_int(o, line++);
        qc__out_str(o, i == 0 || (plan->flags[i] & QC_ST_JUMP) ? "G00X" : "G01X");
        qc__out_fixed(o, qc__mm_to_inch_units(plan->p[i].x, 10000), 4, 0);
        qc__out_char(o, 'Y');
        qc__out_fixed(o, qc__mm_to_inch_units(plan->p[i].y, 10000), 4, 0);
        qc__out_char(o, '\n');
    }
    qc__out_char(o, 'N');
    qc__out_int(o, line);
    qc__out_str(o, "M02\n");
    return QC_OK;
}
