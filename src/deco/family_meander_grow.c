/*
 * Curve evolution for the meander (after Pedersen and Singh, "Organic
 * labyrinths and mazes", NPAR 2006, and differential growth): a closed
 * curve is resampled, faired, shaken by a seeded random push and pushed
 * apart where non-neighbouring parts come nearer than d, and off the
 * boundary, round after round. Moves are small against the vertex spacing,
 * so the curve deforms without passing through itself.
 */
#include <math.h>
#include <string.h>

#include "family_meander.h"

#define SEG_MIN 0.25     /* vertex spacing band, times d */
#define SEG_MAX 0.55
#define STEP_MAX 0.04    /* largest move of a vertex in one round, times d */
#define FAIR 0.12        /* Laplacian fairing weight */
#define FAIR_TIGHT 0.45  /* fairing where the curve turns tighter than allowed */
#define TURN_SLACK 1.6   /* vertices turning tighter than this times the radius
                          * are faired hard (the spline between them turns
                          * tighter than the vertices do) */
#define GUARD_PASSES 4   /* passes undoing crossing moves before a round is dropped */
#define REPEL 0.5        /* repulsion gain, times d */
#define WIGGLE_STEP 0.05 /* the largest random push, times d */
#define REACH 1.5        /* repulsion radius, times d: beyond d, so that with
                          * the length fixed the lines even out at d */

#define CLEAR_WAVE 2.0   /* wavelength of the clearance's waves, times d */
#define CLEAR_SWING 0.3  /* their amplitude, times the clearance (waves out
                          * past 1/4 in at d = 0.6 in leave the seam bare) */
#define RIM_BAND 0.5     /* vertices this far (times d) beyond the clearance ... */
#define RIM_PULL 0.3     /* ... are drawn onto it by this share of the excess:
                          * lobes near a seam flatten into runs along it */
#define FIELD_SLOPE 2.0  /* the bilinear distance field changes by at most this
                          * times a move (sqrt 2 between exact nodes) */
#define LINE_TABLE 64
#define WALL 0.25        /* the hard wall, times the clearance (the mirror pushes first) */
#define SHARP 80.0       /* corners sharper than this (degrees) get ... */
#define SHARP_REACH 2.5  /* ... a smaller spacing within this many d of the tip, */
#define SCALE_MIN 0.5    /* down to this times d at the tip */
#define TILE_CELLS 8     /* tiles of this many cells a side settle on their own: */
#define SETTLE_ROUNDS 5  /* every this many rounds, past half of them, a tile ... */
#define SETTLE_GAIN 0.001 /* ... whose curve grew by less than this share is frozen */
#define SETTLE_MARGIN 2.0 /* only tiles this many d clear of the boundary (beyond
                           * their half diagonal) settle: the rim, the corners and
                           * the small blocks keep every round */

/* A vertex as the repulsion pass reads it, in cell order. */
typedef struct qc__grow_vert {
    double x, y, reach, scale;
    uint32_t i;
} qc__grow_vert;
#define LINE_VERTEX 0.33 /* the mean vertex spacing the mirror assumes, times d */

typedef struct grow {
    qc_vec2 *p, *q;     /* positions, next positions */
    double *pv, *qv;    /* the distance field (bilinear) at p and at q, or less:
                         * a bound carried from round to round while the
                         * vertex is far from the boundary */
    size_t n, cap, qcap; /* vertices; capacities of p and q */
    size_t pvcap, qvcap;
    uint32_t *cell;     /* per vertex: its grid cell */
    uint32_t *idx;      /* vertices sorted by cell */
    qc_vec2 *f;         /* per vertex: summed repulsion */
    double *reach;      /* per vertex: half its longer segment plus two moves */
    double *seg;        /* per vertex: the length of the segment after it */
    unsigned char *close; /* per vertex: something not next to it is within reach */
    qc__grow_vert *sv;  /* cell order: the vertices */
    qc_vec2 *sf;        /* cell order: their repulsion */
    unsigned char *sc;  /* cell order: their close flags */
    size_t seg_cap, idx_cap, cell_cap, f_cap, reach_cap, close_cap, sv_cap, sf_cap, sc_cap;
    uint32_t *start;    /* per cell: first entry in idx (ncell + 1) */
    size_t gx, gy;
    double x0, y0, h;
    double line_f[LINE_TABLE + 1]; /* line_force at r = k R / LINE_TABLE */
    double phase[2];    /* of the clearance's waves */
    float *scale;       /* the spacing's local scale (1, less by sharp corners) */
    size_t sx, sy;      /* its grid: nodes (x0 + i h / 2, y0 + j h / 2)... */
    double sh;          /* ... at this step */
    int scaled;         /* whether any node is below 1 (else it is not read) */
    size_t tx, ty;      /* tiles (TILE_CELLS cells a side) */
    unsigned char *frozen; /* per tile: 1 settled (its vertices stay put), 3
                            * settled among settled tiles (nothing that moves
                            * comes near: not even binned), 2 may settle
                            * (clear of the boundary), 0 none of these */
    double *tile_len;   /* per tile: the curve's length in it when last looked */
    double *tile_now;   /* per tile: its length now */
    unsigned char *still; /* per vertex: its tile is settled (2: among settled
                           * tiles, not binned) */
    size_t still_cap;
    int any_frozen;
    int open;           /* an open curve: its ends stay put, no closing segment */
} grow;

