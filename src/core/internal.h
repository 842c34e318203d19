/*
 * Internals shared across the core's files: error reporting into the
 * context and allocation through the caller's hook. Not installed.
 */
#ifndef QC_INTERNAL_H
#define QC_INTERNAL_H

#include <math.h>
#include <stddef.h>

#include "quiltc.h"

#if defined(__GNUC__) && !defined(__EMSCRIPTEN__) && !defined(_WIN32)
#define QC__HIDDEN __attribute__((visibility("hidden")))
#define QC__PRINTF(f, a) __attribute__((format(printf, f, a)))
#else
#define QC__HIDDEN
#define QC__PRINTF(f, a)
#endif

/* Records status and a printf-style one-line message in ctx; returns status. */
QC__HIDDEN int qc__fail(qc_ctx *ctx, int status, const char *fmt, ...)
    QC__PRINTF(3, 4);

/* Allocation through ctx->alloc. qc__alloc(ctx, 0) returns NULL. */
QC__HIDDEN void *qc__alloc(qc_ctx *ctx, size_t size);
QC__HIDDEN void *qc__realloc(qc_ctx *ctx, void *ptr, size_t old_size,
                             size_t new_size);
QC__HIDDEN void qc__free(qc_ctx *ctx, void *ptr, size_t size);
/* count * elem bytes, or NULL (and QC_ENOMEM in ctx) on overflow or failure. */
QC__HIDDEN void *qc__alloc_array(qc_ctx *ctx, size_t count, size_t elem);

/*
 * Makes room for at least need elements of elem bytes in *ptr (capacity *cap,
 * in elements), growing geometrically. QC_OK, or QC_ENOMEM with *ptr intact.
 */
QC__HIDDEN int qc__reserve(qc_ctx *ctx, void **ptr, size_t *cap, size_t need,
                           size_t elem);

/* The call only when the room is short: a path's push asks twice per
 * command, and most asks find room. need and capv are read twice. */
#define QC__RESERVE(ctx, arr, capv, need)                                          \
    ((size_t)(need) <= (capv) ? QC_OK                                              \
                              : qc__reserve((ctx), (void **)&(arr), &(capv), (need), \
                                            sizeof *(arr)))

/* The same with room for exactly need elements (no doubling): for a large
 * array whose final size is known or well estimated up front. */
QC__HIDDEN int qc__reserve_exact(qc_ctx *ctx, void **ptr, size_t *cap, size_t need,
                                 size_t elem);

#define QC__RESERVE_EXACT(ctx, arr, capv, need) \
    qc__reserve_exact((ctx), (void **)&(arr), &(capv), (need), sizeof *(arr))

/* Cut a finished array or path to what it holds (a failed shrink keeps the
 * block): results held to the end carry no doubling slack. */
QC__HIDDEN void qc__points_fit(qc_ctx *ctx, qc_points *a);
QC__HIDDEN void qc__path_fit(qc_ctx *ctx, qc_path *path);

/* Scans a decimal number ([+-] digits [. digits] [(e|E) [+-] digits]; no
 * hex, nan, inf or locale) at s[*pos..n): 1 with *v correctly rounded
 * (possibly +-inf for a huge exponent) and *pos past it, or 0 when none
 * starts there. An 'e' without exponent digits is left unread. number.c. */
QC__HIDDEN int qc__scan_number(const char *s, size_t n, size_t *pos, double *v);

/* *s = qc_sin(x) and *c = qc_cos(x), the same bits, from one reduction
 * (a circle's arcs ask both of every angle). qmath.c. */
QC__HIDDEN void qc__sincos(double x, double *s, double *c);

/* Squared distance from p to segment ab (a point when a == b); the one
 * formula every stage uses, so their answers agree to the bit. Inline: the
 * flattening asks it twice per subdivision, and the two share the chord's
 * terms once inlined. */
static inline double qc__seg_dist2(qc_vec2 p, qc_vec2 a, qc_vec2 b)
{
    double dx = b.x - a.x, dy = b.y - a.y;
    double len2 = dx * dx + dy * dy;
    double t = len2 > 0.0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / len2 : 0.0;
    double ex, ey;

    t = t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t;
    ex = a.x + t * dx - p.x;
    ey = a.y + t * dy - p.y;
    return ex * ex + ey * ey;
}

