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

/*
 * Every format is y up, absolute coordinates, each rounded on its own from
 * the plan's mm (round half away from zero; no drift). Piece starts
 * (QC_ST_JUMP) are travel moves where the format has them.
 */
typedef enum qc_format {
    QC_FORMAT_PAT = 1, /* Innova AutoPilot: N1G00X1.000Y9.008 CRLF, in, 3 decimals, N<k>M02 */
    QC_FORMAT_QLI,     /* Gammill Statler Stitcher: Galil VP x,y in 0.001 in, NO NEEDLE OFF/ON */
    QC_FORMAT_DXF,     /* R12 ASCII, one POLYLINE per piece, mm ($INSUNITS 4) */
    QC_FORMAT_HPGL,    /* .plt: IN; SP1; PU x,y; PD x,y; in 0.025 mm units */
    QC_FORMAT_QCC,     /* QuiltEZ: "c s", "p X%.4f Y%.4f" in inches (no jumps) */
    QC_FORMAT_IQP,     /* IntelliQuilter StitchV2: float32 inches, a record per piece */
    QC_FORMAT_BQM,     /* Bernina Q-matic: N10G00X...Y... in, 4 decimals, M02 */
    QC_FORMAT_GCODE,   /* .gcode / .nc: G21 G90, G0 jumps, G1 F<feed>, mm, 3 decimals */
    QC_FORMAT_SVG,     /* preview: mm or in, layers "region" and "path", jumps dashed */
    QC_FORMAT_COUNT
} qc_format;

/* "pat", ".pat", "PAT", "x.pat", "plt", "hpgl", "gcode", "nc", ... -> format
 * (case-insensitive, the text after the last '.'); -1 if unknown or NULL. */
int qc_format_from_name(const char *name);
const char *qc_format_name(int format); /* "pat"; NULL if unknown */
const char *qc_format_ext(int format);  /* ".pat"; NULL if unknown */

typedef struct qc_io_opts {
    const qc_region *region; /* SVG: drawn under the path; may be NULL */
    int svg_inches;          /* SVG: width/height in inches (else mm) */
    double feed_mm_min;      /* G-code feed rate; 0 = 1500 */
    const qc_path *travel;   /* SVG: layer "ditch" drawn over the path in a third colour
                              * (a quilt's travel along seams, lines only); may be NULL */
    int dxf_outlines;        /* DXF: the region's rings as closed polylines on layer
                              * OUTLINES (never sewn by quiltc's reader): 0 or > 0
                              * when region is given, < 0 never */
    /* G-code: a line sent before each jump and at the end (pen or needle up)
     * and one after each jump (down), so a plotter does not draw the jumps.
     * NULL = "G0 Z5" / "G1 Z0"; "" = no line. At most 64 printable ASCII
     * characters, else QC_EINVAL. */
    const char *pen_up, *pen_down;
} qc_io_opts;

/* Encodes plan as format through write(ud, ...), buffered (8 KiB chunks).
 * opts may be NULL. Nothing is written when the plan is refused. PAT drops
 * points that round onto the previous line's position and refuses negative
 * coordinates (move the pattern so its bounding box starts at (0, 0)).
 * Errors: QC_EINVAL (unknown format, NULL plan or write), QC_EEMPTY (empty
 * plan), QC_ERANGE (NaN/inf, beyond 1e6 mm, negative for PAT, bad feed),
 * QC_ELIMIT, QC_EIO (write returned non-zero; output is then truncated). */
int qc_io_write(qc_ctx *ctx, int format, const qc_plan *plan,
                const qc_io_opts *opts, qc_write_fn write, void *ud);

/* Reads a .pat into *out (zeroed first), strictly: lines numbered from N1,
 * G00/G01 with X and Y of exactly 3 decimals (inches -> mm), CRLF or LF,
 * N<k>M02 last with nothing after it. G00 points get QC_ST_JUMP (p[0]
 * always). Errors: QC_EFORMAT (the message names the line), QC_EEMPTY (no
 * point), QC_EINVAL, QC_ENOMEM; *out is then empty. */
int qc_io_read_pat(qc_ctx *ctx, const char *buf, size_t len, qc_plan *out);

/*
 * Reads a pattern in any format quiltc writes into *out (zeroed first), in
 * mm, y up, each piece's first point flagged QC_ST_JUMP (travel kept as
 * travel where the format has it; QCC has none). PAT is the strict reader
 * above; SVG goes through qc_io_read_svg_path and qc_stitch_plan with
 * default parameters. QLI: VP, CR arcs, NO NEEDLE OFF/ON. DXF: POLYLINE,
 * LWPOLYLINE (bulges), LINE, ARC, CIRCLE, ELLIPSE, SPLINE, $INSUNITS.
 * HP-GL: PU, PD, PA, PR, IN. QCC. IQP. BQM and G-code: G0..G3 (I, J or R),
 * G20/G21, G90/G91; G-code's pen up (Z > 0, M5) is travel. Arcs are
 * flattened within 0.05 mm. Errors: QC_EFORMAT naming the line (IQP: the
 * byte), QC_ERANGE (a point beyond 1e6 mm), QC_EEMPTY (nothing sewn),
 * QC_ELIMIT (more than QC_MAX_PLAN_POINTS), QC_EINVAL, QC_ENOMEM; *out is
 * then empty.
 */
