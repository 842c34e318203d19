/*
 * Reaching into corners. The evolution keeps the curve a clearance off
 * the boundary and its lines about d apart, so in a sharp corner the
 * curve's nearest lobe stops where the wedge is still a lobe wide: 1.2 to
 * 2 d from a 30 degree tip, where issue 16 asks for 1.6 d. So after the
 * evolution, at every convex corner still out of reach, the curve sends a
 * narrow tongue down the corner's bisector from its nearest segment: two
 * sides and a round tip of radius TIP d, as far in as the clearance lets
 * the tip go. The disc round the corner out to the curve holds no line,
 * so the tongue crosses nothing there; every tongue is checked all the
 * same (nothing outside, no crossing) and left out if it fails.
 */
#include <math.h>
#include <string.h>

#include "family_meander.h"

#define CORNER_MAX 100.0 /* corners sharper than this, degrees, may get a tongue */
#define TIP 0.25         /* the tongue's tip radius, times d (the tightest turn asked for) */
#define TIP_CLEAR 0.08   /* the tip's distance from the seams, times d */
#define SIDE_STEP 0.4    /* vertices along the tongue's sides, times d */
#define ARC_STEPS 6      /* segments of the tip's half circle */
#define WORTH 0.25       /* a tongue must come this much nearer the corner, times d */
#define MAX_TONGUE 24    /* points in one tongue */
#define MARGIN 0.75      /* corners beyond this share of the goal get a tongue */

/* Issue 16's corner reach, times d, for an interior angle in degrees:
 * 90: 0.9, 45: 1.3, 36: 1.5, 31: 1.6, straight between. */
static double goal(double deg)
{
    static const double a[] = {31, 36, 45, 90}, g[] = {1.6, 1.5, 1.3, 0.9};
    int k;

    if (deg <= a[0])
        return g[0];
    for (k = 1; k < 4; k++)
        if (deg <= a[k])
            return g[k - 1] + (g[k] - g[k - 1]) * (deg - a[k - 1]) / (a[k] - a[k - 1]);
    return g[3];
}

/* The segment of c (closing unless open) nearest q: its first vertex. */
static size_t nearest_segment(const qc_points *c, int open, qc_vec2 q, double *dist)
{
    size_t i, best = 0, ns = open ? c->n - 1 : c->n;
    double bd = HUGE_VAL;

    for (i = 0; i < ns; i++) {
        qc_vec2 a = c->v[i], b = c->v[i + 1 == c->n ? 0 : i + 1];
        double ux = b.x - a.x, uy = b.y - a.y, l2 = ux * ux + uy * uy, t = 0.0, dd;
        if (l2 > 0.0)
            t = fmax(0.0, fmin(1.0, ((q.x - a.x) * ux + (q.y - a.y) * uy) / l2));
        dd = qc_hypot(a.x + t * ux - q.x, a.y + t * uy - q.y);
        if (dd < bd) {
            bd = dd;
            best = i;
        }
    }
    *dist = bd;
    return best;
}

/* Whether segment ab keeps at least clear inside (sampled every clear). */
static int seg_inside(const qc__sdf *s, qc_vec2 a, qc_vec2 b, double clear)
{
    double len = qc_hypot(b.x - a.x, b.y - a.y);
    size_t i, m = (size_t)ceil(len / clear) + 1;

    for (i = 0; i <= m; i++) {
        double t = (double)i / (double)m;
        if (qc__sdf_exact(s, QC__V2(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)), NULL) < clear)
            return 0;
    }
    return 1;
}

/* The tongue from a (at the base) to the tip round centre t (radius r,
 * axis direction ax) and back to b, without a and b, into out; returns
 * its point count (0: it does not fit). */
static size_t tongue(qc_vec2 a, qc_vec2 b, qc_vec2 t, qc_vec2 ax, double r, double d,
                     qc_vec2 *out)
{
    qc_vec2 nrm = QC__V2(-ax.y, ax.x), sa, sb, base = QC__V2(0.5 * (a.x + b.x), 0.5 * (a.y + b.y));
    double side = (a.x - base.x) * nrm.x + (a.y - base.y) * nrm.y, len;
    size_t n = 0, k, m;

    if (side < 0.0) /* nrm points to a's side */
        nrm = QC__V2(-nrm.x, -nrm.y);
    sa = QC__V2(t.x + r * nrm.x, t.y + r * nrm.y);
    sb = QC__V2(t.x - r * nrm.x, t.y - r * nrm.y);
    len = qc_hypot(sa.x - a.x, sa.y - a.y);
    m = (size_t)(len / (SIDE_STEP * d));
    if (2 * m + ARC_STEPS + 1 > MAX_TONGUE)
        return 0;
    for (k = 1; k <= m; k++) { /* down a's side */
        double f = (double)k / (double)(m + 1);
        out[n++] = QC__V2(a.x + f * (sa.x - a.x), a.y + f * (sa.y - a.y));
    }
    for (k = 0; k <= ARC_STEPS; k++) { /* round the tip, through its far point */
        double phi = QC_PI * (double)k / ARC_STEPS, cs = qc_cos(phi), sn = qc_sin(phi);
        out[n++] = QC__V2(t.x + r * (cs * nrm.x + sn * ax.x), t.y + r * (cs * nrm.y + sn * ax.y));
    }
    for (k = m; k >= 1; k--) { /* up b's side */
        double f = (double)k / (double)(m + 1);
        out[n++] = QC__V2(b.x + f * (sb.x - b.x), b.y + f * (sb.y - b.y));
    }
    return n;
}

