/*
 * Closing the holes the evolution leaves (issue 17: farthest fabric and
 * evenness). The growth settles where its short-range forces balance, and
 * where channels meet or bend (a T or an L of lines d apart) the fabric
 * lies 0.65-0.7 d from any stitch, not the d/2 of evenly spaced lines. So,
 * a few passes: a distance raster of the curve finds the widest empty
 * discs (its local maxima, climbed to the exact distance), and round each
 * disc within a little of the widest the curve is drawn in towards its
 * centre: every vertex in a band beyond the disc moves radially inward,
 * by up to the excess, the share falling smoothly to nothing across the
 * band, and less where the channel behind it would grow too wide. Lines
 * near the seams move only towards them (they cover the seams). Radial
 * moves of at most 0.15 d, ordered along each ray, fold nothing; no vertex
 * is added (the thread comes from the narrower channels round a hole).
 * A pass is judged by the next one's measure: one after which the widest
 * disc is no narrower is undone and the phase ends, as it is should the
 * curve cross itself (the hard invariant, checked on the whole curve).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "family_meander.h"
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
#define PASSES 6
#define MAX_VERTICES 8000 /* a work budget: larger curves (a 15 x 15 in block at
                           * 0.4 in, whose middle settles during the growth) are
                           * left as grown, each pass being global */
#define TIER 0.04       /* a pass closes the discs within this of the widest, times d */
#define GAIN 0.003      /* a pass is kept if the widest disc shrank by this, times d */

typedef struct holes {
    const qc_points *c;
    int open;
    double d;
    const qc__sdf *s;
    qc__seg_grid sg;
    uint32_t *stamp; /* per vertex: the last disc that moved it, + 1 */
} holes;

static uint32_t next_seg(const void *ud, uint32_t k)
{
    const qc_points *c = ud;
    return k + 1 == c->n ? 0 : k + 1;
}

/* The segment of c nearest q (its first vertex), searching the cells round
 * q out to reach; *dist its distance (HUGE_VAL: none within reach). */
static size_t nearest(const holes *h, qc_vec2 q, double reach, double *dist)
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
                e = qc__seg_dist2(q, h->c->v[i], h->c->v[next_seg(h->c, (uint32_t)i)]);
                if (e < b2 || (e == b2 && i < best)) {
                    b2 = e;
                    best = i;
                }
            }
    *dist = b2 < HUGE_VAL ? sqrt(b2) : HUGE_VAL;
    return best;
}

/* The disc at *q grown: *q moved (8 directions, steps from h down to
 * h/4) while its exact distance to the curve grows; returns the nearest
 * segment, *R the distance (the raster's peak is a cell off). */
