/*
 * The four tessellations of paper §4.1 as a lattice (basis a1 horizontal,
 * a2) with a motif of offsets per cell, for nearest-neighbour distance d:
 * square and triangle (one point per cell), honeycomb (two), snub square
 * 3.3.4.3.4 (four: the corners of a square tilted 15 degrees).
 */
#include <math.h>

#include "sample_internal.h"

#define MAX_MOTIF 4

typedef struct lattice {
    qc_vec2 a1, a2;
    qc_vec2 off[MAX_MOTIF];
    size_t m;
} lattice;

static void make_lattice(int kind, double d, lattice *L)
{
    const double s3 = 1.7320508075688772;
    size_t i;

    L->m = 1;
    L->off[0].x = L->off[0].y = 0.0;
    L->a1.x = d;
    L->a1.y = 0.0;
    switch (kind) {
    case QC_SAMPLE_SQUARE:
        L->a2.x = 0.0;
        L->a2.y = d;
        break;
    case QC_SAMPLE_TRIANGLE:
        L->a2.x = d / 2;
        L->a2.y = d * s3 / 2;
        break;
    case QC_SAMPLE_HEX: /* triangular lattice of side d sqrt 3, sites A and A + (0, d) */
        L->a1.x = d * s3;
        L->a2.x = d * s3 / 2;
        L->a2.y = 1.5 * d;
        L->m = 2;
        L->off[1].x = 0.0;
        L->off[1].y = d;
        break;
    default: { /* snub square: period d (sqrt 6 + sqrt 2) / 2, corners at 60 + 90 k degrees */
        static const double c[4][2] = {{0.5, 0.8660254037844386},
                                       {-0.8660254037844386, 0.5},
                                       {-0.5, -0.8660254037844386},
                                       {0.8660254037844386, -0.5}};
        double r = d * 0.7071067811865476;
        L->a1.x = d * 1.9318516525781366;
        L->a2.x = 0.0;
        L->a2.y = L->a1.x;
        L->m = 4;
        for (i = 0; i < 4; i++) {
            L->off[i].x = r * c[i][0];
            L->off[i].y = r * c[i][1];
        }
    }
    }
}

int qc__sample_lattice(qc_ctx *ctx, const qc__rindex *ix, int kind, double d, double margin,
                       qc_points *out)
{
    lattice L;
    qc_bbox box = ix->box;
    qc_vec2 o;
    double j0, j1, j;
    size_t k;

    make_lattice(kind, d, &L);
    o.x = (box.min.x + box.max.x) / 2; /* centred, so symmetric blocks sample symmetrically */
    o.y = (box.min.y + box.max.y) / 2;
    j0 = floor((box.min.y - o.y - d * 2) / L.a2.y);
    j1 = ceil((box.max.y - o.y + d * 2) / L.a2.y);
    for (j = j0; j <= j1; j++)
        for (k = 0; k < L.m; k++) {
            double y = o.y + j * L.a2.y + L.off[k].y;
            double xs = o.x + j * L.a2.x + L.off[k].x;
            double i0 = ceil((box.min.x - xs) / L.a1.x), i1 = floor((box.max.x - xs) / L.a1.x);
            double i;

            if (y < box.min.y || y > box.max.y)
                continue;
            for (i = i0; i <= i1; i++) {
                qc_vec2 p;
                p.x = xs + i * L.a1.x;
                p.y = y;
                if (qc__rindex_admits(ix, p, margin))
                    QC__TRY(qc_points_push(ctx, out, p));
            }
        }
    return QC_OK;
}
