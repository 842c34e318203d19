/*
 * quiltc core: version, status codes, the context (allocator + last error),
 * plain array types shared by every stage, and the seeded PRNG.
 *
 * Conventions (see STYLE.md): geometry in double millimetres, y up; fallible
 * functions return int, QC_OK (0) or a negative QC_E* code; a detail message
 * is kept in the qc_ctx; outputs are caller-owned structs filled by the call
 * and released with the matching qc_*_free(ctx, x), which accepts a zeroed or
 * already freed struct and leaves it zeroed, ready for reuse.
 *
 * One contract for every output, in every stage:
 * - A call that builds an output ("into *out": qc_region_shape, qc_region_copy,
 *   qc_delaunay, qc_stitch_plan, qc_io_read_pat, qc_generate, ...) zeroes it
 *   first and never reads or frees what it held: pass a fresh or freed struct
 *   (one still holding data would leak).
 * - A call that appends ("appended to *out": qc_*_push, qc_sample, qc_mst,
 *   qc_tree_walk, qc_tsp, qc_curve_*, qc_tile_repeat, qc_io_read_points,
 *   qc_motif_*, ...) adds after what *out holds.
 * - On error, a built output is empty (zeroed: nothing to free, freeing is
 *   harmless) and an appended output holds exactly what it held on entry
 *   (its capacity may have grown). tests/test_oom.c checks both at every
 *   failing allocation.
 */
#ifndef QUILTC_CORE_H
#define QUILTC_CORE_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define QC_VERSION_MAJOR 0
#define QC_VERSION_MINOR 1
#define QC_VERSION_PATCH 0
#define QC_VERSION_STRING "0.1.0"
#define QC_VERSION_NUMBER \
    (QC_VERSION_MAJOR * 10000 + QC_VERSION_MINOR * 100 + QC_VERSION_PATCH)

/* The library's version string, e.g. "0.1.0". */
const char *qc_version(void);
/* The library's QC_VERSION_NUMBER, e.g. 100 for 0.1.0 (the header's may differ). */
int qc_version_number(void);

/* One list generates the enum, qc_strerror() and qc_err_name(). */
#define QC_ERRNO_MAP(X)                                                   \
    X(OK, 0, "success")                                                   \
    X(EINVAL, -1, "invalid argument")                                     \
    X(ENOMEM, -2, "out of memory")                                        \
    X(ERANGE, -3, "value out of range")                                   \
    X(EFORMAT, -4, "malformed input")                                     \
    X(EDEGENERATE, -5, "degenerate geometry")                             \
    X(ENOSPC, -6, "buffer too small")                                     \
    X(ELIMIT, -7, "limit exceeded")                                       \
    X(EIO, -8, "write failed")                                            \
    X(EUNSUPPORTED, -9, "not supported")                                  \
    X(EINTERSECT, -10, "self-intersecting outline")                       \
    X(EEMPTY, -11, "nothing to work with")                                \
    X(EVERSION, -12, "header and library versions differ")

enum {
#define QC__ERR_ENUM(name, value, text) QC_##name = value,
    QC_ERRNO_MAP(QC__ERR_ENUM)
#undef QC__ERR_ENUM
    QC__ERR_LAST = -13
};

/* Static text for a status code ("out of memory"); unknown codes get "unknown error". */
const char *qc_strerror(int status);
/* The code's name without prefix ("ENOMEM"); unknown codes get "EUNKNOWN". */
const char *qc_err_name(int status);

/*
 * Allocator hook, Lua-style: new_size == 0 frees ptr (returns NULL);
 * otherwise (re)allocates ptr from old_size to new_size bytes and returns the
 * block or NULL on failure (leaving ptr valid). old_size is the exact size
 * previously asked for (0 when ptr is NULL).
 */
typedef void *(*qc_alloc_fn)(void *ud, void *ptr, size_t old_size,
                             size_t new_size);

#define QC_ERRMSG_MAX 256

/*
 * The context: caller-owned (stack, static or heap), set up by qc_ctx_init.
 * A context is used by one thread at a time; two contexts share nothing.
 */
struct qc_vec2;  /* below: the tour hook names them */
struct qc_order;

typedef struct qc_ctx {
    qc_alloc_fn alloc; /* never NULL after qc_ctx_init */
    void *alloc_ud;
    int status;        /* last status set by a failing call */
    char msg[QC_ERRMSG_MAX]; /* one-line detail of the last error */
    /* Optional: called with a stage name ("sample", "graph", ...) as each
     * stage of qc_generate begins and with "done" at the end, so a caller
     * with a clock can time them. The core itself has no clock. */
    void (*trace)(void *ud, const char *stage);
    void *trace_ud;
    /* Optional: tours from outside the core (an exact solver the caller can
     * run, such as Concorde). When set, qc_generate's tour skeletons ask it
     * instead of qc_tsp, with the params' tsp_time_ms as its budget: it
     * appends to *order a permutation of pts[0..n) in any rotation (the
     * core starts it at the root and refuses anything else), or returns a
     * negative QC_ status, which qc_generate returns. */
    int (*tour)(void *ud, const struct qc_vec2 *pts, size_t n, double budget_ms,
                struct qc_order *order);
    void *tour_ud;
} qc_ctx;

