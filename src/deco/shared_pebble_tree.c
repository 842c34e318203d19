/*
 * Pebbles after packing (shared_pebble_pack.c): each pebble's children in
 * counter-clockwise order round it, for the rendering walk, and the
 * figures --stats reports (radii, coverage, pebbles touching fewer than
 * three others).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "pebble_internal.h"

typedef struct kid_key {
    uint32_t parent, kid;
    double key;
} kid_key;

static int cmp_kid(const void *pa, const void *pb)
{
    const kid_key *a = pa, *b = pb;

    if (a->parent != b->parent)
        return a->parent < b->parent ? -1 : 1;
    if (a->key != b->key)
        return a->key < b->key ? -1 : 1;
    return a->kid < b->kid ? -1 : a->kid > b->kid;
}

void qc__pebbles_group_starts(const qc__pebbles *pb, uint32_t *first)
{
    size_t n = pb->n, i;

    memset(first, 0, (n + 1) * sizeof *first);
    for (i = 0; i < n; i++)
        if (pb->parent[i] != QC__PEB_NONE)
            first[pb->parent[i] + 1]++;
    for (i = 0; i < n; i++)
        first[i + 1] += first[i];
}

static double angle_of(qc_vec2 from, qc_vec2 to)
{
    return qc_atan2(to.y - from.y, to.x - from.x);
}

/* Counter-clockwise from entry to phi, in (0, 2 pi]. */
static double ccw_from(double entry, double phi)
{
    double k = phi - entry;

    while (k <= 0)
        k += 2 * QC_PI;
    while (k > 2 * QC_PI)
        k -= 2 * QC_PI;
    return k;
}

/* Each group (a few children) of keys[first[p] .. first[p + 1]) sorted in
 * cmp_kid's order, p < ngroups. */
static void sort_groups(kid_key *keys, const uint32_t *first, size_t ngroups)
{
    size_t p0, i;

    for (p0 = 0; p0 < ngroups; p0++)
        for (i = first[p0] + 1; i < first[p0 + 1]; i++) {
            kid_key x = keys[i];
            size_t k = i;
            for (; k > first[p0] && cmp_kid(&keys[k - 1], &x) > 0; k--)
                keys[k] = keys[k - 1];
            keys[k] = x;
        }
}

/* The middle of the widest gap between the root's children, whose keys
 * are keys[lo .. hi) sorted; *g: the child after it (counted from lo). */
static double widest_gap(const kid_key *keys, size_t lo, size_t hi, size_t *g)
{
    double gap = -1, a0 = -QC_PI / 2;
    size_t i;

    *g = 0;
    for (i = lo; i < hi; i++) {
        double k0 = keys[i].key, k1 = i + 1 < hi ? keys[i + 1].key : keys[lo].key + 2 * QC_PI;
        if (k1 - k0 > gap) {
            gap = k1 - k0;
            a0 = 0.5 * (k0 + k1);
            *g = i + 1 - lo;
        }
    }
    return a0;
}

int qc__pebbles_start_angle(qc_ctx *ctx, const qc__pebbles *pb, double *start_angle)
{
    size_t n = pb->n, i, m = 0;
    uint32_t first[2];
    kid_key *keys;
    double entry;

    if (n == 0) {
        *start_angle = -QC_PI / 2;
        return QC_OK;
    }
    entry = pb->parent[0] == QC__PEB_NONE ? 0 : angle_of(pb->c[0], pb->c[pb->parent[0]]);
    for (i = 0; i < n; i++)
        m += pb->parent[i] == 0;
    keys = qc__alloc_array(ctx, m + 1, sizeof *keys);
    if (keys == NULL)
        return QC_ENOMEM;
    for (i = 0, m = 0; i < n; i++)
        if (pb->parent[i] == 0) { /* the root's children, as qc__pebbles_children keys them */
            keys[m].parent = 0;
            keys[m].kid = (uint32_t)i;
            keys[m].key = ccw_from(entry, angle_of(pb->c[0], pb->c[i]));
            m++;
        }
    first[0] = 0;
    first[1] = (uint32_t)m;
    sort_groups(keys, first, 1);
    *start_angle = widest_gap(keys, 0, m, &i);
    qc__free(ctx, keys, (first[1] + 1) * sizeof *keys);
    return QC_OK;
}

