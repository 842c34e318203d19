/*
 * Innova AutoPilot .pat: "N1G00X1.000Y9.008" CRLF, N consecutive from 1,
 * G00 for each piece start (JUMP), G01 otherwise, inches with exactly 3
 * decimals, y up, no header, last line "N<k>M02". Points that round to the
 * previous line's position are dropped; negative positions are refused.
 */
#include <string.h>

#include "io_internal.h"

/* The first point that rounds below 0 (there is one). */
static size_t first_negative(const qc_plan *plan)
{
    size_t i;

    for (i = 0; qc__mm_to_inch_units(plan->p[i].x, 1000) >= 0 &&
                qc__mm_to_inch_units(plan->p[i].y, 1000) >= 0;
         i++)
        ;
    return i;
}

/* The line number as text, counted up in place: no division per line. */
typedef struct line_no {
    char d[24]; /* the digits, d[0] first; copied whole, as one block */
    size_t len;
} line_no;

/* Room a line takes at most: N, the whole of line_no.d, "G00X", two
 * numbers of qc__put_thousandths, 'Y', CR LF. */
#define LINE_ROOM (1 + 24 + 4 + 24 + 1 + 24 + 2)

static void line_no_next(line_no *l)
{
    size_t i = l->len;

    while (i-- > 0 && l->d[i] == '9')
        l->d[i] = '0';
    if (i != (size_t)-1) {
        l->d[i]++;
        return;
    }
    memmove(l->d + 1, l->d, l->len++); /* every digit carried: one more */
    l->d[0] = '1';
}

int qc__write_pat(qc_ctx *ctx, const qc_plan *plan, const qc_io_opts *opts,
                  qc__out *o)
{
    int64_t px = -1, py = -1;
    line_no line;
    size_t i;

    (void)opts;
    /* the rounding only grows with the coordinate: the least of each (o->lo,
     * found as the plan was checked) decides whether any point is negative */
    if (plan->n > 0 && (qc__mm_to_inch_units(o->lo.x, 1000) < 0 ||
                        qc__mm_to_inch_units(o->lo.y, 1000) < 0)) {
        i = first_negative(plan);
        return qc__fail(ctx, QC_ERANGE,
                        "pat: point %lu (%.3f, %.3f) mm is negative; move the "
                        "pattern so its bounding box starts at (0, 0)",
                        (unsigned long)i, plan->p[i].x, plan->p[i].y);
    }
    memset(&line, 0, sizeof line);
    line.d[0] = '1';
    line.len = 1;
    for (i = 0; i < plan->n; i++) {
        int64_t x = qc__mm_to_inch_units(plan->p[i].x, 1000);
        int64_t y = qc__mm_to_inch_units(plan->p[i].y, 1000);
        char *s, *at;

        if (x == px && y == py)
            continue;
        /* the line made in place at the end of the buffer */
        s = at = qc__out_room(o, LINE_ROOM);
        *s++ = 'N';
        memcpy(s, line.d, sizeof line.d);
        s += line.len;
        memcpy(s, "G01X", 4);
        if (i == 0 || (plan->flags[i] & QC_ST_JUMP))
            s[2] = '0';
        s = qc__put_thousandths(s + 4, (uint64_t)x); /* x, y >= 0: checked above */
        *s++ = 'Y';
        s = qc__put_thousandths(s, (uint64_t)y);
        *s++ = '\r';
        *s++ = '\n';
        o->n += (size_t)(s - at);
        line_no_next(&line);
        px = x;
        py = y;
    }
    qc__out_char(o, 'N');
    qc__out_bytes(o, line.d, line.len);
    qc__out_bytes(o, "M02\r\n", 5);
    return QC_OK;
}
