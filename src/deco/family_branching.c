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
#include "region_index.h"

enum { K_BOUND = 0, K_VINE = 1, K_MOTIF = 2 };

/* Unit-frame radius round the attachment left out of the vine test: the
 * motif necessarily meets the vine there. */
#define TRIM 0.4
/* The vine is tested as chords within this fraction of s of the curve. */
#define VINE_TOL 0.02
/* Body hulls: a coarse polyline's hull pushed out by its tolerance (unit frame). */
#define BODY_TOL 0.04
/* Chords of one vine cubic at most. */
#define MAX_CHORDS 256

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

/* qc_hypot's arithmetic, inlined: it runs per candidate and per step. */
static double hyp(double x, double y)
{
    return sqrt(x * x + y * y);
}

static qc_vec2 unit(qc_vec2 d)
{
    double len = hyp(d.x, d.y);
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
    qc__rindex inside; /* the region's edges: a curved outline has thousands,
                        * and each motif placed asks once */
    const qc_motif_set *set;
    qc__cgrid grid;
    shape *sh;
    uint32_t *choice; /* motifs eligible */
    size_t nchoice;
    qc_vec2 *buf;     /* transformed hull */
    size_t nbuf;
    qc_vec2 *chain;   /* a vine cubic's chords (MAX_CHORDS + 1 points) */
    spot *spots;
    size_t nspots, spots_cap;
    qc_rng rng;
    qc__placement *pl;
    struct turn { double deg, c, s; } turn[16]; /* rot's cosines and sines, by angle */
    size_t nturn;
    double step_w[17][4]; /* the cubic's weights at t = k / 16 (place_on_cubic) */
    qc__btile *tile;  /* a tile: items are added to the grid wrapped too */
    /* the inputs and what the steps of qc__branching_run build */
    const qc_skeleton *skel;
    double s, gap, alpha;
    qc_stats *st;
    qc_points pts;    /* the walk's points */
    qc_path vine;     /* one cubic per walk step */
    size_t nseg;
    qc_motif_set def; /* the built-in leaf when no motifs are given */
    qc__btile tile_store;
    qc_skeleton tile_skel;
    qc_path one;      /* a tile's pattern before its layout */
} run;

static int grid_add(run *r, const qc_vec2 *poly, size_t n, unsigned kind, uint32_t id)
{
    if (r->tile != NULL)
        return qc__btile_grid_add(r->ctx, r->tile, &r->grid, poly, n, kind, id);
    return qc__cgrid_add(r->ctx, &r->grid, poly, n, kind, id);
}

/* The hull of placed motif id (a spot), as try_place put it in the grid:
 * its vertices are made again from the spot's map, not stored (a third of
 * a million-point grid's bytes). */
