/*
 * Wanderer (paper §5.2): a two-legged primitive centred on each tour point,
 * its leg bisector turned towards CC_prev + CC_next, the variant (and
 * mirror image) whose legs make angles closest to 60 degrees with the
 * directions to its neighbours; neighbours joined by cubic Béziers that
 * leave and meet the legs with tangents l * |P0P3|. A join that would cross
 * another primitive's hull, another join or the boundary is retried with
 * shorter tangents (l/2, l/4, 0), then with the next primitive's other
 * variants; what still crosses is kept as stated and counted. A primitive
 * whose hull reaches the boundary is shrunk (3/4, then 1/2).
 * Most joins that fail cross the join sewn just before (both meet the same
 * primitive): each rung is tested against that join first, point by point
 * (family_wanderer_chain.c), before the grid; the same choices, sooner.
 */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "family_wanderer.h"

enum { K_BOUND = 0, K_PRIM = 1, K_JOIN = 2, NFLAT = 16, MAXV = 64 }; /* NFLAT: see flat_crosses_last */

typedef struct prim {
    qc__xf xf;
    uint32_t m;
    uint32_t rec;  /* its hull's record in the grid */
    qc_vec2 entry, exit, in_dir, out_dir; /* world */
    qc_vec2 bis;   /* where the legs' bisector points */
} prim;

/* A primitive's hull in the grid: its map and motif (the grid asks for
 * its vertices, hull_of, rather than storing them) and its owner
 * primitive, or UINT32_MAX once replaced. */
typedef struct hrec {
    qc__xf xf;
    uint32_t m, owner;
} hrec;

/* What orient needs of a motif, worked out once per motif rather than
 * per placement (the same arithmetic, so the same bits): its legs'
 * bisector mb and the reflection about it, H = 2 mb mb^T - I. */
typedef struct mgeo {
    qc_vec2 mb;
    double h00, h01, h11;
} mgeo;

typedef struct cand {
    double score;
    uint32_t m;
    int mirror;
} cand;

typedef struct wrun {
    qc_ctx *ctx;
    const qc_motif_set *set;
    uint32_t *var;
    size_t nvar;
    mgeo *geo;           /* by motif index */
    double s;
    qc__cgrid grid;
    hrec *rec;           /* the hulls in the grid, by record */
    size_t nrec, rec_cap;
    qc_vec2 *hbuf;
    size_t nhbuf;
    /* the inputs and what the steps of qc_deco_wanderer build */
    const qc_region *region;
    const qc_skeleton *skel;
    size_t n;            /* tour points, one primitive each */
    double l;            /* the joins' tangent factor */
    qc_stats *st;
    prim *pr;
    prim *keep;          /* 3 x 2 nvar variants placed by choose_variants' first look */
    qc__wchain last;     /* the join sewn last, tested first (most failures cross it) */
    uint32_t last_id;
    double wt[NFLAT + 1][4]; /* the joins' flattening weights */
    qc_motif_set def;    /* built-in variants when no motif has legs */
} wrun;

static qc_vec2 unit(double x, double y)
{
    double len = qc_hypot(x, y);
    qc_vec2 r = {0, 0};
    if (len > 0) {
        r.x = x / len;
        r.y = y / len;
    }
    return r;
}

static double angle_between(qc_vec2 a, qc_vec2 b)
{
    return qc_atan2(a.x * b.y - a.y * b.x, a.x * b.x + a.y * b.y) * (180 / QC_PI);
}

/* A unit direction mapped by f, a similarity of scale k. */
static qc_vec2 lin(const qc__xf *f, qc_vec2 d, double k)
{
    qc_vec2 r;
    r.x = (f->a * d.x + f->b * d.y) / k;
    r.y = (f->c * d.x + f->d * d.y) / k;
    return r;
}

static mgeo motif_geo(const qc_motif *m)
{
    mgeo g;

    g.mb = unit(m->entry_dir.x + m->exit_dir.x, m->entry_dir.y + m->exit_dir.y);
    if (g.mb.x == 0 && g.mb.y == 0)
        g.mb.y = -1;
    g.h00 = 2 * g.mb.x * g.mb.x - 1;
    g.h01 = 2 * g.mb.x * g.mb.y;
    g.h11 = 2 * g.mb.y * g.mb.y - 1;
    return g;
}

