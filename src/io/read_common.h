/*
 * What the pattern readers (read_*.c) share: a line cursor, a locale-free
 * number scanner, and a plan builder that checks every point, tracks the
 * pen (a piece starts where the needle goes down after travel) and
 * flattens arcs the same way in every format.
 */
#ifndef QC_READ_COMMON_H
#define QC_READ_COMMON_H

#include "io_internal.h"

/* Lines of a text buffer; LF, CRLF or a lone CR end a line. */
typedef struct qc__lines {
    const char *s, *end;
    unsigned long line; /* the line last returned, 1-based */
} qc__lines;

QC__HIDDEN void qc__lines_init(qc__lines *it, const char *buf, size_t len);
/* The next line as [*ls, *ls + *n) without its terminator; 0 at the end. */
QC__HIDDEN int qc__lines_next(qc__lines *it, const char **ls, size_t *n);

/* Skips spaces and tabs at s[*pos]. */
QC__HIDDEN void qc__skip_blanks(const char *s, size_t n, size_t *pos);
/* Narrows [*s, *s + *n) to drop leading and trailing spaces and tabs. */
QC__HIDDEN void qc__trim_blanks(const char **s, size_t *n);
/* A decimal number at s[*pos] (blanks skipped first): sign, digits, point,
 * exponent; no locale, no hex, no inf/nan. 1 and *pos past it, or 0. */
QC__HIDDEN int qc__scan_num(const char *s, size_t n, size_t *pos, double *v);

/* Builds the plan one pen move at a time. */
typedef struct qc__reader {
    qc_ctx *ctx;
    qc_plan *plan;
    const char *format;  /* "qli", for messages */
    unsigned long where; /* line (or byte offset) for messages */
    const char *where_word; /* "line", or "byte" for binary formats */
    qc_vec2 pos;         /* the pen, mm */
    int placed;          /* pos was set by a move (else the first move only places it) */
    int down;            /* the needle is down at pos (a piece is open) */
} qc__reader;

QC__HIDDEN void qc__reader_init(qc__reader *r, qc_ctx *ctx, qc_plan *plan, const char *format);
/* Needle up: the next sewn move starts a new piece. */
QC__HIDDEN void qc__reader_lift(qc__reader *r);
/* Travel with the needle up to p (mm). QC_ERANGE for a bad coordinate. */
QC__HIDDEN int qc__reader_travel(qc__reader *r, qc_vec2 p);
/* A stitched line to p (mm); opens a piece at pos first if none is open.
 * The file's first move only places the needle. */
QC__HIDDEN int qc__reader_sew(qc__reader *r, qc_vec2 p);
/* A stitched arc from pos around centre c, sweep radians (CCW positive),
 * ending exactly at end; flattened within 0.05 mm. */
QC__HIDDEN int qc__reader_arc(qc__reader *r, qc_vec2 c, double sweep, qc_vec2 end);
/* The end of input: QC_EEMPTY when nothing was sewn. */
QC__HIDDEN int qc__reader_finish(qc__reader *r);

/* Format readers; out is zeroed by the caller and freed by it on error. */
QC__HIDDEN int qc__read_qli(qc_ctx *ctx, const char *buf, size_t len, qc_plan *out);
QC__HIDDEN int qc__read_hpgl(qc_ctx *ctx, const char *buf, size_t len, qc_plan *out);
QC__HIDDEN int qc__read_qcc(qc_ctx *ctx, const char *buf, size_t len, qc_plan *out);
QC__HIDDEN int qc__read_iqp(qc_ctx *ctx, const char *buf, size_t len, qc_plan *out);
QC__HIDDEN int qc__read_gcode(qc_ctx *ctx, const char *buf, size_t len, qc_plan *out);
QC__HIDDEN int qc__read_bqm(qc_ctx *ctx, const char *buf, size_t len, qc_plan *out);
QC__HIDDEN int qc__read_dxf(qc_ctx *ctx, const char *buf, size_t len, qc_plan *out);

#endif
