/*
 * qc_io_read: one entry for reading a pattern in any format quiltc writes.
 */
#include <string.h>

#include "read_common.h"

int qc_io_read(qc_ctx *ctx, int format, const char *buf, size_t len, qc_plan *out)
{
    int rc;

    memset(out, 0, sizeof *out);
    if (buf == NULL && len > 0)
        return qc__fail(ctx, QC_EINVAL, "read: NULL buffer of %lu bytes", (unsigned long)len);
    switch (format) {
    case QC_FORMAT_PAT:
        return qc_io_read_pat(ctx, buf, len, out);
    case QC_FORMAT_SVG: {
        qc_path path = {0};

        rc = qc_io_read_svg_path(ctx, buf, len, NULL, &path);
        if (rc == QC_OK)
            rc = qc_stitch_plan(ctx, &path, NULL, NULL, out);
        qc_path_free(ctx, &path);
        return rc;
    }
    case QC_FORMAT_QLI: rc = qc__read_qli(ctx, buf, len, out); break;
    case QC_FORMAT_DXF: rc = qc__read_dxf(ctx, buf, len, out); break;
    case QC_FORMAT_HPGL: rc = qc__read_hpgl(ctx, buf, len, out); break;
    case QC_FORMAT_QCC: rc = qc__read_qcc(ctx, buf, len, out); break;
    case QC_FORMAT_IQP: rc = qc__read_iqp(ctx, buf, len, out); break;
    case QC_FORMAT_BQM: rc = qc__read_bqm(ctx, buf, len, out); break;
    case QC_FORMAT_GCODE: rc = qc__read_gcode(ctx, buf, len, out); break;
    default:
        return qc__fail(ctx, QC_EINVAL, "read: unknown format %d", format);
    }
    if (rc != QC_OK)
        qc_plan_free(ctx, out);
    return rc;
}
