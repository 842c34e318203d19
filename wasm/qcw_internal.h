/*
 * What the binding's files share (quiltc_wasm.c: blocks; quiltc_wasm_top.c:
 * quilt tops): the job, and JSON answers built in a growing heap string.
 */
#ifndef QCW_INTERNAL_H
#define QCW_INTERNAL_H

#include "quiltc.h"
#include "quiltc_wasm.h"

#define MAX_STAGES 16

/* One rule of a top's plan, as quiltc quilt --plan reads it. */
typedef struct qcw_rule {
    char *text[3];        /* owned id, class and label patterns (match points into them) */
    qc_patch_match match;
    int none;             /* leave its patches unquilted */
    qc_params params;     /* only the rule's own settings (their given bits) */
    size_t matched;
} qcw_rule;

struct qcw_job {
    qc_ctx ctx;
    qc_region region;     /* a block's region; for a top, its outlines once sewn */
    qc_params params;     /* a block's parameters; for a top, every patch's defaults */
    qc_motif_set motifs;
    qc_result result;
    qc_plan plan;
    int svg_inches;
    const char *stage[MAX_STAGES]; /* trace: stage names and start times */
    double stage_ms[MAX_STAGES];
    size_t nstages;
    double plan_ms, total_ms;
    unsigned char *bytes; /* last export */
    size_t nbytes, bytes_cap;
    char *json;           /* last JSON answer */
    /* a quilt top (quiltc_wasm_top.c) */
    qc_patches patches;   /* n > 0: the job is a top */
    qcw_rule *rule;
    size_t nrules;
    size_t *chosen;       /* per patch: its rule + 1, 0 for the defaults */
    qc_quilt_result quilt;
    int sewn;             /* plan and region hold the top's line and outlines */
    size_t top_pieces;    /* the top's line's pieces, counted before the plan took it */
    struct qcw_text *warnings; /* the last SVG read's warnings, JSON strings */
};

typedef struct qcw_text {
    char *s;
    size_t n, cap;
    int failed;
} qcw_text;

#if defined(__GNUC__)
void qcw__add(qcw_text *t, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
#else
void qcw__add(qcw_text *t, const char *fmt, ...);
#endif
/* A JSON string literal. */
void qcw__add_str(qcw_text *t, const char *s);
/* Hands t to the job as its last JSON answer ("null" when it failed). */
const char *qcw__finish_json(qcw_job *job, qcw_text *t);
/* A message of the binding's own: sets the job's status and message. */
int qcw__fail(qcw_job *job, int status, const char *fmt, const char *arg);
/* Frees the last result (a block's or a top's). */
void qcw__drop_result(qcw_job *job);
/* Frees the top, its plan and its line. */
void qcw__drop_top(qcw_job *job);
/* Options for reading an SVG whose warnings the job keeps (the last read's
 * only: qcw_svg_warnings_json). */
void qcw__svg_opts(qcw_job *job, qc_svg_opts *opts);

#endif
