/*
 * Waves on the meander's straight runs (issue 17: none longer than 2 d).
 * The evolution lays the curve straight along a seam (drawn onto the
 * clearance contour) and between parallel neighbours. Each run of the
 * polyline longer than run d (the caller's) that stays within d/20 of its
 * chord (as test_meander measures a straight run) is redrawn as a sine of about
 * WAVE_LENGTH d and WAVE_SIDE d either side, a whole number of waves so it
 * meets the curve where the run did. Near the boundary its crests towards
 * the seam stop WAVE_INNER d short of it (the troughs, away from the seam,
 * stay within 1/4 in of it: the run was at the clearance). A wave is kept
 * only where it stays inside and crosses nothing: the waves of two
 * neighbouring runs d apart leave them at least d - 2 WAVE_SIDE apart.
 */
#include <math.h>
#include <string.h>

#include "family_meander.h"

#define WAVE_TOL 0.05     /* straight: within this of the chord, times d */
#define WAVE_LENGTH 1.5   /* wavelength, times d (a whole one in any 2 d) */
#define WAVE_SIDE 0.07    /* amplitude either side, times d */
#define WAVE_RIM_BAND 0.5 /* runs nearer the boundary than this, times d, are clipped there */
#define WAVE_STEP 0.15    /* the wave's vertex spacing, times d */
#define WAVE_INNER 0.06   /* a waved vertex stays this far inside, times d */

/* The last vertex j > i such that c[i..j] all lie within tol of chord i j. */
static size_t run_end(const qc_points *c, size_t i, double tol)
{
    size_t j, k, best = i + 1;

    for (j = i + 2; j < c->n; j++) {
        qc_vec2 a = c->v[i], b = c->v[j];
        double len = qc_hypot(b.x - a.x, b.y - a.y);
        for (k = i + 1; k < j; k++)
            if (fabs(qc_orient2d(a, b, c->v[k])) > tol * len)
                return best;
        best = j;
    }
    return best;
}

/* Whether segment ab crosses a segment of c other than lo..hi (the run's
 * own and the two touching it; lo 0 of a closed curve: its last too). */
static int crosses_curve(const qc_points *c, int open, const qc__seg_grid *g, size_t lo, size_t hi,
                         qc_vec2 a, qc_vec2 b)
{
    size_t n = c->n, cell[4], x, y, e;

    qc__seg_grid_cells(g, a, b, cell);
    for (y = cell[1]; y <= cell[3]; y++)
        for (x = cell[0]; x <= cell[2]; x++)
            for (e = g->start[y * g->gx + x]; e < g->start[y * g->gx + x + 1]; e++) {
                size_t s = g->seg[e], t = s + 1 == n ? 0 : s + 1;
                if (open && t == 0)
                    continue;
                if (s >= lo && s <= hi)
                    continue;
                if (!open && lo == 0 && s + 1 == n)
                    continue;
                if (qc__segs_cross_proper(a, b, c->v[s], c->v[t]))
                    return 1;
            }
    return 0;
}

/* Appends the wave replacing run c[i..j] to out; 0 if it would leave the
 * region or cross the curve (out then unchanged). */
static int wave_run(qc_ctx *ctx, const qc_points *c, int open, const qc__seg_grid *g,
                    const qc__sdf *s, double d, size_t i, size_t j, qc_points *out, int *ok)
{
    qc_vec2 a = c->v[i], b = c->v[j], mid = QC__V2(0.5 * (a.x + b.x), 0.5 * (a.y + b.y)), grad;
    double len = qc_hypot(b.x - a.x, b.y - a.y), ux = (b.x - a.x) / len, uy = (b.y - a.y) / len;
    double v = qc__sdf_exact(s, mid, &grad), waves = floor(len / (WAVE_LENGTH * d) + 0.5);
    double nx = -uy, ny = ux, amp = WAVE_SIDE * d, lam;
    size_t m = (size_t)ceil(len / (WAVE_STEP * d)), k, keep = out->n;
    int rim = v < WAVE_RIM_BAND * d;
    qc_vec2 prev = a;

    *ok = 0;
    if (waves < 1.0)
        waves = 1.0;
    lam = len / waves;
    if (rim && nx * grad.x + ny * grad.y > 0.0) /* w > 0: towards the boundary */
        nx = -nx, ny = -ny;
    for (k = 0; k <= m; k++) {
        double t = len * (double)k / (double)m, w, px, py;
        qc_vec2 p;
        /* the run's own vertices are in line: its point at t is on the chord */
        w = amp * qc_sin(2.0 * QC_PI * t / lam);
        px = a.x + ux * t;
        py = a.y + uy * t;
        if (rim && w > 0.0) /* no nearer the boundary than WAVE_INNER d */
            w = fmax(0.0, fmin(w, qc__sdf_exact(s, QC__V2(px, py), NULL) - WAVE_INNER * d));
        px += nx * w;
        py += ny * w;
        p = QC__V2(px, py);
        if (k > 0 && !qc__meander_seg_inside(s, prev, p, 0.5 * WAVE_INNER * d))
            break;
        if (k > 0 && crosses_curve(c, open, g, i == 0 ? 0 : i - 1, j, prev, p))
            break;
        if (k < m)
            QC__TRY(qc_points_push(ctx, out, p));
        prev = p;
    }
    if (k <= m) {
        out->n = keep;
        return QC_OK;
    }
    *ok = 1;
    return QC_OK;
}

static uint32_t next_vertex(const void *ud, uint32_t k)
{
    const qc_points *c = ud;

    return k + 1 == c->n ? 0 : k + 1;
}

int qc__meander_wave(qc_ctx *ctx, qc_points *c, int open, double d, double run, const qc__sdf *s)
{
    qc_points out = {0};
    qc__seg_grid g;
    size_t i, j;
    int rc;

    if (c->n < 4 || !(d > 0.0))
        return QC_OK;
    rc = qc__seg_grid_build(ctx, &g, c->v, open ? c->n - 1 : c->n, next_vertex, c, d, 4.0);
    if (rc < 0)
        return rc;
    for (i = 0; i < c->n && rc == QC_OK;) {
        int ok = 0;
        j = i + 1 < c->n ? run_end(c, i, WAVE_TOL * d) : i;
        if (j > i && qc_hypot(c->v[j].x - c->v[i].x, c->v[j].y - c->v[i].y) > run * d)
            rc = wave_run(ctx, c, open, &g, s, d, i, j, &out, &ok);
        if (rc == QC_OK && ok) {
            i = j; /* j itself starts what follows */
            continue;
        }
        if (rc == QC_OK)
            rc = qc_points_push(ctx, &out, c->v[i]);
        i++;
    }
    qc__seg_grid_free(ctx, &g);
    if (rc == QC_OK) {
        qc_points t = *c;
        *c = out;
        out = t;
    }
    qc_points_free(ctx, &out);
    return rc;
}
