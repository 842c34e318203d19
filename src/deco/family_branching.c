/*
 * Branching (paper §5.1): motifs at the branch tips along the tangent, then
 * along the vine on alternating sides at angle alpha, each accepted only if
 * its hull keeps clear of the other motifs, the vine and the boundary
 * (resolution: shrink to s/2, rotate towards the tip up to 60 degrees, flip
 * side, else skip). Each motif is sewn as a detour from its attachment
 * point and back, so the result is one piece. With a tile mode the region
 * is a tile: the vine runs from its entry port to its exit port, collision
 * tests wrap across its edges (family_branching_tile.c), and the tile is laid out
 * repeat_cols x repeat_rows.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "family_branching_tile.h"

enum { K_BOUND = 0, K_VINE = 1, K_MOTIF = 2 };

/* Unit-frame radius round the attachment left out of the vine test: the
 * motif necessarily meets the vine there. */
#define TRIM 0.4
/* The vine is tested as chords within this fraction of s of the curve. */
#define VINE_TOL 0.02
/* Body hulls: a coarse polyline's hull pushed out by its tolerance (unit frame). */
#define BODY_TOL 0.04

typedef struct spot {
    uint32_t seg;    /* vine cubic */
    double t;        /* parameter in it */
    uint32_t motif;  /* motif index */
    uint32_t order;  /* placement order: ties */
    qc__xf xf;
} spot;

typedef struct shape { /* a motif's unit-frame collision geometry */
    qc_vec2 *body;     /* hull without the part near the attachment */
    size_t nbody, cap;
    qc_vec2 axis;      /* from the attachment towards the centre */
} shape;

static qc_vec2 unit(qc_vec2 d)
{
    double len = qc_hypot(d.x, d.y);
    qc_vec2 r = {0, 0};
    if (len > 0) {
        r.x = d.x / len;
        r.y = d.y / len;
    }
    return r;
}

/* The map putting the unit motif's entry at a, its axis along dir, scaled k. */
static qc__xf place(const qc_motif *m, const shape *sh, qc_vec2 a, qc_vec2 dir, double k)
{
    qc__xf f;
    double co = dir.x * sh->axis.x + dir.y * sh->axis.y;
    double si = sh->axis.x * dir.y - sh->axis.y * dir.x;
    f.a = k * co;
    f.b = -k * si;
    f.c = k * si;
    f.d = k * co;
    f.tx = a.x - (f.a * m->entry.x + f.b * m->entry.y);
    f.ty = a.y - (f.c * m->entry.x + f.d * m->entry.y);
    return f;
}

typedef struct run {
    qc_ctx *ctx;
    const qc_region *region;
    const qc_motif_set *set;
    qc__cgrid grid;
    shape *sh;
    uint32_t *choice; /* motifs eligible */
    size_t nchoice;
    qc_vec2 *buf;     /* transformed hull */
    size_t nbuf;
    spot *spots;
    size_t nspots, spots_cap;
    qc_rng rng;
    qc__placement *pl;
    qc__btile *tile;  /* a tile: items are added to the grid wrapped too */
} run;

static int grid_add(run *r, const qc_vec2 *poly, size_t n, unsigned kind, uint32_t id)
{
    if (r->tile != NULL)
        return qc__btile_grid_add(r->ctx, r->tile, &r->grid, poly, n, kind, id);
    return qc__cgrid_add(r->ctx, &r->grid, poly, n, kind, id);
}

