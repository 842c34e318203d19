/*
 * SVG path data (numbers: qc__scan_number, src/core/number.c): every command (M L H V C S Q T A Z, absolute
 * and relative), implicit repeats, numbers run together ("1.5.5", "-1-2",
 * "1e-3"), arc flags without separators ("a1 1 0 00 1 1"). Quadratics and
 * arcs become cubics. Strict: the first error stops the parse and names
 * the character and the text found there.
 */
#include <math.h>
#include <string.h>

#include "svg_internal.h"


static int is_digit(char c)
{
    return c >= '0' && c <= '9';
}

int qc__svg_skip_sep(const char *s, size_t n, size_t *pos)
{
    size_t i = *pos;
    int comma = 0;

    while (i < n && qc__is_space(s[i]))
        i++;
    if (i < n && s[i] == ',') {
        comma = 1;
        i++;
        while (i < n && qc__is_space(s[i]))
            i++;
    }
    *pos = i;
    return comma;
}

/* Up to 16 characters from s[at..n) for a message, or "end of data". */
static int excerpt_len(size_t n, size_t at)
{
    size_t k = n - at;

    return (int)(k > 16 ? 16 : k);
}

/* " (byte B)": where s[at] lies in the document, when s is an attribute
 * value without entity references (else the offset is not exact: ""). */
static const char *doc_byte(const qc__svg_where *w, const char *s, size_t at, char buf[32])
{
    size_t k;

    if (w->x != NULL)
        for (k = 0; k < w->x->nattr; k++) {
            const qc__xml_attr *a = &w->x->attr[k];

            if (a->value == s && a->raw_len == a->value_len) {
                unsigned long b = (unsigned long)(a->at + at);
                char digits[24];
                int nd = 0, i = 0;

                do {
                    digits[nd++] = (char)('0' + b % 10);
                    b /= 10;
                } while (b > 0);
                memcpy(buf, " (byte ", 7);
                i = 7;
                while (nd > 0)
                    buf[i++] = digits[--nd];
                buf[i++] = ')';
                buf[i] = '\0';
                return buf;
            }
        }
    return "";
}

int qc__svg_check_number(const qc__svg_where *w, double v, const char *s, size_t n,
                         size_t at)
{
    char b[32];

    if (fabs(v) <= QC__SVG_MAX_NUMBER)
        return QC_OK;
    return qc__fail(w->ctx, QC_ERANGE,
                    "svg line %lu, <%s %s> char %lu%s: number \"%.*s\" is beyond %g user units",
                    w->line, w->elem, w->attr, (unsigned long)at + 1, doc_byte(w, s, at, b),
                    excerpt_len(n, at), s + at, QC__SVG_MAX_NUMBER);
}

int qc__svg_syntax(const qc__svg_where *w, const char *s, size_t n, size_t at, const char *what)
{
    char b[32];

    if (at >= n)
        return qc__fail(w->ctx, QC_EFORMAT,
                        "svg line %lu, <%s %s> char %lu%s: %s, found the end of the value",
                        w->line, w->elem, w->attr, (unsigned long)at + 1, doc_byte(w, s, at, b),
                        what);
    return qc__fail(w->ctx, QC_EFORMAT, "svg line %lu, <%s %s> char %lu%s: %s, found \"%.*s\"",
                    w->line, w->elem, w->attr, (unsigned long)at + 1, doc_byte(w, s, at, b), what,
                    excerpt_len(n, at), s + at);
}

void qc__svg_sincos_deg(double deg, double *s, double *c)
{
    double q = deg / 90.0;

    if (q == floor(q) && fabs(q) < 1e15) {
        static const double sv[4] = {0, 1, 0, -1}, cv[4] = {1, 0, -1, 0};
        long long k = (long long)q % 4;

        if (k < 0)
            k += 4;
        *s = sv[k];
        *c = cv[k];
        return;
    }
    *s = qc_sin(deg * (QC_PI / 180.0));
    *c = qc_cos(deg * (QC_PI / 180.0));
}

