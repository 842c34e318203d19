/* A user's motif from SVG (docs/motifs.md); its own file so programs that
 * never read SVG motifs do not link the SVG reader. */
#include "deco_internal.h"

int qc_motif_from_svg(qc_ctx *ctx, const char *buf, size_t len, const char *name,
                      qc_motif_set *out)
{
    qc_path p = {0};

    if (buf == NULL || out == NULL || name == NULL)
        return qc__fail(ctx, QC_EINVAL, "motif SVG, name or set missing");
    QC__TRY(qc_io_read_svg_path(ctx, buf, len, NULL, &p));
    return qc__motif_from_path(ctx, &p, name, out);
}
