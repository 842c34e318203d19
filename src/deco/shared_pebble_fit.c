/*
 * A drawn pebble path cut to its size. Pebbling and packing reserve their
 * path once for the most it could hold (a bound a third to a half above what
 * a typical block draws); the result keeps the path through the stitch plan
 * and the writers, so at 10^6 points the slack would be tens of MB held to
 * the end.
 */
#include "pebble_internal.h"

void qc__pebble_path_fit(qc_ctx *ctx, qc_path *path)
{
    unsigned char *cmd;
    qc_vec2 *pt;

    if (path->ncmd == 0 || path->npt == 0)
        return;
    if (path->cmd_cap > path->ncmd) {
        cmd = qc__realloc(ctx, path->cmd, path->cmd_cap, path->ncmd);
        if (cmd == NULL) {
            qc_clear_error(ctx); /* a shrink that fails keeps the larger block */
            return;
        }
        path->cmd = cmd;
        path->cmd_cap = path->ncmd;
    }
    if (path->pt_cap > path->npt) {
        pt = qc__realloc(ctx, path->pt, path->pt_cap * sizeof *pt, path->npt * sizeof *pt);
        if (pt == NULL) {
            qc_clear_error(ctx);
            return;
        }
        path->pt = pt;
        path->pt_cap = path->npt;
    }
}
