/*
 * The MST's edge order, (exact squared length, a, b) with a < b, at the
 * speed of a float sort. A radix sort on the computed lengths does nearly
 * all of it; exact work is only done where computed lengths nearly tie, and
 * even a lattice's millions of equal lengths cost one exact integer key per
 * edge (qc__len2_key), not exact arithmetic per comparison.
 */
#include <limits.h>
#include <stdlib.h>
#include <string.h>

#include "graph_internal.h"

#define SMALL 16 /* groups up to this size: insertion sort */

static double len2(const qc_vec2 *p, qc_edge e)
{
    double dx = p[e.a].x - p[e.b].x, dy = p[e.a].y - p[e.b].y;

    return dx * dx + dy * dy;
}

static uint64_t len_key(double l)
{
    uint64_t u;

    memcpy(&u, &l, sizeof u); /* l >= +0: the bits order like the values */
    return u;
}

static int index_before(qc_edge x, qc_edge y)
{
    return x.a != y.a ? x.a < y.a : x.b < y.b;
}

/* The total order, lengths compared exactly. */
static int edge_before(const qc_vec2 *p, qc_edge x, qc_edge y)
{
    int c = qc__cmp_len2(p[x.a], p[x.b], p[y.a], p[y.b]);

    return c != 0 ? c < 0 : index_before(x, y);
}

static void sift(const qc_vec2 *p, qc_edge *e, size_t i, size_t m)
{
    for (;;) {
        size_t c = 2 * i + 1;
        qc_edge t;

        if (c >= m)
            return;
        if (c + 1 < m && edge_before(p, e[c], e[c + 1]))
            c++;
        if (!edge_before(p, e[i], e[c]))
            return;
        t = e[i], e[i] = e[c], e[c] = t;
        i = c;
    }
}

/* Sorts e[0..m) by comparisons (no allocation): insertion for a few, else
 * a heap sort (groups whose keys do not fit, rare). */
static void sort_compared(const qc_vec2 *p, qc_edge *e, size_t m)
{
    size_t i, j;

    if (m <= SMALL) {
        for (i = 1; i < m; i++) {
            qc_edge x = e[i];
            for (j = i; j > 0 && edge_before(p, x, e[j - 1]); j--)
                e[j] = e[j - 1];
            e[j] = x;
        }
        return;
    }
    for (i = m / 2; i-- > 0;)
        sift(p, e, i, m);
    for (i = m; i-- > 1;) {
        qc_edge t = e[0];
        e[0] = e[i], e[i] = t;
        sift(p, e, 0, i);
    }
}

/* An edge with its exact squared length as an integer (qc__len2_key). */
typedef struct keyed {
    uint64_t k[4]; /* most significant first */
    qc_edge e;
} keyed;

static int key_cmp(const uint64_t *x, const uint64_t *y)
{
    int i;

    for (i = 0; i < 4; i++)
        if (x[i] != y[i])
            return x[i] < y[i] ? -1 : 1;
    return 0;
}

static int keyed_cmp(const void *x, const void *y)
{
    const keyed *a = x, *b = y;
    int c = key_cmp(a->k, b->k);

    if (c != 0)
        return c;
    return index_before(a->e, b->e) ? -1 : index_before(b->e, a->e);
}

/* d = x - y for x >= y. */
static void key_sub(const uint64_t *x, const uint64_t *y, uint64_t *d)
{
    uint64_t borrow = 0;
    int w;

    for (w = 3; w >= 0; w--) {
        uint64_t t = y[w] + borrow;
        borrow = t < borrow || x[w] < t;
        d[w] = x[w] - t;
    }
}

static unsigned key_bitlen(const uint64_t *x)
{
    unsigned n = 256;
    int w;

    for (w = 0; w < 4; w++, n -= 64)
        if (x[w] != 0) {
            uint64_t v = x[w];
            while ((v & (uint64_t)1 << 63) == 0)
                v <<= 1, n--;
            return n;
        }
    return 0;
}

