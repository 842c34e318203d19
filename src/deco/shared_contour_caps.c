/*
 * Caps for the peaks the offset rings leave bare (echo, spiral). Levels
 * margin + k d keep every place on a ridge within d of a ring, but a peak
 * of the distance field (where three bisectors meet, as at the inner
 * corner of a C) that rises less than a grid step above the last level it
 * passes gets no ring, and the rings round it keep their distance along
 * the bisectors: the C-shape's peak lay 1.05 d from the nearest stitch.
 * Each such peak gets a small ring of its own, which the joins reach by a
 * spur like any ring too small to cut.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "deco_internal.h"

/* A peak farther than this from every ring gets a cap, times d: a ridge
 * lies less than d from the last level below it, so only peaks that missed
 * a level qualify (no caps strung along a strip's centre line). */
#define CAP_FAR 0.97
/* Peaks this close to a cap already made share it, times d. */
#define CAP_SHARE 0.9
/* The cap's radius, times d, and its vertices. */
#define CAP_RADIUS 0.1
#define CAP_SIDES 8

typedef struct peak {
    qc_vec2 at;
    double far, depth;
} peak;

typedef struct ring_walk {
    const qc__rings *r;
    const uint32_t *next;
} ring_walk;

/* Up to this many peak candidates, the ring segments near them are listed
 * in one pass instead of binning every segment in a grid: most regions
 * have one or a few peaks, and the grid cost ten times the queries. */
#define FEW_PEAKS 16

/* Where ring_dist looks: the segments in g, or (listed) those in list. */
typedef struct ring_near {
    const qc__seg_grid *g;
    const uint32_t *list;
    size_t nlist;
    int listed;
} ring_near;

static uint32_t ring_next(const void *ud, uint32_t k)
{
    return ((const ring_walk *)ud)->next[k];
}

/* Distance from q to the nearest ring segment within reach (reach if none).
 * Every segment nearer than reach has its box in q's square of side
 * 2 reach: the grid's cells there, or a list holding all such segments,
 * give the same minimum. */
static double ring_dist(const ring_near *rn, const qc_vec2 *p, const uint32_t *next, qc_vec2 q,
                        double reach)
{
    const qc__seg_grid *g = rn->g;
    qc_vec2 lo, hi;
    size_t c[4], x, y, i;
    double best = reach * reach;

    if (rn->listed) {
        for (i = 0; i < rn->nlist; i++) {
            uint32_t s = rn->list[i];
            double d2 = qc__seg_dist2(q, p[s], p[next[s]]);
            if (d2 < best)
                best = d2;
        }
        return sqrt(best);
    }
    lo.x = q.x - reach;
    lo.y = q.y - reach;
    hi.x = q.x + reach;
    hi.y = q.y + reach;
    qc__seg_grid_cells(g, lo, hi, c);
    for (y = c[1]; y <= c[3]; y++)
        for (x = c[0]; x <= c[2]; x++)
            for (i = g->start[y * g->gx + x]; i < g->start[y * g->gx + x + 1]; i++) {
                uint32_t s = g->seg[i];
                double d2 = qc__seg_dist2(q, p[s], p[next[s]]);
                if (d2 < best)
                    best = d2;
            }
    return sqrt(best);
}

/* Whether node k's value is the highest of its 8 neighbours (ties go to the
 * lower index, so a flat top yields one node per plateau run). */
static int is_peak(const qc__sdf *s, size_t i, size_t jy)
{
    size_t k = jy * s->nx + i;
    int dx, dy;

    for (dy = -1; dy <= 1; dy++)
        for (dx = -1; dx <= 1; dx++) {
            size_t q = (size_t)((long)k + dy * (long)s->nx + dx);
            if (q == k)
                continue;
            if (s->v[q] > s->v[k] || (s->v[q] == s->v[k] && q < k))
                return 0;
        }
    return 1;
}

