/*
 * Closing the holes the evolution leaves (issue 17: farthest fabric and
 * evenness). The growth settles where its short-range forces balance, and
 * where channels meet or bend (a T or an L of lines d apart) the fabric
 * lies 0.65-0.7 d from any stitch, not the d/2 of evenly spaced lines. So,
 * a few passes: a distance raster of the curve finds the widest empty
 * discs (its local maxima, climbed to the exact distance), and into each
 * disc within a little of the widest the curve is bulged: from each side
 * the disc touches in turn, a bump of the line there (its vertices within
 * 0.6 d along the curve moved towards the centre by up to 0.25 d, less
 * further along), the line behind left where it is, so the curve grows
 * into the hole instead of opening the channel behind. Each bump is
 * judged on the spot: the widest gap on a lattice round the disc (seams
 * included) must narrow, the curve must not cross itself there nor turn
 * tighter than d/4 where it did not, and lines near the seams move only
 * towards them (they cover the seams). The best bump is kept; where none
 * helps, the lines all round are drawn in radially instead (by up to
 * 0.15 d, less where the channel behind would grow too wide), judged the
 * same way. A pass that leaves the widest disc wider is undone and the
 * phase ends, as it is should the curve cross itself (the hard
 * invariant, checked on the whole curve).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "family_meander_holes.h"
#include "../measure/measure_internal.h"

#define RES (1.0 / 8.0) /* the distance raster's cells, times d */
#define GOAL 0.57       /* discs wider than this (radius, times d) are closed in ... */
#define AIM 0.52        /* ... towards this radius, times d ... */
#define SHIFT_MAX 0.15   /* ... by at most this, times d */
#define BAND 0.7        /* the vertices moved lie this far beyond the disc, times d */
#define ROOM 0.56       /* a vertex moves only while the space behind it stays
                         * within this (the ridge's distance, times d) */
#define RIM 0.8         /* vertices this near the seams move only towards them ... */
#define SEAM 0.12       /* ... and no nearer than this, times d */
#define PASSES 3
#define MAX_VERTICES 8000 /* a work budget: larger curves (a 15 x 15 in block at
                           * 0.4 in, whose middle settles during the growth) are
                           * left as grown, each pass being global */
#define BUMP_W 0.6   /* a bump spans this arc either side of its contact, times d */
#define CONTACT 0.1  /* vertices this near the disc's rim touch it, times d */
#define LOCAL_RES 0.125 /* the lattice judging a bump, times d ... */
#define LOCAL_PAD 0.65  /* ... out to this beyond the disc, times d */
#define LOCAL_NEAR 0.15 /* the near search's reach beyond the widest so far, times d */
#define MOUTH 0.7 /* the mouths on the seams closed in: wider than this, times d
                   * (narrower ones, drawn in, hook at the seam) */
#define TIER 0.04       /* a pass closes the discs within this of the widest, times d */
#define GAIN 0.003      /* a move is kept if the widest gap round it shrank by this,
                         * a pass unless the widest disc grew by this, times d */


/* The segment of c nearest q (its first vertex), searching the cells round
 * q out to reach; *dist its distance (HUGE_VAL: none within reach). */
static size_t nearest(const qc__holes *h, qc_vec2 q, double reach, double *dist)
{
    size_t cells[4], x, y, k, best = 0, ns = h->open ? h->c->n - 1 : h->c->n;
    double b2 = HUGE_VAL;

    qc__seg_grid_cells(&h->sg, QC__V2(q.x - reach, q.y - reach), QC__V2(q.x + reach, q.y + reach),
                       cells);
    for (y = cells[1]; y <= cells[3]; y++)
        for (x = cells[0]; x <= cells[2]; x++)
            for (k = h->sg.start[y * h->sg.gx + x]; k < h->sg.start[y * h->sg.gx + x + 1]; k++) {
                size_t i = h->sg.seg[k];
                double e;
                if (i >= ns)
                    continue;
                e = qc__seg_dist2(q, h->c->v[i], h->c->v[qc__holes_next(h->c, (uint32_t)i)]);
                if (e < b2 || (e == b2 && i < best)) {
                    b2 = e;
                    best = i;
                }
            }
    *dist = b2 < HUGE_VAL ? sqrt(b2) : HUGE_VAL;
    return best;
}

