/* A user's motif from SVG (docs/motifs.md); its own file so programs that
 * never read SVG motifs do not link the SVG reader. */
#include <math.h>
#include <string.h>

#include "deco_internal.h"

QC__HIDDEN int qc__motif_add(qc_ctx *ctx, qc_path *path, const char *name, int legs,
                             qc_vec2 in_dir, qc_vec2 out_dir, qc_motif_set *out);

static qc_vec2 unit(qc_vec2 from, qc_vec2 to)
{
    qc_vec2 d;
    double len = qc_hypot(to.x - from.x, to.y - from.y);
    d.x = len > 0 ? (to.x - from.x) / len : 0;
    d.y = len > 0 ? (to.y - from.y) / len : 0;
    return d;
}

int qc_motif_from_svg(qc_ctx *ctx, const char *buf, size_t len, const char *name,
                      qc_motif_set *out)
{
    qc_path p = {0}, body = {0};
    size_t i, k;
    qc_vec2 first, last, ind = {0, 0}, outd = {0, 0};
    int rc, legs = 0;

    if (buf == NULL || out == NULL || name == NULL)
        return qc__fail(ctx, QC_EINVAL, "motif SVG, name or set missing");
    QC__TRY(qc_io_read_svg_path(ctx, buf, len, NULL, &p));
    /* Later MOVEs become LINEs: a motif is sewn in one go. */
    for (i = 1; i < p.ncmd; i++)
        if (p.cmd[i] == QC_PATH_MOVE)
            p.cmd[i] = QC_PATH_LINE;
    if (p.ncmd < 2) {
        qc_path_free(ctx, &p);
        return qc__fail(ctx, QC_EDEGENERATE, "motif %s: the SVG has no segment", name);
    }
    first = p.pt[0];
    last = qc_path_last(&p);
    if (qc_hypot(last.x - first.x, last.y - first.y) > 1e-6 * (1 + fabs(first.x) + fabs(first.y))
        && p.ncmd >= 4) {
        /* Two legs: the first and last segments give directions, not stitches. */
        legs = 2;
        {
            /* end of the first segment, start of the last */
            qc_vec2 e_in = p.pt[qc_path_cmd_points(p.cmd[1])];
            size_t klast = qc_path_cmd_points(p.cmd[p.ncmd - 1]);
            qc_vec2 e_out = p.pt[p.npt - klast - 1];
            ind = unit(e_in, first);
            outd = unit(e_out, last);
            rc = qc_path_move_to(ctx, &body, e_in);
            k = 1 + qc_path_cmd_points(p.cmd[1]);
            for (i = 2; rc == QC_OK && i + 1 < p.ncmd; i++) {
                if (p.cmd[i] == QC_PATH_CUBIC)
                    rc = qc_path_cubic_to(ctx, &body, p.pt[k], p.pt[k + 1], p.pt[k + 2]);
                else
                    rc = qc_path_line_to(ctx, &body, p.pt[k]);
                k += qc_path_cmd_points(p.cmd[i]);
            }
        }
        qc_path_free(ctx, &p);
        if (rc != QC_OK) {
            qc_path_free(ctx, &body);
            return rc;
        }
        if (body.ncmd < 2) { /* only legs: a straight body between them */
            rc = qc_path_line_to(ctx, &body, body.pt[0]);
            if (rc != QC_OK) {
                qc_path_free(ctx, &body);
                return rc;
            }
        }
        return qc__motif_add(ctx, &body, name, legs, ind, outd, out);
    }
    return qc__motif_add(ctx, &p, name, 0, ind, outd, out);
}
