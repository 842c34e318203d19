/*
 * DXF (ASCII, R12 and later): group-code/value line pairs. The drawing is
 * the ENTITIES section: POLYLINE with its VERTEX list, LWPOLYLINE (bulges
 * are arcs), LINE, ARC, CIRCLE, ELLIPSE and SPLINE (control points, knots,
 * weights). Each entity is a piece, joined to the one before without a jump
 * when it starts where that one ended. Units come from $INSUNITS; a
 * drawing without them (0, unitless) is in inches or mm as its
 * $MEASUREMENT says (0 imperial, 1 metric: AutoCAD's own fallback), else
 * in mm. A SPLINE of fit points only is the cubic through them that CAD
 * programs draw (chord-length parameters, its end tangents when given,
 * else no curvature at the ends). Entities with no stitch line (TEXT,
 * POINT, HATCH, DIMENSION, ...) are skipped, BLOCKS too, and so is layer
 * OUTLINES (the block and patch outlines quiltc draws beside the path);
 * INSERT (a block reference) is refused rather than misread.
 */
#include <math.h>
#include <string.h>

#include "read_common.h"

#define DXF_MAX_SAMPLES 100000.0 /* per curve */
#define DXF_STEP_MM 0.5          /* spline sampling along its control polygon */

typedef struct dxf_vert {
    double x, y, bulge;
} dxf_vert;

typedef struct dxf {
    qc__reader r;
    qc__lines it;
    int code;           /* the current group */
    const char *val;
    size_t nval;
    double unit;        /* mm per drawing unit */
    double insunits_mm; /* mm per unit from $INSUNITS; 0: unitless or not given */
    int measurement;    /* $MEASUREMENT: 0 imperial, 1 metric, -1 not given */
    /* the entity being read */
    char type[16];
    double g[100];      /* last value of each single group code < 100 */
    int has[100];
    int flags;
    dxf_vert *v;        /* polyline vertices, or spline control points (bulge = weight) */
    size_t nv, v_cap;
    double *knots;
    size_t nk, k_cap;
    double *w;          /* spline weights (group 41, before or after the points) */
    size_t nw, w_cap;
    dxf_vert *fit;      /* spline fit points (groups 11/21) */
    size_t nfit, fit_cap;
    int mirrored;       /* extrusion z < 0 (group 230) */
    int in_polyline;    /* between POLYLINE and SEQEND */
    int poly_mirrored;
    int poly_closed;
    int outline;        /* the entity is on layer OUTLINES: drawn, not sewn */
    int poly_outline;
} dxf;

static int bad(dxf *d, const char *what)
{
    return qc__fail(d->r.ctx, QC_EFORMAT, "dxf line %lu: %s, found \"%.*s\"", d->r.where, what,
                    (int)(d->nval > 40 ? 40 : d->nval), d->val);
}

/* The next group; 0 at the end of input. */
static int next_group(dxf *d)
{
    const char *s;
    size_t n, i = 0;
    double c;

    if (!qc__lines_next(&d->it, &s, &n))
        return 0;
    d->r.where = d->it.line;
    d->val = s;
    d->nval = n;
    if (!qc__scan_num(s, n, &i, &c) || (qc__skip_blanks(s, n, &i), i != n) || c != floor(c) ||
        c < 0 || c > 1071)
        return bad(d, "expected a group code"), -1;
    d->code = (int)c;
    if (!qc__lines_next(&d->it, &s, &n))
        return bad(d, "a group code without its value"), -1;
    qc__trim_blanks(&s, &n);
    d->val = s;
    d->nval = n;
    d->r.where = d->it.line;
    return 1;
}

static int is(const dxf *d, const char *w)
{
    return d->nval == strlen(w) && memcmp(d->val, w, d->nval) == 0;
}

/* A real value; DXF writes exponents ("1.5E+02"), decoded without libm. */
static int number(dxf *d, double *v)
{
    size_t i = 0;

    if (!qc__scan_number(d->val, d->nval, &i, v) || i != d->nval || !(fabs(*v) <= 1e300))
        return bad(d, "expected a number");
    return QC_OK;
}

static int push_vert(dxf *d, double x, double y, double b)
{
    QC__TRY(QC__RESERVE(d->r.ctx, d->v, d->v_cap, d->nv + 1));
    d->v[d->nv].x = x;
    d->v[d->nv].y = y;
    d->v[d->nv].bulge = b;
    d->nv++;
    return QC_OK;
}