/* Whether a segment of c lies within r of q (the first found will do). */
static int near_any(const qc__holes *h, qc_vec2 q, double r)
{
    size_t cells[4], x, y, k, ns = h->open ? h->c->n - 1 : h->c->n;
    double r2 = r * r;

    qc__seg_grid_cells(&h->sg, QC__V2(q.x - r, q.y - r), QC__V2(q.x + r, q.y + r), cells);
    for (y = cells[1]; y <= cells[3]; y++)
        for (x = cells[0]; x <= cells[2]; x++)
            for (k = h->sg.start[y * h->sg.gx + x]; k < h->sg.start[y * h->sg.gx + x + 1]; k++) {
                size_t i = h->sg.seg[k];
                if (i < ns &&
                    qc__seg_dist2(q, h->c->v[i], h->c->v[qc__holes_next(h->c, (uint32_t)i)]) <= r2)
                    return 1;
            }
    return 0;
}

/* The disc at *q grown: *q moved (8 directions, steps from h down to
 * h/4) while its exact distance to the curve grows; returns the nearest
 * segment, *R the distance (the raster's peak is a cell off). */
static size_t climb(const qc__holes *h, qc_vec2 *q, double step, double guess, double *R)
{
    /* the raster's guess is a cell or so off: a search a little beyond
     * it, exact if it finds a segment within its reach */
    size_t s = nearest(h, *q, fmin(2.0 * h->d, guess + 2.0 * step), R), k, t;

    if (!(*R <= guess + 2.0 * step))
        s = nearest(h, *q, 2.0 * h->d, R);

    for (t = 0; t < 3; t++, step *= 0.5)
        for (k = 0; k < 8; k++) {
            double ang = QC_PI * (double)k / 4.0, r;
            qc_vec2 p = QC__V2(q->x + step * qc_cos(ang), q->y + step * qc_sin(ang));
            size_t j;
            /* a segment within *R of p: it is no higher (the quick test) */
            if (qc__sdf_at(h->s, p) < 0.0 || (*R < h->d && near_any(h, p, *R)))
                continue;
            /* p is within step of q, so its nearest lies within *R + step
             * (a margin for rounding): a smaller search, the same answer */
            j = nearest(h, p, fmin(2.0 * h->d, *R + step + 0.01 * h->d), &r);
            if (r > *R && r < HUGE_VAL) {
                *q = p;
                *R = r;
                s = j;
                k = (size_t)-1; /* again round the new place */
            }
        }
    return s;
}

/* Local maxima of the raster above floor, greatest first (then by cell). */
typedef struct peak {
    float f;
    uint32_t at;
    int seam; /* a channel's mouth: a neighbour lies outside the region */
} peak;

static int cmp_peak(const void *pa, const void *pb)
{
    const peak *a = pa, *b = pb;

    if (a->f != b->f)
        return a->f > b->f ? -1 : 1;
    return a->at < b->at ? -1 : a->at > b->at;
}

/* Blocks the cells within rad of q: their discs wait for the next pass. */
static void block(const qc__gap_grid *g, unsigned char *mask, qc_vec2 q, double rad)
{
    long i0 = (long)floor((q.x - rad - g->x0) / g->h), i1 = (long)ceil((q.x + rad - g->x0) / g->h);
    long j0 = (long)floor((q.y - rad - g->y0) / g->h), j1 = (long)ceil((q.y + rad - g->y0) / g->h);
    long i, j;

    for (j = j0 < 0 ? 0 : j0; j <= j1 && j < (long)g->ny; j++)
        for (i = i0 < 0 ? 0 : i0; i <= i1 && i < (long)g->nx; i++)
            mask[(size_t)j * g->nx + (size_t)i] |= 2;
}