/* The map of a motif (geometry g) centred at c, bisector along bis, scaled
 * k, mirrored or not. */
static qc__xf orient(const mgeo *g, qc_vec2 c, qc_vec2 bis, double k, int mirror)
{
    qc_vec2 mb = g->mb;
    double co, si, a, b, cc, d;
    qc__xf f;

    co = mb.x * bis.x + mb.y * bis.y;
    si = mb.x * bis.y - mb.y * bis.x;
    a = co; b = -si; cc = si; d = co;
    if (mirror) { /* reflect about the motif's bisector first */
        double h00 = g->h00, h01 = g->h01, h11 = g->h11;
        double na = a * h00 + b * h01, nb = a * h01 + b * h11;
        double nc = cc * h00 + d * h01, nd = cc * h01 + d * h11;
        a = na; b = nb; cc = nc; d = nd;
    }
    f.a = k * a; f.b = k * b; f.c = k * cc; f.d = k * d;
    f.tx = c.x;
    f.ty = c.y;
    return f;
}

static prim make_prim(const wrun *w, uint32_t m, int mirror, qc_vec2 c, qc_vec2 bis)
{
    const qc_motif *mo = &w->set->m[m];
    prim p;

    memset(&p, 0, sizeof p);
    p.xf = orient(&w->geo[m], c, bis, w->s / 2, mirror);
    p.m = m;
    p.in_dir = lin(&p.xf, mo->entry_dir, w->s / 2);
    p.out_dir = lin(&p.xf, mo->exit_dir, w->s / 2);
    p.entry = qc__xf_apply(&p.xf, mo->entry);
    p.exit = qc__xf_apply(&p.xf, mo->exit);
    p.bis = bis;
    return p;
}

/* Every (variant, mirror) for tour point i, best first; returns the count.
 * keep (or NULL): room for 2 nvar primitives, variant v mirrored or not
 * placed into keep[2 v + mirror]. */
static size_t rank(const wrun *w, const qc_skeleton *sk, size_t i, qc_vec2 *bis_out, cand *cd,
                   prim *keep)
{
    size_t n = sk->norder, v, k, nc = 0;
    qc_vec2 c = sk->p[sk->order[i]];
    qc_vec2 pv = sk->p[sk->order[(i + n - 1) % n]], nx = sk->p[sk->order[(i + 1) % n]];
    qc_vec2 dp = unit(pv.x - c.x, pv.y - c.y), dn = unit(nx.x - c.x, nx.y - c.y);
    qc_vec2 bis = unit(dp.x + dn.x, dp.y + dn.y);
    int mir;

    if (bis.x == 0 && bis.y == 0) /* straight through: bend to the left */
        bis = unit(-dn.y, dn.x);
    if (bis.x == 0 && bis.y == 0)
        bis.y = -1;
    if (n == 1)
        dp = dn = bis;
    for (v = 0; v < w->nvar && nc < MAXV; v++) {
        for (mir = 0; mir < 2; mir++) {
            prim p = make_prim(w, w->var[v], mir, c, bis);
            cand t;
            /* a quick measure: unit vectors 60 degrees apart are 1 apart */
            t.score = fabs(qc_hypot(p.in_dir.x - dp.x, p.in_dir.y - dp.y) - 1) +
                      fabs(qc_hypot(p.out_dir.x - dn.x, p.out_dir.y - dn.y) - 1);
            t.m = w->var[v];
            t.mirror = mir;
            if (keep != NULL)
                keep[2 * v + (size_t)mir] = p;
            for (k = nc; k > 0 && cd[k - 1].score > t.score + 1e-9; k--)
                cd[k] = cd[k - 1];
            cd[k] = t;
            nc++;
        }
    }
    *bis_out = bis;
    return nc;
}

typedef struct skipctx {
    const wrun *w;
    uint32_t i, n, seg;
} skipctx;

/* What a join (or, seg = NFLAT / 2, a replacement hull) of tour point i may
 * touch: its own two primitives, and the ends of its neighbouring joins. */
