/*
 * Motifs: the decorative elements of Branching, Wanderer and Shape Packing.
 * A motif is a path in a unit frame with its collision geometry.
 * (Owned by the pattern-families work; see README "Motif SVG format".)
 */
#ifndef QUILTC_MOTIF_H
#define QUILTC_MOTIF_H

#include "core.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct qc_motif {
    char name[32];
    qc_path path;      /* unit frame: minimum bounding circle centred at the
                          origin with radius 1; starts at `entry`, ends at `exit` */
    qc_vec2 *hull;     /* convex hull of the flattened path, CCW, unit frame */
    size_t nhull;
    qc_vec2 entry, exit; /* where the motif joins the skeleton */
    qc_vec2 entry_dir, exit_dir; /* Wanderer: unit directions of the legs,
                          pointing outward from entry and exit; else (0, 0) */
    int legs;          /* 2 for Wanderer primitives (legs at entry and exit), else 0 */
} qc_motif;

typedef struct qc_motif_set {
    qc_motif *m;
    size_t n, cap;
} qc_motif_set;

void qc_motif_set_free(qc_ctx *ctx, qc_motif_set *set);

/* The built-in library: count and names ("leaf", "heart", ...). */
size_t qc_motif_builtin_count(void);
const char *qc_motif_builtin_name(size_t i);
/* Appends the built-in motifs named in a comma-separated list to *out.
 * QC_EINVAL names an unknown motif. */
int qc_motif_builtin(qc_ctx *ctx, const char *names, qc_motif_set *out);
/* Appends a motif read from an SVG document (docs/motifs.md) named name:
 * every shape as one path (qc_io_read_svg_path); its start point is the
 * attachment; a path that does not return to its start (and has at least
 * three segments, else it is closed with a straight stitch) is a Wanderer
 * primitive whose first and last segments are the legs (not sewn).
 * Families scale a motif so its bounding circle's diameter is the size s.
 * Errors: those of the SVG reader, QC_EDEGENERATE (empty or a single point),
 * QC_ENOMEM. */
int qc_motif_from_svg(qc_ctx *ctx, const char *buf, size_t len,
                      const char *name, qc_motif_set *out);

#ifdef __cplusplus
}
#endif
#endif
