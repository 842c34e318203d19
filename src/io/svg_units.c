/*
 * Lengths with units and the root viewport: the root <svg>'s width and
 * height (mm, cm, in, pt, pc, px at 96 per inch) and viewBox with
 * preserveAspectRatio give the mapping from user units to mm; y is
 * flipped so the document's bottom edge lies on y = 0.
 */
#include <math.h>
#include <string.h>

#include "svg_internal.h"

qc__svg_mat qc__svg_mat_identity(void)
{
    qc__svg_mat m = {1, 0, 0, 1, 0, 0};

    return m;
}

qc__svg_mat qc__svg_mat_mul(qc__svg_mat l, qc__svg_mat r)
{
    qc__svg_mat m;

    m.a = l.a * r.a + l.c * r.b;
    m.b = l.b * r.a + l.d * r.b;
    m.c = l.a * r.c + l.c * r.d;
    m.d = l.b * r.c + l.d * r.d;
    m.e = l.a * r.e + l.c * r.f + l.e;
    m.f = l.b * r.e + l.d * r.f + l.f;
    return m;
}

qc_vec2 qc__svg_mat_apply(const qc__svg_mat *m, qc_vec2 p)
{
    qc_vec2 q;

    q.x = m->a * p.x + m->c * p.y + m->e;
    q.y = m->b * p.x + m->d * p.y + m->f;
    return q;
}

static const struct {
    const char *name;
    double px; /* user units (px) per unit */
} units[] = {
    {"px", 1.0},         {"mm", 96.0 / 25.4}, {"cm", 96.0 / 2.54},
    {"in", 96.0},        {"pt", 96.0 / 72.0}, {"pc", 16.0},
};

int qc__svg_length(const qc__svg_where *w, const char *s, size_t n, int axis, double vp_w,
                   double vp_h, double *out)
{
    size_t i = 0, k, at;
    double v;

    while (i < n && qc__is_space(s[i]))
        i++;
    at = i;
    if (!qc__scan_number(s, n, &i, &v))
        return qc__svg_syntax(w, s, n, at, "expected a length");
    QC__TRY(qc__svg_check_number(w, v, s, n, at));
    if (i < n && s[i] == '%') {
        double ref = axis == QC__SVG_AXIS_X   ? vp_w
                     : axis == QC__SVG_AXIS_Y ? vp_h
                                              : sqrt((vp_w * vp_w + vp_h * vp_h) / 2);
        v = v / 100.0 * ref;
        i++;
    } else {
        for (k = 0; k < sizeof units / sizeof units[0]; k++)
            if (n - i >= 2 && memcmp(s + i, units[k].name, 2) == 0) {
                v *= units[k].px;
                i += 2;
                break;
            }
    }
    while (i < n && qc__is_space(s[i]))
        i++;
    if (i < n)
        return qc__svg_syntax(w, s, n, i, "expected a unit px, mm, cm, in, pt, pc or %");
    QC__TRY(qc__svg_check_number(w, v, s, n, at));
    *out = v;
    return QC_OK;
}

/* Reads a root width or height in px; *given = 0 when absent, "auto" or a
 * percentage (relative to a window we do not have). */
static int root_size(qc__svg_where *w, const qc__xml *x, const char *name, double *px,
                     int *given)
{
    const qc__xml_attr *a = qc__xml_attr_get(x, name);
    size_t i = 0;

    *given = 0;
    if (a == NULL)
        return QC_OK;
    while (i < a->value_len && qc__is_space(a->value[i]))
        i++;
    if (i == a->value_len || strcmp(a->value + i, "auto") == 0 ||
        memchr(a->value, '%', a->value_len) != NULL)
        return QC_OK;
    w->attr = name;
    QC__TRY(qc__svg_length(w, a->value, a->value_len, QC__SVG_AXIS_OTHER, 0, 0, px));
    if (!(*px > 0))
        return qc__fail(w->ctx, QC_ERANGE, "svg line %lu, <svg %s>: %g must be > 0", w->line,
                        name, *px);
    *given = 1;
    return QC_OK;
}

