/*
 * Shape Packing (paper §5.3.2): pebbling first (shared_pebble_pack.c), then every
 * pebble replaced by a motif whose minimum bounding circle is the pebble
 * (the motif's unit frame scaled by the radius), turned so the motif's
 * start faces the pebble it hangs from (paper Fig. 12). The motifs stay one
 * path: each child is sewn as a detour from the point of its parent's motif
 * nearest the child's start, out and back along a short straight stitch.
 * The motif for each pebble is drawn from the set by the seed.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "pebble_internal.h"

#define FIT 0.999     /* motifs drawn this fraction of their pebble */
#define SAMPLES 16    /* per cubic when looking for the nearest point */
#define TRIM_TOL 1e-3 /* flattening where trimmed, times d */
#define DRAW_IN 0.05  /* motifs kept this many mm inside their pebble and the region ... */
#define DRAW_IN_D 0.01 /* ... or this fraction of d when smaller */

/* The SAMPLES + 1 points of every cubic of every motif in the set (unit
 * frame), computed once: each attachment only compares distances. */
typedef struct samples {
    qc_vec2 *pt;
    qc_bbox *box;  /* per cubic (at its first sample's index / (SAMPLES + 1)) */
    size_t *first; /* per motif, its first sample */
    size_t npt;    /* the samples (npt + 1 allocated) */
} samples;

static void samples_free(qc_ctx *ctx, const qc_motif_set *set, samples *sm)
{
    qc__free(ctx, sm->pt, (sm->npt + 1) * sizeof *sm->pt);
    qc__free(ctx, sm->box, (sm->npt / (SAMPLES + 1) + 1) * sizeof *sm->box);
    qc__free(ctx, sm->first, (set->n + 1) * sizeof *sm->first);
    memset(sm, 0, sizeof *sm);
}

static int samples_init(qc_ctx *ctx, const qc_motif_set *set, samples *sm)
{
    size_t i, j, n = 0;

    memset(sm, 0, sizeof *sm);
    sm->first = qc__alloc_array(ctx, set->n + 1, sizeof *sm->first);
    if (sm->first == NULL)
        return QC_ENOMEM;
    for (i = 0; i < set->n; i++) {
        const qc_path *p = &set->m[i].path;
        sm->first[i] = n;
        for (j = 1; j < p->ncmd; j++)
            n += p->cmd[j] == QC_PATH_CUBIC ? SAMPLES + 1 : 0;
    }
    sm->first[set->n] = n;
    sm->npt = n;
    sm->pt = qc__alloc_array(ctx, n + 1, sizeof *sm->pt); /* + 1: never empty */
    sm->box = qc__alloc_array(ctx, n / (SAMPLES + 1) + 1, sizeof *sm->box);
    if (sm->pt == NULL || sm->box == NULL) {
        samples_free(ctx, set, sm);
        return QC_ENOMEM;
    }
    for (i = 0; i < set->n; i++) {
        const qc_path *p = &set->m[i].path;
        qc_vec2 *out = sm->pt + sm->first[i], cur;
        size_t k;
        if (p->ncmd == 0)
            continue;
        k = qc_path_cmd_points(p->cmd[0]);
        cur = p->pt[0];
        for (j = 1; j < p->ncmd; j++) {
            const qc_vec2 *q = p->pt + k;
            k += qc_path_cmd_points(p->cmd[j]);
            if (p->cmd[j] == QC_PATH_CUBIC) {
                qc_vec2 c[4];
                int s;
                c[0] = cur;
                c[1] = q[0];
                c[2] = q[1];
                c[3] = q[2];
                qc_bbox *b = &sm->box[(size_t)(out - sm->pt) / (SAMPLES + 1)];
                for (s = 0; s <= SAMPLES; s++) {
                    *out = qc_cubic_point(c, (double)s / SAMPLES);
                    if (s == 0)
                        b->min = b->max = *out;
                    b->min.x = fmin(b->min.x, out->x);
                    b->min.y = fmin(b->min.y, out->y);
                    b->max.x = fmax(b->max.x, out->x);
                    b->max.y = fmax(b->max.y, out->y);
                    out++;
                }
                cur = q[2];
            } else {
                cur = q[0];
            }
        }
    }
    return QC_OK;
}

