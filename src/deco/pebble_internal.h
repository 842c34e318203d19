/*
 * Internals of Pebbling and Shape Packing (paper §5.3): the packed circles,
 * the boundary queries they need, and the trimming of overgrown paths.
 */
#ifndef QC_PEBBLE_INTERNAL_H
#define QC_PEBBLE_INTERNAL_H

#include "deco_internal.h"

/* qc_path_line_to and qc_path_cubic_to, stored in place while the room
 * reserved for the whole drawing lasts (the calls, their reserve checks
 * and their memcpy were a tenth of a rendering); the calls once it is
 * short. The same path either way. */
static inline int qc__peb_line(qc_ctx *ctx, qc_path *out, qc_vec2 p)
{
    if (out->ncmd < out->cmd_cap && out->npt < out->pt_cap) {
        out->cmd[out->ncmd++] = QC_PATH_LINE;
        out->pt[out->npt++] = p;
        return QC_OK;
    }
    return qc_path_line_to(ctx, out, p);
}

static inline int qc__peb_cubic(qc_ctx *ctx, qc_path *out, qc_vec2 c1, qc_vec2 c2, qc_vec2 p)
{
    if (out->ncmd < out->cmd_cap && out->pt_cap - out->npt >= 3) {
        qc_vec2 *q = out->pt + out->npt;
        out->cmd[out->ncmd++] = QC_PATH_CUBIC;
        q[0] = c1;
        q[1] = c2;
        q[2] = p;
        out->npt += 3;
        return QC_OK;
    }
    return qc_path_cubic_to(ctx, out, c1, c2, p);
}

/* ---- the region's boundary edges, binned (shared_pebble_bound.c) ---- */

typedef struct qc__pbound {
    const qc_region *region;
    qc__cgrid g;      /* every boundary edge as a 2-vertex item, id = its first vertex */
} qc__pbound;

/* Bins region's edges in cells of about cell mm (at most max_cells cells). */
QC__HIDDEN int qc__pbound_init(qc_ctx *ctx, qc__pbound *b, const qc_region *region,
                               double cell, size_t max_cells);
QC__HIDDEN void qc__pbound_free(qc_ctx *ctx, qc__pbound *b);
/* Distance from x to the nearest edge, or reach when no edge is nearer. */
QC__HIDDEN double qc__pbound_dist(qc__pbound *b, qc_vec2 x, double reach);
/* The boundary segments under box (x0, y0, x1, y1), once each, into out:
 * their count, cap + 1 when more than cap. qc__pbound_dist_among answers
 * qc__pbound_dist(x, reach) from such a list (the same value when the box
 * holds x's disc of radius reach). */
QC__HIDDEN size_t qc__pbound_gather(qc__pbound *b, const double *box, uint32_t *out, size_t cap);
QC__HIDDEN double qc__pbound_dist_among(const qc__pbound *b, const uint32_t *items, size_t n,
                                        qc_vec2 x, double reach);
/*
 * The circle (x0 + u s, r0 + s) grows with s >= 0 along the unit direction
 * u (its point x0 - u r0 stays put); the first s <= cap at which its
 * centre comes within k (r0 + s) of an edge (k = 1: the circle touches the
 * boundary), or cap. The circle at s = 0 must keep that distance.
 */
QC__HIDDEN double qc__pbound_ray(qc__pbound *b, qc_vec2 x0, double r0, qc_vec2 u, double cap,
                                 double k);
/* Number of edges the segment pq crosses (symbolically perturbed, so the
 * parity says whether p and q lie on different sides of the boundary). */
QC__HIDDEN size_t qc__pbound_crossings(qc__pbound *b, qc_vec2 p, qc_vec2 q);

/* One crossing of a segment with the boundary. */
typedef struct qc__pcross {
    double t;       /* along the segment, 0..1 */
    uint32_t edge;  /* first vertex of the edge */
    qc_vec2 at;
} qc__pcross;

/* The crossings of pq sorted along it, into *list (grown; *cap elements). */
QC__HIDDEN int qc__pbound_cross_list(qc_ctx *ctx, qc__pbound *b, qc_vec2 p, qc_vec2 q,
                                     qc__pcross **list, size_t *cap, size_t *count);
/* Ring holding vertex v, and that ring's first and one-past-last vertex. */
QC__HIDDEN size_t qc__pbound_ring(const qc_region *r, uint32_t v, uint32_t *lo, uint32_t *hi);

/* ---- the packing (shared_pebble_pack.c) ---- */

#define QC__PEB_NONE 0xFFFFFFFFu
#define QC__PEB_BRIDGE 1u   /* joined to its parent by a straight stitch, not a tangency */
#define QC__PEB_FILLER 2u   /* a filler between a child and its parent (§5.3.1 step 3) */

