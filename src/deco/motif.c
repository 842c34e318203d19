/*
 * The built-in motif library (drawn here as cubic Béziers in a design
 * frame) and the motif set: normalisation to the unit frame (minimum
 * bounding circle at the origin, radius 1) and the convex hull.
 * Branching motifs start and end at the attachment point (0, 0) and grow
 * along +y; Wanderer primitives run from the entry leg to the exit leg.
 */
#include <math.h>
#include <string.h>

#include "deco_internal.h"

enum { M_LEAF, M_HEART, M_FLOWER, M_SPIRAL, M_LOOP, M_TEARDROP, M_STAR, M_CIRCLE,
       W_LOOP, W_HEART, W_SWIRL };

typedef struct builtin {
    char name[12];
    unsigned char kind;
    unsigned char angle; /* Wanderer: degrees between the legs */
} builtin;

static const builtin lib[] = {
    {"leaf", M_LEAF, 0},       {"heart", M_HEART, 0},     {"flower", M_FLOWER, 0},
    {"spiral", M_SPIRAL, 0},   {"loop", M_LOOP, 0},       {"teardrop", M_TEARDROP, 0},
    {"star", M_STAR, 0},       {"circle", M_CIRCLE, 0},   {"loop30", W_LOOP, 30},
    {"loop60", W_LOOP, 60},    {"loop90", W_LOOP, 90},    {"loop120", W_LOOP, 120},
    {"heart60", W_HEART, 60},  {"heart90", W_HEART, 90},  {"swirl45", W_SWIRL, 45},
    {"swirl90", W_SWIRL, 90},
};

#define NLIB (sizeof lib / sizeof lib[0])

size_t qc_motif_builtin_count(void)
{
    return NLIB;
}

const char *qc_motif_builtin_name(size_t i)
{
    return i < NLIB ? lib[i].name : NULL;
}

static qc_vec2 dir(double deg)
{
    double a = deg * (QC_PI / 180);
    return QC__V2(qc_cos(a), qc_sin(a));
}

static qc_vec2 add(qc_vec2 a, qc_vec2 b, double k)
{
    return QC__V2(a.x + k * b.x, a.y + k * b.y);
}

/* A drawing pen: the first error sticks. */
typedef struct pen {
    qc_ctx *ctx;
    qc_path *p;
    int rc;
} pen;

static void M(pen *g, double x, double y)
{
    if (g->rc == QC_OK)
        g->rc = qc_path_move_to(g->ctx, g->p, QC__V2(x, y));
}

static void L(pen *g, double x, double y)
{
    if (g->rc == QC_OK)
        g->rc = qc_path_line_to(g->ctx, g->p, QC__V2(x, y));
}

static void Cv(pen *g, qc_vec2 a, qc_vec2 b, qc_vec2 c)
{
    if (g->rc == QC_OK)
        g->rc = qc_path_cubic_to(g->ctx, g->p, a, b, c);
}

static void C(pen *g, double x1, double y1, double x2, double y2, double x, double y)
{
    Cv(g, QC__V2(x1, y1), QC__V2(x2, y2), QC__V2(x, y));
}

/* Point and derivative of a spiral around c: radius r0 + dr * t, angle a0 + da * t. */
static void spiral_at(qc_vec2 c, double r0, double dr, double a0, double da, double t,
                      qc_vec2 *p, qc_vec2 *d)
{
    double r = r0 + dr * t, a = a0 + da * t, co = qc_cos(a), si = qc_sin(a);
    *p = QC__V2(c.x + r * co, c.y + r * si);
    d->x = dr * co - r * da * si;
    d->y = dr * si + r * da * co;
}

/* The spiral for t in [0, 1] as n cubic Hermite pieces. */
static void spiral(pen *g, qc_vec2 c, double r0, double dr, double a0, double da, int n)
{
    int i;

    for (i = 0; i < n; i++) {
        double t0 = (double)i / n, t1 = (double)(i + 1) / n, h = (t1 - t0) / 3;
        qc_vec2 p0, d0, p1, d1;
        spiral_at(c, r0, dr, a0, da, t0, &p0, &d0);
        spiral_at(c, r0, dr, a0, da, t1, &p1, &d1);
        Cv(g, add(p0, d0, h), add(p1, d1, -h), p1);
    }
}