static qc_vec2 mm(const dxf *d, double x, double y)
{
    return QC__V2(x * d->unit, y * d->unit);
}

/* 2D entities (ARC, CIRCLE, polylines) are in their object coordinate
 * system: with the extrusion (0, 0, -1) that CAD programs write for
 * mirrored shapes, its x axis is the world's -x. */
static qc_vec2 ocs(const dxf *d, double x, double y)
{
    return mm(d, d->mirrored ? -x : x, y);
}

/* Moves to p: continues the open piece when it ended there, else travels. */
static int start_at(dxf *d, qc_vec2 p)
{
    if (d->r.down && fabs(p.x - d->r.pos.x) <= 1e-9 && fabs(p.y - d->r.pos.y) <= 1e-9)
        return QC_OK;
    return qc__reader_travel(&d->r, p);
}

/* The arc from a to b with DXF bulge tan(sweep / 4). */
static int bulge_to(dxf *d, qc_vec2 a, qc_vec2 b, double bulge)
{
    double dx = b.x - a.x, dy = b.y - a.y, c = sqrt(dx * dx + dy * dy), off;

    if (fabs(bulge) < 1e-12 || !(c > 0))
        return qc__reader_sew(&d->r, b);
    off = (1 - bulge * bulge) / (4 * bulge); /* centre offset / chord, to the left */
    return qc__reader_arc(&d->r, QC__V2((a.x + b.x) / 2 - dy * off, (a.y + b.y) / 2 + dx * off),
                          4 * qc_atan2(bulge, 1), b);
}

static int emit_polyline(dxf *d, int closed)
{
    size_t k;

    if (d->nv == 0)
        return QC_OK;
    QC__TRY(start_at(d, ocs(d, d->v[0].x, d->v[0].y)));
    for (k = 1; k < d->nv + (closed ? 1u : 0u); k++) {
        const dxf_vert *a = &d->v[k - 1], *b = &d->v[k % d->nv];

        QC__TRY(bulge_to(d, ocs(d, a->x, a->y), ocs(d, b->x, b->y),
                         d->mirrored ? -a->bulge : a->bulge));
    }
    if (d->nv == 1)
        return qc__reader_sew(&d->r, ocs(d, d->v[0].x, d->v[0].y));
    return QC_OK;
}

/* A CCW sweep brought into (0, 2 pi]; fmod is exact, so huge angles from a
 * hostile file cost nothing. */
static double sweep_in_turn(double sweep)
{
    sweep = fmod(sweep, 2 * QC_PI);
    return sweep <= 0 ? sweep + 2 * QC_PI : sweep;
}

/* ARC and CIRCLE: centre 10/20, radius 40, angles 50/51 in degrees. */
static int emit_arc(dxf *d, int circle)
{
    qc_vec2 c = ocs(d, d->g[10], d->g[20]);
    double r = d->g[40] * d->unit, a0 = circle ? 0 : d->g[50] * QC_PI / 180;
    double sweep = circle ? 2 * QC_PI : (d->g[51] - d->g[50]) * QC_PI / 180;

    if (!(r > 0) || !(fabs(d->g[50]) <= 1e6 && fabs(d->g[51]) <= 1e6))
        return bad(d, "an arc or circle needs a radius > 0 and angles within 1e6 degrees");
    sweep = sweep_in_turn(sweep);
    if (d->mirrored) { /* the world sees the OCS arc mirrored in x */
        a0 = QC_PI - a0;
        sweep = -sweep;
    }
    QC__TRY(start_at(d, QC__V2(c.x + r * qc_cos(a0), c.y + r * qc_sin(a0))));
    return qc__reader_arc(&d->r, c, sweep,
                          QC__V2(c.x + r * qc_cos(a0 + sweep), c.y + r * qc_sin(a0 + sweep)));
}

/* ELLIPSE: centre 10/20, major axis end 11/21 (from the centre), ratio 40,
 * parameters 41..42 (radians). */
