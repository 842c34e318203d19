/*
 * The largest gap: the biggest circle inside the region that the path and
 * the boundary leave empty, by an exact distance transform of a raster of
 * seeds, then the winning cell's clearance measured exactly.
 */
#include <math.h>
#include <string.h>

#include "measure_internal.h"

void qc__gap_seed_segment(qc__gap_grid *g, qc_vec2 a, qc_vec2 b)
{
    double len = qc_hypot(b.x - a.x, b.y - a.y);
    double steps = ceil(len / (0.5 * g->h)), xn = (double)g->nx, yn = (double)g->ny;
    size_t m, k;

    if (!(steps < 1e9))
        steps = 1e9;
    m = steps < 1.0 ? 1 : (size_t)steps;
    for (k = 0; k <= m; k++) {
        double t = (double)k / (double)m;
        double x = (a.x + (b.x - a.x) * t - g->x0) / g->h;
        double y = (a.y + (b.y - a.y) * t - g->y0) / g->h;

        /* the box's far sides (x == nx) belong to the last cells */
        if (x >= -1.0 && y >= -1.0 && x < xn + 1.0 && y < yn + 1.0) {
            /* clamped by comparisons: fmin and fmax are calls, per sample */
            x = x > 0.0 ? (x < xn - 1.0 ? x : xn - 1.0) : 0.0;
            y = y > 0.0 ? (y < yn - 1.0 ? y : yn - 1.0) : 0.0;
            g->f[(size_t)y * g->nx + (size_t)x] = 0.0f;
        }
    }
}

void qc__gap_seed_region(qc__gap_grid *g, const qc_region *region)
{
    size_t k, i, rs = 0;

    for (k = 0; k < region->nrings; k++) {
        size_t end = region->ring_end[k], p = end - 1;

        for (i = rs; i < end; p = i++)
            qc__gap_seed_segment(g, region->v[p], region->v[i]);
        rs = end;
    }
}

qc_vec2 qc__gap_grid_centre(const qc__gap_grid *g, size_t at)
{
    qc_vec2 c;

    c.x = g->x0 + ((double)(at % g->nx) + 0.5) * g->h;
    c.y = g->y0 + ((double)(at / g->nx) + 0.5) * g->h;
    return c;
}

void qc__gap_grid_size(qc__gap_grid *g, qc_bbox box, double resolution)
{
    g->h = resolution;
    for (;;) {
        double fx = ceil((box.max.x - box.min.x) / g->h), fy = ceil((box.max.y - box.min.y) / g->h);
        fx = fx < 1.0 ? 1.0 : fx;
        fy = fy < 1.0 ? 1.0 : fy;
        if (fx * fy <= (double)QC__GAP_MAX_CELLS) {
            g->nx = (size_t)fx;
            g->ny = (size_t)fy;
            break;
        }
        g->h *= 1.25;
    }
    g->x0 = box.min.x;
    g->y0 = box.min.y;
    g->f = NULL;
}

/* The columns of a seeded raster (cells 0 or FAR): each cell's squared
 * distance to the nearest seed in its column, capped at FAR, which is what
 * the parabola envelope gives for such a column. Two sweeps down and up the
 * rows in memory order, with no division and no branch per cell: run[i]
 * counts cells since the last seed in column i, starting from NONE (no seed
 * yet: a count of NONE or more squares past FAR). Counts stay below 2^24,
 * so the floats hold them exactly. */
