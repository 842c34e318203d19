/*
 * Wanderer (paper §5.2): a two-legged primitive centred on each tour point,
 * its leg bisector turned towards CC_prev + CC_next, the variant whose legs
 * make angles closest to 60 degrees with the joins; neighbours joined by
 * cubic Béziers leaving and meeting the legs with tangents l * |P0P3|.
 * A join that would cross a primitive, another join or the boundary is
 * retried with shorter tangents; what still crosses is counted.
 */
#include <math.h>
#include <string.h>

#include "deco_internal.h"

enum { K_BOUND = 0, K_PRIM = 1, K_JOIN = 2, NFLAT = 16 };

typedef struct prim {
    qc__xf xf;
    uint32_t m;
    qc_vec2 entry, exit, in_dir, out_dir; /* world */
} prim;

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

static qc_vec2 lin(const qc__xf *f, qc_vec2 d)
{
    qc_vec2 r;
    r.x = f->a * d.x + f->b * d.y;
    r.y = f->c * d.x + f->d * d.y;
    return unit(r.x, r.y);
}

/* The map of motif m centred at c, bisector along bis, scaled k, mirrored or not. */
static qc__xf orient(const qc_motif *m, qc_vec2 c, qc_vec2 bis, double k, int mirror)
{
    qc_vec2 mb = unit(m->entry_dir.x + m->exit_dir.x, m->entry_dir.y + m->exit_dir.y);
    double co, si, a, b, cc, d;
    qc__xf f;

    if (mb.x == 0 && mb.y == 0)
        mb.y = -1;
    co = mb.x * bis.x + mb.y * bis.y;
    si = mb.x * bis.y - mb.y * bis.x;
    a = co; b = -si; cc = si; d = co;
    if (mirror) { /* reflect about the bisector first: H = 2 mb mb^T - I */
        double h00 = 2 * mb.x * mb.x - 1, h01 = 2 * mb.x * mb.y, h11 = 2 * mb.y * mb.y - 1;
        double na = a * h00 + b * h01, nb = a * h01 + b * h11;
        double nc = cc * h00 + d * h01, nd = cc * h01 + d * h11;
        a = na; b = nb; cc = nc; d = nd;
    }
    f.a = k * a; f.b = k * b; f.c = k * cc; f.d = k * d;
    f.tx = c.x;
    f.ty = c.y;
    return f;
}

typedef struct skipctx {
    uint32_t i, n, seg;
    int own_ok; /* segments this close to an end may touch their own primitive */
} skipctx;

static int skip_fn(void *ud, unsigned kind, uint32_t id)
{
    const skipctx *s = ud;
    uint32_t next = (s->i + 1) % s->n, prev = (s->i + s->n - 1) % s->n;
    if (kind == K_PRIM)
        return (id == s->i && s->seg < 2) || (id == next && s->seg + 2 >= NFLAT);
    if (kind == K_JOIN)
        return (id == prev && s->seg < 2) || (id == next && s->seg + 2 >= NFLAT) || id == s->i;
    return 0;
}

static void join_ctrl(const prim *a, const prim *b, double l, qc_vec2 *c1, qc_vec2 *c2)
{
    double len = qc_hypot(b->entry.x - a->exit.x, b->entry.y - a->exit.y) * l;
    c1->x = a->exit.x + a->out_dir.x * len;
    c1->y = a->exit.y + a->out_dir.y * len;
    c2->x = b->entry.x + b->in_dir.x * len;
    c2->y = b->entry.y + b->in_dir.y * len;
}

static void flat_join(qc_vec2 p0, qc_vec2 c1, qc_vec2 c2, qc_vec2 p3, qc_vec2 *o)
{
    int k;
    for (k = 0; k <= NFLAT; k++) {
        double t = (double)k / NFLAT, u = 1 - t;
        double w0 = u * u * u, w1 = 3 * u * u * t, w2 = 3 * u * t * t, w3 = t * t * t;
        o[k].x = w0 * p0.x + w1 * c1.x + w2 * c2.x + w3 * p3.x;
        o[k].y = w0 * p0.y + w1 * c1.y + w2 * c2.y + w3 * p3.y;
    }
}