static size_t climb(const holes *h, qc_vec2 *q, double step, double *R)
{
    size_t s = nearest(h, *q, 2.0 * h->d, R), k, t;

    for (t = 0; t < 3; t++, step *= 0.5)
        for (k = 0; k < 8; k++) {
            double ang = QC_PI * (double)k / 4.0, r;
            qc_vec2 p = QC__V2(q->x + step * qc_cos(ang), q->y + step * qc_sin(ang));
            size_t j;
            if (qc__sdf_at(h->s, p) < 0.0)
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

/* Draws the vertices round the disc at q (radius R) in towards q by up
 * to shift, each as far as the space behind it allows; stamp marks them
 * for disc number k. */
static void close_in(holes *h, qc_points *c, const qc__gap_grid *g, const unsigned char *mask,
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
                c->v[i] = m;
            }
}

/* One pass: *worst receives the widest disc's exact radius (the greatest
 * of the raster's first peaks, climbed); with act, the discs wider than
 * the goal and than *worst less TIER are closed in (*moved: how many). */
static int pass(qc_ctx *ctx, const qc_region *region, holes *h, qc_points *c, int act,
                double *worst, size_t *moved)
{
    qc__gap_grid g;
    unsigned char *mask = NULL;
    peak *pk = NULL;
    size_t np = 0, pcap = 0, cells, i, k, ns = h->open ? c->n - 1 : c->n;
    double floor2, goal;
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
        qc__gap_seed_segment(&g, c->v[i], c->v[next_seg(c, (uint32_t)i)]);
    rc = qc__gap_transform(ctx, &g);
    floor2 = (GOAL * h->d / g.h - 1.5) * (GOAL * h->d / g.h - 1.5);
    for (i = 0; rc == QC_OK && i < cells; i++) { /* the peaks: no neighbour greater */
        size_t x = i % g.nx, y = i / g.nx;
        int top = mask[i] && (double)g.f[i] > floor2 && g.f[i] < (float)QC__GAP_FAR;
        for (k = 0; k < 9 && top; k++) {
            long xx = (long)x + (long)(k % 3) - 1, yy = (long)y + (long)(k / 3) - 1;
            size_t at;
            if (k == 4 || xx < 0 || yy < 0 || xx >= (long)g.nx || yy >= (long)g.ny)
                continue;
            at = (size_t)yy * g.nx + (size_t)xx;
            top = g.f[at] < g.f[i] || (g.f[at] == g.f[i] && at > i);
        }
        if (top) {
            rc = QC__RESERVE(ctx, pk, pcap, np + 1);
            if (rc < 0)
                break;
            pk[np].f = g.f[i];
            pk[np++].at = (uint32_t)i;
        }
    }
    if (rc == QC_OK && np > 0) {
        qsort(pk, np, sizeof *pk, cmp_peak);
        h->stamp = qc__alloc_array(ctx, c->n, sizeof *h->stamp);
        if (h->stamp == NULL)
            rc = QC_ENOMEM;
        else
            memset(h->stamp, 0, c->n * sizeof *h->stamp);
    }
    if (rc == QC_OK && np > 0)
        rc = qc__seg_grid_build(ctx, &h->sg, c->v, ns, next_seg, c, h->d, 4.0);
    /* the raster errs by up to a cell: every peak within two of the greatest */
    for (k = 0; rc == QC_OK && k < np &&
                sqrt((double)pk[k].f) >= sqrt((double)pk[0].f) - 2.0; k++) {
        qc_vec2 q = qc__gap_grid_centre(&g, pk[k].at);
        double R;
        (void)climb(h, &q, g.h, &R);
        if (R < HUGE_VAL)
            *worst = fmax(*worst, R);
    }
    goal = fmax(GOAL * h->d, *worst - TIER * h->d);
    for (k = 0; rc == QC_OK && act && k < np; k++) {
        qc_vec2 q = qc__gap_grid_centre(&g, pk[k].at);
        double R;

        if (sqrt((double)pk[k].f) * g.h < goal - 2.0 * g.h)
            break; /* (sorted) no climb from here reaches the goal */
        if (mask[pk[k].at] & 2)
            continue;
        (void)climb(h, &q, g.h, &R);
        if (!(R > goal) || R == HUGE_VAL)
            continue;
        close_in(h, c, &g, mask, q, R, fmin(SHIFT_MAX * h->d, R - AIM * h->d), (uint32_t)k);
        (*moved)++;
        /* the discs whose bands this one moved wait for the next pass */
        block(&g, mask, q, 2.0 * (R + BAND * h->d));
    }
    qc__seg_grid_free(ctx, &h->sg);
    qc__free(ctx, h->stamp, h->stamp != NULL ? c->n * sizeof *h->stamp : 0);
    h->stamp = NULL;
    qc__free(ctx, pk, pcap * sizeof *pk);
    qc__free(ctx, g.f, cells * sizeof *g.f);
    qc__free(ctx, mask, cells);
    return rc;
}

int qc__meander_holes(qc_ctx *ctx, const qc_region *region, const qc__sdf *s, double d,
                      int open, qc_points *c)
{
    holes h;
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
     * it: one that finds the widest disc no narrower than the pass before
     * did (was) undoes that pass, and the phase ends */
    for (p = 0; p <= PASSES && rc == QC_OK; p++) {
        memcpy(cur.v, c->v, c->n * sizeof *c->v);
        rc = pass(ctx, region, &h, c, p < PASSES && moved > 0, &now, &moved);
        if (rc < 0)
            break;
        if (p > 0 && !(now < was - GAIN * d)) {
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