/* A stem, five petals round its head, back down. */
static void draw_flower(pen *g)
{
    int k;

    M(g, 0, 0);
    L(g, 0, 0.5);
    for (k = 0; k < 5; k++) {
        double a = -54 + 72 * k;
        qc_vec2 c = QC__V2(0, 0.5);
        Cv(g, add(c, dir(a - 28), 1.25), add(c, dir(a + 28), 1.25), c);
    }
    L(g, 0, 0);
}

/* A stem, then five points with gently bowed edges. */
static void draw_star(pen *g)
{
    qc_vec2 c = QC__V2(0, 1.1), prev = add(c, dir(-90), 0.4);
    int k;

    M(g, 0, 0);
    L(g, prev.x, prev.y);
    for (k = 1; k <= 10; k++) {
        qc_vec2 q = add(c, dir(-90 + 36 * k), (k & 1) ? 1.0 : 0.4);
        qc_vec2 m = QC__V2((prev.x + q.x) / 2, (prev.y + q.y) / 2);
        qc_vec2 a = add(prev, QC__V2(q.x - prev.x, q.y - prev.y), 1.0 / 3);
        qc_vec2 bb = add(prev, QC__V2(q.x - prev.x, q.y - prev.y), 2.0 / 3);
        a = add(a, QC__V2(c.x - m.x, c.y - m.y), 0.15);
        bb = add(bb, QC__V2(c.x - m.x, c.y - m.y), 0.15);
        Cv(g, a, bb, q);
        prev = q;
    }
    L(g, 0, 0);
}

/* In from the left leg (ind), curl inward, swing out to the right leg (outd). */
static void draw_swirl(pen *g, qc_vec2 ind, qc_vec2 outd)
{
    qc_vec2 s = QC__V2(-0.25, -0.6), t = QC__V2(0.25, -0.6), c = QC__V2(0, 0.3);
    qc_vec2 p0, d0, p1, d1;

    spiral_at(c, 0.8, -0.6, QC_PI, -1.75 * QC_PI, 0, &p0, &d0);
    M(g, s.x, s.y);
    Cv(g, add(s, ind, -0.5), add(p0, d0, 0.15), p0);
    spiral(g, c, 0.8, -0.6, QC_PI, -1.75 * QC_PI, 6);
    spiral_at(c, 0.8, -0.6, QC_PI, -1.75 * QC_PI, 1, &p1, &d1);
    Cv(g, add(p1, d1, 0.3), add(t, outd, -0.8), t);
}

