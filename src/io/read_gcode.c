/*
 * G-code (.gcode, .nc) and Bernina Q-matic (.bqm): words of a letter and a
 * number, optional N line numbers, comments in parentheses or after ';'.
 * G0 is travel; G1, G2 (clockwise) and G3 arcs are sewn; modal, so a line
 * of bare X/Y repeats the motion. G20/G21 select inches/mm, G90/G91
 * absolute/relative. A pen or needle held up (Z above 0, or M5 until M3)
 * makes G1 travel too, as plotters use it. Arcs take I, J (or R): relative
 * to the start in G-code, absolute centres in BQM. M2/M30 (M02) end the
 * program; nothing but blank lines may follow.
 */
#include <math.h>
#include <string.h>

#include "read_common.h"

typedef struct gcode {
    qc__reader r;
    double unit;      /* mm per file unit */
    int relative;     /* G91 */
    int motion;       /* 0..3, or -1 before the first */
    int abs_centres;  /* BQM: I, J are absolute */
    int z_up, m_up;   /* pen up by Z > 0, by M5 */
    int ended;
} gcode;

typedef struct words {
    int has[26];
    double v[26];
    int g[8], ng; /* G words of the line, x10 (G91.1 -> 911) */
    int m[4], nm;
} words;

static int bad(gcode *c, const char *what, const char *s, size_t n)
{
    return qc__fail(c->r.ctx, QC_EFORMAT, "%s line %lu: %s, found \"%.*s\"", c->r.format,
                    c->r.where, what, (int)(n > 40 ? 40 : n), s);
}

/* Splits one line into words, comments removed. */
static int parse_words(gcode *c, const char *s, size_t n, words *w)
{
    size_t i = 0;

    memset(w, 0, sizeof *w);
    while (i < n) {
        char L = s[i];
        double v;

        if (L == ' ' || L == '\t' || L == '%') {
            i++;
            continue;
        }
        if (L == ';')
            break;
        if (L == '(') {
            while (i < n && s[i] != ')')
                i++;
            if (i == n)
                return bad(c, "a comment without ')'", s, n);
            i++;
            continue;
        }
        if (L >= 'a' && L <= 'z')
            L = (char)(L - 'a' + 'A');
        if (L < 'A' || L > 'Z')
            return bad(c, "expected a word (letter and number)", s + i, n - i);
        i++;
        if (!qc__scan_num(s, n, &i, &v))
            return bad(c, "expected a number after the letter", s, n);
        if ((L == 'G' || L == 'M') && !(v >= 0 && v < 1000))
            return bad(c, L == 'G' ? "unsupported G code" : "unsupported M code", s, n);
        if (L == 'G') {
            if (w->ng == 8)
                return bad(c, "too many G words on one line", s, n);
            w->g[w->ng++] = (int)floor(v * 10 + 0.5);
        } else if (L == 'M') {
            if (w->nm == 4)
                return bad(c, "too many M words on one line", s, n);
            w->m[w->nm++] = (int)floor(v + 0.5);
        } else {
            if (w->has[L - 'A'] && L != 'N')
                return bad(c, "a letter given twice on one line", s, n);
            w->has[L - 'A'] = 1;
            w->v[L - 'A'] = v;
        }
    }
    return QC_OK;
}

static int modes(gcode *c, const words *w, const char *s, size_t n)
{
    int k;

    for (k = 0; k < w->ng; k++) {
        switch (w->g[k]) {
        case 0: case 10: case 20: case 30:
            c->motion = w->g[k] / 10;
            break;
        case 200: c->unit = 25.4; break;
        case 210: c->unit = 1; break;
        case 900: c->relative = 0; break;
        case 910: c->relative = 1; break;
        case 901: c->abs_centres = 1; break;
        case 911: c->abs_centres = 0; break;
        case 40: case 170: case 940: case 400: case 490: case 540: case 610: case 640:
            break; /* dwell, XY plane, feed per minute, no compensation, work offset */
        default:
            return bad(c, "unsupported G code", s, n);
        }
    }
    for (k = 0; k < w->nm; k++) {
        switch (w->m[k]) {
        case 2: case 30: c->ended = 1; break;
        case 3: case 4: c->m_up = 0; break;
        case 5: c->m_up = 1; break;
        case 0: case 1: case 6: case 7: case 8: case 9: break;
        default: return bad(c, "unsupported M code", s, n);
        }
    }
    if (w->has['Z' - 'A'])
        c->z_up = w->v['Z' - 'A'] * c->unit > 0;
    return QC_OK;
}

