/*
 * The farthest fabric: how far any point of the region, its boundary
 * included, lies from the path. A distance transform of the cells the path
 * passes through finds the farthest cell; a grid of the path's segments then
 * answers the exact distance there, along the boundary and at the corners.
 * (The largest empty circle of gap.c is bounded by the boundary too, so it
 * cannot see a bare star point; this measure can.)
 */
#include <math.h>
#include <string.h>

#include "measure_internal.h"

#define SEAM_DEFAULT_MM 6.35 /* 1/4 in: a seam allowance */
#define BOUNDARY_STEP_MM 0.254 /* 0.01 in */
#define FLATTEN_MM 0.05     /* curves to polylines: a fiftieth of a stitch */
#define SHARP_DEG 150.0      /* corners sharper than this count in worst_corner_mm */

/* The path's segments in a bucket grid: segment k ends at point
 * seg[k] & ~POINT_BIT and starts one before, or there too (a point piece). */
#define POINT_BIT 0x80000000u
typedef struct seg_index {
    const qc_vec2 *pts;
    uint32_t *seg;
    size_t nseg;
    double x0, y0, cell, inv; /* inv = 1 / cell: build and query bin alike */
    size_t gx, gy;
    size_t *start;   /* gx * gy + 1, CSR over item */
    uint32_t *item;  /* segment numbers */
    size_t nitem;
} seg_index;

static size_t cell_of(double v, double lo, double cell, size_t count)
{
    double f = floor((v - lo) / cell), m = (double)(count - 1);

    return f > 0.0 ? (size_t)(f < m ? f : m) : 0;
}

/* Bins by multiplying with the inverse cell size: build and query use it
 * alike, and it is monotone, so a segment within reach of a query point is
 * always in a cell the query scans. */
static size_t bin_of(double v, double lo, double inv, size_t count)
{
    double f = (v - lo) * inv, m = (double)(count - 1);

    /* floor by truncation, which agrees for f >= 0 (floor is a call) */
    return f > 0.0 ? (f < m ? (size_t)f : count - 1) : 0;
}

static void seg_ends(const seg_index *s, size_t k, qc_vec2 *a, qc_vec2 *b)
{
    uint32_t e = s->seg[k];

    *b = s->pts[e & ~POINT_BIT];
    *a = (e & POINT_BIT) ? *b : s->pts[e - 1];
}

static void seg_cells(const seg_index *s, size_t k, size_t c[4])
{
    qc_vec2 a, b;

    seg_ends(s, k, &a, &b);
    if (a.x > b.x) { /* ordered by comparisons: fmin and fmax are calls */
        double t = a.x;
        a.x = b.x, b.x = t;
    }
    if (a.y > b.y) {
        double t = a.y;
        a.y = b.y, b.y = t;
    }
    c[0] = bin_of(a.x, s->x0, s->inv, s->gx);
    c[1] = bin_of(a.y, s->y0, s->inv, s->gy);
    c[2] = bin_of(b.x, s->x0, s->inv, s->gx);
    c[3] = bin_of(b.y, s->y0, s->inv, s->gy);
}

static void seg_index_free(qc_ctx *ctx, seg_index *s)
{
    qc__free(ctx, s->seg, s->nseg * sizeof *s->seg);
    qc__free(ctx, s->start, (s->gx * s->gy + 1) * sizeof *s->start);
    qc__free(ctx, s->item, s->nitem * sizeof *s->item);
    memset(s, 0, sizeof *s);
}

