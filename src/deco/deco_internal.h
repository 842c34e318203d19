/*
 * Internals shared by the decoration families (src/deco/): motif geometry,
 * the collision grid, affine placement.
 */
#ifndef QC_DECO_INTERNAL_H
#define QC_DECO_INTERNAL_H

#include "internal.h"

/* ---- motif geometry (shared_motif_geom.c) ---- */

/* Convex hull of pts[0..n) (Andrew's monotone chain), CCW, no collinear
 * points, written to out (room for 2n); scratch holds 2n. Returns the count. */
/* QC_ELIMIT when cols x rows copies of a tile_points-point tile exceed
 * QC_MAX_TILED_POINTS (tile.c), before any copy is made. */
QC__HIDDEN int qc__tile_budget(qc_ctx *ctx, size_t tile_points, unsigned cols, unsigned rows);
QC__HIDDEN size_t qc__convex_hull(const qc_vec2 *pts, size_t n, qc_vec2 *out,
                                  qc_vec2 *scratch);
/* Moves every edge of the CCW convex polygon h[0..n) outward by d, so a hull
 * of a polyline within d of a curve holds the curve. tmp holds n points. */
QC__HIDDEN void qc__hull_outset(qc_vec2 *h, size_t n, qc_vec2 *tmp, double d);
/* Minimum bounding circle of pts[0..n) (Welzl, iterative, the points visited
 * in a fixed pseudo-random order). scratch holds n points. n == 0: r = 0. */
QC__HIDDEN void qc__min_circle(const qc_vec2 *pts, size_t n, qc_vec2 *scratch,
                               qc_vec2 *c, double *r);

/* Takes ownership of *path (any units, y up) and appends it to out as a
 * motif named name: closed (ends at its start) -> a branching motif attached
 * at its start; open with >= 4 commands -> a Wanderer primitive whose first
 * and last segments are the legs. Later MOVEs become LINEs. *path is freed
 * and zeroed in every case. Errors: QC_EDEGENERATE, QC_ENOMEM. */
QC__HIDDEN int qc__motif_from_path(qc_ctx *ctx, qc_path *path, const char *name,
                                   qc_motif_set *out);

/* An affine map: (x, y) -> (a x + b y + tx, c x + d y + ty). */
typedef struct qc__xf {
    double a, b, c, d, tx, ty;
} qc__xf;

static inline qc_vec2 qc__xf_apply(const qc__xf *f, qc_vec2 p)
{
    qc_vec2 q;
    q.x = f->a * p.x + f->b * p.y + f->tx;
    q.y = f->c * p.x + f->d * p.y + f->ty;
    return q;
}

/* Appends path's commands mapped by f, its leading MOVE turned into a LINE
 * (or dropped when it lands on the current point): a detour from *out. */
QC__HIDDEN int qc__path_append_xf(qc_ctx *ctx, qc_path *out, const qc_path *path,
                                  const qc__xf *f);

/* ---- collision grid (shared_collide.c) ---- */

/* Convex polygons (2 vertices: a segment) binned in a uniform grid. */
typedef struct qc__cgrid_item {
    qc_bbox box;    /* prefilter */
    uint32_t off;   /* first vertex in v */
    uint16_t n;     /* vertex count */
    uint8_t kind;   /* caller's class: boundary, vine, motif, join ... */
    uint8_t chain;  /* 1: an open polyline, tested segment by segment;
                     * 2: a convex polygon the owner's shape callback gives */
    uint32_t id;    /* caller's id */
} qc__cgrid_item;

typedef struct qc__cgrid_ent {
    uint32_t item, next;
} qc__cgrid_ent;

typedef struct qc__cgrid {
    double x0, y0, cell;
    uint32_t nx, ny;
    uint32_t *head;           /* nx * ny, first entry or UINT32_MAX */
    qc__cgrid_ent *ent;
    size_t nent, ent_cap;
    qc__cgrid_item *item;
    uint32_t *stamp;
    size_t nitem, item_cap, stamp_cap;
    qc_vec2 *v;
    size_t nv, v_cap;
    uint32_t cur;
    /* the vertices of a shape item (chain 2) with id id, into a buffer of
     * the owner's that no query uses: the owner keeps what makes them */
    const qc_vec2 *(*shape)(void *ud, uint32_t id);
    void *shape_ud;
} qc__cgrid;