#define NONE ((long)1 << 23) /* > QC__GAP_MAX_CELLS, + ny < 2^24 */
static void columns_by_sweeps(qc__gap_grid *g, long *run)
{
    const double far = (double)(float)QC__GAP_FAR;
    size_t i, j, nx = g->nx, ny = g->ny;

    for (i = 0; i < nx; i++)
        run[i] = NONE;
    for (j = 0; j < ny; j++) { /* down: f holds the distance from above */
        float *row = g->f + j * nx;
        for (i = 0; i < nx; i++) {
            run[i] = row[i] == 0.0f ? 0 : run[i] + 1;
            row[i] = (float)run[i];
        }
    }
    for (i = 0; i < nx; i++)
        run[i] = NONE;
    for (j = ny; j-- > 0;) { /* up: the nearer of the two, squared */
        float *row = g->f + j * nx;
        for (i = 0; i < nx; i++) {
            long down = (long)row[i], up = down == 0 ? 0 : run[i] + 1;
            long best = up < down ? up : down;
            double sq = (double)best * (double)best;
            run[i] = up;
            row[i] = (float)(sq > far ? far : sq);
        }
    }
}

/* A row's exact transform by looking out from each cell only as far as the
 * best found so far reaches: d[q] <= f[q], and a cell k away adds k^2, so
 * with near seeds (the usual raster: a path every few cells) it beats the
 * parabola envelope's divisions. Integers in doubles: exact, so it gives
 * the envelope's very values (an unseeded column's QC__GAP_FAR included).
 * 0 when the row needs more than budget looks (far seeds): the caller runs
 * the envelope instead. */
static int row_by_looking_out(const double *f, size_t n, double *d, size_t budget)
{
    size_t q, k, looks = 0;

    for (q = 0; q < n; q++) {
        double best = f[q];
        size_t reach = q > n - 1 - q ? q : n - 1 - q; /* no cell lies farther */
        for (k = 1; k <= reach && (double)k * (double)k < best; k++) {
            double kk = (double)k * (double)k;
            if (q >= k && kk + f[q - k] < best)
                best = kk + f[q - k];
            if (q + k < n && kk + f[q + k] < best)
                best = kk + f[q + k];
        }
        looks += k;
        if (looks > budget)
            return 0;
        d[q] = best;
    }
    return 1;
}

/* Scratch of the row passes: the envelope's, and a row of doubles. */
typedef struct row_scratch {
    double *col, *out, *z;
    int *v;
    long *run;
    size_t m;
} row_scratch;

static void scratch_free(qc_ctx *ctx, row_scratch *r, size_t nx)
{
    qc__free(ctx, r->col, (3 * r->m + 1) * sizeof *r->col);
    qc__free(ctx, r->v, r->m * sizeof *r->v);
    qc__free(ctx, r->run, nx * sizeof *r->run);
}

static int scratch_alloc(qc_ctx *ctx, row_scratch *r, const qc__gap_grid *g)
{
    r->m = g->nx > g->ny ? g->nx : g->ny;
    r->col = qc__alloc_array(ctx, 3 * r->m + 1, sizeof *r->col);
    r->v = qc__alloc_array(ctx, r->m, sizeof *r->v);
    r->run = qc__alloc_array(ctx, g->nx, sizeof *r->run);
    if (r->col == NULL || r->v == NULL || r->run == NULL) {
        scratch_free(ctx, r, g->nx);
        return QC_ENOMEM;
    }
    r->out = r->col + r->m;
    r->z = r->out + r->m;
    return QC_OK;
}

/* Row j's exact transform into r->out, from its column values in r->col.
 * Both ways give the same values; once looking out has run over its budget
 * (seeds far apart, as in a region seeded only at its boundary), the rows
 * after go straight to the envelope, looking out again every
 * RETRY_EVERY-th row. Returns whether looking out failed. */
#define RETRY_EVERY 16
static int row_exact(row_scratch *r, size_t nx, size_t j, int failed)
{
    if (failed && j % RETRY_EVERY != 0) {
        qc__edt_1d(r->col, nx, r->out, r->v, r->z);
        return 1;
    }
    if (row_by_looking_out(r->col, nx, r->out, 8 * nx + 64))
        return 0;
    qc__edt_1d(r->col, nx, r->out, r->v, r->z);
    return 1;
}

/* qc__edt_1d of a row of column values in place, the floats read and
 * written as they go (no copies to and from doubles): the same arithmetic,
 * f[p] taken back from f[p] + p^2, exact as the values are integers (at
 * most QC__GAP_FAR, p below 2^22: all far below 2^53). */