static int cmp_peak(const void *pa, const void *pb)
{
    const peak *a = pa, *b = pb;

    if (a->far != b->far)
        return a->far > b->far ? -1 : 1;
    if (a->at.y != b->at.y)
        return a->at.y < b->at.y ? -1 : 1;
    return (a->at.x > b->at.x) - (a->at.x < b->at.x);
}

/* The farthest from the rings of the node and the points h / 2 round it
 * that lie deeper than the margin (the node alone when none can be
 * farther than limit). */
static peak peak_refine(const qc__contour *c, const ring_near *g, const uint32_t *next,
                        qc_vec2 at, double reach, double limit)
{
    peak best;
    int dx, dy;

    best.at = at;
    best.far = ring_dist(g, c->rings.pts.v, next, at, reach);
    best.depth = qc__sdf_at(&c->sdf, at);
    if (best.far < limit - 0.71 * c->sdf.h) /* no point h / 2 away gets past limit */
        return best;
    for (dy = -2; dy <= 2; dy++)
        for (dx = -2; dx <= 2; dx++) {
            qc_vec2 q;
            double f, v;
            q.x = at.x + 0.25 * c->sdf.h * dx;
            q.y = at.y + 0.25 * c->sdf.h * dy;
            v = qc__sdf_at(&c->sdf, q);
            if (!(v > c->l0))
                continue;
            f = ring_dist(g, c->rings.pts.v, next, q, reach);
            if (f > best.far) {
                best.at = q;
                best.far = f;
                best.depth = v;
            }
        }
    return best;
}

/* Appends a small counter-clockwise ring round pk (the higher side left). */
static int add_cap(qc_ctx *ctx, qc__rings *r, const peak *pk, double d, double l0,
                   uint32_t level)
{
    double rad = fmin(CAP_RADIUS * d, 0.5 * (pk->depth - l0));
    int k;

    for (k = 0; k < CAP_SIDES; k++) {
        double a = 2.0 * QC_PI * k / CAP_SIDES;
        qc_vec2 v;
        v.x = pk->at.x + rad * qc_cos(a); /* the core's own: the same bytes everywhere */
        v.y = pk->at.y + rad * qc_sin(a);
        QC__TRY(qc_points_push(ctx, &r->pts, v));
    }
    QC__TRY(qc_order_push(ctx, &r->end, (uint32_t)r->pts.n));
    return qc_order_push(ctx, &r->level, level);
}

/* Lists the segments of the n ring points whose box meets the square of
 * half-side pad round one of the np nodes at[]. */
static int near_list(qc_ctx *ctx, const qc_vec2 *p, const uint32_t *next, size_t n,
                     const qc_vec2 *at, size_t np, double pad, uint32_t **list, size_t *nlist,
                     size_t *cap)
{
    size_t s, k;

    for (s = 0; s < n; s++) {
        qc_vec2 a = p[s], b = p[next[s]];
        double lx = a.x < b.x ? a.x : b.x, hx = a.x < b.x ? b.x : a.x;
        double ly = a.y < b.y ? a.y : b.y, hy = a.y < b.y ? b.y : a.y;

        for (k = 0; k < np; k++)
            if (hx >= at[k].x - pad && lx <= at[k].x + pad && hy >= at[k].y - pad &&
                ly <= at[k].y + pad)
                break;
        if (k == np)
            continue;
        QC__TRY(QC__RESERVE(ctx, *list, *cap, *nlist + 1));
        (*list)[(*nlist)++] = (uint32_t)s;
    }
    return QC_OK;
}

/* The nodes above the margin higher than their 8 neighbours, row by row,
 * into *at (*np of them, *cap allocated). */
