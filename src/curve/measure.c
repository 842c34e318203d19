/* A path's sewn length and exact bounding box without flattening it: the
 * stats of every pattern (qc_generate) pay for this once per result. */
#include <math.h>

#include "curve_internal.h"

/* Subdivision bound: 2^20 pieces per cubic at most, whatever the input. */
#define MEASURE_MAX_DEPTH 20
/* 5-point Gauss-Legendre is exact to 1e-5 of a piece's length (1e-7
 * typically; the 0.05 mm flattening it replaces fell 1e-3 short) when its
 * hodograph's control points 3 (q[i+1] - q[i]) lie within 0.6 of the mean
 * velocity q[3] - q[0] from it: the speed then stays well away from 0 and
 * turns by under 37 degrees either way, so it is smooth. Other pieces are
 * halved first. The bound squared: */
#define GL_SPREAD2 0.36
/* Gauss-Legendre nodes and weights on [0, 1] (5 points: exact for a
 * polynomial speed of degree 9). */
static const double gl_t[5] = {0.04691007703066800, 0.23076534494715845, 0.5,
                               0.76923465505284155, 0.95308992296933200};
static const double gl_w[5] = {0.11846344252809454, 0.23931433524968324, 0.28444444444444444,
                               0.23931433524968324, 0.11846344252809454};

static int finite(qc_vec2 p)
{
    return fabs(p.x) <= 1e300 && fabs(p.y) <= 1e300;
}

static double dist(qc_vec2 a, qc_vec2 b)
{
    double dx = b.x - a.x, dy = b.y - a.y;

    return sqrt(dx * dx + dy * dy);
}

/* The integral of the speed |B'(t)| over [0, 1] by Gauss-Legendre. */
static double gauss_length(const qc_vec2 q[4])
{
    double ax = q[1].x - q[0].x, ay = q[1].y - q[0].y;
    double bx = q[2].x - q[1].x, by = q[2].y - q[1].y;
    double cx = q[3].x - q[2].x, cy = q[3].y - q[2].y;
    double sum = 0;
    int i;

    for (i = 0; i < 5; i++) {
        double t = gl_t[i], u = 1 - t;
        double wa = u * u, wb = 2 * u * t, wc = t * t;
        double dx = wa * ax + wb * bx + wc * cx, dy = wa * ay + wb * by + wc * cy;

        sum += gl_w[i] * sqrt(dx * dx + dy * dy);
    }
    return 3 * sum;
}

/* Whether Gauss-Legendre is exact enough on q (GL_SPREAD2). */
static int smooth_speed(const qc_vec2 q[4])
{
    double mx = q[3].x - q[0].x, my = q[3].y - q[0].y, lim = GL_SPREAD2 * (mx * mx + my * my);
    int i;

    for (i = 0; i < 3; i++) {
        double hx = 3 * (q[i + 1].x - q[i].x) - mx, hy = 3 * (q[i + 1].y - q[i].y) - my;
        if (hx * hx + hy * hy > lim)
            return 0;
    }
    return 1;
}

/* Arc length of one cubic: Gauss-Legendre where its speed is smooth, halves
 * otherwise. The arc lies between the chord and the control polygon, so a
 * piece whose polygon exceeds its chord by under exact_gap (round a cusp)
 * is taken as is, its error below that gap. */
static double cubic_length(const qc_vec2 c[4], double exact_gap)
{
    qc_vec2 stack[MEASURE_MAX_DEPTH + 2][4];
    int depth[MEASURE_MAX_DEPTH + 2];
    int sp = 1, k, rough = 1; /* rough: the top is c, known not smooth */
    double len = 0;

    if (smooth_speed(c)) /* most cubics: no stack */
        return gauss_length(c);
    for (k = 0; k < 4; k++)
        stack[0][k] = c[k];
    depth[0] = 0;
    while (sp > 0) {
        qc_vec2 *q = stack[sp - 1];
        int d = depth[sp - 1];
        double chord, poly;

        if (!rough && smooth_speed(q)) {
            len += gauss_length(q);
            sp--;
            continue;
        }
        rough = 0;
        chord = dist(q[0], q[3]);
        poly = dist(q[0], q[1]) + dist(q[1], q[2]) + dist(q[2], q[3]);
        if (poly - chord <= exact_gap || d >= MEASURE_MAX_DEPTH) {
            double g = gauss_length(q);

            len += g < chord ? chord : g > poly ? poly : g;
            sp--;
            continue;
        }
        qc_cubic_split(q, 0.5, stack[sp], q);
        depth[sp - 1] = d + 1;
        depth[sp] = d + 1;
        sp++;
    }
    return len;
}