static int reserve_vertices(qc_ctx *ctx, grow *g, size_t need)
{
    QC__TRY(QC__RESERVE(ctx, g->p, g->cap, need));
    QC__TRY(QC__RESERVE(ctx, g->pv, g->pvcap, need));
    QC__TRY(QC__RESERVE(ctx, g->qv, g->qvcap, need));
    return QC__RESERVE(ctx, g->q, g->qcap, need);
}

/* The cell of p, and its tile in *tile unless tile is NULL (from the
 * cell's column and row: no division by the row length). */
static inline size_t cell_tile(const grow *g, qc_vec2 p, size_t *tile)
{
    size_t i = qc__grid_cell((p.x - g->x0) / g->h, g->gx);
    size_t j = qc__grid_cell((p.y - g->y0) / g->h, g->gy);

    if (tile != NULL)
        *tile = j / TILE_CELLS * g->tx + i / TILE_CELLS;
    return j * g->gx + i;
}

/* The tile of cell c. */
static size_t tile_of(const grow *g, size_t c)
{
    return (c / g->gx / TILE_CELLS) * g->tx + (c % g->gx) / TILE_CELLS;
}

/* Whether cell c lies in a settled tile. */
static int settled(const grow *g, size_t c)
{
    return g->any_frozen && (g->frozen[tile_of(g, c)] & 1);
}

/* Counting sort of the vertices into their cells (stable: index order). */
static int bin(qc_ctx *ctx, grow *g)
{
    size_t nc = g->gx * g->gy, i;

    QC__TRY(QC__RESERVE(ctx, g->cell, g->cell_cap, g->n));
    QC__TRY(QC__RESERVE(ctx, g->idx, g->idx_cap, g->n));
    QC__TRY(QC__RESERVE(ctx, g->f, g->f_cap, g->n));
    QC__TRY(QC__RESERVE(ctx, g->reach, g->reach_cap, g->n));
    QC__TRY(QC__RESERVE(ctx, g->seg, g->seg_cap, g->n));
    QC__TRY(QC__RESERVE(ctx, g->close, g->close_cap, g->n));
    QC__TRY(QC__RESERVE(ctx, g->sv, g->sv_cap, g->n));
    QC__TRY(QC__RESERVE(ctx, g->sf, g->sf_cap, g->n));
    QC__TRY(QC__RESERVE(ctx, g->sc, g->sc_cap, g->n));
    QC__TRY(QC__RESERVE(ctx, g->still, g->still_cap, g->n));
    memset(g->start, 0, (nc + 1) * sizeof *g->start);
    for (i = 0; i < g->n; i++) {
        size_t t = 0;
        g->cell[i] = (uint32_t)cell_tile(g, g->p[i], g->any_frozen ? &t : NULL);
        g->still[i] = (unsigned char)(g->any_frozen ? g->frozen[t] : 0);
        g->still[i] = g->still[i] == 3 ? 2 : g->still[i] == 1; /* 2: not binned */
        if (g->still[i] != 2)
            g->start[g->cell[i] + 1]++;
    }
    for (i = 0; i < nc; i++)
        g->start[i + 1] += g->start[i];
    for (i = 0; i < g->n; i++)
        if (g->still[i] != 2)
            g->idx[g->start[g->cell[i]]++] = (uint32_t)i;
    for (i = nc; i > 0; i--) /* start[c] was advanced to start[c + 1] */
        g->start[i] = g->start[i - 1];
    g->start[0] = 0;
    return QC_OK;
}

/* Radius of the circle through a, b, c (huge when they are in line), given
 * the lengths of ab and bc. */
static double circumradius(qc_vec2 a, qc_vec2 b, qc_vec2 c, double lab, double lbc)
{
    double abx = b.x - a.x, aby = b.y - a.y, bcx = c.x - b.x, bcy = c.y - b.y;
    double cax = a.x - c.x, cay = a.y - c.y;
    double cr = fabs(abx * bcy - aby * bcx);
    double l = lab * lbc * qc__hypot(cax, cay);

    return cr > 1e-12 * l ? l / (2.0 * cr) : 1e30;
}

/* Index distance along the curve (cyclic when it is closed). */
static size_t ring_gap(const grow *g, size_t i, size_t j)
{
    size_t k = i > j ? i - j : j - i;
    return g->open || k < g->n - k ? k : g->n - k;
}

/* The vertices before and after i (an open curve's ends are their own). */
static size_t before(const grow *g, size_t i)
{
    return i > 0 ? i - 1 : g->open ? 0 : g->n - 1;
}

static size_t after(const grow *g, size_t i)
{
    return i + 1 < g->n ? i + 1 : g->open ? i : 0;
}

/* The length of the segment into i (0 at an open curve's start). */
static double seg_before(const grow *g, size_t i)
{
    return i > 0 ? g->seg[i - 1] : g->open ? 0.0 : g->seg[g->n - 1];
}

