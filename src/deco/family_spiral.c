/*
 * Spiral (beyond the paper): one spiral from a centre (the point farthest
 * from the boundary, or start-x/start-y), clipped to the region minus its
 * margin, the pieces joined by running along the margin's offset ring
 * (shared_sdf.c) from where the spiral leaves to where it comes back, so the
 * result is one continuous path inside the region. The spiral is clipped
 * at its exact crossings with the ring's polyline (whose vertices lie on
 * the margin and chords within 0.2% of d of it), and every crossing
 * becomes a ring vertex, so bridges and pieces meet without crossing.
 *
 * Archimedean: r = b theta, b = d / 2 pi (turns d apart). Fermat:
 * r = c sqrt(theta), c = d / sqrt(2 pi): every turn adds the same area
 * (pi d^2), so the first turn has radius d and turn n radius d sqrt(n),
 * d (sqrt(n + 1) - sqrt(n)) from the next: the spacing never exceeds d and
 * shrinks outward (path length grows as R^3 / d^2).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "deco_internal.h"

#define GRID (1.0 / 3.0)   /* distance grid spacing, times d */
#define MIN_MARGIN 1e-3    /* least margin, times d */
#define CHORD (1.0 / 6.0)  /* longest spiral chord, times d */
#define MAX_STEP (QC_PI / 24.0)
#define GAP_RES (1.0 / 6.0)
#define MAX_SAMPLES ((double)(1u << 24))

/* A crossing of the rings: on segment g at parameter t. */
typedef struct ins {
    uint32_t g;
    double t;
    double along;        /* parameter along the spiral's chord */
    uint32_t id;         /* index into pts */
    uint32_t cross;      /* its number in crossing order */
} ins;

typedef struct spiral {
    const qc__sdf *s;
    double d, m;
    int fermat;
    double b;            /* archimedean: r = b theta; fermat: r = b sqrt(theta) */
    qc_vec2 c;           /* centre */
    qc__rings ring;      /* the margin's offset rings */
    uint32_t *ring_of;   /* per vertex */
    double *arc;         /* per vertex: arc length from its ring's first vertex */
    double *perim;       /* per ring */
    qc__seg_grid grid;   /* over the rings (a segment is named by its first vertex) */
    qc_points pts;       /* the spiral's parts inside the margin, in order */
    ins *cr;             /* every crossing of the margin's rings, in order */
    size_t ncr, cr_cap;
    uint32_t *exits;     /* per excursion: its leaving crossing (the next comes back) */
    size_t nexits, exits_cap;
    uint32_t *stamp;     /* per ring vertex: the chord that last tested its segment */
    size_t nstamp;
    uint32_t chord;
    size_t jumps;        /* bridges between different rings (straight) */
} spiral;

static size_t rbegin(const spiral *sp, uint32_t k)
{
    return k ? sp->ring.end.i[k - 1] : 0;
}

static uint32_t vnext(const spiral *sp, uint32_t g, int dir)
{
    uint32_t k = sp->ring_of[g];
    size_t b = rbegin(sp, k), e = sp->ring.end.i[k];

    if (dir > 0)
        return g + 1 == e ? (uint32_t)b : g + 1;
    return g == b ? (uint32_t)(e - 1) : g - 1;
}

static double dist(qc_vec2 a, qc_vec2 b)
{
    return qc_hypot(a.x - b.x, a.y - b.y);
}

static void free_index(qc_ctx *ctx, spiral *sp)
{
    qc__free(ctx, sp->ring_of, sp->ring.pts.n * sizeof *sp->ring_of);
    qc__free(ctx, sp->arc, sp->ring.pts.n * sizeof *sp->arc);
    qc__free(ctx, sp->perim, sp->ring.end.n * sizeof *sp->perim);
    sp->ring_of = NULL;
    sp->arc = NULL;
    sp->perim = NULL;
}