/* 64 bits of x from bit s up (x < 2^(s + 64)). */
static uint64_t key_window(const uint64_t *x, unsigned s)
{
    unsigned w = 3 - s / 64, r = s % 64;

    return r == 0 ? x[w] : x[w] >> r | (w > 0 ? x[w - 1] << (64 - r) : 0);
}

/* Sorts e[0..m) by (a, b): a run of exactly equal lengths. */
static int sort_by_index(qc_ctx *ctx, qc_edge *e, size_t m, uint64_t *scratch)
{
    size_t i, j;

    if (m <= SMALL) {
        for (i = 1; i < m; i++) {
            qc_edge x = e[i];
            for (j = i; j > 0 && index_before(x, e[j - 1]); j--)
                e[j] = e[j - 1];
            e[j] = x;
        }
        return QC_OK;
    }
    for (i = 0; i < m; i++)
        scratch[i] = (uint64_t)e[i].a << 32 | e[i].b;
    QC__TRY(qc__radix_sort(ctx, scratch, NULL, m, 0));
    for (i = 0; i < m; i++) {
        e[i].a = (uint32_t)(scratch[i] >> 32);
        e[i].b = (uint32_t)scratch[i];
    }
    return QC_OK;
}

/* Sorts m keyed edges (keys k, 4 words each, e beside) by comparisons of
 * the whole key: keys spread over more than 128 bits (rare: coordinates
 * near 0 beside a large block). */
static int sort_wide(qc_ctx *ctx, const uint64_t *k, qc_edge *e, size_t m)
{
    keyed *t = qc__alloc_array(ctx, m, sizeof *t);
    size_t i;

    if (t == NULL)
        return QC_ENOMEM;
    for (i = 0; i < m; i++) {
        memcpy(t[i].k, k + 4 * i, sizeof t[i].k);
        t[i].e = e[i];
    }
    qsort(t, m, sizeof *t, keyed_cmp); /* keys with indices are distinct: deterministic */
    for (i = 0; i < m; i++)
        e[i] = t[i].e;
    qc__free(ctx, t, m * sizeof *t);
    return QC_OK;
}

/* An edge with the low 64 bits of its key above the least. */
typedef struct low_edge {
    uint64_t low;
    qc_edge e;
} low_edge;

static int low_edge_cmp(const void *x, const void *y)
{
    const low_edge *a = x, *b = y;

    if (a->low != b->low)
        return a->low < b->low ? -1 : 1;
    return index_before(a->e, b->e) ? -1 : index_before(b->e, a->e);
}

/* Sorts e[i..r), equal in the window, by (low bits, index): with the window
 * they make the whole key when s <= 64. Exact ties go by index alone. */
static int sort_window_run(qc_ctx *ctx, qc_edge *e, const uint64_t *low, const uint32_t *at,
                           size_t i, size_t r, uint64_t *scratch)
{
    low_edge *t;
    size_t j;

    for (j = i + 1; j < r && low[at[j]] == low[at[i]]; j++)
        ;
    if (j == r)
        return sort_by_index(ctx, e + i, r - i, scratch);
    t = qc__alloc_array(ctx, r - i, sizeof *t);
    if (t == NULL)
        return QC_ENOMEM;
    for (j = i; j < r; j++) {
        t[j - i].low = low[at[j]];
        t[j - i].e = e[j];
    }
    qsort(t, r - i, sizeof *t, low_edge_cmp);
    for (j = i; j < r; j++)
        e[j] = t[j - i].e;
    qc__free(ctx, t, (r - i) * sizeof *t);
    return QC_OK;
}

/* Sorts e[0..m) by its exact keys k (4 words each; k is freed here): a
 * radix sort on the 64 bits of (key - least) from bit s up, the window (a
 * lattice's lengths lie within a few ulps: it holds their whole spread, or
 * most of it), then runs that tie there. The keys are narrowed to the
 * window in place, so a group costs at most 44 bytes an edge. */
