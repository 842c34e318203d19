/*
 * Gammill Statler .qli: the Galil DMC subset that quilting software writes.
 * VP x,y moves to an absolute position in 0.001 in; CR r,a0,da is an arc of
 * radius r from the pen (a0 the pen's angle seen from the centre, da the
 * sweep, degrees, CCW positive); NO NEEDLE OFF / NO NEEDLE ON bracket
 * travel. Other NO and REM lines are comments, '#' lines labels, and the
 * sequence commands (CS, VM, VE, BG, AM, EN, speeds) carry no geometry.
 * Commands split at ';' as Galil allows.
 */
#include <string.h>

#include "read_common.h"

#define QLI_MM (25.4 / 1000)

/* Commands that set up or run the sequence: nothing to draw. */
static const char *const no_geometry[] = {"CS", "VM", "VE", "BG", "AM", "EN", "VS", "VA",
                                          "VD", "VT", "SH", "MO", "WT", "ST", "LM", "MG"};

static int starts(const char *s, size_t n, const char *w)
{
    size_t k = strlen(w);

    return n >= k && memcmp(s, w, k) == 0;
}

static int bad(qc__reader *r, const char *what, const char *s, size_t n)
{
    return qc__fail(r->ctx, QC_EFORMAT, "qli line %lu: %s, found \"%.*s\"", r->where,
                    what, (int)(n > 40 ? 40 : n), s);
}

/* n numbers separated by commas after the command's two letters. */
static int numbers(qc__reader *r, const char *s, size_t n, double *v, int count)
{
    size_t i = 2;
    int k;

    for (k = 0; k < count; k++) {
        if (k > 0) {
            qc__skip_blanks(s, n, &i);
            if (i >= n || s[i] != ',')
                return bad(r, "expected a comma", s, n);
            i++;
        }
        if (!qc__scan_num(s, n, &i, &v[k]))
            return bad(r, "expected a number", s, n);
    }
    qc__skip_blanks(s, n, &i);
    if (i != n)
        return bad(r, "unexpected text after the numbers", s, n);
    return QC_OK;
}

static int command(qc__reader *r, int *needle_off, const char *s, size_t n)
{
    double v[3];
    size_t k;

    if (n == 0 || s[0] == '#' || s[0] == '\'' || starts(s, n, "REM"))
        return QC_OK;
    if (starts(s, n, "NO")) {
        if (n == 13 && memcmp(s, "NO NEEDLE OFF", 13) == 0)
            *needle_off = 1;
        else if (n == 12 && memcmp(s, "NO NEEDLE ON", 12) == 0)
            *needle_off = 0;
        return QC_OK;
    }
    if (starts(s, n, "VP")) {
        qc_vec2 p;

        QC__TRY(numbers(r, s, n, v, 2));
        p = QC__V2(v[0] * QLI_MM, v[1] * QLI_MM);
        return *needle_off ? qc__reader_travel(r, p) : qc__reader_sew(r, p);
    }
    if (starts(s, n, "CR")) {
        double rad, a0, da;
        qc_vec2 c, end;

        QC__TRY(numbers(r, s, n, v, 3));
        rad = v[0] * QLI_MM;
        a0 = v[1] * QC_PI / 180;
        da = v[2] * QC_PI / 180;
        if (!(rad >= 0) || !(da >= -360.0 * QC_PI / 180 && da <= 360.0 * QC_PI / 180))
            return bad(r, "an arc needs a radius >= 0 and a sweep within 360 degrees", s, n);
        c = QC__V2(r->pos.x - rad * qc_cos(a0), r->pos.y - rad * qc_sin(a0));
        end = QC__V2(c.x + rad * qc_cos(a0 + da), c.y + rad * qc_sin(a0 + da));
        return *needle_off ? qc__reader_travel(r, end) : qc__reader_arc(r, c, da, end);
    }
    for (k = 0; k < sizeof no_geometry / sizeof no_geometry[0]; k++)
        if (starts(s, n, no_geometry[k]))
            return QC_OK;
    return bad(r, "unknown command", s, n);
}

int qc__read_qli(qc_ctx *ctx, const char *buf, size_t len, qc_plan *out)
{
    qc__lines it;
    qc__reader r;
    const char *ls;
    size_t n;
    int needle_off = 0;

    qc__lines_init(&it, buf, len);
    qc__reader_init(&r, ctx, out, "qli");
    while (qc__lines_next(&it, &ls, &n)) {
        size_t a = 0;

        r.where = it.line;
        while (a <= n) {
            size_t b = a, m;
            const char *c = ls + a;

            while (b < n && ls[b] != ';')
                b++;
            m = b - a;
            qc__trim_blanks(&c, &m);
            QC__TRY(command(&r, &needle_off, c, m));
            if (n == 0 || starts(c, (size_t)(ls + n - c), "REM"))
                break;
            a = b + 1;
        }
    }
    return qc__reader_finish(&r);
}