/* The local scale at p (nearest node). */
static double scale_at(const grow *g, qc_vec2 p)
{
    double fx, fy;
    size_t i, j;

    if (!g->scaled)
        return 1.0;
    fx = floor((p.x - g->x0) / g->sh + 0.5);
    fy = floor((p.y - g->y0) / g->sh + 0.5);

    if (fx < 0.0 || fy < 0.0 || fx >= (double)g->sx || fy >= (double)g->sy)
        return 1.0;
    i = (size_t)fx;
    j = (size_t)fy;
    return (double)g->scale[j * g->sx + i];
}

/* The scale field: 1, falling towards SCALE_MIN at convex corners sharper
 * than SHARP (within SHARP_REACH d of the tip), so that the curve can send
 * a narrower lobe into a star point. Returns QC_OK or QC_ENOMEM. */
static int scale_field(qc_ctx *ctx, grow *g, const qc_region *r, double d)
{
    size_t k, v = 0, n;
    double reach = SHARP_REACH * d, cos_sharp = qc_cos(SHARP * QC_PI / 180.0);

    g->sh = 0.25 * d;
    g->sx = (size_t)((double)g->gx * g->h / g->sh) + 1;
    g->sy = (size_t)((double)g->gy * g->h / g->sh) + 1;
    n = g->sx * g->sy;
    g->scale = qc__alloc_array(ctx, n, sizeof *g->scale);
    if (g->scale == NULL)
        return QC_ENOMEM;
    for (k = 0; k < n; k++)
        g->scale[k] = 1.0f;
    for (k = 0; k < r->nrings; k++) {
        size_t first = v, end = r->ring_end[k];
        for (; v < end; v++) {
            qc_vec2 a = r->v[v == first ? end - 1 : v - 1], p = r->v[v];
            qc_vec2 b = r->v[v + 1 == end ? first : v + 1];
            double ux = a.x - p.x, uy = a.y - p.y, wx = b.x - p.x, wy = b.y - p.y;
            double lu = qc_hypot(ux, uy), lw = qc_hypot(wx, wy), cr;
            long i0, i1, j0, j1, i, j;

            cr = (p.x - a.x) * (b.y - p.y) - (p.y - a.y) * (b.x - p.x);
            /* convex (inside on the left) and sharp: the legs' angle is small */
            if (!(cr > 0.0) || !(lu > 0.0 && lw > 0.0) ||
                (ux * wx + uy * wy) / (lu * lw) < cos_sharp)
                continue;
            i0 = (long)floor((p.x - reach - g->x0) / g->sh);
            i1 = (long)ceil((p.x + reach - g->x0) / g->sh);
            j0 = (long)floor((p.y - reach - g->y0) / g->sh);
            j1 = (long)ceil((p.y + reach - g->y0) / g->sh);
            for (j = j0 < 0 ? 0 : j0; j <= j1 && j < (long)g->sy; j++)
                for (i = i0 < 0 ? 0 : i0; i <= i1 && i < (long)g->sx; i++) {
                    double t = qc_hypot(g->x0 + (double)i * g->sh - p.x,
                                        g->y0 + (double)j * g->sh - p.y) / reach;
                    float sc = (float)(t >= 1.0 ? 1.0 : SCALE_MIN + (1.0 - SCALE_MIN) * t);
                    size_t at = (size_t)j * g->sx + (size_t)i;
                    if (sc < g->scale[at]) {
                        g->scale[at] = sc;
                        g->scaled = 1;
                    }
                }
        }
    }
    return QC_OK;
}

/* Vertex a (in cell order, copied into u) against the slots [b0, b1): each
 * pair nearer than R and not neighbours along the curve pushes both apart.
 * a's push is summed in registers (in the same order as one by one, so the
 * sums are the same to the bit); r2 is tested before any root is taken.
 * The slots within R are first gathered without a branch (a third of the
 * pairs are, and which ones cannot be guessed), a chunk at a time, two
 * slots a turn (the loop's upkeep halved), then summed in slot order as
 * before. */