/*
 * Prepares ctx; returns QC_OK. alloc == NULL selects the libc malloc wrapper
 * (qc_default_alloc, in its own object file). A core built with
 * -DQC_NO_DEFAULT_ALLOC (make firmware) leaves it out: there a NULL hook
 * fails every allocation and nothing references malloc.
 *
 * A macro, as zlib's inflateInit: it hands the library this header's
 * QC_VERSION_NUMBER and sizeof(qc_ctx). A library of another ABI (another
 * major version, or another minor before 1.0: the soname's rule) or another
 * qc_ctx size refuses with QC_EVERSION. Then, if the caller's qc_ctx is at
 * least as large as the library's, ctx holds the status and a message naming
 * both versions and its allocator fails every call, so later calls fail
 * cleanly; a smaller qc_ctx is not written at all.
 */
#define qc_ctx_init(ctx, alloc, alloc_ud) \
    qc_ctx_init_((ctx), (alloc), (alloc_ud), QC_VERSION_NUMBER, sizeof(qc_ctx))
int qc_ctx_init_(qc_ctx *ctx, qc_alloc_fn alloc, void *alloc_ud, int header_version,
                 size_t ctx_size);
/* The libc-backed allocator used when qc_ctx_init gets NULL. */
void *qc_default_alloc(void *ud, void *ptr, size_t old_size, size_t new_size);
/* The detail message of the last error, or "" when none. Never NULL. */
const char *qc_errmsg(const qc_ctx *ctx);
/* Forgets the last error. */
void qc_clear_error(qc_ctx *ctx);

/* ---- plain data ---- */

typedef struct qc_vec2 {
    double x, y;
} qc_vec2;

typedef struct qc_bbox {
    qc_vec2 min, max;
} qc_bbox;

/* A point set. cap is the allocated element count (needed to free). */
typedef struct qc_points {
    qc_vec2 *v;
    size_t n, cap;
} qc_points;

/* An undirected edge between two point indices. */
typedef struct qc_edge {
    uint32_t a, b;
} qc_edge;

typedef struct qc_edges {
    qc_edge *e;
    size_t n, cap;
} qc_edges;

/* A sequence of point indices (a tree walk or a tour). */
typedef struct qc_order {
    uint32_t *i;
    size_t n, cap;
} qc_order;

void qc_points_free(qc_ctx *ctx, qc_points *pts);
void qc_edges_free(qc_ctx *ctx, qc_edges *edges);
void qc_order_free(qc_ctx *ctx, qc_order *order);
/* Appends one point/edge/index, growing the array through ctx. QC_OK or QC_ENOMEM. */
int qc_points_push(qc_ctx *ctx, qc_points *pts, qc_vec2 p);
int qc_edges_push(qc_ctx *ctx, qc_edges *edges, uint32_t a, uint32_t b);
int qc_order_push(qc_ctx *ctx, qc_order *order, uint32_t i);

/*
 * A path: a sequence of commands, each with its points in pt[]:
 * QC_PATH_MOVE (1 point: start a new piece), QC_PATH_LINE (1: end point),
 * QC_PATH_CUBIC (3: control 1, control 2, end point). A continuous pattern
 * has exactly one MOVE, the first command.
 */
enum { QC_PATH_MOVE = 0, QC_PATH_LINE = 1, QC_PATH_CUBIC = 2 };

typedef struct qc_path {
    unsigned char *cmd;
    size_t ncmd, cmd_cap;
    qc_vec2 *pt;
    size_t npt, pt_cap;
} qc_path;

void qc_path_free(qc_ctx *ctx, qc_path *path);
int qc_path_move_to(qc_ctx *ctx, qc_path *path, qc_vec2 p);
int qc_path_line_to(qc_ctx *ctx, qc_path *path, qc_vec2 p);
int qc_path_cubic_to(qc_ctx *ctx, qc_path *path, qc_vec2 c1, qc_vec2 c2,
                     qc_vec2 p);
/* Appends every command of src to dst; with join != 0 a leading MOVE of src
 * becomes a LINE (so the result stays one piece). On QC_ENOMEM dst is left
 * as it was. */
int qc_path_append(qc_ctx *ctx, qc_path *dst, const qc_path *src, int join);
/* Number of points per command (1 or 3). */
size_t qc_path_cmd_points(unsigned char cmd);
/* The current (last) point; (0, 0) for an empty path. */
qc_vec2 qc_path_last(const qc_path *path);
/* Number of MOVE commands, i.e. separate pieces. */
size_t qc_path_pieces(const qc_path *path);

/* ---- seeded PRNG (xoshiro256**, seeded by splitmix64) ---- */

typedef struct qc_rng {
    uint64_t s[4];
} qc_rng;

void qc_rng_seed(qc_rng *rng, uint64_t seed);
uint64_t qc_rng_u64(qc_rng *rng);
/* Uniform double in [0, 1), 53 random bits. */
double qc_rng_unit(qc_rng *rng);
/* Uniform integer in [0, n); n > 0. Unbiased. */
uint64_t qc_rng_below(qc_rng *rng, uint64_t n);

/* ---- deterministic math: same bits on every platform (no libm transcendental) ---- */

#define QC_PI 3.14159265358979323846

double qc_sin(double x);
double qc_cos(double x);
/* Angle of (x, y) in (-pi, pi]; qc_atan2(0, 0) == 0. */
double qc_atan2(double y, double x);
/* sqrt(x*x + y*y) without libm's hypot (whose last bit varies). */
double qc_hypot(double x, double y);

#ifdef __cplusplus
}
#endif
#endif