static int skip_seg(void *ud, unsigned kind, uint32_t id, size_t seg)
{
    const skipctx *s = ud;
    uint32_t next = (s->i + 1) % s->n, prev = (s->i + s->n - 1) % s->n;
    if (kind == K_PRIM) { /* a join starts and ends on its own two primitives */
        uint32_t owner = s->w->rec[id].owner;
        return owner == UINT32_MAX || owner == s->i || owner == next;
    }
    if (kind == K_JOIN) /* neighbouring joins share end points */
        return (id == prev && seg < 2) || (id == next && seg + 2 >= NFLAT);
    return 0;
}

static int skip_fn(void *ud, unsigned kind, uint32_t id)
{
    return skip_seg(ud, kind, id, ((const skipctx *)ud)->seg);
}

static int skip_last(void *ud, size_t seg)
{
    return skip_seg(ud, K_JOIN, ((const skipctx *)ud)->w->last_id, seg);
}

static void join_ctrl(const prim *a, const prim *b, double l, qc_vec2 *c1, qc_vec2 *c2)
{
    double len = qc_hypot(b->entry.x - a->exit.x, b->entry.y - a->exit.y) * l;
    c1->x = a->exit.x + a->out_dir.x * len;
    c1->y = a->exit.y + a->out_dir.y * len;
    c2->x = b->entry.x + b->in_dir.x * len;
    c2->y = b->entry.y + b->in_dir.y * len;
}

/* The Bernstein weights of the NFLAT + 1 points along a join, once. */
static void flat_weights(double (*wt)[4])
{
    int k;
    for (k = 0; k <= NFLAT; k++) {
        double t = (double)k / NFLAT, u = 1 - t;
        wt[k][0] = u * u * u;
        wt[k][1] = 3 * u * u * t;
        wt[k][2] = 3 * u * t * t;
        wt[k][3] = t * t * t;
    }
}

/* Point k of NFLAT + 1 along the cubic p0 c1 c2 p3 (weights wt[k]). */
static qc_vec2 flat_point(const double *wt, qc_vec2 p0, qc_vec2 c1, qc_vec2 c2, qc_vec2 p3)
{
    qc_vec2 o;
    o.x = wt[0] * p0.x + wt[1] * c1.x + wt[2] * c2.x + wt[3] * p3.x;
    o.y = wt[0] * p0.y + wt[1] * c1.y + wt[2] * c2.y + wt[3] * p3.y;
    return o;
}

static void flat_join(const wrun *w, qc_vec2 p0, qc_vec2 c1, qc_vec2 c2, qc_vec2 p3, qc_vec2 *o)
{
    int k;
    for (k = 0; k <= NFLAT; k++)
        o[k] = flat_point(w->wt[k], p0, c1, c2, p3);
}

/* The segments of join i to test against the join sewn last, once per
 * join rather than per rung: bit k unless skip_seg exempts segment k; none
 * when no join is kept yet. */
static unsigned last_mask(const wrun *w, size_t i)
{
    skipctx sk;
    unsigned mask = 0;
    size_t k;

    if (w->last.n == 0)
        return 0;
    sk.w = w;
    sk.i = (uint32_t)i;
    sk.n = (uint32_t)w->n;
    sk.seg = 0;
    for (k = 0; k < NFLAT; k++)
        if (!skip_last(&sk, k))
            mask |= 1u << k;
    return mask;
}

/* The join's polyline f (controls c1, c2 from a's exit to b's entry),
 * tested against the join sewn last (segments in mask) segment by segment,
 * each as its two points are made, those where joins cross it most often
 * first (a quarter of the way along: near the primitive both meet): 1 at
 * the first crossing (a hit the grid query would find too, without its
 * walk or the rest of f), else 0, with f complete if whole (may_join
 * needs only the answer). A point is made once, by the same arithmetic
 * whichever segment asks first. */