static int seg_index_build(qc_ctx *ctx, seg_index *s, const qc_vec2 *pts, size_t n,
                           const uint32_t *ends, size_t nends)
{
    size_t k, b = 0, q, x, y, c[4], ncell, np = ends != NULL ? nends : 1;
    qc_bbox box = qc__points_bbox(pts, n);
    int pass;
    double side;

    memset(s, 0, sizeof *s);
    s->pts = pts;
    for (pass = 0; pass < 2; pass++) { /* count, then fill */
        b = 0;
        s->nseg = 0;
        for (q = 0; q < np; q++) {
            size_t e = ends != NULL ? ends[q] : n, i;
            if (e > n)
                e = n;
            if (e == b + 1) {
                if (pass)
                    s->seg[s->nseg] = (uint32_t)b | POINT_BIT;
                s->nseg++;
            }
            for (i = b + 1; i < e; i++) {
                if (pass)
                    s->seg[s->nseg] = (uint32_t)i;
                s->nseg++;
            }
            b = e > b ? e : b;
        }
        if (s->nseg == 0) { /* no piece given: the first point */
            if (pass)
                s->seg[0] = POINT_BIT;
            s->nseg = 1;
        }
        if (!pass && (s->seg = qc__alloc_array(ctx, s->nseg, sizeof *s->seg)) == NULL) {
            s->nseg = 0;
            return QC_ENOMEM;
        }
    }
    side = fmax(box.max.x - box.min.x, box.max.y - box.min.y);
    s->cell = qc__fit_cell(box, fmax(side / sqrt((double)s->nseg + 1.0), 1e-3),
                           (double)s->nseg + 64.0);
    s->inv = 1.0 / s->cell;
    s->x0 = box.min.x;
    s->y0 = box.min.y;
    s->gx = (size_t)((box.max.x - box.min.x) / s->cell) + 1;
    s->gy = (size_t)((box.max.y - box.min.y) / s->cell) + 1;
    ncell = s->gx * s->gy;
    s->start = qc__alloc_array(ctx, ncell + 1, sizeof *s->start);
    if (s->start == NULL)
        goto oom;
    memset(s->start, 0, (ncell + 1) * sizeof *s->start);
    for (k = 0; k < s->nseg; k++) {
        seg_cells(s, k, c);
        for (y = c[1]; y <= c[3]; y++)
            for (x = c[0]; x <= c[2]; x++)
                s->start[y * s->gx + x + 1]++;
    }
    for (k = 0; k < ncell; k++)
        s->start[k + 1] += s->start[k];
    s->nitem = s->start[ncell];
    s->item = qc__alloc_array(ctx, s->nitem ? s->nitem : 1, sizeof *s->item);
    if (s->item == NULL)
        goto oom;
    if (s->nitem == 0)
        s->nitem = 1;
    for (k = 0; k < s->nseg; k++) {
        seg_cells(s, k, c);
        for (y = c[1]; y <= c[3]; y++)
            for (x = c[0]; x <= c[2]; x++)
                s->item[s->start[y * s->gx + x]++] = (uint32_t)k;
    }
    for (k = ncell; k > 0; k--) /* shift the ends back into starts */
        s->start[k] = s->start[k - 1];
    s->start[0] = 0;
    return QC_OK;
oom:
    seg_index_free(ctx, s);
    return QC_ENOMEM;
}

/* Exact distance from q to the nearest segment, given that some segment lies
 * within bound (HUGE_VAL: unknown). */
static double seg_index_dist(const seg_index *s, qc_vec2 q, double bound)
{
    size_t x, y, x0, x1, y0, y1, k;
    double best = HUGE_VAL;

    if (!(bound < HUGE_VAL)) {
        x0 = y0 = 0;
        x1 = s->gx - 1;
        y1 = s->gy - 1;
    } else {
        x0 = bin_of(q.x - bound, s->x0, s->inv, s->gx);
        x1 = bin_of(q.x + bound, s->x0, s->inv, s->gx);
        y0 = bin_of(q.y - bound, s->y0, s->inv, s->gy);
        y1 = bin_of(q.y + bound, s->y0, s->inv, s->gy);
    }
    for (y = y0; y <= y1; y++)
        for (x = x0; x <= x1; x++) {
            size_t c = y * s->gx + x;
            for (k = s->start[c]; k < s->start[c + 1]; k++) {
                qc_vec2 a, e;
                double d2;
                seg_ends(s, s->item[k], &a, &e);
                d2 = qc__seg_dist2(q, a, e);
                best = d2 < best ? d2 : best;
            }
        }
    return sqrt(best);
}

typedef struct fabric_run {
    qc__gap_grid g;
    seg_index s;
} fabric_run;

/* An upper bound on q's distance to the path from the raster (HUGE_VAL when
 * no seeded cell is known; the raster holds exact squared distances where a
 * cell could be the farthest, upper bounds elsewhere): cell centre to seed centre, plus the half cells
 * either side and the clamping of seeds just outside the box. */
static double bound_at(const fabric_run *r, qc_vec2 q)
{
    const qc__gap_grid *g = &r->g;
    size_t i = cell_of(q.x, g->x0, g->h, g->nx), j = cell_of(q.y, g->y0, g->h, g->ny);
    double f = (double)g->f[j * g->nx + i];

    if (f >= 0.5 * QC__GAP_FAR)
        return HUGE_VAL;
    return (sqrt(f) + 3.0) * g->h;
}

static double exact_at(const fabric_run *r, qc_vec2 q)
{
    return seg_index_dist(&r->s, q, bound_at(r, q));
}

/* Climbs from the winning cell centre: exact distances on a 7 x 7 lattice
 * one cell either side, then a third of that round the best, so the figure
 * hardly depends on the raster (check and --stats use different ones). */
