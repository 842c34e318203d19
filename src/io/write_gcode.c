/*
 * G-code for CNC frames and pen plotters: G21 (mm), G90 (absolute), the
 * feed (opts->feed_mm_min, default 1500) as its own line, then for each
 * piece the pen-up line, "G0 X Y" to its start, the pen-down line, and
 * "G1 X Y" for its sewn points; mm with 3 decimals, y up; the pen-up line
 * and M2 last. LF. The pen lines default to "G0 Z5" / "G1 Z0" (the reader
 * takes Z > 0 as travel, so jumps stay jumps).
 */
#include <string.h>

#include "io_internal.h"

#define DEF_FEED 1500.0
#define MAX_PEN 64

static int pen_ok(const char *s)
{
    size_t i, n = strlen(s);

    for (i = 0; i < n; i++)
        if ((unsigned char)s[i] < 0x20 || (unsigned char)s[i] > 0x7e)
            return 0;
    return n <= MAX_PEN;
}

static void pen(qc__out *o, const char *cmd)
{
    if (cmd[0] == '\0')
        return;
    qc__out_str(o, cmd);
    qc__out_char(o, '\n');
}

int qc__write_gcode(qc_ctx *ctx, const qc_plan *plan, const qc_io_opts *opts,
                    qc__out *o)
{
    double feed = opts->feed_mm_min == 0 ? DEF_FEED : opts->feed_mm_min;
    const char *up = opts->pen_up != NULL ? opts->pen_up : "G0 Z5";
    const char *down = opts->pen_down != NULL ? opts->pen_down : "G1 Z0";
    size_t i;

    if (!(feed > 0 && feed <= 1e6))
        return qc__fail(ctx, QC_ERANGE, "gcode: feed %g mm/min must be in (0, 1e6]",
                        opts->feed_mm_min);
    if (!pen_ok(up) || !pen_ok(down))
        return qc__fail(ctx, QC_EINVAL, "gcode: a pen command must be one line of at most "
                        "%d printable ASCII characters", MAX_PEN);
    qc__out_str(o, "(quiltc " QC_VERSION_STRING ")\nG21\nG90\nF");
    /* the feed first: a pen-down G1 needs one on GRBL */
    qc__out_fixed(o, qc__mm_to_units(feed, 10), 1, 1);
    qc__out_char(o, '\n');
    for (i = 0; i < plan->n; i++) {
        int jump = i == 0 || (plan->flags[i] & QC_ST_JUMP);

        if (jump)
            pen(o, up);
        qc__out_str(o, jump ? "G0 X" : "G1 X");
        qc__out_fixed(o, qc__mm_to_units(plan->p[i].x, 1000), 3, 0);
        qc__out_str(o, " Y");
        qc__out_fixed(o, qc__mm_to_units(plan->p[i].y, 1000), 3, 0);
        qc__out_char(o, '\n');
        if (jump)
            pen(o, down);
    }
    pen(o, up);
    qc__out_str(o, "M2\n");
    return QC_OK;
}