int qc__pebbles_children(qc_ctx *ctx, const qc__pebbles *pb, uint32_t **first_out,
                         uint32_t **kids_out, double *start_angle, double **angle_out)
{
    size_t n = pb->n, i, m, g = 0, p;
    uint32_t *first = qc__alloc_array(ctx, n + 1, sizeof *first);
    uint32_t *kids = qc__alloc_array(ctx, n, sizeof *kids);
    kid_key *keys = qc__alloc_array(ctx, n, sizeof *keys);
    double *angle = angle_out != NULL ? qc__alloc_array(ctx, n, sizeof *angle) : NULL;

    *first_out = NULL;
    *kids_out = NULL;
    if (first == NULL || kids == NULL || keys == NULL || (angle_out != NULL && angle == NULL)) {
        qc__free(ctx, first, (n + 1) * sizeof *first);
        qc__free(ctx, kids, n * sizeof *kids);
        qc__free(ctx, keys, n * sizeof *keys);
        qc__free(ctx, angle, n * sizeof *angle);
        return QC_ENOMEM;
    }
    qc__pebbles_group_starts(pb, first);
    /* counter-clockwise from where p's own parent comes in (root: +x): that
     * direction once per parent, into its children's slots until each
     * child's key replaces it */
    for (p = 0; p < n; p++) {
        double entry;
        if (first[p + 1] == first[p])
            continue;
        entry = pb->parent[p] == QC__PEB_NONE ? 0 : angle_of(pb->c[p], pb->c[pb->parent[p]]);
        for (m = first[p]; m < first[p + 1]; m++)
            keys[m].key = entry;
    }
    for (i = 0; i < n; i++) { /* first[p] runs to the group's end */
        uint32_t q = pb->parent[i];
        double phi;
        if (q == QC__PEB_NONE)
            continue;
        m = first[q]++;
        phi = angle_of(pb->c[q], pb->c[i]);
        if (angle != NULL)
            angle[i] = phi;
        keys[m].parent = q;
        keys[m].kid = (uint32_t)i;
        keys[m].key = ccw_from(keys[m].key, phi);
    }
    for (i = n; i > 0; i--)
        first[i] = first[i - 1];
    first[0] = 0;
    sort_groups(keys, first, n);
    for (i = 0; i < first[n]; i++)
        kids[i] = keys[i].kid;
    /* the root starts in the middle of the widest gap between its children,
     * and meets them counter-clockwise from there */
    *start_angle = widest_gap(keys, first[0], first[1], &g);
    for (i = first[0]; i < first[1]; i++) /* rotate: the gap's far side first */
        kids[i] = keys[first[0] + (i - first[0] + g) % (first[1] - first[0])].kid;
    qc__free(ctx, keys, n * sizeof *keys);
    *first_out = first;
    *kids_out = kids;
    if (angle_out != NULL)
        *angle_out = angle;
    return QC_OK;
}

/* Fraction of the disk (c, r) inside the region (c inside), from 64 points. */
static double inside_fraction(qc__pbound *b, qc_vec2 c, double r)
{
    int i, in = 0;

    for (i = 0; i < 64; i++) { /* a sunflower: even over the disk */
        double rr = r * sqrt((i + 0.5) / 64), a = i * 2.39996322972865332, sn, cs;
        qc_vec2 q;
        qc__sincos(a, &sn, &cs);
        q = QC__V2(c.x + rr * cs, c.y + rr * sn);
        in += (qc__pbound_crossings(b, c, q) & 1) == 0;
    }
    return in / 64.0;
}

int qc__pebbles_stats(qc_ctx *ctx, const qc__pebbles *pb, qc__pbound *b, qc_stats *st)
{
    size_t i, under = 0;
    double lo = HUGE_VAL, hi = 0, sum = 0, area = 0, ra = qc_region_area(b->region);

    (void)ctx;
    for (i = 0; i < pb->n; i++) {
        double r = pb->r[i], a = QC_PI * r * r;
        lo = fmin(lo, r);
        hi = fmax(hi, r);
        sum += r;
        under += pb->contacts[i] < 3;
        if (pb->k < 1 && qc__pbound_dist(b, pb->c[i], r) < r)
            a *= inside_fraction(b, pb->c[i], r);
        area += a;
    }
    st->pebbles += pb->n;
    st->pebbles_under3 += under;
    st->radius_min = pb->n ? lo : 0;
    st->radius_max = hi;
    st->radius_mean = pb->n ? sum / (double)pb->n : 0;
    st->coverage = ra > 0 ? fmin(1, area / ra) : 0;
    return QC_OK;
}
