/*
 * Patterns: the parameters of every family, described by one table (names,
 * units, ranges, defaults) that the CLI and the web page build their options
 * from, and qc_generate, the convenience tier that runs the stages
 * (sample -> graph -> tour -> curve -> decorate) for one region.
 */
#ifndef QUILTC_PATTERN_H
#define QUILTC_PATTERN_H

#include "core.h"
#include "region.h"
#include "motif.h"
#include "sample.h"
#include "graph.h"
#include "tour.h"

#ifdef __cplusplus
extern "C" {
#endif

/*
 * The families, one line each: X(ID, name). The enum, the names, the
 * dispatch and the `family` parameter's choices all come from this list;
 * each family describes itself (qc_family_desc) in its own file,
 * src/deco/family_NAME.c. Append new families at the end: the ids are
 * ABI. Adding one: docs/adding-a-family.md.
 */
#define QC_FAMILY_MAP(X)                                                    \
    X(VINE, vine)           /* the smoothed tree walk alone (paper §4.3) */ \
    X(BRANCHING, branching) /* §5.1 */                                      \
    X(WANDERER, wanderer)   /* §5.2 */                                      \
    X(PEBBLING, pebbling)   /* §5.3.1 */                                    \
    X(PACKING, packing)     /* §5.3.2 */                                    \
    X(FILL, fill)           /* §7.1 fixed-width fill */                     \
    X(STIPPLE, stipple)     /* §7.1 stippling / meander */                  \
    X(ECHO, echo)           /* beyond the paper */                          \
    X(SPIRAL, spiral)       /* beyond the paper */                          \
    X(MEANDER, meander)     /* one closed curve grown by curve evolution */ \
    /* a new family: one line above this one */

typedef enum qc_family {
    QC_FAMILY_DEFAULT = 0,
#define QC__FAMILY_ENUM(id, name) QC_FAMILY_##id,
    QC_FAMILY_MAP(QC__FAMILY_ENUM)
#undef QC__FAMILY_ENUM
    QC_FAMILY_COUNT
} qc_family;

/* Where the points come from: a sampler (the values are qc_sample_kind's,
 * so qc_generate passes them on unchanged) or the caller. */
typedef enum qc_points_kind {
    QC_POINTS_DEFAULT = 0,
    QC_POINTS_TRIANGLE = QC_SAMPLE_TRIANGLE,
    QC_POINTS_SQUARE = QC_SAMPLE_SQUARE,
    QC_POINTS_HEX = QC_SAMPLE_HEX,
    QC_POINTS_SNUB = QC_SAMPLE_SNUB, /* 3.3.4.3.4 */
    QC_POINTS_POISSON = QC_SAMPLE_POISSON,
    QC_POINTS_GIVEN = 6 /* the caller's points (qc_generate's given argument) */
} qc_points_kind;

typedef enum qc_skeleton_kind { QC_SKELETON_DEFAULT = 0, QC_SKELETON_MST, QC_SKELETON_TSP } qc_skeleton_kind;
typedef enum qc_edge_mode { QC_EDGE_DEFAULT = 0, QC_EDGE_STRICT, QC_EDGE_OVERGROW } qc_edge_mode;
typedef enum qc_tile_mode { QC_TILE_DEFAULT = 0, QC_TILE_NONE, QC_TILE_EDGE_TO_EDGE, QC_TILE_ALL_OVER } qc_tile_mode;
typedef enum qc_tip_mode { QC_TIP_DEFAULT = 0, QC_TIP_NONE, QC_TIP_CIRCLE } qc_tip_mode;
typedef enum qc_spiral_kind { QC_SPIRAL_DEFAULT = 0, QC_SPIRAL_ARCHIMEDEAN, QC_SPIRAL_FERMAT } qc_spiral_kind;
typedef enum qc_echo_join { QC_ECHO_DEFAULT = 0, QC_ECHO_SPIRAL, QC_ECHO_RINGS } qc_echo_join;

/*
 * The parameters' stable ids: bit (1 << id) in qc_params.given and in
 * qc_family_desc.params, whatever the table's row order. Append only.
 */
typedef enum qc_param_id {
    QC_PARAM_ID_FAMILY = 0,
    QC_PARAM_ID_POINTS,
    QC_PARAM_ID_SKELETON,
    QC_PARAM_ID_MST,
    QC_PARAM_ID_TSP,
    QC_PARAM_ID_EDGE,
    QC_PARAM_ID_TILE,
    QC_PARAM_ID_TIP,
    QC_PARAM_ID_SPIRAL,
    QC_PARAM_ID_ECHO_JOIN,
    QC_PARAM_ID_SEED,
    QC_PARAM_ID_SPACING,
    QC_PARAM_ID_MARGIN,
    QC_PARAM_ID_SIZE,
    QC_PARAM_ID_GAP,
    QC_PARAM_ID_ANGLE,
    QC_PARAM_ID_TANGENT,
    QC_PARAM_ID_R_SEED,
    QC_PARAM_ID_WIDTH,
    QC_PARAM_ID_TSP_TIME,
    QC_PARAM_ID_REPEAT_COLS,
    QC_PARAM_ID_REPEAT_ROWS,
    QC_PARAM_ID_START_X,
    QC_PARAM_ID_START_Y,
    QC_PARAM_ID_WIGGLE,
    QC_PARAM_ID_TURN_RADIUS,
    QC_PARAM_ID_ITERATIONS,
    QC_PARAM_ID_ROW_OFFSET,
    QC_PARAM_ID_COUNT /* at most 64: one bit each in qc_params.given */
} qc_param_id;

#define QC_PARAM_BIT(id) ((uint64_t)1 << (id))

/*
 * Every parameter of every family. A zero field means "default" unless its
 * bit is set in `given` (see qc_params_set), so a zeroed struct is valid.
 * Lengths are millimetres, angles degrees.
 */
typedef struct qc_params {
    uint64_t seed;
    uint64_t given;     /* QC_PARAM_BIT(id): parameter id was set explicitly */
    int family;         /* qc_family */
    int points;         /* qc_points_kind */
    int skeleton;       /* qc_skeleton_kind */
    int mst;            /* qc_mst_mode (graph.h) */
    int tsp;            /* qc_tsp_method (tour.h) */
    int edge;           /* qc_edge_mode (pebbling, packing) */
    int tile;           /* qc_tile_mode */
    int tip;            /* qc_tip_mode (fill, stipple) */
    int spiral;         /* qc_spiral_kind */
    int echo_join;      /* qc_echo_join */
    double spacing;     /* d: point distance */
    double margin;      /* gap kept between points and the boundary */
    double size;        /* s: motif size */
    double gap;         /* l: gap between motifs along the vine (branching) */
    double angle;       /* alpha: motif angle to the vine (branching) */
    double tangent;     /* l: tangent length ratio (wanderer) */
    double r_seed;      /* root pebble radius / d (pebbling, packing) */
    double width;       /* w: fill width (fill, stipple) */
    double tsp_time_ms; /* time-bounded Or-opt perturbation; 0 = none */
    double repeat_cols; /* tiles across (tiles) */
    double repeat_rows; /* tiles down (tiles) */
    double start_x, start_y; /* where to start: nearest point becomes the root */
    double wiggle;      /* meander: irregularity, 0..1 */
    double turn_radius; /* meander: smallest turn radius */
    double iterations;  /* meander: rounds of curve evolution */
    double row_offset;  /* tiles: odd rows moved right by this fraction of a tile */
    /* Not in the table: non-zero leaves qc_stats.largest_gap_mm,
     * farthest_fabric_mm and seam_bare at 0. The
     * measure never changes the path but costs about a third of a stipple,
     * so a live preview skips it. */
    int skip_gap_stat;
} qc_params;

typedef enum qc_param_type { QC_PARAM_INT, QC_PARAM_ENUM, QC_PARAM_REAL, QC_PARAM_LENGTH, QC_PARAM_SEED } qc_param_type;

/* One row of the parameter table. */
typedef struct qc_param_info {
    const char *name;   /* option name, e.g. "spacing" */
    const char *help;   /* one line */
    const char *unit;   /* "mm", "deg", "ratio", "count", "" */
    qc_param_type type;
    const char *choices; /* enums: names for 1, 2, ... separated by '|' */
    double min, max;     /* valid range (enums: 1..count) */
    double def;          /* default; for lengths 0 with def_per_spacing set */
    double def_per_spacing; /* lengths: default = this * resolved spacing */
    qc_param_id id;      /* stable: its bit in qc_params.given */
    size_t offset;       /* offsetof(qc_params, field) */
} qc_param_info;

/* The table; *count receives its length. Static, never freed. */
const qc_param_info *qc_param_table(size_t *count);
/* The row named name, or NULL. */
const qc_param_info *qc_param_find(const char *name);
/* The row with that id, or NULL. */
const qc_param_info *qc_param_by_id(int id);
/* The families row applies to: bit (1 << qc_family) for each (from the
 * families' descriptors: qc_family_desc.params and .needs). */
uint32_t qc_param_families(const qc_param_info *row);
/* Family name <-> id ("branching" <-> QC_FAMILY_BRANCHING); unknown: -1 / NULL. */
int qc_family_from_name(const char *name);
const char *qc_family_name(int family);
/* Enum choice name -> value (1-based) for row info, or -1. */
int qc_param_choice(const qc_param_info *info, const char *choice);
/* Sets a field by name and marks it given. QC_EINVAL for an unknown name. */
int qc_params_set(qc_ctx *ctx, qc_params *p, const char *name, double value);
/* Sets the seed and marks it given: every 64-bit value (a double, as
 * qc_params_set takes, holds only 53 bits). */
void qc_params_set_seed(qc_params *p, uint64_t seed);
/* Whether parameter id was set explicitly (its bit in p->given). */
int qc_params_given(const qc_params *p, int id);
/* Reads a field by its table row. */
double qc_params_get(const qc_params *p, const qc_param_info *info);

/*
 * Fills every default into *out (in may equal out) and checks ranges:
 * QC_ERANGE with "spacing 0.01 mm out of range [0.5, 500] mm" style messages,
 * QC_EINVAL for an unknown family or choice.
 */
int qc_params_resolve(qc_ctx *ctx, const qc_params *in, qc_params *out);

/* Figures about one generated pattern. */
typedef struct qc_stats {
    size_t points, edges, order;
    double length_mm;   /* path length, curves flattened at 0.05 mm */
    qc_bbox bbox;
    size_t pieces;      /* separate pieces in the path (1 for a good pattern) */
    /* motif families */
    size_t motifs_placed, motifs_shrunk, motifs_rotated, motifs_flipped, motifs_skipped;
    size_t joins_unfixed; /* wanderer connections that still cross */
    /* pebbling / packing */
    size_t pebbles, pebbles_under3;
    double radius_min, radius_mean, radius_max, coverage;
    double largest_gap_mm; /* largest empty circle the path misses; 0 if not computed */
    /* Every family (0 when skip_gap_stat): the farthest any point of the
     * region, boundary included, lies from the path (qc_fabric_measure at
     * d / 10), and the share of the boundary farther than 1/4 in from it. */
    double farthest_fabric_mm, seam_bare;
} qc_stats;

typedef struct qc_result {
    qc_params params;  /* the resolved parameters */
    qc_points points;  /* the sampled (or given) points */
    qc_edges edges;    /* the tree (MST skeletons) */
    qc_order order;    /* the walk or tour */
    qc_path path;      /* the pattern: one continuous path */
    qc_stats stats;
} qc_result;

/*
 * The skeleton handed to a family (paper §4): points, the tree (MST families)
 * and the visiting order (the tree walk from root, or the TSP tour).
 */
typedef struct qc_skeleton {
    const qc_vec2 *p;
    size_t n;
    const qc_edge *edges; /* n-1 tree edges, or NULL for tour skeletons */
    size_t nedges;
    const uint32_t *order; /* walk (2(n-1)+1 entries, root first and last) or tour (n) */
    size_t norder;
    uint32_t root;
} qc_skeleton;

/*
 * A family: decorates the skeleton into one continuous path appended to
 * *out, adding its figures to *stats. params is resolved. Families that need
 * no points (echo, spiral) get an empty skeleton.
 */
typedef int (*qc_family_fn)(qc_ctx *ctx, const qc_region *region,
                            const qc_params *params, const qc_skeleton *skel,
                            const qc_motif_set *motifs, qc_path *out,
                            qc_stats *stats);

/* What a family needs from qc_generate (qc_family_desc.needs). */
#define QC_FAMILY_NEEDS_POINTS 1u /* sampled or given points; else an empty skeleton */
#define QC_FAMILY_NEEDS_TREE   2u /* refuses a tour: the skeleton must be the tree */
#define QC_FAMILY_NEEDS_MOTIFS 4u /* draws motifs (the motifs argument, --motif) */
#define QC_FAMILY_OWN_SEAMS    8u /* reaches the seams itself (pebbles put into the
                                     corners and along the seams): no row of points */