/* Smooth fall from 1 (t <= 0) to 0 (t >= 1). */
static double fall(double t)
{
    t = t <= 0.0 ? 0.0 : t >= 1.0 ? 1.0 : t;
    return 1.0 - t * t * (3.0 - 2.0 * t);
}

/* The space behind p, seen from q: the greatest distance (mm) the raster
 * holds along the ray from p away from q, up to where it falls again (the
 * ridge between p's line and the next), or the seam. */
static double behind(const qc__gap_grid *g, const unsigned char *mask, qc_vec2 p, qc_vec2 u,
                     double d)
{
    double best = 0.0, t;

    for (t = g->h; t <= 1.5 * d; t += g->h) {
        double x = (p.x + t * u.x - g->x0) / g->h, y = (p.y + t * u.y - g->y0) / g->h, v;
        size_t at;
        if (x < 0.0 || y < 0.0 || x >= (double)g->nx || y >= (double)g->ny)
            break;
        at = (size_t)y * g->nx + (size_t)x;
        if (!(mask[at] & 1))
            break;
        v = sqrt((double)g->f[at]) * g->h;
        if (v < best - g->h)
            break;
        best = fmax(best, v);
    }
    return best;
}

/* The widest gap round q: the greatest distance from the curve of the
 * region's points (seams included) on a lattice within half of q, capped
 * at d; or, once it reaches stop, stop (the move judged is no better).
 * Rings of the lattice from q outwards (the widest gap lies near q). A
 * point whose nearest segment in a small search is no further than the
 * widest so far cannot raise it; the others are searched in full, far
 * enough for the segments moves have carried out of their cells. */
static double local_far(const qc__holes *h, qc_vec2 q, double half, double stop)
{
    double step = LOCAL_RES * h->d, cap = h->d, best = 0.0;
    long i, j, ring, m = (long)(half / step);

    for (ring = 0; ring <= m; ring++)
        for (j = -ring; j <= ring; j++)
            for (i = -ring; i <= ring; i += (j == -ring || j == ring) ? 1 : 2 * ring) {
                qc_vec2 p = QC__V2(q.x + (double)i * step, q.y + (double)j * step);
                double r;
                if (qc__sdf_at(h->s, p) < 0.0)
                    continue;
                if (near_any(h, p, best))
                    continue;
                /* most lie just beyond best: a near search first, exact
                 * when it finds a segment that a move cannot have carried
                 * out of the cells searched */
                (void)nearest(h, p, best + (LOCAL_NEAR + BUMP_MAX) * h->d, &r);
                if (!(r <= best + LOCAL_NEAR * h->d))
                    (void)nearest(h, p, cap + BUMP_MAX * h->d, &r);
                best = fmax(best, fmin(r, cap));
                if (best >= stop)
                    return stop;
            }
    return best;
}


/* Raises a bump of the curve at vertex v0 towards q: the vertices within
 * BUMP_W d along the curve either side move by rise, less further along
 * (the line behind stays: the curve grows into the hole). 0, undone, if
 * it would carry a line near a seam away from it, too near it, or make
 * the curve cross itself. */
