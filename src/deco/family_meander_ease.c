/*
 * Easing the evolved curve's tightest turns. The evolution fairs a vertex
 * that turns tighter than the turn radius, but the boundary's wall pushes
 * it back: where the curve hugs a convex corner of the region it follows
 * the clearance's own sharp corner. Without the wall, each such vertex moves
 * halfway towards the midpoint of its neighbours (into the bend, away from
 * the corner), a few passes over, each pass kept only if the curve still
 * stays inside and does not cross itself.
 */
#include <math.h>
#include <string.h>

#include "family_meander.h"

#define EASE_PASSES 6
#define EASE_STEP 0.5    /* share of the way to the neighbours' midpoint */
#define EASE_CLEAR 0.05  /* a moved vertex stays this far inside, times d */

/* Radius of the circle through a, p, b (huge when they are in line). */
static double circumradius(qc_vec2 a, qc_vec2 p, qc_vec2 b)
{
    double cr = fabs((p.x - a.x) * (b.y - p.y) - (p.y - a.y) * (b.x - p.x));
    double l = qc_hypot(p.x - a.x, p.y - a.y) * qc_hypot(b.x - p.x, b.y - p.y) *
               qc_hypot(a.x - b.x, a.y - b.y);

    return cr > 1e-12 * l ? l / (2.0 * cr) : 1e30;
}

int qc__meander_ease(qc_ctx *ctx, qc_points *c, int open, double turn, const qc__sdf *s,
                     double d)
{
    qc_points q = {0};
    size_t pass, i, n = c->n;
    int rc = QC_OK;

    if (n < 4 || !(turn > 0.0))
        return QC_OK;
    for (pass = 0; pass < EASE_PASSES && rc == QC_OK; pass++) {
        size_t moved = 0, crossings = 0;
        q.n = 0;
        for (i = 0; i < n && rc == QC_OK; i++)
            rc = qc_points_push(ctx, &q, c->v[i]);
        for (i = open ? 1 : 0; i < (open ? n - 1 : n) && rc == QC_OK; i++) {
            qc_vec2 a = c->v[i == 0 ? n - 1 : i - 1], p = c->v[i], b = c->v[i + 1 == n ? 0 : i + 1];
            qc_vec2 m;
            if (circumradius(a, p, b) >= turn)
                continue;
            m = QC__V2(p.x + EASE_STEP * (0.5 * (a.x + b.x) - p.x),
                       p.y + EASE_STEP * (0.5 * (a.y + b.y) - p.y));
            if (qc__sdf_exact(s, m, NULL) < EASE_CLEAR * d)
                continue;
            q.v[i] = m;
            moved++;
        }
        if (rc < 0 || moved == 0)
            break;
        rc = qc_path_self_crossings(ctx, q.v, q.n, !open, &crossings);
        if (rc < 0 || crossings > 0)
            break;
        memcpy(c->v, q.v, n * sizeof *c->v);
    }
    qc_points_free(ctx, &q);
    return rc;
}
