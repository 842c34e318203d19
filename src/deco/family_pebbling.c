/*
 * Pebbling (paper §5.3.1), rendering: one continuous path from the root
 * pebble, each circle drawn once counter-clockwise; at the tangent point of
 * each child (met counter-clockwise from where the circle was entered) the
 * path turns onto the child, draws it the same way and comes back to the
 * same point (paper Fig. 11 left). The path is the outline of the union of
 * the pebbles, so it touches itself at tangent points and never crosses.
 * Circles are drawn a little inside their radius (at most 0.05 mm, so
 * touching pebbles stay apart once stitches are rounded to machine units)
 * with cubic arcs that stay inside the circle. With edge overgrow the path
 * is then trimmed to the region, inset by the same amount, and joined along
 * its boundary (shared_pebble_trim.c).
 */
#include <math.h>
#include <string.h>

#include "pebble_internal.h"

#define ARC_K 0.99    /* handle length factor: a cubic arc of <= 90 degrees stays inside */
#define DRAW_IN 0.05  /* circles drawn this many mm inside their radius ... */
#define DRAW_IN_D 0.01 /* ... or this fraction of d when smaller */
#define TRIM_TOL 1e-3 /* flattening where trimmed, times d */

static qc_vec2 on_circle(qc_vec2 c, double r, double a)
{
    qc_vec2 p;
    double sn, cs;
    qc__sincos(a, &sn, &cs);
    p.x = c.x + r * cs;
    p.y = c.y + r * sn;
    return p;
}

/* The last angle an arc round one circle ended at, with its sine and cosine:
 * the next arc round it often starts there (HUGE_VAL: none yet). */
typedef struct turn {
    double a, s, c;
} turn;

/* The arc of (c, r) from angle a over sweep (> 0) counter-clockwise, from the
 * current point, in cubics of at most 90 degrees; ends at *end when given. */
static int arc(qc_ctx *ctx, qc_path *out, qc_vec2 c, double r, double a, double sweep,
               const qc_vec2 *end, turn *t)
{
    int i, m = (int)ceil(sweep / (QC_PI / 2) - 1e-9);
    double th, k, s1, c1, sq, cq;

    if (!(sweep > 1e-12))
        return end != NULL ? qc__peb_line(ctx, out, *end) : QC_OK;
    if (m < 1)
        m = 1;
    th = sweep / m;
    qc__sincos(th / 4, &sq, &cq);
    k = ARC_K * 4.0 / 3.0 * sq / cq * r;
    if (a == t->a && a != 0) { /* (the same bits but for the sign of a zero) */
        s1 = t->s;
        c1 = t->c;
    } else {
        qc__sincos(a, &s1, &c1);
    }
    for (i = 0; i < m; i++) {
        double a1 = a + th * (i + 1), s0 = s1, c0 = c1;
        qc_vec2 p0, p1, p2, p3;
        qc__sincos(a1, &s1, &c1);
        p0.x = c.x + r * c0;
        p0.y = c.y + r * s0;
        if (i + 1 == m && end != NULL) {
            p3 = *end;
        } else {
            p3.x = c.x + r * c1;
            p3.y = c.y + r * s1;
        }
        p1.x = p0.x - k * s0;
        p1.y = p0.y + k * c0;
        p2.x = p3.x + k * s1;
        p2.y = p3.y - k * c1;
        QC__TRY(qc__peb_cubic(ctx, out, p1, p2, p3));
        t->a = a1;
        t->s = s1;
        t->c = c1;
    }
    return QC_OK;
}

/* (0, 2 pi] */
static double wrap(double a)
{
    while (a <= 0)
        a += 2 * QC_PI;
    while (a > 2 * QC_PI)
        a -= 2 * QC_PI;
    return a;
}

typedef struct frame {
    uint32_t i, next;
    double entry, cur;  /* entry angle; how far round from it */
    qc_vec2 start, back; /* where this circle began; where its parent resumes */
    turn t;
} frame;