static const qc_vec2 *placed_hull(void *ud, uint32_t id)
{
    const run *r = ud;
    const spot *sp = &r->spots[id];
    const qc_motif *m = &r->set->m[sp->motif];
    qc_vec2 *h = r->buf + r->nbuf;
    size_t i;

    for (i = 0; i < m->nhull; i++)
        h[i] = qc__xf_apply(&sp->xf, m->hull[i]);
    return h;
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

    /* three tests without side effects, the likeliest to fail first: the
     * body against the vine (two thirds of the attempts that get that far),
     * the whole hull against the boundary and the other motifs, inside */
    for (i = 0; i < nb; i++)
        body[i] = qc__xf_apply(&f, sh->body[i]);
    if (qc__cgrid_hit(&r->grid, body, nb, 1u << K_VINE, NULL, NULL))
        return 0;
    for (i = 0; i < nf; i++)
        full[i] = qc__xf_apply(&f, m->hull[i]);
    if (qc__cgrid_hit(&r->grid, full, nf, 1u << K_BOUND | 1u << K_MOTIF, NULL, NULL))
        return 0;
    if (!qc__rindex_contains(&r->inside, full[0]))
        return 0;
    /* past make_grid's guess, by a quarter: 72 bytes a spot, a million spots */
    *rc = r->nspots < r->spots_cap ? QC_OK
                                   : QC__RESERVE_EXACT(r->ctx, r->spots, r->spots_cap,
                                                       r->spots_cap + r->spots_cap / 4 + 16);
    if (*rc == QC_OK && r->tile == NULL) /* the spot, filled below, keeps its vertices */
        *rc = qc__cgrid_add_shape(r->ctx, &r->grid, full, nf, K_MOTIF, (uint32_t)r->nspots);
    else if (*rc == QC_OK)
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

/* d turned deg degrees; the few angles resolve tries are worked out once. */
static qc_vec2 rot(run *rn, qc_vec2 d, double deg)
{
    double c, s;
    qc_vec2 r;
    size_t i;

    for (i = 0; i < rn->nturn; i++)
        if (memcmp(&rn->turn[i].deg, &deg, sizeof deg) == 0)
            break;
    if (i < rn->nturn) {
        c = rn->turn[i].c;
        s = rn->turn[i].s;
    } else {
        double a = deg * (QC_PI / 180);
        c = qc_cos(a);
        s = qc_sin(a);
        if (rn->nturn < sizeof rn->turn / sizeof rn->turn[0]) {
            rn->turn[rn->nturn].deg = deg;
            rn->turn[rn->nturn].c = c;
            rn->turn[rn->nturn].s = s;
            rn->nturn++;
        }
    }
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
                qc_vec2 dir = side == 0 ? rot(r, tangent, ang) : rot(r, tangent, sgn * (90 - ang));
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
            if (hyp(pts.v[j].x - m->entry.x, pts.v[j].y - m->entry.y) > TRIM)
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

/* Validates the parameters and sets r up: a tile's skeleton with its
 * ports, the built-in leaf when no motifs are given, the rng. */
static int start(run *r, qc_ctx *ctx, const qc_region *region, const qc_params *params,
                 const qc_skeleton *skel, const qc_motif_set *motifs, qc_stats *stats)
{
    int tiled = params->tile == QC_TILE_EDGE_TO_EDGE || params->tile == QC_TILE_ALL_OVER;

    r->ctx = ctx;
    r->region = region;
    r->st = stats;
    r->s = params->size;
    r->gap = params->gap >= 0 ? params->gap : 0;
    r->alpha = params->angle;
    if (skel == NULL || skel->norder == 0)
        return qc__fail(ctx, QC_EEMPTY, "branching needs at least one point");
    if (!(r->s > 0))
        return qc__fail(ctx, QC_ERANGE, "motif size %g mm must be > 0", r->s);
    r->skel = skel;
    if (tiled) { /* the ports join the tree; the walk runs from one to the other */
        QC__TRY(qc__btile_make(ctx, region, skel, params->tile == QC_TILE_ALL_OVER,
                               &r->tile_store, &r->tile_skel));
        qc__btile_offset_rows(&r->tile_store, params->row_offset);
        r->skel = &r->tile_skel;
        r->tile = &r->tile_store;
    }
    if (motifs == NULL || motifs->n == 0) {
        QC__TRY(qc_motif_builtin(ctx, "leaf", &r->def));
        motifs = &r->def;
    }
    r->set = motifs;
    qc_rng_seed(&r->rng, params->seed ^ 0x6272616e6368ull);
    return QC_OK;
}

/* The motifs a candidate may choose: the closed ones, or all if none is. */
static int pick_choices(run *r)
{
    const qc_motif_set *motifs = r->set;
    size_t i;

    r->choice = qc__alloc_array(r->ctx, motifs->n, sizeof *r->choice);
    if (r->choice == NULL)
        return QC_ENOMEM;
    for (i = 0; i < motifs->n; i++)
        if (motifs->m[i].legs == 0)
            r->choice[r->nchoice++] = (uint32_t)i;
    if (r->nchoice == 0)
        for (i = 0; i < motifs->n; i++)
            r->choice[r->nchoice++] = (uint32_t)i;
    return QC_OK;
}

/* The vine: one cubic per walk step. */
static int build_vine(run *r)
{
    const qc_skeleton *skel = r->skel;
    size_t i;

    /* exactly: a doubling's slack would be the peak's at 10^6 points */
    QC__TRY(QC__RESERVE_EXACT(r->ctx, r->pts.v, r->pts.cap, skel->norder));
    for (i = 0; i < skel->norder; i++)
        QC__TRY(qc_points_push(r->ctx, &r->pts, skel->p[skel->order[i]]));
    /* room for the whole vine at once */
    QC__TRY(QC__RESERVE_EXACT(r->ctx, r->vine.cmd, r->vine.cmd_cap, r->pts.n + 1));
    QC__TRY(QC__RESERVE_EXACT(r->ctx, r->vine.pt, r->vine.pt_cap, 3 * r->pts.n + 1));
    QC__TRY(qc_curve_catmull_rom(r->ctx, r->pts.v, r->pts.n, skel->edges == NULL, &r->vine));
    if (r->tile != NULL)
        qc__btile_flat_ports(r->tile, &r->vine);
    r->nseg = r->vine.ncmd > 0 ? r->vine.ncmd - 1 : 0;
    for (i = 1; i < r->vine.ncmd; i++)
        if (r->vine.cmd[i] != QC_PATH_CUBIC)
            return qc__fail(r->ctx, QC_EINVAL, "vine command %zu is not a cubic", i);
    return QC_OK;
}

/* How many chords stand for vine cubic j: within about VINE_TOL s of the
 * curve (n^2 >= dev / tol), 1 to 256. */
static size_t vine_chords(const run *r, size_t j)
{
    const qc_vec2 *q = r->vine.pt + 3 * j; /* MOVE point + 3 per cubic */
    double ax = q[0].x - 2 * q[1].x + q[2].x, ay = q[0].y - 2 * q[1].y + q[2].y;
    double bx = q[1].x - 2 * q[2].x + q[3].x, by = q[1].y - 2 * q[2].y + q[3].y;
    double dev = 0.75 * sqrt(fmax(ax * ax + ay * ay, bx * bx + by * by));
    size_t nk = (size_t)ceil(sqrt(dev / (VINE_TOL * r->s)));

    return nk < 1 ? 1 : nk > MAX_CHORDS ? MAX_CHORDS : nk;
}

/* The collision grid over the region and the vine, s beyond both. */
static int make_grid(run *r)
{
    const qc_path *vine = &r->vine;
    qc_bbox b = qc_region_bbox(r->region), vb = qc__points_bbox(vine->pt, vine->npt);
    size_t nseg = r->nseg, nv = r->region->nv, spots = nseg + nseg / 8 + 16, chords = 0, hull = 0;
    size_t j;
    double s = r->s;

    /* the control points bound the curve */
    b.min.x = fmin(b.min.x, vb.min.x) - s;
    b.min.y = fmin(b.min.y, vb.min.y) - s;
    b.max.x = fmax(b.max.x, vb.max.x) + s;
    b.max.y = fmax(b.max.y, vb.max.y) + s;
    QC__TRY(qc__cgrid_init(r->ctx, &r->grid, b, s, 16 * r->skel->norder + 4096));
    r->grid.shape = placed_hull;
    r->grid.shape_ud = r;
    for (j = 0; j < nseg; j++)
        chords += vine_chords(r, j);
    for (j = 0; j < r->nchoice; j++)
        hull = r->set->m[r->choice[j]].nhull > hull ? r->set->m[r->choice[j]].nhull : hull;
    QC__TRY(QC__RESERVE_EXACT(r->ctx, r->spots, r->spots_cap, spots));
    /* the vine's chains exactly, a guess at the motifs (1.04 per cubic on
     * a 3 m block, 1.09 on a 10 m one; the grid and the spots grow by a
     * quarter past it) */
    if (r->tile != NULL)
        return qc__cgrid_reserve(r->ctx, &r->grid, chords + spots + nv + 64,
                                 2 * chords + hull * spots + 2 * nv + 1024,
                                 2 * chords + 6 * spots + 4 * nv + 256);
    return qc__cgrid_reserve(r->ctx, &r->grid, nseg + spots + nv + 64,
                             chords + nseg + 2 * nv + 1024, chords / 2 + 4 * spots + 4 * nv + 256);
}

/* Vine cubic j as short chords into the grid, and into the placement if asked. */
static int add_vine_chords(run *r, size_t j)
{
    const qc_vec2 *q = r->vine.pt + 3 * j;
    size_t k, nk = vine_chords(r, j);
    qc_vec2 prev = q[0], *chain = r->chain;

    chain[0] = prev;
    for (k = 1; k <= nk; k++) {
        qc_vec2 e[2];
        e[0] = prev;
        e[1] = qc_cubic_point(q, (double)k / nk);
        chain[k] = e[1];
        if (r->tile != NULL) /* wrapped copies: chord by chord */
            QC__TRY(grid_add(r, e, 2, K_VINE, (uint32_t)j));
        if (r->pl != NULL)
            QC__TRY(qc_points_push(r->ctx, &r->pl->vine, prev));
        prev = e[1];
    }
    /* one item for the cubic's chords: a tenth of a million-point vine's
     * items and half its vertices */
    if (r->tile == NULL)
        QC__TRY(qc__cgrid_add_chain(r->ctx, &r->grid, chain, nk + 1, K_VINE, (uint32_t)j));
    if (r->pl != NULL && j + 1 == r->nseg)
        QC__TRY(qc_points_push(r->ctx, &r->pl->vine, prev));
    return QC_OK;
}

/* What motifs keep clear of: the boundary (every ring) and the vine. */
static int fill_grid(run *r)
{
    size_t j;

    QC__TRY(make_shapes(r));
    r->buf = qc__alloc_array(r->ctx, 2 * r->nbuf, sizeof *r->buf); /* + placed_hull's */
    r->chain = qc__alloc_array(r->ctx, MAX_CHORDS + 1, sizeof *r->chain);
    if (r->buf == NULL || r->chain == NULL)
        return QC_ENOMEM;
    QC__TRY(make_grid(r));
    QC__TRY(qc__cgrid_add_region(r->ctx, &r->grid, r->region, K_BOUND));
    QC__TRY(qc__rindex_build(r->ctx, r->region, &r->inside));
    for (j = 0; j < r->nseg; j++)
        QC__TRY(add_vine_chords(r, j));
    return QC_OK;
}

/* Whether walk step i sits at a tip: the walk turns back there. The root
 * is a tip when the walk leaves and returns by one edge; a tile's walk
 * starts at a port, never a tip. */
static int is_tip(const run *r, size_t i)
{
    const uint32_t *o = r->skel->order;
    size_t n = r->pts.n;

    if (i > 0)
        return o[i - 1] == o[i + 1];
    return r->tile == NULL && o[1] == o[n - 2] && (n == 3 || o[0] == o[n - 1]);
}

/* Step 3: the tips, in walk (depth-first) order. */
static int place_tips(run *r)
{
    const qc_vec2 *v = r->pts.v;
    size_t i, n = r->pts.n;

    if (n == 1) {
        qc_vec2 up = {0, 1};
        return candidate(r, v[0], up, 0, r->alpha, r->s, 0, 0, r->st);
    }
    if (r->skel->edges == NULL || r->nseg + 1 != n || n < 3)
        return QC_OK;
    for (i = 0; i + 1 < n; i++) {
        size_t from = i ? i - 1 : 1;
        qc_vec2 d;

        if (!is_tip(r, i))
            continue;
        d = unit((qc_vec2){v[i].x - v[from].x, v[i].y - v[from].y});
        QC__TRY(candidate(r, v[i], d, 0, r->alpha, r->s, (uint32_t)i, 0, r->st));
    }
    return QC_OK;
}

/* Candidates every step along vine cubic j, alternating sides; *acc is the
 * length since the last one. */
static int place_on_cubic(run *r, size_t j, double step, double *acc, int *side)
{
    const qc_vec2 *q = r->vine.pt + 3 * j;
    size_t k, nk = 16;
    qc_vec2 prev = q[0];

    for (k = 1; k <= nk; k++) {
        double t = (double)k / nk;
        const double *w = r->step_w[k];
        qc_vec2 p; /* qc_cubic_point(q, t), its weights made once */
        double dl;

        p.x = w[0] * q[0].x + w[1] * q[1].x + w[2] * q[2].x + w[3] * q[3].x;
        p.y = w[0] * q[0].y + w[1] * q[1].y + w[2] * q[2].y + w[3] * q[3].y;
        dl = hyp(p.x - prev.x, p.y - prev.y);

        if (*acc + dl >= step && k < nk) {
            qc_vec2 tg = unit(qc_cubic_tangent(q, t));
            if (tg.x != 0 || tg.y != 0)
                QC__TRY(candidate(r, p, tg, *side, r->alpha, r->s, (uint32_t)j, t, r->st));
            *side = -*side;
            *acc = 0;
        } else {
            *acc += dl;
        }
        prev = p;
    }
    return QC_OK;
}

/* Step 4: along each branch once (the walk's first pass down it), every
 * step, alternating sides. */
static int place_along(run *r)
{
    const qc_skeleton *skel = r->skel;
    double step = r->s / 2 + r->gap, acc = step / 2;
    int walk = skel->edges != NULL && r->nseg + 1 == r->pts.n && skel->n > 0, side = 1;
    unsigned char *seen = NULL;
    size_t j;
    int rc = QC_OK;

    for (j = 0; j <= 16; j++) { /* qc_cubic_point's weights, as it works them out */
        double t = (double)j / 16, u = 1 - t;
        r->step_w[j][0] = u * u * u;
        r->step_w[j][1] = 3 * u * u * t;
        r->step_w[j][2] = 3 * u * t * t;
        r->step_w[j][3] = t * t * t;
    }

    if (walk) {
        seen = qc__alloc(r->ctx, skel->n);
        if (seen == NULL)
            return QC_ENOMEM;
        memset(seen, 0, skel->n);
        seen[skel->order[0]] = 1;
    }
    for (j = 0; rc == QC_OK && j < r->nseg; j++) {
        if (walk) {
            uint32_t to = skel->order[j + 1];
            int down = !seen[to];
            seen[to] = 1;
            if (!down) {
                acc = step / 2;
                continue;
            }
        }
        rc = place_on_cubic(r, j, step, &acc, &side);
    }
    qc__free(r->ctx, seen, seen != NULL ? skel->n : 0);
    return rc;
}

/* Room for the result at once: vine, splits and motifs. */
static int reserve_result(const run *r, qc_path *dst)
{
    size_t nc = dst->ncmd + 1 + r->nseg + 3 * r->nspots, i;
    size_t np = dst->npt + 1 + 3 * (r->nseg + r->nspots) + r->nspots;

    for (i = 0; i < r->nspots; i++) {
        nc += r->set->m[r->spots[i].motif].path.ncmd;
        np += r->set->m[r->spots[i].motif].path.npt;
    }
    QC__TRY(QC__RESERVE_EXACT(r->ctx, dst->cmd, dst->cmd_cap, nc));
    return QC__RESERVE_EXACT(r->ctx, dst->pt, dst->pt_cap, np);
}

/* The motif of spot sp as a detour from its attachment and back. */
static int sew_motif(const run *r, size_t sp, qc_path *dst)
{
    const qc_motif *m = &r->set->m[r->spots[sp].motif];
    qc_vec2 at = qc__xf_apply(&r->spots[sp].xf, m->entry), end;

    QC__TRY(qc__path_append_xf(r->ctx, dst, &m->path, &r->spots[sp].xf));
    end = qc_path_last(dst);
    /* an open motif (a Wanderer primitive) comes back in a straight line */
    if (end.x != at.x || end.y != at.y)
        return qc_path_line_to(r->ctx, dst, at);
    return QC_OK;
}

/* The spots in cmp_spot's order without moving them: the tips are placed
 * in walk order, then the spots along the vine in its order, so the array
 * is at most two sorted runs, read here as one merged run (a sort of a
 * million 72-byte spots cost a twentieth of the decoration and a copy of
 * them). More runs (no caller makes them) are sorted first. */
typedef struct spot_merge {
    const spot *s;
    size_t a, a_end, b, b_end;
} spot_merge;

static void merge_begin(run *r, spot_merge *m)
{
    size_t i, cut = r->nspots;

    for (i = 1; i < r->nspots; i++)
        if (cmp_spot(&r->spots[i - 1], &r->spots[i]) > 0) {
            if (cut < r->nspots) { /* a third run */
                qsort(r->spots, r->nspots, sizeof *r->spots, cmp_spot);
                cut = r->nspots;
                break;
            }
            cut = i;
        }
    m->s = r->spots;
    m->a = 0;
    m->a_end = cut;
    m->b = cut;
    m->b_end = r->nspots;
}

/* The next spot in order, or NULL when none is left. */
static const spot *merge_peek(const spot_merge *m)
{
    if (m->a < m->a_end &&
        (m->b >= m->b_end || cmp_spot(&m->s[m->a], &m->s[m->b]) < 0))
        return &m->s[m->a];
    return m->b < m->b_end ? &m->s[m->b] : NULL;
}

static void merge_take(spot_merge *m, const spot *sp)
{
    if (m->a < m->a_end && sp == &m->s[m->a])
        m->a++;
    else
        m->b++;
}

/* Assemble: the vine, split at each attachment for the detour. */
static int assemble(run *r, qc_path *dst)
{
    size_t j, nseg = r->nseg;
    spot_merge mg;
    const spot *sp;

    qc__cgrid_free(r->ctx, &r->grid); /* placed: the result need not share the peak with it */
    qc__rindex_free(r->ctx, &r->inside);
    merge_begin(r, &mg);
    QC__TRY(reserve_result(r, dst));
    QC__TRY(qc_path_move_to(r->ctx, dst, r->vine.pt[0]));
    for (j = 0; j < nseg + (nseg == 0); j++) {
        qc_vec2 cur[4], l[4], rr[4];
        double t0 = 0;

        if (nseg > 0)
            memcpy(cur, r->vine.pt + 3 * j, sizeof cur);
        for (; (sp = merge_peek(&mg)) != NULL && sp->seg == j; merge_take(&mg, sp)) {
            double t = sp->t;
            if (nseg > 0 && t > t0 + 1e-12) {
                qc_cubic_split(cur, (t - t0) / (1 - t0), l, rr);
                QC__TRY(qc_path_cubic_to(r->ctx, dst, l[1], l[2], l[3]));
                memcpy(cur, rr, sizeof cur);
                t0 = t;
            }
            QC__TRY(sew_motif(r, (size_t)(sp - r->spots), dst));
        }
        if (nseg > 0)
            QC__TRY(qc_path_cubic_to(r->ctx, dst, cur[1], cur[2], cur[3]));
    }
    return QC_OK;
}

static void run_free(run *r)
{
    qc_ctx *ctx = r->ctx;

    qc__cgrid_free(ctx, &r->grid);
    qc__rindex_free(ctx, &r->inside);
    free_shapes(r);
    qc__free(ctx, r->buf, 2 * r->nbuf * sizeof *r->buf);
    qc__free(ctx, r->chain, (MAX_CHORDS + 1) * sizeof *r->chain);
    qc__free(ctx, r->spots, r->spots_cap * sizeof *r->spots);
    if (r->set != NULL)
        qc__free(ctx, r->choice, r->set->n * sizeof *r->choice);
    qc_path_free(ctx, &r->vine);
    qc_points_free(ctx, &r->pts);
    qc_motif_set_free(ctx, &r->def);
    qc_path_free(ctx, &r->one);
    qc__btile_free(ctx, &r->tile_store);
}

int qc__branching_run(qc_ctx *ctx, const qc_region *region, const qc_params *params,
                      const qc_skeleton *skel, const qc_motif_set *motifs, qc_path *out,
                      qc_stats *stats, qc__placement *pl)
{
    run r;
    qc_stats dummy;
    int rc;

    memset(&r, 0, sizeof r);
    r.pl = pl;
    rc = start(&r, ctx, region, params, skel, motifs,
               stats != NULL ? stats : memset(&dummy, 0, sizeof dummy));
    if (rc < 0)
        goto out_free_run;
    rc = pick_choices(&r);
    if (rc == QC_OK)
        rc = build_vine(&r);
    if (rc == QC_OK)
        rc = fill_grid(&r);
    if (rc == QC_OK)
        rc = place_tips(&r);
    if (rc == QC_OK)
        rc = place_along(&r);
    if (rc == QC_OK)
        rc = assemble(&r, r.tile != NULL ? &r.one : out);
    if (rc == QC_OK && r.tile != NULL) /* copies side by side, rows alternating */
        rc = qc__btile_layout(ctx, r.tile, params, &r.one, out);
out_free_run:
    run_free(&r);
    return rc;
}

const qc_family_desc qc__family_branching = {
    QC_FAMILY_BRANCHING, "branching", "motifs at the branch tips and along the vine (paper §5.1)",
    QC_FAMILY_NEEDS_POINTS | QC_FAMILY_NEEDS_MOTIFS,
    QC_PARAM_BIT(QC_PARAM_ID_SIZE) | QC_PARAM_BIT(QC_PARAM_ID_GAP) |
        QC_PARAM_BIT(QC_PARAM_ID_ANGLE) | QC_PARAM_BIT(QC_PARAM_ID_TILE) |
        QC_PARAM_BIT(QC_PARAM_ID_REPEAT_COLS) | QC_PARAM_BIT(QC_PARAM_ID_REPEAT_ROWS) |
        QC_PARAM_BIT(QC_PARAM_ID_ROW_OFFSET),
    qc_deco_branching, NULL};