/* Squared distance from x to box b: no sample in b is nearer (rounding is
 * monotone, so this holds for the computed squares too). */
static double box_dist2(const qc_bbox *b, qc_vec2 x)
{
    double dx = x.x < b->min.x ? b->min.x - x.x : x.x > b->max.x ? x.x - b->max.x : 0;
    double dy = x.y < b->min.y ? b->min.y - x.y : x.y > b->max.y ? x.y - b->max.y : 0;
    return dx * dx + dy * dy;
}

/* Where on motif m (unit frame; its cubics sampled at smp, their boxes at
 * box) is nearest x: command *cmd at parameter *t. The squared distance
 * sorts out the farther samples, the box a cubic with none nearer; sqrt
 * only where it may decide (as strict as before, so ties still keep the
 * first). */
static void nearest_on(const qc_motif *m, const qc_vec2 *smp, const qc_bbox *box, qc_vec2 x,
                       uint32_t *cmd, double *t)
{
    const qc_path *p = &m->path;
    size_t j, k = qc_path_cmd_points(p->cmd[0]);
    double best = HUGE_VAL, best2 = HUGE_VAL;
    qc_vec2 cur = p->pt[0];

    *cmd = 1;
    *t = 0;
    for (j = 1; j < p->ncmd; j++) {
        const qc_vec2 *q = p->pt + k;
        k += qc_path_cmd_points(p->cmd[j]);
        if (p->cmd[j] == QC_PATH_CUBIC) {
            int s;
            if (!(box_dist2(box++, x) < best2)) { /* no sample has d2 < best2 */
                smp += SAMPLES + 1;
                cur = q[2];
                continue;
            }
            for (s = 0; s <= SAMPLES; s++, smp++) {
                double dx = smp->x - x.x, dy = smp->y - x.y, d2 = dx * dx + dy * dy, dd;
                if (!(d2 < best2))
                    continue; /* sqrt(d2) >= best */
                dd = sqrt(d2);
                if (dd < best) {
                    best = dd;
                    best2 = d2;
                    *cmd = (uint32_t)j;
                    *t = (double)s / SAMPLES;
                }
            }
            cur = q[2];
        } else {
            double ex = q[0].x - cur.x, ey = q[0].y - cur.y, l2 = ex * ex + ey * ey;
            double tt = l2 > 0 ? ((x.x - cur.x) * ex + (x.y - cur.y) * ey) / l2 : 0, dd;
            tt = tt < 0 ? 0 : tt > 1 ? 1 : tt;
            dd = qc_hypot(cur.x + tt * ex - x.x, cur.y + tt * ey - x.y);
            if (dd < best) {
                best = dd;
                best2 = dd * dd;
                *cmd = (uint32_t)j;
                *t = tt;
            }
            cur = q[0];
        }
    }
}

typedef struct att {
    uint32_t parent, kid, cmd;
    double t;
} att;

static int cmp_att(const void *pa, const void *pb)
{
    const att *a = pa, *b = pb;

    if (a->parent != b->parent)
        return a->parent < b->parent ? -1 : 1;
    if (a->cmd != b->cmd)
        return a->cmd < b->cmd ? -1 : 1;
    if (a->t != b->t)
        return a->t < b->t ? -1 : 1;
    return a->kid < b->kid ? -1 : a->kid > b->kid;
}

