/*
 * The in-and-out spiral: where the spiral must end on its boundary (a top
 * enters each patch at a seam and leaves it at one), a spiral winding in to
 * its centre would leave by a straight link across all its turns. This one
 * is double: the first arm winds in on every other ring, the second winds
 * back out on the rings between, and the line ends on the boundary where
 * it began (the start, when that lies on the boundary).
 *
 * Each ring is cut by a band BAND d wide (along the ring) on the line of
 * nearest points running in from the start: ring k is sewn the long way
 * from its band's side A to side B (the first arm) or B to A (the second),
 * and the steps between rings two apart run diagonally across the band,
 * through the gap of the ring between: the first arm's from B(k) to
 * A(k + 2), the second's from A(k + 1) to B(k - 1), each parallel to the
 * other arm's, so no step crosses a ring or a step. At the centre one short
 * step at side B turns the line round, after a spur from there round the
 * next ring in, if any (the band cannot cut the innermost rings). It needs rings nested one in the
 * next (one ring a level); a region that splits or has holes keeps the
 * one-arm spiral. Rings too small for the band (the centre) are left out.
 */
#include <math.h>
#include <string.h>

#include "deco_internal.h"

#define BAND 1.0 /* the band's width along each ring, times d */
#define MIN_RING_BANDS 3.0 /* a ring shorter than this many bands is left out */
/* The band turns alike on every ring it cuts (straight on an edge, round
 * the corners on a bisector); where a ring turns it more than this (rad)
 * otherwise, the rings from there in are left out. */
#define MAX_TURN_CHANGE 0.5
#define ON_BOUNDARY 1e-6 /* mm: a start this near the boundary lies on it */
#define GAP_RES (1.0 / 6.0) /* largest-gap raster, times d (as shared_contour.c) */

typedef struct ring {
    const qc_vec2 *v;
    const double *cum; /* arc length at each vertex, cum[n] the ring's length */
    size_t n;
    double len;
} ring;

static double dist(qc_vec2 a, qc_vec2 b)
{
    return qc_hypot(b.x - a.x, b.y - a.y);
}

/* The arc length of the point of r nearest p. */
static double nearest_on(const ring *r, qc_vec2 p)
{
    double best = HUGE_VAL, s = 0;
    size_t i;

    for (i = 0; i < r->n; i++) {
        qc_vec2 a = r->v[i], b = r->v[i + 1 < r->n ? i + 1 : 0];
        double l = r->cum[i + 1] - r->cum[i], d2 = qc__seg_dist2(p, a, b), t = 0;

        if (d2 < best) {
            if (l > 0)
                t = fmin(fmax(((p.x - a.x) * (b.x - a.x) + (p.y - a.y) * (b.y - a.y)) / (l * l),
                              0.0), 1.0);
            best = d2;
            s = r->cum[i] + t * l;
        }
    }
    return s;
}

/* Arc length s taken round the ring into [0, len). */
static double wrap(const ring *r, double s)
{
    s = fmod(s, r->len);
    return s < 0 ? s + r->len : s;
}

/* The point at arc length s (any real: taken round the ring). */
static qc_vec2 point_at(const ring *r, double s)
{
    size_t lo = 0, hi = r->n;
    qc_vec2 a, b, p;
    double l, t;

    s = wrap(r, s);
    while (hi - lo > 1) { /* the last vertex at or before s */
        size_t mid = lo + (hi - lo) / 2;

        if (r->cum[mid] <= s)
            lo = mid;
        else
            hi = mid;
    }
    a = r->v[lo];
    b = r->v[lo + 1 < r->n ? lo + 1 : 0];
    l = r->cum[lo + 1] - r->cum[lo];
    t = l > 0 ? (s - r->cum[lo]) / l : 0;
    p.x = a.x + t * (b.x - a.x);
    p.y = a.y + t * (b.y - a.y);
    return p;
}

/* The arc length of vertex m counted round the ring (m any integer). */
static double vertex_s(const ring *r, long m)
{
    long n = (long)r->n, q = m >= 0 ? m / n : -((-m + n - 1) / n);

    return r->cum[m - q * n] + (double)q * r->len;
}

