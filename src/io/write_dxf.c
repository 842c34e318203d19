/*
 * DXF R12 ASCII: a HEADER declaring millimetres ($INSUNITS 4) and one open
 * 2D POLYLINE (VERTEX ... SEQEND) per piece on layer 0, coordinates in mm
 * with 4 decimals, y up. Jumps are the gaps between polylines. CRLF.
 * When opts->region is given (and opts->dxf_outlines is not negative) its
 * rings (the block's outline, a quilt top's patches) come first, closed
 * polylines on layer OUTLINES, so long-arm software shows them apart from
 * the path and can hide them.
 */
#include "io_internal.h"

static void group(qc__out *o, int code, const char *value)
{
    if (code < 10)
        qc__out_str(o, "  ");
    else if (code < 100)
        qc__out_char(o, ' ');
    qc__out_int(o, code);
    qc__out_str(o, "\r\n");
    qc__out_str(o, value);
    qc__out_str(o, "\r\n");
}

static void coord(qc__out *o, int code, double mm)
{
    qc__out_char(o, ' ');
    qc__out_int(o, code);
    qc__out_str(o, "\r\n");
    qc__out_fixed(o, qc__mm_to_units(mm, 10000), 4, 0);
    qc__out_str(o, "\r\n");
}

static void vertex_on(qc__out *o, qc_vec2 p, const char *layer)
{
    group(o, 0, "VERTEX");
    group(o, 8, layer);
    coord(o, 10, p.x);
    coord(o, 20, p.y);
    group(o, 30, "0.0");
}

static void vertex(qc__out *o, qc_vec2 p)
{
    vertex_on(o, p, "0");
}

static void outlines(qc__out *o, const qc_region *r)
{
    size_t k, i, start = 0;

    for (k = 0; k < r->nrings; k++) {
        group(o, 0, "POLYLINE");
        group(o, 8, "OUTLINES");
        group(o, 66, "1");
        group(o, 10, "0.0");
        group(o, 20, "0.0");
        group(o, 30, "0.0");
        group(o, 70, "1"); /* closed */
        for (i = start; i < r->ring_end[k]; i++)
            vertex_on(o, r->v[i], "OUTLINES");
        group(o, 0, "SEQEND");
        group(o, 8, "OUTLINES");
        start = r->ring_end[k];
    }
}

int qc__write_dxf(qc_ctx *ctx, const qc_plan *plan, const qc_io_opts *opts,
                  qc__out *o)
{
    size_t i;

    (void)ctx;
    group(o, 0, "SECTION");
    group(o, 2, "HEADER");
    group(o, 9, "$ACADVER");
    group(o, 1, "AC1009");
    group(o, 9, "$INSUNITS");
    group(o, 70, "4");
    group(o, 9, "$MEASUREMENT");
    group(o, 70, "1");
    group(o, 0, "ENDSEC");
    group(o, 0, "SECTION");
    group(o, 2, "ENTITIES");
    if (opts->dxf_outlines >= 0 && opts->region != NULL)
        outlines(o, opts->region);
    for (i = 0; i < plan->n; i++) {
        if (i == 0 || (plan->flags[i] & QC_ST_JUMP)) {
            if (i > 0) {
                group(o, 0, "SEQEND");
                group(o, 8, "0");
            }
            group(o, 0, "POLYLINE");
            group(o, 8, "0");
            group(o, 66, "1");
            group(o, 10, "0.0");
            group(o, 20, "0.0");
            group(o, 30, "0.0");
            group(o, 70, "0");
        }
        vertex(o, plan->p[i]);
    }
    group(o, 0, "SEQEND");
    group(o, 8, "0");
    group(o, 0, "ENDSEC");
    group(o, 0, "EOF");
    return QC_OK;
}