/* Skips item (kind, id) when it returns non-zero. */
typedef int (*qc__cgrid_skip)(void *ud, unsigned kind, uint32_t id);

/* A grid over box with cells of about cell mm, at most max_cells cells. */
QC__HIDDEN int qc__cgrid_init(qc_ctx *ctx, qc__cgrid *g, qc_bbox box, double cell,
                              size_t max_cells);
QC__HIDDEN void qc__cgrid_free(qc_ctx *ctx, qc__cgrid *g);
/* Adds a convex polygon (n >= 1, CCW when n >= 3). */
QC__HIDDEN int qc__cgrid_add(qc_ctx *ctx, qc__cgrid *g, const qc_vec2 *poly, size_t n,
                             unsigned kind, uint32_t id);
/* Adds convex polygon poly (n vertices) as a shape item: binned and
 * tested as qc__cgrid_add's, its vertices not stored but asked of
 * g->shape (which must then give poly again) when a query reaches it. */
QC__HIDDEN int qc__cgrid_add_shape(qc_ctx *ctx, qc__cgrid *g, const qc_vec2 *poly, size_t n,
                                   unsigned kind, uint32_t id);
/* Adds an open polyline (2 <= n <= 65535) as one item that touches what
 * one of its segments touches: as its segments added one by one, in one
 * item, one vertex per joint and the cells its segments meet. */
QC__HIDDEN int qc__cgrid_add_chain(qc_ctx *ctx, qc__cgrid *g, const qc_vec2 *pts, size_t n,
                                   unsigned kind, uint32_t id);
/* Adds every boundary edge of region as a two-point item of kind (id 0). */
QC__HIDDEN int qc__cgrid_add_region(qc_ctx *ctx, qc__cgrid *g, const qc_region *region,
                                    unsigned kind);
/* 1 if poly touches an item whose kind bit is in kinds and that skip does
 * not exclude (skip may be NULL), else 0. */
QC__HIDDEN int qc__cgrid_hit(qc__cgrid *g, const qc_vec2 *poly, size_t n,
                             unsigned kinds, qc__cgrid_skip skip, void *ud);
/* Per-segment skip for polyline queries. */
typedef int (*qc__cgrid_skip_seg)(void *ud, unsigned kind, uint32_t id, size_t seg);
/* 1 if a segment of the polyline pts[0..n) touches an item (one pass over
 * the cells under the polyline's box), else 0. */
QC__HIDDEN int qc__cgrid_hit_polyline(qc__cgrid *g, const qc_vec2 *pts, size_t n,
                                      unsigned kinds, qc__cgrid_skip_seg skip, void *ud);
/* Makes room for exactly items more items of verts vertices and entries cells
 * in all (a later add beyond them grows the arrays geometrically). */
QC__HIDDEN int qc__cgrid_reserve(qc_ctx *ctx, qc__cgrid *g, size_t items, size_t verts,
                                 size_t entries);
/* Separating-axis test of two convex polygons (1 or 2 vertices allowed);
 * 1 if they touch or overlap (within eps mm). */
QC__HIDDEN int qc__convex_touch(const qc_vec2 *a, size_t na, const qc_vec2 *b,
                                size_t nb, double eps);

/* ---- inspection (tests) ---- */

/* What branching placed: per motif its attachment point and its collision
 * hulls in mm (full: against motifs and boundary; body: against the vine). */
typedef struct qc__placement {
    qc_points full, body;  /* hull vertices, ring after ring */
    qc_order full_end, body_end; /* one past each hull's last vertex */
    qc_points attach;
    qc_points vine;        /* the vine, flattened as tested */
} qc__placement;