/* Appends the ring from arc length from, span along it in direction dir
 * (+1: as the vertices run, -1: against), its ends included. */
static int sew_arc(qc_ctx *ctx, const ring *r, double from, double span, int dir,
                   qc_points *out)
{
    long m;

    from = wrap(r, from);
    QC__TRY(qc_points_push(ctx, out, point_at(r, from)));
    if (dir > 0) {
        for (m = 0; m < (long)r->n && r->cum[m] <= from; m++)
            ;
        for (; vertex_s(r, m) < from + span; m++)
            QC__TRY(qc_points_push(ctx, out, r->v[m % (long)r->n]));
    } else {
        for (m = (long)r->n - 1; m >= 0 && r->cum[m] >= from; m--)
            ;
        for (; vertex_s(r, m) > from - span; m--)
            QC__TRY(qc_points_push(ctx, out, r->v[(m % (long)r->n + (long)r->n) % (long)r->n]));
    }
    return qc_points_push(ctx, out, point_at(r, from + dir * span));
}

/* How far (radians, left positive) ring r turns across the band at s. */
static double band_turn(const ring *r, double s, double g)
{
    qc_vec2 a = point_at(r, s - 0.5 * g), p = point_at(r, s), b = point_at(r, s + 0.5 * g);
    double ux = p.x - a.x, uy = p.y - a.y, wx = b.x - p.x, wy = b.y - p.y;

    return qc_atan2(ux * wy - uy * wx, ux * wx + uy * wy);
}

/* Whether the rings nest one in the next: one ring a level, levels 0, 1, ... */
static int nested(const qc__rings *rs)
{
    size_t k;

    for (k = 0; k < rs->end.n; k++)
        if (rs->level.i[k] != k)
            return 0;
    return rs->end.n >= 2;
}

/* At B(last), the innermost ring's side B: the next ring in, if any (the
 * band could not cut it), sewn round whole by a spur from B and back. */
static int sew_centre(qc_ctx *ctx, const ring *rg, size_t nr, const double *s, size_t last,
                      double g, qc_points *out)
{
    qc_vec2 b = point_at(&rg[last], s[last] + 0.5 * g);
    double q;

    QC__TRY(qc_points_push(ctx, out, b));
    if (last + 1 >= nr)
        return QC_OK;
    q = nearest_on(&rg[last + 1], b);
    QC__TRY(sew_arc(ctx, &rg[last + 1], q, rg[last + 1].len, 1, out));
    return qc_points_push(ctx, out, b);
}

/* The double spiral from s[k] (each ring's band centre) over rings 0..last,
 * and round ring last + 1 (if any) at the turn. */
static int sew_both_arms(qc_ctx *ctx, const ring *rg, size_t nr, const double *s, size_t last,
                         double g, qc_points *out)
{
    size_t k;

    for (k = 0; k <= last; k += 2) /* in: A(k) the long way round to B(k) */
        QC__TRY(sew_arc(ctx, &rg[k], s[k] - 0.5 * g, rg[k].len - g, -1, out));
    QC__TRY(sew_centre(ctx, rg, nr, s, last, g, out));
    for (k = (last & 1) ? last : last - 1;; k -= 2) { /* out: B(k) round to A(k) */
        QC__TRY(sew_arc(ctx, &rg[k], s[k] + 0.5 * g, rg[k].len - g, 1, out));
        if (k == 1)
            break;
    }
    return qc_points_push(ctx, out, point_at(&rg[0], s[0])); /* the band's centre on ring 0 */
}

/* Where the line leaves, from p on ring 0: the start itself when it lies on
 * the boundary (a top's seam corner: the link out is then no stitch at
 * all, and meets no seam stitched past it), else the boundary point
 * nearest p. */