static int flat_crosses_last(const wrun *w, const prim *a, const prim *b, qc_vec2 c1,
                             qc_vec2 c2, qc_vec2 *f, unsigned mask, int whole)
{
    static const unsigned char first[NFLAT] = {5, 4, 6, 3, 2, 1, 0, 7,
                                               8, 9, 10, 11, 12, 13, 14, 15};
    unsigned long made = 0; /* bit k: f[k] made */
    int o;

    for (o = 0; o < NFLAT; o++) {
        size_t k = first[o];
        if (!(mask >> k & 1))
            continue;
        if (!(made >> k & 1))
            f[k] = flat_point(w->wt[k], a->exit, c1, c2, b->entry);
        f[k + 1] = flat_point(w->wt[k + 1], a->exit, c1, c2, b->entry);
        made |= 3ul << k;
        if (qc__wchain_seg_touch(&w->last, f + k))
            return 1;
    }
    for (o = 0; whole && o <= NFLAT; o++)
        if (!(made >> o & 1))
            f[o] = flat_point(w->wt[o], a->exit, c1, c2, b->entry);
    return 0;
}

/* Whether the join i (polyline f) crosses anything it must not. */
static int join_hits(wrun *w, const qc_vec2 *f, size_t i, size_t n)
{
    skipctx sk;

    sk.w = w;
    sk.i = (uint32_t)i;
    sk.n = (uint32_t)n;
    sk.seg = 0;
    return qc__cgrid_hit_polyline(&w->grid, f, NFLAT + 1,
                                  1u << K_BOUND | 1u << K_PRIM | 1u << K_JOIN, skip_seg, &sk);
}

/* The vertices of hull record id, as add_hull put them in the grid. */
static const qc_vec2 *hull_of(void *ud, uint32_t id)
{
    const wrun *w = ud;
    const hrec *h = &w->rec[id];
    const qc_motif *m = &w->set->m[h->m];
    qc_vec2 *v = w->hbuf + w->nhbuf;
    size_t k;

    for (k = 0; k < m->nhull; k++)
        v[k] = qc__xf_apply(&h->xf, m->hull[k]);
    return v;
}

/* Adds primitive i's hull as a new record. */
static int add_hull(wrun *w, prim *p, uint32_t owner)
{
    const qc_motif *m = &w->set->m[p->m];
    size_t k;

    QC__TRY(QC__RESERVE(w->ctx, w->rec, w->rec_cap, w->nrec + 1));
    for (k = 0; k < m->nhull; k++)
        w->hbuf[k] = qc__xf_apply(&p->xf, m->hull[k]);
    w->rec[w->nrec].xf = p->xf;
    w->rec[w->nrec].m = p->m;
    w->rec[w->nrec].owner = owner;
    QC__TRY(qc__cgrid_add_shape(w->ctx, &w->grid, w->hbuf, m->nhull, K_PRIM, (uint32_t)w->nrec));
    p->rec = (uint32_t)w->nrec++;
    return QC_OK;
}

/* Tries the tangent ladder for join a -> b: 1 and the controls when clear. */
static int try_join(wrun *w, const prim *a, const prim *b, double l, size_t i, size_t n,
                    qc_vec2 *c1, qc_vec2 *c2, qc_vec2 *f)
{
    static const double shrink[] = {1, 0.5, 0.25, 0};
    unsigned mask = last_mask(w, i);
    size_t tr;

    for (tr = 0; tr < 4; tr++) {
        join_ctrl(a, b, l * shrink[tr], c1, c2);
        /* the join sewn last first: most joins that fail cross it */
        if (!flat_crosses_last(w, a, b, *c1, *c2, f, mask, 1) && !join_hits(w, f, i, n))
            return 1;
        if (l == 0)
            break;
    }
    return 0;
}

/* The built-in variants of the motifs named ("heart" -> heart60, heart90)
 * as a comma list in names (size bytes); its length, 0 for none. */
