/*
 * Boundary edge index: a uniform grid for distance queries and horizontal
 * bands for the even-odd ray test, both in compressed-row form, and the
 * finer raster of rings and sides (region_index.h) that answers a query
 * far enough from the boundary, or near enough to it, by one look.
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
    return qc__grid_cell((v - lo) / size, n);
}

/* cell_of for v >= lo (a point in the box): truncation is floor there, no libm call. */
static size_t cell_in(double v, double lo, double size, size_t n)
{
    size_t c = (size_t)((v - lo) / size);
    return c < n ? c : n - 1;
}

static int in_box(const qc__rindex *ix, qc_vec2 p)
{
    return p.x >= ix->box.min.x && p.x <= ix->box.max.x && p.y >= ix->box.min.y &&
           p.y <= ix->box.max.y;
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
        size_t x0 = cell_of(qc__lesser(p.x, q.x), ix->box.min.x, ix->cell, ix->nx);
        size_t x1 = cell_of(qc__greater(p.x, q.x), ix->box.min.x, ix->cell, ix->nx);
        size_t y0 = cell_of(qc__lesser(p.y, q.y), ix->box.min.y, ix->cell, ix->ny);
        size_t y1 = cell_of(qc__greater(p.y, q.y), ix->box.min.y, ix->cell, ix->ny);
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
        size_t b0 = cell_of(qc__lesser(p.y, q.y), ix->box.min.y, ix->band, ix->nband);
        size_t b1 = cell_of(qc__greater(p.y, q.y), ix->box.min.y, ix->band, ix->nband);
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

/* The finer raster: about INFO_PER_EDGE cells an edge, for outlines of at
 * least INFO_MIN_EDGES edges (a few long edges: the bands answer at once). */
#define INFO_PER_EDGE 8.0
#define INFO_MIN_EDGES 64

/* The x of edge ab at height y, clamped to the edge (ab not horizontal). */
static double x_at(qc_vec2 a, qc_vec2 b, double y)
{
    double t = (y - a.y) / (b.y - a.y);

    t = t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t;
    return a.x + t * (b.x - a.x);
}

/* Marks (rings rg 0) the raster cells edge ab passes through, each row's
 * span widened by the slack so rounding cannot leave a point of the edge in
 * an unmarked cell, and flips info (meanwhile an odd count) of the cell
 * where ab crosses a row's centre line. */
static void mark_edge(qc__rindex *ix, unsigned char *rg, qc_vec2 a, qc_vec2 b)
{
    double e = ix->slack, ylo = qc__lesser(a.y, b.y), yhi = qc__greater(a.y, b.y);
    size_t j = cell_of(ylo - e, ix->box.min.y, ix->fcell, ix->fny);
    size_t j1 = cell_of(yhi + e, ix->box.min.y, ix->fcell, ix->fny);

    for (; j <= j1; j++) {
        double s0 = ix->box.min.y + (double)j * ix->fcell, yc = s0 + 0.5 * ix->fcell;
        double xa = a.x, xb = b.x;
        unsigned char *row = ix->info + j * ix->fnx, *rings = rg + j * ix->fnx;
        size_t i, i1;

        if (a.y != b.y) {
            xa = x_at(a, b, s0 - e > ylo ? s0 - e : ylo);
            xb = x_at(a, b, s0 + ix->fcell + e < yhi ? s0 + ix->fcell + e : yhi);
        }
        i = cell_of(qc__lesser(xa, xb) - e, ix->box.min.x, ix->fcell, ix->fnx);
        i1 = cell_of(qc__greater(xa, xb) + e, ix->box.min.x, ix->fcell, ix->fnx);
        memset(rings + i, 0, i1 - i + 1);
        if ((a.y > yc) != (b.y > yc))
            row[cell_of(a.x + (yc - a.y) * (b.x - a.x) / (b.y - a.y), ix->box.min.x, ix->fcell,
                        ix->fnx)] ^= 1;
    }
}

static unsigned char least(unsigned char a, unsigned char b)
{
    return a < b ? a : b;
}

/* One sweep of the chessboard transform over the rings rg (row-major,
 * nx by ny): each row takes its neighbours one ring further than the row
 * before (dir 1: above; -1: below) and then its neighbour before it along
 * the row. Both sweeps give each cell its Chebyshev distance to the
 * nearest 0. */
static void rings_sweep(unsigned char *rg, size_t nx, size_t ny, int dir)
{
    size_t k, x;

    for (k = 0; k < ny; k++) {
        size_t y = dir > 0 ? k : ny - 1 - k;
        unsigned char *r = rg + y * nx;
        const unsigned char *u = dir > 0 ? r - nx : r + nx;
        if (k > 0 && nx == 1)
            r[0] = least(r[0], (unsigned char)(u[0] + 1));
        else if (k > 0) {
            r[0] = least(r[0], (unsigned char)(least(u[0], u[1]) + 1));
            for (x = 1; x + 1 < nx; x++)
                r[x] = least(r[x], (unsigned char)(least(least(u[x - 1], u[x]), u[x + 1]) + 1));
            r[x] = least(r[x], (unsigned char)(least(u[x - 1], u[x]) + 1));
        }
        if (dir > 0)
            for (x = 1; x < nx; x++)
                r[x] = least(r[x], (unsigned char)(r[x - 1] + 1));
        else
            for (x = nx - 1; x-- > 0;)
                r[x] = least(r[x], (unsigned char)(r[x + 1] + 1));
    }
}

/* Turns each row's crossing flips into sides: a cell two rings or more from
 * every marked cell lies inside when an odd number of edges cross its row's
 * centre line right of it. Such crossings lie in marked cells, two columns
 * or more from it, so rounding cannot move one past it; and no edge passes
 * within a cell of it, so every point of it lies on its centre's side. */
static void settle_sides(qc__rindex *ix, const unsigned char *rg)
{
    size_t y, x;

    for (y = 0; y < ix->fny; y++) {
        unsigned char *row = ix->info + y * ix->fnx, in = 0;
        const unsigned char *rings = rg + y * ix->fnx;
        for (x = ix->fnx; x-- > 0;) {
            unsigned char flip = row[x];
            row[x] = (unsigned char)(rings[x] | (rings[x] >= 2 && in ? QC__RINDEX_INSIDE : 0));
            in ^= flip != 0;
        }
    }
}

static int build_info(qc_ctx *ctx, qc__rindex *ix)
{
    const qc_region *r = ix->region;
    double w = ix->box.max.x - ix->box.min.x, h = ix->box.max.y - ix->box.min.y, fc;
    unsigned char *rg;
    size_t a, n;

    if (r->nv < INFO_MIN_EDGES)
        return QC_OK;
    fc = fmax(sqrt(w * h / (INFO_PER_EDGE * (double)r->nv)), fmax(w, h) / 1024.0);
    ix->slack = 1e-9 * fc + 1e-12 * (fabs(ix->box.min.x) + fabs(ix->box.min.y) +
                                     fabs(ix->box.max.x) + fabs(ix->box.max.y));
    if (!(fc > 0.0) || !(ix->slack < 1e-3 * fc))
        return QC_OK; /* a sliver, or so far out that rounding blurs a cell */
    ix->fcell = fc;
    ix->fnx = (size_t)clampd(ceil(w / fc), 1.0, 1024.0);
    ix->fny = (size_t)clampd(ceil(h / fc), 1.0, 1024.0);
    n = ix->fnx * ix->fny;
    ix->info = qc__alloc(ctx, n);
    rg = qc__alloc(ctx, n);
    if (ix->info == NULL || rg == NULL) {
        qc__free(ctx, rg, n);
        return QC_ENOMEM; /* the caller frees info */
    }
    memset(ix->info, 0, n);
    memset(rg, QC__RINDEX_RINGS, n);
    for (a = 0; a < r->nv; a++)
        mark_edge(ix, rg, r->v[a], r->v[ix->next[a]]);
    rings_sweep(rg, ix->fnx, ix->fny, 1);
    rings_sweep(rg, ix->fnx, ix->fny, -1);
    settle_sides(ix, rg);
    qc__free(ctx, rg, n);
    return QC_OK;
}

#define GRID_PER_EDGE 9.0

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
    /* GRID_PER_EDGE cells an edge, at most 1024 x 1024: an outline's edges
     * fill a band, not the box, so one cell an edge would hold a dozen */
    cell = sqrt(w * h / (GRID_PER_EDGE * (double)region->nv));
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
    if (rc == QC_OK)
        rc = build_info(ctx, ix);
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
    if (ix->info != NULL)
        qc__free(ctx, ix->info, ix->fnx * ix->fny);
    memset(ix, 0, sizeof *ix);
}

