/*
 * clip-path, where it can be applied exactly: the clip is one closed convex
 * polygon (a rect, a polygon, a path of straight edges) and the clipped
 * shape lies wholly inside it (kept), wholly beyond one of its edges
 * (dropped), or is itself one closed convex polygon (cut by
 * Sutherland-Hodgman, exact for two convex polygons). The walk warns about
 * every other case and reads the shape unclipped.
 */
#include <math.h>
#include <string.h>

#include "svg_internal.h"

static double cross(qc_vec2 a, qc_vec2 b, qc_vec2 p)
{
    return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

/* One closed subpath of straight edges: its vertices without the closing
 * repeat and without consecutive duplicates into *out; 0 otherwise. */
static int polygon_of(qc_ctx *ctx, const qc_path *p, qc_vec2 **v, size_t *n, size_t *cap,
                      int *ok)
{
    size_t c;

    *ok = 0;
    *n = 0;
    if (p->ncmd < 4 || p->cmd[0] != QC_PATH_MOVE)
        return QC_OK;
    for (c = 1; c < p->ncmd; c++)
        if (p->cmd[c] != QC_PATH_LINE)
            return QC_OK;
    if (p->pt[0].x != p->pt[p->npt - 1].x || p->pt[0].y != p->pt[p->npt - 1].y)
        return QC_OK;
    QC__TRY(qc__reserve(ctx, (void **)v, cap, p->npt, sizeof **v));
    for (c = 0; c + 1 < p->npt; c++)
        if (*n == 0 || (*v)[*n - 1].x != p->pt[c].x || (*v)[*n - 1].y != p->pt[c].y)
            (*v)[(*n)++] = p->pt[c];
    *ok = *n >= 3;
    return QC_OK;
}

/* The sign of a convex polygon's turns (+1 or -1), or 0 when it is not
 * convex or has no area. */
static int convex_sign(const qc_vec2 *v, size_t n)
{
    size_t i;
    int sign = 0;
    double area = 0;

    for (i = 0; i < n; i++) {
        qc_vec2 a = v[i], b = v[(i + 1) % n], c = v[(i + 2) % n];
        double t = cross(a, b, c);

        area += a.x * b.y - b.x * a.y;
        if (t == 0)
            continue;
        if (sign == 0)
            sign = t > 0 ? 1 : -1;
        else if ((t > 0) != (sign > 0))
            return 0;
    }
    if (sign == 0 || (area > 0) != (sign > 0))
        return 0; /* collinear, or a star whose turns agree but that winds twice */
    return sign;
}

int qc__svg_clip_make(qc_ctx *ctx, const qc_path *shapes, size_t nshapes, qc__svg_clip *c,
                      int *ok)
{
    int poly;

    *ok = 0;
    c->sign = 0;
    if (nshapes != 1)
        return QC_OK;
    QC__TRY(polygon_of(ctx, shapes, &c->v, &c->n, &c->cap, &poly));
    if (poly)
        c->sign = convex_sign(c->v, c->n);
    *ok = c->sign != 0;
    return QC_OK;
}

void qc__svg_clip_free(qc_ctx *ctx, qc__svg_clip *c)
{
    qc__free(ctx, c->v, c->cap * sizeof *c->v);
    c->v = NULL;
    c->n = c->cap = 0;
}

/* Which side of clip edge i p is on: > 0 inside. */
static double side(const qc__svg_clip *c, size_t i, qc_vec2 p)
{
    return c->sign * cross(c->v[i], c->v[(i + 1) % c->n], p);
}

int qc__svg_clip_where(const qc__svg_clip *c, const qc_path *shape)
{
    size_t i, k;
    int inside = 1;

    if (c->n == 0)
        return -1; /* an empty clip lets nothing through */
    for (i = 0; i < c->n; i++) {
        size_t out = 0;

        for (k = 0; k < shape->npt; k++)
            out += side(c, i, shape->pt[k]) < 0;
        if (out == shape->npt)
            return -1;
        if (out > 0)
            inside = 0;
    }
    return inside;
}

/* Sutherland-Hodgman: the convex polygon (*a)[0..*na) cut by each edge of
 * c in turn (exact for two convex polygons); fewer than 3 vertices left is
 * empty (*na = 0). */
static int cut_polygon(qc_ctx *ctx, const qc__svg_clip *c, qc_vec2 **a, size_t *na, size_t *acap)
{
    qc_vec2 *b = NULL;
    size_t nb = 0, bcap = 0, i, k;
    int rc = QC_OK;

    for (i = 0; i < c->n && *na > 0; i++) {
        rc = qc__reserve(ctx, (void **)&b, &bcap, 2 * *na, sizeof *b);
        if (rc < 0)
            break;
        nb = 0;
        for (k = 0; k < *na; k++) {
            qc_vec2 p = (*a)[k], q = (*a)[(k + 1) % *na];
            double sp = side(c, i, p), sq = side(c, i, q);

            if (sp >= 0)
                b[nb++] = p;
            if ((sp >= 0) != (sq >= 0)) {
                double t = sp / (sp - sq);

                b[nb++] = QC__V2(p.x + t * (q.x - p.x), p.y + t * (q.y - p.y));
            }
        }
        {
            qc_vec2 *tv = *a;
            size_t tc = *acap;

            *a = b;
            *acap = bcap;
            *na = nb;
            b = tv;
            bcap = tc;
        }
    }
    qc__free(ctx, b, bcap * sizeof *b);
    if (*na < 3)
        *na = 0;
    return rc;
}

int qc__svg_clip_cut(qc_ctx *ctx, const qc__svg_clip *c, qc_path *shape, int *done)
{
    qc_vec2 *a = NULL;
    size_t na = 0, acap = 0, k;
    int poly, rc;

    *done = 0;
    QC__TRY(polygon_of(ctx, shape, &a, &na, &acap, &poly));
    if (!poly || convex_sign(a, na) == 0) {
        qc__free(ctx, a, acap * sizeof *a);
        return QC_OK;
    }
    rc = cut_polygon(ctx, c, &a, &na, &acap);
    if (rc == QC_OK) {
        shape->ncmd = shape->npt = 0;
        for (k = 0; k < na && rc == QC_OK; k++)
            rc = k == 0 ? qc_path_move_to(ctx, shape, a[0]) : qc_path_line_to(ctx, shape, a[k]);
        if (rc == QC_OK && na > 0)
            rc = qc_path_line_to(ctx, shape, a[0]);
        *done = rc == QC_OK;
    }
    qc__free(ctx, a, acap * sizeof *a);
    return rc;
}

int qc__svg_clip_meet(qc_ctx *ctx, const qc__svg_clip *a, const qc__svg_clip *b,
                      qc__svg_clip *out)
{
    out->n = 0;
    out->sign = a->sign;
    if (a->n == 0 || b->n == 0)
        return QC_OK; /* nothing passes either */
    QC__TRY(qc__reserve(ctx, (void **)&out->v, &out->cap, a->n, sizeof *out->v));
    memcpy(out->v, a->v, a->n * sizeof *a->v);
    out->n = a->n;
    return cut_polygon(ctx, b, &out->v, &out->n, &out->cap);
}
