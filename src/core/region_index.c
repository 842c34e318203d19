/*
 * Boundary edge index: a uniform grid for distance queries and horizontal
 * bands for the even-odd ray test, both in compressed-row form.
 */
#include <math.h>
#include <string.h>

#include "region_index.h"

static double clampd(double v, double lo, double hi)
{
    return v < lo ? lo : v > hi ? hi : v;
}

static size_t cell_of(double v, double lo, double size, size_t n)
{
    double c = floor((v - lo) / size);
    return (size_t)clampd(c, 0.0, (double)(n - 1));
}

/* Fills next[] from the ring structure. */
static void link_rings(const qc_region *r, uint32_t *next)
{
    size_t k, start = 0;

    for (k = 0; k < r->nrings; k++) {
        size_t end = r->ring_end[k], i;
        for (i = start; i < end; i++)
            next[i] = (uint32_t)(i + 1 < end ? i + 1 : start);
        start = end;
    }
}

/* Counting pass (fill == 0) then filling pass over the grid cells each edge's box covers. */
static size_t grid_pass(qc__rindex *ix, int fill)
{
    const qc_region *r = ix->region;
    size_t a, total = 0;

    for (a = 0; a < r->nv; a++) {
        qc_vec2 p = r->v[a], q = r->v[ix->next[a]];
        size_t x0 = cell_of(fmin(p.x, q.x), ix->box.min.x, ix->cell, ix->nx);
        size_t x1 = cell_of(fmax(p.x, q.x), ix->box.min.x, ix->cell, ix->nx);
        size_t y0 = cell_of(fmin(p.y, q.y), ix->box.min.y, ix->cell, ix->ny);
        size_t y1 = cell_of(fmax(p.y, q.y), ix->box.min.y, ix->cell, ix->ny);
        size_t x, y;

        for (y = y0; y <= y1; y++)
            for (x = x0; x <= x1; x++) {
                size_t c = y * ix->nx + x;
                if (fill)
                    ix->cell_edge[ix->cell_start[c]++] = (uint32_t)a;
                else
                    ix->cell_start[c + 1]++;
                total++;
            }
    }
    return total;
}

static size_t band_pass(qc__rindex *ix, int fill)
{
    const qc_region *r = ix->region;
    size_t a, total = 0;

    for (a = 0; a < r->nv; a++) {
        qc_vec2 p = r->v[a], q = r->v[ix->next[a]];
        size_t b0 = cell_of(fmin(p.y, q.y), ix->box.min.y, ix->band, ix->nband);
        size_t b1 = cell_of(fmax(p.y, q.y), ix->box.min.y, ix->band, ix->nband);
        size_t b;

        if (p.y == q.y)
            continue; /* horizontal edges never cross a horizontal ray */
        for (b = b0; b <= b1; b++) {
            if (fill)
                ix->band_edge[ix->band_start[b]++] = (uint32_t)a;
            else
                ix->band_start[b + 1]++;
            total++;
        }
    }
    return total;
}

/* Turns counts in start[1..n] into offsets, fills, and restores the starts. */
static int build_csr(qc_ctx *ctx, qc__rindex *ix, uint32_t **start, size_t n, uint32_t **items,
                     size_t *nitems, size_t (*pass)(qc__rindex *, int))
{
    size_t i, total;

    *start = qc__alloc_array(ctx, n + 1, sizeof **start);
    if (*start == NULL)
        return QC_ENOMEM;
    memset(*start, 0, (n + 1) * sizeof **start);
    total = pass(ix, 0);
    if (total > UINT32_MAX)
        return qc__fail(ctx, QC_ELIMIT, "region index needs %lu entries", (unsigned long)total);
    for (i = 0; i < n; i++)
        (*start)[i + 1] += (*start)[i];
    *items = qc__alloc_array(ctx, total ? total : 1, sizeof **items);
    if (*items == NULL)
        return QC_ENOMEM;
    *nitems = total;
    /* pass 2 advances start[c] to the end of cell c; shift back afterwards */
    pass(ix, 1);
    for (i = n; i > 0; i--)
        (*start)[i] = (*start)[i - 1];
    (*start)[0] = 0;
    return QC_OK;
}

int qc__rindex_build(qc_ctx *ctx, const qc_region *region, qc__rindex *ix)
{
    double w, h, cell;
    int rc;

    memset(ix, 0, sizeof *ix);
    ix->region = region;
    if (region->nv == 0)
        return QC_OK;
    ix->next = qc__alloc_array(ctx, region->nv, sizeof *ix->next);
    if (ix->next == NULL)
        return QC_ENOMEM;
    link_rings(region, ix->next);
    ix->box = qc_region_bbox(region);
    w = ix->box.max.x - ix->box.min.x;
    h = ix->box.max.y - ix->box.min.y;
    /* about one edge per cell, at most 1024 x 1024 cells */
    cell = sqrt(w * h / (double)region->nv);
    cell = fmax(cell, fmax(w, h) / 1024.0);
    if (!(cell > 0.0))
        cell = fmax(fmax(w, h), 1.0);
    ix->cell = cell;
    ix->nx = (size_t)clampd(ceil(w / cell), 1.0, 1024.0);
    ix->ny = (size_t)clampd(ceil(h / cell), 1.0, 1024.0);
    ix->nband = (size_t)clampd(ceil(sqrt((double)region->nv)) * 2.0, 1.0, 65536.0);
    ix->band = h > 0.0 ? h / (double)ix->nband : 1.0;
    rc = build_csr(ctx, ix, &ix->cell_start, ix->nx * ix->ny, &ix->cell_edge, &ix->ncell_edge,
                   grid_pass);
    if (rc == QC_OK)
        rc = build_csr(ctx, ix, &ix->band_start, ix->nband, &ix->band_edge, &ix->nband_edge,
                       band_pass);
    if (rc < 0)
        qc__rindex_free(ctx, ix);
    return rc;
}