int qc_deco_wanderer(qc_ctx *ctx, const qc_region *region, const qc_params *params,
                     const qc_skeleton *skel, const qc_motif_set *motifs, qc_path *out,
                     qc_stats *stats)
{
    qc_motif_set def = {0};
    const qc_motif_set *set = motifs;
    prim *pr = NULL;
    uint32_t *var = NULL;
    size_t nvar = 0, n, i, ring;
    double s, l = params->tangent;
    qc__cgrid grid;
    qc_stats dummy;
    int rc = QC_OK;

    memset(&grid, 0, sizeof grid);
    if (stats == NULL)
        stats = memset(&dummy, 0, sizeof dummy);
    if (skel == NULL || skel->norder == 0)
        return qc__fail(ctx, QC_EEMPTY, "wanderer needs at least one point");
    s = params->size;
    if (!(s > 0))
        return qc__fail(ctx, QC_ERANGE, "motif size %g mm must be > 0", s);
    if (!(l >= 0))
        l = 0;
    n = skel->norder;
    if (set != NULL)
        for (i = 0; i < set->n; i++)
            nvar += set->m[i].legs == 2;
    if (nvar == 0) {
        QC__TRY(qc_motif_builtin(ctx, "loop30,loop60,loop90,loop120", &def));
        set = &def;
    }
    var = qc__alloc_array(ctx, set->n, sizeof *var);
    pr = qc__alloc_array(ctx, n, sizeof *pr);
    if (var == NULL || pr == NULL) {
        rc = QC_ENOMEM;
        goto out_free;
    }
    nvar = 0;
    for (i = 0; i < set->n; i++)
        if (set->m[i].legs == 2)
            var[nvar++] = (uint32_t)i;

    /* Primitives: centred, bisector to CC_prev + CC_next, best variant. */
    for (i = 0; i < n; i++) {
        qc_vec2 c = skel->p[skel->order[i]];
        qc_vec2 pv = skel->p[skel->order[(i + n - 1) % n]], nx = skel->p[skel->order[(i + 1) % n]];
        qc_vec2 dp = unit(pv.x - c.x, pv.y - c.y), dn = unit(nx.x - c.x, nx.y - c.y);
        qc_vec2 bis = unit(dp.x + dn.x, dp.y + dn.y);
        double best = 1e300;
        size_t v;
        int mir;
        if (bis.x == 0 && bis.y == 0)
            bis = unit(-dn.y, dn.x);
        if (bis.x == 0 && bis.y == 0)
            bis.y = -1;
        if (n == 1)
            dp = dn = bis;
        for (v = 0; v < nvar; v++) {
            for (mir = 0; mir < 2; mir++) {
                const qc_motif *m = &set->m[var[v]];
                qc__xf f = orient(m, c, bis, s / 2, mir);
                qc_vec2 ind = lin(&f, m->entry_dir), outd = lin(&f, m->exit_dir);
                double sc = fabs(fabs(angle_between(ind, dp)) - 60) +
                            fabs(fabs(angle_between(outd, dn)) - 60);
                if (sc < best - 1e-9) {
                    best = sc;
                    pr[i].xf = f;
                    pr[i].m = var[v];
                    pr[i].in_dir = ind;
                    pr[i].out_dir = outd;
                    pr[i].entry = qc__xf_apply(&f, m->entry);
                    pr[i].exit = qc__xf_apply(&f, m->exit);
                }
            }
        }
    }

    {
        qc_bbox b = qc_region_bbox(region);
        double cell = s;
        for (i = 0; i < n; i++) {
            qc_vec2 c = skel->p[skel->order[i]];
            b.min.x = fmin(b.min.x, c.x);
            b.min.y = fmin(b.min.y, c.y);
            b.max.x = fmax(b.max.x, c.x);
            b.max.y = fmax(b.max.y, c.y);
        }
        b.min.x -= s; b.min.y -= s; b.max.x += s; b.max.y += s;
        rc = qc__cgrid_init(ctx, &grid, b, cell, 8 * n + 4096);
    }
    for (ring = 0; rc == QC_OK && ring < region->nrings; ring++) {
        size_t lo = ring ? region->ring_end[ring - 1] : 0, hi = region->ring_end[ring];
        for (i = lo; i < hi && rc == QC_OK; i++) {
            qc_vec2 e[2];
            e[0] = region->v[i];
            e[1] = region->v[i + 1 < hi ? i + 1 : lo];
            rc = qc__cgrid_add(ctx, &grid, e, 2, K_BOUND, 0);
        }
    }
    for (i = 0; rc == QC_OK && i < n; i++) {
        const qc_motif *m = &set->m[pr[i].m];
        qc_vec2 h[256];
        size_t k, nh = m->nhull < 256 ? m->nhull : 256;
        for (k = 0; k < nh; k++)
            h[k] = qc__xf_apply(&pr[i].xf, m->hull[k]);
        rc = qc__cgrid_add(ctx, &grid, h, nh, K_PRIM, (uint32_t)i);
    }

    /* The path: primitive, join, primitive, ..., back to the first. */
    if (rc == QC_OK)
        rc = qc_path_move_to(ctx, out, pr[0].entry);
    for (i = 0; rc == QC_OK && i < n; i++) {
        const prim *a = &pr[i], *b = &pr[(i + 1) % n];
        static const double shrink[] = {1, 0.5, 0.25, 0};
        qc_vec2 c1, c2, f[NFLAT + 1];
        size_t tr, k;
        int crossed = 1;
        rc = qc__path_append_xf(ctx, out, &set->m[a->m].path, &a->xf);
        if (rc != QC_OK || n == 1)
            break;
        for (tr = 0; tr < 4 && crossed; tr++) {
            skipctx sk;
            join_ctrl(a, b, l * shrink[tr], &c1, &c2);
            flat_join(a->exit, c1, c2, b->entry, f);
            sk.i = (uint32_t)i;
            sk.n = (uint32_t)n;
            crossed = 0;
            for (k = 0; k < NFLAT && !crossed; k++) {
                sk.seg = (uint32_t)k;
                crossed = qc__cgrid_hit(&grid, f + k, 2, 1u << K_BOUND | 1u << K_PRIM | 1u << K_JOIN,
                                        skip_fn, &sk);
            }
            if (!crossed && tr > 0)
                break;
        }
        if (crossed) { /* nothing helped: keep the stated tangents */
            stats->joins_unfixed++;
            join_ctrl(a, b, l, &c1, &c2);
            flat_join(a->exit, c1, c2, b->entry, f);
        }
        for (k = 0; k < NFLAT && rc == QC_OK; k++)
            rc = qc__cgrid_add(ctx, &grid, f + k, 2, K_JOIN, (uint32_t)i);
        if (rc == QC_OK)
            rc = qc_path_cubic_to(ctx, out, c1, c2, b->entry);
    }
    if (rc == QC_OK)
        stats->motifs_placed += n;

out_free:
    qc__cgrid_free(ctx, &grid);
    qc__free(ctx, pr, n * sizeof *pr);
    qc__free(ctx, var, set->n * sizeof *var);
    qc_motif_set_free(ctx, &def);
    return rc;
}