static int bump(qc__holes *h, qc_points *c, size_t v0, qc_vec2 q, double rise)
{
    size_t n = c->n, side, k, j;
    qc_vec2 u = QC__V2(q.x - c->v[v0].x, q.y - c->v[v0].y);
    double ul = qc_hypot(u.x, u.y), w = BUMP_W * h->d;

    h->nundo = 0;
    if (!(ul > 0.0))
        return 0;
    u.x /= ul;
    u.y /= ul;
    for (side = 0; side < 2; side++) {
        double arc = 0.0;
        for (j = v0, k = 0; k < n / 2; k++) {
            size_t nx;
            qc_vec2 p = c->v[j], m;
            double was, now, s;
            if (h->open && (j == 0 || j + 1 == n))
                break;
            nx = side ? (j + 1 == n ? 0 : j + 1) : (j == 0 ? n - 1 : j - 1);
            if (!(side && j == v0)) {
                s = rise * fall(arc / w);
                m = QC__V2(p.x + s * u.x, p.y + s * u.y);
                was = qc__sdf_at(h->s, p);
                now = qc__sdf_at(h->s, m);
                if ((was < RIM * h->d && now > was) || now < SEAM * h->d) {
                    qc__holes_undo(h, c);
                    return 0;
                }
                h->undo[h->nundo] = (uint32_t)j;
                h->was[h->nundo++] = p;
                c->v[j] = m;
            }
            arc += qc_hypot(c->v[nx].x - p.x, c->v[nx].y - p.y);
            if (arc > w)
                break;
            j = nx;
        }
    }
    for (k = 0; k < h->nundo; k++) {
        size_t i = h->undo[k];
        if (qc__holes_crosses_at(h, c, i) || qc__holes_crosses_at(h, c, i == 0 ? n - 1 : i - 1)) {
            qc__holes_undo(h, c);
            return 0;
        }
    }
    if (qc__holes_turns_tighter(h, c)) {
        qc__holes_undo(h, c);
        return 0;
    }
    return 1;
}

/* Tries a bump from each side (up to four, 60 degrees apart or more) the
 * disc at q (radius R) touches and keeps the one that narrows the widest
 * gap round it most, if any does. */
static int try_bumps(qc__holes *h, qc_points *c, qc_vec2 q, double R)
{
    size_t cells[4], x, y, e, pick[4], np = 0, k, best = (size_t)-1;
    double reach = R + CONTACT * h->d, half = R + LOCAL_PAD * h->d, rise;
    double before = local_far(h, q, half, HUGE_VAL), least = before - GAIN * h->d;

    rise = fmin(BUMP_MAX * h->d, R - AIM * h->d);
    if (!(rise > 0.0))
        return 0;
    /* the contacts: the nearest vertex, then the nearest more than 60
     * degrees round from those picked */
    for (k = 0; k < 4; k++) {
        double bd = HUGE_VAL;
        size_t bi = (size_t)-1;
        qc__seg_grid_cells(&h->sg, QC__V2(q.x - reach, q.y - reach), QC__V2(q.x + reach, q.y + reach),
                           cells);
        for (y = cells[1]; y <= cells[3]; y++)
            for (x = cells[0]; x <= cells[2]; x++)
                for (e = h->sg.start[y * h->sg.gx + x]; e < h->sg.start[y * h->sg.gx + x + 1]; e++) {
                    size_t i = h->sg.seg[e], t;
                    qc_vec2 p = c->v[i];
                    double r = qc_hypot(p.x - q.x, p.y - q.y);
                    int ok = r < reach && r > 0.0 && (r < bd || (r == bd && i < bi));
                    for (t = 0; t < np && ok; t++) {
                        qc_vec2 o = c->v[pick[t]];
                        double ro = qc_hypot(o.x - q.x, o.y - q.y);
                        ok = ((p.x - q.x) * (o.x - q.x) + (p.y - q.y) * (o.y - q.y)) < 0.5 * r * ro;
                    }
                    if (ok && !(h->open && (i == 0 || i + 1 == c->n))) {
                        bd = r;
                        bi = i;
                    }
                }
        if (bi == (size_t)-1)
            break;
        pick[np++] = bi;
    }
    for (k = 0; k < np; k++) {
        double after;
        if (!bump(h, c, pick[k], q, rise))
            continue;
        after = local_far(h, q, half, least);
        qc__holes_undo(h, c);
        if (after < least) {
            least = after;
            best = k;
        }
    }
    if (best == (size_t)-1)
        return 0;
    if (!bump(h, c, pick[best], q, rise))
        return 0;
    h->nundo = 0;
    return 1;
}

