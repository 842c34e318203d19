/*
 * Keeping every stitch inside: smoothing rounds a cusp or a reflex corner
 * wide, and a tour arc can jump a notch or a hole, so after decoration each
 * command is sampled against the region; a straying cubic is tightened
 * (control points pulled towards its ends) and, when even its chord strays,
 * replaced by the shortest route inside round the region's reflex corners.
 */
#include <math.h>
#include <string.h>

#include "keep_inside.h"
#include "region_index.h"

#define STEP_MM 0.2    /* sampling along a command */
#define INSET_MM 0.5   /* route nodes sit this far inside a reflex corner */
#define MAX_NODES 2000 /* route nodes (reflex corners) considered */
#define MAX_DISC_CELLS 4.0 /* a safe disc's side, in index cells, at most */

typedef struct kin {
    qc_ctx *ctx;
    const qc_region *region;
    const char *family;
    qc__rindex ix;
    int built;
    qc_vec2 *node;      /* inset reflex corners, then the two route ends */
    size_t nnode, cap;  /* nnode corners; arrays hold nnode + 2 */
    unsigned char *vis; /* nnode^2: 0 unknown, 1 visible, 2 blocked */
    double *dist;
    uint32_t *prev;
    unsigned char *done;
    /* a disc inside the region with no boundary within QC__INSIDE_TOL_MM
     * of it (safe_r 0: none yet): every point in it passes ok_point */
    qc_vec2 safe_c;
    double safe_r;
} kin;

static int ok_point(const kin *k, qc_vec2 p)
{
    return qc__rindex_contains(&k->ix, p) || qc__rindex_near(&k->ix, p, QC__INSIDE_TOL_MM);
}

/* Whether the box of q[0..n) (a hair wider than rounding can carry a
 * sample) lies inside the region: then every sample of the command is
 * inside and need not be tested one by one. */
static int hull_inside(const kin *k, const qc_vec2 *q, size_t n)
{
    qc_bbox b;
    double pad;
    size_t i;

    b.min = b.max = q[0];
    for (i = 1; i < n; i++) { /* comparisons: fmin and fmax are calls */
        b.min.x = q[i].x < b.min.x ? q[i].x : b.min.x;
        b.max.x = q[i].x > b.max.x ? q[i].x : b.max.x;
        b.min.y = q[i].y < b.min.y ? q[i].y : b.min.y;
        b.max.y = q[i].y > b.max.y ? q[i].y : b.max.y;
    }
    pad = -b.min.x > b.max.x ? -b.min.x : b.max.x;
    pad = -b.min.y > pad ? -b.min.y : pad;
    pad = b.max.y > pad ? b.max.y : pad;
    pad = 1e-9 * (1.0 + pad);
    b.min.x -= pad, b.min.y -= pad, b.max.x += pad, b.max.y += pad;
    return qc__rindex_box_inside(&k->ix, b);
}

/* Whether all n points lie in the safe disc. */
static int in_safe(const kin *k, const qc_vec2 *p, size_t n)
{
    double r2 = k->safe_r * k->safe_r;
    size_t i;

    for (i = 0; i < n; i++) {
        double dx = p[i].x - k->safe_c.x, dy = p[i].y - k->safe_c.y;
        if (!(dx * dx + dy * dy <= r2))
            return 0;
    }
    return k->safe_r > 0.0;
}

/* Whether the convex hull of the n points (a segment's ends, a cubic's
 * control points: every sample the checks below take) lies in a safe
 * disc, so they would all pass; the disc is re-centred on p[0] (radius 64,
 * 8 or 1 times the points' spread, the largest clear of the boundary) when
 * they leave it. Only a shortcut: sampling decides wherever this cannot,
 * so the answers (and the output) are the same, with a few index queries
 * per stretch of path instead of one per 0.2 mm. */
