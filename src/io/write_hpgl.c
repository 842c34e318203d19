/*
 * HP-GL (.plt): "IN;" "SP1;", then "PU x,y;" to each piece's start and
 * "PD x,y;" for every sewn point, one command a line, in plotter units of
 * 0.025 mm (1016 per inch), y up; "PU;" "SP0;" to finish. LF.
 */
#include "io_internal.h"

int qc__write_hpgl(qc_ctx *ctx, const qc_plan *plan, const qc_io_opts *opts,
                   qc__out *o)
{
    size_t i;

    (void)ctx;
    (void)opts;
    qc__out_str(o, "IN;\nSP1;\n");
    for (i = 0; i < plan->n; i++) {
        int up = i == 0 || (plan->flags[i] & QC_ST_JUMP);

        qc__out_str(o, up ? "PU" : "PD");
        qc__out_int(o, qc__mm_to_units(plan->p[i].x, 40));
        qc__out_char(o, ',');
        qc__out_int(o, qc__mm_to_units(plan->p[i].y, 40));
        qc__out_str(o, ";\n");
    }
    qc__out_str(o, "PU;\nSP0;\n");
    return QC_OK;
}
