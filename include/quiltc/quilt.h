/*
 * Quilt tops: a pieced top is many patches sharing seams. Each patch gets
 * its own pattern (qc_generate), and the patterns are joined into one line
 * that passes from patch to patch along the seams ("in the ditch", where
 * the stitches hide), so the whole top is sewn without a jump.
 *
 *   SVG -> qc_io_read_svg_patches -> qc_patches -> qc_patches_overlap (refuse)
 *       -> qc_quilt (a pattern per patch, seam travel) -> qc_quilt_result.path
 */
#ifndef QUILTC_QUILT_H
#define QUILTC_QUILT_H

#include "core.h"
#include "region.h"
#include "io.h"
#include "motif.h"
#include "pattern.h"

#ifdef __cplusplus
extern "C" {
#endif

/* One patch of a top: a piece of fabric where the SVG draws it. */
typedef struct qc_patch {
    qc_region region;   /* normalized, mm, y up; its own holes follow the fill rule */
    char *id;           /* the element's id, class and inkscape:label; "" when absent */
    char *cls;
    char *label;
    uint32_t fill;      /* 0xRRGGBB when has_fill (inherited from groups as SVG does) */
    int has_fill;       /* the fill is a colour qc_color_parse understands */
    size_t element;     /* the shape element's number in document order, 1-based */
    unsigned long line; /* the element's line in the SVG */
    size_t piece;       /* 1-based piece of an element drawn as separate pieces */
} qc_patch;

typedef struct qc_patches {
    qc_patch *p;
    size_t n, cap;
} qc_patches;

void qc_patches_free(qc_ctx *ctx, qc_patches *ps);

/*
 * Reads every closed filled shape of an SVG (as qc_io_read_svg_region reads
 * them: transforms, groups, units, fill rule) as patches, kept where they
 * are drawn: one patch per separate piece of a shape (an outer ring with its
 * own holes). *out is zeroed first; on error it is left empty. Patches may
 * share edges and vertices; overlaps are not checked here (see
 * qc_patches_overlap). Errors: those of qc_io_read_svg_region, and
 * QC_EINTERSECT for a shape crossing itself (the message names the
 * element and its line).
 */
int qc_io_read_svg_patches(qc_ctx *ctx, const char *buf, size_t len,
                           const qc_svg_opts *opts, qc_patches *out);

/*
 * Finds two patches whose insides overlap (touching along seams or at
 * corners is not overlap): 1 with *a < *b their indices and *where a point
 * of the overlap in mm, or 0 when there is none. tol (mm, 0 = 0.05, the SVG
 * reader's flattening tolerance) is how far apart two edges may be and still
 * count as one seam (two flattenings of one curved seam). No allocation;
 * O(pairs of patches whose boxes meet x their edges).
 */
int qc_patches_overlap(const qc_patches *ps, double tol, size_t *a, size_t *b,
                       qc_vec2 *where);

/* A CSS colour (#rgb, #rrggbb, rgb(r, g, b), basic names such as "navy"):
 * 1 and *rgb = 0xRRGGBB when understood, else 0. */
int qc_color_parse(const char *s, uint32_t *rgb);

/* How a plan's rule picks patches: every field given must fit. */
typedef struct qc_patch_match {
    const char *id, *cls, *label; /* '*' matches any run of characters; NULL: anything */
    uint32_t fill;                /* 0xRRGGBB, when has_fill */
    int has_fill;
} qc_patch_match;

/* 1 when '*'-pattern matches all of s. */
int qc_glob(const char *pattern, const char *s);
/* 1 when patch p fits m: id and label by qc_glob, class when any one of the
 * patch's space-separated classes fits, fill exactly (a patch with no fill
 * colour never fits a fill). A plan is an ordered list: the first rule that
 * fits a patch chooses for it. */
int qc_patch_matches(const qc_patch_match *m, const qc_patch *p);

/* Every ring of every patch, in one region (to draw and to write as the
 * outline layer). *out is zeroed first and empty on error. */
int qc_patches_outlines(qc_ctx *ctx, const qc_patches *ps, qc_region *out);

enum { QC_JOIN_DITCH = 0, QC_JOIN_JUMP = 1 };

/* Seam tolerance: the default is well under a needle's width and above
 * the slop of hand-drawn or exported tops (coordinates rounded to 0.1 mm,
 * two flattenings of one curved seam, 0.05 mm apart). */
#define QC_QUILT_SEAM_TOL 0.1
#define QC_QUILT_MAX_SEAM_TOL 10.0

typedef struct qc_quilt_params {
    int join;        /* QC_JOIN_DITCH (default): travel along seams; QC_JOIN_JUMP: jumps */
    double seam_tol; /* mm, in (0, QC_QUILT_MAX_SEAM_TOL]: vertices this near are one seam
                        vertex, and a vertex this near an edge splits it; 0 = QC_QUILT_SEAM_TOL */
} qc_quilt_params;

/* What to sew in one patch. */
typedef struct qc_patch_job {
    const qc_params *params;    /* NULL: the patch is left unquilted */
    const qc_motif_set *motifs; /* NULL: the built-in library */
} qc_patch_job;

typedef struct qc_patch_result {
    int family;            /* the family used (resolved); 0 when unquilted */
    double length_mm;      /* the patch's own pattern */
    double largest_gap_mm; /* qc_generate's measure (0 when skip_gap_stat; some
                              families do not measure it) */
    double farthest_fabric_mm; /* every family: the farthest any fabric of the patch
                                  lies from its own pattern (0 when skip_gap_stat) */
    double seam_bare;      /* share of its boundary farther than 1/4 in from it */
    size_t pieces;         /* pieces of the pattern as generated */
    size_t order;          /* place in the sewing order, 0-based; SIZE_MAX when unquilted */
    int ditch_only;        /* 1: too small for its family at its spacing (qc_generate's
                              QC_EEMPTY), so its outline is sewn in the ditch instead */
} qc_patch_result;

typedef struct qc_quilt_result {
    qc_path path;           /* the whole top, mm, where drawn */
    qc_path ditch;          /* the seam travel alone, one piece per travel (to draw it) */
    qc_patch_result *patch; /* per patch, in the order of qc_patches */
    size_t npatch;
    uint32_t *order;        /* quilted patches in sewing order */
    size_t norder;
    double ditch_mm;        /* length travelled along seams */
    double link_mm;         /* stitched from a seam to a pattern's ends and back */
    size_t jumps;           /* joins made with a jump (QC_JOIN_JUMP, or no seam between) */
} qc_quilt_result;

/*
 * Quilts a top: jobs[i] says what to sew in ps->p[i] (n = ps->n). Patches
 * are sewn in a greedy order that keeps the travel along the seams short
 * (next, the unsewn patch cheapest to reach from where the last one ended:
 * seam distance divided by the unsewn patches meeting at the arrival
 * vertex, so corners shared by several patches are sewn in one visit);
 * each pattern starts where the travel arrives (its params'
 * start_x/start_y are set to the arrival point; patch i's seed is the
 * params' seed + i, so equal patches differ) and every piece of a
 * pattern is linked to the nearest point of its patch's boundary by a
 * straight stitch that stays inside the patch. With QC_JOIN_DITCH the
 * travel between two such boundary points is the shortest path along the
 * seams (the patches' edges, split where a vertex of one lies on an edge
 * of another), and the whole top is one piece as long as the patches are
 * connected by seams; otherwise, and with QC_JOIN_JUMP, a piece starts
 * (a MOVE: a jump for the stitch plan). The patches must not overlap
 * (qc_patches_overlap). Deterministic. On success *out owns everything
 * (qc_quilt_result_free); on failure it is left empty. A patch too small
 * for its family at its spacing (qc_generate says QC_EEMPTY: no point or
 * ring fits) is not an error: the line goes once round the boundary it
 * enters by, in the ditch, and the patch is marked ditch_only. Errors:
 * QC_EINVAL (NULL arguments, bad join or seam_tol), QC_EEMPTY (no patch
 * quilted), qc_generate's other errors (the message is prefixed
 * "patch N: "), QC_ENOMEM.
 */
int qc_quilt(qc_ctx *ctx, const qc_patches *ps, const qc_patch_job *jobs,
             const qc_quilt_params *params, qc_quilt_result *out);
void qc_quilt_result_free(qc_ctx *ctx, qc_quilt_result *r);
/* Moves the outlines and the result (path and ditch) so the outlines' lower
 * left corner is the origin, as a block is placed (PAT refuses negative
 * coordinates; the patterns stay inside the top). No allocation. */
void qc_quilt_to_origin(qc_quilt_result *r, qc_region *outlines);


#ifdef __cplusplus
}
#endif
#endif