QC__HIDDEN void qc__placement_free(qc_ctx *ctx, qc__placement *pl);
/* qc_deco_branching that also records its placements into *pl (may be NULL). */
QC__HIDDEN int qc__branching_run(qc_ctx *ctx, const qc_region *region,
                                 const qc_params *params, const qc_skeleton *skel,
                                 const qc_motif_set *motifs, qc_path *out,
                                 qc_stats *stats, qc__placement *pl);

/* ---- fixed-width fill outlines (shared_fill_tree.c) ---- */

/* A tree as half-edges sorted counter-clockwise round each node. */
typedef struct qc__ftree {
    const qc_vec2 *p;  /* node positions */
    size_t n;          /* nodes */
    uint32_t *off;     /* n + 1: node v's half-edges are [off[v], off[v+1]) */
    uint32_t *src, *tgt, *twin; /* per half-edge */
    size_t nh;         /* half-edges (2 per tree edge) */
    uint32_t *rep;     /* n: the node each point was merged into */
} qc__ftree;

/* Builds the half-edge tree from edges over p[0..n) (zero-length edges
 * dropped, their ends merged, so duplicate points are one node). Errors:
 * QC_EINVAL (an index out of range), QC_ENOMEM. */
QC__HIDDEN int qc__ftree_build(qc_ctx *ctx, const qc_vec2 *p, size_t n, const qc_edge *e,
                               size_t ne, qc__ftree *t);
QC__HIDDEN void qc__ftree_free(qc_ctx *ctx, qc__ftree *t);
/* The node a duplicate point was merged into. */
QC__HIDDEN uint32_t qc__ftree_rep(const qc__ftree *t, uint32_t v);

/* How an outline is drawn. */
typedef struct qc__fstyle {
    double half;       /* w / 2 */
    double tip;        /* tip circle radius (> half), 0 for none */
    double arc_step;   /* largest angle of one arc segment, radians */
    const double *tip_at; /* per node tip radius overriding tip, or NULL */
} qc__fstyle;

/* The closed outline at distance half round the whole tree, counter-
 * clockwise, starting at root (points appended, the first not repeated). */
QC__HIDDEN int qc__ftree_loop(qc_ctx *ctx, const qc__ftree *t, uint32_t root,
                              const qc__fstyle *st, qc_points *out);
/* The open outline from leaf a to leaf b: the a-b path is crossed once,
 * every other branch outlined on its own side (tiles). */
QC__HIDDEN int qc__ftree_open(qc_ctx *ctx, const qc__ftree *t, uint32_t a, uint32_t b,
                              const qc__fstyle *st, qc_points *out);

/* ---- the fill and stipple runner (shared_fill_outline.c) ---- */

/* What tells fill and stipple apart. */
typedef struct qc__outline_style {
    const char *name;  /* the family, for messages */
    double arc_step;   /* largest tip-arc angle, radians */
    int smooth;        /* 1: through a Catmull-Rom spline; 0: straight lines */
} qc__outline_style;

/* The tree outlined at params->width (tiled when params->tile asks), the
 * path appended to out; stats->largest_gap_mm filled unless skipped. */
QC__HIDDEN int qc__fill_outline(qc_ctx *ctx, const qc_region *region, const qc_params *prm,
                                const qc_skeleton *skel, const qc__outline_style *style,
                                qc_path *out, qc_stats *stats);

/* The parameters fill and stipple read. */
#define QC__FILL_PARAMS                                                              \
    (QC_PARAM_BIT(QC_PARAM_ID_TILE) | QC_PARAM_BIT(QC_PARAM_ID_TIP) |               \
     QC_PARAM_BIT(QC_PARAM_ID_WIDTH) | QC_PARAM_BIT(QC_PARAM_ID_REPEAT_COLS) |       \
     QC_PARAM_BIT(QC_PARAM_ID_REPEAT_ROWS) | QC_PARAM_BIT(QC_PARAM_ID_ROW_OFFSET))

/* ---- tiles (tile.c) ---- */

/* Port stubs: the nearest this many points are tried. */
#define PORT_CANDIDATES 16

/* The tree node a tile port at a joins: the nearest (of the PORT_CANDIDATES
 * nearest) whose straight stub crosses no tree edge; the nearest if all
 * cross. Ties: the lowest index. */