static int sort_keyed(qc_ctx *ctx, uint64_t *k, qc_edge *e, size_t m)
{
    uint64_t least[4], d[4], *low = NULL, *rel;
    uint32_t *at = NULL;
    qc_edge *tmp = NULL;
    size_t i, r, lo = 0, hi = 0;
    unsigned s;
    int rc = QC_OK;

    for (i = 1; i < m; i++) {
        if (key_cmp(k + 4 * i, k + 4 * lo) < 0)
            lo = i;
        if (key_cmp(k + 4 * i, k + 4 * hi) > 0)
            hi = i;
    }
    memcpy(least, k + 4 * lo, sizeof least);
    key_sub(k + 4 * hi, least, d);
    s = key_bitlen(d) > 64 ? key_bitlen(d) - 64 : 0;
    if (s > 64) {
        rc = sort_wide(ctx, k, e, m);
        qc__free(ctx, k, 4 * m * sizeof *k);
        return rc;
    }
    at = qc__alloc_array(ctx, m, sizeof *at);
    low = s > 0 ? qc__alloc_array(ctx, m, sizeof *low) : NULL;
    if (at == NULL || (s > 0 && low == NULL)) {
        qc__free(ctx, k, 4 * m * sizeof *k);
        rc = QC_ENOMEM;
        goto out;
    }
    for (i = 0; i < m; i++) { /* k[i] is written once k[4i..4i+4) is read */
        key_sub(k + 4 * i, least, d);
        if (low != NULL)
            low[i] = d[3];
        k[i] = key_window(d, s);
        at[i] = (uint32_t)i;
    }
    rel = qc__realloc(ctx, k, 4 * m * sizeof *k, m * sizeof *k);
    if (rel == NULL) {
        qc__free(ctx, k, 4 * m * sizeof *k);
        rc = QC_ENOMEM;
        goto out;
    }
    if ((rc = qc__radix_sort(ctx, rel, at, m, 0)) == QC_OK &&
        (tmp = qc__alloc_array(ctx, m, sizeof *tmp)) == NULL)
        rc = QC_ENOMEM;
    if (rc == QC_OK) { /* e in window order; low[] stays in e's old order */
        for (i = 0; i < m; i++)
            tmp[i] = e[at[i]];
        memcpy(e, tmp, m * sizeof *e);
        qc__free(ctx, tmp, m * sizeof *tmp);
    }
    for (i = 0; i < m && rc == QC_OK; i = r) {
        for (r = i + 1; r < m && rel[r] == rel[i]; r++)
            ;
        if (r - i == 1)
            continue;
        rc = s == 0 ? sort_by_index(ctx, e + i, r - i, rel + i) /* rel[i..r): scratch */
                    : sort_window_run(ctx, e, low, at, i, r, rel + i);
    }
    qc__free(ctx, rel, m * sizeof *rel);
out:
    qc__free(ctx, low, low != NULL ? m * sizeof *low : 0);
    qc__free(ctx, at, m * sizeof *at);
    return rc;
}

/* The points' scale (qc__len2_key_scale over all of them), found when a
 * first group needs keys: a scale for every group, without a pass over the
 * group's points in random order. */
typedef struct scales {
    const qc_vec2 *p;
    size_t n;
    int all, known;
} scales;

static int keys_at(const qc_vec2 *p, const qc_edge *e, size_t m, int scale, uint64_t *k)
{
    size_t i;

    for (i = 0; i < m; i++)
        if (!qc__len2_key(p[e[i].a], p[e[i].b], scale, k + 4 * i))
            return 0;
    return 1;
}

/* Sorts a group of edges whose computed lengths the float filter cannot
 * tell apart: a few by exact comparisons, more by exact keys (at the
 * points' scale, else at the group's own); keys too wide for 256 bits
 * (coordinates some 2^70 apart in magnitude) by comparisons. */
