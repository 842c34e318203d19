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

/* Sorts e[i..r), whose keys agree in the window, by the whole key: ties
 * of the window that are not exact ties (rare). */
static int sort_window_tie(qc_ctx *ctx, const keyed *k, const uint32_t *at, qc_edge *e,
                           size_t i, size_t r)
{
    keyed *t = qc__alloc_array(ctx, r - i, sizeof *t);
    size_t j;

    if (t == NULL)
        return QC_ENOMEM;
    for (j = i; j < r; j++)
        t[j - i] = k[at[j]];
    qsort(t, r - i, sizeof *t, keyed_cmp); /* keys with indices are distinct */
    for (j = i; j < r; j++)
        e[j] = t[j - i].e;
    qc__free(ctx, t, (r - i) * sizeof *t);
    return QC_OK;
}

/* Whether the keys of at[i..r), equal in the window of bits [s, s + 64)
 * above the least key, are equal: by their low 64 bits when those and the
 * window cover them (s <= 64), else whole. */
static int exact_tie(const keyed *k, const uint64_t *low, const uint32_t *at, size_t i,
                     size_t r, unsigned s)
{
    size_t j;

    for (j = i + 1; j < r; j++)
        if (s > 64 ? key_cmp(k[at[j]].k, k[at[i]].k) != 0 : low[at[j]] != low[at[i]])
            return 0;
    return 1;
}

/* Sorts keyed edges into e: a radix sort on the 64 bits of (key - least)
 * that lead (a lattice's lengths lie within a few ulps: the window holds
 * their whole spread, or most of it), then runs that tie there by index. */
static int sort_keyed(qc_ctx *ctx, const keyed *k, qc_edge *e, size_t m)
{
    uint64_t *rel = qc__alloc_array(ctx, m, sizeof *rel), d[4];
    uint64_t *low = qc__alloc_array(ctx, m, sizeof *low);
    uint32_t *at = qc__alloc_array(ctx, m, sizeof *at);
    size_t i, r, lo = 0, hi = 0;
    unsigned s;
    int rc = QC_OK;

    if (rel == NULL || low == NULL || at == NULL) {
        rc = QC_ENOMEM;
        goto out;
    }
    for (i = 1; i < m; i++) {
        if (key_cmp(k[i].k, k[lo].k) < 0)
            lo = i;
        if (key_cmp(k[i].k, k[hi].k) > 0)
            hi = i;
    }
    key_sub(k[hi].k, k[lo].k, d);
    s = key_bitlen(d) > 64 ? key_bitlen(d) - 64 : 0;
    for (i = 0; i < m; i++) {
        key_sub(k[i].k, k[lo].k, d);
        rel[i] = key_window(d, s);
        low[i] = d[3];
        at[i] = (uint32_t)i;
    }
    if ((rc = qc__radix_sort(ctx, rel, at, m, 0)) < 0)
        goto out;
    for (i = 0; i < m; i++) /* e in key order; low[] then holds e's old order */
        e[i] = k[at[i]].e;
    for (i = 0; i < m && rc == QC_OK; i = r) {
        for (r = i + 1; r < m && rel[r] == rel[i]; r++)
            ;
        if (r - i == 1)
            continue;
        if (s == 0 || exact_tie(k, low, at, i, r, s))
            rc = sort_by_index(ctx, e + i, r - i, rel + i); /* rel[i..r): scratch */
        else
            rc = sort_window_tie(ctx, k, at, e, i, r);
    }
out:
    qc__free(ctx, rel, m * sizeof *rel);
    qc__free(ctx, low, m * sizeof *low);
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

static int keys_at(const qc_vec2 *p, const qc_edge *e, size_t m, int scale, keyed *k)
{
    size_t i;

    for (i = 0; i < m; i++) {
        if (!qc__len2_key(p[e[i].a], p[e[i].b], scale, k[i].k))
            return 0;
        k[i].e = e[i];
    }
    return 1;
}

/* Sorts a group of edges whose computed lengths the float filter cannot
 * tell apart: a few by exact comparisons, more by exact keys (at the
 * points' scale, else at the group's own); keys too wide for 256 bits
 * (coordinates some 2^70 apart in magnitude) by comparisons. */
static int sort_group(qc_ctx *ctx, scales *sc, qc_edge *e, size_t m, keyed **buf, size_t *cap)
{
    const qc_vec2 *p = sc->p;
    int scale = INT_MAX;
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
    QC__TRY(QC__RESERVE(ctx, *buf, *cap, m));
    if (keys_at(p, e, m, sc->all, *buf))
        return sort_keyed(ctx, *buf, e, m);
    for (i = 0; i < m; i++)
        qc__len2_key_scale(p[e[i].a], p[e[i].b], &scale);
    if (scale > sc->all && keys_at(p, e, m, scale, *buf))
        return sort_keyed(ctx, *buf, e, m);
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
    keyed *buf = NULL;
    size_t i, r, g, cap = 0;
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
                rc = sort_group(ctx, &sc, e + g, i - g, &buf, &cap);
            g = i;
        }
        gmax = rmax;
    }
    if (rc == QC_OK && m - g > 1)
        rc = sort_group(ctx, &sc, e + g, m - g, &buf, &cap);
    qc__free(ctx, buf, cap * sizeof *buf);
    if (rc < 0)
        return qc__fail(ctx, rc, "mst: out of memory sorting %lu edges", (unsigned long)m);
    return QC_OK;
}
