/* Growing and freeing the plain array types of core.h. */
#include <string.h>

#include "internal.h"

void qc_points_free(qc_ctx *ctx, qc_points *pts)
{
    if (pts == NULL)
        return;
    qc__free(ctx, pts->v, pts->cap * sizeof *pts->v);
    memset(pts, 0, sizeof *pts);
}

void qc_edges_free(qc_ctx *ctx, qc_edges *edges)
{
    if (edges == NULL)
        return;
    qc__free(ctx, edges->e, edges->cap * sizeof *edges->e);
    memset(edges, 0, sizeof *edges);
}

void qc_order_free(qc_ctx *ctx, qc_order *order)
{
    if (order == NULL)
        return;
    qc__free(ctx, order->i, order->cap * sizeof *order->i);
    memset(order, 0, sizeof *order);
}

int qc_points_push(qc_ctx *ctx, qc_points *pts, qc_vec2 p)
{
    QC__TRY(QC__RESERVE(ctx, pts->v, pts->cap, pts->n + 1));
    pts->v[pts->n++] = p;
    return QC_OK;
}

int qc_edges_push(qc_ctx *ctx, qc_edges *edges, uint32_t a, uint32_t b)
{
    QC__TRY(QC__RESERVE(ctx, edges->e, edges->cap, edges->n + 1));
    edges->e[edges->n].a = a;
    edges->e[edges->n].b = b;
    edges->n++;
    return QC_OK;
}

int qc_order_push(qc_ctx *ctx, qc_order *order, uint32_t i)
{
    QC__TRY(QC__RESERVE(ctx, order->i, order->cap, order->n + 1));
    order->i[order->n++] = i;
    return QC_OK;
}

/* Cuts the array's block to what it holds (as qc__path_fit). */
void qc__points_fit(qc_ctx *ctx, qc_points *a)
{
    qc_vec2 *v;

    if (a->n == 0 || a->cap <= a->n)
        return;
    v = (qc_vec2 *)qc__realloc(ctx, a->v, a->cap * sizeof *v, a->n * sizeof *v);
    if (v == NULL) {
        qc_clear_error(ctx);
        return;
    }
    a->v = v;
    a->cap = a->n;
}
