/*
 * Merging a flattened piece's short steps without bending it. A plain merge
 * (drop every point closer than the minimum to the last kept one) drops
 * corners: a link from a pebble's end to a seam 0.4 mm away vanishes, and
 * the stitch that replaces it cuts diagonally across the pebble hugging the
 * seam. Here a short step is merged into a neighbour only where the new
 * chord stays within `keep` of the points it replaces: the later point is
 * dropped if it can be (as a plain merge does), else the earlier one moves
 * onto it. Where neither can, the path turns there and the short stitch
 * stays, unless it is shorter than `floor_len` (then whichever merge strays
 * less). A point the piece passes through again elsewhere (a retraced
 * corner, a pebble's link to the seam sewn out and back) is a junction: it
 * is kept in place where it can be, or the two passes that met there would
 * cross; of two junctions too close to sew between, the one merged away
 * the first time is merged away at every later pass too.
 */
#include <math.h>
#include <string.h>

#include "stitch_internal.h"

#define MAX_MERGE_RUN 64 /* points merged into one stitch at most (bounds the work) */
/* The junction table is cut by a grid of cells over the piece's box, each
 * cell's places hashed within its own run of slots (cell_slots: one and a
 * half per point of the cell). A table hashed over all of it misses the
 * cache at every probe: at 12 million points (a 10 m wanderer) that was 80%
 * of the merge; places near in space are near in the table, and the path
 * walks through space. */
#define POINTS_PER_CELL 4

typedef struct grid {
    double x0, y0, inv; /* cells of side 1 / inv from (x0, y0) */
    uint32_t gx, gy;
} grid;

int qc__merge_init(qc_ctx *ctx, qc__merge *mg, size_t longest)
{
    memset(mg, 0, sizeof *mg);
    if (longest == 0)
        return QC_OK;
    if (longest > UINT32_MAX / 2 - 1) /* a slot holds (index + 1) * 2 + 1 */
        return qc__fail(ctx, QC_ELIMIT, "a piece of %lu points is too long to merge",
                        (unsigned long)longest);
    mg->cells = longest / POINTS_PER_CELL + 1;
    mg->slots = longest + longest / 2 + mg->cells; /* cell_slots() over every cell */
    mg->table = (uint32_t *)qc__alloc_array(ctx, mg->slots, sizeof *mg->table);
    mg->start = (uint32_t *)qc__alloc_array(ctx, mg->cells + 1, sizeof *mg->start);
    mg->place = (uint32_t *)qc__alloc_array(ctx, longest, sizeof *mg->place);
    mg->gone = (unsigned char *)qc__alloc(ctx, longest / 8 + 1);
    mg->cap = longest;
    if (mg->table == NULL || mg->start == NULL || mg->place == NULL ||
        mg->gone == NULL) {
        qc__merge_free(ctx, mg);
        return qc__fail(ctx, QC_ENOMEM, "out of memory: merging a piece of %lu points",
                        (unsigned long)longest);
    }
    return QC_OK;
}

void qc__merge_free(qc_ctx *ctx, qc__merge *mg)
{
    qc__free(ctx, mg->table, mg->slots * sizeof *mg->table);
    qc__free(ctx, mg->start, (mg->cells + 1) * sizeof *mg->start);
    qc__free(ctx, mg->place, mg->cap * sizeof *mg->place);
    qc__free(ctx, mg->gone, mg->cap / 8 + 1);
    memset(mg, 0, sizeof *mg);
}

/* Slots of a cell of cnt points: one and a half per point (not two: the
 * table is the largest scratch beside the points at the peak of a large
 * plan), and at least one more than it has places, so a probe always ends. */
static uint32_t cell_slots(uint32_t cnt)
{
    return cnt + cnt / 2 + 1;
}

static int is_gone(const unsigned char *gone, uint32_t place)
{
    return gone[place / 8] >> (place % 8) & 1;
}

static void set_gone(unsigned char *gone, uint32_t place)
{
    gone[place / 8] = (unsigned char)(gone[place / 8] | 1u << (place % 8));
}

static uint64_t bits_of(double x)
{
    uint64_t b;

    x += 0.0; /* -0 and +0 are one place */
    memcpy(&b, &x, sizeof b);
    return b;
}

static uint32_t place_hash(qc_vec2 p)
{
    uint64_t h = bits_of(p.x) * 0x9E3779B97F4A7C15u ^ bits_of(p.y);

    h ^= h >> 29;
    h *= 0xBF58476D1CE4E5B9u;
    h ^= h >> 32;
    return (uint32_t)h;
}