static int clear_inside(kin *k, const qc_vec2 *p, size_t n)
{
    double e = 0.0, r;
    size_t i;

    if (in_safe(k, p, n))
        return 1;
    for (i = 1; i < n; i++)
        e = fmax(e, qc_hypot(p[i].x - p[0].x, p[i].y - p[0].y));
    e = fmax(e, STEP_MM);
    if (!qc__rindex_contains(&k->ix, p[0]))
        return 0;
    for (r = 64.0 * e; r >= e; r *= 0.125)
        if (!qc__rindex_near(&k->ix, p[0], r + QC__INSIDE_TOL_MM)) {
            /* as wide as the boundary allows, while a query stays within
             * MAX_DISC_CELLS index cells: one disc then serves a whole
             * stretch of small commands (motifs, pebbles) */
            while (2.0 * r < MAX_DISC_CELLS * k->ix.cell &&
                   !qc__rindex_near(&k->ix, p[0], 2.0 * r + QC__INSIDE_TOL_MM))
                r *= 2.0;
            k->safe_c = p[0];
            k->safe_r = r;
            return in_safe(k, p, n);
        }
    return 0;
}

/* Whether every sample of the command q[0..n) is known inside without
 * sampling: in the safe disc, its box inside the region, or in a disc
 * found anew. Sampling decides wherever none can say. */
static int known_inside(kin *k, const qc_vec2 *q, size_t n)
{
    return in_safe(k, q, n) || clear_inside(k, q, n) || hull_inside(k, q, n);
}

/* The sample count is worked out only where the shortcuts cannot decide
 * (most commands never need it: its hypots were the checks' largest cost). */
static int seg_ok(kin *k, qc_vec2 a, qc_vec2 b)
{
    double len, m;
    size_t i, n;
    qc_vec2 ends[2];

    ends[0] = a;
    ends[1] = b;
    if (known_inside(k, ends, 2))
        return 1;
    len = qc_hypot(b.x - a.x, b.y - a.y);
    m = ceil(len / STEP_MM);
    n = m < 1.0 ? 1 : (m < 1e7 ? (size_t)m : 10000000u);
    for (i = 0; i <= n; i++) {
        double t = (double)i / (double)n;
        if (!ok_point(k, QC__V2(a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t)))
            return 0;
    }
    return 1;
}

static int cubic_ok(kin *k, const qc_vec2 *q)
{
    double len, m;
    size_t i, n;

    if (known_inside(k, q, 4))
        return 1;
    len = qc_hypot(q[1].x - q[0].x, q[1].y - q[0].y) +
          qc_hypot(q[2].x - q[1].x, q[2].y - q[1].y) +
          qc_hypot(q[3].x - q[2].x, q[3].y - q[2].y);
    m = ceil(len / STEP_MM);
    n = m < 1.0 ? 1 : (m < 1e7 ? (size_t)m : 10000000u);
    for (i = 0; i <= n; i++)
        if (!ok_point(k, qc_cubic_point(q, (double)i / (double)n)))
            return 0;
    return 1;
}

static int fail_outside(const kin *k, qc_vec2 p)
{
    qc_bbox b = qc_region_bbox(k->region);
    double d = qc_region_boundary_distance(k->region, p);

    return qc__fail(k->ctx, QC_ERANGE,
                    "the %s family cannot keep its path inside the region (%.1f x %.1f mm, "
                    "%.2f x %.2f in): it reaches (%.2f, %.2f) mm = (%.3f, %.3f) in, %.2f mm "
                    "(%.3f in) outside; try a larger margin or another family",
                    k->family, b.max.x - b.min.x, b.max.y - b.min.y,
                    (b.max.x - b.min.x) / 25.4, (b.max.y - b.min.y) / 25.4, p.x, p.y,
                    p.x / 25.4, p.y / 25.4, d, d / 25.4);
}

/* The point nearest p inside region, INSET_MM in from the boundary where
 * that fits (else on it); *ok 0 when none is found. */