int qc__svg_arc_to(qc_ctx *ctx, qc_path *out, qc_vec2 p0, double rx, double ry,
                   double phi_deg, int large, int sweep, qc_vec2 p1)
{
    double sn, cs, dx2, dy2, x1p, y1p, lambda, rx2, ry2, num, den, coef;
    double cxp, cyp, cx, cy, ux, uy, vx, vy, th1, dth, delta, k;
    int segs, i;

    if (p0.x == p1.x && p0.y == p1.y)
        return QC_OK;
    rx = fabs(rx);
    ry = fabs(ry);
    if (rx == 0 || ry == 0)
        return qc_path_line_to(ctx, out, p1);
    qc__svg_sincos_deg(phi_deg, &sn, &cs);
    dx2 = (p0.x - p1.x) / 2;
    dy2 = (p0.y - p1.y) / 2;
    x1p = cs * dx2 + sn * dy2;
    y1p = -sn * dx2 + cs * dy2;
    lambda = (x1p * x1p) / (rx * rx) + (y1p * y1p) / (ry * ry);
    if (lambda > 1) {
        double sl = sqrt(lambda);

        rx *= sl;
        ry *= sl;
    }
    rx2 = rx * rx;
    ry2 = ry * ry;
    num = rx2 * ry2 - rx2 * y1p * y1p - ry2 * x1p * x1p;
    den = rx2 * y1p * y1p + ry2 * x1p * x1p;
    coef = den > 0 && num > 0 ? sqrt(num / den) : 0;
    if (large == sweep)
        coef = -coef;
    cxp = coef * rx * y1p / ry;
    cyp = -coef * ry * x1p / rx;
    cx = cs * cxp - sn * cyp + (p0.x + p1.x) / 2;
    cy = sn * cxp + cs * cyp + (p0.y + p1.y) / 2;
    ux = (x1p - cxp) / rx;
    uy = (y1p - cyp) / ry;
    vx = (-x1p - cxp) / rx;
    vy = (-y1p - cyp) / ry;
    th1 = qc_atan2(uy, ux);
    dth = qc_atan2(ux * vy - uy * vx, ux * vx + uy * vy);
    if (!sweep && dth > 0)
        dth -= 2 * QC_PI;
    else if (sweep && dth < 0)
        dth += 2 * QC_PI;
    segs = (int)ceil(fabs(dth) / (QC_PI / 2) - 1e-9);
    if (segs < 1)
        segs = 1;
    if (segs > 4)
        segs = 4;
    delta = dth / segs;
    k = 4.0 / 3.0 * qc_sin(delta / 4) / qc_cos(delta / 4);
    for (i = 0; i < segs; i++) {
        double t1 = th1 + delta * i, t2 = th1 + delta * (i + 1);
        double s1 = qc_sin(t1), c1 = qc_cos(t1), s2 = qc_sin(t2), c2 = qc_cos(t2);
        double a[3][2];
        qc_vec2 q[3];
        int j;

        a[0][0] = c1 - k * s1;
        a[0][1] = s1 + k * c1;
        a[1][0] = c2 + k * s2;
        a[1][1] = s2 - k * c2;
        a[2][0] = c2;
        a[2][1] = s2;
        for (j = 0; j < 3; j++)
            q[j] = QC__V2(cx + rx * cs * a[j][0] - ry * sn * a[j][1],
                      cy + rx * sn * a[j][0] + ry * cs * a[j][1]);
        if (i == segs - 1)
            q[2] = p1; /* land exactly on the end point */
        QC__TRY(qc_path_cubic_to(ctx, out, q[0], q[1], q[2]));
    }
    return QC_OK;
}

/* ---- path data ---- */

typedef struct pstate {
    const qc__svg_where *w;
    const char *s;
    size_t n, i;
    qc_path *out;
    qc_vec2 cur, start, ctrl; /* ctrl: last cubic c2 or quadratic control */
    int pending;              /* a subpath started but nothing drawn yet */
    char prev;                /* 'C' after C/S, 'Q' after Q/T, else 0 */
} pstate;