static int peak_nodes(qc_ctx *ctx, const qc__contour *c, qc_vec2 **at, size_t *np, size_t *cap)
{
    const qc__sdf *s = &c->sdf;
    size_t i, jy;

    for (jy = 1; jy + 1 < s->ny; jy++)
        for (i = 1; i + 1 < s->nx; i++) {
            if (!(s->v[jy * s->nx + i] > c->l0) || !is_peak(s, i, jy))
                continue;
            QC__TRY(QC__RESERVE(ctx, *at, *cap, *np + 1));
            (*at)[*np].x = s->x0 + (double)i * s->h;
            (*at)[*np].y = s->y0 + (double)jy * s->h;
            ++*np;
        }
    return QC_OK;
}

int qc__contour_cap_peaks(qc_ctx *ctx, qc__contour *c, double d)
{
    const qc__sdf *s = &c->sdf;
    qc__rings *r = &c->rings;
    qc__seg_grid g;
    ring_walk w;
    ring_near rn;
    qc_vec2 *cand = NULL;
    uint32_t *next = NULL, *list = NULL, top = 0;
    peak *pk = NULL;
    size_t npk = 0, cap = 0, n = r->pts.n, nr = r->end.n, k, b, i, kept = 0, ncand = 0,
           cand_cap = 0, nlist = 0, list_cap = 0;
    double reach = 2.0 * d;
    int rc;

    memset(&g, 0, sizeof g);
    if (n == 0 || s->nx < 3 || s->ny < 3)
        return QC_OK;
    next = qc__alloc_array(ctx, n, sizeof *next);
    if (next == NULL)
        return qc__fail(ctx, QC_ENOMEM, "out of memory capping the offset rings' peaks");
    for (k = 0, b = 0; k < nr; b = r->end.i[k++]) {
        for (i = b; i + 1 < r->end.i[k]; i++)
            next[i] = (uint32_t)(i + 1);
        next[r->end.i[k] - 1] = (uint32_t)b;
        if (r->level.i[k] > top)
            top = r->level.i[k];
    }
    w.r = r;
    w.next = next;
    memset(&rn, 0, sizeof rn);
    rc = peak_nodes(ctx, c, &cand, &ncand, &cand_cap);
    if (rc == QC_OK && ncand > FEW_PEAKS) {
        rc = qc__seg_grid_build(ctx, &g, r->pts.v, n, ring_next, &w, d, 4.0);
        rn.g = &g;
    } else if (rc == QC_OK && ncand > 0) { /* refined points lie h / 2 from their node at most */
        rc = near_list(ctx, r->pts.v, next, n, cand, ncand, reach + 0.51 * s->h, &list, &nlist,
                       &list_cap);
        rn.list = list;
        rn.nlist = nlist;
        rn.listed = 1;
    }
    for (k = 0; k < ncand && rc == QC_OK; k++) {
        peak p = peak_refine(c, &rn, next, cand[k], reach, CAP_FAR * d);

        if (!(p.far > CAP_FAR * d))
            continue;
        rc = QC__RESERVE(ctx, pk, cap, npk + 1);
        if (rc == QC_OK)
            pk[npk++] = p;
    }
    if (rc == QC_OK && npk > 1)
        qsort(pk, npk, sizeof *pk, cmp_peak);
    for (k = 0; k < npk && rc == QC_OK; k++) { /* farthest first; one cap covers its neighbours */
        size_t q;
        int near = 0;
        for (q = 0; q < kept && !near; q++)
            near = qc_hypot(pk[q].at.x - pk[k].at.x, pk[q].at.y - pk[k].at.y) <= CAP_SHARE * d;
        if (!near)
            pk[kept++] = pk[k];
    }
    for (k = 0; k < kept && rc == QC_OK; k++)
        rc = add_cap(ctx, r, &pk[k], d, c->l0, top + 1);
    qc__seg_grid_free(ctx, &g);
    qc__free(ctx, list, list_cap * sizeof *list);
    qc__free(ctx, cand, cand_cap * sizeof *cand);
    qc__free(ctx, next, n * sizeof *next);
    qc__free(ctx, pk, cap * sizeof *pk);
    if (rc < 0)
        return qc__fail(ctx, rc, "out of memory capping the offset rings' peaks");
    return QC_OK;
}