static qc_vec2 project_inside(const kin *k, qc_vec2 p, int *ok)
{
    const qc_region *r = k->region;
    double best = HUGE_VAL, in;
    qc_vec2 q = p;
    size_t c, rs = 0, i;

    for (c = 0; c < r->nrings; c++) {
        size_t end = r->ring_end[c], j = end - 1;
        for (i = rs; i < end; j = i++) {
            qc_vec2 a = r->v[j], b = r->v[i];
            double ex = b.x - a.x, ey = b.y - a.y, l2 = ex * ex + ey * ey, t, d;
            qc_vec2 f;
            t = l2 > 0 ? ((p.x - a.x) * ex + (p.y - a.y) * ey) / l2 : 0.0;
            t = t < 0 ? 0 : (t > 1 ? 1 : t);
            f = QC__V2(a.x + t * ex, a.y + t * ey);
            d = qc_hypot(p.x - f.x, p.y - f.y);
            if (d < best)
                best = d, q = f;
        }
        rs = end;
    }
    *ok = 0;
    for (in = INSET_MM; in > 0.01 && best > 0; in *= 0.5) {
        qc_vec2 c2 = QC__V2(q.x + (q.x - p.x) / best * in, q.y + (q.y - p.y) / best * in);
        if (qc__rindex_contains(&k->ix, c2)) {
            *ok = 1;
            return c2;
        }
    }
    *ok = ok_point(k, q);
    return q;
}

/* ---- the route inside: shortest path through inset reflex corners ---- */

static int cross_proper(qc_vec2 a, qc_vec2 b, qc_vec2 c, qc_vec2 d)
{
    double o1 = qc_orient2d(a, b, c), o2 = qc_orient2d(a, b, d);
    double o3 = qc_orient2d(c, d, a), o4 = qc_orient2d(c, d, b);

    return ((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) &&
           ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0));
}

static int visible(kin *k, qc_vec2 a, qc_vec2 b)
{
    const qc_region *r = k->region;
    double lx = fmin(a.x, b.x), hx = fmax(a.x, b.x), ly = fmin(a.y, b.y), hy = fmax(a.y, b.y);
    size_t q, rs = 0, i;

    for (q = 0; q < r->nrings; q++) {
        size_t end = r->ring_end[q], p = end - 1;
        for (i = rs; i < end; p = i++) {
            qc_vec2 c = r->v[p], d = r->v[i];
            if (fmax(c.x, d.x) < lx || fmin(c.x, d.x) > hx || fmax(c.y, d.y) < ly ||
                fmin(c.y, d.y) > hy)
                continue;
            if (cross_proper(a, b, c, d))
                return 0;
        }
        rs = end;
    }
    return seg_ok(k, a, b);
}

static int build_nodes(kin *k)
{
    const qc_region *r = k->region;
    size_t q, rs = 0, i, n = 0;

    k->built = 1;
    for (i = 0; i < r->nv; i++)
        n += qc_region_corner_angle(r, i) > 181.0;
    if (n > MAX_NODES)
        n = MAX_NODES;
    k->cap = n + 2;
    k->node = qc__alloc_array(k->ctx, k->cap, sizeof *k->node);
    k->dist = qc__alloc_array(k->ctx, k->cap, sizeof *k->dist);
    k->prev = qc__alloc_array(k->ctx, k->cap, sizeof *k->prev);
    k->done = qc__alloc(k->ctx, k->cap);
    k->vis = qc__alloc_array(k->ctx, n ? n * n : 1, 1);
    if (k->node == NULL || k->dist == NULL || k->prev == NULL || k->done == NULL ||
        k->vis == NULL)
        return QC_ENOMEM;
    memset(k->vis, 0, n ? n * n : 1);
    for (q = 0; q < r->nrings; q++) {
        size_t end = r->ring_end[q];
        for (i = rs; i < end && k->nnode < n; i++) {
            qc_vec2 p = r->v[i == rs ? end - 1 : i - 1], v = r->v[i];
            qc_vec2 nx = r->v[i + 1 == end ? rs : i + 1], c;
            double l1, l2, ax, ay, bx, by, mx, my, ml;

            if (qc_region_corner_angle(r, i) <= 181.0)
                continue;
            l1 = qc_hypot(v.x - p.x, v.y - p.y);
            l2 = qc_hypot(nx.x - v.x, nx.y - v.y);
            if (!(l1 > 0) || !(l2 > 0))
                continue;
            ax = -(v.y - p.y) / l1, ay = (v.x - p.x) / l1; /* left normals: inside */
            bx = -(nx.y - v.y) / l2, by = (nx.x - v.x) / l2;
            mx = ax + bx, my = ay + by;
            ml = qc_hypot(mx, my);
            if (!(ml > 1e-12))
                continue;
            c = QC__V2(v.x + INSET_MM * mx / ml, v.y + INSET_MM * my / ml);
            if (qc__rindex_admits(&k->ix, c, 0.5 * INSET_MM))
                k->node[k->nnode++] = c;
        }
        rs = end;
    }
    return QC_OK;
}

