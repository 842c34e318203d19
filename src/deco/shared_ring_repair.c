/*
 * Repairs of traced contour rings where a level set is thinner than the
 * distance field's grid: islands that cross the body they were cut from,
 * and crossings undone by rejoining the two segments (shared_sdf_rings.c calls
 * both).
 */
#include <math.h>
#include <string.h>

#include "deco_internal.h"

static size_t ring_begin(const qc__rings *r, size_t k)
{
    return k ? r->end.i[k - 1] : 0;
}

static double ring_area(const qc__rings *r, size_t k, qc_bbox *box)
{
    size_t b = ring_begin(r, k), e = r->end.i[k], i, j = e - 1;
    double a = 0.0;

    box->min = box->max = r->pts.v[b];
    for (i = b; i < e; j = i++) {
        const qc_vec2 *p = r->pts.v;
        a += p[j].x * p[i].y - p[i].x * p[j].y;
        box->min.x = fmin(box->min.x, p[i].x);
        box->min.y = fmin(box->min.y, p[i].y);
        box->max.x = fmax(box->max.x, p[i].x);
        box->max.y = fmax(box->max.y, p[i].y);
    }
    return 0.5 * fabs(a);
}

static int boxes_meet(qc_bbox a, qc_bbox b)
{
    return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y;
}

static int seg_cross(qc_vec2 a, qc_vec2 b, qc_vec2 c, qc_vec2 d)
{
    double o1, o2, o3, o4;

    /* a proper crossing lies in both boxes (the predicates are exact) */
    if (qc__greater(a.x, b.x) < qc__lesser(c.x, d.x) ||
        qc__greater(c.x, d.x) < qc__lesser(a.x, b.x) ||
        qc__greater(a.y, b.y) < qc__lesser(c.y, d.y) ||
        qc__greater(c.y, d.y) < qc__lesser(a.y, b.y))
        return 0;
    o1 = qc_orient2d(a, b, c);
    o2 = qc_orient2d(a, b, d);
    if (!((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)))
        return 0;
    o3 = qc_orient2d(c, d, a);
    o4 = qc_orient2d(c, d, b);
    return (o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0);
}

/* Whether small ring k properly crosses ring q. */
static int rings_cross(const qc__rings *r, size_t k, size_t q, qc_bbox kbox)
{
    const qc_vec2 *p = r->pts.v;
    size_t kb = ring_begin(r, k), ke = r->end.i[k], qb = ring_begin(r, q), qe = r->end.i[q];
    size_t i, j, pi, pj;

    for (j = qb, pj = qe - 1; j < qe; pj = j++) {
        qc_bbox sb;
        sb.min.x = fmin(p[pj].x, p[j].x);
        sb.min.y = fmin(p[pj].y, p[j].y);
        sb.max.x = fmax(p[pj].x, p[j].x);
        sb.max.y = fmax(p[pj].y, p[j].y);
        if (!boxes_meet(sb, kbox))
            continue;
        for (i = kb, pi = ke - 1; i < ke; pi = i++)
            if (seg_cross(p[pi], p[i], p[pj], p[j]))
                return 1;
    }
    return 0;
}

/* Whether ring k crosses itself. */
static int ring_self_cross(const qc__rings *r, size_t k)
{
    const qc_vec2 *p = r->pts.v + ring_begin(r, k);
    size_t n = r->end.i[k] - ring_begin(r, k), i, j;

    for (i = 0; i < n; i++)
        for (j = i + 2; j < n; j++)
            if (!(i == 0 && j == n - 1) &&
                seg_cross(p[i], p[i + 1], p[j], p[(j + 1) % n]))
                return 1;
    return 0;
}

/* Drops the small rings (area under 4 h^2) from ring first on that cross a
 * larger ring of their level: marching squares loses a sharp tip's thin
 * wedge between grid nodes and keeps its end as an island, and once every
 * vertex sits on the exact level the island crosses the body. The wedge
 * beyond is narrower than the grid. Self-crossing small rings (both sides
 * of such a wedge on the same lines) go too. */