/* Draws the vertices round the disc at q (radius R) in towards q by up
 * to shift, each as far as the space behind it allows; stamp marks them
 * for disc number k. */
static void close_in(qc__holes *h, qc_points *c, const qc__gap_grid *g, const unsigned char *mask,
                     qc_vec2 q, double R, double shift, uint32_t k)
{
    double reach = R + BAND * h->d, pad = 0.25 * h->d, band = BAND * h->d;
    size_t cells[4], x, y, e;

    qc__seg_grid_cells(&h->sg, QC__V2(q.x - reach - pad, q.y - reach - pad),
                       QC__V2(q.x + reach + pad, q.y + reach + pad), cells);
    for (y = cells[1]; y <= cells[3]; y++)
        for (x = cells[0]; x <= cells[2]; x++)
            for (e = h->sg.start[y * h->sg.gx + x]; e < h->sg.start[y * h->sg.gx + x + 1]; e++) {
                size_t i = h->sg.seg[e];
                qc_vec2 p = c->v[i], m;
                double r = qc_hypot(p.x - q.x, p.y - q.y), s, was, now;

                if (h->stamp[i] == k + 1 || !(r < reach) || !(r > 0.0) ||
                    (h->open && (i == 0 || i + 1 == c->n)))
                    continue;
                h->stamp[i] = k + 1;
                s = shift * fall((r - R) / band);
                /* the ridge behind moves out by about half the shift */
                s = fmin(s, fmax(0.0, 2.0 * (ROOM * h->d -
                                             behind(g, mask, p, QC__V2((p.x - q.x) / r, (p.y - q.y) / r), h->d))));
                if (s > r - 0.5 * R) /* (a vertex inside the disc: the raster erred) */
                    s = fmax(0.0, r - 0.5 * R);
                m = QC__V2(p.x + s * (q.x - p.x) / r, p.y + s * (q.y - p.y) / r);
                was = qc__sdf_at(h->s, p);
                now = qc__sdf_at(h->s, m);
                /* near the seams a vertex may only come nearer them (it covers
                 * them), and no nearer than the seam clearance */
                if ((was < RIM * h->d && now > was) || now < SEAM * h->d)
                    continue;
                h->undo[h->nundo] = (uint32_t)i;
                h->was[h->nundo++] = p;
                c->v[i] = m;
            }
}

/* The raster's peaks above floor2 (squared cells; no neighbour greater),
 * in *pk (*np of them, *pcap allocated), each marked a mouth on the seams
 * when a neighbour lies outside. QC_OK or QC_ENOMEM. */
static int find_peaks(qc_ctx *ctx, const qc__gap_grid *g, const unsigned char *mask,
                      double floor2, peak **pk, size_t *np, size_t *pcap)
{
    size_t i, k, cells = g->nx * g->ny;
    int rc = QC_OK;

    for (i = 0; rc == QC_OK && i < cells; i++) {
        size_t x = i % g->nx, y = i / g->nx;
        int top = mask[i] && (double)g->f[i] > floor2 && g->f[i] < (float)QC__GAP_FAR;
        int seam = 0;
        for (k = 0; k < 9 && top; k++) {
            long xx = (long)x + (long)(k % 3) - 1, yy = (long)y + (long)(k / 3) - 1;
            size_t at;
            if (k == 4 || xx < 0 || yy < 0 || xx >= (long)g->nx || yy >= (long)g->ny)
                continue;
            at = (size_t)yy * g->nx + (size_t)xx;
            /* outside cells are far from the curve, never a peak's rival */
            seam |= !mask[at];
            top = !mask[at] || g->f[at] < g->f[i] || (g->f[at] == g->f[i] && at > i);
        }
        if (top) {
            rc = QC__RESERVE(ctx, *pk, *pcap, *np + 1);
            if (rc < 0)
                break;
            (*pk)[*np].f = g->f[i];
            (*pk)[*np].seam = seam;
            (*pk)[(*np)++].at = (uint32_t)i;
        }
    }
    return rc;
}