static void row_envelope(float *row, size_t n, row_scratch *r)
{
    double *hv = r->out, *z = r->z; /* hv[k]: f[v[k]] + v[k]^2 */
    int *v = r->v, k = 0, q, nn = (int)n;

    v[0] = 0;
    hv[0] = (double)row[0] + 0.0;
    z[0] = -HUGE_VAL;
    z[1] = HUGE_VAL;
    for (q = 1; q < nn; q++) {
        double hq = (double)row[q] + (double)q * q, s;

        s = (hq - hv[k]) / (2.0 * (q - v[k]));
        while (s <= z[k]) { /* z[0] = -inf stops this at k == 0 */
            k--;
            s = (hq - hv[k]) / (2.0 * (q - v[k]));
        }
        k++;
        v[k] = q;
        hv[k] = hq;
        z[k] = s;
        z[k + 1] = HUGE_VAL;
    }
    /* parabola k serves the cells q <= z[k + 1] past the last one's: run by
     * run, its own f[p] once (what qc__edt_1d's per-cell scan picks) */
    for (k = 0, q = 0; q < nn; k++) {
        double zk = z[k + 1], fp = hv[k] - (double)v[k] * v[k], dq;
        int last = zk >= (double)(nn - 1) ? nn - 1 : (zk < (double)q ? q - 1 : (int)zk);

        for (dq = (double)(q - v[k]); q <= last; q++, dq += 1.0)
            row[q] = (float)(dq * dq + fp);
    }
}

/* qc__gap_transform; far (seeds only on the region's boundary): every
 * row by the envelope, looking out would only run over its budget, and
 * with rows not NULL only the rows it flags. */
static int transform(qc_ctx *ctx, qc__gap_grid *g, int far, const unsigned char *rows)
{
    row_scratch r;
    size_t i, j;
    int failed = far;

    QC__TRY(scratch_alloc(ctx, &r, g));
    columns_by_sweeps(g, r.run);
    for (j = 0; j < g->ny; j++) {
        float *row = g->f + j * g->nx;
        if (rows != NULL && !rows[j])
            continue;
        if (far) {
            row_envelope(row, g->nx, &r);
            continue;
        }
        for (i = 0; i < g->nx; i++)
            r.col[i] = (double)row[i];
        failed = row_exact(&r, g->nx, j, failed);
        for (i = 0; i < g->nx; i++)
            row[i] = (float)r.out[i];
    }
    scratch_free(ctx, &r, g->nx);
    return QC_OK;
}

int qc__gap_transform(qc_ctx *ctx, qc__gap_grid *g)
{
    return transform(ctx, g, 0, NULL);
}

int qc__gap_transform_far(qc_ctx *ctx, qc__gap_grid *g, const unsigned char *rows)
{
    return transform(ctx, g, 1, rows);
}

/* Cell q's exact value from its row's column values, looking out no
 * farther than its best, or as soon as that falls to stop or below (then
 * an upper bound, <= stop); *looks counts the cells looked at. */
static double cell_exact(const double *f, size_t n, size_t q, double stop, size_t *looks)
{
    double best = f[q];
    size_t k, reach = q > n - 1 - q ? q : n - 1 - q;

    for (k = 1; k <= reach && (double)k * (double)k < best && best > stop; k++) {
        double kk = (double)k * (double)k;
        if (q >= k && kk + f[q - k] < best)
            best = kk + f[q - k];
        if (q + k < n && kk + f[q + k] < best)
            best = kk + f[q + k];
    }
    *looks += k;
    return best;
}