/* Tries motif m at a along dir scaled k: places it (1) or not (0). */
static int try_place(run *r, uint32_t mi, qc_vec2 a, qc_vec2 dir, double k, uint32_t seg,
                     double t, int *rc)
{
    const qc_motif *m = &r->set->m[mi];
    const shape *sh = &r->sh[mi];
    qc__xf f = place(m, sh, a, dir, k);
    size_t i, nf = m->nhull, nb = sh->nbody;
    qc_vec2 *full = r->buf, *body = r->buf + nf;

    for (i = 0; i < nf; i++)
        full[i] = qc__xf_apply(&f, m->hull[i]);
    if (qc__cgrid_hit(&r->grid, full, nf, 1u << K_BOUND | 1u << K_MOTIF, NULL, NULL))
        return 0;
    if (!qc_region_contains(r->region, full[0]))
        return 0;
    for (i = 0; i < nb; i++)
        body[i] = qc__xf_apply(&f, sh->body[i]);
    if (qc__cgrid_hit(&r->grid, body, nb, 1u << K_VINE, NULL, NULL))
        return 0;
    *rc = QC__RESERVE(r->ctx, r->spots, r->spots_cap, r->nspots + 1);
    if (*rc == QC_OK)
        *rc = grid_add(r, full, nf, K_MOTIF, (uint32_t)r->nspots);
    if (*rc == QC_OK && r->pl != NULL) {
        for (i = 0; i < nf && *rc == QC_OK; i++)
            *rc = qc_points_push(r->ctx, &r->pl->full, full[i]);
        if (*rc == QC_OK)
            *rc = qc_order_push(r->ctx, &r->pl->full_end, (uint32_t)r->pl->full.n);
        for (i = 0; i < nb && *rc == QC_OK; i++)
            *rc = qc_points_push(r->ctx, &r->pl->body, body[i]);
        if (*rc == QC_OK)
            *rc = qc_order_push(r->ctx, &r->pl->body_end, (uint32_t)r->pl->body.n);
        if (*rc == QC_OK)
            *rc = qc_points_push(r->ctx, &r->pl->attach, a);
    }
    if (*rc != QC_OK)
        return 0;
    r->spots[r->nspots].seg = seg;
    r->spots[r->nspots].t = t;
    r->spots[r->nspots].motif = mi;
    r->spots[r->nspots].order = (uint32_t)r->nspots;
    r->spots[r->nspots].xf = f;
    r->nspots++;
    return 1;
}

static qc_vec2 rot(qc_vec2 d, double deg)
{
    double a = deg * (QC_PI / 180), c = qc_cos(a), s = qc_sin(a);
    qc_vec2 r;
    r.x = c * d.x - s * d.y;
    r.y = s * d.x + c * d.y;
    return r;
}

/* One attempt sequence for motif mi; 1 placed, 0 not, or an error. */
static int resolve(run *r, uint32_t mi, qc_vec2 a, qc_vec2 tangent, int side, double alpha,
                   double s, uint32_t seg, double t, qc_stats *st)
{
    static const double scales[] = {1, 0.75, 0.5};
    static const double tip_turn[] = {0, 15, -15, 30, -30};
    size_t si, ai, nang = side == 0 ? 5 : 4;
    int rc = QC_OK, sd, flips = side != 0 ? 2 : 1;

    for (ai = 0; ai < nang; ai++) {
        double ang = side == 0 ? tip_turn[ai] : alpha + 15.0 * (double)ai;
        if (side != 0 && ai > 0 && ang > 60 + 1e-9) {
            if (alpha >= 60)
                break;
            ang = 60;
        }
        for (si = 0; si < 3; si++) {
            for (sd = 0; sd < flips; sd++) {
                int sgn = sd == 0 ? side : -side;
                /* tips turn about the tangent; elsewhere alpha from the normal, leaning forward */
                qc_vec2 dir = side == 0 ? rot(tangent, ang) : rot(tangent, sgn * (90 - ang));
                if (try_place(r, mi, a, dir, s / 2 * scales[si], seg, t, &rc)) {
                    st->motifs_placed++;
                    st->motifs_shrunk += si > 0;
                    st->motifs_rotated += ai > 0;
                    st->motifs_flipped += sd > 0;
                    return 1;
                }
                if (rc != QC_OK)
                    return rc;
            }
        }
        if (side != 0 && ang >= 60)
            break;
    }
    return 0;
}

/*
 * One candidate: the randomly chosen motif, then the set's others, each
 * with the cheapest change first (the other side at full size keeps the
 * look), then smaller, then turned towards the tip. tangent: the vine's
 * forward direction; side: +1 left, -1 right, 0 a tip. QC_OK or an error.
 */
static int candidate(run *r, qc_vec2 a, qc_vec2 tangent, int side, double alpha, double s,
                     uint32_t seg, double t, qc_stats *st)
{
    size_t first = r->nchoice > 1 ? (size_t)qc_rng_below(&r->rng, r->nchoice) : 0, c;

    for (c = 0; c < r->nchoice; c++) {
        int got = resolve(r, r->choice[(first + c) % r->nchoice], a, tangent, side, alpha, s,
                          seg, t, st);
        if (got != 0)
            return got < 0 ? got : QC_OK;
    }
    st->motifs_skipped++;
    return QC_OK;
}

static int cmp_spot(const void *pa, const void *pb)
{
    const spot *a = pa, *b = pb;
    if (a->seg != b->seg)
        return a->seg < b->seg ? -1 : 1;
    if (a->t != b->t)
        return a->t < b->t ? -1 : 1;
    return a->order < b->order ? -1 : a->order > b->order;
}