QC__HIDDEN uint32_t qc__tile_port_node(const qc_vec2 *p, size_t n, const qc_edge *e, size_t ne,
                                       qc_vec2 a);

/* ---- distance grids and offset rings (shared_sdf.c, shared_sdf_rings.c,
 *      shared_ring_repair.c) ---- */

/* Distance to a region's boundary sampled on a grid: node (i, j) at
 * (x0 + i h, y0 + j h), v > 0 inside, < 0 outside; seg: each node's
 * nearest boundary edge (edge e runs from vertex prev[e] to vertex e;
 * next[e] is the edge after it, ring[e] its ring); flat: 1 where the
 * nearest point is inside that edge. The region must outlive the grid. */
typedef struct qc__sdf {
    double x0, y0, h;
    size_t nx, ny;
    double *v;
    uint32_t *seg;
    unsigned char *flat;
    uint32_t *prev, *next, *ring;
    /* per edge e: its start (prev[e]'s vertex), its vector and squared
     * length, as the distance queries compute them (5 doubles) */
    double *eg;
    const qc_region *region;
} qc__sdf;

/* The signed distance of a normalized region on a grid of spacing about h
 * (raised so the grid has at most 2^24 nodes) padded by two nodes round its
 * box: exact distances near the boundary, nearest edges carried by two
 * raster sweeps elsewhere. Errors: QC_EEMPTY (no outline), QC_ERANGE (h not
 * > 0), QC_ENOMEM. */
QC__HIDDEN int qc__sdf_build(qc_ctx *ctx, const qc_region *region, double h, qc__sdf *out);
/* The spacing qc__sdf_build would use for h (h itself when the region or h
 * is unusable): decided before anything is allocated. */
QC__HIDDEN double qc__sdf_step(const qc_region *region, double h);
QC__HIDDEN void qc__sdf_free(qc_ctx *ctx, qc__sdf *s);
/* Bilinear value at p (the border value outside the grid). */
QC__HIDDEN double qc__sdf_at(const qc__sdf *s, qc_vec2 p);
/* Signed distance at p to the nearest of the edges nearest to the four
 * nodes round p and their neighbours (exact wherever those include the
 * true nearest edge, which is all but contrived cases); grad (may be NULL)
 * receives the unit gradient. */
QC__HIDDEN double qc__sdf_exact(const qc__sdf *s, qc_vec2 p, qc_vec2 *grad);
/* The same, also giving the nearest edge (*edge) and whether the nearest
 * point is inside it (*flat: the distance is to a line there). */
QC__HIDDEN double qc__sdf_exact_full(const qc__sdf *s, qc_vec2 p, qc_vec2 *grad, uint32_t *edge,
                                     int *flat);
/* Grid node of largest value (ties: the lowest index) and its position. */
QC__HIDDEN double qc__sdf_max(const qc__sdf *s, qc_vec2 *at);

/* Closed rings, ring after ring (closing implicitly). */
typedef struct qc__rings {
    qc_points pts;
    qc_order end;      /* one past each ring's last vertex */
    qc_order level;    /* each ring's level index k */
} qc__rings;

/* Appends the iso-contours v = l0 + k step, k = 0 .. max_levels - 1, by
 * marching squares (saddles by the cell's mean), each with the higher side
 * on its left (counter-clockwise round the parts above the level). Every
 * vertex lies on its level (exact field) and every chord within 0.2% of
 * step of it. Errors: QC_ENOMEM. */
QC__HIDDEN int qc__sdf_rings(qc_ctx *ctx, const qc__sdf *s, double l0, double step,
                             size_t max_levels, qc__rings *out);
QC__HIDDEN void qc__rings_free(qc_ctx *ctx, qc__rings *r);
/* shared_ring_repair.c, on the rings from index first on (h: the grid step):
 * drops small islands that cross a larger ring of their level or
 * themselves; undoes crossings within a level by rejoining segments. */
QC__HIDDEN void qc__rings_prune_islands(qc__rings *r, size_t first, double h);
QC__HIDDEN int qc__rings_untangle(qc_ctx *ctx, qc__rings *r, size_t first, double h);

