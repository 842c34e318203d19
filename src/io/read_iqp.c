/*
 * IntelliQuilter .iqp ("StitchV2"): an 8-byte magic and 16 header bytes,
 * then records {int32 LE type, int32 LE length, payload}: types 4 and 8
 * carry length bytes of text, type 7 one sewn piece (length / 4 pairs of
 * float32 LE x, y in inches: the payload is 2 * length bytes), type 2 (no
 * length) ends the file. Messages name the byte offset.
 */
#include <math.h>
#include <string.h>

#include "read_common.h"

#define IQP_HEADER 24

static uint32_t u32le(const unsigned char *b)
{
    return (uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 | (uint32_t)b[3] << 24;
}

static double f32le(const unsigned char *b)
{
    uint32_t bits = u32le(b);
    float f;

    memcpy(&f, &bits, 4);
    return (double)f;
}

static int bad(qc_ctx *ctx, size_t at, const char *what)
{
    return qc__fail(ctx, QC_EFORMAT, "iqp byte %lu: %s", (unsigned long)at, what);
}

static int piece(qc__reader *r, const unsigned char *p, size_t npts)
{
    size_t k;

    qc__reader_lift(r);
    for (k = 0; k < npts; k++) {
        qc_vec2 v = QC__V2(f32le(p + 8 * k) * 25.4, f32le(p + 8 * k + 4) * 25.4);

        QC__TRY(k == 0 ? qc__reader_travel(r, v) : qc__reader_sew(r, v));
    }
    return QC_OK;
}

int qc__read_iqp(qc_ctx *ctx, const char *buf, size_t len, qc_plan *out)
{
    const unsigned char *b = (const unsigned char *)buf;
    qc__reader r;
    size_t at = IQP_HEADER;

    qc__reader_init(&r, ctx, out, "iqp");
    r.where_word = "byte";
    if (len < IQP_HEADER || memcmp(buf, "StitchV2", 8) != 0)
        return bad(ctx, 0, "not an IntelliQuilter file (no StitchV2 header)");
    for (;;) {
        uint32_t type, length;
        size_t bytes;

        if (len - at < 4)
            return bad(ctx, at, "the file ends before its end record (type 2)");
        type = u32le(b + at);
        r.where = (unsigned long)at;
        if (type == 2) {
            if (len - at != 4)
                return bad(ctx, at + 4, "bytes after the end record");
            break;
        }
        if (len - at < 8)
            return bad(ctx, at, "a record without its length");
        length = u32le(b + at + 4);
        at += 8;
        if (type == 4 || type == 8) {
            bytes = length;
        } else if (type == 7) {
            if (length % 4 != 0)
                return bad(ctx, at - 4, "a coordinate record's length is not a multiple of 4");
            bytes = (size_t)length * 2;
        } else {
            return bad(ctx, at - 8, "unknown record type (expected 2, 4, 7 or 8)");
        }
        if (bytes > len - at)
            return bad(ctx, at - 4, "a record longer than the file");
        if (type == 7)
            QC__TRY(piece(&r, b + at, bytes / 8));
        at += bytes;
    }
    return qc__reader_finish(&r);
}