/* Unit-frame body hulls (hull of the points away from the attachment). */
static int make_shapes(run *r)
{
    size_t i, j;
    qc_points pts = {0};
    qc_vec2 *scr = NULL;
    size_t nscr = 0;
    int rc = QC_OK;

    r->sh = qc__alloc_array(r->ctx, r->set->n, sizeof *r->sh);
    if (r->sh == NULL)
        return QC_ENOMEM;
    memset(r->sh, 0, r->set->n * sizeof *r->sh);
    for (i = 0; i < r->set->n && rc == QC_OK; i++) {
        const qc_motif *m = &r->set->m[i];
        size_t keep = 0;
        pts.n = 0;
        rc = qc_curve_flatten(r->ctx, &m->path, BODY_TOL, &pts, NULL);
        for (j = 0; rc == QC_OK && j < pts.n; j++)
            if (qc_hypot(pts.v[j].x - m->entry.x, pts.v[j].y - m->entry.y) > TRIM)
                pts.v[keep++] = pts.v[j];
        if (rc == QC_OK && keep < 3) { /* too small to trim: the whole hull */
            keep = m->nhull;
            pts.n = 0;
            for (j = 0; j < keep && rc == QC_OK; j++)
                rc = qc_points_push(r->ctx, &pts, m->hull[j]);
        }
        if (rc == QC_OK && nscr < 2 * keep) {
            qc__free(r->ctx, scr, nscr * sizeof *scr);
            nscr = 2 * keep;
            scr = qc__alloc_array(r->ctx, nscr, sizeof *scr);
            if (scr == NULL) {
                nscr = 0;
                rc = QC_ENOMEM;
            }
        }
        if (rc == QC_OK) {
            r->sh[i].body = qc__alloc_array(r->ctx, 2 * keep, sizeof *r->sh[i].body);
            if (r->sh[i].body == NULL)
                rc = QC_ENOMEM;
            else
                r->sh[i].cap = 2 * keep;
        }
        if (rc == QC_OK) {
            r->sh[i].nbody = qc__convex_hull(pts.v, keep, r->sh[i].body, scr);
            qc__hull_outset(r->sh[i].body, r->sh[i].nbody, scr, BODY_TOL);
            r->sh[i].axis = unit((qc_vec2){-m->entry.x, -m->entry.y});
            if (r->sh[i].axis.x == 0 && r->sh[i].axis.y == 0)
                r->sh[i].axis.y = 1;
            if (r->nbuf < m->nhull + 2 * keep)
                r->nbuf = m->nhull + 2 * keep;
        }
    }
    qc__free(r->ctx, scr, nscr * sizeof *scr);
    qc_points_free(r->ctx, &pts);
    return rc;
}

static void free_shapes(run *r)
{
    size_t i;

    if (r->sh == NULL)
        return;
    for (i = 0; i < r->set->n; i++)
        qc__free(r->ctx, r->sh[i].body, r->sh[i].cap * sizeof *r->sh[i].body);
    qc__free(r->ctx, r->sh, r->set->n * sizeof *r->sh);
    r->sh = NULL;
}

void qc__placement_free(qc_ctx *ctx, qc__placement *pl)
{
    if (pl == NULL)
        return;
    qc_points_free(ctx, &pl->full);
    qc_points_free(ctx, &pl->body);
    qc_order_free(ctx, &pl->full_end);
    qc_order_free(ctx, &pl->body_end);
    qc_points_free(ctx, &pl->attach);
    qc_points_free(ctx, &pl->vine);
}

int qc_deco_branching(qc_ctx *ctx, const qc_region *region, const qc_params *params,
                      const qc_skeleton *skel, const qc_motif_set *motifs, qc_path *out,
                      qc_stats *stats)
{
    return qc__branching_run(ctx, region, params, skel, motifs, out, stats, NULL);
}