/* ---- rings joined into one path (family_echo_join.c) ---- */

typedef struct qc__join_opts {
    double gap;      /* width of a ladder: two parallel steps gap mm apart */
    double reach;    /* longest ordinary step, mm */
    uint32_t start;  /* vertex (index into the rings' points) to start at */
    int spiral;      /* 1: chain rings by single steps where possible (open path) */
    const qc__sdf *sdf; /* if not NULL, steps keep sdf >= vmin (the margin) */
    double vmin;
} qc__join_opts;

/* What the join did. */
typedef struct qc__join_info {
    size_t ladders, spurs, tails; /* links of each kind */
    size_t jumps;    /* rings reached by a straight jump (no clear step) */
    size_t low;      /* steps that had to leave the sdf >= vmin zone */
} qc__join_info;

/* Joins every ring into one path appended to *out (consecutive points are
 * joined; no closing point is implied). Rings are linked into a tree by
 * steps along their normals that cross no ring and no other step, chosen
 * shortest first: ladders (two parallel steps; the walk goes out along
 * one, round the other ring and back along the other) or, for rings too
 * small to cut, spurs (one step sewn out and back). With spiral set, a
 * chain of single steps (each ring sewn round from where the step lands
 * to just short of it, then on to the next ring) is laid first, so
 * concentric rings become one spiral. Rings no step reaches are joined by
 * straight jumps (counted). Errors: QC_ENOMEM. */
QC__HIDDEN int qc__rings_join(qc_ctx *ctx, const qc__rings *r, const qc__join_opts *o,
                              qc_points *out, qc__join_info *info);

/* ---- offset contours joined into one path (shared_contour.c: echo, spiral) ---- */

typedef struct qc__contour {
    qc__sdf sdf;
    qc__rings rings;  /* outermost level first */
    double l0;        /* the outermost level: the margin (at least 0.001 d) */
    double vmax;      /* the deepest grid node's distance from the boundary */
    qc_vec2 at_max;   /* and where it lies */
} qc__contour;

/* The rings margin + k d (equal_area: rings d sqrt(n) in from the deepest
 * point, each enclosing pi d^2 less than the next on a disc). Messages name
 * who. Errors: QC_EEMPTY (no outline, no ring fits), QC_ERANGE (d),
 * QC_ELIMIT (d too fine for the grid, too many equal-area rings),
 * QC_ENOMEM. On failure *c holds nothing. */
QC__HIDDEN int qc__contour_build(qc_ctx *ctx, const qc_region *region, double d, double margin,
                                 int equal_area, const char *who, qc__contour *c);
/* shared_contour_caps.c: a small ring (a cap) on each peak of the distance
 * field farther than 0.97 d from every ring, so no fabric lies much farther
 * than d from a stitch. Errors: QC_ENOMEM. */
QC__HIDDEN int qc__contour_cap_peaks(qc_ctx *ctx, qc__contour *c, double d);
/* The rings joined (qc__rings_join, spiral mode or not) from the ring point
 * nearest start and appended to *out as one polyline (all or nothing);
 * stats: largest gap (unless params->skip_gap_stat), joins unfixed. */
QC__HIDDEN int qc__contour_sew(qc_ctx *ctx, const qc_region *region, const qc_params *params,
                               const qc__contour *c, qc_vec2 start, int spiral, qc_path *out,
                               qc_stats *stats);
QC__HIDDEN void qc__contour_free(qc_ctx *ctx, qc__contour *c);
/* family_spiral_out.c: the rings sewn as a double spiral from the ring 0
 * point nearest start, in on every other ring and back out between them,
 * ending on the boundary at the start (or nearest ring 0's band); appended
 * to *out (all or nothing),
 * stats: largest gap. 1 when sewn, 0 when the rings do not nest one a
 * level or are too few or small (nothing appended), or QC_ENOMEM. */
QC__HIDDEN int qc__spiral_in_out(qc_ctx *ctx, const qc_region *region, const qc_params *params,
                                 const qc__contour *c, qc_vec2 start, qc_path *out,
                                 qc_stats *stats);

#endif