static qc_vec2 exit_point(const qc__contour *c, qc_vec2 start, qc_vec2 p)
{
    qc_vec2 grad, q;
    double v;

    if (fabs(qc__sdf_exact(&c->sdf, start, NULL)) <= ON_BOUNDARY)
        return start;
    v = qc__sdf_exact(&c->sdf, p, &grad);
    q.x = p.x - v * grad.x;
    q.y = p.y - v * grad.y;
    return q;
}

int qc__spiral_in_out(qc_ctx *ctx, const qc_region *region, const qc_params *params,
                      const qc__contour *c, qc_vec2 start, qc_path *out, qc_stats *stats)
{
    const qc__rings *rs = &c->rings;
    double g = BAND * params->spacing, *cum = NULL, *s = NULL;
    ring *rg = NULL;
    qc_points pts = {0};
    qc_path one = {0};
    size_t nr = rs->end.n, k, last = 0, at = 0, ncum = rs->pts.n + nr, i;
    int rc = QC_OK;

    if (!nested(rs))
        return 0;
    rg = (ring *)qc__alloc_array(ctx, nr, sizeof *rg);
    cum = (double *)qc__alloc_array(ctx, ncum, sizeof *cum);
    s = (double *)qc__alloc_array(ctx, nr, sizeof *s);
    if (rg == NULL || cum == NULL || s == NULL) {
        rc = QC_ENOMEM;
        goto out;
    }
    for (k = 0, i = 0; k < nr; k++) { /* arc lengths, and the rings the band fits */
        size_t n = rs->end.i[k] - at, j;

        rg[k].v = rs->pts.v + at;
        rg[k].n = n;
        rg[k].cum = cum + i;
        cum[i] = 0;
        for (j = 0; j < n; j++)
            cum[i + j + 1] = cum[i + j] + dist(rg[k].v[j], rg[k].v[j + 1 < n ? j + 1 : 0]);
        rg[k].len = cum[i + n];
        if (n >= 3 && rg[k].len >= MIN_RING_BANDS * g && last + 1 == k)
            last = k;
        at = rs->end.i[k];
        i += n + 1;
    }
    if (last < 1 || !(rg[0].len >= MIN_RING_BANDS * g)) {
        rc = 0; /* no room for two arms: the one-arm spiral */
        goto out;
    }
    s[0] = nearest_on(&rg[0], start);
    for (k = 1; k <= last; k++) { /* the band runs in along nearest points */
        s[k] = nearest_on(&rg[k], point_at(&rg[k - 1], s[k - 1]));
        if (fabs(band_turn(&rg[k], s[k], g) - band_turn(&rg[0], s[0], g)) > MAX_TURN_CHANGE) {
            last = k - 1; /* the band slid round a corner: its steps would cross */
            break;
        }
    }
    if (last < 1) {
        rc = 0;
        goto out;
    }
    rc = sew_both_arms(ctx, rg, nr, s, last, g, &pts);
    if (rc == QC_OK)
        rc = qc_points_push(ctx, &pts, exit_point(c, start, pts.v[pts.n - 1]));
    if (rc == QC_OK)
        rc = qc_path_move_to(ctx, &one, pts.v[0]);
    for (i = 1; i < pts.n && rc == QC_OK; i++)
        if (dist(pts.v[i - 1], pts.v[i]) > 0)
            rc = qc_path_line_to(ctx, &one, pts.v[i]);
    if (rc == QC_OK && stats != NULL && !params->skip_gap_stat) {
        double gap = qc_largest_gap(ctx, region, pts.v, pts.n, GAP_RES * params->spacing, NULL);

        if (gap < 0.0)
            rc = (int)gap;
        else
            stats->largest_gap_mm = gap;
    }
    if (rc == QC_OK)
        rc = qc_path_append(ctx, out, &one, 1);
    if (rc == QC_OK)
        rc = 1;
out:
    qc__free(ctx, rg, nr * sizeof *rg);
    qc__free(ctx, cum, ncum * sizeof *cum);
    qc__free(ctx, s, nr * sizeof *s);
    qc_points_free(ctx, &pts);
    qc_path_free(ctx, &one);
    return rc;
}