/* The raster's byte for p, in the box. */
static unsigned info_at(const qc__rindex *ix, qc_vec2 p)
{
    size_t x = cell_in(p.x, ix->box.min.x, ix->fcell, ix->fnx);
    size_t y = cell_in(p.y, ix->box.min.y, ix->fcell, ix->fny);

    return ix->info[y * ix->fnx + x];
}

/* What the raster says of an edge within r of p: 0 none (every edge lies
 * farther than k - 1 cells, k p's rings), 1 one (a marked cell k away holds
 * a point of an edge, within a cell's diagonal of its far corner), -1 it
 * cannot say. The bounds keep the slack from the threshold. */
static int near_by_rings(const qc__rindex *ix, qc_vec2 p, double r)
{
    unsigned k;

    if (ix->info == NULL || !in_box(ix, p))
        return -1;
    k = info_at(ix, p) & QC__RINDEX_RINGS;
    if (k >= 2 && (double)(k - 1) * ix->fcell - ix->slack >= r)
        return 0;
    if (k < QC__RINDEX_RINGS && 1.41422 * (double)(k + 1) * ix->fcell + 4.0 * ix->slack < r)
        return 1;
    return -1;
}

/* Whether y lies in ab's span of heights: else qc__ray_edge gives 0, the
 * test inline (most edges of a band or grid row miss the ray). */