/* Per pebble a motif (seeded) and its map: entry turned towards the parent. */
static int place_motifs(qc_ctx *ctx, qc__pebbles *pb, const qc_motif_set *set, uint64_t seed,
                        double a0, double inset)
{
    size_t n = pb->n, i, nchoice = 0;
    uint32_t *choice = qc__alloc_array(ctx, set->n, sizeof *choice);
    double *have = qc__alloc_array(ctx, set->n, sizeof *have); /* entry angles */
    qc_rng rng;

    pb->motif = qc__alloc_array(ctx, n, sizeof *pb->motif);
    pb->xf = qc__alloc_array(ctx, n, sizeof *pb->xf);
    if (choice == NULL || have == NULL || pb->motif == NULL || pb->xf == NULL) {
        qc__free(ctx, choice, set->n * sizeof *choice);
        qc__free(ctx, have, set->n * sizeof *have);
        return QC_ENOMEM;
    }
    for (i = 0; i < set->n; i++) {
        const qc_motif *m = &set->m[i];
        have[i] = m->entry.x != 0 || m->entry.y != 0 ? qc_atan2(m->entry.y, m->entry.x)
                                                     : -QC_PI / 2;
    }
    for (i = 0; i < set->n; i++) /* closed motifs first; open ones only if that is all */
        if (set->m[i].legs == 0 && set->m[i].path.ncmd >= 2)
            choice[nchoice++] = (uint32_t)i;
    if (nchoice == 0)
        for (i = 0; i < set->n; i++)
            if (set->m[i].path.ncmd >= 2)
                choice[nchoice++] = (uint32_t)i;
    if (nchoice == 0) {
        qc__free(ctx, choice, set->n * sizeof *choice);
        qc__free(ctx, have, set->n * sizeof *have);
        return qc__fail(ctx, QC_EINVAL, "packing: the motif set has no drawable motif");
    }
    qc_rng_seed(&rng, seed ^ 0x7061636b696e67ull);
    for (i = 0; i < n; i++) {
        uint32_t p = pb->parent[i];
        double want, s, co, si;
        pb->motif[i] = choice[nchoice > 1 ? qc_rng_below(&rng, nchoice) : 0];
        want = p == QC__PEB_NONE ? a0
                                 : qc_atan2(pb->c[p].y - pb->c[i].y, pb->c[p].x - pb->c[i].x);
        s = FIT * pb->r[i] - inset;
        qc__sincos(want - have[pb->motif[i]], &si, &co);
        pb->xf[i].a = s * co;
        pb->xf[i].b = -s * si;
        pb->xf[i].c = s * si;
        pb->xf[i].d = s * co;
        pb->xf[i].tx = pb->c[i].x;
        pb->xf[i].ty = pb->c[i].y;
    }
    qc__free(ctx, choice, set->n * sizeof *choice);
    qc__free(ctx, have, set->n * sizeof *have);
    return QC_OK;
}

/* The motif points all copies would hold, refused over the budget for
 * npoints skeleton points (deco.h) before any copy is drawn. */
static int copies_budget(qc_ctx *ctx, const qc__pebbles *pb, const qc_motif_set *set,
                         size_t npoints)
{
    double total = 0, budget = QC_PACKED_POINTS_BUDGET(npoints);
    size_t i, most = 0;

    for (i = 0; i < pb->n; i++) {
        size_t k = set->m[pb->motif[i]].path.npt;
        total += (double)k;
        most = k > most ? k : most;
    }
    if (total > budget)
        return qc__fail(ctx, QC_ELIMIT,
                        "packing: %lu motif copies (up to %lu points each) make %.0f points, "
                        "over the limit of %.0f for %lu points; use a simpler motif or raise "
                        "the spacing",
                        (unsigned long)pb->n, (unsigned long)most, total, budget,
                        (unsigned long)npoints);
    return QC_OK;
}

/* The budget before any pebble is placed: every skeleton point makes about
 * one pebble or more (1.35-1.45 on the lattices), each drawn with a choosable
 * motif, so npoints copies of the smallest already over the budget are
 * refused at once (the exact count follows once the motifs are chosen). */
static int copies_estimate(qc_ctx *ctx, const qc_motif_set *set, size_t npoints, double d)
{
    double budget = QC_PACKED_POINTS_BUDGET(npoints);
    size_t i, least = 0;
    const qc_motif *pick = NULL;
    int closed = 0;

    for (i = 0; i < set->n; i++) /* closed motifs when there are any, as place_motifs */
        closed |= set->m[i].legs == 0 && set->m[i].path.ncmd >= 2;
    for (i = 0; i < set->n; i++) {
        const qc_motif *m = &set->m[i];
        if (m->path.ncmd < 2 || (closed && m->legs != 0))
            continue;
        if (pick == NULL || m->path.npt < least) {
            pick = m;
            least = m->path.npt;
        }
    }
    if (pick != NULL && (double)npoints * (double)least > budget)
        return qc__fail(ctx, QC_ELIMIT,
                        "packing: about %.0f motif points (%lu points at spacing %g mm, "
                        "motif %s of %lu points) exceed the limit of %.0f; raise the spacing "
                        "or use a simpler motif",
                        (double)npoints * (double)least, (unsigned long)npoints, d, pick->name,
                        (unsigned long)least, budget);
    return QC_OK;
}