static void refine(const fabric_run *r, const qc_region *region, const unsigned char *mask,
                   qc_fabric *out)
{
    double span = r->g.h;
    int round, i, j;

    for (round = 0; round < 2; round++, span /= 3.0) {
        qc_vec2 c = out->farthest_at;
        for (j = -3; j <= 3; j++)
            for (i = -3; i <= 3; i++) {
                qc_vec2 q = QC__V2(c.x + span * i / 3.0, c.y + span * j / 3.0);
                size_t ci = cell_of(q.x, r->g.x0, r->g.h, r->g.nx);
                size_t cj = cell_of(q.y, r->g.y0, r->g.h, r->g.ny);
                double d;
                if (!mask[cj * r->g.nx + ci] || !qc_region_contains(region, q))
                    continue;
                d = exact_at(r, q);
                if (d > out->farthest_mm) {
                    out->farthest_mm = d;
                    out->farthest_at = q;
                }
            }
    }
}

double qc_region_corner_angle(const qc_region *region, size_t i)
{
    size_t k, rs = 0;

    for (k = 0; k < region->nrings; k++) {
        size_t end = region->ring_end[k];
        if (i < end) {
            qc_vec2 p = region->v[i == rs ? end - 1 : i - 1], v = region->v[i];
            qc_vec2 nx = region->v[i + 1 == end ? rs : i + 1];
            double ax = v.x - p.x, ay = v.y - p.y, bx = nx.x - v.x, by = nx.y - v.y;
            double turn = qc_atan2(ax * by - ay * bx, ax * bx + ay * by);
            return 180.0 - turn * (180.0 / QC_PI);
        }
        rs = end;
    }
    return 180.0;
}

static int check_args(qc_ctx *ctx, const qc_region *region, const qc_vec2 *pts, size_t n,
                      double resolution, const qc_fabric *out)
{
    size_t i;

    if (region == NULL || region->nrings == 0 || out == NULL)
        return qc__fail(ctx, QC_EINVAL, "fabric measure: no region or no output");
    if (pts == NULL || n == 0)
        return qc__fail(ctx, QC_EINVAL, "fabric measure: the path has no point");
    if (!(resolution > 0.0) || !(resolution < HUGE_VAL))
        return qc__fail(ctx, QC_EINVAL, "fabric measure: resolution %g mm must be > 0",
                        resolution);
    if (n >= POINT_BIT)
        return qc__fail(ctx, QC_ELIMIT, "fabric measure: %lu points exceed 2^31",
                        (unsigned long)n);
    for (i = 0; i < n; i++)
        if (!isfinite(pts[i].x) || !isfinite(pts[i].y))
            return qc__fail(ctx, QC_ERANGE, "fabric measure: point %lu is not finite",
                            (unsigned long)i);
    for (i = 0; i < region->nv; i++)
        if (!isfinite(region->v[i].x) || !isfinite(region->v[i].y))
            return qc__fail(ctx, QC_ERANGE, "fabric measure: region vertex %lu is not finite",
                            (unsigned long)i);
    return QC_OK;
}

/* Upper bounds carried along the boundary walk: the distance to the path
 * grows by at most the step taken (it is 1-Lipschitz), so a sample whose
 * bound is already below both the seam allowance and the farthest figure
 * cannot change either and needs no exact query. The slack covers the
 * rounding of the sums, so the figures are those of an exact query at
 * every sample. */
#define CHAIN_SLACK 1e-9

typedef struct chain {
    qc_vec2 at;
    double bound; /* HUGE_VAL: none yet */
} chain;

/* The exact distance at c, or a bound no greater than needed when that
 * decides nothing (*exact 0); the chain moves to c. */
static double chained_at(const fabric_run *r, chain *ch, qc_vec2 c, double below, int *exact)
{
    double ub = bound_at(r, c), d;

    if (ch->bound < HUGE_VAL)
        ub = fmin(ub, ch->bound + qc_hypot(c.x - ch->at.x, c.y - ch->at.y) + CHAIN_SLACK);
    ch->at = c;
    if (ub + CHAIN_SLACK < below) {
        ch->bound = ub;
        *exact = 0;
        return ub;
    }
    d = seg_index_dist(&r->s, c, ub < HUGE_VAL ? ub + CHAIN_SLACK : ub);
    ch->bound = d;
    *exact = 1;
    return d;
}