/* About n / POINTS_PER_CELL square cells (at most cells) over the box of
 * v[0..n); one cell if the box is a point. */
static grid make_grid(const qc_vec2 *v, size_t n, size_t cells)
{
    double x1 = v[0].x, y1 = v[0].y, w, h, side;
    grid g;
    size_t i;

    g.x0 = x1, g.y0 = y1;
    for (i = 1; i < n; i++) { /* comparisons, not fmin (a libm call) */
        g.x0 = v[i].x < g.x0 ? v[i].x : g.x0, x1 = v[i].x > x1 ? v[i].x : x1;
        g.y0 = v[i].y < g.y0 ? v[i].y : g.y0, y1 = v[i].y > y1 ? v[i].y : y1;
    }
    w = x1 - g.x0, h = y1 - g.y0;
    g.gx = g.gy = 1;
    g.inv = 0;
    if (!(w + h > 0 && w + h < HUGE_VAL))
        return g;
    side = sqrt(w * h * POINTS_PER_CELL / (double)n);
    side = fmax(side, (w + h) * POINTS_PER_CELL / (double)n);
    for (;;) {
        double fx = w / side + 1, fy = h / side + 1;

        if (fx * fy <= (double)cells) {
            g.gx = (uint32_t)fx, g.gy = (uint32_t)fy;
            g.inv = 1 / side;
            return g;
        }
        side *= 1.25;
    }
}

static uint32_t cell_of(const grid *g, qc_vec2 p)
{
    double fx = (p.x - g->x0) * g->inv, fy = (p.y - g->y0) * g->inv;
    uint32_t cx = fx > 0 ? (fx < g->gx ? (uint32_t)fx : g->gx - 1) : 0;
    uint32_t cy = fy > 0 ? (fy < g->gy ? (uint32_t)fy : g->gy - 1) : 0;

    return cy * g->gx + cx;
}

/* place[i]: the slot of v[i]'s place in the table, whose entry holds (its
 * least index + 1) * 2, plus 1 if it is a junction (v[i] recurs in
 * v[0..n) other than as a repeat of the point just before: a run of equal
 * points is one visit). A hash table on the exact coordinates finds each
 * place's first index in one pass (a sort by place was a third of a
 * 10^5-point job). The answer does not depend on the table's order. */
static void junction_slots(qc__merge *mg, const qc_vec2 *v, size_t n)
{
    uint32_t *table = mg->table, *start = mg->start;
    uint32_t *place = mg->place;
    grid g = make_grid(v, n, mg->cells);
    size_t i, ncell = (size_t)g.gx * g.gy;

    memset(start, 0, (ncell + 1) * sizeof *start);
    for (i = 0; i < n; i++) { /* the points of each cell (place[i] holds its cell) */
        place[i] = cell_of(&g, v[i]);
        start[place[i] + 1]++;
    }
    for (i = 0; i < ncell; i++) /* ... then its slots */
        start[i + 1] = start[i] + cell_slots(start[i + 1]);
    memset(table, 0, start[ncell] * sizeof *table);
    for (i = 0; i < n; i++) {
        uint32_t c = place[i], lo = start[c], size = start[c + 1] - lo;
        uint32_t h = lo + (uint32_t)(((uint64_t)place_hash(v[i]) * size) >> 32);

        while (table[h] != 0) {
            qc_vec2 q = v[table[h] / 2 - 1];

            if (q.x == v[i].x && q.y == v[i].y)
                break;
            h = h + 1 == lo + size ? lo : h + 1;
        }
        if (table[h] == 0)
            table[h] = (uint32_t)(i + 1) * 2;
        else if (!(v[i - 1].x == v[i].x && v[i - 1].y == v[i].y))
            table[h] |= 1u; /* a new visit, not a repeat of the point before */
        place[i] = h;
    }
}

/* The least index of v[i]'s place if it is a junction, else QC__NOT_JOINT
 * (place[i] its slot, as junction_slots left it). */
static uint32_t joint_of(const qc__merge *mg, size_t i)
{
    uint32_t e = mg->table[mg->place[i]];

    return e & 1 ? e / 2 - 1 : QC__NOT_JOINT;
}

void qc__merge_junctions(qc__merge *mg, const qc_vec2 *v, size_t n)
{
    size_t i;

    junction_slots(mg, v, n);
    for (i = 0; i < n; i++)
        mg->place[i] = joint_of(mg, i);
}

static double dist(qc_vec2 a, qc_vec2 b)
{
    return qc_hypot(b.x - a.x, b.y - a.y);
}