/* x in the unit frame of f. */
static qc_vec2 unmap(const qc__xf *f, qc_vec2 x)
{
    double det = f->a * f->d - f->b * f->c, dx = x.x - f->tx, dy = x.y - f->ty;
    qc_vec2 u;
    u.x = (f->d * dx - f->b * dy) / det;
    u.y = (-f->c * dx + f->a * dy) / det;
    return u;
}

typedef struct frame {
    uint32_t i, cmd, pt;   /* pebble; its motif's command and point offset */
    uint32_t next;         /* next attachment */
    int loaded;
    double t0;             /* the command is drawn up to t0 */
    qc_vec2 seg[4];        /* the command's remaining piece, mm */
    qc_vec2 back;          /* where the parent resumes */
} frame;

static void start_frame(frame *g, uint32_t i, uint32_t next, const qc_motif *m, qc_vec2 back)
{
    g->i = i;
    g->cmd = 1;
    g->pt = (uint32_t)qc_path_cmd_points(m->path.cmd[0]);
    g->next = next;
    g->loaded = 0;
    g->t0 = 0;
    g->back = back;
}

/* Room for everything render draws, reserved once: a 10^6-point packing's
 * path is hundreds of MB, and doubling would leave up to half of it unused
 * (the peak bytes per point) and copy it on every growth. The first stitch;
 * per motif its commands but the move, the stitch closing an open motif and
 * the one back to the parent; per child the piece of the command it splits
 * (a cubic) and the stitch out to it. */
static int reserve_render(qc_ctx *ctx, const qc__pebbles *pb, const qc_motif_set *set,
                          const uint32_t *first, qc_path *out)
{
    size_t i, ncmd = out->ncmd + 1, npt = out->npt + 1;

    for (i = 0; i < pb->n; i++) {
        const qc_path *m = &set->m[pb->motif[i]].path;
        size_t kids = first[i + 1] - first[i];
        ncmd += m->ncmd + 1 + 2 * kids;
        npt += m->npt + 1 + 4 * kids;
    }
    QC__TRY(QC__RESERVE_EXACT(ctx, out->cmd, out->cmd_cap, ncmd));
    return QC__RESERVE_EXACT(ctx, out->pt, out->pt_cap, npt);
}