static int emit_ellipse(dxf *d)
{
    qc_vec2 c = mm(d, d->g[10], d->g[20]), M = mm(d, d->g[11], d->g[21]), N;
    double k = d->g[40], t0 = d->has[41] ? d->g[41] : 0, t1 = d->has[42] ? d->g[42] : 2 * QC_PI;
    double a = sqrt(M.x * M.x + M.y * M.y), sweep = t1 - t0, step, steps;
    size_t i, n;

    if (!(a > 0) || !(k > 0 && k <= 1) || !(fabs(t0) <= 1e6 && fabs(t1) <= 1e6))
        return bad(d, "an ellipse needs a major axis and a ratio in (0, 1]");
    N = QC__V2(-M.y * k, M.x * k);
    sweep = sweep_in_turn(sweep);
    step = sqrt(8 * 0.05 / a);
    if (step > QC_PI / 8)
        step = QC_PI / 8;
    steps = ceil(sweep / step);
    n = steps > DXF_MAX_SAMPLES ? (size_t)DXF_MAX_SAMPLES : (size_t)steps;
    for (i = 0; i <= n; i++) {
        double t = t0 + sweep * (double)i / (double)n;
        qc_vec2 p = QC__V2(c.x + M.x * qc_cos(t) + N.x * qc_sin(t),
                           c.y + M.y * qc_cos(t) + N.y * qc_sin(t));

        QC__TRY(i == 0 ? start_at(d, p) : qc__reader_sew(&d->r, p));
    }
    return QC_OK;
}

/* A point of the B-spline at u by de Boor's algorithm, in homogeneous
 * coordinates (weights in bulge). span: U[span] <= u < U[span + 1]. */
static qc_vec2 de_boor(const dxf *d, int p, size_t span, double u, double *tmp)
{
    int j, r;

    for (j = 0; j <= p; j++) {
        const dxf_vert *v = &d->v[span - (size_t)p + (size_t)j];

        tmp[3 * j] = v->x * v->bulge;
        tmp[3 * j + 1] = v->y * v->bulge;
        tmp[3 * j + 2] = v->bulge;
    }
    for (r = 1; r <= p; r++)
        for (j = p; j >= r; j--) {
            size_t i = span - (size_t)p + (size_t)j;
            double den = d->knots[i + (size_t)p + 1 - (size_t)r] - d->knots[i];
            double al = den > 0 ? (u - d->knots[i]) / den : 0;
            int q;

            for (q = 0; q < 3; q++)
                tmp[3 * j + q] = (1 - al) * tmp[3 * (j - 1) + q] + al * tmp[3 * j + q];
        }
    return mm(d, tmp[3 * p] / tmp[3 * p + 2], tmp[3 * p + 1] / tmp[3 * p + 2]);
}

/* Second derivatives m[0..n] of the cubic spline through (s[i], y[i]):
 * its first derivative at an end is d0 / d1 where has0 / has1, else its
 * second derivative there is 0. Thomas' algorithm; c is scratch. */
static void spline_moments(const double *s, const double *y, size_t n, int has0, double d0,
                           int has1, double d1, double *m, double *c)
{
    size_t i;
    double b0 = has0 ? (s[1] - s[0]) / 3 : 1, r0 = has0 ? (y[1] - y[0]) / (s[1] - s[0]) - d0 : 0;

    /* row i: h[i-1] m[i-1] / 6 + (h[i-1] + h[i]) m[i] / 3 + h[i] m[i+1] / 6 = r[i] */
    c[0] = has0 ? (s[1] - s[0]) / 6 / b0 : 0;
    m[0] = r0 / b0;
    for (i = 1; i <= n; i++) {
        double hl = s[i] - s[i - 1], hr = i < n ? s[i + 1] - s[i] : 0, a = hl / 6, b, r;

        if (i < n) {
            b = (hl + hr) / 3;
            r = (y[i + 1] - y[i]) / hr - (y[i] - y[i - 1]) / hl;
        } else if (has1) {
            b = hl / 3;
            r = d1 - (y[n] - y[n - 1]) / hl;
        } else {
            a = 0;
            b = 1;
            r = 0;
        }
        b -= a * c[i - 1];
        c[i] = i < n ? hr / 6 / b : 0;
        m[i] = (r - a * m[i - 1]) / b;
    }
    for (i = n; i-- > 0;)
        m[i] -= c[i] * m[i + 1];
}

/* A SPLINE given by fit points only: the cubic through them, in chord
 * length, as CAD programs draw it (their end tangents, groups 12/22 and
 * 13/23, when given; else zero curvature at the ends). */
