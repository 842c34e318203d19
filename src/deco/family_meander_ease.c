/*
 * Easing and rounding the curve's tightest turns. The evolution fairs a vertex that
 * turns tighter than the turn radius, but the boundary's wall pushes it
 * back: where the curve hugs a convex corner of the region it follows the
 * clearance's own sharp corner, and a tongue (family_meander_reach.c)
 * leaves the curve at an angle. Without the wall, each such vertex moves
 * halfway towards the midpoint of its neighbours (into the bend, away from
 * the boundary), a few passes over; a move is kept only if the vertex stays
 * inside and its two segments cross nothing (checked against the segments
 * near it, binned in a grid). The spline through a corner still turns
 * tighter than its three vertices say, so a last pass (qc__meander_round)
 * measures each vertex's turn over the turn radius along the curve, as the
 * tests do, and rounds what is still tight: inwards where that bares no
 * seam, else outwards (the corner stays, its legs spread), respacing the
 * vertices at the tight turns every round, then waves what it left straight.
 */
#include <math.h>
#include <string.h>

#include "family_meander.h"

#define EASE_PASSES 6
#define EASE_STEP 0.5    /* share of the way to the neighbours' midpoint */
#define EASE_CLEAR 0.05  /* a moved vertex stays this far inside, times d */
#define EASE_BELOW 0.95  /* eased: turning tighter than this times the radius
                          * (a tongue's tip turns at the radius itself) */
#define WAVE_RUN 1.5     /* runs longer than this, times d, are waved first ... */
#define WAVE_AGAIN 1.5   /* ... and these once more after the rounding */
#define ROUND_PASSES 10  /* rounds of rounding (tight runs move half way each) */
#define ROUND_BELOW 1.0  /* rounded: turning tighter than this times the radius */
#define EASY_TURN 0.7    /* cos of a turn (45 degrees) surely wider than ROUND_BELOW */
#define ROUND_DENSE 0.5  /* segments at a tight turn split this short, times the radius */
#define ROUND_STEP 0.5   /* share of the way to the middle of the stencil */
#define ROUND_TIP 0.105  /* runs with a vertex this near the boundary, times d, are
                          * rounded last: a tongue's tip, deep in a corner (the
                          * clearance is 0.22 d; the tips reach.c draws lie 0.08 d
                          * off the seams), inwards only if outwards fails */