/* One pass: *worst receives the widest disc's exact radius (the greatest
 * of the raster's first peaks, climbed) inside; with act, the discs wider
 * than the goal and than *worst less TIER are closed in (*moved: how many),
 * and the mouths on the seams wider than MOUTH and than the widest mouth
 * less TIER. */
static int pass(qc_ctx *ctx, const qc_region *region, qc__holes *h, qc_points *c, int act,
                double *worst, size_t *moved)
{
    qc__gap_grid g;
    unsigned char *mask = NULL;
    peak *pk = NULL;
    size_t np = 0, pcap = 0, cells, i, k, ns = h->open ? c->n - 1 : c->n;
    double floor2, goal[2], widest[2] = {0.0, 0.0}, first[2] = {HUGE_VAL, HUGE_VAL};
    int rc;

    *moved = 0;
    *worst = 0.0;
    memset(&g, 0, sizeof g);
    memset(&h->sg, 0, sizeof h->sg);
    rc = qc__gap_grid_inside(ctx, region, RES * h->d, &g, &mask);
    if (rc < 0)
        return rc;
    cells = g.nx * g.ny;
    for (i = 0; i < ns; i++)
        qc__gap_seed_segment(&g, c->v[i], c->v[qc__holes_next(c, (uint32_t)i)]);
    rc = qc__gap_transform(ctx, &g);
    floor2 = (GOAL * h->d / g.h - 1.5) * (GOAL * h->d / g.h - 1.5);
    if (rc == QC_OK)
        rc = find_peaks(ctx, &g, mask, floor2, &pk, &np, &pcap);
    if (rc == QC_OK && np > 0) {
        qsort(pk, np, sizeof *pk, cmp_peak);
        h->stamp = qc__alloc_array(ctx, c->n, sizeof *h->stamp);
        h->undo = qc__alloc_array(ctx, c->n, sizeof *h->undo);
        h->was = qc__alloc_array(ctx, c->n, sizeof *h->was);
        if (h->stamp == NULL || h->undo == NULL || h->was == NULL)
            rc = QC_ENOMEM;
        else
            memset(h->stamp, 0, c->n * sizeof *h->stamp);
    }
    if (rc == QC_OK && np > 0)
        rc = qc__seg_grid_build(ctx, &h->sg, c->v, ns, qc__holes_next, c, h->d, 4.0);
    /* the raster errs by up to a cell: every peak within two of the greatest;
     * the mouths on the seams are a tier of their own, so that a wide one
     * does not hold back the holes inside (nor they it) */
    for (k = 0; rc == QC_OK && k < np; k++) {
        qc_vec2 q = qc__gap_grid_centre(&g, pk[k].at);
        double R;
        int t = pk[k].seam;
        if (first[t] == HUGE_VAL)
            first[t] = sqrt((double)pk[k].f);
        if (sqrt((double)pk[k].f) < first[t] - 1.0)
            continue;
        (void)climb(h, &q, g.h, sqrt((double)pk[k].f) * g.h, &R);
        if (R < HUGE_VAL)
            widest[t] = fmax(widest[t], R);
    }
    *worst = widest[0]; /* the holes inside judge the pass */
    goal[0] = fmax(GOAL * h->d, widest[0] - TIER * h->d);
    goal[1] = fmax(MOUTH * h->d, widest[1] - TIER * h->d);
    for (k = 0; rc == QC_OK && act && k < np; k++) {
        qc_vec2 q = qc__gap_grid_centre(&g, pk[k].at);
        double R;

        if (sqrt((double)pk[k].f) * g.h < fmin(goal[0], goal[1]) - g.h)
            break; /* (sorted) no climb from here reaches a goal */
        if (mask[pk[k].at] & 2)
            continue;
        (void)climb(h, &q, g.h, sqrt((double)pk[k].f) * g.h, &R);
        if (!(R > goal[pk[k].seam]) || R == HUGE_VAL)
            continue;
        /* a mouth is drawn in all round (its bumps hook at the seam) */
        if (pk[k].seam || !try_bumps(h, c, q, R)) { /* else drawn in, judged the same way */
            double before = local_far(h, q, R + LOCAL_PAD * h->d, HUGE_VAL);
            h->nundo = 0;
            close_in(h, c, &g, mask, q, R, fmin(SHIFT_MAX * h->d, R - AIM * h->d), (uint32_t)k);
            if (qc__holes_turns_tighter(h, c) ||
                !(local_far(h, q, R + LOCAL_PAD * h->d, before - GAIN * h->d) < before - GAIN * h->d)) {
                qc__holes_undo(h, c);
                continue;
            }
            h->nundo = 0;
        }
        (*moved)++;
        /* the discs whose bands this one moved wait for the next pass */
        block(&g, mask, q, 2.0 * (R + BAND * h->d));
    }
    qc__seg_grid_free(ctx, &h->sg);
    qc__free(ctx, h->stamp, h->stamp != NULL ? c->n * sizeof *h->stamp : 0);
    qc__free(ctx, h->undo, h->undo != NULL ? c->n * sizeof *h->undo : 0);
    qc__free(ctx, h->was, h->was != NULL ? c->n * sizeof *h->was : 0);
    h->stamp = h->undo = NULL;
    h->was = NULL;
    qc__free(ctx, pk, pcap * sizeof *pk);
    qc__free(ctx, g.f, cells * sizeof *g.f);
    qc__free(ctx, mask, cells);
    return rc;
}