void qc__rings_prune_islands(qc__rings *r, size_t first, double h)
{
    size_t k, q, kept = first, w;

    w = ring_begin(r, first);
    for (k = first; k < r->end.n; k++) {
        qc_bbox kbox, qbox;
        double ka = ring_area(r, k, &kbox);
        size_t b = ring_begin(r, k), e = r->end.i[k], i;
        int drop = ka < 4.0 * h * h && ring_self_cross(r, k);

        for (q = first; q < r->end.n && ka < 4.0 * h * h && !drop; q++) {
            double qa;
            if (q == k || r->level.i[q] != r->level.i[k])
                continue;
            qa = ring_area(r, q, &qbox);
            if ((qa > ka || (qa == ka && q < k)) && boxes_meet(kbox, qbox))
                drop = rings_cross(r, k, q, kbox);
        }
        if (drop)
            continue;
        for (i = b; i < e; i++) /* compact in place */
            r->pts.v[w++] = r->pts.v[i];
        r->end.i[kept] = (uint32_t)w;
        r->level.i[kept++] = r->level.i[k];
    }
    r->end.n = r->level.n = kept;
    r->pts.n = w;
}

/* The level's segments a -> succ[a] filed by the cells of about cell mm
 * their boxes meet: key[i] the cell (row by row over the box of p), seg[i]
 * the segment, sorted by cell and then segment. Only the cells a ring
 * passes through hold entries, so a long ring round a big block costs its
 * length, not its box's area. *m receives the entry count. */
static int file_segments(qc_ctx *ctx, const qc_vec2 *p, const uint32_t *succ, size_t n,
                         double cell, uint64_t **key, uint32_t **seg, size_t *m)
{
    qc__seg_grid g; /* only its geometry: the cells of each box */
    qc_bbox box = qc__points_bbox(p, n);
    size_t i, k, x, y, c[4], cap = 0;

    memset(&g, 0, sizeof g);
    g.cell = cell;
    g.x0 = box.min.x;
    g.y0 = box.min.y;
    g.gx = (size_t)((box.max.x - box.min.x) / cell) + 1;
    g.gy = (size_t)((box.max.y - box.min.y) / cell) + 1;
    for (i = 0; i < n; i++) {
        qc__seg_grid_cells(&g, p[i], p[succ[i]], c);
        cap += (c[2] - c[0] + 1) * (c[3] - c[1] + 1);
    }
    *m = cap;
    *key = qc__alloc_array(ctx, cap, sizeof **key);
    *seg = qc__alloc_array(ctx, cap, sizeof **seg);
    if (*key == NULL || *seg == NULL)
        return QC_ENOMEM;
    for (i = 0, k = 0; i < n; i++) {
        qc__seg_grid_cells(&g, p[i], p[succ[i]], c);
        for (y = c[1]; y <= c[3]; y++)
            for (x = c[0]; x <= c[2]; x++) {
                (*key)[k] = (uint64_t)y * g.gx + x;
                (*seg)[k++] = (uint32_t)i;
            }
    }
    return qc__radix_sort(ctx, *key, *seg, cap, 0); /* stable: segments stay in order */
}

/* The level's vertices from b0 on joined by succ (indices relative to
 * b0): finds the pairs of segments (a, succ[a]), (c, succ[c]) that cross
 * properly, filed by cells of about cell mm, and for each pair whose ends
 * no earlier pair touched, exchanges succ[a] and succ[c] (mark[] bit 0:
 * touched in this pass, bit 1: ever). *found counts the crossings seen. */
