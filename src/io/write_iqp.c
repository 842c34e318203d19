/*
 * IntelliQuilter .iqp (binary "StitchV2"): 8-byte magic, 8 spaces, 8 NULs,
 * then records {int32 LE type, int32 LE length, payload}: one type-7
 * coordinate record per piece (float32 LE x, y pairs in inches, y up;
 * length is half the payload's byte count), and type 2 (no length) last.
 */
#include <string.h>

#include "io_internal.h"

static void u32le(qc__out *o, uint32_t v)
{
    unsigned char b[4];

    b[0] = (unsigned char)(v & 0xff);
    b[1] = (unsigned char)((v >> 8) & 0xff);
    b[2] = (unsigned char)((v >> 16) & 0xff);
    b[3] = (unsigned char)((v >> 24) & 0xff);
    qc__out_bytes(o, b, 4);
}

static void f32le(qc__out *o, double mm)
{
    float f = (float)(mm / QC__MM_PER_IN);
    uint32_t bits;

    memcpy(&bits, &f, 4);
    u32le(o, bits);
}

int qc__write_iqp(qc_ctx *ctx, const qc_plan *plan, const qc_io_opts *opts,
                  qc__out *o)
{
    size_t i = 0, j;

    (void)opts;
    qc__out_bytes(o, "StitchV2        \0\0\0\0\0\0\0\0", 24);
    while (i < plan->n) {
        for (j = i + 1; j < plan->n && !(plan->flags[j] & QC_ST_JUMP); j++)
            ;
        if ((j - i) > 0x7fffffff / 4)
            return qc__fail(ctx, QC_ELIMIT, "iqp: a piece of %lu points is too long",
                            (unsigned long)(j - i));
        u32le(o, 7);
        u32le(o, (uint32_t)((j - i) * 4)); /* (j - i) * 8 bytes / 2 */
        for (; i < j; i++) {
            f32le(o, plan->p[i].x);
            f32le(o, plan->p[i].y);
        }
    }
    u32le(o, 2);
    return QC_OK;
}