static int render(qc_ctx *ctx, const qc__pebbles *pb, double eps, qc_path *out)
{
    uint32_t *first = NULL, *kids = NULL;
    double *angle = NULL; /* each pebble's direction from its parent */
    frame *st = NULL;
    size_t sp = 0, cap = 0;
    double a0;
    int rc;

    rc = qc__pebbles_children(ctx, pb, &first, &kids, &a0, &angle);
    if (rc == QC_OK)
        rc = QC__RESERVE(ctx, st, cap, 64);
    /* room for the whole path at once, not by doublings (nor rounded up to
     * one: cut to size after drawing): per pebble at most 4 + (children + 1)
     * cubics and 2 lines, so 8 commands and 20 points */
    if (rc == QC_OK)
        rc = QC__RESERVE_EXACT(ctx, out->cmd, out->cmd_cap, out->ncmd + 8 * pb->n + 2);
    if (rc == QC_OK)
        rc = QC__RESERVE_EXACT(ctx, out->pt, out->pt_cap, out->npt + 20 * pb->n + 2);
    if (rc == QC_OK) {
        st[0].i = 0;
        st[0].next = first[0];
        st[0].entry = a0;
        st[0].cur = 0;
        st[0].start = on_circle(pb->c[0], pb->r[0] - eps, a0);
        st[0].back = st[0].start;
        st[0].t.a = HUGE_VAL;
        sp = 1;
        rc = out->ncmd == 0 ? qc_path_move_to(ctx, out, st[0].start)
                            : qc__peb_line(ctx, out, st[0].start);
    }
    while (rc == QC_OK && sp > 0) {
        frame *f = &st[sp - 1];
        uint32_t i = f->i;
        double ri = pb->r[i] - eps;
        if (f->next < first[i + 1]) {
            uint32_t c = kids[f->next++];
            double phi = angle[c];
            double key = wrap(phi - f->entry);
            qc_vec2 ti = on_circle(pb->c[i], ri, phi), tc = ti;
            rc = arc(ctx, out, pb->c[i], ri, f->entry + f->cur, key - f->cur, &ti, &f->t);
            if (key > f->cur)
                f->cur = key;
            /* a tangent child starts where its parent turns (a cusp the
             * stitches cannot cross); a bridged one at the end of its stitch */
            if (rc == QC_OK && (pb->flags[c] & QC__PEB_BRIDGE)) {
                tc = on_circle(pb->c[c], pb->r[c] - eps, phi + QC_PI);
                rc = qc__peb_line(ctx, out, tc);
            }
            if (rc == QC_OK)
                rc = QC__RESERVE(ctx, st, cap, sp + 1);
            if (rc == QC_OK) {
                frame *g = &st[sp++];
                g->i = c;
                g->next = first[c];
                g->entry = phi + QC_PI;
                g->cur = 0;
                g->start = tc;
                g->back = ti;
                g->t.a = HUGE_VAL;
            }
        } else {
            qc_vec2 back = f->back, start = f->start;
            rc = arc(ctx, out, pb->c[i], ri, f->entry + f->cur, 2 * QC_PI - f->cur, &start,
                     &f->t);
            sp--;
            if (rc == QC_OK && sp > 0 && (back.x != start.x || back.y != start.y))
                rc = qc__peb_line(ctx, out, back);
        }
    }
    qc__free(ctx, st, cap * sizeof *st);
    qc__free(ctx, first, (pb->n + 1) * sizeof *first);
    qc__free(ctx, kids, pb->n * sizeof *kids);
    qc__free(ctx, angle, pb->n * sizeof *angle);
    return rc;
}

int qc__pebbling_run(qc_ctx *ctx, const qc_region *region, const qc_params *params,
                     const qc_skeleton *skel, qc_path *out, qc_stats *stats, qc__pebbles *keep)
{
    qc__pbound b;
    qc__pebbles pb;
    qc_path raw = {0};
    double d = params->spacing;
    int rc;

    memset(&pb, 0, sizeof pb);
    if (skel == NULL || skel->n == 0)
        return qc__fail(ctx, QC_EEMPTY, "pebbling needs at least one point");
    if (region == NULL || region->nrings == 0)
        return qc__fail(ctx, QC_EEMPTY, "pebbling needs a region");
    rc = qc__pbound_init(ctx, &b, region, d, 4 * skel->n + 4096);
    if (rc != QC_OK)
        return rc;
    rc = qc__pebbles_pack(ctx, region, &b, params, skel, &pb);
    if (rc == QC_OK)
        pb.draw_in = fmin(DRAW_IN, DRAW_IN_D * d);
    if (rc == QC_OK && pb.k < 1) {
        rc = render(ctx, &pb, pb.draw_in, &raw);
        if (rc == QC_OK)
            rc = qc__path_trim(ctx, region, d, 4 * skel->n + 4096, pb.draw_in, &raw, pb.c[0],
                               TRIM_TOL * d, out, &pb.trim_jumps);
        qc_path_free(ctx, &raw);
    } else if (rc == QC_OK) {
        rc = render(ctx, &pb, pb.draw_in, out);
    }
    if (rc == QC_OK)
        qc__path_fit(ctx, out);
    if (rc == QC_OK && stats != NULL)
        rc = qc__pebbles_stats(ctx, &pb, &b, stats);
    qc_path_free(ctx, &raw);
    qc__pbound_free(ctx, &b);
    if (rc == QC_OK && keep != NULL)
        *keep = pb;
    else
        qc__pebbles_free(ctx, &pb);
    return rc;
}

int qc_deco_pebbling(qc_ctx *ctx, const qc_region *region, const qc_params *params,
                     const qc_skeleton *skel, const qc_motif_set *motifs, qc_path *out,
                     qc_stats *stats)
{
    (void)motifs;
    return qc__pebbling_run(ctx, region, params, skel, out, stats, NULL);
}

/* Snub-square points by default: their even spacing packs the pebbles tightest. */
int qc__pebble_param_default(const qc_params *p, int id, double *value)
{
    (void)p;
    if (id != QC_PARAM_ID_POINTS)
        return 0;
    *value = QC_POINTS_SNUB;
    return 1;
}

const qc_family_desc qc__family_pebbling = {
    QC_FAMILY_PEBBLING, "pebbling", "packed circles drawn as one path (paper §5.3.1)",
    QC_FAMILY_NEEDS_POINTS | QC_FAMILY_OWN_SEAMS,
    QC_PARAM_BIT(QC_PARAM_ID_EDGE) | QC_PARAM_BIT(QC_PARAM_ID_R_SEED), qc_deco_pebbling, qc__pebble_param_default};