static int uncross_pass(qc_ctx *ctx, const qc_vec2 *p, uint32_t *succ, size_t n, double cell,
                        unsigned char *mark, size_t *found)
{
    uint64_t *key = NULL;
    uint32_t *seg = NULL;
    size_t m = 0, b, e, k, q, i;
    int rc;

    *found = 0;
    for (i = 0; i < n; i++)
        mark[i] &= 2; /* keep "ever swapped" */
    rc = file_segments(ctx, p, succ, n, cell, &key, &seg, &m);
    for (b = 0; b < m && rc == QC_OK; b = e) { /* every pair in a cell */
        for (e = b + 1; e < m && key[e] == key[b]; e++)
            ;
        for (k = b; k < e; k++)
            for (q = k + 1; q < e; q++) {
                uint32_t a = seg[k], c = seg[q], an = succ[a], cn = succ[c];
                if (c == an || a == cn || a == c || !seg_cross(p[a], p[an], p[c], p[cn]))
                    continue;
                ++*found;
                if ((mark[a] | mark[an] | mark[c] | mark[cn]) & 1)
                    continue;
                mark[a] = mark[an] = mark[c] = mark[cn] = 3;
                succ[a] = cn; /* a -> cn and c -> an: uncrossed, directions kept */
                succ[c] = an;
            }
    }
    qc__free(ctx, key, m * sizeof *key);
    qc__free(ctx, seg, m * sizeof *seg);
    return rc;
}

/* Where a level set is thinner than the grid (a neck near a saddle, a
 * ridge just above the level) marching squares cannot tell its sides
 * apart, and once the vertices sit on the exact level its rings may cross.
 * Each crossing of segments a -> a', c -> c' is undone by joining a -> c'
 * and c -> a' instead, which cuts a self-crossing ring into two or merges
 * two rings into one, keeping every vertex and direction (the neck, being
 * thinner than the grid, is cut or closed). Rings from `first` on. */
int qc__rings_untangle(qc_ctx *ctx, qc__rings *r, size_t first, double h)
{
    size_t b0, n, k, i, pass, found = 1, w;
    uint32_t *succ = NULL, lv;
    unsigned char *mark = NULL;
    qc_vec2 *tmp = NULL;
    int rc = QC_ENOMEM;

    if (first >= r->end.n)
        return QC_OK;
    b0 = ring_begin(r, first);
    n = r->pts.n - b0;
    lv = r->level.i[first];
    succ = qc__alloc_array(ctx, n, sizeof *succ);
    mark = qc__alloc(ctx, n);
    if (succ == NULL || mark == NULL)
        goto out;
    for (k = first; k < r->end.n; k++) {
        size_t b = ring_begin(r, k) - b0, e = r->end.i[k] - b0;
        for (i = b; i < e; i++)
            succ[i] = (uint32_t)(i + 1 < e ? i + 1 : b);
    }
    memset(mark, 0, n);
    for (pass = 0; pass < 32 && found > 0; pass++) {
        rc = uncross_pass(ctx, r->pts.v + b0, succ, n, 2.0 * h, mark, &found);
        if (rc < 0)
            goto out;
    }
    rc = QC_ENOMEM;
    if (pass == 1) { /* nothing crossed */
        rc = QC_OK;
        goto out;
    }
    tmp = qc__alloc_array(ctx, n, sizeof *tmp);
    if (tmp == NULL)
        goto out;
    r->end.n = r->level.n = first;
    for (i = 0, w = 0; i < n; i++) { /* the cycles, in order of their first vertex */
        size_t c = i, w0 = w, q;
        int swapped = 0;
        double area = 0.0;

        if (mark[i] & 4)
            continue;
        do {
            mark[c] |= 4;
            swapped |= mark[c] & 2;
            tmp[w++] = r->pts.v[b0 + c];
            c = succ[c];
        } while (!(mark[c] & 4));
        for (q = w0; q < w; q++) {
            qc_vec2 u = tmp[q], v = tmp[q + 1 < w ? q + 1 : w0];
            area += u.x * v.y - v.x * u.y;
        }
        /* a sliver cut off a neck thinner than the grid goes */
        if (w - w0 < 3 || (swapped && fabs(0.5 * area) < h * h)) {
            w = w0;
            continue;
        }
        if (qc_order_push(ctx, &r->end, (uint32_t)(b0 + w)) < 0 ||
            qc_order_push(ctx, &r->level, lv) < 0)
            goto out;
    }
    memcpy(r->pts.v + b0, tmp, w * sizeof *tmp);
    r->pts.n = b0 + w;
    rc = QC_OK;
out:
    qc__free(ctx, succ, n * sizeof *succ);
    qc__free(ctx, mark, n);
    qc__free(ctx, tmp, n * sizeof *tmp);
    return rc;
}