int qc__gap_transform_above(qc_ctx *ctx, qc__gap_grid *g, const unsigned char *mask,
                            double floor, int raise, size_t *best_at)
{
    row_scratch r;
    size_t i, j, nx = g->nx, budget = 8 * nx + 64;

    QC__TRY(scratch_alloc(ctx, &r, g));
    columns_by_sweeps(g, r.run); /* f: squared column distances, upper bounds */
    *best_at = SIZE_MAX;
    for (j = 0; j < g->ny; j++) {
        float *row = g->f + j * nx;
        const unsigned char *in = mask + j * nx;
        double floor0 = floor;
        size_t at0 = *best_at, looks = 0;

        for (i = 0; i < nx; i++)
            r.out[i] = r.col[i] = (double)row[i];
        /* cell by cell in index order, exact only where the upper bound
         * passes the floor, so the first cell of the greatest value wins
         * as a scan of the whole transform would pick it */
        for (i = 0; i < nx && looks <= budget; i++)
            if (in[i] && r.col[i] > floor) {
                /* a cell that falls to the floor is out: its bound will do */
                double d = cell_exact(r.col, nx, i, floor, &looks);
                r.out[i] = d;
                if (raise && d > floor) {
                    floor = d;
                    *best_at = j * nx + i;
                }
            }
        if (looks > budget) { /* far seeds: the whole row, then its scan */
            floor = floor0;
            *best_at = at0;
            (void)row_exact(&r, nx, 0, 0);
            for (i = 0; i < nx; i++)
                if (raise && in[i] && r.out[i] > floor) {
                    floor = r.out[i];
                    *best_at = j * nx + i;
                }
        }
        for (i = 0; i < nx; i++)
            row[i] = (float)r.out[i];
    }
    scratch_free(ctx, &r, nx);
    return QC_OK;
}

/* Segments of the pieces: piece k is pts[ends[k-1] .. ends[k]) (ends NULL: one piece). */
typedef struct pieces {
    const qc_vec2 *pts;
    size_t n;
    const uint32_t *ends;
    size_t nends;
} pieces;

static size_t piece_end(const pieces *pc, size_t k)
{
    return pc->ends != NULL ? pc->ends[k] : pc->n;
}

/* Exact clearance of c: distance to the nearest path segment or boundary edge. */
static double clearance(const qc_region *region, const pieces *pc, qc_vec2 c)
{
    double best = qc_region_boundary_distance(region, c);
    double b2 = best * best;
    size_t k, b = 0, i;

    for (k = 0; k < (pc->ends != NULL ? pc->nends : 1); k++) {
        size_t e = piece_end(pc, k);
        if (e == b + 1)
            b2 = fmin(b2, qc__seg_dist2(c, pc->pts[b], pc->pts[b]));
        for (i = b + 1; i < e; i++)
            b2 = fmin(b2, qc__seg_dist2(c, pc->pts[i - 1], pc->pts[i]));
        b = e;
    }
    return sqrt(b2);
}

int qc__gap_grid_inside(qc_ctx *ctx, const qc_region *region, double resolution,
                        qc__gap_grid *g, unsigned char **mask)
{
    size_t cells, k;
    int rc = QC_ENOMEM;

    qc__gap_grid_size(g, qc_region_bbox(region), resolution);
    cells = g->nx * g->ny;
    g->f = qc__alloc_array(ctx, cells, sizeof *g->f);
    *mask = qc__alloc(ctx, cells);
    if (g->f != NULL && *mask != NULL)
        rc = qc__raster_inside(ctx, region, g->x0 + 0.5 * g->h, g->y0 + 0.5 * g->h, g->h,
                               g->nx, g->ny, *mask);
    if (rc < 0) {
        qc__free(ctx, g->f, cells * sizeof *g->f);
        qc__free(ctx, *mask, cells);
        g->f = NULL;
        *mask = NULL;
        return rc;
    }
    for (k = 0; k < cells; k++)
        g->f[k] = (float)QC__GAP_FAR;
    return QC_OK;
}