static int emit_fit_spline(dxf *d)
{
    size_t n = 0, i, k, steps;
    double *buf, *s, *x, *y, *mx, *my, *c, t0x = d->g[12], t0y = d->g[22];
    double t1x = d->g[13], t1y = d->g[23], l0 = sqrt(t0x * t0x + t0y * t0y);
    double l1 = sqrt(t1x * t1x + t1y * t1y);
    int has0 = d->has[12] && l0 > 0, has1 = d->has[13] && l1 > 0, rc = QC_OK;

    if (d->nfit < 2)
        return bad(d, "a SPLINE needs control points, or two or more fit points");
    if ((buf = (double *)qc__alloc_array(d->r.ctx, d->nfit, 7 * sizeof *buf)) == NULL)
        return QC_ENOMEM;
    s = buf;
    x = s + d->nfit;
    y = x + d->nfit;
    mx = y + d->nfit;
    my = mx + d->nfit;
    c = my + d->nfit;
    for (i = 0; i < d->nfit; i++) { /* repeated points add nothing */
        double h = n ? sqrt((d->fit[i].x - x[n - 1]) * (d->fit[i].x - x[n - 1]) +
                            (d->fit[i].y - y[n - 1]) * (d->fit[i].y - y[n - 1]))
                     : 0;

        if (n && !(h > 0))
            continue;
        s[n] = n ? s[n - 1] + h : 0;
        x[n] = d->fit[i].x;
        y[n++] = d->fit[i].y;
    }
    if (n < 2) {
        qc__free(d->r.ctx, buf, d->nfit * 7 * sizeof *buf);
        return start_at(d, mm(d, x[0], y[0]));
    }
    n--;
    spline_moments(s, x, n, has0, t0x / l0, has1, t1x / l1, mx, c);
    spline_moments(s, y, n, has0, t0y / l0, has1, t1y / l1, my, c);
    rc = start_at(d, mm(d, x[0], y[0]));
    for (i = 0; i < n && rc == QC_OK; i++) {
        double h = s[i + 1] - s[i], st = ceil(h * d->unit / DXF_STEP_MM) + 8;

        steps = st > DXF_MAX_SAMPLES ? (size_t)DXF_MAX_SAMPLES : (size_t)st;
        for (k = 1; k <= steps && rc == QC_OK; k++) {
            double b = (double)k / (double)steps, a = 1 - b, e = h * h / 6;
            double px = a * x[i] + b * x[i + 1] + ((a * a * a - a) * mx[i] + (b * b * b - b) * mx[i + 1]) * e;
            double py = a * y[i] + b * y[i + 1] + ((a * a * a - a) * my[i] + (b * b * b - b) * my[i + 1]) * e;

            rc = qc__reader_sew(&d->r, mm(d, px, py));
        }
    }
    qc__free(d->r.ctx, buf, d->nfit * 7 * sizeof *buf);
    return rc;
}

static int emit_spline(dxf *d)
{
    int p = d->has[71] && d->g[71] >= 1 && d->g[71] <= 11 ? (int)d->g[71] : d->has[71] ? 0 : 3;
    double tmp[3 * 12], len = 0, u0, u1, steps;
    size_t k, n, span;

    if (d->nv == 0)
        return emit_fit_spline(d);
    if (p < 1 || p > 11 || d->nk != d->nv + (size_t)p + 1)
        return bad(d, "a SPLINE needs degree 1..11 and control points + degree + 1 knots");
    for (k = 1; k < d->nk; k++)
        if (!(d->knots[k] >= d->knots[k - 1]))
            return bad(d, "a SPLINE's knots must not decrease");
    if (d->nw != 0 && d->nw != d->nv)
        return bad(d, "a SPLINE needs one weight per control point, or none");
    for (k = 0; k < d->nw; k++) {
        if (!(d->w[k] > 0))
            return bad(d, "a SPLINE's weights must be > 0");
        d->v[k].bulge = d->w[k];
    }
    for (k = 1; k < d->nv; k++) {
        double dx = d->v[k].x - d->v[k - 1].x, dy = d->v[k].y - d->v[k - 1].y;

        len += sqrt(dx * dx + dy * dy) * d->unit; /* not hypot: libm's differs by platform */
    }
    u0 = d->knots[p];
    u1 = d->knots[d->nv];
    if (!(u1 > u0))
        return bad(d, "a SPLINE's knots span nothing");
    steps = ceil(len / DXF_STEP_MM) + 8.0 * (double)d->nv;
    n = steps > DXF_MAX_SAMPLES ? (size_t)DXF_MAX_SAMPLES : (size_t)steps;
    span = (size_t)p;
    for (k = 0; k <= n; k++) {
        double u = k == n ? u1 : u0 + (u1 - u0) * (double)k / (double)n;
        qc_vec2 pt;

        while (span + 1 < d->nv && d->knots[span + 1] <= u)
            span++;
        pt = de_boor(d, p, span, u, tmp);
        QC__TRY(k == 0 ? start_at(d, pt) : qc__reader_sew(&d->r, pt));
    }
    return QC_OK;
}

