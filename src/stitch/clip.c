/*
 * Clipping polylines to a region: exact cuts at ring edges, even-odd inside.
 * Ring edges are bucketed into horizontal bands so a segment only meets the
 * edges of the bands it spans, and an inside test only those of one band.
 */
#include <math.h>

#include "stitch_internal.h"

#define MAX_BANDS 4096

typedef struct bands {
    double y0, inv_h;
    size_t nb;
    uint32_t *start;    /* nb + 1 offsets into edge */
    uint32_t *edge;     /* edge k runs from v[k] to v[next[k]] */
    uint32_t *next;
    size_t nedge_ref;
} bands;

typedef struct clipper {
    qc_ctx *ctx;
    const qc_region *r;
    bands b;
    qc_points *out;
    qc_order *out_end;
    double *t;     /* crossing parameters of the current segment */
    size_t nt, tcap;
    int open;      /* a piece is being appended to out */
} clipper;

static size_t band_of(const bands *b, double y)
{
    double k = floor((y - b->y0) * b->inv_h);

    if (!(k > 0))
        return 0;
    return k >= (double)b->nb ? b->nb - 1 : (size_t)k;
}

static void bands_free(qc_ctx *ctx, bands *b)
{
    qc__free(ctx, b->start, (b->nb + 1) * sizeof *b->start);
    qc__free(ctx, b->edge, b->nedge_ref * sizeof *b->edge);
}

/* b->next must be allocated (nv entries) by the caller's block. */
static int bands_build(qc_ctx *ctx, const qc_region *r, bands *b)
{
    qc_bbox box = qc_region_bbox(r);
    size_t k, e, start = 0, total = 0;

    b->start = NULL;
    b->edge = NULL;
    b->nedge_ref = 0;
    b->nb = r->nv < 4 ? 1 : r->nv > MAX_BANDS ? MAX_BANDS : r->nv;
    b->y0 = box.min.y;
    b->inv_h = box.max.y > box.min.y ? (double)b->nb / (box.max.y - box.min.y) : 0;
    for (k = 0; k < r->nrings; k++) {
        for (e = start; e < r->ring_end[k]; e++)
            b->next[e] = (uint32_t)(e + 1 < r->ring_end[k] ? e + 1 : start);
        start = r->ring_end[k];
    }
    b->start = (uint32_t *)qc__alloc_array(ctx, b->nb + 1, sizeof *b->start);
    if (b->start == NULL)
        return QC_ENOMEM;
    for (k = 0; k <= b->nb; k++)
        b->start[k] = 0;
    for (e = 0; e < r->nv; e++) {
        double ya = r->v[e].y, yb = r->v[b->next[e]].y;
        size_t lo = band_of(b, fmin(ya, yb)), hi = band_of(b, fmax(ya, yb));

        for (k = lo; k <= hi; k++)
            b->start[k + 1]++;
        total += hi - lo + 1;
    }
    if (total > UINT32_MAX)
        return qc__fail(ctx, QC_ELIMIT, "clip region too large to index");
    for (k = 0; k < b->nb; k++)
        b->start[k + 1] += b->start[k];
    b->edge = (uint32_t *)qc__alloc_array(ctx, total, sizeof *b->edge);
    if (b->edge == NULL)
        return QC_ENOMEM;
    b->nedge_ref = total;
    for (e = 0; e < r->nv; e++) {
        double ya = r->v[e].y, yb = r->v[b->next[e]].y;
        size_t lo = band_of(b, fmin(ya, yb)), hi = band_of(b, fmax(ya, yb));

        for (k = lo; k <= hi; k++)
            b->edge[b->start[k]++] = (uint32_t)e;
    }
    for (k = b->nb; k > 0; k--) /* undo the fill's shift */
        b->start[k] = b->start[k - 1];
    b->start[0] = 0;
    return QC_OK;
}

/* Even-odd test; points on an edge count as inside (as qc_region_contains). */
static int inside(const clipper *c, qc_vec2 p)
{
    const bands *b = &c->b;
    const qc_vec2 *v = c->r->v;
    size_t k, i;
    int in = 0;

    k = band_of(b, p.y);
    for (i = b->start[k]; i < b->start[k + 1]; i++) {
        qc_vec2 a = v[b->edge[i]], q = v[b->next[b->edge[i]]];
        double cross = (q.x - a.x) * (p.y - a.y) - (q.y - a.y) * (p.x - a.x);

        if (cross == 0 && p.x >= fmin(a.x, q.x) && p.x <= fmax(a.x, q.x) &&
            p.y >= fmin(a.y, q.y) && p.y <= fmax(a.y, q.y))
            return 1;
        if ((a.y > p.y) != (q.y > p.y) &&
            p.x < a.x + (p.y - a.y) * (q.x - a.x) / (q.y - a.y))
            in = !in;
    }
    return in;
}