#define TIP_ACUTE 50.0   /* ... and inwards only near a corner sharper than this, degrees
                          * (the blocks' tips keep their seams) ... */
#define TIP_REACH 1.25   /* ... within this, times d */
#define ROUND_REACH 2.0  /* rounded outwards: the curve this far either side of the
                          * run moves too, times the radius */
#define ROUND_OUT_GAIN 1.5 /* ... back out by this times the run's mean move: the
                          * corner moves out a little, towards the seam it covers */
#define ROUND_SIDE 24    /* ... but at most this many vertices either side */
#define ROUND_OUT_MAX 64 /* ... and at most this many in all */
#define ROUND_CLUMP 0.2  /* vertices nearer than this, times the radius, merge */
#define SEAM_MM 6.35     /* issue 17: every seam within 1/4 in of a stitch, kept as it was */
#define SEAM_OFF 0.05    /* mm: a sample further outside is off the seam (past a corner) */
#define SEAM_SAMPLES 8   /* seam points on either side of a vertex, out to SEAM_MM */
#define OUT_SAMPLES 14   /* ... and out to 1.75 SEAM_MM, rounding outwards */

/* Radius of the circle through a, p, b (huge when they are in line). */
static double circumradius(qc_vec2 a, qc_vec2 p, qc_vec2 b)
{
    double cr = fabs((p.x - a.x) * (b.y - p.y) - (p.y - a.y) * (b.x - p.x));
    double l = qc_hypot(p.x - a.x, p.y - a.y) * qc_hypot(b.x - p.x, b.y - p.y) *
               qc_hypot(a.x - b.x, a.y - b.y);

    return cr > 1e-12 * l ? l / (2.0 * cr) : 1e30;
}

/* The curve's vertices binned in square cells (positions as binned). */
typedef struct vbins {
    double x0, y0, h;
    size_t gx, gy;
    size_t *start; /* gx gy + 1 */
    uint32_t *idx;
} vbins;

static size_t vcell(const vbins *b, qc_vec2 p, size_t *cx, size_t *cy)
{
    *cx = qc__grid_cell((p.x - b->x0) / b->h, b->gx);
    *cy = qc__grid_cell((p.y - b->y0) / b->h, b->gy);
    return *cy * b->gx + *cx;
}

static int vbins_build(qc_ctx *ctx, vbins *b, const qc_points *c, double h)
{
    qc_vec2 lo = c->v[0], hi = c->v[0];
    size_t i, nc, cx, cy;

    for (i = 1; i < c->n; i++) { /* (no NaN: compared, not fmin's call) */
        qc_vec2 p = c->v[i];
        lo.x = p.x < lo.x ? p.x : lo.x, lo.y = p.y < lo.y ? p.y : lo.y;
        hi.x = p.x > hi.x ? p.x : hi.x, hi.y = p.y > hi.y ? p.y : hi.y;
    }
    while ((hi.x - lo.x) / h * ((hi.y - lo.y) / h) > 4.0 * (double)c->n + 64.0)
        h *= 1.5;
    b->h = h;
    b->x0 = lo.x;
    b->y0 = lo.y;
    b->gx = (size_t)((hi.x - lo.x) / h) + 1;
    b->gy = (size_t)((hi.y - lo.y) / h) + 1;
    nc = b->gx * b->gy;
    b->start = qc__alloc_array(ctx, nc + 1, sizeof *b->start);
    b->idx = qc__alloc_array(ctx, c->n, sizeof *b->idx);
    if (b->start == NULL || b->idx == NULL)
        return QC_ENOMEM;
    memset(b->start, 0, (nc + 1) * sizeof *b->start);
    for (i = 0; i < c->n; i++)
        b->start[vcell(b, c->v[i], &cx, &cy) + 1]++;
    for (i = 0; i < nc; i++)
        b->start[i + 1] += b->start[i];
    for (i = 0; i < c->n; i++)
        b->idx[b->start[vcell(b, c->v[i], &cx, &cy)]++] = (uint32_t)i;
    memmove(b->start + 1, b->start, nc * sizeof *b->start);
    b->start[0] = 0;
    return QC_OK;
}

static void vbins_free(qc_ctx *ctx, vbins *b, size_t n)
{
    qc__free(ctx, b->start, (b->gx * b->gy + 1) * sizeof *b->start);
    qc__free(ctx, b->idx, n * sizeof *b->idx);
}

/* Whether segment (i, j) of c, for i, j neighbours of a moved vertex k,
 * crosses a segment of c not next to it: every segment with a vertex in
 * the cells round p (the cells are over twice the longest segment). */
static int seg_crosses(const qc_points *c, int open, const vbins *b, size_t k, qc_vec2 p,
                       size_t i, size_t j)
{
    size_t n = c->n, cx, cy, x, y, e;

    vcell(b, p, &cx, &cy);
    for (y = cy ? cy - 1 : 0; y <= cy + 1 && y < b->gy; y++)
        for (x = cx ? cx - 1 : 0; x <= cx + 1 && x < b->gx; x++)
            for (e = b->start[y * b->gx + x]; e < b->start[y * b->gx + x + 1]; e++) {
                size_t s = b->idx[e], t = s + 1 == n ? 0 : s + 1;
                if (open && t == 0)
                    continue;
                if (s == i || s == j || t == i || t == j || s == k || t == k)
                    continue; /* next to it, or the moved vertex's own */
                if (qc__segs_cross_proper(c->v[i], c->v[j], c->v[s], c->v[t]))
                    return 1;
                /* the segment ending at s too (s's bin stands for both) */
                t = s;
                s = s == 0 ? (open ? SIZE_MAX : n - 1) : s - 1;
                if (s == SIZE_MAX || s == i || s == j || t == i || t == j || s == k || t == k)
                    continue;
                if (qc__segs_cross_proper(c->v[i], c->v[j], c->v[s], c->v[t]))
                    return 1;
            }
    return 0;
}

int qc__meander_seg_inside(const qc__sdf *s, qc_vec2 a, qc_vec2 b, double inner)
{
    double len = qc_hypot(b.x - a.x, b.y - a.y), t = 0.0, floor_step = 1e-3 * inner;

    for (;;) { /* sphere tracing: nothing of the boundary within v of q */
        double u = len > 0.0 ? fmin(t, len) / len : 0.0;
        double v = qc__sdf_exact(s, QC__V2(a.x + u * (b.x - a.x), a.y + u * (b.y - a.y)), NULL);
        if (v < inner)
            return 0;
        if (t >= len)
            return 1;
        t += fmax(v - inner, floor_step);
    }
}

/* seg[k] the length of c's segment from vertex k to the next (the last
 * one closing the curve); seg holds c->n. */
static void seg_lengths(const qc_points *c, double *seg)
{
    size_t n = c->n, k;

    for (k = 0; k < n; k++) {
        qc_vec2 a = c->v[k], b = c->v[k + 1 == n ? 0 : k + 1];
        seg[k] = qc_hypot(b.x - a.x, b.y - a.y);
    }
}

/* The point arc length len from vertex i along c, backwards (dir < 0) or
 * forwards; an open curve's end where it is nearer. seg: c's segment
 * lengths (seg_lengths: a length is the same to the bit either way). */
static qc_vec2 along(const qc_points *c, const double *seg, int open, size_t i, int dir,
                     double len)
{
    size_t n = c->n, k = i, steps;

    for (steps = 0; steps < n; steps++) {
        size_t j;
        double sj;
        if (dir < 0 && k == 0 && open)
            return c->v[0];
        if (dir > 0 && k + 1 == n && open)
            return c->v[n - 1];
        j = dir < 0 ? (k == 0 ? n - 1 : k - 1) : (k + 1 == n ? 0 : k + 1);
        sj = seg[dir < 0 ? j : k];
        if (sj >= len) {
            double t = len / sj;
            return QC__V2(c->v[k].x + t * (c->v[j].x - c->v[k].x),
                          c->v[k].y + t * (c->v[j].y - c->v[k].y));
        }
        len -= sj;
        k = j;
    }
    return c->v[i];
}

/* Whether vertex i turns tighter than ROUND_BELOW times the radius, as
 * the tests measure a turn: the circle through it and the points the
 * radius before and after it along c (for an arc, its own radius; at a
 * corner the circle the spline could at best round it to). */
static int turns_tight(const qc_points *c, const double *seg, int open, size_t i, double turn)
{
    size_t n = c->n, ia = i == 0 ? n - 1 : i - 1, ib = i + 1 == n ? 0 : i + 1;

    if (open && (i == 0 || i + 1 == n))
        return 0;
    if (seg[ia] >= turn && seg[i] >= turn) {
        /* the points the radius either side lie on i's own segments: the
         * circle through them and i is turn / (2 cos(half the angle at i))
         * across, 1.3 radii or more where the curve turns by less than
         * EASY_TURN (the answer as measured, without measuring) */
        qc_vec2 a = c->v[ia], p = c->v[i], b = c->v[ib];
        if ((p.x - a.x) * (b.x - p.x) + (p.y - a.y) * (b.y - p.y) > EASY_TURN * seg[ia] * seg[i])
            return 0;
    }
    return circumradius(along(c, seg, open, i, -1, turn), c->v[i],
                        along(c, seg, open, i, 1, turn)) < ROUND_BELOW * turn;
}

/* c with the segments at a tight vertex split into pieces of at most
 * ROUND_DENSE times the radius (the same polyline, with room to bend).
 * seg: room for c->n lengths. */
static int densify(qc_ctx *ctx, const qc_points *c, int open, double turn, double *seg,
                   qc_points *out)
{
    size_t n = c->n, i, k;
    unsigned char prev_tight = 0, first_tight;
    int rc = QC_OK;

    out->n = 0;
    seg_lengths(c, seg);
    first_tight = (unsigned char)turns_tight(c, seg, open, 0, turn);
    prev_tight = first_tight;
    for (i = 0; i < n && rc == QC_OK; i++) {
        size_t j = i + 1 == n ? 0 : i + 1;
        qc_vec2 a = c->v[i], b = c->v[j];
        unsigned char next_tight =
            j == 0 ? first_tight : (unsigned char)turns_tight(c, seg, open, j, turn);
        double len = seg[i];
        size_t m = (size_t)ceil(len / (ROUND_DENSE * turn));

        rc = qc_points_push(ctx, out, a);
        if ((prev_tight || next_tight) && !(open && j == 0))
            for (k = 1; k < m && rc == QC_OK; k++)
                rc = qc_points_push(ctx, out, QC__V2(a.x + (double)k / (double)m * (b.x - a.x),
                                                     a.y + (double)k / (double)m * (b.y - a.y)));
        prev_tight = next_tight;
    }
    return rc;
}

/* Distance from q to segment ab. */
static double seg_dist(qc_vec2 q, qc_vec2 a, qc_vec2 b)
{
    double ux = b.x - a.x, uy = b.y - a.y, l2 = ux * ux + uy * uy, t = 0.0;

    if (l2 > 0.0)
        t = fmax(0.0, fmin(1.0, ((q.x - a.x) * ux + (q.y - a.y) * uy) / l2));
    return qc_hypot(a.x + t * ux - q.x, a.y + t * uy - q.y);
}

/* Whether segment ab passes within SEAM_MM of q. A segment whose box is
 * twice that away in x or y is not measured: its distance, rounding and
 * all, is over SEAM_MM (the same answers, fewer roots). */
static int near_seam(qc_vec2 q, qc_vec2 a, qc_vec2 b)
{
    double m = 2.0 * SEAM_MM, x0 = q.x - m, x1 = q.x + m, y0 = q.y - m, y1 = q.y + m;

    if ((a.x < x0 && b.x < x0) || (a.x > x1 && b.x > x1) || (a.y < y0 && b.y < y0) ||
        (a.y > y1 && b.y > y1))
        return 0;
    return seg_dist(q, a, b) <= SEAM_MM;
}

/* Whether moving vertex i of c to m leaves a piece of seam near it further
 * than SEAM_MM from the curve that was within it: the seam is sampled
 * along the tangent at the boundary point nearest the vertex, against the
 * two moved segments and every other segment binned near. */
static int bares_seam(const qc_points *c, int open, const vbins *b, const qc__sdf *s, size_t i,
                      qc_vec2 m)
{
    size_t n = c->n, ia = i == 0 ? n - 1 : i - 1, ib = i + 1 == n ? 0 : i + 1;
    qc_vec2 g, p = c->v[i], f;
    double v = qc__sdf_exact(s, p, &g), step = SEAM_MM / SEAM_SAMPLES;
    int k;

    if (v > SEAM_MM)
        return 0; /* it covers no seam */
    f = QC__V2(p.x - v * g.x, p.y - v * g.y);
    for (k = -SEAM_SAMPLES; k <= SEAM_SAMPLES; k++) {
        qc_vec2 q = QC__V2(f.x - (double)k * step * g.y, f.y + (double)k * step * g.x);
        size_t cx, cy, x, y, e;
        int covered;
        if (qc_hypot(q.x - p.x, q.y - p.y) > SEAM_MM || qc__sdf_exact(s, q, NULL) < -SEAM_OFF)
            continue; /* p did not cover it, or past a corner: no seam */
        covered = near_seam(q, m, c->v[ib]) ||
                  (!(open && i == 0) && near_seam(q, c->v[ia], m));
        vcell(b, q, &cx, &cy);
        for (y = cy ? cy - 1 : 0; !covered && y <= cy + 1 && y < b->gy; y++)
            for (x = cx ? cx - 1 : 0; !covered && x <= cx + 1 && x < b->gx; x++)
                for (e = b->start[y * b->gx + x]; !covered && e < b->start[y * b->gx + x + 1]; e++) {
                    size_t j = b->idx[e], j1 = j + 1 == n ? 0 : j + 1;
                    if (j == i || j1 == i || (open && j1 == 0))
                        continue;
                    covered = near_seam(q, c->v[j], c->v[j1]);
                }
        if (!covered)
            return 1;
    }
    return 0;
}

/* Whether a corner of the region sharper than TIP_ACUTE lies within reach of p. */
static int near_acute(const qc__sdf *s, qc_vec2 p, double reach)
{
    const qc_region *r = s->region;
    size_t i;

    for (i = 0; i < r->nv; i++)
        if (qc_hypot(r->v[i].x - p.x, r->v[i].y - p.y) < reach &&
            qc_region_corner_angle(r, i) < TIP_ACUTE)
            return 1;
    return 0;
}

/* Moves the run of tight vertices from vertex first, count of them, each
 * part of the way to the middle of the points the radius before and after
 * it (to[]): all of them, or none where one would come within EASE_CLEAR d
 * of the boundary, bare a seam or cross the curve (a corner half rounded
 * turns tighter than before). A run with a vertex within tip of the
 * boundary (a tongue's tip) is left, but for acute > 0 where a corner
 * sharper than TIP_ACUTE lies within acute of it: that one may bare the
 * seam (the turn radius is a machine limit, the corner's fabric not).
 * Returns 1 if moved. */
static int round_run(qc_points *c, int open, const vbins *b, const qc__sdf *s, double inner,
                     double tip, double acute, size_t first, size_t count, const qc_vec2 *to,
                     qc_vec2 *was)
{
    size_t n = c->n, k, i = first;
    int at_tip = 0;

    for (k = 0; k < count && !at_tip; k++, i = i + 1 == n ? 0 : i + 1)
        at_tip = qc__sdf_exact(s, c->v[i], NULL) < tip;
    if (at_tip && !(acute > 0.0 && near_acute(s, c->v[first], acute)))
        return 0;
    for (k = 0, i = first; k < count; k++, i = i + 1 == n ? 0 : i + 1) {
        size_t ia = i == 0 ? n - 1 : i - 1, ib = i + 1 == n ? 0 : i + 1;
        qc_vec2 m = to[i];
        was[k] = c->v[i];
        if (!qc__meander_seg_inside(s, c->v[ia], m, inner) ||
            !qc__meander_seg_inside(s, m, c->v[ib], inner) ||
            (!at_tip && bares_seam(c, open, b, s, i, m)))
            break;
        c->v[i] = m;
        if (seg_crosses(c, open, b, i, m, ia, i) || seg_crosses(c, open, b, i, m, i, ib)) {
            c->v[i] = was[k];
            break;
        }
    }
    if (k == count)
        return 1;
    while (k-- > 0) { /* undone, last first */
        i = i == 0 ? n - 1 : i - 1;
        c->v[i] = was[k];
    }
    return 0;
}

/* Seam point k (-OUT_SAMPLES..OUT_SAMPLES) near p: along the tangent at
 * the boundary point f nearest p (g the distance field's gradient at p),
 * drawn back onto the boundary. */
static qc_vec2 seam_sample(const qc__sdf *s, qc_vec2 f, qc_vec2 g, int k)
{
    double step = SEAM_MM / SEAM_SAMPLES, v;
    qc_vec2 q = QC__V2(f.x - (double)k * step * g.y, f.y + (double)k * step * g.x);

    v = qc__sdf_exact(s, q, &g);
    return QC__V2(q.x - v * g.x, q.y - v * g.y);
}

/* Whether a segment of c (binned in b) passes within SEAM_MM of q. */
static int seam_covered(const qc_points *c, int open, const vbins *b, qc_vec2 q)
{
    size_t n = c->n, cx, cy, x, y, e;

    vcell(b, q, &cx, &cy);
    for (y = cy ? cy - 1 : 0; y <= cy + 1 && y < b->gy; y++)
        for (x = cx ? cx - 1 : 0; x <= cx + 1 && x < b->gx; x++)
            for (e = b->start[y * b->gx + x]; e < b->start[y * b->gx + x + 1]; e++) {
                size_t j = b->idx[e], j1 = j + 1 == n ? 0 : j + 1, j0 = j == 0 ? n - 1 : j - 1;
                if (!(open && j1 == 0) && near_seam(q, c->v[j], c->v[j1]))
                    return 1;
                if (!(open && j == 0) && near_seam(q, c->v[j0], c->v[j]))
                    return 1;
            }
    return 0;
}

/* Bit k + OUT_SAMPLES set for each of p's seam samples that c covers. */
static uint32_t seam_cover(const qc_points *c, int open, const vbins *b, const qc__sdf *s,
                           qc_vec2 p)
{
    uint32_t bits = 0;
    qc_vec2 g, f;
    double v = qc__sdf_exact(s, p, &g);
    int k;

    if (v > SEAM_MM)
        return 0; /* no seam near */
    f = QC__V2(p.x - v * g.x, p.y - v * g.y);
    for (k = -OUT_SAMPLES; k <= OUT_SAMPLES; k++)
        if (seam_covered(c, open, b, seam_sample(s, f, g, k)))
            bits |= (uint32_t)1 << (k + OUT_SAMPLES);
    return bits;
}

/* The vertex after i of a closed curve of n. */
static size_t j_next(size_t n, size_t i)
{
    return i + 1 == n ? 0 : i + 1;
}

/* The vertex steps from i along c (dir < 0 backwards), or SIZE_MAX past an
 * open curve's end vertex (which stays). */
static size_t step_from(size_t n, int open, size_t i, int dir)
{
    if (dir < 0)
        return i == 0 ? (open ? SIZE_MAX : n - 1) : (open && i == 1 ? SIZE_MAX : i - 1);
    return i + 1 == n ? (open ? SIZE_MAX : 0) : (open && i + 2 == n ? SIZE_MAX : i + 1);
}

/* Walks c from vertex i in direction dir (-1, 1) while the arc from i
 * stays under reach, for ROUND_SIDE vertices at most: arcs[k] the arc to
 * the k-th vertex passed, *end the last vertex reached (i if none); returns
 * how many were passed. */
static size_t walk_out(const qc_points *c, int open, size_t i, int dir, double reach,
                       double *arcs, size_t *end)
{
    size_t k;
    double arc = 0.0;

    *end = i;
    for (k = 0; k < ROUND_SIDE; k++) {
        size_t j = step_from(c->n, open, i, dir);
        if (j == SIZE_MAX)
            break;
        arc += qc_hypot(c->v[j].x - c->v[i].x, c->v[j].y - c->v[i].y);
        if (arc >= reach)
            break;
        arcs[k] = arc;
        *end = i = j;
    }
    return k;
}

/* Rounds the run of tight vertices from first, count of them, outwards
 * where round_run() could not round it inwards (a hook that leaves a run
 * along a seam: cut, it bares the seam it covered): the run moves to[] as
 * there while it and the curve out to ROUND_REACH radii either side move
 * back out by the run's mean move, fading with the distance from the run.
 * The corner stays about where it was, its legs spread, its turn widens.
 * Checked as round_run() checks; all or nothing. Returns 1 if moved. */
static int round_out(qc_points *c, int open, const vbins *b, const qc__sdf *s, double inner,
                     double turn, size_t first, size_t count, const qc_vec2 *to, qc_vec2 *was)
{
    size_t n = c->n, k, i = first, last = first, lo = first, before, after, moved = 0, m;
    double mx = 0.0, my = 0.0, reach = ROUND_REACH * turn;
    double dist[ROUND_OUT_MAX], back[ROUND_SIDE], fwd[ROUND_SIDE];
    uint32_t cover[2 * ROUND_OUT_MAX + 1];
    qc_vec2 at[2 * ROUND_OUT_MAX + 1];

    if (count > ROUND_OUT_MAX)
        return 0;
    for (k = 0; k < count; k++, i = j_next(n, i)) {
        mx += ROUND_OUT_GAIN * (to[i].x - c->v[i].x) / (double)count;
        my += ROUND_OUT_GAIN * (to[i].y - c->v[i].y) / (double)count;
        last = i;
    }
    /* the stretch that moves: out to reach along c either side of the run,
     * each vertex's arc length from the run in dist[] */
    before = walk_out(c, open, first, -1, reach, back, &lo);
    after = walk_out(c, open, last, 1, reach, fwd, &i);
    m = before + count + after;
    if (m + 2 >= n || m > ROUND_OUT_MAX)
        return 0;
    for (k = 0; k < m; k++)
        dist[k] = k < before           ? back[before - 1 - k]
                  : k < before + count ? 0.0
                                       : fwd[k - before - count];
    /* the seam near its vertices and the middles of its segments, as covered */
    for (k = 0, i = lo == 0 ? n - 1 : lo - 1; k <= m; k++, i = j_next(n, i)) {
        size_t j = j_next(n, i);
        at[2 * k] = QC__V2(0.5 * (c->v[i].x + c->v[j].x), 0.5 * (c->v[i].y + c->v[j].y));
        if (k < m)
            at[2 * k + 1] = c->v[j];
    }
    for (k = 0; k < 2 * m + 1; k++)
        cover[k] = seam_cover(c, open, b, s, at[k]);
    for (k = 0, i = lo; k < m; k++, i = j_next(n, i)) {
        size_t ia = i == 0 ? n - 1 : i - 1, ib = j_next(n, i);
        double w = 1.0 - dist[k] / reach;
        qc_vec2 q = k >= before && k < before + count ? to[i] : c->v[i];
        was[k] = c->v[i];
        q = QC__V2(q.x - w * mx, q.y - w * my);
        if (!qc__meander_seg_inside(s, c->v[ia], q, inner) ||
            !qc__meander_seg_inside(s, q, c->v[ib], inner))
            break;
        c->v[i] = q;
        if (seg_crosses(c, open, b, i, q, ia, i) || seg_crosses(c, open, b, i, q, i, ib)) {
            c->v[i] = was[k];
            break;
        }
        moved++;
    }
    for (k = 0; moved == m && k < 2 * m + 1; k++) /* no seam it covered left bare */
        if ((cover[k] & ~seam_cover(c, open, b, s, at[k])) != 0)
            break;
    if (moved == m && k == 2 * m + 1)
        return 1;
    for (k = 0, i = lo; k < moved; k++, i = j_next(n, i)) /* undone */
        c->v[i] = was[k];
    return 0;
}

/* c with the vertices closer than ROUND_CLUMP radii to the one before
 * dropped (rounding a corner gathers them), then split again at the tight
 * ones (densify): the rounding keeps room to bend. seg: room for c->n
 * lengths. */
static int respace(qc_ctx *ctx, qc_points *c, int open, double turn, double *seg)
{
    qc_points dense = {0};
    size_t i, k = 1, n = c->n;
    int rc;

    for (i = 1; i < n; i++) {
        qc_vec2 a = c->v[k - 1], p = c->v[i];
        if (!(open && i + 1 == n) && qc_hypot(p.x - a.x, p.y - a.y) < ROUND_CLUMP * turn)
            continue;
        c->v[k++] = p;
    }
    c->n = k;
    rc = densify(ctx, c, open, turn, seg, &dense);
    if (rc == QC_OK) {
        qc_points t = *c;
        *c = dense;
        dense = t;
    }
    qc_points_free(ctx, &dense);
    return rc;
}

/* The per-vertex scratch of the rounding, for n vertices. */
typedef struct round_buf {
    unsigned char *tight;
    qc_vec2 *to, *was;
    double *seg; /* the segment lengths */
    size_t cap;
} round_buf;

static void round_buf_free(qc_ctx *ctx, round_buf *r)
{
    qc__free(ctx, r->tight, r->cap);
    qc__free(ctx, r->to, r->cap * sizeof *r->to);
    qc__free(ctx, r->was, r->cap * sizeof *r->was);
    qc__free(ctx, r->seg, r->cap * sizeof *r->seg);
    memset(r, 0, sizeof *r);
}

static int round_buf_fit(qc_ctx *ctx, round_buf *r, size_t n)
{
    if (n <= r->cap)
        return QC_OK;
    round_buf_free(ctx, r);
    r->tight = qc__alloc(ctx, n);
    r->to = qc__alloc_array(ctx, n, sizeof *r->to);
    r->was = qc__alloc_array(ctx, n, sizeof *r->was);
    r->seg = qc__alloc_array(ctx, n, sizeof *r->seg);
    r->cap = n;
    return r->tight == NULL || r->to == NULL || r->was == NULL || r->seg == NULL ? QC_ENOMEM
                                                                                 : QC_OK;
}

int qc__meander_round(qc_ctx *ctx, qc_points *c, int open, double turn, const qc__sdf *s,
                      double d)
{
    round_buf r;
    size_t pass, i, n;
    double longest = 0.0;
    int rc;

    if (c->n < 4 || !(turn > 0.0))
        return QC_OK;
    memset(&r, 0, sizeof r);
    rc = qc__meander_wave(ctx, c, open, d, WAVE_RUN, s); /* first: a wave turns gently */
    for (pass = 0; pass < ROUND_PASSES && rc == QC_OK; pass++) {
        vbins bins;
        size_t moved = 0, start = 0, seen;

        rc = round_buf_fit(ctx, &r, c->n); /* dropping clumps only shortens c */
        if (rc == QC_OK)
            rc = respace(ctx, c, open, turn, r.seg);
        n = c->n;
        if (rc == QC_OK)
            rc = round_buf_fit(ctx, &r, n);
        if (rc < 0 || n < 4)
            break;
        seg_lengths(c, r.seg);
        if (pass == 0)
            for (i = 0; i + (open ? 1 : 0) < n; i++)
                longest = fmax(longest, r.seg[i]);
        for (i = 0; i < n; i++) {
            r.tight[i] = (unsigned char)turns_tight(c, r.seg, open, i, turn);
            if (r.tight[i]) {
                qc_vec2 a = along(c, r.seg, open, i, -1, turn), b = along(c, r.seg, open, i, 1, turn);
                qc_vec2 p = c->v[i];
                r.to[i] = QC__V2(p.x + ROUND_STEP * (0.5 * (a.x + b.x) - p.x),
                                 p.y + ROUND_STEP * (0.5 * (a.y + b.y) - p.y));
            } else {
                start = i + 1 == n ? 0 : i + 1; /* a run never wraps past here */
            }
        }
        if (open)
            start = 0;
        memset(&bins, 0, sizeof bins);
        rc = vbins_build(ctx, &bins, c, 2.5 * longest + 1e-9);
        for (seen = 0, i = start; seen < n && rc == QC_OK;) {
            size_t count = 0, j = i;
            while (seen + count < n && r.tight[j]) {
                count++;
                j = j + 1 == n ? 0 : j + 1;
            }
            if (count > 0) {
                int ok = round_run(c, open, &bins, s, EASE_CLEAR * d, ROUND_TIP * d, 0.0, i,
                                   count, r.to, r.was);
                if (!ok)
                    ok = round_out(c, open, &bins, s, EASE_CLEAR * d, turn, i, count, r.to,
                                   r.was);
                if (!ok)
                    ok = round_run(c, open, &bins, s, EASE_CLEAR * d, ROUND_TIP * d, TIP_REACH * d, i,
                                   count, r.to, r.was);
                moved += (size_t)ok;
            } else {
                j = j + 1 == n ? 0 : j + 1;
            }
            seen += count > 0 ? count : 1;
            i = j;
        }
        vbins_free(ctx, &bins, n);
        if (moved == 0)
            break;
    }
    round_buf_free(ctx, &r);
    if (rc == QC_OK) /* and what the rounding left straight, or could not wave before */
        rc = qc__meander_wave(ctx, c, open, d, WAVE_AGAIN, s);
    if (rc == QC_OK) { /* the split points left in line: the corner as it was */
        size_t k = 0;
        n = c->n;
        for (i = 0; i < n; i++) {
            qc_vec2 a = k > 0 ? c->v[k - 1] : c->v[n - 1], p = c->v[i], b = c->v[i + 1 == n ? 0 : i + 1];
            double cr = (p.x - a.x) * (b.y - p.y) - (p.y - a.y) * (b.x - p.x);
            double dot = (p.x - a.x) * (b.x - p.x) + (p.y - a.y) * (b.y - p.y);
            if (i > 0 && !(open && i + 1 == n) && fabs(cr) <= 1e-9 * dot && dot > 0.0)
                continue;
            c->v[k++] = p;
        }
        c->n = k;
    }
    return rc;
}

int qc__meander_ease(qc_ctx *ctx, qc_points *c, int open, double turn, const qc__sdf *s,
                     double d)
{
    size_t pass, i, n = c->n;
    double longest = 0.0;
    int rc = QC_OK;

    if (n < 4 || !(turn > 0.0))
        return QC_OK;
    for (i = 0; i + (open ? 1 : 0) < n; i++) {
        qc_vec2 a = c->v[i], b = c->v[i + 1 == n ? 0 : i + 1];
        longest = fmax(longest, qc_hypot(b.x - a.x, b.y - a.y));
    }
    for (pass = 0; pass < EASE_PASSES && rc == QC_OK; pass++) {
        vbins bins;
        size_t moved = 0;

        memset(&bins, 0, sizeof bins);
        rc = vbins_build(ctx, &bins, c, 2.5 * longest + 1e-9);
        for (i = open ? 1 : 0; i < (open ? n - 1 : n) && rc == QC_OK; i++) {
            size_t ia = i == 0 ? n - 1 : i - 1, ib = i + 1 == n ? 0 : i + 1;
            qc_vec2 a = c->v[ia], p = c->v[i], b = c->v[ib], m;
            if (circumradius(a, p, b) >= EASE_BELOW * turn)
                continue;
            m = QC__V2(p.x + EASE_STEP * (0.5 * (a.x + b.x) - p.x),
                       p.y + EASE_STEP * (0.5 * (a.y + b.y) - p.y));
            if (qc__sdf_exact(s, m, NULL) < EASE_CLEAR * d)
                continue;
            c->v[i] = m;
            if (seg_crosses(c, open, &bins, i, m, ia, i) || seg_crosses(c, open, &bins, i, m, i, ib))
                c->v[i] = p;
            else
                moved++;
        }
        vbins_free(ctx, &bins, n);
        if (moved == 0)
            break;
    }
    return rc;
}