/* Per vertex its ring and arc length, per ring its perimeter. */
static int index_arcs(qc_ctx *ctx, spiral *sp)
{
    const qc_vec2 *p = sp->ring.pts.v;
    size_t n = sp->ring.pts.n, nr = sp->ring.end.n, k, g;

    sp->ring_of = qc__alloc_array(ctx, n, sizeof *sp->ring_of);
    sp->arc = qc__alloc_array(ctx, n, sizeof *sp->arc);
    sp->perim = qc__alloc_array(ctx, nr, sizeof *sp->perim);
    if (sp->ring_of == NULL || sp->arc == NULL || sp->perim == NULL)
        return QC_ENOMEM;
    for (k = 0, g = 0; k < nr; k++) {
        double run = 0.0;
        size_t b = g;
        for (; g < sp->ring.end.i[k]; g++) {
            sp->ring_of[g] = (uint32_t)k;
            if (g > b)
                run += dist(p[g - 1], p[g]);
            sp->arc[g] = run;
        }
        sp->perim[k] = run + dist(p[g - 1], p[b]);
    }
    return QC_OK;
}

static uint32_t next_vertex(const void *ud, uint32_t g)
{
    return vnext((const spiral *)ud, g, 1);
}

/* The segment grid over the rings. */
static int index_rings(qc_ctx *ctx, spiral *sp)
{
    QC__TRY(index_arcs(ctx, sp));
    return qc__seg_grid_build(ctx, &sp->grid, sp->ring.pts.v, sp->ring.pts.n, next_vertex, sp,
                              sp->d, 4.0);
}

/* The spiral point at angle th (radians from the start). */
static qc_vec2 at(const spiral *sp, double th)
{
    double r = sp->fermat ? sp->b * sqrt(th) : sp->b * th;
    qc_vec2 q;

    q.x = sp->c.x + r * qc_cos(th);
    q.y = sp->c.y + r * qc_sin(th);
    return q;
}

/* The next angle: chords at most CHORD d long and MAX_STEP wide. */
static double next_angle(const spiral *sp, double th)
{
    double r, dr, speed, step;

    if (sp->fermat) {
        r = sp->b * sqrt(th);
        dr = th > 0.0 ? sp->b / (2.0 * sqrt(th)) : HUGE_VAL;
    } else {
        r = sp->b * th;
        dr = sp->b;
    }
    speed = sqrt(r * r + dr * dr);
    step = speed > 0.0 ? CHORD * sp->d / speed : MAX_STEP;
    if (th == 0.0 && sp->fermat) /* r grows as sqrt: first step by radius */
        step = (CHORD * sp->d / sp->b) * (CHORD * sp->d / sp->b);
    return th + (step < MAX_STEP ? step : MAX_STEP);
}

static int emit(qc_ctx *ctx, qc_points *out, qc_vec2 p)
{
    if (out->n > 0 && out->v[out->n - 1].x == p.x && out->v[out->n - 1].y == p.y)
        return QC_OK;
    return qc_points_push(ctx, out, p);
}

/* Whether chord p-q crosses segment a-b: exact predicates, a point on the
 * other's line counting as on its left (so shared vertices and touching
 * chords are counted once, consistently). */
static int crosses(qc_vec2 p, qc_vec2 q, qc_vec2 a, qc_vec2 b, double *t_ab, double *t_pq)
{
    double o1 = qc_orient2d(a, b, p), o2 = qc_orient2d(a, b, q), o3, o4;

    if ((o1 >= 0.0) == (o2 >= 0.0))
        return 0;
    o3 = qc_orient2d(p, q, a);
    o4 = qc_orient2d(p, q, b);
    if ((o3 >= 0.0) == (o4 >= 0.0))
        return 0;
    *t_ab = o3 / (o3 - o4);
    *t_pq = o1 / (o1 - o2);
    return 1;
}

/* Whether p is inside the margin's rings: the parity of a ray's crossings,
 * counted as chord_hits counts them. */
