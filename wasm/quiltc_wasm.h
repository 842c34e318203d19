/*
 * The JavaScript boundary: flat qcw_* functions over the unchanged library,
 * compiled to WebAssembly for the page (wasm/web/) and natively for the
 * tests (tests/wasm/qcw_native.c), so both run the same composition as the
 * CLI. A job holds one region, the parameters, the motifs and the last
 * result. Every fallible call returns QC_OK or a negative QC_E* status and
 * qcw_error() gives the one-line reason. Strings and arrays returned belong
 * to the job and stay valid until the next call that changes the same data.
 * Lengths are millimetres, y up.
 */
#ifndef QUILTC_WASM_H
#define QUILTC_WASM_H

#include <stddef.h>
#include <stdint.h>

typedef struct qcw_job qcw_job;

qcw_job *qcw_new(void);
void qcw_free(qcw_job *job);
const char *qcw_error(const qcw_job *job);
const char *qcw_version(void);

/* The parameter table as a JSON array of rows (name, help, unit, type,
 * choices, min, max, def, def_per_spacing, families), and the built-in
 * motif names as a JSON array of strings. */
const char *qcw_params_json(qcw_job *job);
const char *qcw_motifs_json(qcw_job *job);
/* The library's families in id order (qc_family_info) as a JSON array of
 * {name, summary, id, points, tree, motifs, defaults}: the QC_FAMILY_NEEDS_*
 * flags as booleans, defaults as qcw_resolved_json gives them for a job
 * with only that family set. */
const char *qcw_families_json(qcw_job *job);
/* Every parameter as qc_params_resolve fills it from the job's parameters
 * (lengths in mm, enums by choice name, the seed as a decimal string), as a
 * JSON object by row name; NULL (and qcw_error) if they do not resolve. */
const char *qcw_resolved_json(qcw_job *job);

/* The region, normalized and moved so its bounding box starts at (0, 0),
 * exactly as the CLI loads it. On failure the job has no region. */
int qcw_region_shape(qcw_job *job, const char *spec, double mm_per_unit);
int qcw_region_svg(qcw_job *job, const char *svg, size_t len);
/* What the last SVG read (a block's outline or a top) could not honour: a
 * JSON array of one-line warnings naming the element, as the CLI prints. */
const char *qcw_svg_warnings_json(qcw_job *job);
const double *qcw_region_xy(const qcw_job *job); /* x,y pairs */
size_t qcw_region_vertices(const qcw_job *job);
const uint32_t *qcw_region_ring_ends(const qcw_job *job);
size_t qcw_region_rings(const qcw_job *job);

/* Forgets the parameters and motifs; svg_inches: SVG exports in inches. */
void qcw_params_reset(qcw_job *job, int svg_inches);
/* One row of the table by name: lengths in mm, enums as 1-based choices. */
int qcw_param(qcw_job *job, const char *name, double value);
/* The 64-bit seed as two 32-bit halves (JS numbers hold 53 bits). */
int qcw_seed(qcw_job *job, double hi, double lo);
/* Appends built-in motifs (comma-separated names) or one SVG motif. */
int qcw_motifs(qcw_job *job, const char *names);
int qcw_motif_svg(qcw_job *job, const char *svg, size_t len, const char *name);

/* qc_generate, then qc_stitch_plan with tie_stitches (0..100). */
int qcw_run(qcw_job *job, int tie_stitches);
/* The plan: n points as x,y pairs (mm) and QC_ST_* flags per point. */
size_t qcw_points(const qcw_job *job);
const double *qcw_xy(const qcw_job *job);
const unsigned char *qcw_flags(const qcw_job *job);
/* Figures of the last run as one JSON object (counts, length, stitches,
 * thread, sewing time, milliseconds per stage). */
const char *qcw_stats_json(qcw_job *job);

/* Encodes the last plan as a format named like the CLI's (pat, svg, ...). */
int qcw_export(qcw_job *job, const char *format);
const unsigned char *qcw_export_data(const qcw_job *job);
size_t qcw_export_size(const qcw_job *job);

/* ---- quilt tops (as quiltc quilt TOP.svg [--plan P.json]) ----
 * A top replaces the job's region: every closed shape of the SVG is a patch
 * kept where drawn (qc_io_read_svg_patches); overlapping patches are refused
 * naming both, with the place in mm_per_unit units called units. The job's
 * parameters and motifs are every patch's defaults. */
int qcw_top_svg(qcw_job *job, const char *svg, size_t len, double mm_per_unit,
                const char *units);
/* The patches as a JSON array of {id, class, label, fill ("#rrggbb" or
 * null), element, line, rings: [[x, y, x, y, ...], ...]}, moved as the sewn
 * top is (its lower-left corner at the origin). */
const char *qcw_patches_json(qcw_job *job);
/* The plan: ordered rules, the first that fits a patch chooses for it.
 * qcw_rule_add appends a rule matching id, class and label ('*' wildcards;
 * "" for any) and fill (a CSS colour, "" for any); qcw_rule_param and
 * qcw_rule_none set the last rule's parameters (as qcw_param; the rest are
 * the defaults) or leave its patches unquilted. */
void qcw_rules_clear(qcw_job *job);
int qcw_rule_add(qcw_job *job, const char *id, const char *cls, const char *label,
                 const char *fill);
int qcw_rule_param(qcw_job *job, const char *name, double value);
int qcw_rule_none(qcw_job *job);
/* Sews the top as one line (qc_quilt, join: 0 ditch, 1 jump), moves it to
 * the origin and plans it with tie_stitches, as quiltc quilt does; then
 * qcw_points/qcw_xy/qcw_flags/qcw_export give it (the export with the
 * outlines and the ditch travel). A rule fitting no patch is an error. */
int qcw_quilt(qcw_job *job, int join, int tie_stitches);
/* The seam travel as a JSON array of pieces [x, y, x, y, ...] (mm). */
const char *qcw_ditch_json(qcw_job *job);
/* quiltc quilt --stats' figures: per patch (patch, id, line, rule, family,
 * order, length_mm, largest_gap_mm, pieces) and the totals. */
const char *qcw_quilt_stats_json(qcw_job *job);

#endif