/* viewBox="min-x min-y width height"; *given = 0 when absent. */
static int view_box(qc__svg_where *w, const qc__xml *x, double vb[4], int *given)
{
    const qc__xml_attr *a = qc__xml_attr_get(x, "viewBox");
    const char *s;
    size_t i = 0, n, k;

    *given = 0;
    if (a == NULL)
        return QC_OK;
    s = a->value;
    n = a->value_len;
    w->attr = "viewBox";
    while (i < n && qc__is_space(s[i]))
        i++;
    for (k = 0; k < 4; k++) {
        size_t at;

        if (k > 0)
            qc__svg_skip_sep(s, n, &i);
        at = i;
        if (!qc__scan_number(s, n, &i, &vb[k]))
            return qc__svg_syntax(w, s, n, at, "expected 4 numbers");
        QC__TRY(qc__svg_check_number(w, vb[k], s, n, at));
    }
    while (i < n && qc__is_space(s[i]))
        i++;
    if (i < n)
        return qc__svg_syntax(w, s, n, i, "expected the end after 4 numbers");
    if (!(vb[2] > 0) || !(vb[3] > 0))
        return qc__fail(w->ctx, QC_ERANGE,
                        "svg line %lu, <%s viewBox>: width %g and height %g must be > 0",
                        w->line, w->elem, vb[2], vb[3]);
    *given = 1;
    return QC_OK;
}

/* The viewBox-to-viewport transform (px) per preserveAspectRatio. */
static int fit(qc__svg_where *w, const qc__xml *x, const double vb[4], double vw, double vh,
               qc__svg_mat *m)
{
    const qc__xml_attr *a = qc__xml_attr_get(x, "preserveAspectRatio");
    double sx = vw / vb[2], sy = vh / vb[3];
    int ax = 1, ay = 1, slice = 0, none = 0; /* 0 min, 1 mid, 2 max */

    if (a != NULL) {
        const char *s = a->value;
        size_t n = a->value_len, i = 0, j;

        w->attr = "preserveAspectRatio";
        while (i < n && qc__is_space(s[i]))
            i++;
        if (n - i >= 5 && memcmp(s + i, "defer", 5) == 0)
            for (i += 5; i < n && qc__is_space(s[i]); i++)
                ;
        j = i;
        while (j < n && !qc__is_space(s[j]))
            j++;
        if (j - i == 4 && memcmp(s + i, "none", 4) == 0) {
            none = 1;
        } else if (j - i == 8 && s[i] == 'x' && s[i + 4] == 'Y') {
            static const char *const pos[3] = {"Min", "Mid", "Max"};
            int k;

            ax = ay = -1;
            for (k = 0; k < 3; k++) {
                if (memcmp(s + i + 1, pos[k], 3) == 0)
                    ax = k;
                if (memcmp(s + i + 5, pos[k], 3) == 0)
                    ay = k;
            }
            if (ax < 0 || ay < 0)
                return qc__svg_syntax(w, s, n, i, "expected none or xMinYMin ... xMaxYMax");
        } else {
            return qc__svg_syntax(w, s, n, i, "expected none or xMinYMin ... xMaxYMax");
        }
        for (i = j; i < n && qc__is_space(s[i]); i++)
            ;
        j = i;
        while (j < n && !qc__is_space(s[j]))
            j++;
        if (j - i == 5 && memcmp(s + i, "slice", 5) == 0)
            slice = 1;
        else if (!(j - i == 4 && memcmp(s + i, "meet", 4) == 0) && j > i)
            return qc__svg_syntax(w, s, n, i, "expected meet or slice");
        for (i = j; i < n && qc__is_space(s[i]); i++)
            ;
        if (i < n)
            return qc__svg_syntax(w, s, n, i, "unexpected text");
    }
    if (!none) {
        double sc = slice ? (sx > sy ? sx : sy) : (sx < sy ? sx : sy);

        sx = sy = sc;
    }
    m->a = sx;
    m->b = 0;
    m->c = 0;
    m->d = sy;
    m->e = -vb[0] * sx + (vw - vb[2] * sx) * (none ? 0 : ax) / 2;
    m->f = -vb[1] * sy + (vh - vb[3] * sy) * (none ? 0 : ay) / 2;
    return QC_OK;
}

/* quiltc's previews record where the plan's (0, 0) lies on the page
 * (data-quiltc-origin-mm="X Y", mm from the bottom-left corner, y up), so
 * reading one back gives the plan's own coordinates, not the page's. */