static double gap_run(qc_ctx *ctx, const qc_region *region, const pieces *pc,
                      double resolution, qc_vec2 *centre_out)
{
    const qc_vec2 *pts = pc->pts;
    size_t n = pc->n;
    qc__gap_grid g;
    unsigned char *mask = NULL;
    size_t i, k, best_at = 0;
    double best = -1.0, r;
    int rc;

    if (region == NULL || region->nrings == 0)
        return qc__fail(ctx, QC_EINVAL, "largest gap: the region has no ring");
    if (pts == NULL && n > 0)
        return qc__fail(ctx, QC_EINVAL, "largest gap: %lu points but pts is NULL",
                        (unsigned long)n);
    if (!(resolution > 0.0) || !(resolution < HUGE_VAL))
        return qc__fail(ctx, QC_EINVAL, "largest gap: resolution %g mm must be > 0",
                        resolution);
    for (i = 0; i < n; i++)
        if (!isfinite(pts[i].x) || !isfinite(pts[i].y))
            return qc__fail(ctx, QC_ERANGE, "largest gap: point %lu is not finite",
                            (unsigned long)i);
    for (i = 0; i < region->nv; i++)
        if (!isfinite(region->v[i].x) || !isfinite(region->v[i].y))
            return qc__fail(ctx, QC_ERANGE, "largest gap: region vertex %lu is not finite",
                            (unsigned long)i);
    rc = qc__gap_grid_inside(ctx, region, resolution, &g, &mask);
    if (rc < 0)
        goto out;
    {
        size_t b = 0, q;
        for (q = 0; q < (pc->ends != NULL ? pc->nends : 1); q++) {
            size_t e = piece_end(pc, q);
            if (e == b + 1)
                qc__gap_seed_segment(&g, pts[b], pts[b]);
            for (i = b + 1; i < e; i++)
                qc__gap_seed_segment(&g, pts[i - 1], pts[i]);
            b = e;
        }
    }
    qc__gap_seed_region(&g, region);
    rc = qc__gap_transform_above(ctx, &g, mask, -1.0, 1, &k);
    if (rc < 0)
        goto out;
    if (k != SIZE_MAX) {
        best_at = k;
        best = (double)g.f[k];
    }
out:
    if (rc < 0) {
        qc__free(ctx, g.f, g.nx * g.ny * sizeof *g.f);
        qc__free(ctx, mask, g.nx * g.ny);
        return rc;
    }
    {
        qc_vec2 c = qc__gap_grid_centre(&g, best_at);
        r = best < 0.0 ? 0.0 : clearance(region, pc, c);
        if (best < 0.0) /* no cell centre inside: a sliver far below the resolution */
            c = region->v[0];
        if (centre_out != NULL)
            *centre_out = c;
    }
    qc__free(ctx, g.f, g.nx * g.ny * sizeof *g.f);
    qc__free(ctx, mask, g.nx * g.ny);
    return r;
}

double qc_largest_gap(qc_ctx *ctx, const qc_region *region, const qc_vec2 *pts, size_t n,
                      double resolution, qc_vec2 *centre_out)
{
    pieces pc;

    pc.pts = pts;
    pc.n = n;
    pc.ends = NULL;
    pc.nends = 0;
    return gap_run(ctx, region, &pc, resolution, centre_out);
}

double qc_path_largest_gap(qc_ctx *ctx, const qc_region *region, const qc_path *path,
                           double resolution, qc_vec2 *centre_out)
{
    qc_points flat = {0};
    qc_order ends = {0};
    pieces pc;
    double r;
    int rc;

    if (path == NULL)
        return qc__fail(ctx, QC_EINVAL, "largest gap: path is NULL");
    rc = qc_curve_flatten(ctx, path, 0.01, &flat, &ends);
    if (rc < 0) {
        r = rc;
    } else {
        pc.pts = flat.v;
        pc.n = flat.n;
        pc.ends = ends.i;
        pc.nends = ends.n;
        r = gap_run(ctx, region, &pc, resolution, centre_out);
    }
    qc_points_free(ctx, &flat);
    qc_order_free(ctx, &ends);
    return r;
}