#define REPEL_CHUNK 64
static void repel_run(grow *g, size_t a, size_t b0, size_t b1, double R, double R2)
{
    const qc__grow_vert u = g->sv[a];
    const qc__grow_vert *sv = g->sv;
    qc_vec2 *sf = g->sf, fa = sf[a];
    unsigned char *sc = g->sc, ca = sc[a];
    size_t b, n = g->n, lo, m, k;
    uint32_t near[REPEL_CHUNK];
    int closed = !g->open;

    for (lo = b0; lo < b1; lo += REPEL_CHUNK) {
        size_t hi = b1 - lo > REPEL_CHUNK ? lo + REPEL_CHUNK : b1;
        for (b = lo, m = 0; b + 1 < hi; b += 2) {
            double dx0 = u.x - sv[b].x, dy0 = u.y - sv[b].y;
            double dx1 = u.x - sv[b + 1].x, dy1 = u.y - sv[b + 1].y;
            near[m] = (uint32_t)b;
            m += dx0 * dx0 + dy0 * dy0 < R2;
            near[m] = (uint32_t)(b + 1);
            m += dx1 * dx1 + dy1 * dy1 < R2;
        }
        if (b < hi) {
            double dx = u.x - sv[b].x, dy = u.y - sv[b].y;
            near[m] = (uint32_t)b;
            m += dx * dx + dy * dy < R2;
        }
        for (k = 0; k < m; k++) {
            const qc__grow_vert *w = &sv[near[k]];
            double dx = u.x - w->x, dy = u.y - w->y, r2 = dx * dx + dy * dy, r, f, Rs;
            size_t gap;

            b = near[k];
            gap = u.i > w->i ? u.i - w->i : w->i - u.i;
            if (gap <= 1 || (closed && gap + 1 >= n)) /* neighbours along the curve */
                continue;
            if (r2 < 1e-18) { /* coincident: no direction to push, but watch them */
                ca = sc[b] = 1;
                continue;
            }
            r = sqrt(r2);
            if (r < u.reach + w->reach) /* their segments might cross after the move */
                ca = sc[b] = 1;
            Rs = R * (u.scale < w->scale ? u.scale : w->scale);
            if (r >= Rs)
                continue;
            f = (1.0 - r / Rs) / r;
            fa.x += dx * f;
            fa.y += dy * f;
            sf[b].x -= dx * f;
            sf[b].y -= dy * f;
        }
    }
    sf[a] = fa;
    sc[a] = ca;
}

/* Cell c (at cx, cy), not settled, against itself and its four forward
 * neighbours: the neighbours' slots are contiguous (c + 1 right after
 * c; the row below's three cells in a run), so a vertex meets them in two
 * runs instead of five. Each sum still takes its terms in the same order
 * as cell by cell (a's own run: c, then c + 1, then the row below left to
 * right; a neighbour's vertex: from c's vertices in slot order), so the
 * forces are the same to the bit. */
static void repel_cell(grow *g, size_t c, size_t cx, size_t cy, double R, double R2)
{
    size_t a, end = g->start[c + 1];
    size_t right = cx + 1 < g->gx ? g->start[c + 2] : end;
    size_t lo = 0, hi = 0;

    if (cy + 1 < g->gy) {
        size_t below = c + g->gx;
        lo = g->start[cx > 0 ? below - 1 : below];
        hi = g->start[(cx + 1 < g->gx ? below + 1 : below) + 1];
    }
    for (a = g->start[c]; a < end; a++)
        repel_run(g, a, a + 1, right, R, R2);
    if (lo < hi)
        for (a = g->start[c]; a < end; a++)
            repel_run(g, a, lo, hi, R, R2);
}

/* Every vertex's summed repulsion from the vertices within R of it (as
 * unit vectors weighted 1 - r / R) into g->f, and the close flags: each
 * pair once, cell by cell against the cell itself and four of its
 * neighbours, on copies in cell order (the curve's own order scatters in
 * memory). */
static void repulsion(grow *g, double R)
{
    static const int nb[4][2] = {{1, 0}, {-1, 1}, {0, 1}, {1, 1}};
    size_t cx, cy, a, n = g->start[g->gx * g->gy]; /* the binned vertices */
    double R2 = R * R;
    int t;

    for (a = 0; a < n; a++) {
        uint32_t i = g->idx[a];
        g->sv[a].x = g->p[i].x;
        g->sv[a].y = g->p[i].y;
        g->sv[a].reach = g->reach[i];
        g->sv[a].scale = g->scaled ? scale_at(g, g->p[i]) : 1.0;
        g->sv[a].i = i;
        g->sf[a].x = g->sf[a].y = 0.0;
        g->sc[a] = 0;
    }
    for (cy = 0; cy < g->gy; cy++)
        for (cx = 0; cx < g->gx; cx++) {
            size_t c = cy * g->gx + cx;
            int still = settled(g, c);
            if (!still) {
                repel_cell(g, c, cx, cy, R, R2);
                continue;
            }
            /* a frozen tile's vertices need no push among themselves */
            for (t = 0; t < 4; t++) {
                long x = (long)cx + nb[t][0], y = (long)cy + nb[t][1];
                size_t cc;
                if (x < 0 || (size_t)x >= g->gx || (size_t)y >= g->gy)
                    continue;
                cc = (size_t)y * g->gx + (size_t)x;
                if (settled(g, cc))
                    continue;
                for (a = g->start[c]; a < g->start[c + 1]; a++)
                    repel_run(g, a, g->start[cc], g->start[cc + 1], R, R2);
            }
        }
    for (a = 0; a < n; a++) {
        uint32_t i = g->idx[a];
        g->f[i] = g->sf[a];
        g->close[i] |= g->sc[a];
    }
}

/* The summed repulsion (as repulsion() gives it, in units of R) on a
 * vertex from a straight line at distance r with vertices every l:
 * (2 / l) * integral over s in [0, S] of (1 - q / R) r / q, q = hypot(r, s),
 * S = sqrt(R^2 - r^2), by Simpson's rule. The boundary pushes like the
 * mirror image of the curve behind it. */
