/*
 * Travel along the seams: the point of a patch's boundary nearest a
 * pattern's end (the straight stitch to it stays inside the patch, since
 * the disc reaching the nearest boundary point holds no boundary), and the
 * shortest way along the seam graph between two seam points (Dijkstra from
 * both ends of the source's edge, a binary heap with lazy deletion).
 */
#include <math.h>
#include <string.h>

#include "quilt_internal.h"

static double dist(qc_vec2 a, qc_vec2 b)
{
    return qc_hypot(a.x - b.x, a.y - b.y);
}

qc__seam_pt qc__seams_nearest(const qc__seams *s, size_t patch, qc_vec2 p)
{
    size_t r = patch ? s->patch_end[patch - 1] : 0, j;
    qc__seam_pt best;
    double bd = HUGE_VAL;

    best.p = p;
    best.u = best.v = 0;
    for (; r < s->patch_end[patch]; r++) {
        size_t start = r ? s->ring_end[r - 1] : 0, end = s->ring_end[r];

        for (j = start; j < end; j++) {
            uint32_t a = s->bnd[j], b = s->bnd[j + 1 < end ? j + 1 : start];
            qc_vec2 pa = s->v[a], pb = s->v[b], q;
            double dx = pb.x - pa.x, dy = pb.y - pa.y, l2 = dx * dx + dy * dy, t = 0, d;

            if (l2 > 0)
                t = ((p.x - pa.x) * dx + (p.y - pa.y) * dy) / l2;
            t = t < 0 ? 0 : t > 1 ? 1 : t;
            q.x = pa.x + t * dx;
            q.y = pa.y + t * dy;
            d = dist(p, q);
            if (d < bd) {
                bd = d;
                best.p = q;
                best.u = t == 1 ? b : a;
                best.v = t == 0 ? a : b;
            }
        }
    }
    return best;
}

int qc__seam_dist_init(qc_ctx *ctx, const qc__seams *s, qc__seam_dist *sd)
{
    memset(sd, 0, sizeof *sd);
    sd->d = (double *)qc__alloc_array(ctx, s->nv, sizeof *sd->d);
    sd->prev = (uint32_t *)qc__alloc_array(ctx, s->nv, sizeof *sd->prev);
    if (sd->d == NULL || sd->prev == NULL) {
        qc__seam_dist_free(ctx, s, sd);
        return QC_ENOMEM;
    }
    return QC_OK;
}

void qc__seam_dist_free(qc_ctx *ctx, const qc__seams *s, qc__seam_dist *sd)
{
    qc__free(ctx, sd->d, s->nv * sizeof *sd->d);
    qc__free(ctx, sd->prev, s->nv * sizeof *sd->prev);
    qc__free(ctx, sd->heap, sd->heap_cap * sizeof *sd->heap);
    memset(sd, 0, sizeof *sd);
}

static int heap_less(const qc__seam_dist *sd, size_t a, size_t b)
{
    if (sd->heap[a].d != sd->heap[b].d)
        return sd->heap[a].d < sd->heap[b].d;
    return sd->heap[a].k < sd->heap[b].k;
}

static void heap_swap(qc__seam_dist *sd, size_t a, size_t b)
{
    double d = sd->heap[a].d;
    uint32_t k = sd->heap[a].k;

    sd->heap[a] = sd->heap[b];
    sd->heap[b].d = d;
    sd->heap[b].k = k;
}

static int heap_push(qc_ctx *ctx, qc__seam_dist *sd, double d, uint32_t k)
{
    size_t i = sd->nheap;

    QC__TRY(QC__RESERVE(ctx, sd->heap, sd->heap_cap, sd->nheap + 1));
    sd->heap[sd->nheap].d = d;
    sd->heap[sd->nheap++].k = k;
    while (i > 0 && heap_less(sd, i, (i - 1) / 2)) {
        heap_swap(sd, i, (i - 1) / 2);
        i = (i - 1) / 2;
    }
    return QC_OK;
}

static void heap_pop(qc__seam_dist *sd)
{
    size_t i = 0;

    sd->heap[0] = sd->heap[--sd->nheap];
    for (;;) {
        size_t l = 2 * i + 1, r = l + 1, m = i;
        if (l < sd->nheap && heap_less(sd, l, m))
            m = l;
        if (r < sd->nheap && heap_less(sd, r, m))
            m = r;
        if (m == i)
            break;
        heap_swap(sd, i, m);
        i = m;
    }
}

static int relax(qc_ctx *ctx, qc__seam_dist *sd, uint32_t k, double d, uint32_t from)
{
    if (!(d < sd->d[k]))
        return QC_OK;
    sd->d[k] = d;
    sd->prev[k] = from;
    return heap_push(ctx, sd, d, k);
}

int qc__seam_dist_from(qc_ctx *ctx, const qc__seams *s, qc__seam_dist *sd, qc__seam_pt from)
{
    size_t k;

    for (k = 0; k < s->nv; k++) {
        sd->d[k] = HUGE_VAL;
        sd->prev[k] = UINT32_MAX;
    }
    sd->from = from;
    sd->nheap = 0;
    QC__TRY(relax(ctx, sd, from.u, dist(from.p, s->v[from.u]), UINT32_MAX));
    QC__TRY(relax(ctx, sd, from.v, dist(from.p, s->v[from.v]), UINT32_MAX));
    while (sd->nheap > 0) {
        double d = sd->heap[0].d;
        uint32_t u = sd->heap[0].k, e;

        heap_pop(sd);
        if (d > sd->d[u])
            continue; /* a stale entry */
        for (e = s->adj_start[u]; e < s->adj_start[u + 1]; e++)
            QC__TRY(relax(ctx, sd, s->adj[e], d + dist(s->v[u], s->v[s->adj[e]]), u));
    }
    return QC_OK;
}

static int same_edge(qc__seam_pt a, qc__seam_pt b)
{
    return (a.u == b.u && a.v == b.v) || (a.u == b.v && a.v == b.u);
}

/* Appends the vertices from the source to k, source first. */
static int push_chain(qc_ctx *ctx, const qc__seams *s, const qc__seam_dist *sd, uint32_t k,
                      qc_points *path)
{
    size_t n0 = path->n, a, b;
    uint32_t c;

    for (c = k; c != UINT32_MAX; c = sd->prev[c])
        QC__TRY(qc_points_push(ctx, path, s->v[c]));
    for (a = n0, b = path->n - 1; a < b; a++, b--) {
        qc_vec2 t = path->v[a];
        path->v[a] = path->v[b];
        path->v[b] = t;
    }
    return QC_OK;
}

double qc__seam_travel(qc_ctx *ctx, const qc__seams *s, const qc__seam_dist *sd, qc__seam_pt to,
                       qc_points *path, int *rc)
{
    double du = sd->d[to.u] + dist(s->v[to.u], to.p);
    double dv = sd->d[to.v] + dist(s->v[to.v], to.p);
    double best = fmin(du, dv);
    int direct = same_edge(sd->from, to) && dist(sd->from.p, to.p) <= best;

    *rc = QC_OK;
    if (direct)
        best = dist(sd->from.p, to.p);
    if (path == NULL || best == HUGE_VAL)
        return best;
    *rc = qc_points_push(ctx, path, sd->from.p);
    if (*rc >= 0 && !direct)
        *rc = push_chain(ctx, s, sd, du <= dv ? to.u : to.v, path);
    if (*rc >= 0)
        *rc = qc_points_push(ctx, path, to.p);
    return best;
}