/* Whether nodes u and v (route ends are nnode and nnode + 1) see each other. */
static int see(kin *k, size_t u, size_t v)
{
    size_t n = k->nnode;
    unsigned char *c;

    if (u >= n || v >= n)
        return visible(k, k->node[u], k->node[v]);
    c = &k->vis[u < v ? u * n + v : v * n + u];
    if (*c == 0)
        *c = visible(k, k->node[u], k->node[v]) ? 1 : 2;
    return *c == 1;
}

/* Appends the shortest route inside from a to b (b included) as lines. */
static int route(kin *k, qc_vec2 a, qc_vec2 b, qc_path *out)
{
    size_t n, s, t, i, u, hops = 0;

    if (!k->built)
        QC__TRY(build_nodes(k));
    n = k->nnode;
    s = n, t = n + 1;
    k->node[s] = a;
    k->node[t] = b;
    for (i = 0; i < n + 2; i++) {
        k->dist[i] = HUGE_VAL;
        k->done[i] = 0;
        k->prev[i] = UINT32_MAX;
    }
    k->dist[s] = 0;
    for (;;) {
        double best = HUGE_VAL;
        u = SIZE_MAX;
        for (i = 0; i < n + 2; i++)
            if (!k->done[i] && k->dist[i] < best)
                best = k->dist[i], u = i;
        if (u == SIZE_MAX)
            return fail_outside(k, QC__V2(0.5 * (a.x + b.x), 0.5 * (a.y + b.y)));
        if (u == t)
            break;
        k->done[u] = 1;
        for (i = 0; i < n + 2; i++) {
            double d;
            if (k->done[i] || i == s)
                continue;
            d = k->dist[u] + qc_hypot(k->node[i].x - k->node[u].x, k->node[i].y - k->node[u].y);
            if (d < k->dist[i] && see(k, u, i)) {
                k->dist[i] = d;
                k->prev[i] = (uint32_t)u;
            }
        }
    }
    /* the hops run t -> s backwards: count, then emit forwards */
    for (u = t; u != s; u = k->prev[u])
        hops++;
    for (i = hops; i > 0; i--) {
        size_t j;
        u = t;
        for (j = 1; j < i; j++)
            u = k->prev[u];
        QC__TRY(qc_path_line_to(k->ctx, out, k->node[u]));
    }
    return QC_OK;
}

/* ---- the pass ---- */

static int fix_cubic(kin *k, const qc_vec2 *q, qc_path *out, size_t *fixed)
{
    static const double pull[] = {0.75, 0.5, 0.25};
    qc_vec2 c[4];
    size_t i;

    if (cubic_ok(k, q))
        return qc_path_cubic_to(k->ctx, out, q[1], q[2], q[3]);
    ++*fixed;
    c[0] = q[0];
    c[3] = q[3];
    for (i = 0; i < sizeof pull / sizeof pull[0]; i++) {
        c[1] = QC__V2(q[0].x + pull[i] * (q[1].x - q[0].x), q[0].y + pull[i] * (q[1].y - q[0].y));
        c[2] = QC__V2(q[3].x + pull[i] * (q[2].x - q[3].x), q[3].y + pull[i] * (q[2].y - q[3].y));
        if (cubic_ok(k, c))
            return qc_path_cubic_to(k->ctx, out, c[1], c[2], c[3]);
    }
    if (seg_ok(k, q[0], q[3]))
        return qc_path_line_to(k->ctx, out, q[3]);
    return route(k, q[0], q[3], out);
}

/* The first fix, at command c (points from at): *out, which holds only
 * that command's fixed form, becomes in's commands before c followed by it. */
