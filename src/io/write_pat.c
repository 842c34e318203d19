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
    char d[24]; /* the digits end at d + sizeof d */
    size_t start;
} line_no;

static void line_no_next(line_no *l)
{
    size_t i = sizeof l->d;

    while (i-- > l->start && l->d[i] == '9')
        l->d[i] = '0';
    if (i + 1 == l->start) /* every digit carried: one more */
        l->d[--l->start] = '1';
    else
        l->d[i]++;
}

int qc__write_pat(qc_ctx *ctx, const qc_plan *plan, const qc_io_opts *opts,
                  qc__out *o)
{
    int64_t px = -1, py = -1;
    line_no line;
    double lo_x = 0, lo_y = 0;
    size_t i;

    (void)opts;
    /* the rounding only grows with the coordinate: the least of each
     * decides whether any point is negative */
    for (i = 0; i < plan->n; i++) {
        lo_x = i == 0 || plan->p[i].x < lo_x ? plan->p[i].x : lo_x;
        lo_y = i == 0 || plan->p[i].y < lo_y ? plan->p[i].y : lo_y;
    }
    if (plan->n > 0 && (qc__mm_to_inch_units(lo_x, 1000) < 0 ||
                        qc__mm_to_inch_units(lo_y, 1000) < 0)) {
        i = first_negative(plan);
        return qc__fail(ctx, QC_ERANGE,
                        "pat: point %lu (%.3f, %.3f) mm is negative; move the "
                        "pattern so its bounding box starts at (0, 0)",
                        (unsigned long)i, plan->p[i].x, plan->p[i].y);
    }
    line.start = sizeof line.d - 1;
    line.d[line.start] = '1';
    for (i = 0; i < plan->n; i++) {
        int64_t x = qc__mm_to_inch_units(plan->p[i].x, 1000);
        int64_t y = qc__mm_to_inch_units(plan->p[i].y, 1000);
        char buf[128], *end = buf + sizeof buf, *s = end;

        if (x == px && y == py)
            continue;
        /* the line made backwards and written at once */
        *--s = '\n';
        *--s = '\r';
        s = qc__fmt_thousandths(s, (uint64_t)y); /* x, y >= 0: checked above */
        *--s = 'Y';
        s = qc__fmt_thousandths(s, (uint64_t)x);
        s -= 4;
        memcpy(s, i == 0 || (plan->flags[i] & QC_ST_JUMP) ? "G00X" : "G01X", 4);
        s -= sizeof line.d - line.start;
        memcpy(s, line.d + line.start, sizeof line.d - line.start);
        line_no_next(&line);
        *--s = 'N';
        qc__out_bytes(o, s, (size_t)(end - s));
        px = x;
        py = y;
    }
    qc__out_char(o, 'N');
    qc__out_bytes(o, line.d + line.start, sizeof line.d - line.start);
    qc__out_bytes(o, "M02\r\n", 5);
    return QC_OK;
}
