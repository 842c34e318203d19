/*
 * Pebbling and packing, phase 3 (ours, issue 16): into the corners and
 * along the seams. Pebbles packed from the skeleton keep off the seams by
 * their own size: a 45 deg corner was left 1.8 d bare, a fifth of the
 * seams more than 1/4 in from a stitch. A pebble goes into each corner
 * sharper than CORNER_DEG, tangent to both its sides at the radius that
 * brings its edge TIP_D d from the tip (at most r_seed d), and then one
 * tangent to the seam wherever a stretch of it lies farther than SEAM_D d
 * from every pebble. Each hangs from the pebble it touches, else through a
 * filler tangent to both (no larger than r_seed d); else it is left out (a
 * straight stitch could be crossed by a pebble placed after it), so the
 * path stays the outline of the pebbles and never crosses itself.
 */
#include <math.h>

#include "pebble_pack.h"

static double dist(qc_vec2 a, qc_vec2 b)
{
    double dx = a.x - b.x, dy = a.y - b.y;
    return sqrt(dx * dx + dy * dy);
}

static qc_vec2 unit_from(qc_vec2 a, qc_vec2 b)
{
    double l = dist(a, b);
    return l > 0 ? QC__V2((b.x - a.x) / l, (b.y - a.y) / l) : QC__V2(1, 0);
}

#define CORNER_DEG 150.0 /* corners sharper than this get a pebble */
#define TIP_D 1.0        /* a corner pebble's edge this far from the tip, times d */
#define CORNER_OK_D 0.8  /* a corner already this near a pebble (times d) is left */
#define SEAM_D 0.35      /* a seam this far from every pebble (times d) gets one */
#define SEAM_STEP 0.25   /* seams looked at every this much, times d */

/* The places qc__pack_reach may try (a bound, for the pebbles' capacity). */
size_t qc__pack_reach_tries(const qc_region *region, double d)
{
    size_t ring, i, n = 0;

    for (ring = 0; ring < region->nrings; ring++) {
        size_t lo = ring ? region->ring_end[ring - 1] : 0, hi = region->ring_end[ring];
        for (i = lo; i < hi; i++) {
            qc_vec2 a = region->v[i], b = region->v[i + 1 < hi ? i + 1 : lo];
            double m = ceil(dist(a, b) / (SEAM_STEP * d));
            n += 1 + (m < 1e7 ? (size_t)m : 10000000u);
        }
    }
    return n;
}

/* Distance from x to the nearest pebble's edge when at most reach (its
 * pebble in *a), else HUGE_VAL. */
static double bare(qc__pack *P, qc_vec2 x, double reach, uint32_t *a)
{
    uint32_t j = qc__pack_nearest(P, x, reach);

    if (j == QC__PEB_NONE)
        return HUGE_VAL;
    *a = j;
    return dist(x, P->pb->c[j]) - P->pb->r[j];
}

/* Pebble (x, c), clear of every pebble and the boundary, hung from the
 * nearest pebble: tangent to it, else through a filler, else slid to
 * touch it when too near for a filler; else left out. */
static void attach(qc__pack *P, qc_vec2 x, double c)
{
    qc__pebbles *pb = P->pb;
    uint32_t a = QC__PEB_NONE;
    qc_vec2 u, x0;
    double gap = bare(P, x, c + 2 * pb->r_first, &a) - c, f;

    if (a == QC__PEB_NONE)
        return;
    if (gap <= pb->touch) {
        qc__pack_place(P, x, c, a, 0);
        return;
    }
    u = unit_from(pb->c[a], x);
    x0 = QC__V2(pb->c[a].x + u.x * pb->r[a], pb->c[a].y + u.y * pb->r[a]);
    f = gap / 2;
    if (f < pb->r_min) { /* too narrow for a filler: slid to touch a */
        qc_vec2 y = QC__V2(x.x - u.x * gap, x.y - u.y * gap);
        if (qc__pack_same_side(P, x, y) &&
            qc__pack_clearance(P, y, c, a) >= c * (1 - 1e-9))
            qc__pack_place(P, y, c, a, 0);
    } else if (f <= pb->r_first && qc__pack_same_side(P, pb->c[a], x0) &&
               qc__pack_ray(P, x0, u, f, a) >= f * (1 - 1e-12)) {
        uint32_t g = qc__pack_place(P, QC__V2(x0.x + u.x * f, x0.y + u.y * f), f, a,
                                    QC__PEB_FILLER);
        qc__pack_place(P, x, c, g, 0);
    }
}