/* Index of the point of p[0..n) nearest q (ties: the lowest); 0 when n == 0. */
QC__HIDDEN size_t qc__nearest_point(const qc_vec2 *p, size_t n, qc_vec2 q);

/* The bounding box of p[0..n), n >= 1. */
QC__HIDDEN qc_bbox qc__points_bbox(const qc_vec2 *p, size_t n);
/* cell, grown by half until a grid of that cell over box has at most
 * max_cells cells (bucket grids: about a constant number of items each). */
QC__HIDDEN double qc__fit_cell(qc_bbox box, double cell, double max_cells);

/* The ring of region r that vertex v belongs to (binary search of ring_end). */
QC__HIDDEN size_t qc__region_ring_of(const qc_region *r, size_t v);

/* The families' descriptors, one per src/deco/family_NAME.c (QC_FAMILY_MAP). */
#define QC__FAMILY_DECL(id, name) QC__HIDDEN extern const qc_family_desc qc__family_##name;
QC_FAMILY_MAP(QC__FAMILY_DECL)
#undef QC__FAMILY_DECL
/* value checked against parameter id's row of the table (the one source of
 * each range): QC_OK, or qc_params_resolve's error and message. */
QC__HIDDEN int qc__param_check(qc_ctx *ctx, int id, double value);
/* The descriptor of family id (a qc_family), or NULL. */
QC__HIDDEN const qc_family_desc *qc__family(int id);

/*
 * Stable LSD radix sort (radix_sort.c) of key[0..n) by bits [shift, 64),
 * carrying val[] along when val != NULL. Digits that are equal in every key
 * are skipped.
 * QC_OK or QC_ENOMEM (arrays untouched on failure).
 */
QC__HIDDEN int qc__radix_sort(qc_ctx *ctx, uint64_t *key, uint32_t *val,
                              size_t n, unsigned shift);

/* Index of cell (x, y) of a 2^bits x 2^bits grid along the Hilbert curve,
 * 1 <= bits <= 32 (hilbert_key.c). */
QC__HIDDEN uint64_t qc__hilbert_key(uint32_t x, uint32_t y, unsigned bits);

/* ---- rasters (raster.c): the measures and the SDF offsetting ---- */

/*
 * Even-odd inside mask of region on the lattice (x0 + i h, y0 + j h),
 * i < nx, j < ny: mask[j * nx + i] = 1 inside, 0 outside (a sample exactly
 * on a crossing counts as inside on its right). Scanline with the edges
 * bucketed by row: O(nx ny + perimeter / h + edges). QC_OK or QC_ENOMEM.
 */
QC__HIDDEN int qc__raster_inside(qc_ctx *ctx, const qc_region *region, double x0,
                                 double y0, double h, size_t nx, size_t ny,
                                 unsigned char *mask);

/* Felzenszwalb-Huttenlocher 1-D squared distance transform of f[0..n)
 * (step 1) into d (not overlapping f: it is scratch till the last pass);
 * v (n ints) and z (n + 1 doubles) are scratch. */
QC__HIDDEN void qc__edt_1d(const double *f, size_t n, double *d, int *v, double *z);

/* ---- segments in a uniform grid (seg_grid.c) ---- */

/* Segment k runs from p[k] to p[next(ud, k)]. */
typedef uint32_t (*qc__seg_next)(const void *ud, uint32_t k);

typedef struct qc__seg_grid {
    double x0, y0, cell; /* the lower-left cell's corner; square cells */
    size_t gx, gy;
    size_t *start;       /* gx gy + 1 offsets into seg, row by row */
    uint32_t *seg;       /* segment numbers, cell by cell */
    size_t nseg;         /* entries allocated (at least 1) */
} qc__seg_grid;

/* Bins the n segments of p into cells of about cell mm, grown by half
 * until there are at most cells_per_seg n + 64 of them. QC_OK or QC_ENOMEM
 * (*g then freed). */