/* The cubic's coordinate (stride-picked x or y) at t, Bernstein form. */
static double bern(double p0, double p1, double p2, double p3, double t)
{
    double u = 1 - t;

    return u * u * u * p0 + 3 * u * u * t * p1 + 3 * u * t * t * p2 + t * t * t * p3;
}

/* Widens [*lo, *hi] (holding the end points) by one coordinate's interior
 * extrema: the roots in (0, 1) of the derivative a t^2 + b t + c. */
static void widen(double p0, double p1, double p2, double p3, double *lo, double *hi)
{
    double a = p1 - p0, b = p2 - p1, c = p3 - p2; /* the derivative's legs / 3 */
    double qa = a - 2 * b + c, qb = 2 * (b - a), qc = a;
    double roots[2], disc;
    int n = 0, i;

    if (p1 >= *lo && p1 <= *hi && p2 >= *lo && p2 <= *hi)
        return; /* the hull is inside already */
    if (qa == 0) {
        if (qb != 0)
            roots[n++] = -qc / qb;
    } else {
        disc = qb * qb - 4 * qa * qc;
        if (disc >= 0) {
            double s = -0.5 * (qb + (qb < 0 ? -sqrt(disc) : sqrt(disc)));
            roots[n++] = s / qa;
            if (s != 0)
                roots[n++] = qc / s;
        }
    }
    for (i = 0; i < n; i++)
        if (roots[i] > 0 && roots[i] < 1) {
            double v = bern(p0, p1, p2, p3, roots[i]);
            if (v < *lo)
                *lo = v;
            if (v > *hi)
                *hi = v;
        }
}

typedef struct measure {
    double len;
    qc_bbox box;
    int any;
} measure;

void qc_curve_measure(const qc_path *path, double tol, double *length, qc_bbox *box)
{
    measure m;
    qc_vec2 cur = {0, 0};
    size_t c, k = 0;

    m.len = 0;
    m.box.min = cur;
    m.box.max = cur;
    m.any = 0;
    if (!(tol > 0))
        tol = 0.01;
    for (c = 0; c < path->ncmd; c++) {
        unsigned char cmd = path->cmd[c];

        if (c == 0 && cmd != QC_PATH_MOVE)
            qc__box_take(&m.box, &m.any, cur);
        if (cmd == QC_PATH_CUBIC) {
            qc_vec2 q[4];

            qc__curve_cubic(path, k, cur, q);
            qc__box_take(&m.box, &m.any, q[3]);
            if (finite(q[0]) && finite(q[1]) && finite(q[2]) && finite(q[3])) {
                m.len += cubic_length(q, 1e-3 * tol);
                widen(q[0].x, q[1].x, q[2].x, q[3].x, &m.box.min.x, &m.box.max.x);
                widen(q[0].y, q[1].y, q[2].y, q[3].y, &m.box.min.y, &m.box.max.y);
            } else {
                m.len += qc_hypot(q[3].x - q[0].x, q[3].y - q[0].y);
            }
            cur = q[3];
            k += 3;
        } else {
            qc_vec2 p = path->pt[k++];

            if (cmd != QC_PATH_MOVE)
                m.len += qc_hypot(p.x - cur.x, p.y - cur.y);
            qc__box_take(&m.box, &m.any, p);
            cur = p;
        }
    }
    *length = m.len;
    *box = m.box;
}