static int render(qc_ctx *ctx, const qc__pebbles *pb, const qc_motif_set *set,
                  const att *atts, const uint32_t *first, qc_path *out)
{
    frame *st = NULL;
    size_t sp = 0, cap = 0;
    qc_vec2 e0;
    int rc = reserve_render(ctx, pb, set, first, out);

    if (rc != QC_OK)
        return rc;
    e0 = qc__xf_apply(&pb->xf[0], set->m[pb->motif[0]].entry);
    rc = QC__RESERVE(ctx, st, cap, 64);
    if (rc == QC_OK) {
        start_frame(&st[0], 0, first[0], &set->m[pb->motif[0]], e0);
        sp = 1;
        rc = out->ncmd == 0 ? qc_path_move_to(ctx, out, e0) : qc__peb_line(ctx, out, e0);
    }
    while (rc == QC_OK && sp > 0) {
        frame *f = &st[sp - 1];
        const qc_motif *m = &set->m[pb->motif[f->i]];
        const qc__xf *xf = &pb->xf[f->i];
        int cubic;
        if (f->cmd >= m->path.ncmd) { /* done: an open motif comes back to its start */
            qc_vec2 entry = qc__xf_apply(xf, m->entry), back = f->back;
            if (m->legs != 0 || m->exit.x != m->entry.x || m->exit.y != m->entry.y)
                rc = qc__peb_line(ctx, out, entry);
            sp--;
            if (rc == QC_OK && sp > 0)
                rc = qc__peb_line(ctx, out, back);
            continue;
        }
        cubic = m->path.cmd[f->cmd] == QC_PATH_CUBIC;
        if (!f->loaded) {
            f->seg[0] = qc_path_last(out);
            f->seg[1] = qc__xf_apply(xf, m->path.pt[f->pt]);
            if (cubic) {
                f->seg[2] = qc__xf_apply(xf, m->path.pt[f->pt + 1]);
                f->seg[3] = qc__xf_apply(xf, m->path.pt[f->pt + 2]);
            }
            f->t0 = 0;
            f->loaded = 1;
        }
        if (f->next < first[f->i + 1] && atts[f->next].cmd == f->cmd) {
            const att *a = &atts[f->next++];
            double t = a->t;
            qc_vec2 q, ek;
            if (t > f->t0 + 1e-12 && f->t0 < 1) {
                double tl = (t - f->t0) / (1 - f->t0);
                if (cubic) {
                    qc_vec2 l[4], r[4];
                    int z;
                    qc_cubic_split(f->seg, tl, l, r);
                    rc = qc__peb_cubic(ctx, out, l[1], l[2], l[3]);
                    for (z = 0; z < 4; z++)
                        f->seg[z] = r[z];
                } else {
                    f->seg[0].x += tl * (f->seg[1].x - f->seg[0].x);
                    f->seg[0].y += tl * (f->seg[1].y - f->seg[0].y);
                    rc = qc__peb_line(ctx, out, f->seg[0]);
                }
                f->t0 = t;
            }
            q = qc_path_last(out);
            ek = qc__xf_apply(&pb->xf[a->kid], set->m[pb->motif[a->kid]].entry);
            if (rc == QC_OK)
                rc = qc__peb_line(ctx, out, ek);
            if (rc == QC_OK)
                rc = QC__RESERVE(ctx, st, cap, sp + 1);
            if (rc == QC_OK) {
                start_frame(&st[sp], a->kid, first[a->kid], &set->m[pb->motif[a->kid]], q);
                sp++;
            }
            continue;
        }
        if (f->t0 < 1 - 1e-12)
            rc = cubic ? qc__peb_cubic(ctx, out, f->seg[1], f->seg[2], f->seg[3])
                       : qc__peb_line(ctx, out, f->seg[1]);
        f->pt += (uint32_t)qc_path_cmd_points(m->path.cmd[f->cmd]);
        f->cmd++;
        f->loaded = 0;
    }
    qc__free(ctx, st, cap * sizeof *st);
    return rc;
}

/* Children grouped by parent, in the order their parent's motif meets them. */
static int attachments(qc_ctx *ctx, const qc__pebbles *pb, const qc_motif_set *set,
                       att **atts_out, uint32_t **first_out)
{
    size_t n = pb->n, i, g;
    att *atts = qc__alloc_array(ctx, n, sizeof *atts);
    uint32_t *first = qc__alloc_array(ctx, n + 1, sizeof *first);
    samples sm;

    *atts_out = atts;
    *first_out = first;
    if (atts == NULL || first == NULL)
        return QC_ENOMEM;
    QC__TRY(samples_init(ctx, set, &sm));
    qc__pebbles_group_starts(pb, first); /* first[p] runs to the group's end */
    for (i = 0; i < n; i++) {
        uint32_t p = pb->parent[i];
        qc_vec2 e;
        att *a;
        if (p == QC__PEB_NONE)
            continue;
        a = &atts[first[p]++];
        e = qc__xf_apply(&pb->xf[i], set->m[pb->motif[i]].entry);
        a->parent = p;
        a->kid = (uint32_t)i;
        nearest_on(&set->m[pb->motif[p]], sm.pt + sm.first[pb->motif[p]],
                   sm.box + sm.first[pb->motif[p]] / (SAMPLES + 1), unmap(&pb->xf[p], e),
                   &a->cmd, &a->t);
    }
    samples_free(ctx, set, &sm);
    for (i = n; i > 0; i--)
        first[i] = first[i - 1];
    first[0] = 0;
    for (g = 0; g < n; g++) /* each group (a few children) in the order cmp_att gives */
        for (i = first[g] + 1; i < first[g + 1]; i++) {
            att x = atts[i];
            size_t k = i;
            for (; k > first[g] && cmp_att(&atts[k - 1], &x) > 0; k--)
                atts[k] = atts[k - 1];
            atts[k] = x;
        }
    return QC_OK;
}