QC__HIDDEN int qc__seg_grid_build(qc_ctx *ctx, qc__seg_grid *g, const qc_vec2 *p, size_t n,
                                  qc__seg_next next, const void *ud, double cell,
                                  double cells_per_seg);
/* qc_hypot's formula (qmath.c returns it), inline for the loops that
 * measure a segment per vertex per round: the same bits, no call. */
static inline double qc__hypot(double x, double y)
{
    return sqrt(x * x + y * y);
}

/* fmin and fmax as C99 has them (a NaN loses), without the library call,
 * for binning loops that take an edge's box several times per query. */
static inline double qc__lesser(double a, double b)
{
    return a < b || b != b ? a : b;
}

static inline double qc__greater(double a, double b)
{
    return a > b || b != b ? a : b;
}

/* The cell of grid coordinate t (in cells) on a row of n: floor(t) clamped
 * to [0, n - 1], NaN to 0. Truncation is floor for t >= 1, so binning loops
 * make no libm call per coordinate. */
static inline size_t qc__grid_cell(double t, size_t n)
{
    if (!(t >= 1.0))
        return 0;
    return t < (double)(n - 1) ? (size_t)t : n - 1;
}

/* The cells (x0, y0, x1, y1, inclusive) the box of ab meets, clamped. */
QC__HIDDEN void qc__seg_grid_cells(const qc__seg_grid *g, qc_vec2 a, qc_vec2 b, size_t c[4]);
QC__HIDDEN void qc__seg_grid_free(qc_ctx *ctx, qc__seg_grid *g);

/* Union-find over 0..n-1 (union_find.c). qc__uf_init makes every element
 * its own set; qc__uf_find returns the root (halving the path);
 * qc__uf_union joins two sets under the smaller root: 1, or 0 if a and b
 * were in one set already. */
QC__HIDDEN void qc__uf_init(uint32_t *parent, size_t n);
QC__HIDDEN uint32_t qc__uf_find(uint32_t *parent, uint32_t x);
QC__HIDDEN int qc__uf_union(uint32_t *parent, uint32_t a, uint32_t b);

/* White space in every text format the core reads, without the C locale's
 * isspace: blank, tab, LF, CR, form feed. */
/* xoshiro256** (rng.c), inline for the samplers' inner loops: qc_rng_u64
 * and qc_rng_unit are these. */
static inline uint64_t qc__rng_u64(qc_rng *rng)
{
    uint64_t *s = rng->s, x = s[1] * 5, t = s[1] << 17, result;

    result = ((x << 7) | (x >> 57)) * 9;
    s[2] ^= s[0];
    s[3] ^= s[1];
    s[1] ^= s[2];
    s[0] ^= s[3];
    s[2] ^= t;
    s[3] = (s[3] << 45) | (s[3] >> 19);
    return result;
}

static inline double qc__rng_unit(qc_rng *rng)
{
    return (double)(qc__rng_u64(rng) >> 11) * (1.0 / 9007199254740992.0);
}

static inline int qc__is_space(char c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f';
}

/* Whether segments ab and cd cross properly: each one's ends strictly on
 * either side of the other (exact orientation: touching is not crossing). */
static inline int qc__segs_cross_proper(qc_vec2 a, qc_vec2 b, qc_vec2 c, qc_vec2 d)
{
    double o1 = qc_orient2d(a, b, c), o2 = qc_orient2d(a, b, d);
    double o3, o4;

    if (!((o1 > 0.0 && o2 < 0.0) || (o1 < 0.0 && o2 > 0.0)))
        return 0;
    o3 = qc_orient2d(c, d, a);
    o4 = qc_orient2d(c, d, b);
    return (o3 > 0.0 && o4 < 0.0) || (o3 < 0.0 && o4 > 0.0);
}

/* A point from its coordinates (a C99 compound literal). */
#define QC__V2(x, y) ((qc_vec2){(x), (y)})

/* Returns the status if it is an error. */
#define QC__TRY(expr)            \
    do {                         \
        int qc__rc_ = (expr);    \
        if (qc__rc_ < 0)         \
            return qc__rc_;      \
    } while (0)

#endif