void qc__rindex_free(qc_ctx *ctx, qc__rindex *ix)
{
    size_t nv = ix->region != NULL ? ix->region->nv : 0;

    qc__free(ctx, ix->next, nv * sizeof *ix->next);
    if (ix->cell_start != NULL)
        qc__free(ctx, ix->cell_start, (ix->nx * ix->ny + 1) * sizeof *ix->cell_start);
    qc__free(ctx, ix->cell_edge, (ix->ncell_edge ? ix->ncell_edge : 1) * sizeof *ix->cell_edge);
    if (ix->band_start != NULL)
        qc__free(ctx, ix->band_start, (ix->nband + 1) * sizeof *ix->band_start);
    qc__free(ctx, ix->band_edge, (ix->nband_edge ? ix->nband_edge : 1) * sizeof *ix->band_edge);
    memset(ix, 0, sizeof *ix);
}

int qc__rindex_contains(const qc__rindex *ix, qc_vec2 p)
{
    const qc_vec2 *v = ix->region->v;
    size_t b, i;
    int inside = 0;

    if (ix->region->nv == 0 || p.y < ix->box.min.y || p.y > ix->box.max.y ||
        p.x < ix->box.min.x || p.x > ix->box.max.x)
        return 0;
    b = cell_of(p.y, ix->box.min.y, ix->band, ix->nband);
    for (i = ix->band_start[b]; i < ix->band_start[b + 1]; i++) {
        uint32_t e = ix->band_edge[i];
        int m = qc__ray_edge(p, v[e], v[ix->next[e]]);

        if (m == 2)
            return 1;
        inside ^= m;
    }
    /* horizontal edges are not banded: a point on one is on the boundary */
    return inside || (ix->region->nv > 0 && qc__rindex_near(ix, p, 0.0));
}

int qc__rindex_near(const qc__rindex *ix, qc_vec2 p, double r)
{
    const qc_vec2 *v = ix->region->v;
    size_t x0, x1, y0, y1, x, y;
    double r2 = r * r;

    if (ix->region->nv == 0 || p.x + r < ix->box.min.x || p.x - r > ix->box.max.x ||
        p.y + r < ix->box.min.y || p.y - r > ix->box.max.y)
        return 0;
    x0 = cell_of(p.x - r, ix->box.min.x, ix->cell, ix->nx);
    x1 = cell_of(p.x + r, ix->box.min.x, ix->cell, ix->nx);
    y0 = cell_of(p.y - r, ix->box.min.y, ix->cell, ix->ny);
    y1 = cell_of(p.y + r, ix->box.min.y, ix->cell, ix->ny);
    for (y = y0; y <= y1; y++)
        for (x = x0; x <= x1; x++) {
            size_t c = y * ix->nx + x, i;
            for (i = ix->cell_start[c]; i < ix->cell_start[c + 1]; i++) {
                uint32_t e = ix->cell_edge[i];
                double d2 = qc__seg_dist2(p, v[e], v[ix->next[e]]);
                if (d2 < r2 || (r == 0.0 && d2 == 0.0))
                    return 1;
            }
        }
    return 0;
}

int qc__rindex_admits(const qc__rindex *ix, qc_vec2 p, double margin)
{
    if (!qc__rindex_contains(ix, p))
        return 0;
    return margin <= 0.0 || !qc__rindex_near(ix, p, margin);
}

/* The grid cells a box covers, at most MAX_BOX_CELLS of them: a larger box
 * is answered by the caller's sampling instead. */
#define MAX_BOX_CELLS 64

int qc__rindex_box_inside(const qc__rindex *ix, qc_bbox b)
{
    const qc_vec2 *v = ix->region->v;
    size_t x0, x1, y0, y1, x, y;

    if (ix->region->nv == 0 || !(b.min.x > ix->box.min.x) || !(b.max.x < ix->box.max.x) ||
        !(b.min.y > ix->box.min.y) || !(b.max.y < ix->box.max.y))
        return 0;
    x0 = cell_of(b.min.x, ix->box.min.x, ix->cell, ix->nx);
    x1 = cell_of(b.max.x, ix->box.min.x, ix->cell, ix->nx);
    y0 = cell_of(b.min.y, ix->box.min.y, ix->cell, ix->ny);
    y1 = cell_of(b.max.y, ix->box.min.y, ix->cell, ix->ny);
    if ((x1 - x0 + 1) * (y1 - y0 + 1) > MAX_BOX_CELLS)
        return 0;
    /* an edge is filed in every cell its own box covers, so any edge whose
     * box meets b is filed in a cell that b covers */
    for (y = y0; y <= y1; y++)
        for (x = x0; x <= x1; x++) {
            size_t c = y * ix->nx + x, i;
            for (i = ix->cell_start[c]; i < ix->cell_start[c + 1]; i++) {
                uint32_t e = ix->cell_edge[i];
                qc_vec2 p = v[e], q = v[ix->next[e]];
                /* the edge's box meets b (comparisons: fmin and fmax are calls) */
                if ((p.x >= b.min.x || q.x >= b.min.x) && (p.x <= b.max.x || q.x <= b.max.x) &&
                    (p.y >= b.min.y || q.y >= b.min.y) && (p.y <= b.max.y || q.y <= b.max.y))
                    return 0;
            }
        }
    /* no edge meets b: all of it lies on one side, that of its centre */
    return qc__rindex_contains(ix, QC__V2(0.5 * (b.min.x + b.max.x), 0.5 * (b.min.y + b.max.y)));
}