/* The arc's centre from I/J or R; sweep CCW positive. */
static int arc(gcode *c, const words *w, qc_vec2 end, const char *s, size_t n)
{
    qc_vec2 p0 = c->r.pos, ctr;
    int cw = c->motion == 2;
    double a0, a1, sweep;

    if (w->has['R' - 'A']) {
        double dx = end.x - p0.x, dy = end.y - p0.y, d = sqrt(dx * dx + dy * dy);
        double rad = w->v['R' - 'A'] * c->unit, h2, h;

        if (!(d > 0))
            return bad(c, "an R arc needs an end point apart from its start", s, n);
        h2 = rad * rad - d * d / 4;
        if (h2 < -1e-6 * rad * rad)
            return bad(c, "an R arc whose radius is shorter than half its chord", s, n);
        h = h2 > 0 ? sqrt(h2) : 0;
        /* R > 0 takes the short way round, R < 0 the long way. */
        if ((rad > 0) == cw)
            h = -h;
        ctr = QC__V2((p0.x + end.x) / 2 - h * dy / d, (p0.y + end.y) / 2 + h * dx / d);
    } else {
        double i = w->v['I' - 'A'] * c->unit, j = w->v['J' - 'A'] * c->unit;

        ctr = c->abs_centres ? QC__V2(i, j) : QC__V2(p0.x + i, p0.y + j);
    }
    a0 = qc_atan2(p0.y - ctr.y, p0.x - ctr.x);
    a1 = qc_atan2(end.y - ctr.y, end.x - ctr.x);
    sweep = a1 - a0;
    if (cw) {
        while (sweep >= 0)
            sweep -= 2 * QC_PI;
    } else {
        while (sweep <= 0)
            sweep += 2 * QC_PI;
    }
    return qc__reader_arc(&c->r, ctr, sweep, end);
}

static int line(gcode *c, const char *s, size_t n)
{
    words w;
    qc_vec2 p;
    int moves;

    QC__TRY(parse_words(c, s, n, &w));
    if (c->ended) {
        if (w.ng || w.nm || w.has['X' - 'A'] || w.has['Y' - 'A'])
            return bad(c, "a command after the program's end (M2)", s, n);
        return QC_OK;
    }
    QC__TRY(modes(c, &w, s, n));
    moves = w.has['X' - 'A'] || w.has['Y' - 'A'];
    if (!moves)
        return QC_OK;
    if (c->motion < 0)
        return bad(c, "a move before any G0, G1, G2 or G3", s, n);
    p = c->r.pos;
    if (c->relative) {
        p.x += w.v['X' - 'A'] * c->unit;
        p.y += w.v['Y' - 'A'] * c->unit;
    } else {
        if (w.has['X' - 'A'])
            p.x = w.v['X' - 'A'] * c->unit;
        if (w.has['Y' - 'A'])
            p.y = w.v['Y' - 'A'] * c->unit;
    }
    if (c->motion == 0 || c->z_up || c->m_up)
        return qc__reader_travel(&c->r, p);
    if (c->motion == 1 || !c->r.placed)
        return qc__reader_sew(&c->r, p);
    return arc(c, &w, p, s, n);
}

static int read_program(qc_ctx *ctx, const char *buf, size_t len, qc_plan *out,
                        const char *format, double unit, int abs_centres)
{
    gcode c;
    qc__lines it;
    const char *s;
    size_t n;

    memset(&c, 0, sizeof c);
    qc__reader_init(&c.r, ctx, out, format);
    c.unit = unit;
    c.motion = -1;
    c.abs_centres = abs_centres;
    qc__lines_init(&it, buf, len);
    while (qc__lines_next(&it, &s, &n)) {
        c.r.where = it.line;
        QC__TRY(line(&c, s, n));
    }
    return qc__reader_finish(&c.r);
}

int qc__read_gcode(qc_ctx *ctx, const char *buf, size_t len, qc_plan *out)
{
    return read_program(ctx, buf, len, out, "gcode", 1, 0);
}

int qc__read_bqm(qc_ctx *ctx, const char *buf, size_t len, qc_plan *out)
{
    return read_program(ctx, buf, len, out, "bqm", 25.4, 1);
}