/* Draws motif b; two-legged primitives also get their leg directions. */
static void draw(pen *g, const builtin *b, qc_vec2 *in_dir, qc_vec2 *out_dir)
{
    double h = b->angle / 2.0;
    qc_vec2 ind = dir(-90 - h), outd = dir(-90 + h);

    *in_dir = ind;
    *out_dir = outd;
    switch (b->kind) {
    case M_LEAF:
        M(g, 0, 0);
        C(g, 0.3, 0.3, 0.55, 0.8, 0, 1.45);
        C(g, -0.55, 0.8, -0.3, 0.3, 0, 0);
        break;
    case M_HEART: /* on a short stem: its wide base stays off the vine */
        M(g, 0, 0);
        L(g, 0, 0.4);
        C(g, 0.5, 0.75, 0.85, 1.15, 0.55, 1.5);
        C(g, 0.35, 1.7, 0.05, 1.6, 0, 1.35);
        C(g, -0.05, 1.6, -0.35, 1.7, -0.55, 1.5);
        C(g, -0.85, 1.15, -0.5, 0.75, 0, 0.4);
        L(g, 0, 0);
        break;
    case M_FLOWER:
        draw_flower(g);
        break;
    case M_SPIRAL: /* in along one arm, out along the other, ends where it began */
        M(g, 0, 0);
        spiral(g, QC__V2(0, 1), 1, -0.8, -QC_PI / 2, 3 * QC_PI, 8);
        L(g, 0.2 * qc_cos(QC_PI / 2), 1 + 0.5);
        spiral(g, QC__V2(0, 1), 0.5, 0.5, QC_PI / 2, -3 * QC_PI, 8);
        break;
    case M_LOOP:
        M(g, 0, 0); /* up, round the top, crossing back down to the start */
        C(g, -0.15, 0.35, 0.55, 0.75, 0.5, 1.2);
        C(g, 0.45, 1.65, -0.5, 1.65, -0.5, 1.15);
        C(g, -0.5, 0.7, 0.3, 0.4, 0, 0);
        break;
    case M_TEARDROP:
        M(g, 0, 0);
        C(g, 0.6, 0.5, 0.65, 1.35, 0, 1.35);
        C(g, -0.65, 1.35, -0.6, 0.5, 0, 0);
        break;
    case M_STAR:
        draw_star(g);
        break;
    case M_CIRCLE: { /* a short stem and a circle of radius 1 */
        const double K = 0.5522847498;
        M(g, 0, 0);
        L(g, 0, 0.5);
        C(g, K, 0.5, 1, 1.5 - K, 1, 1.5);
        C(g, 1, 1.5 + K, K, 2.5, 0, 2.5);
        C(g, -K, 2.5, -1, 1.5 + K, -1, 1.5);
        C(g, -1, 1.5 - K, -K, 0.5, 0, 0.5);
        L(g, 0, 0);
        break;
    }
    case W_LOOP: { /* in from the lower left, over the top, crossing, out lower right */
        qc_vec2 s = QC__V2(-0.3, -0.55), t = QC__V2(0.3, -0.55), top = QC__V2(0, 1);
        M(g, s.x, s.y);
        Cv(g, add(s, ind, -1.3), QC__V2(0.9, 1), top);
        Cv(g, QC__V2(-0.9, 1), add(t, outd, -1.3), t);
        break;
    }
    case W_HEART: { /* the point at the bottom, where both legs meet */
        qc_vec2 bt = QC__V2(0, -0.8);
        M(g, bt.x, bt.y);
        Cv(g, add(bt, ind, -0.7), QC__V2(0.8, 0.8), QC__V2(0.45, 0.8));
        C(g, 0.2, 0.8, 0.05, 0.65, 0, 0.45);
        C(g, -0.05, 0.65, -0.2, 0.8, -0.45, 0.8);
        Cv(g, QC__V2(-0.8, 0.8), add(bt, outd, -0.7), bt);
        break;
    }
    case W_SWIRL:
        draw_swirl(g, ind, outd);
        break;
    default:
        break;
    }
}

void qc_motif_set_free(qc_ctx *ctx, qc_motif_set *set)
{
    size_t i;

    if (set == NULL)
        return;
    for (i = 0; i < set->n; i++) {
        qc_path_free(ctx, &set->m[i].path);
        qc__free(ctx, set->m[i].hull, set->m[i].nhull * sizeof *set->m[i].hull);
    }
    qc__free(ctx, set->m, set->cap * sizeof *set->m);
    memset(set, 0, sizeof *set);
}

/* Flattens path into pts (cleared first) at a tolerance fine enough for a unit frame. */
static int flat(qc_ctx *ctx, const qc_path *path, qc_points *pts)
{
    pts->n = 0;
    return qc_curve_flatten(ctx, path, 1e-4, pts, NULL);
}

#define HULL_TOL 0.04

static void map_path(qc_path *p, double k, qc_vec2 c)
{
    size_t i;

    for (i = 0; i < p->npt; i++) {
        p->pt[i].x = (p->pt[i].x - c.x) * k;
        p->pt[i].y = (p->pt[i].y - c.y) * k;
    }
}

/*
 * Takes ownership of *path (a design-frame drawing): normalises it, builds
 * its hull and appends it to out as name. Frees path on failure.
 */
QC__HIDDEN int qc__motif_add(qc_ctx *ctx, qc_path *path, const char *name, int legs,
                             qc_vec2 in_dir, qc_vec2 out_dir, qc_motif_set *out);