static double line_force(double r, double R, double l)
{
    double S = sqrt(R * R - r * r), sum = 0.0, h;
    int k, m = 32;

    if (!(S > 0.0))
        return 0.0;
    h = S / m;
    for (k = 0; k <= m; k++) {
        double s = k * h, q = sqrt(r * r + s * s), w = k == 0 || k == m ? 1 : k % 2 ? 4 : 2;
        sum += q > 0.0 ? w * (1.0 - q / R) * r / q : w;
    }
    return 2.0 / l * sum * h / 3.0;
}

static void line_table(grow *g, double d)
{
    int k;

    for (k = 0; k <= LINE_TABLE; k++)
        g->line_f[k] = line_force(REACH * d * k / LINE_TABLE, REACH * d, LINE_VERTEX * d);
}

/* The mirror's push at image distance r (linear in the table). */
static double mirror(const grow *g, double r, double d)
{
    double t = r / (REACH * d) * LINE_TABLE;
    int k;

    if (t >= LINE_TABLE)
        return 0.0;
    if (t <= 0.0)
        return g->line_f[0];
    k = (int)t;
    return g->line_f[k] + (g->line_f[k + 1] - g->line_f[k]) * (t - k);
}

/* The clearance at p: o->clear varied by two waves (across and up) so that
 * the curve's run along a straight edge undulates instead of lying flat. */
static double clearance(const grow *g, const qc__grow_opts *o, qc_vec2 p)
{
    double k = 2.0 * QC_PI / (CLEAR_WAVE * o->d);
    double w = qc_sin(k * p.x + g->phase[0]) + qc_sin(k * p.y + g->phase[1]);

    return o->clear * (1.0 + 0.5 * CLEAR_SWING * w);
}

/* p moved back onto the clearance contour if it came nearer the boundary
 * than half the clearance. */
static qc_vec2 keep_inside(const grow *g, const qc__grow_opts *o, qc_vec2 p)
{
    double wall = WALL * o->clear * scale_at(g, p), v = qc__sdf_at(o->sdf, p);
    qc_vec2 grad;

    if (v >= wall + o->sdf->h)
        return p;
    v = qc__sdf_exact(o->sdf, p, &grad);
    if (v >= wall)
        return p;
    p.x += (wall - v) * grad.x;
    p.y += (wall - v) * grad.y;
    return p;
}

/* One round of forces: g->q receives the moved vertices. */
static void step(grow *g, const qc__grow_opts *o, qc_rng *rng)
{
    double d = o->d, cap = STEP_MAX * d, amp = o->wiggle * WIGGLE_STEP * d;
    /* where the mirror's image is R away */
    double reach_b = o->clear * (1.0 + CLEAR_SWING) * REACH;
    size_t n = g->n, i;

    /* Two segments that cross after moves of at most cap have endpoints,
     * one of each, within half of each one's length plus cap of each other
     * before: the repulsion pass flags those (close), and the guard checks
     * only flagged segments. Sharp turns (over 90 degrees) are flagged too:
     * there a segment may cross the one after next. */
    for (i = 0; i < n; i++) {
        qc_vec2 p = g->p[i], b = g->p[after(g, i)];
        g->seg[i] = qc__hypot(b.x - p.x, b.y - p.y);
    }
    for (i = 0; i < n; i++) {
        qc_vec2 a = g->p[before(g, i)], p = g->p[i], b = g->p[after(g, i)];
        double la = seg_before(g, i), lb = g->seg[i];

        if (g->still[i] == 2) { /* not binned: nothing that moves comes near */
            g->close[i] = 0;
            continue;
        }
        g->reach[i] = 0.5 * (la > lb ? la : lb) + cap;
        g->close[i] = (p.x - a.x) * (b.x - p.x) + (p.y - a.y) * (b.y - p.y) <= 0.0;
    }
    repulsion(g, REACH * d);
    for (i = 0; i < n; i++) {
        qc_vec2 a, p = g->p[i], b, f, m;
        double w, push = 0.0, pull = 0.0;
        qc_vec2 pull_dir = QC__V2(0.0, 0.0);
        double mx, my, len, v, known = g->pv[i], wall = WALL * o->clear + 2.0 * o->sdf->h;

        if ((g->open && (i == 0 || i + 1 == n)) || g->still[i]) {
            /* the ends stay on their ports, a settled tile's vertices in
             * place (their fairing weight is not worked out: most of a large
             * block's vertices once its tiles settle) */
            g->q[i] = p;
            g->qv[i] = g->pv[i];
            continue;
        }
        a = g->p[before(g, i)];
        b = g->p[after(g, i)];
        f = g->f[i];
        w = circumradius(a, p, b, seg_before(g, i), g->seg[i]) < TURN_SLACK * o->turn ? FAIR_TIGHT : FAIR;
        if (!(known >= reach_b + o->sdf->h)) /* the bound says too little */
            known = qc__sdf_at(o->sdf, p);
        v = known;
        if (v < reach_b + o->sdf->h && v > -d) {
            qc_vec2 grad;
            v = qc__sdf_exact(o->sdf, p, &grad);
            push = v < 0.0 ? 2.0 * g->line_f[0]
                           : mirror(g, v * d / (clearance(g, o, p) * scale_at(g, p)), d);
            f.x += push * grad.x;
            f.y += push * grad.y;
            if (v > 0.0) { /* the rim: drawn onto the clearance contour */
                double c = clearance(g, o, p) * scale_at(g, p), e = v - c;
                if (e > 0.0 && e < RIM_BAND * d) {
                    pull = RIM_PULL * e * (1.0 - e / (RIM_BAND * d));
                    pull_dir = grad;
                }
            }
        }
        if (push > g->line_f[LINE_TABLE / 2]) /* pressed to the wall: keep it smooth */
            w = FAIR_TIGHT;
        m.x = w * (0.5 * (a.x + b.x) - p.x) + REPEL * d * f.x;
        m.y = w * (0.5 * (a.y + b.y) - p.y) + REPEL * d * f.y;
        mx = amp * (2.0 * qc_rng_unit(rng) - 1.0);
        my = amp * (2.0 * qc_rng_unit(rng) - 1.0);
        m.x += mx - pull * pull_dir.x;
        m.y += my - pull * pull_dir.y;
        len = qc__hypot(m.x, m.y);
        if (len > cap) {
            m.x *= cap / len;
            m.y *= cap / len;
        }
        g->q[i].x = p.x + m.x;
        g->q[i].y = p.y + m.y;
        /* the boundary is a wall (checked where the vertex lands: across a
         * cusp the field at its old place says nothing) */
        g->qv[i] = known - FIELD_SLOPE * cap;
        if (g->qv[i] >= wall) /* far from the wall: the bound will do */
            continue;
        g->qv[i] = qc__sdf_at(o->sdf, g->q[i]);
        if (g->qv[i] < wall) {
            qc_vec2 k = keep_inside(g, o, g->q[i]);
            if (k.x != g->q[i].x || k.y != g->q[i].y) {
                g->q[i] = k;
                g->qv[i] = qc__sdf_at(o->sdf, k);
            }
        }
    }
}

