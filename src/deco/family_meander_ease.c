/*
 * Easing the curve's tightest turns. The evolution fairs a vertex that
 * turns tighter than the turn radius, but the boundary's wall pushes it
 * back: where the curve hugs a convex corner of the region it follows the
 * clearance's own sharp corner, and a tongue (family_meander_reach.c)
 * leaves the curve at an angle. Without the wall, each such vertex moves
 * halfway towards the midpoint of its neighbours (into the bend, away from
 * the boundary), a few passes over; a move is kept only if the vertex stays
 * inside and its two segments cross nothing (checked against the segments
 * near it, binned in a grid).
 */
#include <math.h>
#include <string.h>

#include "family_meander.h"

#define EASE_PASSES 6
#define EASE_STEP 0.5    /* share of the way to the neighbours' midpoint */
#define EASE_CLEAR 0.05  /* a moved vertex stays this far inside, times d */
#define EASE_BELOW 0.95  /* eased: turning tighter than this times the radius
                          * (a tongue's tip turns at the radius itself) */

/* Radius of the circle through a, p, b (huge when they are in line). */
static double circumradius(qc_vec2 a, qc_vec2 p, qc_vec2 b)
{
    double cr = fabs((p.x - a.x) * (b.y - p.y) - (p.y - a.y) * (b.x - p.x));
    double l = qc_hypot(p.x - a.x, p.y - a.y) * qc_hypot(b.x - p.x, b.y - p.y) *
               qc_hypot(a.x - b.x, a.y - b.y);

    return cr > 1e-12 * l ? l / (2.0 * cr) : 1e30;
}

static int crosses(qc_vec2 a, qc_vec2 b, qc_vec2 c, qc_vec2 d)
{
    double d1 = qc_orient2d(a, b, c), d2 = qc_orient2d(a, b, d);
    double d3 = qc_orient2d(c, d, a), d4 = qc_orient2d(c, d, b);

    return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
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
    double fx = floor((p.x - b->x0) / b->h), fy = floor((p.y - b->y0) / b->h);

    *cx = fx <= 0.0 ? 0 : fx >= (double)(b->gx - 1) ? b->gx - 1 : (size_t)fx;
    *cy = fy <= 0.0 ? 0 : fy >= (double)(b->gy - 1) ? b->gy - 1 : (size_t)fy;
    return *cy * b->gx + *cx;
}

static int vbins_build(qc_ctx *ctx, vbins *b, const qc_points *c, double h)
{
    qc_vec2 lo = c->v[0], hi = c->v[0];
    size_t i, nc, cx, cy;

    for (i = 1; i < c->n; i++) {
        lo.x = fmin(lo.x, c->v[i].x), lo.y = fmin(lo.y, c->v[i].y);
        hi.x = fmax(hi.x, c->v[i].x), hi.y = fmax(hi.y, c->v[i].y);
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
                if (crosses(c->v[i], c->v[j], c->v[s], c->v[t]))
                    return 1;
                /* the segment ending at s too (s's bin stands for both) */
                t = s;
                s = s == 0 ? (open ? SIZE_MAX : n - 1) : s - 1;
                if (s == SIZE_MAX || s == i || s == j || t == i || t == j || s == k || t == k)
                    continue;
                if (crosses(c->v[i], c->v[j], c->v[s], c->v[t]))
                    return 1;
            }
    return 0;
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
