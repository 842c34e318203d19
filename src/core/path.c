/* Building paths of move/line/cubic commands. */
#include <string.h>

#include "internal.h"

void qc_path_free(qc_ctx *ctx, qc_path *path)
{
    if (path == NULL)
        return;
    qc__free(ctx, path->cmd, path->cmd_cap);
    qc__free(ctx, path->pt, path->pt_cap * sizeof *path->pt);
    memset(path, 0, sizeof *path);
}

size_t qc_path_cmd_points(unsigned char cmd)
{
    return cmd == QC_PATH_CUBIC ? 3 : 1;
}

static int push(qc_ctx *ctx, qc_path *path, unsigned char cmd,
                const qc_vec2 *pts)
{
    size_t k = qc_path_cmd_points(cmd);

    QC__TRY(QC__RESERVE(ctx, path->cmd, path->cmd_cap, path->ncmd + 1));
    QC__TRY(QC__RESERVE(ctx, path->pt, path->pt_cap, path->npt + k));
    path->cmd[path->ncmd++] = cmd;
    memcpy(path->pt + path->npt, pts, k * sizeof *pts);
    path->npt += k;
    return QC_OK;
}

int qc_path_move_to(qc_ctx *ctx, qc_path *path, qc_vec2 p)
{
    return push(ctx, path, QC_PATH_MOVE, &p);
}

int qc_path_line_to(qc_ctx *ctx, qc_path *path, qc_vec2 p)
{
    return push(ctx, path, QC_PATH_LINE, &p);
}

int qc_path_cubic_to(qc_ctx *ctx, qc_path *path, qc_vec2 c1, qc_vec2 c2,
                     qc_vec2 p)
{
    qc_vec2 pts[3];

    pts[0] = c1;
    pts[1] = c2;
    pts[2] = p;
    return push(ctx, path, QC_PATH_CUBIC, pts);
}

int qc_path_append(qc_ctx *ctx, qc_path *dst, const qc_path *src, int join)
{
    size_t c, k = 0, ncmd = dst->ncmd, npt = dst->npt;

    for (c = 0; c < src->ncmd; c++) {
        unsigned char cmd = src->cmd[c];
        int rc;

        if (cmd == QC_PATH_MOVE && join && c == 0 && dst->ncmd > 0)
            cmd = QC_PATH_LINE;
        rc = push(ctx, dst, cmd, src->pt + k);
        if (rc < 0) { /* all or nothing: dst as it was */
            dst->ncmd = ncmd;
            dst->npt = npt;
            return rc;
        }
        k += qc_path_cmd_points(src->cmd[c]);
    }
    return QC_OK;
}

qc_vec2 qc_path_last(const qc_path *path)
{
    qc_vec2 zero = {0.0, 0.0};

    return path->npt > 0 ? path->pt[path->npt - 1] : zero;
}

size_t qc_path_pieces(const qc_path *path)
{
    size_t c, n = 0;

    for (c = 0; c < path->ncmd; c++)
        n += path->cmd[c] == QC_PATH_MOVE;
    return n;
}

/* Cuts the path's blocks to what it holds: a result keeps its path through
 * the stitch plan and the writers, so at 10^6 points a doubling's slack is
 * tens of MB held to the end. A shrink that fails keeps the larger block. */
void qc__path_fit(qc_ctx *ctx, qc_path *path)
{
    unsigned char *cmd;
    qc_vec2 *pt;

    if (path->ncmd == 0 || path->npt == 0)
        return;
    if (path->cmd_cap > path->ncmd) {
        cmd = (unsigned char *)qc__realloc(ctx, path->cmd, path->cmd_cap, path->ncmd);
        if (cmd == NULL) {
            qc_clear_error(ctx);
            return;
        }
        path->cmd = cmd;
        path->cmd_cap = path->ncmd;
    }
    if (path->pt_cap > path->npt) {
        pt = (qc_vec2 *)qc__realloc(ctx, path->pt, path->pt_cap * sizeof *pt,
                                    path->npt * sizeof *pt);
        if (pt == NULL) {
            qc_clear_error(ctx);
            return;
        }
        path->pt = pt;
        path->pt_cap = path->npt;
    }
}