/* Resamples q into p: long segments split (while the curve may still
 * grow), vertices nearer than the band to the last kept one dropped. */
static int resample(qc_ctx *ctx, grow *g, const qc__grow_opts *o)
{
    double lo = SEG_MIN * o->d, hi = SEG_MAX * o->d, total = 0.0;
    size_t n = g->n, i, m = 0, dropped = 0;
    int may_grow;

    for (i = 0; i + (g->open ? 1 : 0) < n; i++) {
        qc_vec2 a = g->q[i], b = g->q[i + 1 == n ? 0 : i + 1];
        g->seg[i] = qc__hypot(b.x - a.x, b.y - a.y); /* read again below */
        total += g->seg[i];
    }
    may_grow = total < o->max_len;
    QC__TRY(reserve_vertices(ctx, g, 2 * n + 1));
    for (i = 0; i < n; i++) {
        qc_vec2 a = g->q[i], b = g->q[i + 1 == n ? 0 : i + 1];
        double len;

        if (m > 0 && !(g->open && i + 1 == n)) {
            qc_vec2 l = g->p[m - 1];
            if (qc__hypot(a.x - l.x, a.y - l.y) < lo && n - dropped > 8) {
                dropped++;
                continue;
            }
        }
        g->pv[m] = g->qv[i];
        g->p[m++] = a;
        if (g->open && i + 1 == n)
            break;
        len = g->seg[i];
        if (len > hi && (may_grow || len > 2.0 * hi)) {
            qc_vec2 mid = QC__V2(0.5 * (a.x + b.x), 0.5 * (a.y + b.y));
            double v = qc__sdf_at(o->sdf, mid);
            if (v > 2.0 * o->sdf->h || (v > -2.0 * o->sdf->h && qc__sdf_exact(o->sdf, mid, NULL) > 0.0)) {
                /* a jump between pieces stays one segment */
                g->pv[m] = v;
                g->p[m++] = mid;
            }
        }
    }
    g->n = m;
    return QC_OK;
}

