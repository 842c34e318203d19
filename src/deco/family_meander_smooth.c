/*
 * The meander's curve sewn smooth without crossing itself. The evolved
 * polyline never crosses itself, but the Catmull-Rom spline through it
 * bulges up to a sixth of a chord to the side, which can cross a
 * neighbouring line where two pass close or the curve turns hard. So the
 * spline is flattened and checked (as src/measure/crossings.c counts), and
 * every span in a crossing is drawn flatter (its control points pulled
 * towards its ends) until none is left: at worst those spans become the
 * polyline's own segments.
 */
#include <math.h>
#include <string.h>

#include "family_meander.h"
#include "region_index.h"

#define FLAT_TOL 0.01   /* flattening for the check, mm (as the tests measure) */
#define LEVELS 4        /* control points kept: 1, 1/2, 1/4, then a straight span */
#define ROUNDS 16       /* then every span still crossing is made straight */
#define STRAY 0.05      /* a span further outside than this (mm) is flattened too: half
                         * of what qc_generate's keep-inside pass lets by, so that
                         * pass (which could reroute it across a neighbour) leaves it */
#define STRAY_STEP 0.1  /* mm */
#define BEND_ROUNDS 6   /* chords over the boundary bent inside, at most this often */
#define BEND_INNER 0.05 /* the bend's new vertex lies this far inside, times d */
#define BEND_STEPS 16   /* places tried across the chord, each side */

/* Segment k of an open polyline ends at the next point. */
static uint32_t next_point(const void *ud, uint32_t k)
{
    (void)ud;
    return k + 1;
}

/* Scratch of the smoothing rounds. */
typedef struct smooth {
    qc_path span;      /* one span on its own, to flatten */
    qc_points part;    /* it flattened */
    qc_points flat;    /* the whole path flattened */
    uint32_t *owner;   /* per flat segment: its span */
    size_t owner_cap;
    qc__rindex ix;     /* the region's outline, with an sdf */
} smooth;

/* The path through r[0..n) (no two consecutive points coincide): span k
 * is the spline's span with its control points pulled towards its ends by
 * level[k], straight at the last level. */
static int draw(qc_ctx *ctx, const qc_path *spline, const qc_vec2 *r, size_t n, size_t spans,
                const unsigned char *level, qc_path *out)
{
    size_t k;

    out->ncmd = out->npt = 0;
    QC__TRY(qc_path_move_to(ctx, out, r[0]));
    for (k = 0; k < spans; k++) {
        qc_vec2 a = r[k], b = r[k + 1 == n ? 0 : k + 1];
        const qc_vec2 *c = spline->pt + 1 + 3 * k; /* MOVE, then 3 points a CUBIC */
        double f = 1.0 / (double)(1u << level[k]);

        if (level[k] + 1 >= LEVELS)
            QC__TRY(qc_path_line_to(ctx, out, b));
        else
            QC__TRY(qc_path_cubic_to(ctx, out,
                                     QC__V2(a.x + f * (c[0].x - a.x), a.y + f * (c[0].y - a.y)),
                                     QC__V2(b.x + f * (c[1].x - b.x), b.y + f * (c[1].y - b.y)),
                                     b));
    }
    return QC_OK;
}

/* Whether segment ab strays outside the region by more than STRAY,
 * sampled every STRAY_STEP against the exact outline, as qc_generate's
 * keep-inside pass samples (the field only says where to look). */
static int strays(const qc__sdf *sdf, const qc__rindex *ix, qc_vec2 a, qc_vec2 b)
{
    double len = qc_hypot(b.x - a.x, b.y - a.y);
    size_t i, m;

    if (qc__sdf_at(sdf, a) > len + 2.0 * sdf->h) /* the whole segment is well inside */
        return 0;
    m = (size_t)ceil(len / STRAY_STEP);
    for (i = 0; i <= m; i++) {
        double t = m > 0 ? (double)i / (double)m : 0.0;
        qc_vec2 p = QC__V2(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y));
        if (!qc__rindex_contains(ix, p) && !qc__rindex_near(ix, p, STRAY))
            return 1;
    }
    return 0;
}

/* Flattens path (as draw() made it, spans commands after its MOVE) span
 * by span, so every flat segment knows its span; sets hit[k] for every
 * span in a crossing or (with sdf) straying outside the region, and
 * counts them in *found. */