/* The farthest of v[lo..hi) from segment ab: how far a chord from a to b
 * strays from the points it would replace. */
static double stray(const qc_vec2 *v, size_t lo, size_t hi, qc_vec2 a, qc_vec2 b)
{
    double d2 = 0;

    for (; lo < hi; lo++) { /* as fmax (a NaN distance is passed over), without its call */
        double e = qc__seg_dist2(v[lo], a, b);
        d2 = e > d2 ? e : d2;
    }
    return sqrt(d2);
}

/* Stores the tail as m[*k - 1], the kept point now settled, and makes p the
 * tail: the next kept point, which the merge may still move. */
static void keep_tail(qc_vec2 *m, size_t *k, qc_vec2 *tail, qc_vec2 p)
{
    m[*k - 1] = *tail;
    *tail = p;
    ++*k;
}

/* m[k - 1], the kept point the merge may still move, is held in tail and
 * stored only once a later point is kept: m may then run over v itself (m
 * <= v), as what the merge reads of v is past m[k - 2] (stray reads from
 * v[before + 1], and m[k - 2] is v[before] or earlier). */
size_t qc__merge_piece(qc__merge *mg, const qc_vec2 *v, size_t n, double min_seg,
                       double floor_len, double keep, qc_vec2 *m)
{
    unsigned char *gone = mg->gone;
    qc_vec2 tail; /* m[k - 1] */
    size_t i, k = 0, at = 0, before = 0; /* v indices of m[k - 1] and m[k - 2] */
    /* a step whose square exceeds this is at least min_seg long, whatever
     * the square root rounds to: most steps, without one (none when
     * min_seg keeps every step or is too small to square exactly) */
    double long2 = min_seg >= 1e-100 ? min_seg * min_seg * (1 + 1e-9) : HUGE_VAL;

    if (n == 0)
        return 0;
    /* the slots only: the few short steps look their junctions up */
    junction_slots(mg, v, n);
    memset(gone, 0, n / 8 + 1);
    tail = v[0];
    k = 1;
    for (i = 1; i < n; i++) {
        int last = i + 1 == n, joints, here_ok, prev_ok;
        uint32_t pi, pa; /* the junctions of v[i] and v[at] */
        double dx = v[i].x - tail.x, dy = v[i].y - tail.y, d, drop_here, drop_prev;

        d = dx * dx + dy * dy > long2 ? HUGE_VAL : dist(tail, v[i]);
        if (d == 0 && !last)
            continue;
        if (d >= min_seg || (i - at > MAX_MERGE_RUN && !last)) {
            before = at;
            at = i;
            keep_tail(m, &k, &tail, v[i]);
            continue;
        }
        /* a short step (most are not: the junctions are read only here) */
        pi = joint_of(mg, i);
        pa = joint_of(mg, at);
        joints = pi != QC__NOT_JOINT && pa != QC__NOT_JOINT;
        here_ok = !last && pi == QC__NOT_JOINT;
        prev_ok = k >= 2 && pa == QC__NOT_JOINT;
        /* dropping v[i]: the chord runs on from m[k - 1] to v[i + 1];
         * moving m[k - 1] onto v[i]: the chord runs from m[k - 2] */
        drop_here = last ? HUGE_VAL : stray(v, at + 1, i + 1, tail, v[i + 1]);
        drop_prev = k >= 2 && i - before <= MAX_MERGE_RUN
                    ? stray(v, before + 1, i, m[k - 2], v[i]) : HUGE_VAL;
        if (here_ok && drop_here <= keep)
            continue;
        if (prev_ok && drop_prev <= keep) {
            tail = v[i];
            at = i;
            continue;
        }
        if (d >= floor_len) { /* the path turns here: the short stitch stays */
            before = at;
            at = i;
            keep_tail(m, &k, &tail, v[i]);
            continue;
        }
        /* too short to sew: merge all the same, sparing a junction; of two,
         * as an earlier pass did; else where it strays less */
        if (joints && !last) {
            here_ok = is_gone(gone, pi) ||
                      (!is_gone(gone, pa) && (k < 2 || drop_here <= drop_prev));
            set_gone(gone, here_ok ? pi : pa);
        } else if (here_ok == prev_ok) {
            here_ok = !last && drop_here <= drop_prev;
        }
        if (here_ok)
            continue;
        if (k >= 2) {
            tail = v[i];
            at = i;
        } else if (d > 0) {
            keep_tail(m, &k, &tail, v[i]); /* a piece shorter than floor_len in all */
        }
    }
    m[k - 1] = tail;
    return k;
}