int qc__motif_add(qc_ctx *ctx, qc_path *path, const char *name, int legs,
                  qc_vec2 in_dir, qc_vec2 out_dir, qc_motif_set *out)
{
    qc_points pts = {0};
    qc_vec2 *scratch = NULL, *hull = NULL, c;
    size_t nscr = 0, nh = 0, it, hull_cap = 0;
    double r;
    int rc;
    qc_motif *m;

    rc = flat(ctx, path, &pts);
    if (rc == QC_OK && pts.n < 2)
        rc = qc__fail(ctx, QC_EDEGENERATE, "motif %s has no extent", name);
    /* Flattening depends slightly on scale: repeat until the circle settles. */
    for (it = 0; rc == QC_OK && it < 4; it++) {
        if (nscr < 2 * pts.n) {
            qc__free(ctx, scratch, nscr * sizeof *scratch);
            nscr = 2 * pts.n;
            scratch = qc__alloc_array(ctx, nscr, sizeof *scratch);
            if (scratch == NULL) {
                nscr = 0;
                rc = QC_ENOMEM;
                break;
            }
        }
        qc__min_circle(pts.v, pts.n, scratch, &c, &r);
        if (!(r > 1e-12)) {
            rc = qc__fail(ctx, QC_EDEGENERATE, "motif %s has no extent", name);
            break;
        }
        if (fabs(r - 1) < 1e-13 && fabs(c.x) < 1e-13 && fabs(c.y) < 1e-13)
            break;
        map_path(path, 1 / r, c);
        rc = flat(ctx, path, &pts);
    }
    if (rc == QC_OK && nscr < 2 * pts.n)
        rc = qc__fail(ctx, QC_ENOMEM, "motif %s scratch", name);
    if (rc == QC_OK) {
        hull = qc__alloc_array(ctx, 2 * pts.n, sizeof *hull);
        if (hull == NULL)
            rc = QC_ENOMEM;
        else
            hull_cap = 2 * pts.n;
    }
    if (rc == QC_OK) { /* few vertices: the coarse polyline's hull, pushed out by its tolerance */
        pts.n = 0;
        rc = qc_curve_flatten(ctx, path, HULL_TOL, &pts, NULL);
    }
    if (rc == QC_OK) {
        qc_vec2 *h2;
        nh = qc__convex_hull(pts.v, pts.n, hull, scratch);
        qc__hull_outset(hull, nh, scratch, HULL_TOL * (1 + 1e-6));
        h2 = qc__realloc(ctx, hull, hull_cap * sizeof *hull, nh * sizeof *hull);
        if (h2 == NULL) { /* keep the larger block */
            rc = qc__fail(ctx, QC_ENOMEM, "motif %s hull", name);
        } else {
            hull = h2;
            hull_cap = nh;
        }
    }
    if (rc == QC_OK)
        rc = QC__RESERVE(ctx, out->m, out->cap, out->n + 1);
    if (rc != QC_OK) {
        qc__free(ctx, hull, hull_cap * sizeof *hull);
        goto done;
    }
    m = &out->m[out->n++];
    memset(m, 0, sizeof *m);
    strncpy(m->name, name, sizeof m->name - 1);
    m->path = *path;
    memset(path, 0, sizeof *path);
    m->hull = hull;
    m->nhull = nh;
    m->entry = m->path.pt[0];
    m->exit = qc_path_last(&m->path);
    m->legs = legs;
    if (legs) {
        m->entry_dir = in_dir;
        m->exit_dir = out_dir;
    }
done:
    qc_path_free(ctx, path);
    qc__free(ctx, scratch, nscr * sizeof *scratch);
    qc_points_free(ctx, &pts);
    return rc;
}

/* Frees the motifs of set from index n on: set back to its first n. */
static void set_truncate(qc_ctx *ctx, qc_motif_set *set, size_t n)
{
    for (; set->n > n; set->n--) {
        qc_motif *m = &set->m[set->n - 1];
        qc_path_free(ctx, &m->path);
        qc__free(ctx, m->hull, m->nhull * sizeof *m->hull);
    }
}

static int add_builtins(qc_ctx *ctx, const char *names, qc_motif_set *out);

int qc_motif_builtin(qc_ctx *ctx, const char *names, qc_motif_set *out)
{
    size_t n0;
    int rc;

    if (names == NULL || out == NULL)
        return qc__fail(ctx, QC_EINVAL, "motif names missing");
    n0 = out->n;
    rc = add_builtins(ctx, names, out);
    if (rc < 0)
        set_truncate(ctx, out, n0); /* as on entry (core.h) */
    return rc;
}

