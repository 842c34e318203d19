/*
 * Encoders to a write callback (no FILE* in the library) and readers from a
 * byte buffer: machine formats, SVG regions and paths, point files.
 */
#ifndef QUILTC_IO_H
#define QUILTC_IO_H

#include "core.h"
#include "region.h"
#include "stitch.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Receives encoded bytes; returns 0 on success, non-zero to abort (QC_EIO). */
typedef int (*qc_write_fn)(void *ud, const void *data, size_t len);

typedef enum qc_format {
    QC_FORMAT_PAT = 1, /* Innova AutoPilot */
    QC_FORMAT_QLI,     /* Gammill Statler Stitcher */
    QC_FORMAT_DXF,     /* R12 ASCII polylines */
    QC_FORMAT_HPGL,    /* .plt */
    QC_FORMAT_QCC,     /* QuiltEZ */
    QC_FORMAT_IQP,     /* IntelliQuilter */
    QC_FORMAT_BQM,     /* Bernina Q-matic */
    QC_FORMAT_GCODE,   /* .gcode / .nc */
    QC_FORMAT_SVG,
    QC_FORMAT_COUNT
} qc_format;

/* "pat", ".pat", "PAT", "plt", "hpgl", "gcode", "nc", ... -> format; -1 if unknown. */
int qc_format_from_name(const char *name);
const char *qc_format_name(int format); /* "pat" */
const char *qc_format_ext(int format);  /* ".pat" */

typedef struct qc_io_opts {
    const qc_region *region; /* SVG: drawn under the path; may be NULL */
    int svg_inches;          /* SVG: width/height in inches (else mm) */
    double feed_mm_min;      /* G-code feed rate; 0 = 1500 */
} qc_io_opts;

/* Encodes plan as format through write(ud, ...). opts may be NULL.
 * Errors: QC_EINVAL (unknown format), QC_EEMPTY (empty plan), QC_ERANGE (a
 * coordinate the format cannot hold), QC_EIO (write returned non-zero). */
int qc_io_write(qc_ctx *ctx, int format, const qc_plan *plan,
                const qc_io_opts *opts, qc_write_fn write, void *ud);

/* Reads a .pat into *out (zeroed first); QC_EFORMAT names the line. */
int qc_io_read_pat(qc_ctx *ctx, const char *buf, size_t len, qc_plan *out);

typedef struct qc_svg_opts {
    double tolerance;   /* curve flattening, mm; 0 = 0.05 */
    size_t max_bytes;   /* refuse larger input; 0 = 16 MiB */
} qc_svg_opts;

/*
 * Reads the closed shapes of an SVG document as a region in mm, y up (the
 * SVG's y axis is flipped), holes from each shape's fill-rule. Supports
 * path (all commands, arcs), rect (rounded), circle, ellipse, polygon,
 * polyline, transform and nested g, viewBox with width/height in mm, cm, in,
 * pt, px. Not normalized: call qc_region_normalize. Errors: QC_EFORMAT
 * (malformed XML or path data; the message says where), QC_EEMPTY (no
 * closed shape), QC_ERANGE (NaN/inf/huge numbers), QC_ELIMIT (too large).
 */
int qc_io_read_svg_region(qc_ctx *ctx, const char *buf, size_t len,
                          const qc_svg_opts *opts, qc_region *out);

/* Reads every shape of an SVG document (open or closed) as one path in mm,
 * y up, one MOVE per subpath, curves kept as cubics. Same errors. */
int qc_io_read_svg_path(qc_ctx *ctx, const char *buf, size_t len,
                        const qc_svg_opts *opts, qc_path *out);

/* Reads points: CSV "x,y" lines (a header line and '#' comments allowed) or
 * TSPLIB (NODE_COORD_SECTION, EDGE_WEIGHT_TYPE EUC_2D). Appends to *out.
 * Errors: QC_EFORMAT naming the line, QC_ERANGE, QC_EEMPTY. */
int qc_io_read_points(qc_ctx *ctx, const char *buf, size_t len, qc_points *out);

#ifdef __cplusplus
}
#endif
#endif