static int spans(qc_vec2 a, qc_vec2 b, double y)
{
    return a.y < b.y ? (y >= a.y && y <= b.y) : (y >= b.y && y <= a.y);
}

/* Whether edge ab, met in column x > 0 of a grid row it is filed in, is
 * filed in column x - 1 too (its left end's cell lies before x). */
static int filed_left(const qc__rindex *ix, qc_vec2 a, qc_vec2 b, size_t x)
{
    return (qc__lesser(a.x, b.x) - ix->box.min.x) / ix->cell < (double)x;
}

/* The ray from p towards +x, through the raster: the x of the centre of
 * the first cell past p's with a known side (two rings or more), its side
 * to *side; HUGE_VAL (side 0) when the row has none. */
static double known_along(const qc__rindex *ix, qc_vec2 p, unsigned *side)
{
    size_t x = cell_in(p.x, ix->box.min.x, ix->fcell, ix->fnx);
    const unsigned char *row =
        ix->info + cell_in(p.y, ix->box.min.y, ix->fcell, ix->fny) * ix->fnx;

    for (x++; x < ix->fnx; x++)
        if ((row[x] & QC__RINDEX_RINGS) >= 2) {
            *side = row[x] >> 7;
            return ix->box.min.x + ((double)x + 0.5) * ix->fcell;
        }
    *side = 0;
    return HUGE_VAL;
}

/* The even-odd count of the ray from p (in the box, near an edge) by the
 * edges it crosses before the raster's first known cell, plus that cell's
 * side; 2 when p lies on an edge. The edges it tests, non-horizontal ones
 * filed in p's grid row from the column before p's to the known cell's,
 * are the band's that cross the ray before it, and the band's others cross
 * it two raster cells or more beyond, so the count is the band's. */
static int count_to_known(const qc__rindex *ix, qc_vec2 p)
{
    const qc_vec2 *v = ix->region->v;
    unsigned side;
    double xk = known_along(ix, p, &side);
    size_t cx = cell_in(p.x, ix->box.min.x, ix->cell, ix->nx), x0 = cx > 0 ? cx - 1 : 0, x, i;
    size_t x1 = cell_of(xk < ix->box.max.x ? xk : ix->box.max.x, ix->box.min.x, ix->cell, ix->nx);
    size_t row = cell_in(p.y, ix->box.min.y, ix->cell, ix->ny) * ix->nx;
    int inside = (int)side;

    for (x = x0; x <= x1; x++)
        for (i = ix->cell_start[row + x]; i < ix->cell_start[row + x + 1]; i++) {
            uint32_t e = ix->cell_edge[i];
            qc_vec2 a = v[e], b = v[ix->next[e]];
            int m;
            if (!spans(a, b, p.y) || a.y == b.y || (x > x0 && filed_left(ix, a, b, x)))
                continue; /* misses the ray, not banded, or tested in the column before */
            m = qc__ray_edge(p, a, b);
            if (m == 2)
                return 2;
            /* a crossing past the known cell is in its side already */
            if (m == 1 && a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y) < xk)
                inside ^= 1;
        }
    return inside;
}

/* The even-odd count over p's band (p in the box); 2 when p lies on an edge. */
static int count_band(const qc__rindex *ix, qc_vec2 p)
{
    const qc_vec2 *v = ix->region->v;
    size_t b = cell_of(p.y, ix->box.min.y, ix->band, ix->nband), i;
    int inside = 0;

    for (i = ix->band_start[b]; i < ix->band_start[b + 1]; i++) {
        uint32_t e = ix->band_edge[i];
        int m;

        if (!spans(v[e], v[ix->next[e]], p.y))
            continue;
        m = qc__ray_edge(p, v[e], v[ix->next[e]]);
        if (m == 2)
            return 2;
        inside ^= m;
    }
    return inside;
}

int qc__rindex_contains(const qc__rindex *ix, qc_vec2 p)
{
    int inside;

    if (ix->region->nv == 0 || !in_box(ix, p))
        return 0;
    if (ix->info != NULL) {
        unsigned f = info_at(ix, p);
        if ((f & QC__RINDEX_RINGS) >= 2)
            return f >> 7;
        inside = count_to_known(ix, p);
    } else {
        inside = count_band(ix, p);
    }
    if (inside == 2)
        return 1;
    /* horizontal edges are not banded: a point on one is on the boundary */
    return inside || qc__rindex_near(ix, p, 0.0);
}

int qc__rindex_near(const qc__rindex *ix, qc_vec2 p, double r)
{
    const qc_vec2 *v = ix->region->v;
    size_t x0, x1, y0, y1, x, y;
    double r2 = r * r;
    int says;

    if (ix->region->nv == 0 || p.x + r < ix->box.min.x || p.x - r > ix->box.max.x ||
        p.y + r < ix->box.min.y || p.y - r > ix->box.max.y)
        return 0;
    if ((says = near_by_rings(ix, p, r)) >= 0)
        return says;
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
