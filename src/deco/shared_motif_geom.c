/* Motif geometry: convex hull, minimum bounding circle, mapped paths. */
#include <math.h>
#include <string.h>

#include "deco_internal.h"

static double cross3(qc_vec2 o, qc_vec2 a, qc_vec2 b)
{
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

/* Insertion sort would be quadratic: a bottom-up merge sort by (x, y). */
static int less_xy(qc_vec2 a, qc_vec2 b)
{
    return a.x < b.x || (a.x == b.x && a.y < b.y);
}

static void sort_xy(qc_vec2 *p, qc_vec2 *tmp, size_t n)
{
    size_t w, i;
    qc_vec2 *src = p, *dst = tmp;

    for (w = 1; w < n; w *= 2) {
        for (i = 0; i < n; i += 2 * w) {
            size_t lo = i, mid = i + w < n ? i + w : n;
            size_t hi = i + 2 * w < n ? i + 2 * w : n, a = lo, b = mid, k = lo;
            while (a < mid && b < hi)
                dst[k++] = less_xy(src[b], src[a]) ? src[b++] : src[a++];
            while (a < mid)
                dst[k++] = src[a++];
            while (b < hi)
                dst[k++] = src[b++];
        }
        {
            qc_vec2 *t = src;
            src = dst;
            dst = t;
        }
    }
    if (src != p)
        memcpy(p, src, n * sizeof *p);
}

size_t qc__convex_hull(const qc_vec2 *pts, size_t n, qc_vec2 *out, qc_vec2 *scratch)
{
    size_t i, k = 0, lower;
    qc_vec2 *s = scratch; /* 2n: sorted copy + merge buffer */

    if (n == 0)
        return 0;
    memcpy(s, pts, n * sizeof *s);
    sort_xy(s, s + n, n);
    for (i = 0; i < n; i++) {
        while (k >= 2 && cross3(out[k - 2], out[k - 1], s[i]) <= 0)
            k--;
        out[k++] = s[i];
    }
    lower = k + 1;
    for (i = n - 1; i-- > 0;) {
        while (k >= lower && cross3(out[k - 2], out[k - 1], s[i]) <= 0)
            k--;
        out[k++] = s[i];
    }
    return k > 1 ? k - 1 : k;
}

/* Moves every edge of the CCW convex polygon h outward by d (tmp: n points). */
void qc__hull_outset(qc_vec2 *h, size_t n, qc_vec2 *tmp, double d)
{
    size_t i;

    if (n < 3)
        return;
    for (i = 0; i < n; i++) {
        qc_vec2 a = h[(i + n - 1) % n], b = h[i], c = h[(i + 1) % n];
        double l1 = qc_hypot(b.x - a.x, b.y - a.y), l2 = qc_hypot(c.x - b.x, c.y - b.y);
        double n1x = (b.y - a.y) / l1, n1y = -(b.x - a.x) / l1;
        double n2x = (c.y - b.y) / l2, n2y = -(c.x - b.x) / l2;
        double k = d / (1 + n1x * n2x + n1y * n2y);
        tmp[i].x = b.x + k * (n1x + n2x);
        tmp[i].y = b.y + k * (n1y + n2y);
    }
    memcpy(h, tmp, n * sizeof *h);
}

static double dist2(qc_vec2 a, qc_vec2 b)
{
    double dx = a.x - b.x, dy = a.y - b.y;
    return dx * dx + dy * dy;
}

static int outside(qc_vec2 c, double r, qc_vec2 p)
{
    return sqrt(dist2(c, p)) > r * (1 + 1e-14) + 1e-300;
}

static void circle2(qc_vec2 a, qc_vec2 b, qc_vec2 *c, double *r)
{
    c->x = (a.x + b.x) / 2;
    c->y = (a.y + b.y) / 2;
    *r = sqrt(dist2(a, b)) / 2;
}

static void circle3(qc_vec2 a, qc_vec2 b, qc_vec2 p, qc_vec2 *c, double *r)
{
    double bx = b.x - a.x, by = b.y - a.y, px = p.x - a.x, py = p.y - a.y;
    double d = 2 * (bx * py - by * px);
    double b2 = bx * bx + by * by, p2 = px * px + py * py;

    if (fabs(d) < 1e-300) { /* collinear: the widest pair */
        double ab = dist2(a, b), ap = dist2(a, p), bp = dist2(b, p);
        if (ab >= ap && ab >= bp)
            circle2(a, b, c, r);
        else if (ap >= bp)
            circle2(a, p, c, r);
        else
            circle2(b, p, c, r);
        return;
    }
    c->x = a.x + (py * b2 - by * p2) / d;
    c->y = a.y + (bx * p2 - px * b2) / d;
    *r = sqrt(fmax(fmax(dist2(*c, a), dist2(*c, b)), dist2(*c, p)));
}

void qc__min_circle(const qc_vec2 *pts, size_t n, qc_vec2 *s, qc_vec2 *c, double *r)
{
    size_t i, j, k;
    qc_rng rng;

    c->x = c->y = 0;
    *r = 0;
    if (n == 0)
        return;
    memcpy(s, pts, n * sizeof *s);
    qc_rng_seed(&rng, 0x6d6263u); /* a fixed shuffle: expected linear time */
    for (i = n - 1; i > 0; i--) {
        size_t o = (size_t)qc_rng_below(&rng, (uint64_t)i + 1);
        qc_vec2 t = s[i];
        s[i] = s[o];
        s[o] = t;
    }
    *c = s[0];
    for (i = 1; i < n; i++) {
        if (!outside(*c, *r, s[i]))
            continue;
        *c = s[i];
        *r = 0;
        for (j = 0; j < i; j++) {
            if (!outside(*c, *r, s[j]))
                continue;
            circle2(s[i], s[j], c, r);
            for (k = 0; k < j; k++)
                if (outside(*c, *r, s[k]))
                    circle3(s[i], s[j], s[k], c, r);
        }
    }
}

int qc__path_append_xf(qc_ctx *ctx, qc_path *out, const qc_path *path, const qc__xf *f)
{
    size_t i, k = 0;

    for (i = 0; i < path->ncmd; i++) {
        unsigned char cmd = path->cmd[i];
        const qc_vec2 *p = path->pt + k;
        k += qc_path_cmd_points(cmd);
        if (cmd == QC_PATH_MOVE) {
            qc_vec2 q = qc__xf_apply(f, p[0]);
            qc_vec2 last = qc_path_last(out);
            if (out->ncmd == 0)
                QC__TRY(qc_path_move_to(ctx, out, q));
            else if (fabs(q.x - last.x) > 1e-9 || fabs(q.y - last.y) > 1e-9)
                QC__TRY(qc_path_line_to(ctx, out, q));
        } else if (cmd == QC_PATH_LINE) {
            QC__TRY(qc_path_line_to(ctx, out, qc__xf_apply(f, p[0])));
        } else {
            QC__TRY(qc_path_cubic_to(ctx, out, qc__xf_apply(f, p[0]),
                                     qc__xf_apply(f, p[1]), qc__xf_apply(f, p[2])));
        }
    }
    return QC_OK;
}
