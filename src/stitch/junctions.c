/*
 * A piece's junctions (merge.c): the points it passes through again. A
 * hash table on the exact coordinates finds each place's first index in
 * one pass (a sort by place was a third of a 10^5-point job); a slot holds
 * (first index + 1) * 2, plus 1 once the place has a second visit. The
 * answer depends on neither the table's order nor the order the points
 * are filed in, only on each place's points being filed in index order.
 * A long piece's table is far larger than the caches and the hash sends
 * every point to a random slot, so there the points are first bucketed by
 * a coarse grid cell (a stable counting sort: a bucket holds a few runs of
 * consecutive points) and each bucket gets its own small table.
 */
#include <math.h>
#include <string.h>

#include "stitch_internal.h"

#define BUCKET_FROM 65536 /* pieces this long are bucketed first */
#define PER_CELL 512      /* points per grid cell, about: runs of a pass stay long */

static uint64_t bits_of(double x)
{
    uint64_t b;

    x += 0.0; /* -0 and +0 are one place */
    memcpy(&b, &x, sizeof b);
    return b;
}

static size_t place_hash(qc_vec2 p, size_t mask)
{
    uint64_t h = bits_of(p.x) * 0x9E3779B97F4A7C15u ^ bits_of(p.y);

    h ^= h >> 29;
    h *= 0xBF58476D1CE4E5B9u;
    h ^= h >> 32;
    return (size_t)h & mask;
}

/* Files point i in table (slots mask + 1): its slot, marked as a second
 * visit unless it repeats the point before. */
static inline size_t file_point(const qc_vec2 *v, size_t i, uint32_t *table, size_t mask)
{
    size_t h = place_hash(v[i], mask);

    while (table[h] != 0) {
        qc_vec2 q = v[table[h] / 2 - 1];

        if (q.x == v[i].x && q.y == v[i].y)
            break;
        h = (h + 1) & mask;
    }
    if (table[h] == 0)
        table[h] = (uint32_t)(i + 1) * 2;
    else if (!(v[i - 1].x == v[i].x && v[i - 1].y == v[i].y))
        table[h] |= 1u; /* a new visit, not a repeat of the point before */
    return h;
}

static size_t joint_of(uint32_t e)
{
    return e & 1 ? (size_t)e / 2 - 1 : QC__NOT_JOINT;
}

/* The whole piece in one table. */
static void mark_direct(const qc_vec2 *v, size_t n, uint32_t *table, size_t slots,
                        size_t *place)
{
    size_t i;

    memset(table, 0, slots * sizeof *table);
    for (i = 0; i < n; i++)
        place[i] = file_point(v, i, table, slots - 1);
    for (i = 0; i < n; i++)
        place[i] = joint_of(table[place[i]]);
}

/* The coarse grid over the finite points' box: about PER_CELL points a
 * cell; anything else (not finite) goes to cell 0. */
typedef struct cells {
    double x0, y0, inv;
    size_t nx, ny;
} cells;

static void cells_make(const qc_vec2 *v, size_t n, cells *g)
{
    double x0 = HUGE_VAL, y0 = HUGE_VAL, x1 = -HUGE_VAL, y1 = -HUGE_VAL, w, h, s;
    double want = (double)(n / PER_CELL + 1);
    size_t i;

    for (i = 0; i < n; i++)
        if (fabs(v[i].x) <= 1e300 && fabs(v[i].y) <= 1e300) {
            x0 = v[i].x < x0 ? v[i].x : x0;
            x1 = v[i].x > x1 ? v[i].x : x1;
            y0 = v[i].y < y0 ? v[i].y : y0;
            y1 = v[i].y > y1 ? v[i].y : y1;
        }
    g->x0 = x0 <= x1 ? x0 : 0;
    g->y0 = y0 <= y1 ? y0 : 0;
    w = x0 <= x1 ? x1 - x0 : 0;
    h = y0 <= y1 ? y1 - y0 : 0;
    s = sqrt(w * h / want);
    if (!(s > 0))
        s = (w > h ? w : h) / want;
    g->inv = s > 0 ? 1.0 / s : 0;
    g->nx = (size_t)fmin(w * g->inv, want) + 1;
    g->ny = (size_t)fmin(h * g->inv, want / (double)g->nx) + 1;
}

static size_t cell_of(const cells *g, qc_vec2 p)
{
    double x = (p.x - g->x0) * g->inv, y = (p.y - g->y0) * g->inv;

    if (!(x >= 0 && y >= 0)) /* NaN too */
        return 0;
    return (y < (double)(g->ny - 1) ? (size_t)y : g->ny - 1) * g->nx +
           (x < (double)(g->nx - 1) ? (size_t)x : g->nx - 1);
}

/* Bucketed: table holds the points by cell (n), the cells' starts
 * (ncell + 1) and, in what is left, each cell's own table. 0 when some
 * cell holds too many points for that room (the caller goes direct). */
static int mark_bucketed(const qc_vec2 *v, size_t n, uint32_t *table, size_t slots,
                         size_t *place)
{
    cells g;
    size_t ncell, i, c, room, most = 0;
    uint32_t *idx = table, *start, *local;

    cells_make(v, n, &g);
    ncell = g.nx * g.ny;
    if (n + ncell + 1 + 16 > slots)
        return 0;
    start = table + n;
    local = start + ncell + 1;
    room = slots - n - ncell - 1;
    memset(start, 0, (ncell + 1) * sizeof *start);
    for (i = 0; i < n; i++) { /* place holds the cells till the scatter */
        place[i] = cell_of(&g, v[i]);
        start[place[i] + 1]++;
    }
    for (c = 0; c < ncell; c++) {
        most = start[c + 1] > most ? start[c + 1] : most;
        start[c + 1] += start[c];
    }
    if (2 * most > room)
        return 0;
    for (i = 0; i < n; i++) /* stable: each cell's points in index order */
        idx[start[place[i]]++] = (uint32_t)i;
    for (c = ncell; c > 0; c--) /* the starts again */
        start[c] = start[c - 1];
    start[0] = 0;
    for (c = 0; c < ncell; c++) {
        size_t lo = start[c], hi = start[c + 1], t = 16, k;

        while (t < 2 * (hi - lo))
            t *= 2;
        if (t > room)
            t = room; /* hi - lo <= room / 2: a power of two fits */
        while (t & (t - 1))
            t &= t - 1;
        memset(local, 0, t * sizeof *local);
        for (k = lo; k < hi; k++)
            place[idx[k]] = file_point(v, idx[k], local, t - 1);
        for (k = lo; k < hi; k++)
            place[idx[k]] = joint_of(local[place[idx[k]]]);
    }
    return 1;
}

void qc__mark_junctions(const qc_vec2 *v, size_t n, uint32_t *table, size_t slots,
                        size_t *place)
{
    if (n < BUCKET_FROM || !mark_bucketed(v, n, table, slots, place))
        mark_direct(v, n, table, slots, place);
}