static int find_crossings(qc_ctx *ctx, smooth *w, const qc_path *path, size_t spans,
                          const qc__sdf *sdf, double h, unsigned char *hit, size_t *found)
{
    size_t k, i, j, c, pi = 1, nf;
    qc__seg_grid grid;

    w->flat.n = 0;
    *found = 0;
    for (k = 0; k < spans; k++) {
        unsigned char cmd = path->cmd[k + 1];
        w->span.ncmd = w->span.npt = 0;
        w->part.n = 0;
        QC__TRY(qc_path_move_to(ctx, &w->span, path->pt[pi - 1]));
        if (cmd == QC_PATH_CUBIC)
            QC__TRY(qc_path_cubic_to(ctx, &w->span, path->pt[pi], path->pt[pi + 1],
                                     path->pt[pi + 2]));
        else
            QC__TRY(qc_path_line_to(ctx, &w->span, path->pt[pi]));
        pi += cmd == QC_PATH_CUBIC ? 3 : 1;
        QC__TRY(qc_curve_flatten(ctx, &w->span, FLAT_TOL, &w->part, NULL));
        for (i = w->flat.n == 0 ? 0 : 1; i < w->part.n; i++) {
            QC__TRY(qc_points_push(ctx, &w->flat, w->part.v[i]));
            if (w->flat.n >= 2) {
                QC__TRY(QC__RESERVE(ctx, w->owner, w->owner_cap, w->flat.n - 1));
                w->owner[w->flat.n - 2] = (uint32_t)k;
            }
        }
    }
    nf = w->flat.n;
    for (i = 0; sdf != NULL && i + 1 < nf; i++)
        if (strays(sdf, &w->ix, w->flat.v[i], w->flat.v[i + 1])) {
            (*found)++;
            hit[w->owner[i]] = 1;
        }
    if (nf < 4)
        return QC_OK;
    QC__TRY(qc__seg_grid_build(ctx, &grid, w->flat.v, nf - 1, next_point, NULL, h, 4.0));
    for (c = 0; c < grid.gx * grid.gy; c++)
        for (i = grid.start[c]; i < grid.start[c + 1]; i++)
            for (j = i + 1; j < grid.start[c + 1]; j++) {
                size_t s = grid.seg[i], t = grid.seg[j], gap = s > t ? s - t : t - s;
                if (gap < 2 || gap + 2 == nf) /* neighbours (a closed path's ends meet) */
                    continue;
                if (!qc__segs_cross_proper(w->flat.v[s], w->flat.v[s + 1], w->flat.v[t], w->flat.v[t + 1]))
                    continue;
                (*found)++;
                hit[w->owner[s]] = hit[w->owner[t]] = 1;
            }
    qc__seg_grid_free(ctx, &grid);
    return QC_OK;
}

/* A point to bend ab through: the middle of its run outside (as strays()
 * samples), moved across ab to the nearest place inner inside the exact
 * outline; *ok 0 when there is none near. */
static qc_vec2 bend_point(const qc__rindex *ix, qc_vec2 a, qc_vec2 b, double inner, int *ok)
{
    double len = qc_hypot(b.x - a.x, b.y - a.y), t0 = -1.0, t1 = -1.0, t;
    size_t i, m = (size_t)ceil(len / STRAY_STEP);
    qc_vec2 mid, nrm;
    int k;

    *ok = 0;
    for (i = 0; i <= m && m > 0; i++) {
        qc_vec2 p;
        t = (double)i / (double)m;
        p = QC__V2(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y));
        if (!qc__rindex_contains(ix, p) && !qc__rindex_near(ix, p, STRAY)) {
            if (t0 < 0.0)
                t0 = t;
            t1 = t;
        }
    }
    if (t0 < 0.0 || !(len > 0.0))
        return a;
    t = 0.5 * (t0 + t1);
    mid = QC__V2(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y));
    nrm = QC__V2(-(b.y - a.y) / len, (b.x - a.x) / len);
    for (k = 1; k <= BEND_STEPS; k++) { /* out to half the chord, either side */
        double off = 0.5 * len * (double)k / BEND_STEPS;
        qc_vec2 p = QC__V2(mid.x + off * nrm.x, mid.y + off * nrm.y);
        qc_vec2 q = QC__V2(mid.x - off * nrm.x, mid.y - off * nrm.y);
        if (qc__rindex_admits(ix, p, inner)) {
            *ok = 1;
            return p;
        }
        if (qc__rindex_admits(ix, q, inner)) {
            *ok = 1;
            return q;
        }
    }
    return a;
}

/* r with a vertex added in every segment that cuts across the boundary (a
 * chord over a cusp's tip): its point furthest outside, moved inside; kept only
 * if the polyline still does not cross itself. */