static size_t variant_names(const qc_motif_set *motifs, char *names, size_t size)
{
    size_t len = 0, i, b;

    names[0] = '\0';
    for (i = 0; motifs != NULL && i < motifs->n; i++) {
        size_t nl = strlen(motifs->m[i].name);
        for (b = 0; b < qc_motif_builtin_count(); b++) {
            const char *bn = qc_motif_builtin_name(b);
            size_t bl = strlen(bn);
            if (nl == 0 || bl <= nl || memcmp(bn, motifs->m[i].name, nl) != 0 ||
                bn[nl] < '0' || bn[nl] > '9' || len + bl + 2 > size)
                continue;
            if (len > 0)
                names[len++] = ',';
            memcpy(names + len, bn, bl + 1);
            len += bl;
        }
    }
    return len;
}

/* The motifs with legs, or when none has them the built-in variants of
 * the motifs named, else the loops. */
static int pick_set(wrun *w, const qc_motif_set *motifs)
{
    char names[512];
    size_t i, nvar = 0;

    w->set = motifs;
    for (i = 0; motifs != NULL && i < motifs->n; i++)
        nvar += motifs->m[i].legs == 2;
    if (nvar > 0)
        return QC_OK;
    QC__TRY(qc_motif_builtin(w->ctx, variant_names(motifs, names, sizeof names) > 0
                                         ? names : "loop30,loop60,loop90,loop120",
                             &w->def));
    w->set = &w->def;
    return QC_OK;
}

/* The variants' list, the primitives and a hull buffer for the largest. */
static int alloc_run(wrun *w)
{
    size_t i, maxhull = 0;

    w->var = qc__alloc_array(w->ctx, w->set->n, sizeof *w->var);
    w->geo = qc__alloc_array(w->ctx, w->set->n, sizeof *w->geo);
    w->pr = qc__alloc_array(w->ctx, w->n, sizeof *w->pr);
    w->keep = qc__alloc_array(w->ctx, 6 * w->set->n, sizeof *w->keep);
    if (w->var == NULL || w->geo == NULL || w->pr == NULL || w->keep == NULL)
        return QC_ENOMEM;
    for (i = 0; i < w->set->n; i++) {
        w->geo[i] = motif_geo(&w->set->m[i]);
        if (w->set->m[i].legs == 2)
            w->var[w->nvar++] = (uint32_t)i;
        if (w->set->m[i].nhull > maxhull)
            maxhull = w->set->m[i].nhull;
    }
    w->hbuf = qc__alloc_array(w->ctx, 2 * maxhull, sizeof *w->hbuf); /* + hull_of's */
    if (w->hbuf == NULL)
        return QC_ENOMEM;
    w->nhbuf = maxhull;
    return QC_OK;
}

/* Primitive i its best variant by rank; keep as for rank. */
static void first_choice(wrun *w, size_t i, prim *keep)
{
    const qc_skeleton *skel = w->skel;
    cand cd[MAXV];
    qc_vec2 bis;

    rank(w, skel, i, &bis, cd, keep);
    w->pr[i] = make_prim(w, cd[0].m, cd[0].mirror, skel->p[skel->order[i]], bis);
}

/* Primitive i's variant judged again against its neighbours' real legs;
 * placed: its variants as rank placed them (or NULL to place them here). */
static void second_choice(wrun *w, size_t i, const prim *placed)
{
    const qc_skeleton *skel = w->skel;
    prim *pr = w->pr;
    size_t n = w->n, k;
    const prim *pv = &pr[(i + n - 1) % n], *nx = &pr[(i + 1) % n];
    qc_vec2 bis = pr[i].bis;
    double best = 1e300;

    for (k = 0; k < 2 * w->nvar; k++) {
        prim q = placed != NULL ? placed[k]
                                : make_prim(w, w->var[k / 2], (int)(k & 1),
                                            skel->p[skel->order[i]], bis);
        qc_vec2 din = unit(pv->exit.x - q.entry.x, pv->exit.y - q.entry.y);
        qc_vec2 dout;
        double sc = fabs(fabs(angle_between(q.in_dir, din)) - 60);
        if (!(sc < best - 1e-9)) /* the out leg only adds: it cannot win */
            continue;
        dout = unit(nx->entry.x - q.exit.x, nx->entry.y - q.exit.y);
        sc += fabs(fabs(angle_between(q.out_dir, dout)) - 60);
        if (sc < best - 1e-9) {
            best = sc;
            pr[i] = q;
        }
    }
}