int qc__meander_holes(qc_ctx *ctx, const qc_region *region, const qc__sdf *s, double d,
                      int open, qc_points *c)
{
    qc__holes h;
    qc_points prev = {0}, cur = {0}, t;
    size_t p, moved = 1, crossings = 0;
    double was = HUGE_VAL, now = 0.0;
    int rc = QC_OK;

    if (c->n < 3 || c->n > MAX_VERTICES)
        return QC_OK;
    memset(&h, 0, sizeof h);
    h.open = open;
    h.d = d;
    h.s = s;
    h.c = c;
    rc = QC__RESERVE(ctx, prev.v, prev.cap, c->n);
    if (rc == QC_OK)
        rc = QC__RESERVE(ctx, cur.v, cur.cap, c->n);
    /* each pass measures the curve it starts from (now) before it moves
     * it: one that finds the widest disc wider than the pass before did
     * (was) undoes that pass, and the phase ends (every move was judged
     * where it was made: the widest disc, blocked behind another in one
     * pass, may wait for the next) */
    for (p = 0; p <= PASSES && rc == QC_OK; p++) {
        memcpy(cur.v, c->v, c->n * sizeof *c->v);
        rc = pass(ctx, region, &h, c, p < PASSES && moved > 0, &now, &moved);
        if (rc < 0)
            break;
        if (p > 0 && now > was + GAIN * d) {
            memcpy(c->v, prev.v, c->n * sizeof *c->v);
            break;
        }
        if (moved > 0)
            rc = qc_path_self_crossings(ctx, c->v, c->n, !open, &crossings);
        if (rc == QC_OK && crossings > 0) { /* not by construction: undone */
            memcpy(c->v, cur.v, c->n * sizeof *c->v);
            break;
        }
        if (moved == 0)
            break;
        t = prev; /* the curve this pass started from is the one to go back to */
        prev = cur;
        cur = t;
        was = now;
    }
    qc_points_free(ctx, &prev);
    qc_points_free(ctx, &cur);
    return rc;
}