static qc_vec2 lerp(qc_vec2 a, qc_vec2 b, double t)
{
    qc_vec2 r;

    r.x = a.x + (b.x - a.x) * t;
    r.y = a.y + (b.y - a.y) * t;
    return r;
}

static int close_piece(clipper *c)
{
    if (!c->open)
        return QC_OK;
    c->open = 0;
    return qc_order_push(c->ctx, c->out_end, (uint32_t)c->out->n);
}

/* Parameters along a->b where it crosses a ring edge, sorted. Each edge is
 * tested once: in the first band it shares with the segment. */
static int crossings(clipper *c, qc_vec2 a, qc_vec2 b)
{
    const bands *bd = &c->b;
    const qc_vec2 *v = c->r->v;
    double minx = fmin(a.x, b.x), maxx = fmax(a.x, b.x);
    double miny = fmin(a.y, b.y), maxy = fmax(a.y, b.y);
    double dx = b.x - a.x, dy = b.y - a.y;
    size_t lo = band_of(bd, miny), hi = band_of(bd, maxy), k, i, j;

    c->nt = 0;
    for (k = lo; k <= hi; k++) {
        for (i = bd->start[k]; i < bd->start[k + 1]; i++) {
            qc_vec2 p = v[bd->edge[i]], q = v[bd->next[bd->edge[i]]];
            double ex, ey, den, t, s;
            size_t first;

            if (fmax(p.x, q.x) < minx || fmin(p.x, q.x) > maxx ||
                fmax(p.y, q.y) < miny || fmin(p.y, q.y) > maxy)
                continue;
            first = band_of(bd, fmin(p.y, q.y));
            if ((first > lo ? first : lo) != k)
                continue;
            ex = q.x - p.x;
            ey = q.y - p.y;
            den = dx * ey - dy * ex;
            if (den == 0)
                continue; /* parallel: the midpoint tests decide */
            t = ((p.x - a.x) * ey - (p.y - a.y) * ex) / den;
            s = ((p.x - a.x) * dy - (p.y - a.y) * dx) / den;
            if (t <= 0 || t >= 1 || s < 0 || s > 1)
                continue;
            QC__TRY(QC__RESERVE(c->ctx, c->t, c->tcap, c->nt + 1));
            for (j = c->nt; j > 0 && c->t[j - 1] > t; j--)
                c->t[j] = c->t[j - 1];
            c->t[j] = t;
            c->nt++;
        }
    }
    return QC_OK;
}

static int push(clipper *c, qc_vec2 p)
{
    if (c->out->n >= UINT32_MAX)
        return qc__fail(c->ctx, QC_ELIMIT, "clipped path exceeds 2^32 points");
    return qc_points_push(c->ctx, c->out, p);
}

static int clip_segment(clipper *c, qc_vec2 a, qc_vec2 b)
{
    size_t i;

    QC__TRY(crossings(c, a, b));
    for (i = 0; i <= c->nt; i++) {
        double t0 = i == 0 ? 0 : c->t[i - 1], t1 = i == c->nt ? 1 : c->t[i];

        if (inside(c, lerp(a, b, 0.5 * (t0 + t1)))) {
            if (!c->open) {
                QC__TRY(push(c, lerp(a, b, t0)));
                c->open = 1;
            }
            QC__TRY(push(c, t1 == 1 ? b : lerp(a, b, t1)));
        } else {
            QC__TRY(close_piece(c));
        }
    }
    return QC_OK;
}

int qc__clip_pieces(qc_ctx *ctx, const qc_points *in, const qc_order *in_end,
                    const qc_region *region, qc_points *out, qc_order *out_end)
{
    clipper c;
    size_t k, i, start = 0;
    int rc;

    if (region->nv == 0 || region->nrings == 0)
        return QC_OK; /* nothing is inside an empty region */
    c.ctx = ctx;
    c.r = region;
    c.out = out;
    c.out_end = out_end;
    c.t = NULL;
    c.nt = c.tcap = 0;
    c.open = 0;
    c.b.next = (uint32_t *)qc__alloc_array(ctx, region->nv, sizeof *c.b.next);
    if (c.b.next == NULL)
        return QC_ENOMEM;
    rc = bands_build(ctx, region, &c.b);
    for (k = 0; k < in_end->n && rc == QC_OK; k++) {
        size_t end = in_end->i[k];

        if (end - start == 1 && inside(&c, in->v[start])) {
            rc = push(&c, in->v[start]);
            c.open = 1;
        }
        for (i = start; i + 1 < end && rc == QC_OK; i++)
            rc = clip_segment(&c, in->v[i], in->v[i + 1]);
        if (rc == QC_OK)
            rc = close_piece(&c);
        start = end;
    }
    bands_free(ctx, &c.b);
    qc__free(ctx, c.b.next, region->nv * sizeof *c.b.next);
    qc__free(ctx, c.t, c.tcap * sizeof *c.t);
    return rc;
}