/* Whether the circle (x, r) keeps clear of every pebble and the boundary. */
static int fits(qc__pack *P, qc_vec2 x, double r)
{
    return qc__pack_clearance(P, x, r, QC__PEB_NONE) >= r * (1 - 1e-9);
}

/* A pebble into the convex corner at vertex v (prev p, next q). */
static void into_corner(qc__pack *P, qc_vec2 p, qc_vec2 v, qc_vec2 q)
{
    qc__pebbles *pb = P->pb;
    qc_vec2 e1 = unit_from(v, p), e2 = unit_from(v, q), u;
    double cosa = e1.x * e2.x + e1.y * e2.y, s, lo, hi, cap;
    uint32_t a;
    int it;

    if (e1.x * e2.y - e1.y * e2.x <= 0 || cosa < qc_cos(CORNER_DEG * QC_PI / 180))
        return; /* reflex, straight, or blunt */
    if (bare(P, v, CORNER_OK_D * P->d, &a) <= CORNER_OK_D * P->d)
        return;
    u = unit_from(QC__V2(0, 0), QC__V2(e1.x + e2.x, e1.y + e2.y));
    s = sqrt(fmax(0, 0.5 * (1 - cosa))); /* sine of half the angle */
    if (!(s > 1e-6))
        return;
    cap = fmin(pb->r_first, TIP_D * P->d * s / (1 - s));
    /* the largest radius up to cap at which the inscribed circle fits */
#define AT(r) QC__V2(v.x + u.x * (r) / s, v.y + u.y * (r) / s)
    if (cap < pb->r_min || !fits(P, AT(pb->r_min), pb->r_min))
        return;
    lo = pb->r_min;
    hi = cap;
    if (fits(P, AT(cap), cap))
        lo = cap;
    else
        for (it = 0; it < 50; it++) {
            double mid = 0.5 * (lo + hi);
            if (fits(P, AT(mid), mid))
                lo = mid;
            else
                hi = mid;
        }
    attach(P, AT(lo), lo);
#undef AT
}

/* Pebbles tangent to the seam along edge a -> b where it is bare. */
static void along_seam(qc__pack *P, qc_vec2 a, qc_vec2 b)
{
    qc__pebbles *pb = P->pb;
    double len = dist(a, b), step = SEAM_STEP * P->d, lift = 1e-4 * P->d;
    qc_vec2 t = unit_from(a, b), n = QC__V2(-t.y, t.x); /* left: inside */
    size_t m, j;

    if (!(len > 0))
        return;
    m = (size_t)ceil(len / step);
    for (j = 0; j < m; j++) {
        double at = (j + 0.5) * len / (double)m, r;
        qc_vec2 s = QC__V2(a.x + t.x * at, a.y + t.y * at), x0;
        uint32_t near;
        if (bare(P, s, SEAM_D * P->d, &near) <= SEAM_D * P->d)
            continue;
        x0 = QC__V2(s.x + n.x * lift, s.y + n.y * lift);
        r = qc__pack_ray(P, x0, n, pb->r_first, QC__PEB_NONE);
        if (r >= pb->r_min)
            attach(P, QC__V2(x0.x + n.x * r, x0.y + n.y * r), r);
    }
}

void qc__pack_reach(qc__pack *P)
{
    const qc_region *region = P->b->region;
    size_t ring, i;

    if (P->pb->n == 0)
        return;
    for (ring = 0; ring < region->nrings; ring++) {
        size_t lo = ring ? region->ring_end[ring - 1] : 0, hi = region->ring_end[ring];
        for (i = lo; i < hi; i++)
            into_corner(P, region->v[i == lo ? hi - 1 : i - 1], region->v[i],
                        region->v[i + 1 < hi ? i + 1 : lo]);
    }
    for (ring = 0; ring < region->nrings; ring++) {
        size_t lo = ring ? region->ring_end[ring - 1] : 0, hi = region->ring_end[ring];
        for (i = lo; i < hi; i++)
            along_seam(P, region->v[i], region->v[i + 1 < hi ? i + 1 : lo]);
    }
}