static int frame_origin(qc__svg_where *w, const qc__xml *x, qc__svg_mat *m)
{
    const qc__xml_attr *a = qc__xml_attr_get(x, "data-quiltc-origin-mm");
    const char *s;
    size_t n, i = 0, k, at;
    double o[2];

    if (a == NULL)
        return QC_OK;
    s = a->value;
    n = a->value_len;
    w->attr = "data-quiltc-origin-mm";
    while (i < n && qc__is_space(s[i]))
        i++;
    for (k = 0; k < 2; k++) {
        if (k > 0)
            qc__svg_skip_sep(s, n, &i);
        at = i;
        if (!qc__scan_number(s, n, &i, &o[k]))
            return qc__svg_syntax(w, s, n, at, "expected a number");
        if (!(fabs(o[k]) <= QC__SVG_MAX_MM))
            return qc__fail(w->ctx, QC_ERANGE, "svg line %lu, <svg data-quiltc-origin-mm>: "
                            "%g mm is beyond %g mm", w->line, o[k], QC__SVG_MAX_MM);
    }
    while (i < n && qc__is_space(s[i]))
        i++;
    if (i < n)
        return qc__svg_syntax(w, s, n, i, "expected the end after two numbers");
    m->e -= o[0];
    m->f -= o[1];
    return QC_OK;
}

int qc__svg_root_viewport(const qc__svg_where *where, const qc__xml *x, qc__svg_mat *m,
                          double *vp_w, double *vp_h)
{
    qc__svg_where w = *where;
    qc__svg_mat to_px = qc__svg_mat_identity(), to_mm;
    double vb[4] = {0, 0, 0, 0}, pw = 0, ph = 0, height_mm;
    int has_vb, has_w, has_h;

    QC__TRY(root_size(&w, x, "width", &pw, &has_w));
    QC__TRY(root_size(&w, x, "height", &ph, &has_h));
    QC__TRY(view_box(&w, x, vb, &has_vb));
    if (has_vb) {
        /* a missing side follows the viewBox's aspect ratio */
        if (!has_w && !has_h) {
            pw = vb[2];
            ph = vb[3];
        } else if (!has_w) {
            pw = ph * vb[2] / vb[3];
        } else if (!has_h) {
            ph = pw * vb[3] / vb[2];
        }
        QC__TRY(fit(&w, x, vb, pw, ph, &to_px));
        *vp_w = vb[2];
        *vp_h = vb[3];
        height_mm = ph * QC__SVG_PX_MM;
    } else {
        /* without a viewBox one user unit is one px whatever width says */
        *vp_w = has_w ? pw : 0;
        *vp_h = has_h ? ph : 0;
        height_mm = has_h ? ph * QC__SVG_PX_MM : 0;
    }
    /* px -> mm, y flipped about the document's height */
    to_mm.a = QC__SVG_PX_MM;
    to_mm.b = 0;
    to_mm.c = 0;
    to_mm.d = -QC__SVG_PX_MM;
    to_mm.e = 0;
    to_mm.f = height_mm;
    *m = qc__svg_mat_mul(to_mm, to_px);
    return frame_origin(&w, x, m);
}

int qc__svg_nested_viewport(const qc__svg_where *where, const qc__xml *x, double vp_w,
                            double vp_h, qc__svg_mat *m)
{
    static const char *const names[4] = {"x", "y", "width", "height"};
    static const int axes[4] = {QC__SVG_AXIS_X, QC__SVG_AXIS_Y, QC__SVG_AXIS_X,
                                QC__SVG_AXIS_Y};
    qc__svg_where w = *where;
    double v[4] = {0, 0, 0, 0}, vb[4];
    int has[4] = {0, 0, 0, 0}, has_vb, k;
    qc__svg_mat t = qc__svg_mat_identity(), f = qc__svg_mat_identity();

    for (k = 0; k < 4; k++) {
        const qc__xml_attr *a = qc__xml_attr_get(x, names[k]);

        if (a == NULL)
            continue;
        w.attr = names[k];
        QC__TRY(qc__svg_length(&w, a->value, a->value_len, axes[k], vp_w, vp_h, &v[k]));
        has[k] = 1;
    }
    QC__TRY(view_box(&w, x, vb, &has_vb));
    t.e = v[0];
    t.f = v[1];
    if (has_vb) {
        /* width and height default to 100% of the enclosing viewport */
        double vw = has[2] ? v[2] : vp_w > 0 ? vp_w : vb[2];
        double vh = has[3] ? v[3] : vp_h > 0 ? vp_h : vb[3];

        if (!(vw > 0) || !(vh > 0))
            return qc__fail(w.ctx, QC_ERANGE,
                            "svg line %lu, <svg>: nested viewport %g x %g must be > 0",
                            w.line, vw, vh);
        QC__TRY(fit(&w, x, vb, vw, vh, &f));
    }
    *m = qc__svg_mat_mul(t, f);
    return QC_OK;
}