static int start_copy(qc_ctx *ctx, const qc_path *in, size_t c, size_t at, qc_path *out)
{
    qc_path head = {0};
    int rc;

    rc = QC__RESERVE_EXACT(ctx, head.cmd, head.cmd_cap, in->ncmd + out->ncmd + 16);
    if (rc == QC_OK)
        rc = QC__RESERVE_EXACT(ctx, head.pt, head.pt_cap, in->npt + out->npt + 48);
    if (rc == QC_OK) {
        memcpy(head.cmd, in->cmd, c);
        memcpy(head.pt, in->pt, at * sizeof *in->pt);
        head.ncmd = c;
        head.npt = at;
        rc = qc_path_append(ctx, &head, out, 0);
    }
    if (rc < 0) {
        qc_path_free(ctx, &head);
        return rc;
    }
    qc_path_free(ctx, out);
    *out = head;
    return QC_OK;
}

/* Writes the fixed path to *out only from the first fix on (before it,
 * *out holds at most the command in hand): a path with nothing to fix,
 * the usual case, is never copied. */
static int rewrite(kin *k, const qc_path *in, qc_path *out, size_t *fixed)
{
    qc_vec2 cur = QC__V2(0.0, 0.0);
    size_t c, at = 0;
    int copying = 0;

    for (c = 0; c < in->ncmd; c++) {
        const qc_vec2 *p = in->pt + at;
        unsigned char cmd = in->cmd[c];
        qc_vec2 end = cmd == QC_PATH_CUBIC ? p[2] : p[0];
        size_t f0 = *fixed, at0 = at;

        if (!copying)
            out->ncmd = out->npt = 0; /* the previous command came through as it was */
        at += qc_path_cmd_points(cmd);
        /* a loop's apex over the seam: pull it in */
        if (!in_safe(k, &end, 1) && !ok_point(k, end)) {
            int ok;
            qc_vec2 moved = project_inside(k, end, &ok);
            if (!ok)
                return fail_outside(k, end);
            end = moved;
            ++*fixed;
        }
        /* before the first fix, a command that comes through as it was is
         * not stored: the next one drops it, and a path with no fix is
         * never copied */
        if (cmd == QC_PATH_MOVE) {
            if (copying || *fixed > f0)
                QC__TRY(qc_path_move_to(k->ctx, out, end));
        } else if (cmd == QC_PATH_LINE) {
            if (seg_ok(k, cur, end)) {
                if (copying || *fixed > f0)
                    QC__TRY(qc_path_line_to(k->ctx, out, end));
            } else {
                ++*fixed;
                QC__TRY(route(k, cur, end, out));
            }
        } else {
            qc_vec2 q[4];
            q[0] = cur, q[1] = p[0], q[2] = p[1], q[3] = end;
            if (copying || *fixed > f0 || !cubic_ok(k, q))
                QC__TRY(fix_cubic(k, q, out, fixed));
        }
        if (!copying && *fixed > f0) {
            QC__TRY(start_copy(k->ctx, in, c, at0, out));
            copying = 1;
        }
        cur = end;
    }
    return QC_OK;
}

int qc__path_keep_inside(qc_ctx *ctx, const qc_region *region, const char *family,
                         qc_path *path, size_t *fixed)
{
    kin k;
    qc_path out = {0};
    size_t nfixed = 0, cap;
    int rc;

    memset(&k, 0, sizeof k);
    k.ctx = ctx;
    k.region = region;
    k.family = family != NULL ? family : "chosen";
    QC__TRY(qc__rindex_build(ctx, region, &k.ix));
    rc = rewrite(&k, path, &out, &nfixed);
    if (rc == QC_OK && nfixed > 0) {
        qc_path_free(ctx, path);
        *path = out;
        memset(&out, 0, sizeof out);
    }
    qc_path_free(ctx, &out);
    cap = k.cap;
    qc__free(ctx, k.node, cap * sizeof *k.node);
    qc__free(ctx, k.dist, cap * sizeof *k.dist);
    qc__free(ctx, k.prev, cap * sizeof *k.prev);
    qc__free(ctx, k.done, cap);
    qc__free(ctx, k.vis, cap > 2 ? (cap - 2) * (cap - 2) : 1);
    qc__rindex_free(ctx, &k.ix);
    if (fixed != NULL)
        *fixed = rc == QC_OK ? nfixed : 0;
    return rc;
}