/* Each primitive its best variant, then judged again against the real
 * P0P3: the second look at i sees i - 1's second choice and i + 1's first.
 * Both run in one sweep, the first a step ahead, so that the second reuses
 * the variants the first placed (w->keep: i's, i + 1's and the last's)
 * rather than placing them again. */
static void choose_variants(wrun *w)
{
    size_t n = w->n, i, nk = 2 * w->nvar;
    prim *keep = 2 * w->nvar <= MAXV ? w->keep : NULL; /* rank places all of them */

    if (n == 1) {
        first_choice(w, 0, NULL);
        return;
    }
    first_choice(w, n - 1, keep != NULL ? keep + 2 * nk : NULL);
    first_choice(w, 0, keep);
    for (i = 0; i < n; i++) {
        const prim *mine = keep == NULL ? NULL : i + 1 == n ? keep + 2 * nk : keep + (i & 1) * nk;
        if (i + 2 < n)
            first_choice(w, i + 1, keep != NULL ? keep + ((i + 1) & 1) * nk : NULL);
        second_choice(w, i, mine);
    }
}

/* The collision grid over the region and the tour, s beyond both, with
 * the boundary in it. */
static int make_grid(wrun *w)
{
    const qc_skeleton *skel = w->skel;
    qc_bbox b = qc_region_bbox(w->region);
    size_t n = w->n, nv = w->region->nv, i;
    double s = w->s;

    for (i = 0; i < n; i++) {
        qc_vec2 c = skel->p[skel->order[i]];
        b.min.x = fmin(b.min.x, c.x);
        b.min.y = fmin(b.min.y, c.y);
        b.max.x = fmax(b.max.x, c.x);
        b.max.y = fmax(b.max.y, c.y);
    }
    b.min.x -= s; b.min.y -= s; b.max.x += s; b.max.y += s;
    QC__TRY(qc__cgrid_init(w->ctx, &w->grid, b, s, 8 * n + 4096));
    w->grid.shape = hull_of;
    w->grid.shape_ud = w;
    /* a chain per join, a hull (no vertices) per primitive and per
     * replacement (a few percent): exactly, as a regrowth doubles arrays
     * of millions */
    QC__TRY(qc__cgrid_reserve(w->ctx, &w->grid, 2 * n + n / 16 + nv + 64,
                              (NFLAT + 1) * n + 2 * nv + 1024,
                              8 * n + 4 * nv + 256));
    return qc__cgrid_add_region(w->ctx, &w->grid, w->region, K_BOUND);
}

/* Primitive i, shrunk (3/4, then 1/2) while its hull reaches the boundary,
 * into the grid. */
static int fit_prim(wrun *w, size_t i)
{
    static const double shrink[] = {0.75, 0.5};
    prim *p = &w->pr[i];
    const qc_motif *m = &w->set->m[p->m];
    double s0 = w->s;
    size_t k, tr;

    for (tr = 0; tr < 2; tr++) {
        uint32_t mi = p->m;
        int mir;

        for (k = 0; k < m->nhull; k++)
            w->hbuf[k] = qc__xf_apply(&p->xf, m->hull[k]);
        if (!qc__cgrid_hit(&w->grid, w->hbuf, m->nhull, 1u << K_BOUND, NULL, NULL))
            break;
        w->s = s0 * shrink[tr];
        mir = p->xf.a * p->xf.d - p->xf.b * p->xf.c < 0;
        *p = make_prim(w, mi, mir, w->skel->p[w->skel->order[i]], p->bis);
        w->s = s0;
    }
    w->st->motifs_shrunk += tr > 0;
    return add_hull(w, p, (uint32_t)i);
}

/* Whether a join meets a and b alike: the same entry and leg (all a join
 * to them depends on). */
static int same_entry(const prim *a, const prim *b)
{
    return a->entry.x == b->entry.x && a->entry.y == b->entry.y && a->in_dir.x == b->in_dir.x &&
           a->in_dir.y == b->in_dir.y;
}

/* Whether some rung of the tangent ladder for join i: a -> b keeps clear
 * of the join sewn last: when none does, try_join fails, so a variant is
 * turned down before its hull's grid query (the same choice, sooner). */