static int in_rings(const spiral *sp, qc_vec2 p)
{
    const qc_vec2 *v = sp->ring.pts.v;
    qc_vec2 far = p;
    size_t g;
    int in = 0;

    for (g = 0; g < sp->ring.pts.n; g++)
        far.x = v[g].x > far.x ? v[g].x : far.x;
    far.x += 1.0 + sp->d;
    for (g = 0; g < sp->ring.pts.n; g++) {
        double t, u;
        if (crosses(p, far, v[g], v[vnext(sp, (uint32_t)g, 1)], &t, &u))
            in = !in;
    }
    return in;
}

static int cmp_hit(const void *pa, const void *pb);

/* Appends the crossings of chord p-q with the rings to sp->cr, sorted
 * along the chord. */
static int chord_hits(qc_ctx *ctx, spiral *sp, qc_vec2 p, qc_vec2 q)
{
    const qc_vec2 *v = sp->ring.pts.v;
    const qc__seg_grid *gr = &sp->grid;
    size_t c[4], x, y, i, first = sp->ncr;

    qc__seg_grid_cells(gr, p, q, c);
    sp->chord++;
    for (y = c[1]; y <= c[3]; y++)
        for (x = c[0]; x <= c[2]; x++)
            for (i = gr->start[y * gr->gx + x]; i < gr->start[y * gr->gx + x + 1]; i++) {
                uint32_t g = gr->seg[i];
                double t, u;

                if (sp->stamp[g] == sp->chord)
                    continue;
                sp->stamp[g] = sp->chord;
                if (!crosses(p, q, v[g], v[vnext(sp, g, 1)], &t, &u))
                    continue;
                QC__TRY(QC__RESERVE(ctx, sp->cr, sp->cr_cap, sp->ncr + 1));
                sp->cr[sp->ncr].g = g;
                sp->cr[sp->ncr].t = t;     /* along the ring segment */
                sp->cr[sp->ncr].along = u; /* along the chord */
                sp->ncr++;
            }
    if (sp->ncr - first > 1)
        qsort(sp->cr + first, sp->ncr - first, sizeof *sp->cr, cmp_hit);
    return QC_OK;
}

/* The grid's distance at p; -HUGE_VAL off the grid. */
static double field(const spiral *sp, qc_vec2 p)
{
    const qc__sdf *s = sp->s;

    if (p.x < s->x0 || p.y < s->y0 || p.x > s->x0 + (double)(s->nx - 1) * s->h ||
        p.y > s->y0 + (double)(s->ny - 1) * s->h)
        return -HUGE_VAL;
    return qc__sdf_at(s, p);
}

/* The angle at which the spiral reaches radius r. */
static double angle_at(const spiral *sp, double r)
{
    return sp->fermat ? (r / sp->b) * (r / sp->b) : r / sp->b;
}

/* Walks the spiral from r_start (inside it nothing of the region lies) out
 * to r_max, keeping the parts inside the margin's rings (sp->pts; every
 * crossing is a point there) and noting each excursion outside (sp->exits;
 * the crossing after comes back). */
