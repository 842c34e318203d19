/*
 * Where a Poisson candidate cannot go: a raster of small squares, each
 * marked once it lies wholly within one placed point's disk of radius d,
 * so a candidate in a marked square is turned down without the distance
 * tests (most candidates round a point fall in its neighbours' disks).
 * Marks are conservative: a square is marked only when its farthest corner
 * lies nearer than d less a slack far above rounding, so a marked square
 * holds no point that the exact test would let through.
 */
#include <math.h>
#include <string.h>

#include "sample_internal.h"

int qc__cover_init(qc_ctx *ctx, qc__cover *c, qc_bbox box, double d, double side)
{
    double slack = 1e-9 * d + 1e-12 * (fabs(box.min.x) + fabs(box.min.y) + fabs(box.max.x) +
                                       fabs(box.max.y));

    memset(c, 0, sizeof *c);
    c->x0 = box.min.x;
    c->y0 = box.min.y;
    c->side = side;
    c->reach = d > slack ? d - slack : 0.0;
    c->lim = c->reach * c->reach;
    c->nx = (size_t)((box.max.x - box.min.x) / side) + 1;
    c->ny = (size_t)((box.max.y - box.min.y) / side) + 1;
    c->dead = qc__alloc(ctx, c->nx * c->ny);
    if (c->dead == NULL)
        return QC_ENOMEM;
    memset(c->dead, 0, c->nx * c->ny);
    return QC_OK;
}

void qc__cover_free(qc_ctx *ctx, qc__cover *c)
{
    qc__free(ctx, c->dead, c->nx * c->ny);
}

static double larger(double a, double b)
{
    return a > b ? a : b;
}

/* Whether square i of a row lies within reach of q, fy2 its row's share. */
static int square_within(const qc__cover *c, qc_vec2 q, double fy2, long i)
{
    double xlo = c->x0 + (double)i * c->side, xhi = xlo + c->side;
    double fx = larger(q.x - xlo, xhi - q.x);

    return fx * fx + fy2 < c->lim;
}

/* The squares of row j whose farthest corner from q lies within reach:
 * the span the row's height leaves, checked on its corners. Along the
 * span q.x - xlo falls and xhi - q.x rises (rounding is monotone), so the
 * farthest corner's distance falls then rises and the squares within
 * reach run unbroken: only the ends are checked, from both sides. */
static void mark_row(qc__cover *c, qc_vec2 q, long j)
{
    double ylo = c->y0 + (double)j * c->side, yhi = ylo + c->side;
    double fy = larger(q.y - ylo, yhi - q.y), fy2 = fy * fy, rest = c->lim - fy2, r, a, b;
    long i, i1;
    unsigned char *row = c->dead + (size_t)j * c->nx;

    if (!(rest > 0.0))
        return;
    r = sqrt(rest);
    a = (q.x - r - c->x0) / c->side; /* squares ceil(a) .. floor(b) - 1, clamped */
    b = (q.x + r - c->x0) / c->side;
    i = qc__ceil_from0(a);
    i1 = b < 0.0 ? -1 : (b < (double)c->nx ? (long)b - 1 : (long)c->nx - 1);
    while (i <= i1 && !square_within(c, q, fy2, i))
        i++;
    while (i1 >= i && !square_within(c, q, fy2, i1))
        i1--;
    for (; i <= i1; i++)
        row[i] = 1;
}

void qc__cover_mark(qc__cover *c, qc_vec2 q)
{
    double j0 = (q.y - c->reach - c->y0) / c->side; /* rows floor(j0) .. floor(j1), clamped */
    double j1 = (q.y + c->reach - c->y0) / c->side;
    long j = j0 > 0.0 ? (long)j0 : 0;
    long jend = qc__floor_below(j1, c->ny);

    if (!(c->reach > 0.0))
        return;
    for (; j <= jend; j++)
        mark_row(c, q, j);
}