int qc__packing_run(qc_ctx *ctx, const qc_region *region, const qc_params *params,
                    const qc_skeleton *skel, const qc_motif_set *motifs, qc_path *out,
                    qc_stats *stats, qc__pebbles *keep)
{
    qc__pbound b;
    qc__pebbles pb;
    qc_motif_set def = {0};
    qc_path raw = {0};
    uint32_t *first = NULL;
    att *atts = NULL;
    double d = params->spacing, a0 = 0;
    size_t n = 0;
    int rc;

    memset(&pb, 0, sizeof pb);
    memset(&b, 0, sizeof b);
    if (skel == NULL || skel->n == 0)
        return qc__fail(ctx, QC_EEMPTY, "packing needs at least one point");
    if (region == NULL || region->nrings == 0)
        return qc__fail(ctx, QC_EEMPTY, "packing needs a region");
    if (motifs == NULL || motifs->n == 0) {
        rc = qc_motif_builtin(ctx, "heart", &def);
        if (rc != QC_OK)
            goto out;
        motifs = &def;
    }
    rc = copies_estimate(ctx, motifs, skel->n, d);
    if (rc == QC_OK)
        rc = qc__pbound_init(ctx, &b, region, d, 4 * skel->n + 4096);
    if (rc == QC_OK)
        rc = qc__pebbles_pack(ctx, region, &b, params, skel, &pb);
    n = pb.n;
    pb.draw_in = fmin(DRAW_IN, DRAW_IN_D * d);
    if (rc == QC_OK) /* the root's motif faces the middle of its widest gap */
        rc = qc__pebbles_start_angle(ctx, &pb, &a0);
    if (rc == QC_OK)
        rc = place_motifs(ctx, &pb, motifs, params->seed, a0, pb.draw_in);
    if (rc == QC_OK)
        rc = copies_budget(ctx, &pb, motifs, skel->n);
    if (rc == QC_OK)
        rc = attachments(ctx, &pb, motifs, &atts, &first);
    if (rc == QC_OK && pb.k < 1) {
        rc = render(ctx, &pb, motifs, atts, first, &raw);
        if (rc == QC_OK)
            rc = qc__path_trim(ctx, region, d, 4 * skel->n + 4096, pb.draw_in, &raw, pb.c[0],
                               TRIM_TOL * d, out, &pb.trim_jumps);
        qc_path_free(ctx, &raw);
    } else if (rc == QC_OK) {
        rc = render(ctx, &pb, motifs, atts, first, out);
    }
    if (rc == QC_OK)
        qc__path_fit(ctx, out);
    if (rc == QC_OK && stats != NULL) {
        rc = qc__pebbles_stats(ctx, &pb, &b, stats);
        stats->motifs_placed += pb.n;
    }
out:
    qc__free(ctx, atts, n * sizeof *atts);
    qc__free(ctx, first, (n + 1) * sizeof *first);
    qc_path_free(ctx, &raw);
    qc__pbound_free(ctx, &b);
    qc_motif_set_free(ctx, &def);
    if (rc == QC_OK && keep != NULL)
        *keep = pb;
    else
        qc__pebbles_free(ctx, &pb);
    return rc;
}

int qc_deco_packing(qc_ctx *ctx, const qc_region *region, const qc_params *params,
                    const qc_skeleton *skel, const qc_motif_set *motifs, qc_path *out,
                    qc_stats *stats)
{
    return qc__packing_run(ctx, region, params, skel, motifs, out, stats, NULL);
}

const qc_family_desc qc__family_packing = {
    QC_FAMILY_PACKING, "packing", "pebbles replaced by motifs, one path (paper §5.3.2)",
    QC_FAMILY_NEEDS_POINTS | QC_FAMILY_NEEDS_MOTIFS | QC_FAMILY_OWN_SEAMS,
    QC_PARAM_BIT(QC_PARAM_ID_EDGE) | QC_PARAM_BIT(QC_PARAM_ID_R_SEED), qc_deco_packing,
    qc__pebble_param_default};