typedef struct qc__pebbles {
    qc_vec2 *c;         /* centres, mm */
    double *r;          /* radii, mm */
    uint32_t *parent;   /* the pebble it hangs from (tangent), QC__PEB_NONE for pebble 0, the root */
    uint32_t *node;     /* the skeleton point it stands for, QC__PEB_NONE for fillers */
    unsigned char *flags;
    unsigned char *contacts; /* pebbles it touches, plus 1 if it touches the boundary (<= 255) */
    size_t n, cap;
    /* what the run did */
    size_t dropped;     /* skeleton points already covered: no pebble */
    size_t grown_leaf, grown_pair; /* §5.3.1 phase 2, steps 1 and 2 */
    size_t trim_jumps;  /* overgrow: trimmed pieces joined by a straight stitch */
    /* the sizes used, mm */
    double r_min, r_first, r_grow, touch, k;
    double draw_in;     /* circles (and trimmed paths) drawn this far inside */
    /* packing only: per pebble its motif and map (unit frame -> mm) */
    uint32_t *motif;
    qc__xf *xf;
} qc__pebbles;

QC__HIDDEN void qc__pebbles_free(qc_ctx *ctx, qc__pebbles *pb);

/*
 * Phases 1 and 2 of §5.3.1 over skel inside region: pebbles sized in the
 * skeleton's visiting order (fillers in the gaps), then leaves and pebbles
 * touching two others grown until they touch a third or the boundary;
 * then pebbles into the corners and along the seams left bare (phase 3).
 * b holds region's edges. *pb is filled (zeroed first). Errors: QC_EEMPTY
 * (no point, or no pebble fits), QC_ERANGE (spacing, r_seed), QC_EINVAL
 * (a skeleton index out of range), QC_ENOMEM.
 */
QC__HIDDEN int qc__pebbles_pack(qc_ctx *ctx, const qc_region *region, qc__pbound *b,
                                const qc_params *params, const qc_skeleton *skel,
                                qc__pebbles *pb);

/* Children of every pebble in the order a counter-clockwise walk round it
 * meets them, starting from its parent: kids[first[i] .. first[i + 1]).
 * *start_angle receives the root's starting angle (the middle of the widest
 * gap between its children). Arrays are allocated (n + 1 and n entries);
 * with angle_out, also *angle_out (n entries): each pebble's direction from
 * its parent, qc_atan2 of the centres' difference (the root's unset). */
/* first[0..n]: where each parent's children start, grouped by parent in the
 * order they were made (a counting sort: no qsort of 10^6 entries, nor its
 * hidden buffer); first[n] = the children's count. */
QC__HIDDEN void qc__pebbles_group_starts(const qc__pebbles *pb, uint32_t *first);
QC__HIDDEN int qc__pebbles_children(qc_ctx *ctx, const qc__pebbles *pb, uint32_t **first,
                                    uint32_t **kids, double *start_angle,
                                    double **angle_out);
/* Only *start_angle of qc__pebbles_children (the same bits): from the
 * root's children alone. */
QC__HIDDEN int qc__pebbles_start_angle(qc_ctx *ctx, const qc__pebbles *pb, double *start_angle);


/* Radius min/mean/max, count, pebbles touching fewer than three, coverage. */
QC__HIDDEN int qc__pebbles_stats(qc_ctx *ctx, const qc__pebbles *pb, qc__pbound *b,
                                 qc_stats *st);

/* ---- trimming overgrown paths (shared_pebble_trim.c) ---- */

/*
 * Appends the closed path in, cut to region moved inset mm inwards (the
 * region itself when that would change its shape), to out: every stretch
 * outside is replaced by the boundary between where it leaves and where it
 * comes back (the side that, with the stretch, does not wind round the
 * inside point ref; else the shorter). Curves wholly inside are kept, the
 * rest flattened to tol mm. Where the path meets the boundary it is drawn
 * 1e-4 tol inside, so two stretches along the same piece of boundary touch
 * and never cross. A stretch leaving by one ring and coming back by
 * another is joined straight (counted in *jumps). cell, max_cells: the
 * edge grid (qc__pbound_init). QC_EEMPTY when nothing is inside.
 */
QC__HIDDEN int qc__path_trim(qc_ctx *ctx, const qc_region *region, double cell,
                             size_t max_cells, double inset, const qc_path *in, qc_vec2 ref,
                             double tol, qc_path *out, size_t *jumps);

/* ---- the families with their pebbles kept (tests) ---- */

QC__HIDDEN int qc__pebbling_run(qc_ctx *ctx, const qc_region *region, const qc_params *params,
                                const qc_skeleton *skel, qc_path *out, qc_stats *stats,
                                qc__pebbles *keep);
QC__HIDDEN int qc__packing_run(qc_ctx *ctx, const qc_region *region, const qc_params *params,
                               const qc_skeleton *skel, const qc_motif_set *motifs,
                               qc_path *out, qc_stats *stats, qc__pebbles *keep);

/* Pebbling's and packing's own defaults (family_pebbling.c): snub points. */
QC__HIDDEN int qc__pebble_param_default(const qc_params *p, int id, double *value);

#endif
