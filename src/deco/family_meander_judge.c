/*
 * The judge of the holes pass's local moves (family_meander_holes.c): a
 * bump or a draw-in is kept only if the curve does not cross itself where
 * it moved, nor turn tighter than TURN_MIN d, nor run straight for longer
 * than STRAIGHT d, where it did not before; turns and runs measured as
 * the tests measure them.
 */
#include <math.h>

#include "family_meander_holes.h"

#define TURN_MIN 0.2 /* a move makes no vertex turn tighter than this, times d */
#define TURN_ARC 0.25 /* ... measured through the points this far along, times d, */
#define STRAIGHT 2.0  /* ... nor run straight for longer than this, times d ... */
#define STRAIGHT_SPAN 8 /* ... judged this many vertices either side */

/* Whether the segment from vertex i crosses another segment of c. */
int qc__holes_crosses_at(const qc__holes *h, const qc_points *c, size_t i)
{
    size_t ns = h->open ? c->n - 1 : c->n, cells[4], x, y, k, i1 = qc__holes_next(c, (uint32_t)i);
    qc_vec2 a = c->v[i], b = c->v[i1];
    double pad = BUMP_MAX * h->d;

    if (i >= ns)
        return 0;
    qc__seg_grid_cells(&h->sg, QC__V2(fmin(a.x, b.x) - pad, fmin(a.y, b.y) - pad),
                       QC__V2(fmax(a.x, b.x) + pad, fmax(a.y, b.y) + pad), cells);
    for (y = cells[1]; y <= cells[3]; y++)
        for (x = cells[0]; x <= cells[2]; x++)
            for (k = h->sg.start[y * h->sg.gx + x]; k < h->sg.start[y * h->sg.gx + x + 1]; k++) {
                size_t j = h->sg.seg[k], j1;
                if (j >= ns || j == i)
                    continue;
                j1 = qc__holes_next(c, (uint32_t)j);
                if (j1 == i || i1 == j)
                    continue;
                if (qc__segs_cross_proper(a, b, c->v[j], c->v[j1]))
                    return 1;
            }
    return 0;
}

/* The point dist (mm) along c from vertex i, forwards (dir 1) or back;
 * an open curve's end if it comes first. */
static qc_vec2 along(const qc__holes *h, const qc_points *c, size_t i, double dist, int dir)
{
    size_t n = c->n, k;

    for (k = 0; k < n; k++) {
        size_t j = dir ? (i + 1 == n ? 0 : i + 1) : (i == 0 ? n - 1 : i - 1);
        qc_vec2 p = c->v[i], q;
        double len;
        if (h->open && ((dir && i + 1 == n) || (!dir && i == 0)))
            return p;
        q = c->v[j];
        len = qc_hypot(q.x - p.x, q.y - p.y);
        if (len >= dist)
            return QC__V2(p.x + (q.x - p.x) * dist / len, p.y + (q.y - p.y) * dist / len);
        dist -= len;
        i = j;
    }
    return c->v[i];
}

/* The radius of the circle through vertex i and the points TURN_ARC d
 * before and after it along c, as the tests measure turns (huge where
 * they are in line). */
static double turn_at(const qc__holes *h, const qc_points *c, size_t i)
{
    qc_vec2 a = along(h, c, i, TURN_ARC * h->d, 0), b = along(h, c, i, TURN_ARC * h->d, 1);
    qc_vec2 at = c->v[i];
    double ab = qc_hypot(at.x - a.x, at.y - a.y), bc = qc_hypot(b.x - at.x, b.y - at.y);
    double ca = qc_hypot(a.x - b.x, a.y - b.y);
    double cr = fabs((at.x - a.x) * (b.y - at.y) - (at.y - a.y) * (b.x - at.x));

    return cr > 1e-12 * ab * bc * ca ? ab * bc * ca / (2.0 * cr) : HUGE_VAL;
}

/* The tightest turn (circumradius, mm) at the vertices the last move
 * moved and their neighbours, two either side. */
static double tightest(const qc__holes *h, const qc_points *c)
{
    size_t n = c->n, k;
    double best = HUGE_VAL;

    for (k = 0; k < h->nundo; k++) { /* the spline through i bends two spans either side */
        size_t j, i = h->undo[k];
        for (j = 0; j < 5 && j < n; j++) {
            size_t at = (i + n + j - 2) % n;
            best = fmin(best, turn_at(h, c, at));
        }
    }
    return best;
}

/* The longest straight stretch through vertex i within STRAIGHT_SPAN
 * vertices either side (mm along the curve): a run whose vertices all lie
 * within d/20 of the chord between its ends, as the tests measure it. */
static double straight_at(const qc__holes *h, const qc_points *c, size_t i)
{
    size_t n = c->n, span = STRAIGHT_SPAN, a, b, k;
    double best = 0.0, tol = h->d / 20.0;

    if (n < 2 * span + 3)
        return 0.0;
    for (a = 0; a <= span; a++) /* the run from i - a to i + b (cyclic offsets) */
        for (b = (a == 0 ? 1 : 0); b <= span; b++) {
            size_t ia = (i + n - a) % n, ib = (i + b) % n;
            qc_vec2 p = c->v[ia], q = c->v[ib];
            double len = qc_hypot(q.x - p.x, q.y - p.y);
            int ok = len > 0.0 && !(h->open && (i < a || i + b >= n));
            for (k = 1; k < a + b && ok; k++) {
                qc_vec2 v = c->v[(ia + k) % n];
                ok = fabs((q.x - p.x) * (v.y - p.y) - (q.y - p.y) * (v.x - p.x)) <= tol * len;
            }
            if (ok)
                best = fmax(best, len);
        }
    return best;
}

/* The longest straight stretch through the vertices the last move moved. */
static double straightest(const qc__holes *h, const qc_points *c)
{
    double best = 0.0;
    size_t k;

    for (k = 0; k < h->nundo; k++)
        best = fmax(best, straight_at(h, c, h->undo[k]));
    return best;
}

/* Whether the last move made the curve turn tighter than TURN_MIN d
 * where it turned less tightly before, or run straight for longer than
 * STRAIGHT d where it ran straight for less (compared with the moved
 * vertices put back for a moment). */
int qc__holes_turns_tighter(qc__holes *h, qc_points *c)
{
    double now = tightest(h, c), before, run = straightest(h, c), run_was;
    size_t k;

    if (!(now < TURN_MIN * h->d) && !(run > STRAIGHT * h->d))
        return 0;
    for (k = 0; k < h->nundo; k++) { /* swap: as it was */
        qc_vec2 t = c->v[h->undo[k]];
        c->v[h->undo[k]] = h->was[k];
        h->was[k] = t;
    }
    before = tightest(h, c);
    run_was = straightest(h, c);
    for (k = 0; k < h->nundo; k++) { /* and back */
        qc_vec2 t = c->v[h->undo[k]];
        c->v[h->undo[k]] = h->was[k];
        h->was[k] = t;
    }
    return (now < TURN_MIN * h->d && now < before) || (run > STRAIGHT * h->d && run > run_was);
}

/* Puts back what the last bump moved. */
void qc__holes_undo(qc__holes *h, qc_points *c)
{
    size_t k;

    for (k = 0; k < h->nundo; k++)
        c->v[h->undo[k]] = h->was[k];
    h->nundo = 0;
}
