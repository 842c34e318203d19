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

int qc__pebbles_children(qc_ctx *ctx, const qc__pebbles *pb, uint32_t **first_out,
                         uint32_t **kids_out, double *start_angle, double **angle_out)
{
    size_t n = pb->n, i, m, g = 0, p0;
    uint32_t *first = qc__alloc_array(ctx, n + 1, sizeof *first);
    uint32_t *kids = qc__alloc_array(ctx, n, sizeof *kids);
    kid_key *keys = qc__alloc_array(ctx, n, sizeof *keys);
    double *angle = angle_out != NULL ? qc__alloc_array(ctx, n, sizeof *angle) : NULL;
    double gap = -1, a0 = -QC_PI / 2;

    *first_out = NULL;
    *kids_out = NULL;
    if (first == NULL || kids == NULL || keys == NULL || (angle_out != NULL && angle == NULL)) {
        qc__free(ctx, first, (n + 1) * sizeof *first);
        qc__free(ctx, kids, n * sizeof *kids);
        qc__free(ctx, keys, n * sizeof *keys);
        qc__free(ctx, angle, n * sizeof *angle);
        return QC_ENOMEM;
    }
    qc__pebbles_group_starts(pb, first); /* first[p] runs to the group's end */
    for (i = 0; i < n; i++) {
        uint32_t p = pb->parent[i];
        double entry, k, phi;
        if (p == QC__PEB_NONE)
            continue;
        m = first[p]++;
        /* counter-clockwise from where p's own parent comes in (root: +x) */
        entry = pb->parent[p] == QC__PEB_NONE ? 0 : angle_of(pb->c[p], pb->c[pb->parent[p]]);
        phi = angle_of(pb->c[p], pb->c[i]);
        if (angle != NULL)
            angle[i] = phi;
        k = phi - entry;
        while (k <= 0)
            k += 2 * QC_PI;
        while (k > 2 * QC_PI)
            k -= 2 * QC_PI;
        keys[m].parent = p;
        keys[m].kid = (uint32_t)i;
        keys[m].key = k;
    }
    for (i = n; i > 0; i--)
        first[i] = first[i - 1];
    first[0] = 0;
    for (p0 = 0; p0 < n; p0++) /* each group (a few children) in cmp_kid's order */
        for (i = first[p0] + 1; i < first[p0 + 1]; i++) {
            kid_key x = keys[i];
            size_t k = i;
            for (; k > first[p0] && cmp_kid(&keys[k - 1], &x) > 0; k--)
                keys[k] = keys[k - 1];
            keys[k] = x;
        }
    for (i = 0; i < first[n]; i++)
        kids[i] = keys[i].kid;
    /* the root starts in the middle of the widest gap between its children,
     * and meets them counter-clockwise from there */
    for (i = first[0]; i < first[1]; i++) {
        double k0 = keys[i].key, k1 = i + 1 < first[1] ? keys[i + 1].key
                                                       : keys[first[0]].key + 2 * QC_PI;
        if (k1 - k0 > gap) {
            gap = k1 - k0;
            a0 = 0.5 * (k0 + k1);
            g = i + 1 - first[0];
        }
    }
    for (i = first[0]; i < first[1]; i++) /* rotate: the gap's far side first */
        kids[i] = keys[first[0] + (i - first[0] + g) % (first[1] - first[0])].kid;
    *start_angle = a0;
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