/* Whether segments ab and cd cross (proper crossing, by sign). */
static int seg_cross(qc_vec2 a, qc_vec2 b, qc_vec2 c, qc_vec2 d)
{
    double d1 = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    double d2 = (b.x - a.x) * (d.y - a.y) - (b.y - a.y) * (d.x - a.x);
    double d3 = (d.x - c.x) * (a.y - c.y) - (d.y - c.y) * (a.x - c.x);
    double d4 = (d.x - c.x) * (b.y - c.y) - (d.y - c.y) * (b.x - c.x);

    return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

/* One pass over the moved segments: where two would cross (or touch),
 * their four vertices go back to where they were. Moves are small against
 * the cells, so crossing partners are binned next to each other. Returns
 * the number of pairs undone. */
static size_t undo_crossings(grow *g)
{
    size_t n = g->n, i, undone = 0;

    for (i = 0; i < n; i++) {
        size_t i1 = i + 1 == n ? 0 : i + 1, c, cx, cy, x0, x1, y0, y1, x, y, k;

        if ((!g->close[i] && !g->close[i1]) || (g->open && i1 == 0) || g->still[i] == 2)
            continue;
        c = g->cell[i];
        cx = c % g->gx;
        cy = c / g->gx;
        x0 = cx > 0 ? cx - 1 : 0;
        x1 = cx + 1 < g->gx ? cx + 1 : cx;
        y0 = cy > 0 ? cy - 1 : 0;
        y1 = cy + 1 < g->gy ? cy + 1 : cy;
        for (y = y0; y <= y1; y++)
            for (x = x0; x <= x1; x++) {
                size_t cc = y * g->gx + x;
                for (k = g->start[cc]; k < g->start[cc + 1]; k++) {
                    size_t j = g->idx[k], j1 = j + 1 == n ? 0 : j + 1;
                    if (j <= i || ring_gap(g, i, j) < 2) /* the cells hold flagged segments only */
                        continue;
                    if (!seg_cross(g->q[i], g->q[i1], g->q[j], g->q[j1]))
                        continue;
                    g->q[i] = g->p[i];
                    g->q[i1] = g->p[i1];
                    g->q[j] = g->p[j];
                    g->q[j1] = g->p[j1];
                    g->qv[i] = g->pv[i];
                    g->qv[i1] = g->pv[i1];
                    g->qv[j] = g->pv[j];
                    g->qv[j1] = g->pv[j1];
                    undone++;
                }
            }
    }
    return undone;
}

/* Whether the segment from i is checked: one of its ends is flagged (and
 * it is not an open curve's missing closing segment). */
static int flagged(const grow *g, size_t i)
{
    size_t i1 = i + 1 == g->n ? 0 : i + 1;

    return (g->close[i] || g->close[i1]) && !(g->open && i1 == 0);
}

/* The cells' lists cut down to the flagged segments, in the same order
 * (the lists are binned afresh next round). */
static void keep_flagged(grow *g)
{
    size_t nc = g->gx * g->gy, c, k, m = 0, from = 0;

    for (c = 0; c < nc; c++) {
        size_t end = g->start[c + 1];
        g->start[c] = (uint32_t)m;
        for (k = from; k < end; k++)
            if (flagged(g, g->idx[k]))
                g->idx[m++] = g->idx[k];
        from = end;
    }
    g->start[nc] = (uint32_t)m;
}

/* Undoes crossing moves until none is left (all moves undone at worst:
 * the curve before the round did not cross itself). */
static void guard(grow *g)
{
    int pass;

    keep_flagged(g);
    for (pass = 0; pass < GUARD_PASSES; pass++)
        if (undo_crossings(g) == 0)
            return;
    memcpy(g->q, g->p, g->n * sizeof *g->q);
    memcpy(g->qv, g->pv, g->n * sizeof *g->qv);
}

/* The tiles that may settle: clear of the boundary by their half diagonal
 * and SETTLE_MARGIN d (2 in frozen), with their lengths zeroed. */
static int tiles_init(qc_ctx *ctx, grow *g, const qc__grow_opts *o)
{
    double side = TILE_CELLS * g->h, half = 0.5 * side * 1.4142135623730951;
    size_t i, j;

    g->tx = (g->gx + TILE_CELLS - 1) / TILE_CELLS;
    g->ty = (g->gy + TILE_CELLS - 1) / TILE_CELLS;
    g->frozen = qc__alloc_array(ctx, g->tx * g->ty, sizeof *g->frozen);
    g->tile_len = qc__alloc_array(ctx, g->tx * g->ty, sizeof *g->tile_len);
    g->tile_now = qc__alloc_array(ctx, g->tx * g->ty, sizeof *g->tile_now);
    if (g->frozen == NULL || g->tile_len == NULL || g->tile_now == NULL)
        return QC_ENOMEM;
    for (j = 0; j < g->ty; j++)
        for (i = 0; i < g->tx; i++) {
            qc_vec2 mid = QC__V2(g->x0 + ((double)i + 0.5) * side, g->y0 + ((double)j + 0.5) * side);
            g->frozen[j * g->tx + i] = qc__sdf_at(o->sdf, mid) > half + SETTLE_MARGIN * o->d ? 2 : 0;
            g->tile_len[j * g->tx + i] = 0.0;
        }
    return QC_OK;
}

/* Every SETTLE_ROUNDS rounds: the curve's length per tile (segments by
 * the cell of their start); past half of the rounds, a tile that may
 * settle and grew by less than SETTLE_GAIN since the last look is frozen
 * for the rest. */
static void settle(grow *g, const qc__grow_opts *o, size_t it)
{
    size_t nt = g->tx * g->ty, n = g->n, t, i;

    if (g->open || it % SETTLE_ROUNDS != 0)
        return;
    for (t = 0; t < nt; t++)
        g->tile_now[t] = 0.0;
    for (i = 0; i < n; i++) {
        qc_vec2 a = g->p[i], b = g->p[i + 1 == n ? 0 : i + 1];
        size_t tt;
        (void)cell_tile(g, a, &tt);
        if (g->frozen[tt] == 2)
            g->tile_now[tt] += qc__hypot(b.x - a.x, b.y - a.y);
    }
    for (t = 0; t < nt; t++) {
        if (g->frozen[t] != 2)
            continue;
        if (2 * it >= o->iterations && g->tile_len[t] > 0.0 &&
            g->tile_now[t] - g->tile_len[t] < SETTLE_GAIN * g->tile_len[t]) {
            g->frozen[t] = 1;
            g->any_frozen = 1;
        }
        g->tile_len[t] = g->tile_now[t];
    }
    for (t = 0; t < nt; t++) { /* settled all round: left out of the bins */
        size_t x = t % g->tx, y = t / g->tx, k = 0;
        if (g->frozen[t] != 1 || x == 0 || y == 0 || x + 1 == g->tx || y + 1 == g->ty)
            continue;
        for (i = 0; i < 9; i++)
            k += (g->frozen[t + (i / 3) * g->tx + i % 3 - g->tx - 1] & 1u) != 0;
        if (k == 9)
            g->frozen[t] = 3;
    }
}

int qc__meander_grow(qc_ctx *ctx, qc_points *c, const qc__grow_opts *o)
{
    grow g;
    qc_rng rng;
    qc_bbox box = qc_region_bbox(o->sdf->region);
    size_t it, nc;
    int rc = QC_OK;

    if (c->n < 3)
        return QC_OK;
    memset(&g, 0, sizeof g);
    qc_rng_seed(&rng, o->seed ^ 0x6d65616e646572ull); /* "meander" */
    g.h = qc__fit_cell(box, REACH * o->d, 4.0 * (double)c->n + 64.0);
    g.x0 = box.min.x - g.h;
    g.y0 = box.min.y - g.h;
    g.gx = (size_t)((box.max.x - box.min.x) / g.h) + 3;
    g.gy = (size_t)((box.max.y - box.min.y) / g.h) + 3;
    nc = g.gx * g.gy;
    g.start = qc__alloc_array(ctx, nc + 1, sizeof *g.start);
    if (g.start == NULL || reserve_vertices(ctx, &g, c->n + 1) < 0) {
        rc = QC_ENOMEM;
        goto out;
    }
    memcpy(g.p, c->v, c->n * sizeof *g.p);
    g.n = c->n;
    for (it = 0; it < g.n; it++)
        g.pv[it] = qc__sdf_at(o->sdf, g.p[it]);
    g.open = o->open;
    line_table(&g, o->d);
    if (scale_field(ctx, &g, o->sdf->region, o->d) < 0) {
        rc = QC_ENOMEM;
        goto out;
    }
    if (tiles_init(ctx, &g, o) < 0) {
        rc = QC_ENOMEM;
        goto out;
    }
    g.phase[0] = 2.0 * QC_PI * qc_rng_unit(&rng);
    g.phase[1] = 2.0 * QC_PI * qc_rng_unit(&rng);
    for (it = 0; it < o->iterations; it++) {
        settle(&g, o, it);
        rc = bin(ctx, &g);
        if (rc < 0)
            break;
        step(&g, o, &rng);
        guard(&g);
        rc = resample(ctx, &g, o);
        if (rc < 0)
            break;
    }
    if (g.n > c->cap) {
        size_t cap = c->cap;
        if (QC__RESERVE(ctx, c->v, cap, g.n) < 0) {
            rc = QC_ENOMEM;
            goto out;
        }
        c->cap = cap;
    }
    memcpy(c->v, g.p, g.n * sizeof *g.p);
    c->n = g.n;
out:
    qc__free(ctx, g.p, g.cap * sizeof *g.p);
    qc__free(ctx, g.q, g.qcap * sizeof *g.q);
    qc__free(ctx, g.pv, g.pvcap * sizeof *g.pv);
    qc__free(ctx, g.qv, g.qvcap * sizeof *g.qv);
    qc__free(ctx, g.cell, g.cell_cap * sizeof *g.cell);
    qc__free(ctx, g.idx, g.idx_cap * sizeof *g.idx);
    qc__free(ctx, g.f, g.f_cap * sizeof *g.f);
    qc__free(ctx, g.reach, g.reach_cap * sizeof *g.reach);
    qc__free(ctx, g.seg, g.seg_cap * sizeof *g.seg);
    qc__free(ctx, g.close, g.close_cap * sizeof *g.close);
    qc__free(ctx, g.sv, g.sv_cap * sizeof *g.sv);
    qc__free(ctx, g.sf, g.sf_cap * sizeof *g.sf);
    qc__free(ctx, g.sc, g.sc_cap * sizeof *g.sc);
    qc__free(ctx, g.scale, g.sx * g.sy * sizeof *g.scale);
    qc__free(ctx, g.start, (nc + 1) * sizeof *g.start);
    qc__free(ctx, g.still, g.still_cap * sizeof *g.still);
    qc__free(ctx, g.frozen, g.tx * g.ty * sizeof *g.frozen);
    qc__free(ctx, g.tile_len, g.tx * g.ty * sizeof *g.tile_len);
    qc__free(ctx, g.tile_now, g.tx * g.ty * sizeof *g.tile_now);
    if (rc < 0)
        return qc__fail(ctx, rc, "out of memory growing a meander of %lu vertices",
                        (unsigned long)g.n);
    return QC_OK;
}