/* Draws the entity just read (its groups are in d). */
static int finish_entity(dxf *d)
{
    const char *t = d->type;

    if (d->outline && strcmp(t, "POLYLINE") != 0 && strcmp(t, "VERTEX") != 0 &&
        strcmp(t, "SEQEND") != 0)
        return QC_OK;
    if (strcmp(t, "LINE") == 0) {
        QC__TRY(start_at(d, mm(d, d->g[10], d->g[20])));
        return qc__reader_sew(&d->r, mm(d, d->g[11], d->g[21]));
    }
    if (strcmp(t, "LWPOLYLINE") == 0)
        return emit_polyline(d, d->flags & 1);
    if (strcmp(t, "POLYLINE") == 0) {
        if (d->flags & (16 | 64))
            return bad(d, "polygon meshes and polyface meshes are not supported");
        d->in_polyline = 1;
        d->poly_closed = d->flags & 1;
        d->poly_mirrored = d->mirrored;
        d->poly_outline = d->outline;
        d->nv = 0;
        return QC_OK;
    }
    if (strcmp(t, "VERTEX") == 0) {
        if (!d->in_polyline)
            return bad(d, "a VERTEX outside a POLYLINE");
        if (d->flags & 16) /* a spline frame's control point: not on the curve */
            return QC_OK;
        return push_vert(d, d->g[10], d->g[20], d->g[42]);
    }
    if (strcmp(t, "SEQEND") == 0) {
        int closed = d->poly_closed;

        if (!d->in_polyline)
            return QC_OK;
        d->in_polyline = 0;
        d->mirrored = d->poly_mirrored; /* vertices follow their POLYLINE's system */
        return d->poly_outline ? QC_OK : emit_polyline(d, closed);
    }
    if (strcmp(t, "ARC") == 0 || strcmp(t, "CIRCLE") == 0)
        return emit_arc(d, t[0] == 'C');
    if (strcmp(t, "ELLIPSE") == 0)
        return emit_ellipse(d);
    if (strcmp(t, "SPLINE") == 0)
        return emit_spline(d);
    if (strcmp(t, "INSERT") == 0)
        return bad(d, "INSERT (a block reference) is not supported: explode the blocks first");
    return QC_OK;
}

/* One group of an entity. Vertex lists and knots repeat codes. */
static int entity_group(dxf *d)
{
    double v;
    int lw = strcmp(d->type, "LWPOLYLINE") == 0, sp = strcmp(d->type, "SPLINE") == 0;

    if (d->code == 230) {
        QC__TRY(number(d, &v));
        d->mirrored = v < 0;
        return QC_OK;
    }
    if (d->code == 8) {
        d->outline = is(d, "OUTLINES");
        return QC_OK;
    }
    if (d->code >= 100 || (d->code >= 1 && d->code <= 9))
        return QC_OK; /* handles, names, other layers, subclass markers */
    if (d->code >= 60 && d->code < 80) {
        QC__TRY(number(d, &v));
        if (!(fabs(v) <= 2147483647.0) || v != floor(v))
            return bad(d, "expected an integer");
        if (d->code == 70)
            d->flags = (int)v;
        d->g[d->code] = v;
        d->has[d->code] = 1;
        return QC_OK;
    }
    QC__TRY(number(d, &v));
    if ((lw || sp) && d->code == 10) {
        QC__TRY(push_vert(d, v, 0, lw ? 0 : 1));
    } else if ((lw || sp) && d->code == 20 && d->nv > 0) {
        d->v[d->nv - 1].y = v;
    } else if (lw && d->code == 42 && d->nv > 0) {
        d->v[d->nv - 1].bulge = v;
    } else if (sp && d->code == 11) {
        QC__TRY(QC__RESERVE(d->r.ctx, d->fit, d->fit_cap, d->nfit + 1));
        d->fit[d->nfit].x = v;
        d->fit[d->nfit].y = 0;
        d->fit[d->nfit++].bulge = 0;
    } else if (sp && d->code == 21 && d->nfit > 0) {
        d->fit[d->nfit - 1].y = v;
    } else if (sp && d->code == 40) {
        QC__TRY(QC__RESERVE(d->r.ctx, d->knots, d->k_cap, d->nk + 1));
        d->knots[d->nk++] = v;
    } else if (sp && d->code == 41) {
        QC__TRY(QC__RESERVE(d->r.ctx, d->w, d->w_cap, d->nw + 1));
        d->w[d->nw++] = v;
        return QC_OK;
    }
    if (d->code < 100) {
        d->g[d->code] = v;
        d->has[d->code] = 1;
    }
    return QC_OK;
}

