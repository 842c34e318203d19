/*
 * The straight links between a patch's pattern and its seams. The seam
 * point nearest a piece's end is the shortest link, but a pass of the
 * pattern can lie between them (a vine along the seam, a pebble hugging
 * it), and the link then crosses the pattern. So the nearest is kept when
 * its link crosses nothing; otherwise the nearest of a bounded number of
 * other seam points of the patch (each edge's nearest point and points
 * spread evenly along the rings) whose link crosses no segment of the
 * flattened pattern and stays inside the patch. None: the nearest. (No
 * margin is kept from the pattern: the stitch plan keeps a link's corners,
 * so a link grazing a pass stays on its side.)
 */
#include <math.h>
#include <string.h>

#include "quilt_internal.h"

#define LINK_TRIES 64 /* other seam points tried per link */
#define LINK_FLAT_TOL 0.05 /* mm: the pattern's flattening for the test */

static double dist(qc_vec2 a, qc_vec2 b)
{
    return qc_hypot(a.x - b.x, a.y - b.y);
}

/* Segment k runs to point k + 1; the last point of a piece to itself (a
 * zero-length segment crossing nothing), so pieces are not joined. */
static uint32_t next_pt(const void *ud, uint32_t k)
{
    const qc__links *lk = (const qc__links *)ud;
    size_t lo = 0, hi = lk->ends.n;

    while (lo < hi) { /* the first piece end past k (ends ascend) */
        size_t mid = lo + (hi - lo) / 2;

        if (lk->ends.i[mid] <= k)
            lo = mid + 1;
        else
            hi = mid;
    }
    if (lo < lk->ends.n && lk->ends.i[lo] == k + 1)
        return k;
    return k + 1 < lk->flat.n ? k + 1 : k;
}

int qc__links_init(qc_ctx *ctx, const qc_path *pattern, qc__links *lk)
{
    double len = 0;
    size_t k;
    int rc;

    memset(lk, 0, sizeof *lk);
    rc = qc_curve_flatten(ctx, pattern, LINK_FLAT_TOL, &lk->flat, &lk->ends);
    if (rc == QC_OK && lk->flat.n >= 2) {
        for (k = 0; k + 1 < lk->flat.n; k++)
            len += dist(lk->flat.v[k], lk->flat.v[k + 1]);
        rc = qc__seg_grid_build(ctx, &lk->grid, lk->flat.v, lk->flat.n, next_pt, lk,
                                fmax(2.0 * len / (double)lk->flat.n, 1e-3), 4.0);
        lk->have_grid = rc == QC_OK;
    }
    if (rc < 0)
        qc__links_free(ctx, lk);
    return rc;
}

void qc__links_free(qc_ctx *ctx, qc__links *lk)
{
    if (lk->have_grid)
        qc__seg_grid_free(ctx, &lk->grid);
    qc_points_free(ctx, &lk->flat);
    qc_order_free(ctx, &lk->ends);
    memset(lk, 0, sizeof *lk);
}

static int cross_proper(qc_vec2 a, qc_vec2 b, qc_vec2 c, qc_vec2 d)
{
    double o1 = qc_orient2d(a, b, c), o2 = qc_orient2d(a, b, d), o3, o4;

    if (!((o1 > 0.0 && o2 < 0.0) || (o1 < 0.0 && o2 > 0.0)))
        return 0;
    o3 = qc_orient2d(c, d, a);
    o4 = qc_orient2d(c, d, b);
    return (o3 > 0.0 && o4 < 0.0) || (o3 < 0.0 && o4 > 0.0);
}

/* Whether link ab properly crosses a segment of the pattern (as the
 * self-crossing measure counts). */
static int crosses_pattern(const qc__links *lk, qc_vec2 a, qc_vec2 b)
{
    size_t c[4], x, y, j;

    if (!lk->have_grid)
        return 0;
    qc__seg_grid_cells(&lk->grid, a, b, c);
    for (y = c[1]; y <= c[3]; y++)
        for (x = c[0]; x <= c[2]; x++) {
            size_t cell = y * lk->grid.gx + x;

            for (j = lk->grid.start[cell]; j < lk->grid.start[cell + 1]; j++) {
                uint32_t k = lk->grid.seg[j];

                if (cross_proper(a, b, lk->flat.v[k], lk->flat.v[next_pt(lk, k)]))
                    return 1;
            }
        }
    return 0;
}

/* Whether link ab (a on patch i's boundary) stays inside the patch: it
 * crosses none of the patch's ring edges and its midpoint is inside. */