static int trace(qc_ctx *ctx, spiral *sp, double r_start, double r_max)
{
    double th = angle_at(sp, r_start), th_max = angle_at(sp, r_max);
    qc_vec2 prev = at(sp, th), cur;
    double far = CHORD * sp->d + 2.0 * sp->s->h, vprev = field(sp, prev), vcur;
    int in = in_rings(sp, prev);

    if (in)
        QC__TRY(qc_points_push(ctx, &sp->pts, prev));
    while (th < th_max) {
        size_t c0 = sp->ncr, c;

        th = next_angle(sp, th);
        cur = at(sp, th);
        vcur = field(sp, cur);
        /* a chord whose ends both lie farther from the margin than it is
         * long (with the grid's slack) cannot cross the margin's rings */
        if (!((vprev > sp->m + far && vcur > sp->m + far) ||
              (vprev < sp->m - far && vcur < sp->m - far)))
            QC__TRY(chord_hits(ctx, sp, prev, cur));
        vprev = vcur;
        for (c = c0; c < sp->ncr; c++) {
            ins *h = &sp->cr[c];
            qc_vec2 a = sp->ring.pts.v[h->g], b = sp->ring.pts.v[vnext(sp, h->g, 1)], x;

            x.x = a.x + h->t * (b.x - a.x);
            x.y = a.y + h->t * (b.y - a.y);
            if (in) { /* leaving */
                QC__TRY(QC__RESERVE(ctx, sp->exits, sp->exits_cap, sp->nexits + 1));
                sp->exits[sp->nexits++] = (uint32_t)c;
            }
            h->id = (uint32_t)sp->pts.n;
            h->cross = (uint32_t)c;
            QC__TRY(qc_points_push(ctx, &sp->pts, x));
            in = !in;
        }
        if (in)
            QC__TRY(emit(ctx, &sp->pts, cur));
        prev = cur;
    }
    if (sp->nexits > 0 && sp->exits[sp->nexits - 1] + 1 >= sp->ncr)
        sp->nexits--; /* the last excursion never comes back */
    return QC_OK;
}

static int cmp_hit(const void *pa, const void *pb)
{
    const ins *a = pa, *b = pb;

    if (a->along != b->along)
        return a->along < b->along ? -1 : 1;
    return (a->g > b->g) - (a->g < b->g);
}

static int cmp_ins(const void *pa, const void *pb)
{
    const ins *a = pa, *b = pb;

    if (a->g != b->g)
        return a->g < b->g ? -1 : 1;
    if (a->t != b->t)
        return a->t < b->t ? -1 : 1;
    return (a->id > b->id) - (a->id < b->id);
}

/* Puts every crossing into the rings as a vertex; vid[c]: crossing c's. */
static int insert_crossings(qc_ctx *ctx, spiral *sp, ins *in, size_t nin, uint32_t *vid)
{
    qc__rings nr;
    size_t k, g, q = 0;
    int rc = QC_OK;

    memset(&nr, 0, sizeof nr);
    if (nin > 1) /* qsort wants a real array, even for nothing to sort */
        qsort(in, nin, sizeof *in, cmp_ins);
    for (k = 0, g = 0; k < sp->ring.end.n && rc == QC_OK; k++) {
        for (; g < sp->ring.end.i[k] && rc == QC_OK; g++) {
            rc = qc_points_push(ctx, &nr.pts, sp->ring.pts.v[g]);
            for (; q < nin && in[q].g == g && rc == QC_OK; q++) {
                vid[in[q].cross] = (uint32_t)nr.pts.n;
                rc = qc_points_push(ctx, &nr.pts, sp->pts.v[in[q].id]);
            }
        }
        if (rc == QC_OK)
            rc = qc_order_push(ctx, &nr.end, (uint32_t)nr.pts.n);
        if (rc == QC_OK)
            rc = qc_order_push(ctx, &nr.level, 0);
    }
    if (rc < 0) {
        qc__rings_free(ctx, &nr);
        return rc;
    }
    free_index(ctx, sp);
    qc__rings_free(ctx, &sp->ring);
    sp->ring = nr;
    return index_arcs(ctx, sp);
}

/* Along the margin's ring from vertex a to vertex b, the shorter way (the
 * points strictly between are appended); a straight jump if they lie on
 * different rings (a margin that splits the region). */
static int bridge(qc_ctx *ctx, spiral *sp, uint32_t a, uint32_t b, qc_points *out)
{
    const qc_vec2 *p = sp->ring.pts.v;
    uint32_t k = sp->ring_of[a], g;
    double per = sp->perim[k], fwd;
    int dir;

    if (sp->ring_of[b] != k) {
        sp->jumps++;
        return QC_OK;
    }
    fwd = fmod(sp->arc[b] - sp->arc[a] + 2.0 * per, per);
    dir = fwd <= per - fwd ? 1 : -1;
    for (g = vnext(sp, a, dir); g != b; g = vnext(sp, g, dir))
        QC__TRY(emit(ctx, out, p[g]));
    return QC_OK;
}