/*
 * A family as the library registers it: one per src/deco/family_NAME.c.
 * Static, never freed.
 */
typedef struct qc_family_desc {
    qc_family id;
    const char *name;    /* "stipple": the CLI's and the page's name */
    const char *summary; /* one line, for --help and the page */
    unsigned needs;      /* QC_FAMILY_NEEDS_* */
    /* QC_PARAM_BIT(id) for each parameter of its own it reads; the ones
     * every family takes (family, seed, spacing, margin, start-x/-y) and,
     * with QC_FAMILY_NEEDS_POINTS, the skeleton's (points, skeleton, mst,
     * tsp, tsp-time) are implied. */
    uint64_t params;
    qc_family_fn run;
    /* Its own default for parameter id, from the parameters resolved so far
     * (family and spacing always are): 1 with *value set, or 0 for the
     * table's default. NULL: the table's defaults throughout. */
    int (*param_default)(const qc_params *p, int id, double *value);
} qc_family_desc;

/* The i-th family (0-based, in id order: qc_family_info(i)->id == i + 1),
 * or NULL for i >= QC_FAMILY_COUNT - 1. Loop until NULL to list them. */
const qc_family_desc *qc_family_info(size_t i);

/*
 * Generates one pattern inside region (normalized). given: points for
 * QC_POINTS_GIVEN (else ignored, may be NULL). motifs: NULL for the built-in
 * library. On success *out owns everything (free with qc_result_free); on
 * failure *out is left zeroed. Errors: those of qc_params_resolve, QC_EEMPTY
 * (no point fits in the region), QC_ERANGE (a given point outside the region
 * or nearer its boundary than the margin), QC_ELIMIT (too many points),
 * QC_ENOMEM.
 */
int qc_generate(qc_ctx *ctx, const qc_region *region, const qc_params *params,
                const qc_points *given, const qc_motif_set *motifs,
                qc_result *out);
void qc_result_free(qc_ctx *ctx, qc_result *res);

/*
 * Fills res->stats.farthest_fabric_mm and seam_bare as qc_generate does
 * without skip_gap_stat (for a preview that generated with it and measures
 * afterwards). Errors: those of qc_path_fabric.
 */
int qc_result_measure(qc_ctx *ctx, const qc_region *region, qc_result *res);

/* Caps that keep every request linear-memory and bounded (see README). */
#define QC_MAX_POINTS 4000000u

#ifdef __cplusplus
}
#endif
#endif
