/*
 * The pattern readers' shared parts: lines, numbers, and the pen that turns
 * travel and sewn moves into plan pieces (see read_common.h).
 */
#include <math.h>
#include <string.h>

#include "read_common.h"

#define READ_MAX_MM 1e6        /* the writers' limit, so every file read can be written */
#define ARC_TOLERANCE_MM 0.05  /* chord error of a flattened arc */
#define ARC_MAX_STEPS 100000.0 /* per arc: a 1 km radius circle needs about 9,000 */

void qc__lines_init(qc__lines *it, const char *buf, size_t len)
{
    it->s = buf;
    it->end = buf + len;
    it->line = 0;
}

int qc__lines_next(qc__lines *it, const char **ls, size_t *n)
{
    const char *p = it->s;

    if (p == NULL || p >= it->end)
        return 0;
    while (p < it->end && *p != '\n' && *p != '\r')
        p++;
    *ls = it->s;
    *n = (size_t)(p - it->s);
    if (p < it->end && *p == '\r')
        p++;
    if (p < it->end && *p == '\n')
        p++;
    it->s = p;
    it->line++;
    return 1;
}

void qc__skip_blanks(const char *s, size_t n, size_t *pos)
{
    while (*pos < n && (s[*pos] == ' ' || s[*pos] == '\t'))
        (*pos)++;
}

void qc__trim_blanks(const char **s, size_t *n)
{
    size_t i = 0;

    qc__skip_blanks(*s, *n, &i);
    *s += i;
    *n -= i;
    while (*n > 0 && ((*s)[*n - 1] == ' ' || (*s)[*n - 1] == '\t'))
        (*n)--;
}

/* Digits with at most one point, after an optional sign: G-code and HP-GL
 * have no exponents, so "X1E5" must not read as 100000. */
int qc__scan_num(const char *s, size_t n, size_t *pos, double *v)
{
    size_t i, end;
    int digits = 0, point = 0;

    qc__skip_blanks(s, n, pos);
    i = *pos;
    if (i < n && (s[i] == '+' || s[i] == '-'))
        i++;
    for (; i < n; i++) {
        if (s[i] >= '0' && s[i] <= '9')
            digits++;
        else if (s[i] == '.' && !point)
            point = 1;
        else
            break;
    }
    if (digits == 0)
        return 0;
    end = i;
    i = *pos;
    if (!qc__scan_number(s, end, &i, v) || i != end)
        return 0;
    *pos = end;
    return 1;
}

void qc__reader_init(qc__reader *r, qc_ctx *ctx, qc_plan *plan, const char *format)
{
    memset(r, 0, sizeof *r);
    r->ctx = ctx;
    r->plan = plan;
    r->format = format;
    r->where_word = "line";
}

void qc__reader_lift(qc__reader *r)
{
    r->down = 0;
}

static int check_point(qc__reader *r, qc_vec2 p)
{
    if (!(fabs(p.x) <= READ_MAX_MM && fabs(p.y) <= READ_MAX_MM))
        return qc__fail(r->ctx, QC_ERANGE,
                        "%s %s %lu: point (%g, %g) mm is not a number or beyond 1e6 mm",
                        r->format, r->where_word, r->where, p.x, p.y);
    return QC_OK;
}

static int push(qc__reader *r, qc_vec2 p, unsigned flags)
{
    if (r->plan->n >= QC_MAX_PLAN_POINTS)
        return qc__fail(r->ctx, QC_ELIMIT, "%s %s %lu: more than %lu points",
                        r->format, r->where_word, r->where, (unsigned long)QC_MAX_PLAN_POINTS);
    return qc_plan_push(r->ctx, r->plan, p, flags);
}

int qc__reader_travel(qc__reader *r, qc_vec2 p)
{
    QC__TRY(check_point(r, p));
    r->pos = p;
    r->down = 0;
    r->placed = 1;
    return QC_OK;
}

int qc__reader_sew(qc__reader *r, qc_vec2 p)
{
    QC__TRY(check_point(r, p));
    if (!r->placed) /* the file's first position is where the needle starts */
        return qc__reader_travel(r, p);
    if (!r->down) {
        QC__TRY(push(r, r->pos, QC_ST_JUMP));
        r->down = 1;
    }
    QC__TRY(push(r, p, 0));
    r->pos = p;
    return QC_OK;
}

int qc__reader_arc(qc__reader *r, qc_vec2 c, double sweep, qc_vec2 end)
{
    double dx = r->pos.x - c.x, dy = r->pos.y - c.y;
    double rad = sqrt(dx * dx + dy * dy), a0 = qc_atan2(dy, dx), step, steps;
    size_t k, n;

    QC__TRY(check_point(r, c));
    QC__TRY(check_point(r, end));
    if (!(rad > 1e-9) || !(fabs(sweep) <= 2 * QC_PI + 1e-9))
        return qc__reader_sew(r, end);
    /* The chord of angle t errs by rad * (1 - cos(t / 2)) ~ rad t^2 / 8. */
    step = rad > ARC_TOLERANCE_MM ? sqrt(8 * ARC_TOLERANCE_MM / rad) : QC_PI / 4;
    if (step > QC_PI / 4)
        step = QC_PI / 4;
    steps = ceil(fabs(sweep) / step);
    if (steps > ARC_MAX_STEPS)
        steps = ARC_MAX_STEPS;
    n = steps < 1 ? 1 : (size_t)steps;
    for (k = 1; k < n; k++) {
        double a = a0 + sweep * (double)k / (double)n;

        QC__TRY(qc__reader_sew(r, QC__V2(c.x + rad * qc_cos(a), c.y + rad * qc_sin(a))));
    }
    return qc__reader_sew(r, end);
}

int qc__reader_finish(qc__reader *r)
{
    /* A file that only places the needle is a one-point pattern, as a PAT
     * of one G00 line is (writers drop moves that round onto the last). */
    if (r->plan->n == 0 && r->placed)
        return push(r, r->pos, QC_ST_JUMP);
    if (r->plan->n == 0)
        return qc__fail(r->ctx, QC_EEMPTY, "%s: no move in the file", r->format);
    return QC_OK;
}
