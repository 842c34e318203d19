/* Placing a finished block: mirror, rotate, move its outline's box to a corner. */
#include <math.h>

#include "internal.h"

/* cos and sin of deg, exact at multiples of 90 so quarter turns keep exact
 * coordinates (qc_cos(pi/2) is 6e-17, not 0). */
static void turn(double deg, double *c, double *s)
{
    double q = deg / 90;

    if (q == floor(q)) {
        static const double cs[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
        long k = (long)fmod(q, 4);
        if (k < 0)
            k += 4;
        *c = cs[k][0];
        *s = cs[k][1];
        return;
    }
    *c = qc_cos(deg * QC_PI / 180);
    *s = qc_sin(deg * QC_PI / 180);
}

static qc_vec2 apply(const qc_xform *m, qc_vec2 p)
{
    qc_vec2 q;
    q.x = m->a * p.x + m->b * p.y + m->tx;
    q.y = m->c * p.x + m->d * p.y + m->ty;
    return q;
}

int qc_place_xform(qc_ctx *ctx, const qc_region *frame, const qc_place *pl, qc_xform *out)
{
    double c, s, mx, my;
    qc_bbox b;
    size_t i;

    if (frame == NULL || pl == NULL || out == NULL || frame->nv == 0)
        return qc__fail(ctx, QC_EINVAL, "place: no region or placement");
    if (!(fabs(pl->rotate_deg) <= 360))
        return qc__fail(ctx, QC_ERANGE, "rotate %g deg must be in [-360, 360]", pl->rotate_deg);
    if (!(fabs(pl->at.x) <= 1e6) || !(fabs(pl->at.y) <= 1e6))
        return qc__fail(ctx, QC_ERANGE, "place at (%g, %g) mm must be within 1e6 mm",
                        pl->at.x, pl->at.y);
    turn(pl->rotate_deg, &c, &s);
    mx = (pl->mirror & QC_MIRROR_X) ? -1 : 1;
    my = (pl->mirror & QC_MIRROR_Y) ? -1 : 1;
    /* rotate after mirroring: R * diag(mx, my) */
    out->a = c * mx;
    out->b = -s * my;
    out->c = s * mx;
    out->d = c * my;
    out->tx = out->ty = 0;
    b.min = b.max = apply(out, frame->v[0]);
    for (i = 1; i < frame->nv; i++) {
        qc_vec2 p = apply(out, frame->v[i]);
        b.min.x = fmin(b.min.x, p.x);
        b.min.y = fmin(b.min.y, p.y);
        b.max.x = fmax(b.max.x, p.x);
        b.max.y = fmax(b.max.y, p.y);
    }
    out->tx = pl->at.x - b.min.x;
    out->ty = pl->at.y - b.min.y;
    return QC_OK;
}

void qc_plan_transform(qc_plan *plan, const qc_xform *m)
{
    size_t i;

    for (i = 0; i < plan->n; i++)
        plan->p[i] = apply(m, plan->p[i]);
}

void qc_region_transform(qc_region *r, const qc_xform *m)
{
    size_t k, start = 0, i;

    for (i = 0; i < r->nv; i++)
        r->v[i] = apply(m, r->v[i]);
    if (m->a * m->d - m->b * m->c >= 0)
        return;
    for (k = 0; k < r->nrings; k++) { /* a mirror image: reverse rings to keep their turn */
        size_t lo = start, hi = r->ring_end[k] - 1;
        for (; lo < hi; lo++, hi--) {
            qc_vec2 t = r->v[lo];
            r->v[lo] = r->v[hi];
            r->v[hi] = t;
        }
        start = r->ring_end[k];
    }
}