/* Appends each named built-in motif to out. */
static int add_builtins(qc_ctx *ctx, const char *names, qc_motif_set *out)
{
    const char *s = names;

    while (*s != '\0') {
        const char *e = strchr(s, ',');
        size_t len = e != NULL ? (size_t)(e - s) : strlen(s), i;
        if (len > 0) {
            for (i = 0; i < NLIB; i++)
                if (strlen(lib[i].name) == len && memcmp(lib[i].name, s, len) == 0)
                    break;
            if (i == NLIB)
                return qc__fail(ctx, QC_EINVAL, "unknown motif '%.*s'", (int)(len > 40 ? 40 : len), s);
            {
                qc_path p = {0};
                qc_vec2 ind, outd;
                pen g;
                g.ctx = ctx;
                g.p = &p;
                g.rc = QC_OK;
                draw(&g, &lib[i], &ind, &outd);
                if (g.rc != QC_OK) {
                    qc_path_free(ctx, &p);
                    return g.rc;
                }
                QC__TRY(qc__motif_add(ctx, &p, lib[i].name, lib[i].kind >= W_LOOP ? 2 : 0,
                                      ind, outd, out));
            }
        }
        s += len;
        if (*s == ',')
            s++;
    }
    return QC_OK;
}

static qc_vec2 unit_to(qc_vec2 from, qc_vec2 to)
{
    qc_vec2 d;
    double len = qc_hypot(to.x - from.x, to.y - from.y);
    d.x = len > 0 ? (to.x - from.x) / len : 0;
    d.y = len > 0 ? (to.y - from.y) / len : 0;
    return d;
}

int qc__motif_from_path(qc_ctx *ctx, qc_path *src, const char *name, qc_motif_set *out)
{
    qc_path p = *src, body = {0};
    size_t i, k;
    qc_vec2 first, last, ind = {0, 0}, outd = {0, 0};
    int rc, legs = 0;

    memset(src, 0, sizeof *src);
    /* Later MOVEs become LINEs: a motif is sewn in one go. */
    for (i = 1; i < p.ncmd; i++)
        if (p.cmd[i] == QC_PATH_MOVE)
            p.cmd[i] = QC_PATH_LINE;
    if (p.ncmd < 2) {
        qc_path_free(ctx, &p);
        return qc__fail(ctx, QC_EDEGENERATE, "motif %s has no segment", name);
    }
    first = p.pt[0];
    last = qc_path_last(&p);
    if (qc_hypot(last.x - first.x, last.y - first.y) > 1e-6 * (1 + fabs(first.x) + fabs(first.y))
        && p.ncmd >= 4) {
        /* Two legs: the first and last segments give directions, not stitches. */
        legs = 2;
        {
            /* end of the first segment, start of the last */
            qc_vec2 e_in = p.pt[qc_path_cmd_points(p.cmd[1])];
            size_t klast = qc_path_cmd_points(p.cmd[p.ncmd - 1]);
            qc_vec2 e_out = p.pt[p.npt - klast - 1];
            ind = unit_to(e_in, first);
            outd = unit_to(e_out, last);
            rc = qc_path_move_to(ctx, &body, e_in);
            k = 1 + qc_path_cmd_points(p.cmd[1]);
            for (i = 2; rc == QC_OK && i + 1 < p.ncmd; i++) {
                if (p.cmd[i] == QC_PATH_CUBIC)
                    rc = qc_path_cubic_to(ctx, &body, p.pt[k], p.pt[k + 1], p.pt[k + 2]);
                else
                    rc = qc_path_line_to(ctx, &body, p.pt[k]);
                k += qc_path_cmd_points(p.cmd[i]);
            }
        }
        qc_path_free(ctx, &p);
        if (rc != QC_OK) {
            qc_path_free(ctx, &body);
            return rc;
        }
        return qc__motif_add(ctx, &body, name, legs, ind, outd, out);
    }
    if (qc_hypot(last.x - first.x, last.y - first.y) > 0) { /* too short for legs: close it */
        rc = qc_path_line_to(ctx, &p, first);
        if (rc != QC_OK) {
            qc_path_free(ctx, &p);
            return rc;
        }
    }
    return qc__motif_add(ctx, &p, name, 0, ind, outd, out);
}