/* The boundary walk: seam share, the farthest boundary point, the corners. */
static void walk_boundary(const fabric_run *r, const qc_region *region, double seam_mm,
                          double *corner_mm, qc_fabric *out)
{
    double step = fmin(r->g.h, BOUNDARY_STEP_MM), total = 0.0, bare = 0.0;
    size_t k, rs = 0, i;
    int exact;

    for (k = 0; k < region->nrings; k++) {
        size_t end = region->ring_end[k], p = end - 1;
        chain ch;

        ch.bound = HUGE_VAL;
        for (i = rs; i < end; p = i++) {
            qc_vec2 a = region->v[p], b = region->v[i];
            double len = qc_hypot(b.x - a.x, b.y - a.y), dv, m = ceil(len / step), t;
            size_t q, mm = m < 1.0 ? 1 : (m < 1e7 ? (size_t)m : 10000000u);
            chain at_b = ch;
            int sharp = qc_region_corner_angle(region, i) < SHARP_DEG;

            /* the corner: exact where it is reported, else only when it may
             * raise the farthest or the worst corner */
            dv = chained_at(r, &at_b, b,
                            corner_mm != NULL ? -HUGE_VAL
                            : sharp ? fmin(out->farthest_mm, out->worst_corner_mm)
                                    : out->farthest_mm,
                            &exact);
            if (corner_mm != NULL)
                corner_mm[i] = dv;
            if (exact && dv > out->farthest_mm) {
                out->farthest_mm = dv;
                out->farthest_at = b;
            }
            if (exact && sharp && dv > out->worst_corner_mm)
                out->worst_corner_mm = dv;
            for (q = 0; q < mm; q++) {
                qc_vec2 c;
                double dc;
                t = ((double)q + 0.5) / (double)mm;
                c.x = a.x + (b.x - a.x) * t;
                c.y = a.y + (b.y - a.y) * t;
                dc = chained_at(r, &ch, c, fmin(seam_mm, out->farthest_mm), &exact);
                if (!exact)
                    continue;
                if (dc > seam_mm)
                    bare += len / (double)mm;
                if (dc > out->farthest_mm) {
                    out->farthest_mm = dc;
                    out->farthest_at = c;
                }
            }
            total += len;
        }
        rs = end;
    }
    out->seam_bare = total > 0.0 ? bare / total : 0.0;
}

int qc_fabric_measure(qc_ctx *ctx, const qc_region *region, const qc_vec2 *pts, size_t n,
                      const uint32_t *ends, size_t nends, double resolution, double seam_mm,
                      double *corner_mm, qc_fabric *out)
{
    fabric_run r;
    unsigned char *mask = NULL;
    size_t k, cells, best_at = 0, b = 0, q, np = ends != NULL ? nends : 1;
    double best = -1.0;
    int rc;

    QC__TRY(check_args(ctx, region, pts, n, resolution, out));
    memset(out, 0, sizeof *out);
    if (!(seam_mm > 0.0))
        seam_mm = SEAM_DEFAULT_MM;
    memset(&r, 0, sizeof r);
    rc = qc__gap_grid_inside(ctx, region, resolution, &r.g, &mask);
    cells = r.g.nx * r.g.ny;
    if (rc < 0)
        goto out;
    for (q = 0; q < np; q++) {
        size_t e = ends != NULL ? ends[q] : n, i;
        if (e > n)
            e = n;
        if (e == b + 1)
            qc__gap_seed_segment(&r.g, pts[b], pts[b]);
        for (i = b + 1; i < e; i++)
            qc__gap_seed_segment(&r.g, pts[i - 1], pts[i]);
        b = e > b ? e : b;
    }
    /* exact only where a cell may win; elsewhere f keeps an upper bound,
     * all bound_at needs */
    rc = qc__gap_transform_above(ctx, &r.g, mask, -1.0, 1, &k);
    if (rc < 0)
        goto out;
    if (k != SIZE_MAX) {
        best_at = k;
        best = (double)r.g.f[k];
    }
    rc = seg_index_build(ctx, &r.s, pts, n, ends, nends);
    if (rc < 0)
        goto out;
    if (best >= 0.0) {
        qc_vec2 c;
        c.x = r.g.x0 + ((double)(best_at % r.g.nx) + 0.5) * r.g.h;
        c.y = r.g.y0 + ((double)(best_at / r.g.nx) + 0.5) * r.g.h;
        out->farthest_mm = exact_at(&r, c);
        out->farthest_at = c;
        refine(&r, region, mask, out);
    }
    walk_boundary(&r, region, seam_mm, corner_mm, out);
out:
    seg_index_free(ctx, &r.s);
    qc__free(ctx, r.g.f, cells * sizeof *r.g.f);
    qc__free(ctx, mask, cells);
    return rc;
}

int qc_path_fabric(qc_ctx *ctx, const qc_region *region, const qc_path *path,
                   double resolution, double seam_mm, double *corner_mm, qc_fabric *out)
{
    qc_points flat = {0};
    qc_order ends = {0};
    int rc;

    if (path == NULL)
        return qc__fail(ctx, QC_EINVAL, "fabric measure: path is NULL");
    rc = qc_curve_flatten(ctx, path, FLATTEN_MM, &flat, &ends);
    if (rc == QC_OK)
        rc = qc_fabric_measure(ctx, region, flat.v, flat.n, ends.i, ends.n, resolution,
                               seam_mm, corner_mm, out);
    qc_points_free(ctx, &flat);
    qc_order_free(ctx, &ends);
    return rc;
}
