/*
 * G-code for CNC frames: G21 (mm), G90 (absolute), "G0 X Y" to each piece's
 * start, "G1 X Y" for sewn points with the feed (opts->feed_mm_min, default
 * 1500) on the first G1 after each G0, mm with 3 decimals, y up, M2 last. LF.
 */
#include "io_internal.h"

#define DEF_FEED 1500.0

int qc__write_gcode(qc_ctx *ctx, const qc_plan *plan, const qc_io_opts *opts,
                    qc__out *o)
{
    double feed = opts->feed_mm_min == 0 ? DEF_FEED : opts->feed_mm_min;
    int need_feed = 1;
    size_t i;

    if (!(feed > 0 && feed <= 1e6))
        return qc__fail(ctx, QC_ERANGE, "gcode: feed %g mm/min must be in (0, 1e6]",
                        opts->feed_mm_min);
    qc__out_str(o, "(quiltc " QC_VERSION_STRING ")\nG21\nG90\n");
    for (i = 0; i < plan->n; i++) {
        int jump = i == 0 || (plan->flags[i] & QC_ST_JUMP);

        qc__out_str(o, jump ? "G0 X" : "G1 X");
        qc__out_fixed(o, qc__mm_to_units(plan->p[i].x, 1000), 3, 0);
        qc__out_str(o, " Y");
        qc__out_fixed(o, qc__mm_to_units(plan->p[i].y, 1000), 3, 0);
        if (!jump && need_feed) {
            qc__out_str(o, " F");
            qc__out_fixed(o, qc__mm_to_units(feed, 10), 1, 1);
        }
        need_feed = jump;
        qc__out_char(o, '\n');
    }
    qc__out_str(o, "M2\n");
    return QC_OK;
}