int qc_io_read(qc_ctx *ctx, int format, const char *buf, size_t len, qc_plan *out);

/* One finding of a linter: line (1-based; 0 = whole file), a kind
 * ("dialect", "numbering", "decimals", "line-ending") and one line of text. */
typedef void (*qc_finding_fn)(void *ud, size_t line, const char *kind, const char *text);

/*
 * Lints a .pat against the AutoPilot dialect without stopping at the first
 * fault: every deviation goes to report(ud, ...) (may be NULL) and is
 * counted in *findings; the coordinates that could be read go into *out
 * (mm; G00 points flagged QC_ST_JUMP) for geometric checks. Errors: only
 * QC_ENOMEM; a malformed file is findings, not an error.
 */
int qc_io_check_pat(qc_ctx *ctx, const char *buf, size_t len, qc_finding_fn report,
                    void *ud, qc_plan *out, size_t *findings);

/* A reader's warning: one line naming what in the file it could not honour
 * and where (the element's id or number, and its line). */
typedef void (*qc_warn_fn)(void *ud, const char *text);

typedef struct qc_svg_opts {
    double tolerance;   /* curve flattening, mm; 0 = 0.05 */
    size_t max_bytes;   /* refuse larger input; 0 = 16 MiB */
    qc_warn_fn warn;    /* receives warnings (at most 50, then a count); NULL drops them */
    void *warn_ud;
} qc_svg_opts;

/*
 * Reads the closed shapes of an SVG document as a region in mm, y up
 * (y_mm = page height - y, so the page's bottom-left corner is (0, 0);
 * a quiltc preview's data-quiltc-origin-mm moves it back to the plan's own
 * origin), holes from each shape's fill-rule (evenodd keeps every ring;
 * nonzero keeps a ring only where the fill changes across it). Shapes with
 * fill:none are strokes or guides and left out (with a warning) when the
 * document has filled shapes; a document of outlines only (a quiltc
 * preview, a line drawing) reads its closed outlines. Supports
 * path (all commands, arcs), rect (rounded), circle, ellipse, polygon,
 * polyline, transform and nested g, viewBox with width/height in mm, cm, in,
 * pt, px, <use> clones (href or xlink:href, x/y, nested; a budget of depth,
 * count and bytes refuses hostile files with QC_ELIMIT), CSS from <style>
 * (selectors .class, #id, type and *) and class attributes, display:none and
 * visibility:hidden (inherited: Inkscape's hidden layers), clip-path on
 * shapes, groups and uses where exact (a clip of one convex straight-edged
 * shape, nested clips intersected; each shape inside, beyond, or convex
 * itself). What it cannot honour (other clips, mask, text, images, other
 * selectors, a missing or external clone source) goes to opts->warn, naming
 * the element; a clone cycle is QC_EFORMAT.
 * Not normalized: call qc_region_normalize. Errors: QC_EFORMAT
 * (malformed XML or path data; the message says where), QC_EEMPTY (no
 * closed shape), QC_ERANGE (NaN/inf/huge numbers), QC_ELIMIT (too large),
 * QC_EINVAL (bad options), QC_ENOMEM.
 */
int qc_io_read_svg_region(qc_ctx *ctx, const char *buf, size_t len,
                          const qc_svg_opts *opts, qc_region *out);

/* Reads every shape of an SVG document (open or closed) as one path in mm,
 * y up, one MOVE per subpath, curves kept as cubics. Dashed strokes (jumps,
 * as quiltc draws them) and the element with id="region" (quiltc's block
 * outline) are not stitch lines and are left out. Same errors. */
int qc_io_read_svg_path(qc_ctx *ctx, const char *buf, size_t len,
                        const qc_svg_opts *opts, qc_path *out);

/* Reads points: CSV "x,y" lines (comma-separated; a header as the first
 * content line, '#' comments, a UTF-8 BOM allowed) or TSPLIB
 * (NODE_COORD_SECTION with ids 1..DIMENSION in order; EUC_2D, CEIL_2D, ATT,
 * MAX_2D, MAN_2D). Coordinates within 1e9. Appends to *out, which keeps its
 * contents on error. Errors: QC_EFORMAT naming the line and text, QC_ERANGE,
 * QC_EEMPTY, QC_ELIMIT, QC_EINVAL, QC_ENOMEM. */
int qc_io_read_points(qc_ctx *ctx, const char *buf, size_t len, qc_points *out);

#ifdef __cplusplus
}
#endif
#endif