static int sort_group(qc_ctx *ctx, scales *sc, qc_edge *e, size_t m)
{
    const qc_vec2 *p = sc->p;
    int scale = INT_MAX, ok;
    uint64_t *k;
    size_t i;

    if (m <= SMALL) {
        sort_compared(p, e, m);
        return QC_OK;
    }
    if (!sc->known) {
        sc->all = INT_MAX;
        for (i = 0; i < sc->n; i++)
            qc__len2_key_scale(p[i], p[i], &sc->all);
        sc->known = 1;
    }
    k = qc__alloc_array(ctx, m, 4 * sizeof *k);
    if (k == NULL)
        return QC_ENOMEM;
    ok = keys_at(p, e, m, sc->all, k);
    if (!ok) {
        for (i = 0; i < m; i++)
            qc__len2_key_scale(p[e[i].a], p[e[i].b], &scale);
        ok = scale > sc->all && keys_at(p, e, m, scale, k);
    }
    if (ok)
        return sort_keyed(ctx, k, e, m);
    qc__free(ctx, k, 4 * m * sizeof *k);
    sort_compared(p, e, m);
    return QC_OK;
}

/* The float filter of qc__cmp_len2: every edge of computed length lo is
 * shorter, exactly, than every edge of computed length hi (each within 4
 * ulps of its exact value, unless under 2^-900, where squares underflow). */
static int apart(double lo, double hi)
{
    return hi - lo > 8.0 * 0x1p-53 * (lo + hi) && hi > 0x1p-900;
}

int qc__sort_edges(qc_ctx *ctx, const qc_vec2 *p, size_t n, qc_edge *e, size_t m)
{
    scales sc;
    uint64_t *key = qc__alloc_array(ctx, m, sizeof *key);
    size_t i, r, g;
    double gmax = 0;
    int rc = QC_OK;

    if (key == NULL)
        return qc__fail(ctx, QC_ENOMEM, "mst: out of memory sorting %lu edges",
                        (unsigned long)m);
    sc.p = p;
    sc.n = n;
    sc.all = INT_MAX;
    sc.known = 0;
    for (i = 0; i < m; i++)
        key[i] = (len_key(len2(p, e[i])) >> 32) << 32 | (uint64_t)i;
    if (qc__radix_sort(ctx, key, NULL, m, 32) < 0) {
        qc__free(ctx, key, m * sizeof *key);
        return QC_ENOMEM;
    }
    /* Permute through key[] as scratch: e[index in key[i]] -> position i. */
    for (i = 0; i < m; i++) {
        qc_edge x = e[(uint32_t)key[i]];
        key[i] = (uint64_t)x.a << 32 | x.b;
    }
    for (i = 0; i < m; i++) {
        e[i].a = (uint32_t)(key[i] >> 32);
        e[i].b = (uint32_t)key[i];
    }
    qc__free(ctx, key, m * sizeof *key);
    /* Runs [i, r) agree in the upper 32 bits; the group [g, i) before them
     * closes when the filter tells it apart from the run. */
    for (g = i = 0; i < m && rc == QC_OK; i = r) {
        double l = len2(p, e[i]), rmin = l, rmax = l;
        uint64_t hi = len_key(l) >> 32;

        for (r = i + 1; r < m && len_key(l = len2(p, e[r])) >> 32 == hi; r++) {
            rmin = l < rmin ? l : rmin;
            rmax = l > rmax ? l : rmax;
        }
        if (i > g && apart(gmax, rmin)) {
            if (i - g > 1)
                rc = sort_group(ctx, &sc, e + g, i - g);
            g = i;
        }
        gmax = rmax;
    }
    if (rc == QC_OK && m - g > 1)
        rc = sort_group(ctx, &sc, e + g, m - g);
    if (rc < 0)
        return qc__fail(ctx, rc, "mst: out of memory sorting %lu edges", (unsigned long)m);
    return QC_OK;
}