static int number_start(const pstate *p)
{
    char c;

    if (p->i >= p->n)
        return 0;
    c = p->s[p->i];
    return is_digit(c) || c == '.' || c == '-' || c == '+';
}

static int number(pstate *p, double *v)
{
    size_t at = p->i;

    if (!qc__scan_number(p->s, p->n, &p->i, v))
        return qc__svg_syntax(p->w, p->s, p->n, at, "expected a number");
    return qc__svg_check_number(p->w, *v, p->s, p->n, at);
}

static int flag(pstate *p, double *v)
{
    if (p->i >= p->n || (p->s[p->i] != '0' && p->s[p->i] != '1'))
        return qc__svg_syntax(p->w, p->s, p->n, p->i, "expected an arc flag 0 or 1");
    *v = p->s[p->i++] == '1';
    return QC_OK;
}

static int begin(pstate *p)
{
    if (!p->pending)
        return QC_OK;
    p->pending = 0;
    return qc_path_move_to(p->w->ctx, p->out, p->start);
}

static int check_size(const pstate *p)
{
    if (p->out->npt > QC_MAX_POINTS)
        return qc__fail(p->w->ctx, QC_ELIMIT,
                        "svg line %lu, <%s %s>: more than %lu points", p->w->line,
                        p->w->elem, p->w->attr, (unsigned long)QC_MAX_POINTS);
    return QC_OK;
}

static int line(pstate *p, qc_vec2 q)
{
    QC__TRY(begin(p));
    QC__TRY(qc_path_line_to(p->w->ctx, p->out, q));
    p->cur = q;
    p->prev = 0;
    return check_size(p);
}

static int cubic(pstate *p, qc_vec2 c1, qc_vec2 c2, qc_vec2 q)
{
    QC__TRY(begin(p));
    QC__TRY(qc_path_cubic_to(p->w->ctx, p->out, c1, c2, q));
    p->cur = q;
    p->ctrl = c2;
    p->prev = 'C';
    return check_size(p);
}

static int quad(pstate *p, qc_vec2 c, qc_vec2 q)
{
    qc_vec2 c1, c2;

    c1 = QC__V2(p->cur.x + 2.0 / 3.0 * (c.x - p->cur.x), p->cur.y + 2.0 / 3.0 * (c.y - p->cur.y));
    c2 = QC__V2(q.x + 2.0 / 3.0 * (c.x - q.x), q.y + 2.0 / 3.0 * (c.y - q.y));
    QC__TRY(cubic(p, c1, c2, q));
    p->ctrl = c;
    p->prev = 'Q';
    return QC_OK;
}

static int args_of(char up)
{
    switch (up) {
    case 'M': case 'L': case 'T': return 2;
    case 'H': case 'V': return 1;
    case 'C': return 6;
    case 'S': case 'Q': return 4;
    case 'A': return 7;
    default: return 0;
    }
}

/* One command's arguments (white space or one comma between them). */
static int read_args(pstate *p, char up, double a[7])
{
    int k, na = args_of(up);

    for (k = 0; k < na; k++) {
        if (k > 0)
            qc__svg_skip_sep(p->s, p->n, &p->i);
        if (up == 'A' && (k == 3 || k == 4))
            QC__TRY(flag(p, &a[k]));
        else
            QC__TRY(number(p, &a[k]));
    }
    return QC_OK;
}