static int inside_patch(const qc__seams *s, const qc_region *region, size_t patch, qc_vec2 a,
                        qc_vec2 b)
{
    size_t r, j;
    qc_vec2 mid;

    for (r = patch ? s->patch_end[patch - 1] : 0; r < s->patch_end[patch]; r++) {
        size_t start = r ? s->ring_end[r - 1] : 0, end = s->ring_end[r];

        for (j = start; j < end; j++)
            if (cross_proper(a, b, s->v[s->bnd[j]], s->v[s->bnd[j + 1 < end ? j + 1 : start]]))
                return 0;
    }
    mid.x = 0.5 * (a.x + b.x);
    mid.y = 0.5 * (a.y + b.y);
    return qc_region_contains(region, mid);
}

typedef struct cand {
    double d;
    qc__seam_pt sp;
} cand;

/* The point at parameter t of ring edge pa-pb (vertices a, b), as
 * qc__seams_nearest encodes it. */
static qc__seam_pt on_edge(const qc__seams *s, uint32_t a, uint32_t b, double t)
{
    qc__seam_pt sp;
    qc_vec2 pa = s->v[a], pb = s->v[b];

    sp.p.x = pa.x + t * (pb.x - pa.x);
    sp.p.y = pa.y + t * (pb.y - pa.y);
    if (t <= 0)
        sp.p = pa;
    if (t >= 1)
        sp.p = pb;
    sp.u = t >= 1 ? b : a;
    sp.v = t <= 0 ? a : b;
    return sp;
}

/* Keeps the LINK_TRIES nearest candidates, sorted; a tie keeps the first. */
static void keep(cand *c, size_t *n, qc__seam_pt sp, qc_vec2 p)
{
    double d = dist(sp.p, p);
    size_t k = *n;

    if (k == LINK_TRIES) {
        if (!(d < c[k - 1].d))
            return;
        k--;
    } else {
        (*n)++;
    }
    while (k > 0 && d < c[k - 1].d) {
        c[k] = c[k - 1];
        k--;
    }
    c[k].d = d;
    c[k].sp = sp;
}

/* The candidates: every ring edge's point nearest p, and LINK_TRIES points
 * spread evenly along the patch's rings. */
static void candidates(const qc__seams *s, size_t patch, qc_vec2 p, cand *c, size_t *n)
{
    size_t r0 = patch ? s->patch_end[patch - 1] : 0, r, j;
    double perim = 0, step, at = 0, next = 0;

    *n = 0;
    for (r = r0; r < s->patch_end[patch]; r++) {
        size_t start = r ? s->ring_end[r - 1] : 0, end = s->ring_end[r];

        for (j = start; j < end; j++)
            perim += dist(s->v[s->bnd[j]], s->v[s->bnd[j + 1 < end ? j + 1 : start]]);
    }
    step = perim / LINK_TRIES;
    for (r = r0; r < s->patch_end[patch]; r++) {
        size_t start = r ? s->ring_end[r - 1] : 0, end = s->ring_end[r];

        for (j = start; j < end; j++) {
            uint32_t a = s->bnd[j], b = s->bnd[j + 1 < end ? j + 1 : start];
            qc_vec2 pa = s->v[a], pb = s->v[b];
            double dx = pb.x - pa.x, dy = pb.y - pa.y, l2 = dx * dx + dy * dy, l = sqrt(l2);
            double t = l2 > 0 ? ((p.x - pa.x) * dx + (p.y - pa.y) * dy) / l2 : 0;

            keep(c, n, on_edge(s, a, b, t < 0 ? 0 : t > 1 ? 1 : t), p);
            while (step > 0 && next < at + l) {
                keep(c, n, on_edge(s, a, b, l > 0 ? (next - at) / l : 0), p);
                next += step;
            }
            at += l;
        }
    }
}

qc__seam_pt qc__links_seam_pt(const qc__links *lk, const qc__seams *s, const qc_region *region,
                              size_t patch, qc_vec2 p)
{
    qc__seam_pt best = qc__seams_nearest(s, patch, p);
    cand c[LINK_TRIES];
    size_t n, k;

    if (!crosses_pattern(lk, best.p, p))
        return best;
    candidates(s, patch, p, c, &n);
    for (k = 0; k < n; k++)
        if (!crosses_pattern(lk, c[k].sp.p, p) && inside_patch(s, region, patch, c[k].sp.p, p))
            return c[k].sp;
    return best;
}