static int may_join(const wrun *w, const prim *a, const prim *b, size_t i)
{
    static const double shrink[] = {1, 0.5, 0.25, 0};
    qc_vec2 c1, c2, f[NFLAT + 1];
    unsigned mask = last_mask(w, i);
    size_t tr;

    for (tr = 0; tr < 4; tr++) {
        join_ctrl(a, b, w->l * shrink[tr], &c1, &c2);
        if (!flat_crosses_last(w, a, b, c1, c2, f, mask, 0))
            return 1;
        if (w->l == 0)
            break;
    }
    return 0;
}

/* The join i -> j through one of j's other variants whose hull keeps
 * clear: 1 (pr[j] replaced, c1, c2, f set), 0 if none does, or an error. */
static int join_other_variant(wrun *w, size_t i, size_t j, qc_vec2 *c1, qc_vec2 *c2,
                              qc_vec2 *f)
{
    const qc_skeleton *skel = w->skel;
    cand cd[MAXV];
    qc_vec2 bis;
    size_t nc = rank(w, skel, j, &bis, cd, NULL), alt, k;

    for (alt = 1; alt < nc; alt++) {
        prim q = make_prim(w, cd[alt].m, cd[alt].mirror, skel->p[skel->order[j]], bis);
        const qc_motif *m = &w->set->m[q.m];
        skipctx sk;

        /* met like the one try_join just failed with, or failing on the join sewn last */
        if (same_entry(&q, &w->pr[j]) || !may_join(w, &w->pr[i], &q, i))
            continue;
        for (k = 0; k < m->nhull; k++)
            w->hbuf[k] = qc__xf_apply(&q.xf, m->hull[k]);
        sk.w = w;
        sk.i = (uint32_t)j; /* its hull may meet its own joins and primitives */
        sk.n = (uint32_t)w->n;
        sk.seg = NFLAT / 2;
        if (qc__cgrid_hit(&w->grid, w->hbuf, m->nhull, 1u << K_JOIN | 1u << K_BOUND, skip_fn, &sk))
            continue;
        if (try_join(w, &w->pr[i], &q, w->l, i, w->n, c1, c2, f)) {
            w->rec[w->pr[j].rec].owner = UINT32_MAX;
            w->pr[j] = q;
            QC__TRY(add_hull(w, &w->pr[j], (uint32_t)j));
            return 1;
        }
    }
    return 0;
}

/* Primitive i and its join to the next, into out and the grid. */
static int sew_step(wrun *w, size_t i, qc_path *out)
{
    prim *pr = w->pr;
    size_t n = w->n, j = (i + 1) % n;
    qc_vec2 c1, c2, f[NFLAT + 1];
    int ok;

    QC__TRY(qc__path_append_xf(w->ctx, out, &w->set->m[pr[i].m].path, &pr[i].xf));
    if (n == 1)
        return QC_OK;
    ok = try_join(w, &pr[i], &pr[j], w->l, i, n, &c1, &c2, f);
    if (!ok && j != 0) /* the next primitive's other variants, unless it is sewn */
        ok = join_other_variant(w, i, j, &c1, &c2, f);
    if (ok < 0)
        return ok;
    if (!ok) { /* nothing helped: keep the stated tangents */
        w->st->joins_unfixed++;
        join_ctrl(&pr[i], &pr[j], w->l, &c1, &c2);
        flat_join(w, pr[i].exit, c1, c2, pr[j].entry, f);
    }
    QC__TRY(qc__cgrid_add_chain(w->ctx, &w->grid, f, NFLAT + 1, K_JOIN, (uint32_t)i));
    qc__wchain_set(&w->last, f, NFLAT + 1);
    w->last_id = (uint32_t)i;
    return qc_path_cubic_to(w->ctx, out, c1, c2, pr[j].entry);
}

/* Room in out for the whole path at once, each primitive counted as the
 * largest variant plus its join: at 10^6 points a doubling array would
 * hold its old and new copies at once. */
