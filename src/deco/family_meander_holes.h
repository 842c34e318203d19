/*
 * The meander's holes pass (family_meander_holes.c) and the judge of its
 * local moves (family_meander_judge.c): what a bump or a draw-in must not
 * do to the curve where it moved it.
 */
#ifndef QC_FAMILY_MEANDER_HOLES_H
#define QC_FAMILY_MEANDER_HOLES_H

#include "family_meander.h"

#define BUMP_MAX 0.25 /* a bump rises by at most this, times d */

typedef struct qc__holes {
    const qc_points *c;
    int open;
    double d;
    const qc__sdf *s;
    qc__seg_grid sg;
    uint32_t *stamp; /* per vertex: the last disc that moved it, + 1 */
    uint32_t *undo;  /* the vertices one bump moved ... */
    qc_vec2 *was;    /* ... and where they were */
    size_t nundo;
} qc__holes;

/* The segment after segment k of the closed curve ud (a qc_points). */
static inline uint32_t qc__holes_next(const void *ud, uint32_t k)
{
    const qc_points *c = ud;
    return k + 1 == c->n ? 0 : k + 1;
}

/* Whether the segment from vertex i crosses another segment of c. */
QC__HIDDEN int qc__holes_crosses_at(const qc__holes *h, const qc_points *c, size_t i);

/*
 * Whether the last move (h->undo, h->was) made c turn tighter than 0.2 d
 * where it turned less tightly before, or run straight for longer than
 * 2 d where it ran straight for less.
 */
QC__HIDDEN int qc__holes_turns_tighter(qc__holes *h, qc_points *c);

/* Puts back what the last move moved. */
QC__HIDDEN void qc__holes_undo(qc__holes *h, qc_points *c);

#endif