static void begin_entity(dxf *d)
{
    size_t n = d->nval < sizeof d->type - 1 ? d->nval : sizeof d->type - 1;

    memcpy(d->type, d->val, n);
    d->type[n] = '\0';
    memset(d->g, 0, sizeof d->g);
    memset(d->has, 0, sizeof d->has);
    d->flags = 0;
    d->mirrored = 0;
    d->outline = 0;
    if (!d->in_polyline || strcmp(d->type, "VERTEX") != 0)
        if (strcmp(d->type, "SEQEND") != 0)
            d->nv = 0;
    d->nk = 0;
    d->nw = 0;
    d->nfit = 0;
}

static int header_units(dxf *d)
{
    static const double per_unit[] = {0, 25.4, 304.8, 0, 1, 10, 1000};
    double v;

    if (next_group(d) != 1 || d->code != 70)
        return bad(d, "$INSUNITS without its value (group 70)");
    QC__TRY(number(d, &v));
    if (v != floor(v) || v < 0 || v > 6 || v == 3)
        return bad(d, "$INSUNITS other than unitless, in, ft, mm, cm or m");
    d->insunits_mm = per_unit[(int)v];
    return QC_OK;
}

static int header_measurement(dxf *d)
{
    double v;

    if (next_group(d) != 1 || d->code != 70)
        return bad(d, "$MEASUREMENT without its value (group 70)");
    QC__TRY(number(d, &v));
    if (v != 0 && v != 1)
        return bad(d, "$MEASUREMENT other than 0 (imperial) or 1 (metric)");
    d->measurement = (int)v;
    return QC_OK;
}

/* The drawing's unit once the header is read (it may name either first). */
static void settle_units(dxf *d)
{
    d->unit = d->insunits_mm > 0 ? d->insunits_mm : d->measurement == 0 ? 25.4 : 1.0;
}

static int read_all(dxf *d)
{
    int section = 0; /* 1 HEADER, 2 ENTITIES, 3 other */
    int in_entity = 0, g;

    while ((g = next_group(d)) == 1) {
        if (d->code == 0 && in_entity) {
            QC__TRY(finish_entity(d));
            in_entity = 0;
        }
        if (d->code == 0 && is(d, "SECTION")) {
            if (next_group(d) != 1 || d->code != 2)
                return bad(d, "a SECTION without its name (group 2)");
            section = is(d, "HEADER") ? 1 : is(d, "ENTITIES") ? 2 : 3;
            if (section == 2)
                settle_units(d);
        } else if (d->code == 0 && is(d, "ENDSEC")) {
            if (section == 2 && d->in_polyline)
                return bad(d, "a POLYLINE without its SEQEND");
            section = 0;
        } else if (d->code == 0 && is(d, "EOF")) {
            return QC_OK;
        } else if (section == 1 && d->code == 9 && is(d, "$INSUNITS")) {
            QC__TRY(header_units(d));
        } else if (section == 1 && d->code == 9 && is(d, "$MEASUREMENT")) {
            QC__TRY(header_measurement(d));
        } else if (section == 2 && d->code == 0) {
            begin_entity(d);
            in_entity = 1;
        } else if (section == 2 && in_entity) {
            QC__TRY(entity_group(d));
        }
    }
    if (g < 0)
        return QC_EFORMAT;
    return qc__fail(d->r.ctx, QC_EFORMAT, "dxf: the file ends without EOF");
}

int qc__read_dxf(qc_ctx *ctx, const char *buf, size_t len, qc_plan *out)
{
    dxf d;
    int rc;

    memset(&d, 0, sizeof d);
    qc__reader_init(&d.r, ctx, out, "dxf");
    qc__lines_init(&d.it, buf, len);
    d.unit = 1;
    d.measurement = -1;
    rc = read_all(&d);
    if (d.v)
        qc__free(ctx, d.v, d.v_cap * sizeof *d.v);
    if (d.knots)
        qc__free(ctx, d.knots, d.k_cap * sizeof *d.knots);
    if (d.w)
        qc__free(ctx, d.w, d.w_cap * sizeof *d.w);
    if (d.fit)
        qc__free(ctx, d.fit, d.fit_cap * sizeof *d.fit);
    if (rc == QC_OK)
        rc = qc__reader_finish(&d.r);
    return rc;
}