static int reserve_path(wrun *w, qc_path *out)
{
    size_t v, cmds = 0, pts = 0;

    for (v = 0; v < w->nvar; v++) {
        const qc_path *p = &w->set->m[w->var[v]].path;
        cmds = p->ncmd > cmds ? p->ncmd : cmds;
        pts = p->npt > pts ? p->npt : pts;
    }
    if (w->n > (SIZE_MAX - 1) / (pts + 3))
        return qc__fail(w->ctx, QC_ENOMEM, "wanderer path of %zu primitives", w->n);
    QC__TRY(QC__RESERVE_EXACT(w->ctx, out->cmd, out->cmd_cap, out->ncmd + 1 + w->n * (cmds + 1)));
    return QC__RESERVE_EXACT(w->ctx, out->pt, out->pt_cap, out->npt + 1 + w->n * (pts + 3));
}

/* The path: primitive, join, primitive, ..., back to the first. */
static int sew(wrun *w, qc_path *out)
{
    size_t i;

    QC__TRY(reserve_path(w, out));
    QC__TRY(qc_path_move_to(w->ctx, out, w->pr[0].entry));
    for (i = 0; i < w->n; i++)
        QC__TRY(sew_step(w, i, out));
    w->st->motifs_placed += w->n;
    return QC_OK;
}

static void wrun_free(wrun *w)
{
    qc_ctx *ctx = w->ctx;

    qc__cgrid_free(ctx, &w->grid);
    qc__free(ctx, w->rec, w->rec_cap * sizeof *w->rec);
    qc__free(ctx, w->hbuf, 2 * w->nhbuf * sizeof *w->hbuf);
    qc__free(ctx, w->pr, w->n * sizeof *w->pr);
    if (w->set != NULL) {
        qc__free(ctx, w->var, w->set->n * sizeof *w->var);
        qc__free(ctx, w->geo, w->set->n * sizeof *w->geo);
        qc__free(ctx, w->keep, 6 * w->set->n * sizeof *w->keep);
    }
    qc_motif_set_free(ctx, &w->def);
}

int qc_deco_wanderer(qc_ctx *ctx, const qc_region *region, const qc_params *params,
                     const qc_skeleton *skel, const qc_motif_set *motifs, qc_path *out,
                     qc_stats *stats)
{
    wrun w;
    qc_stats dummy;
    size_t i;
    int rc;

    if (skel == NULL || skel->norder == 0)
        return qc__fail(ctx, QC_EEMPTY, "wanderer needs at least one point");
    if (!(params->size > 0))
        return qc__fail(ctx, QC_ERANGE, "motif size %g mm must be > 0", params->size);
    memset(&w, 0, sizeof w);
    w.ctx = ctx;
    w.region = region;
    w.skel = skel;
    w.n = skel->norder;
    w.s = params->size;
    w.l = params->tangent >= 0 ? params->tangent : 0;
    w.st = stats != NULL ? stats : memset(&dummy, 0, sizeof dummy);
    flat_weights(w.wt);
    rc = pick_set(&w, motifs);
    if (rc == QC_OK)
        rc = alloc_run(&w);
    if (rc != QC_OK)
        goto out_free_run;
    choose_variants(&w);
    rc = make_grid(&w);
    for (i = 0; rc == QC_OK && i < w.n; i++)
        rc = fit_prim(&w, i);
    if (rc == QC_OK)
        rc = sew(&w, out);
out_free_run:
    wrun_free(&w);
    return rc;
}

/* A tour by default: the primitives sit on consecutive tour points. */
static int wanderer_default(const qc_params *p, int id, double *value)
{
    (void)p;
    if (id != QC_PARAM_ID_SKELETON)
        return 0;
    *value = QC_SKELETON_TSP;
    return 1;
}

const qc_family_desc qc__family_wanderer = {
    QC_FAMILY_WANDERER, "wanderer", "two-legged motifs on a tour, joined by curves (paper §5.2)",
    QC_FAMILY_NEEDS_POINTS | QC_FAMILY_NEEDS_MOTIFS,
    QC_PARAM_BIT(QC_PARAM_ID_SIZE) | QC_PARAM_BIT(QC_PARAM_ID_TANGENT), qc_deco_wanderer,
    wanderer_default};
