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

/* The junction table has a power of two of slots, at least twice the
 * longest piece: probes stay short. */
static size_t table_slots(size_t longest)
{
    size_t t = 16;

    while (t < 2 * longest)
        t *= 2;
    return t;
}

int qc__merge_init(qc_ctx *ctx, qc__merge *mg, size_t longest)
{
    memset(mg, 0, sizeof *mg);
    if (longest == 0)
        return QC_OK;
    if (longest > UINT32_MAX / 2 - 1) /* a slot holds (index + 1) * 2 + 1 */
        return qc__fail(ctx, QC_ELIMIT, "a piece of %lu points is too long to merge",
                        (unsigned long)longest);
    mg->slots = table_slots(longest);
    mg->m = (qc_vec2 *)qc__alloc_array(ctx, longest, sizeof *mg->m);
    mg->table = (uint32_t *)qc__alloc_array(ctx, mg->slots, sizeof *mg->table);
    mg->place = (size_t *)qc__alloc_array(ctx, longest, sizeof *mg->place);
    mg->gone = (unsigned char *)qc__alloc(ctx, longest);
    mg->cap = longest;
    if (mg->m == NULL || mg->table == NULL || mg->place == NULL || mg->gone == NULL) {
        qc__merge_free(ctx, mg);
        return qc__fail(ctx, QC_ENOMEM, "out of memory: merging a piece of %lu points",
                        (unsigned long)longest);
    }
    return QC_OK;
}

void qc__merge_free(qc_ctx *ctx, qc__merge *mg)
{
    qc__free(ctx, mg->m, mg->cap * sizeof *mg->m);
    qc__free(ctx, mg->table, mg->slots * sizeof *mg->table);
    qc__free(ctx, mg->place, mg->cap * sizeof *mg->place);
    qc__free(ctx, mg->gone, mg->cap);
    memset(mg, 0, sizeof *mg);
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

    for (; lo < hi; lo++)
        d2 = fmax(d2, qc__seg_dist2(v[lo], a, b));
    return sqrt(d2);
}

size_t qc__merge_piece(qc__merge *mg, const qc_vec2 *v, size_t n, double min_seg,
                       double floor_len, double keep)
{
    qc_vec2 *m = mg->m;
    const size_t *place = mg->place;
    unsigned char *gone = mg->gone;
    size_t i, k = 0, at = 0, before = 0; /* v indices of m[k - 1] and m[k - 2] */

    if (n == 0)
        return 0;
    qc__mark_junctions(v, n, mg->table, mg->slots, mg->place);
    memset(gone, 0, n);
    m[k++] = v[0];
    for (i = 1; i < n; i++) {
        int last = i + 1 == n, joints = place[i] != QC__NOT_JOINT && place[at] != QC__NOT_JOINT;
        int here_ok = !last && place[i] == QC__NOT_JOINT, prev_ok = k >= 2 && place[at] == QC__NOT_JOINT;
        double d = dist(m[k - 1], v[i]), drop_here, drop_prev;

        if (d == 0 && !last)
            continue;
        if (d >= min_seg || (i - at > MAX_MERGE_RUN && !last)) {
            before = at;
            at = i;
            m[k++] = v[i];
            continue;
        }
        /* dropping v[i]: the chord runs on from m[k - 1] to v[i + 1];
         * moving m[k - 1] onto v[i]: the chord runs from m[k - 2] */
        drop_here = last ? HUGE_VAL : stray(v, at + 1, i + 1, m[k - 1], v[i + 1]);
        drop_prev = k >= 2 && i - before <= MAX_MERGE_RUN
                    ? stray(v, before + 1, i, m[k - 2], v[i]) : HUGE_VAL;
        if (here_ok && drop_here <= keep)
            continue;
        if (prev_ok && drop_prev <= keep) {
            m[k - 1] = v[i];
            at = i;
            continue;
        }
        if (d >= floor_len) { /* the path turns here: the short stitch stays */
            before = at;
            at = i;
            m[k++] = v[i];
            continue;
        }
        /* too short to sew: merge all the same, sparing a junction; of two,
         * as an earlier pass did; else where it strays less */
        if (joints && !last) {
            here_ok = gone[place[i]] || (!gone[place[at]] && (k < 2 || drop_here <= drop_prev));
            gone[here_ok ? place[i] : place[at]] = 1;
        } else if (here_ok == prev_ok) {
            here_ok = !last && drop_here <= drop_prev;
        }
        if (here_ok)
            continue;
        if (k >= 2) {
            m[k - 1] = v[i];
            at = i;
        } else if (d > 0) {
            m[k++] = v[i]; /* a piece shorter than floor_len in all */
        }
    }
    return k;
}