static int apply(pstate *p, char cmd, const double a[7])
{
    int rel = cmd >= 'a' && cmd <= 'z';
    char up = (char)(rel ? cmd - 'a' + 'A' : cmd);
    double ox = rel ? p->cur.x : 0, oy = rel ? p->cur.y : 0;

    switch (up) {
    case 'M':
        p->start = p->cur = QC__V2(ox + a[0], oy + a[1]);
        p->pending = 1;
        p->prev = 0;
        return QC_OK;
    case 'L':
        return line(p, QC__V2(ox + a[0], oy + a[1]));
    case 'H':
        return line(p, QC__V2(ox + a[0], p->cur.y));
    case 'V':
        return line(p, QC__V2(p->cur.x, oy + a[0]));
    case 'C':
        return cubic(p, QC__V2(ox + a[0], oy + a[1]), QC__V2(ox + a[2], oy + a[3]),
                     QC__V2(ox + a[4], oy + a[5]));
    case 'S': {
        qc_vec2 c1 = p->cur;

        if (p->prev == 'C')
            c1 = QC__V2(2 * p->cur.x - p->ctrl.x, 2 * p->cur.y - p->ctrl.y);
        return cubic(p, c1, QC__V2(ox + a[0], oy + a[1]), QC__V2(ox + a[2], oy + a[3]));
    }
    case 'Q':
        return quad(p, QC__V2(ox + a[0], oy + a[1]), QC__V2(ox + a[2], oy + a[3]));
    case 'T': {
        qc_vec2 c = p->cur;

        if (p->prev == 'Q')
            c = QC__V2(2 * p->cur.x - p->ctrl.x, 2 * p->cur.y - p->ctrl.y);
        return quad(p, c, QC__V2(ox + a[0], oy + a[1]));
    }
    case 'A': {
        qc_vec2 q = QC__V2(ox + a[5], oy + a[6]);

        QC__TRY(begin(p));
        QC__TRY(qc__svg_arc_to(p->w->ctx, p->out, p->cur, a[0], a[1], a[2], a[3] != 0,
                               a[4] != 0, q));
        p->cur = q;
        p->prev = 0;
        return check_size(p);
    }
    default: /* Z */
        if (!p->pending && (p->cur.x != p->start.x || p->cur.y != p->start.y))
            QC__TRY(qc_path_line_to(p->w->ctx, p->out, p->start));
        p->cur = p->start;
        p->pending = 1; /* a drawing command next starts a subpath here */
        p->prev = 0;
        return QC_OK;
    }
}

static int is_command(char c)
{
    return c != 0 && strchr("MmLlHhVvCcSsQqTtAaZz", c) != NULL;
}

int qc__svg_parse_path(const qc__svg_where *w, const char *d, size_t n, qc_path *out)
{
    pstate p;
    char cmd;

    memset(&p, 0, sizeof p);
    p.w = w;
    p.s = d;
    p.n = n;
    p.out = out;
    while (p.i < n && qc__is_space(d[p.i]))
        p.i++;
    if (p.i >= n)
        return QC_OK; /* empty data draws nothing */
    if (d[p.i] != 'M' && d[p.i] != 'm')
        return qc__svg_syntax(w, d, n, p.i, "path data must start with M or m");
    for (;;) {
        double a[7];
        char up;

        while (p.i < n && qc__is_space(d[p.i]))
            p.i++;
        if (p.i >= n)
            break;
        cmd = d[p.i];
        if (!is_command(cmd))
            return qc__svg_syntax(w, d, n, p.i, "expected a path command letter");
        p.i++;
        up = (char)(cmd >= 'a' ? cmd - 'a' + 'A' : cmd);
        while (p.i < n && qc__is_space(d[p.i]))
            p.i++;
        if (up == 'Z') {
            QC__TRY(apply(&p, cmd, a));
            continue;
        }
        for (;;) {
            QC__TRY(read_args(&p, up, a));
            QC__TRY(apply(&p, cmd, a));
            /* implicit repeat: more arguments follow; after M they are L */
            if (cmd == 'M')
                cmd = 'L';
            else if (cmd == 'm')
                cmd = 'l';
            if (qc__svg_skip_sep(d, n, &p.i)) {
                if (!number_start(&p))
                    return qc__svg_syntax(w, d, n, p.i, "expected a number after ','");
            } else if (!number_start(&p)) {
                break;
            }
        }
    }
    return QC_OK;
}
