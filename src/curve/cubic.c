/* Points, tangents and splits of one cubic Bezier segment q[0..3]. */
#include "internal.h"

qc_vec2 qc_cubic_point(const qc_vec2 *q, double t)
{
    double u = 1 - t, a = u * u * u, b = 3 * u * u * t, c = 3 * u * t * t, d = t * t * t;
    qc_vec2 r;

    r.x = a * q[0].x + b * q[1].x + c * q[2].x + d * q[3].x;
    r.y = a * q[0].y + b * q[1].y + c * q[2].y + d * q[3].y;
    return r;
}

qc_vec2 qc_cubic_tangent(const qc_vec2 *q, double t)
{
    double u = 1 - t;
    qc_vec2 r;

    r.x = 3 * u * u * (q[1].x - q[0].x) + 6 * u * t * (q[2].x - q[1].x) +
          3 * t * t * (q[3].x - q[2].x);
    r.y = 3 * u * u * (q[1].y - q[0].y) + 6 * u * t * (q[2].y - q[1].y) +
          3 * t * t * (q[3].y - q[2].y);
    return r;
}

static qc_vec2 lerp(qc_vec2 p, qc_vec2 s, double t)
{
    qc_vec2 r;

    r.x = p.x + t * (s.x - p.x);
    r.y = p.y + t * (s.y - p.y);
    return r;
}

/* de Casteljau at t: the part before t into l[0..3], after it into r[0..3]. */
void qc_cubic_split(const qc_vec2 *q, double t, qc_vec2 *l, qc_vec2 *r)
{
    qc_vec2 a = lerp(q[0], q[1], t), b = lerp(q[1], q[2], t), c = lerp(q[2], q[3], t);
    qc_vec2 d = lerp(a, b, t), e = lerp(b, c, t), f = lerp(d, e, t);
    qc_vec2 q3 = q[3];

    l[0] = q[0];
    l[1] = a;
    l[2] = d;
    l[3] = f;
    r[0] = f;
    r[1] = e;
    r[2] = c;
    r[3] = q3;
}
