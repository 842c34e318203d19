/*
 * Centripetal Catmull-Rom splines (alpha = 0.5) as cubic Béziers.
 *
 * With knot intervals d = |P(i+1) - P(i)|^0.5, the spline's velocity (per
 * knot time) at P(i) is V(i) = a*d1/(d0*(d0+d1)) + b*d0/(d1*(d0+d1)), where
 * a, b are the incoming and outgoing chords and d0, d1 their intervals. The
 * Bézier of segment i -> i+1 has controls P(i) + d*V(i)/3, P(i+1) - d*V(i+1)/3.
 */
#include <math.h>
#include <string.h>

#include "curve_internal.h"

/* Consecutive points closer than this (mm) count as one. */
#define CR_COINCIDENT 1e-9
/* |V| below this fraction of its size on a straight line means the path
 * doubles back on itself (V is then exactly or nearly zero: a cusp). */
#define CR_HAIRPIN 1e-3

static qc_vec2 sub(qc_vec2 a, qc_vec2 b)
{
    qc_vec2 r;

    r.x = a.x - b.x;
    r.y = a.y - b.y;
    return r;
}

static double len(qc_vec2 a)
{
    return qc_hypot(a.x, a.y);
}

/* Velocity at a point with incoming chord a and outgoing chord b. */
static qc_vec2 velocity(qc_vec2 a, qc_vec2 b)
{
    double d0 = sqrt(len(a)), d1 = sqrt(len(b));
    double s = d0 + d1, ka = d1 / (d0 * s), kb = d0 / (d1 * s);
    double straight = 2 * d0 * d1 / s; /* |V| when a and b point the same way */
    qc_vec2 v;

    v.x = a.x * ka + b.x * kb;
    v.y = a.y * ka + b.y * kb;
    if (len(v) < CR_HAIRPIN * straight) {
        /* A hairpin: turn round smoothly to the left of a instead of
         * stopping dead, so the derivative never vanishes. */
        double la = len(a), m = 0.5 * straight;

        v.x = -a.y / la * m;
        v.y = a.x / la * m;
    }
    return v;
}

/* Copies pts without consecutive duplicates (and, closed, without a last
 * point equal to the first) into q; returns the count. */
static size_t dedupe(const qc_vec2 *pts, size_t n, int closed, qc_vec2 *q)
{
    size_t i, m = 0;

    for (i = 0; i < n; i++) {
        if (m > 0 && len(sub(pts[i], q[m - 1])) <= CR_COINCIDENT)
            continue;
        q[m++] = pts[i];
    }
    while (closed && m > 1 && len(sub(q[m - 1], q[0])) <= CR_COINCIDENT)
        m--;
    return m;
}

int qc_curve_catmull_rom(qc_ctx *ctx, const qc_vec2 *pts, size_t n,
                         int closed, qc_path *out)
{
    qc_vec2 *q, *v;
    size_t i, m, nseg;
    int rc = QC_OK;

    if (n == 0)
        return QC_OK;
    if (pts == NULL)
        return qc__fail(ctx, QC_EINVAL, "catmull-rom: NULL points with n = %lu",
                        (unsigned long)n);
    for (i = 0; i < n; i++)
        if (!(fabs(pts[i].x) <= 1e9 && fabs(pts[i].y) <= 1e9))
            return qc__fail(ctx, QC_ERANGE,
                            "catmull-rom: point %lu (%g, %g) is not finite or too large",
                            (unsigned long)i, pts[i].x, pts[i].y);
    q = (qc_vec2 *)qc__alloc_array(ctx, n, 2 * sizeof *q);
    if (q == NULL)
        return QC_ENOMEM;
    v = q + n;
    m = dedupe(pts, n, closed, q);
    nseg = m < 2 ? 0 : closed ? m : m - 1;
    /* Reserve everything first so the path is never left half-appended. */
    rc = QC__RESERVE(ctx, out->cmd, out->cmd_cap, out->ncmd + nseg + 1);
    if (rc == QC_OK)
        rc = QC__RESERVE(ctx, out->pt, out->pt_cap, out->npt + 3 * nseg + 1);
    if (rc != QC_OK)
        goto out_free_q;

    for (i = 0; i < m && nseg > 0; i++) {
        qc_vec2 a, b;

        if (i == 0 && !closed) {
            b = sub(q[1], q[0]);
            a = b; /* the start reflected: P(-1) = 2 P(0) - P(1) */
        } else if (i == m - 1 && !closed) {
            a = sub(q[m - 1], q[m - 2]);
            b = a;
        } else {
            a = sub(q[i], q[(i + m - 1) % m]);
            b = sub(q[(i + 1) % m], q[i]);
        }
        v[i] = velocity(a, b);
    }
    if (out->ncmd == 0)
        (void)qc_path_move_to(ctx, out, q[0]); /* cannot fail: reserved */
    for (i = 0; i < nseg; i++) {
        size_t j = (i + 1) % m;
        double d = sqrt(len(sub(q[j], q[i]))) / 3;
        qc_vec2 c1, c2;

        c1.x = q[i].x + d * v[i].x;
        c1.y = q[i].y + d * v[i].y;
        c2.x = q[j].x - d * v[j].x;
        c2.y = q[j].y - d * v[j].y;
        (void)qc_path_cubic_to(ctx, out, c1, c2, q[j]);
    }
out_free_q:
    qc__free(ctx, q, n * 2 * sizeof *q);
    return rc;
}
