/* Clipping polylines to a region: exact cuts at ring edges, even-odd inside. */
#include <math.h>

#include "stitch_internal.h"

typedef struct clipper {
    qc_ctx *ctx;
    const qc_region *r;
    qc_points *out;
    qc_order *out_end;
    double *t;     /* crossing parameters of the current segment */
    size_t nt, tcap;
    int open;      /* a piece is being appended to out */
} clipper;

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

/* Parameters along a->b where it crosses a ring edge, sorted. */
static int crossings(clipper *c, qc_vec2 a, qc_vec2 b)
{
    const qc_region *r = c->r;
    double minx = fmin(a.x, b.x), maxx = fmax(a.x, b.x);
    double miny = fmin(a.y, b.y), maxy = fmax(a.y, b.y);
    double dx = b.x - a.x, dy = b.y - a.y;
    size_t k, start = 0, i, j;

    c->nt = 0;
    for (k = 0; k < r->nrings; k++) {
        size_t end = r->ring_end[k];
        for (i = start; i < end; i++) {
            qc_vec2 p = r->v[i], q = r->v[i + 1 < end ? i + 1 : start];
            double ex, ey, den, t, s;

            if (fmax(p.x, q.x) < minx || fmin(p.x, q.x) > maxx ||
                fmax(p.y, q.y) < miny || fmin(p.y, q.y) > maxy)
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
        start = end;
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
        int inside = qc_region_contains(c->r, lerp(a, b, 0.5 * (t0 + t1)));

        if (inside) {
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
    int rc = QC_OK;

    c.ctx = ctx;
    c.r = region;
    c.out = out;
    c.out_end = out_end;
    c.t = NULL;
    c.nt = c.tcap = 0;
    c.open = 0;
    for (k = 0; k < in_end->n && rc == QC_OK; k++) {
        size_t end = in_end->i[k];

        if (end - start == 1 && qc_region_contains(region, in->v[start])) {
            rc = push(&c, in->v[start]);
            c.open = 1;
        }
        for (i = start; i + 1 < end && rc == QC_OK; i++)
            rc = clip_segment(&c, in->v[i], in->v[i + 1]);
        if (rc == QC_OK)
            rc = close_piece(&c);
        start = end;
    }
    qc__free(ctx, c.t, c.tcap * sizeof *c.t);
    return rc;
}