static int bend_inside(qc_ctx *ctx, qc_points *r, int closed, const qc__sdf *sdf,
                       const qc__rindex *ix, double inner)
{
    qc_points t = {0};
    size_t i, added = 0, crossings = 0;
    int rc = QC_OK;

    for (i = 0; i < r->n && rc == QC_OK; i++) {
        qc_vec2 a = r->v[i], b = r->v[i + 1 == r->n ? 0 : i + 1];
        rc = qc_points_push(ctx, &t, a);
        if (rc == QC_OK && (closed || i + 1 < r->n) && strays(sdf, ix, a, b)) {
            int ok;
            qc_vec2 m = bend_point(ix, a, b, inner, &ok);
            if (ok) {
                rc = qc_points_push(ctx, &t, m);
                added++;
            }
        }
    }
    if (rc == QC_OK && added > 0)
        rc = qc_path_self_crossings(ctx, t.v, t.n, closed, &crossings);
    if (rc == QC_OK && added > 0 && crossings == 0) {
        qc_points u = *r;
        *r = t;
        t = u;
    }
    qc_points_free(ctx, &t);
    return rc;
}

int qc__meander_smooth(qc_ctx *ctx, const qc_vec2 *pts, size_t n, int closed, double d,
                       const qc__sdf *sdf, qc_path *out)
{
    qc_points r = {0};
    qc_path spline = {0}, path = {0};
    smooth w;
    unsigned char *level = NULL, *hit = NULL;
    size_t i, spans = 0, found = 1, round;
    int rc = QC_OK;

    memset(&w, 0, sizeof w);
    if (sdf != NULL)
        QC__TRY(qc__rindex_build(ctx, sdf->region, &w.ix));
    for (i = 0; i < n && rc == QC_OK; i++) /* as the spline skips them: no repeats */
        if (r.n == 0 || qc_hypot(pts[i].x - r.v[r.n - 1].x, pts[i].y - r.v[r.n - 1].y) >= 1e-9)
            rc = qc_points_push(ctx, &r, pts[i]);
    while (rc == QC_OK && closed && r.n > 1 &&
           qc_hypot(r.v[0].x - r.v[r.n - 1].x, r.v[0].y - r.v[r.n - 1].y) < 1e-9)
        r.n--;
    for (i = 0; i < BEND_ROUNDS && rc == QC_OK && sdf != NULL && r.n >= 3; i++)
        rc = bend_inside(ctx, &r, closed, sdf, &w.ix, BEND_INNER * d);
    if (rc == QC_OK)
        rc = qc_curve_catmull_rom(ctx, r.v, r.n, closed, &spline);
    if (rc < 0 || r.n < 3)
        goto done;
    spans = closed ? r.n : r.n - 1;
    if (spline.ncmd != spans + 1 || spline.npt != 1 + 3 * spans) /* not span for span: as it is */
        goto done;
    level = qc__alloc(ctx, spans);
    hit = qc__alloc(ctx, spans);
    if (level == NULL || hit == NULL) {
        rc = QC_ENOMEM;
        goto done;
    }
    memset(level, 0, spans);
    for (round = 0; round < ROUNDS && found > 0 && rc == QC_OK; round++) {
        memset(hit, 0, spans);
        rc = draw(ctx, &spline, r.v, r.n, spans, level, &path);
        if (rc == QC_OK)
            rc = find_crossings(ctx, &w, &path, spans, sdf, 0.5 * d, hit, &found);
        for (i = 0; i < spans && rc == QC_OK; i++)
            if (hit[i] && level[i] + 1 < LEVELS)
                level[i]++;
            else if (hit[i] && round + 1 == ROUNDS)
                level[i] = LEVELS - 1;
    }
    /* left: spans straight already that still stray (a chord over a cusp,
     * as the polyline itself strays: qc_generate's keep-inside pass takes
     * them), or crossings the last round's straightening has not been
     * checked for: those alone are straightened, a few rounds over, before
     * the whole polyline is drawn (its corners turn far tighter) */
    for (round = 0; round < ROUNDS && found > 0 && rc == QC_OK; round++) {
        memset(hit, 0, spans);
        rc = draw(ctx, &spline, r.v, r.n, spans, level, &path);
        if (rc == QC_OK)
            rc = find_crossings(ctx, &w, &path, spans, NULL, 0.5 * d, hit, &found);
        for (i = 0; i < spans && rc == QC_OK; i++)
            if (hit[i])
                level[i] = LEVELS - 1;
    }
    if (rc == QC_OK && found > 0) { /* the polyline itself */
        memset(level, LEVELS - 1, spans);
        rc = draw(ctx, &spline, r.v, r.n, spans, level, &path);
    }
done:
    if (rc == QC_OK)
        rc = qc_path_append(ctx, out, path.ncmd > 0 ? &path : &spline, 0);
    qc__free(ctx, level, spans);
    qc__free(ctx, hit, spans);
    qc_points_free(ctx, &r);
    qc_path_free(ctx, &spline);
    qc_path_free(ctx, &path);
    qc_path_free(ctx, &w.span);
    qc_points_free(ctx, &w.part);
    qc_points_free(ctx, &w.flat);
    if (sdf != NULL)
        qc__rindex_free(ctx, &w.ix);
    qc__free(ctx, w.owner, w.owner_cap * sizeof *w.owner);
    return rc;
}
