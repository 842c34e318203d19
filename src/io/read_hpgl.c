/*
 * HP-GL (.plt, .hpgl): two-letter commands ended by ';' (or run together),
 * parameters separated by commas or blanks. PU and PD lift and lower the pen
 * and move through their coordinate pairs; PA and PR select absolute and
 * relative coordinates (and move when given pairs); IN resets. Units are
 * plotter units of 0.025 mm. Commands with no geometry (SP, IP, LT, VS, FS,
 * DF, EN, ...) are skipped; SC (user scaling) and LB (labels) would change
 * what the numbers mean or draw text, and are refused rather than misread.
 */
#include <string.h>

#include "read_common.h"

#define PLU_MM 0.025

static const char *const no_geometry[] = {"SP", "IP", "LT", "VS", "FS", "DF", "EN",
                                          "PG", "VA", "RO", "WU", "PW", "NR", "CO"};

typedef struct hpgl {
    qc__reader r;
    int relative;
    const char *s;
    size_t n, at;
} hpgl;

static int is_letter(char c)
{
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
}

static int bad(hpgl *h, const char *what)
{
    size_t k = h->at < h->n ? h->n - h->at : 0;

    return qc__fail(h->r.ctx, QC_EFORMAT, "hpgl line %lu: %s, found \"%.*s\"", h->r.where,
                    what, (int)(k > 30 ? 30 : k), h->s + h->at);
}

static void skip_seps(hpgl *h)
{
    while (h->at < h->n && (h->s[h->at] == ' ' || h->s[h->at] == '\t' ||
                            h->s[h->at] == ',' || h->s[h->at] == '\r' || h->s[h->at] == '\n')) {
        if (h->s[h->at] == '\n')
            h->r.where++;
        h->at++;
    }
}

/* Moves through the command's coordinate pairs, sewing when pen_down. */
static int pairs(hpgl *h, int pen_down)
{
    double x, y;

    for (;;) {
        skip_seps(h);
        if (!qc__scan_num(h->s, h->n, &h->at, &x))
            return QC_OK;
        skip_seps(h);
        if (!qc__scan_num(h->s, h->n, &h->at, &y))
            return bad(h, "expected a y coordinate");
        {
            qc_vec2 p = QC__V2(x * PLU_MM, y * PLU_MM);

            if (h->relative) {
                p.x += h->r.pos.x;
                p.y += h->r.pos.y;
            }
            QC__TRY(pen_down ? qc__reader_sew(&h->r, p) : qc__reader_travel(&h->r, p));
        }
    }
}

static int command(hpgl *h, char a, char b, int *pen_down)
{
    size_t k;

    if (a == 'P' && (b == 'U' || b == 'D')) {
        *pen_down = b == 'D';
        if (!*pen_down)
            qc__reader_lift(&h->r);
        return pairs(h, *pen_down);
    }
    if (a == 'P' && (b == 'A' || b == 'R')) {
        h->relative = b == 'R';
        return pairs(h, *pen_down);
    }
    if (a == 'I' && b == 'N') {
        h->relative = 0;
        *pen_down = 0;
        qc__reader_lift(&h->r);
        return QC_OK;
    }
    if ((a == 'S' && b == 'C') || (a == 'L' && b == 'B'))
        return bad(h, a == 'S' ? "SC (user scaling) is not supported"
                               : "LB (labels) is not supported");
    for (k = 0; k < sizeof no_geometry / sizeof no_geometry[0]; k++)
        if (a == no_geometry[k][0] && b == no_geometry[k][1]) {
            while (h->at < h->n && h->s[h->at] != ';' && !is_letter(h->s[h->at]))
                h->at++;
            return QC_OK;
        }
    h->at -= 2;
    return bad(h, "unknown command");
}

int qc__read_hpgl(qc_ctx *ctx, const char *buf, size_t len, qc_plan *out)
{
    hpgl h;
    int pen_down = 0;

    memset(&h, 0, sizeof h);
    qc__reader_init(&h.r, ctx, out, "hpgl");
    h.r.where = 1;
    h.s = buf;
    h.n = len;
    for (;;) {
        char a, b;

        while (h.at < h.n && (h.s[h.at] == ';' || h.s[h.at] == ' ' || h.s[h.at] == '\t' ||
                              h.s[h.at] == '\r' || h.s[h.at] == '\n')) {
            if (h.s[h.at] == '\n')
                h.r.where++;
            h.at++;
        }
        if (h.at >= h.n)
            break;
        if (h.at + 1 >= h.n || !is_letter(h.s[h.at]) || !is_letter(h.s[h.at + 1]))
            return bad(&h, "expected a two-letter command");
        a = (char)(h.s[h.at] & ~0x20);
        b = (char)(h.s[h.at + 1] & ~0x20);
        h.at += 2;
        QC__TRY(command(&h, a, b, &pen_down));
    }
    return qc__reader_finish(&h.r);
}