/* c with pts[0..k) inserted after vertex i. */
static int insert(qc_ctx *ctx, qc_points *c, size_t i, const qc_vec2 *pts, size_t k)
{
    size_t j;

    for (j = 0; j < k; j++)
        QC__TRY(qc_points_push(ctx, c, pts[j]));
    memmove(c->v + i + 1 + k, c->v + i + 1, (c->n - k - i - 1) * sizeof *c->v);
    memcpy(c->v + i + 1, pts, k * sizeof *pts);
    return QC_OK;
}

/* Takes the tongue out again: c as before insert(). */
static void remove_pts(qc_points *c, size_t i, size_t k)
{
    memmove(c->v + i + 1, c->v + i + 1 + k, (c->n - k - i - 1) * sizeof *c->v);
    c->n -= k;
}

int qc__meander_reach(qc_ctx *ctx, const qc_region *region, const qc__sdf *s, double d,
                      int open, qc_points *c)
{
    size_t q, v = 0;

    if (c->n < 3)
        return QC_OK;
    for (q = 0; q < region->nrings; q++) {
        size_t first = v, end = region->ring_end[q];
        for (; v < end; v++) {
            qc_vec2 pv = region->v[v == first ? end - 1 : v - 1], p = region->v[v];
            qc_vec2 nx = region->v[v + 1 == end ? first : v + 1], bis, t, ax, a, b, pts[MAX_TONGUE];
            double deg = qc_region_corner_angle(region, v), reach, half, at, bl, r = TIP * d;
            double l1 = qc_hypot(p.x - pv.x, p.y - pv.y), l2 = qc_hypot(nx.x - p.x, nx.y - p.y);
            size_t i, j, k, crossings = 0;
            int ok = 1;

            if (!(deg < CORNER_MAX) || !(l1 > 0.0) || !(l2 > 0.0))
                continue;
            i = nearest_segment(c, open, p, &reach);
            if (reach <= MARGIN * goal(deg) * d)
                continue;
            bis = QC__V2((pv.x - p.x) / l1 + (nx.x - p.x) / l2, (pv.y - p.y) / l1 + (nx.y - p.y) / l2);
            bl = qc_hypot(bis.x, bis.y);
            if (!(bl > 1e-9))
                continue;
            bis = QC__V2(bis.x / bl, bis.y / bl);
            half = 0.5 * deg * QC_PI / 180.0;
            at = (r + TIP_CLEAR * d) / qc_sin(half); /* the tip's centre, from the corner */
            if (at - r > reach - WORTH * d)
                continue;
            t = QC__V2(p.x + at * bis.x, p.y + at * bis.y);
            a = c->v[i];
            b = c->v[i + 1 == c->n ? 0 : i + 1];
            ax = QC__V2(p.x - t.x, p.y - t.y); /* towards the corner */
            bl = qc_hypot(ax.x, ax.y);
            ax = QC__V2(ax.x / bl, ax.y / bl);
            k = tongue(a, b, t, ax, r, d, pts);
            if (k == 0)
                continue;
            for (j = 0; j + 1 < k && ok; j++)
                ok = seg_inside(s, pts[j], pts[j + 1], 0.5 * TIP_CLEAR * d);
            ok = ok && seg_inside(s, a, pts[0], 0.5 * TIP_CLEAR * d) &&
                 seg_inside(s, pts[k - 1], b, 0.5 * TIP_CLEAR * d);
            if (!ok)
                continue;
            QC__TRY(insert(ctx, c, i, pts, k));
            QC__TRY(qc_path_self_crossings(ctx, c->v, c->n, !open, &crossings));
            if (crossings > 0)
                remove_pts(c, i, k);
        }
    }
    return QC_OK;
}