/* The inside parts joined by bridges into *out. */
static int join(qc_ctx *ctx, spiral *sp, qc_points *out)
{
    size_t n = sp->ncr, i, e = 0;
    uint32_t *vid = qc__alloc_array(ctx, n ? n : 1, sizeof *vid);
    uint32_t *ptid = qc__alloc_array(ctx, n ? n : 1, sizeof *ptid);
    int rc = QC_ENOMEM;

    if (vid == NULL || ptid == NULL)
        goto out;
    for (i = 0; i < n; i++) /* insert_crossings reorders sp->cr */
        ptid[i] = sp->cr[i].id;
    rc = insert_crossings(ctx, sp, sp->cr, n, vid);
    for (i = 0; i < sp->pts.n && rc == QC_OK; i++) {
        rc = emit(ctx, out, sp->pts.v[i]);
        if (rc == QC_OK && e < sp->nexits && ptid[sp->exits[e]] == i) {
            rc = bridge(ctx, sp, vid[sp->exits[e]], vid[sp->exits[e] + 1], out);
            e++;
        }
    }
out:
    qc__free(ctx, vid, (n ? n : 1) * sizeof *vid);
    qc__free(ctx, ptid, (n ? n : 1) * sizeof *ptid);
    return rc;
}

static qc_vec2 centre_of(const qc_params *params, const qc__sdf *s)
{
    qc_vec2 c;

    if (qc_params_given(params, QC_PARAM_ID_START_X) ||
        qc_params_given(params, QC_PARAM_ID_START_Y)) {
        c.x = params->start_x;
        c.y = params->start_y;
    } else {
        qc__sdf_max(s, &c);
    }
    return c;
}

static void spiral_free(qc_ctx *ctx, spiral *sp)
{
    free_index(ctx, sp);
    qc__seg_grid_free(ctx, &sp->grid);
    qc__free(ctx, sp->exits, sp->exits_cap * sizeof *sp->exits);
    qc__free(ctx, sp->cr, sp->cr_cap * sizeof *sp->cr);
    qc__free(ctx, sp->stamp, sp->nstamp * sizeof *sp->stamp);
    qc__rings_free(ctx, &sp->ring);
    qc_points_free(ctx, &sp->pts);
}