int qc__branching_run(qc_ctx *ctx, const qc_region *region, const qc_params *params,
                      const qc_skeleton *skel, const qc_motif_set *motifs, qc_path *out,
                      qc_stats *stats, qc__placement *pl)
{
    run r;
    qc_motif_set def = {0};
    qc_path vine = {0}, one = {0}, *dst = out;
    qc__btile tile;
    qc_skeleton tsk;
    qc_points pts = {0};
    qc_stats dummy;
    double s = params->size, gap = params->gap, alpha = params->angle, step, acc = 0;
    size_t i, j, nseg;
    unsigned char *seen = NULL;
    int rc = QC_OK, side = 1, walk;
    int tiled = params->tile == QC_TILE_EDGE_TO_EDGE || params->tile == QC_TILE_ALL_OVER;

    memset(&r, 0, sizeof r);
    memset(&tile, 0, sizeof tile);
    if (stats == NULL)
        stats = memset(&dummy, 0, sizeof dummy);
    if (skel == NULL || skel->norder == 0)
        return qc__fail(ctx, QC_EEMPTY, "branching needs at least one point");
    if (!(s > 0))
        return qc__fail(ctx, QC_ERANGE, "motif size %g mm must be > 0", s);
    if (!(gap >= 0))
        gap = 0;
    if (tiled) { /* the ports join the tree; the walk runs from one to the other */
        rc = qc__btile_make(ctx, region, skel, params->tile == QC_TILE_ALL_OVER, &tile, &tsk);
        if (rc < 0)
            return rc;
        skel = &tsk;
        r.tile = &tile;
        dst = &one;
    }
    if (motifs == NULL || motifs->n == 0) {
        rc = qc_motif_builtin(ctx, "leaf", &def);
        if (rc != QC_OK) {
            qc_motif_set_free(ctx, &def);
            qc__btile_free(ctx, &tile);
            return rc;
        }
        motifs = &def;
    }
    r.ctx = ctx;
    r.region = region;
    r.set = motifs;
    r.pl = pl;
    qc_rng_seed(&r.rng, params->seed ^ 0x6272616e6368ull);
    r.choice = qc__alloc_array(ctx, motifs->n, sizeof *r.choice);
    if (r.choice == NULL) {
        rc = QC_ENOMEM;
        goto out_free;
    }
    for (i = 0; i < motifs->n; i++)
        if (motifs->m[i].legs == 0)
            r.choice[r.nchoice++] = (uint32_t)i;
    if (r.nchoice == 0)
        for (i = 0; i < motifs->n; i++)
            r.choice[r.nchoice++] = (uint32_t)i;

    /* The vine: one cubic per walk step. */
    for (i = 0; i < skel->norder && rc == QC_OK; i++)
        rc = qc_points_push(ctx, &pts, skel->p[skel->order[i]]);
    if (rc == QC_OK) /* room for the whole vine at once */
        rc = QC__RESERVE(ctx, vine.cmd, vine.cmd_cap, pts.n + 1);
    if (rc == QC_OK)
        rc = QC__RESERVE(ctx, vine.pt, vine.pt_cap, 3 * pts.n + 1);
    if (rc == QC_OK)
        rc = qc_curve_catmull_rom(ctx, pts.v, pts.n, skel->edges == NULL, &vine);
    if (rc != QC_OK)
        goto out_free;
    if (tiled)
        qc__btile_flat_ports(&tile, &vine);
    nseg = vine.ncmd > 0 ? vine.ncmd - 1 : 0;
    for (i = 1; i < vine.ncmd; i++)
        if (vine.cmd[i] != QC_PATH_CUBIC) {
            rc = qc__fail(ctx, QC_EINVAL, "vine command %zu is not a cubic", i);
            goto out_free;
        }

    rc = make_shapes(&r);
    if (rc == QC_OK) {
        r.buf = qc__alloc_array(ctx, r.nbuf, sizeof *r.buf);
        if (r.buf == NULL)
            rc = QC_ENOMEM;
    }
    if (rc == QC_OK) {
        qc_bbox b = qc_region_bbox(region), vb;
        vb.min = vb.max = vine.pt[0]; /* control points bound the curve */
        for (i = 1; i < vine.npt; i++) {
            vb.min.x = fmin(vb.min.x, vine.pt[i].x);
            vb.min.y = fmin(vb.min.y, vine.pt[i].y);
            vb.max.x = fmax(vb.max.x, vine.pt[i].x);
            vb.max.y = fmax(vb.max.y, vine.pt[i].y);
        }
        b.min.x = fmin(b.min.x, vb.min.x) - s;
        b.min.y = fmin(b.min.y, vb.min.y) - s;
        b.max.x = fmax(b.max.x, vb.max.x) + s;
        b.max.y = fmax(b.max.y, vb.max.y) + s;
        rc = qc__cgrid_init(ctx, &r.grid, b, s, 16 * skel->norder + 4096);
        if (rc == QC_OK)
            rc = QC__RESERVE(ctx, r.spots, r.spots_cap, nseg + 16);
        if (rc == QC_OK) /* a guess at the vine's chords and the motifs: fewer regrowths */
            rc = qc__cgrid_reserve(ctx, &r.grid, 4 * nseg + region->nv + 64,
                                   16 * nseg + 2 * region->nv + 1024, 12 * nseg + 4 * region->nv + 256);
    }
    /* The boundary, every ring. */
    if (rc == QC_OK)
        rc = qc__cgrid_add_region(ctx, &r.grid, region, K_BOUND);
    /* The vine as short chords (within a few percent of s of the curve). */
    for (j = 0; rc == QC_OK && j < nseg; j++) {
        const qc_vec2 *q = vine.pt + 3 * j; /* MOVE point + 3 per cubic */
        /* chords within about VINE_TOL * s of the curve: n^2 >= dev / tol */
        double ax = q[0].x - 2 * q[1].x + q[2].x, ay = q[0].y - 2 * q[1].y + q[2].y;
        double bx = q[1].x - 2 * q[2].x + q[3].x, by = q[1].y - 2 * q[2].y + q[3].y;
        double dev = 0.75 * sqrt(fmax(ax * ax + ay * ay, bx * bx + by * by));
        size_t k, nk = (size_t)ceil(sqrt(dev / (VINE_TOL * s)));
        qc_vec2 prev = q[0];
        if (nk < 1)
            nk = 1;
        if (nk > 256)
            nk = 256;
        for (k = 1; k <= nk && rc == QC_OK; k++) {
            qc_vec2 e[2];
            e[0] = prev;
            e[1] = qc_cubic_point(q, (double)k / nk);
            rc = grid_add(&r, e, 2, K_VINE, (uint32_t)j);
            if (rc == QC_OK && pl != NULL)
                rc = qc_points_push(ctx, &pl->vine, prev);
            prev = e[1];
        }
        if (rc == QC_OK && pl != NULL && j + 1 == nseg)
            rc = qc_points_push(ctx, &pl->vine, prev);
    }

    /* Step 3: the tips, in walk (depth-first) order. */
    if (rc == QC_OK && pts.n == 1) {
        qc_vec2 up = {0, 1};
        rc = candidate(&r, pts.v[0], up, 0, alpha, s, 0, 0, stats);
    }
    if (rc == QC_OK && skel->edges != NULL && nseg + 1 == pts.n && pts.n >= 3) {
        for (i = 0; i + 1 < pts.n && rc == QC_OK; i++) {
            /* the root is a tip when the walk leaves and returns by one edge;
             * a tile's walk starts at a port, never a tip */
            int tip = i == 0 ? !tiled && skel->order[1] == skel->order[pts.n - 2] &&
                                   (pts.n == 3 || skel->order[0] == skel->order[pts.n - 1])
                             : skel->order[i - 1] == skel->order[i + 1];
            qc_vec2 d;
            if (!tip)
                continue;
            d = unit((qc_vec2){pts.v[i].x - pts.v[i ? i - 1 : 1].x,
                               pts.v[i].y - pts.v[i ? i - 1 : 1].y});
            rc = candidate(&r, pts.v[i], d, 0, alpha, s, (uint32_t)i, 0, stats);
        }
    }
    /* Step 4: along each branch once (the walk's first pass down it), every
     * step, alternating sides. */
    step = s / 2 + gap;
    acc = step / 2;
    walk = skel->edges != NULL && nseg + 1 == pts.n && skel->n > 0;
    if (rc == QC_OK && walk) {
        seen = qc__alloc(ctx, skel->n);
        if (seen == NULL)
            rc = QC_ENOMEM;
        else
            memset(seen, 0, skel->n);
    }
    if (rc == QC_OK && walk)
        seen[skel->order[0]] = 1;
    for (j = 0; rc == QC_OK && j < nseg; j++) {
        const qc_vec2 *q = vine.pt + 3 * j;
        size_t k, nk = 16;
        qc_vec2 prev = q[0];
        if (walk) {
            uint32_t to = skel->order[j + 1];
            int down = !seen[to];
            seen[to] = 1;
            if (!down) {
                acc = step / 2;
                continue;
            }
        }
        for (k = 1; k <= nk && rc == QC_OK; k++) {
            double t = (double)k / nk;
            qc_vec2 p = qc_cubic_point(q, t);
            double dl = qc_hypot(p.x - prev.x, p.y - prev.y);
            if (acc + dl >= step && k < nk) {
                qc_vec2 tg = unit(qc_cubic_tangent(q, t));
                if (tg.x != 0 || tg.y != 0)
                    rc = candidate(&r, p, tg, side, alpha, s, (uint32_t)j, t, stats);
                side = -side;
                acc = 0;
            } else {
                acc += dl;
            }
            prev = p;
        }
    }

    /* Assemble: the vine, split at each attachment for the detour. */
    if (rc == QC_OK && r.nspots > 1)
        qsort(r.spots, r.nspots, sizeof *r.spots, cmp_spot);
    if (rc == QC_OK) { /* room for the result at once: vine, splits and motifs */
        size_t nc = dst->ncmd + 1 + nseg + 3 * r.nspots, np = dst->npt + 1 + 3 * (nseg + r.nspots) + r.nspots;
        for (i = 0; i < r.nspots; i++) {
            nc += motifs->m[r.spots[i].motif].path.ncmd;
            np += motifs->m[r.spots[i].motif].path.npt;
        }
        rc = QC__RESERVE(ctx, dst->cmd, dst->cmd_cap, nc);
        if (rc == QC_OK)
            rc = QC__RESERVE(ctx, dst->pt, dst->pt_cap, np);
    }
    if (rc == QC_OK) {
        size_t sp = 0;
        rc = qc_path_move_to(ctx, dst, vine.pt[0]);
        for (j = 0; j < nseg + (nseg == 0) && rc == QC_OK; j++) {
            qc_vec2 cur[4], l[4], rr[4];
            double t0 = 0;
            if (nseg > 0)
                memcpy(cur, vine.pt + 3 * j, sizeof cur);
            for (; sp < r.nspots && r.spots[sp].seg == j && rc == QC_OK; sp++) {
                double t = r.spots[sp].t;
                if (nseg > 0 && t > t0 + 1e-12) {
                    qc_cubic_split(cur, (t - t0) / (1 - t0), l, rr);
                    rc = qc_path_cubic_to(ctx, dst, l[1], l[2], l[3]);
                    memcpy(cur, rr, sizeof cur);
                    t0 = t;
                }
                if (rc == QC_OK) {
                    const qc_motif *m = &motifs->m[r.spots[sp].motif];
                    qc_vec2 at = qc__xf_apply(&r.spots[sp].xf, m->entry), end;
                    rc = qc__path_append_xf(ctx, dst, &m->path, &r.spots[sp].xf);
                    end = qc_path_last(dst);
                    /* an open motif (a Wanderer primitive) comes back in a straight line */
                    if (rc == QC_OK && (end.x != at.x || end.y != at.y))
                        rc = qc_path_line_to(ctx, dst, at);
                }
            }
            if (rc == QC_OK && nseg > 0)
                rc = qc_path_cubic_to(ctx, dst, cur[1], cur[2], cur[3]);
        }
    }
    if (rc == QC_OK && tiled) /* copies side by side, rows alternating */
        rc = qc__btile_layout(ctx, &tile, params, &one, out);

out_free:
    qc__free(ctx, seen, seen != NULL ? skel->n : 0);
    qc__cgrid_free(ctx, &r.grid);
    free_shapes(&r);
    qc__free(ctx, r.buf, r.nbuf * sizeof *r.buf);
    qc__free(ctx, r.spots, r.spots_cap * sizeof *r.spots);
    qc__free(ctx, r.choice, motifs->n * sizeof *r.choice);
    qc_path_free(ctx, &vine);
    qc_points_free(ctx, &pts);
    qc_motif_set_free(ctx, &def);
    qc_path_free(ctx, &one);
    qc__btile_free(ctx, &tile);
    return rc;
}

const qc_family_desc qc__family_branching = {
    QC_FAMILY_BRANCHING, "branching", "motifs at the branch tips and along the vine (paper §5.1)",
    QC_FAMILY_NEEDS_POINTS | QC_FAMILY_NEEDS_MOTIFS,
    QC_PARAM_BIT(QC_PARAM_ID_SIZE) | QC_PARAM_BIT(QC_PARAM_ID_GAP) |
        QC_PARAM_BIT(QC_PARAM_ID_ANGLE) | QC_PARAM_BIT(QC_PARAM_ID_TILE) |
        QC_PARAM_BIT(QC_PARAM_ID_REPEAT_COLS) | QC_PARAM_BIT(QC_PARAM_ID_REPEAT_ROWS),
    qc_deco_branching, NULL};
