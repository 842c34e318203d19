/*
 * The packing under way (shared_pebble_pack.c), as phase 3
 * (shared_pebble_reach.c) sees it: the pebbles so far in their grid, and
 * the queries and placement phases 1 and 2 use.
 */
#ifndef QC_PEBBLE_PACK_H
#define QC_PEBBLE_PACK_H

#include "pebble_internal.h"

/* A pebble as the grid walks see it: its centre and radius (copies of
 * pb->c and pb->r) beside its link, so a neighbour costs one cache line,
 * not three (c, r and the link apart). */
typedef struct qc__pnode {
    qc_vec2 c;
    double r;
    uint32_t next;     /* the next pebble in its cell, QC__PEB_NONE at the end */
    uint32_t cell;
} qc__pnode;

/* pair_centre's terms for one pair of pebbles (shared_pebble_pack.c). */
typedef struct qc__pair_frame {
    uint32_t j, k;
    int valid;
    qc_vec2 cj, e;
    double rj, rk, D;
} qc__pair_frame;

typedef struct qc__pack {
    qc_ctx *ctx;
    qc__pbound *b;
    qc__pebbles *pb;
    double x0, y0, h;  /* the pebble grid */
    uint32_t nx, ny;
    uint32_t *head;
    qc__pnode *node;   /* per pebble */
    double rmax;       /* largest radius so far */
    double d;
    qc__pair_frame pair;
} qc__pack;

/* A pebble (c, r) hanging from parent (stands for no skeleton point);
 * its index. The pebbles' capacity must allow it. */
QC__HIDDEN uint32_t qc__pack_place(qc__pack *P, qc_vec2 c, double r, uint32_t parent,
                                   unsigned flags);
/* Largest radius (at most cap) of a circle at x touching no pebble but ex
 * and keeping its centre k r from the boundary. */
QC__HIDDEN double qc__pack_clearance(qc__pack *P, qc_vec2 x, double cap, uint32_t ex);
/* The circle (x0 + u s, s): the largest s <= cap touching no pebble but ex
 * and keeping k s from the boundary. */
QC__HIDDEN double qc__pack_ray(qc__pack *P, qc_vec2 x0, qc_vec2 u, double cap, uint32_t ex);
/* Whether q lies on the same side of the boundary as p (p inside). */
QC__HIDDEN int qc__pack_same_side(qc__pack *P, qc_vec2 p, qc_vec2 q);
/* The pebble whose edge is nearest x when within reach, else QC__PEB_NONE. */
QC__HIDDEN uint32_t qc__pack_nearest(qc__pack *P, qc_vec2 x, double reach);

/* Phase 3 (shared_pebble_reach.c): pebbles into the corners and along the
 * seams; the places it may try, a bound for the pebbles' capacity (each
 * adds at most two pebbles). */
QC__HIDDEN void qc__pack_reach(qc__pack *P);
QC__HIDDEN size_t qc__pack_reach_tries(const qc_region *region, double d);

#endif