int qc_deco_spiral(qc_ctx *ctx, const qc_region *region, const qc_params *params,
                   const qc_skeleton *skel, const qc_motif_set *motifs, qc_path *out,
                   qc_stats *stats)
{
    qc__sdf s;
    spiral sp;
    qc_path one = {0};
    qc_points line = {0};
    qc_bbox box;
    qc_vec2 at_max;
    double d = params->spacing, r_max = 0.0, r_start, dx, dy, samples;
    size_t i;
    int rc, k;

    (void)skel;
    (void)motifs;
    memset(&s, 0, sizeof s);
    memset(&sp, 0, sizeof sp);
    if (region == NULL || region->nrings == 0)
        return qc__fail(ctx, QC_EEMPTY, "spiral: the region has no outline");
    if (!(d > 0.0) || !isfinite(d))
        return qc__fail(ctx, QC_ERANGE, "spiral: spacing %g mm must be > 0", d);
    QC__TRY(qc__sdf_build(ctx, region, GRID * d, &s));
    sp.s = &s;
    sp.d = d;
    sp.m = fmax(params->margin, MIN_MARGIN * d);
    sp.fermat = params->spiral == QC_SPIRAL_FERMAT;
    sp.b = sp.fermat ? d / sqrt(2.0 * QC_PI) : d / (2.0 * QC_PI);
    sp.c = centre_of(params, &s);
    if (s.h > 0.5 * d) {
        rc = qc__fail(ctx, QC_ELIMIT, "spiral: spacing %g mm is too fine for a region this "
                      "size (grid %g mm)", d, s.h);
        goto out;
    }
    if (!(qc__sdf_max(&s, &at_max) > sp.m)) {
        rc = qc__fail(ctx, QC_EEMPTY, "spiral: nothing lies inside the margin of %g mm", sp.m);
        goto out;
    }
    box = qc_region_bbox(region);
    for (k = 0; k < 4; k++) {
        qc_vec2 corner;
        corner.x = k & 1 ? box.max.x : box.min.x;
        corner.y = k & 2 ? box.max.y : box.min.y;
        r_max = fmax(r_max, dist(corner, sp.c));
    }
    r_max += d;
    /* a centre off the block: the turns that stay clear of its box are skipped */
    dx = fmax(fmax(box.min.x - sp.c.x, sp.c.x - box.max.x), 0.0);
    dy = fmax(fmax(box.min.y - sp.c.y, sp.c.y - box.max.y), 0.0);
    r_start = fmax(qc_hypot(dx, dy) - 2.0 * d, 0.0);
    samples = sp.fermat ? ((r_max / d) * (r_max / d) * (r_max / d) -
                           (r_start / d) * (r_start / d) * (r_start / d)) * 2.0 * QC_PI / CHORD
                        : QC_PI * (r_max * r_max - r_start * r_start) / (d * d * CHORD);
    if (samples > MAX_SAMPLES) {
        rc = qc__fail(ctx, QC_ELIMIT, "spiral: %.3g samples (%s spiral out to %g mm at spacing "
                      "%g mm) exceed the limit of %.3g", samples,
                      sp.fermat ? "fermat" : "archimedean", r_max, d, MAX_SAMPLES);
        goto out;
    }
    rc = qc__sdf_rings(ctx, &s, sp.m, d, 1, &sp.ring);
    if (rc == QC_OK && sp.ring.end.n == 0)
        rc = qc__fail(ctx, QC_EEMPTY, "spiral: nothing lies inside the margin of %g mm", sp.m);
    if (rc == QC_OK)
        rc = index_rings(ctx, &sp);
    if (rc == QC_OK) {
        sp.nstamp = sp.ring.pts.n;
        sp.stamp = qc__alloc_array(ctx, sp.nstamp, sizeof *sp.stamp);
        if (sp.stamp == NULL)
            rc = qc__fail(ctx, QC_ENOMEM, "spiral: out of memory");
        else
            memset(sp.stamp, 0, sp.nstamp * sizeof *sp.stamp);
    }
    if (rc == QC_OK)
        rc = trace(ctx, &sp, r_start, r_max);
    if (rc == QC_OK)
        rc = join(ctx, &sp, &line);
    if (rc == QC_OK && line.n == 0)
        rc = qc__fail(ctx, QC_EEMPTY, "spiral: the spiral from (%g, %g) misses the region",
                      sp.c.x, sp.c.y);
    if (rc < 0)
        goto out;
    rc = qc_path_move_to(ctx, &one, line.v[0]);
    for (i = 1; i < line.n && rc == QC_OK; i++)
        rc = qc_path_line_to(ctx, &one, line.v[i]);
    if (rc == QC_OK && stats != NULL && !params->skip_gap_stat) {
        double g = qc_largest_gap(ctx, region, line.v, line.n, GAP_RES * d, NULL);
        if (g < 0.0)
            rc = (int)g;
        else
            stats->largest_gap_mm = g;
        stats->joins_unfixed += sp.jumps;
    }
    if (rc == QC_OK) /* all or nothing: *out as it was on failure */
        rc = qc_path_append(ctx, out, &one, 1);
out:
    spiral_free(ctx, &sp);
    qc__sdf_free(ctx, &s);
    qc_path_free(ctx, &one);
    qc_points_free(ctx, &line);
    return rc;
}

const qc_family_desc qc__family_spiral = {
    QC_FAMILY_SPIRAL, "spiral", "one spiral from the centre, kept inside by the margin's ring", 0,
    QC_PARAM_BIT(QC_PARAM_ID_SPIRAL), qc_deco_spiral, NULL};
