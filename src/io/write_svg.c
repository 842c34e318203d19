/*
 * SVG preview: width/height in mm (or inches) with a matching viewBox, so one
 * user unit is one mm (or inch); y flipped. Layer <g id="region"> holds the
 * region's rings, <g id="path"> the sewn path and, dashed, the jumps, and
 * <g id="ditch"> (when given) a quilt's travel along the seams, in green.
 * Coordinates rounded to 0.001 mm (0.0001 in), trailing zeros dropped.
 * The root's data-quiltc-origin-mm names the page position of the plan's
 * (0, 0) (read_svg honours it, so a preview converts without the margin).
 */
#include <math.h>

#include "io_internal.h"

#define SVG_MARGIN_MM 2.0

typedef struct frame {
    double minx, maxy, scale; /* user units per mm */
    int64_t unit;             /* fixed-point steps per user unit */
    int decimals;
} frame;

static void num(qc__out *o, const frame *f, double user)
{
    qc__out_fixed(o, qc__round(user * (double)f->unit), f->decimals, 1);
}

static void point(qc__out *o, const frame *f, qc_vec2 p)
{
    num(o, f, (p.x - f->minx + SVG_MARGIN_MM) * f->scale);
    qc__out_char(o, ' ');
    num(o, f, (f->maxy - p.y + SVG_MARGIN_MM) * f->scale);
}

static void grow(qc_bbox *b, qc_vec2 p)
{
    b->min.x = fmin(b->min.x, p.x);
    b->min.y = fmin(b->min.y, p.y);
    b->max.x = fmax(b->max.x, p.x);
    b->max.y = fmax(b->max.y, p.y);
}

static void region_layer(qc__out *o, const frame *f, const qc_region *r)
{
    size_t k, i, start = 0;

    qc__out_str(o, "<g id=\"region\" fill=\"none\" stroke=\"#2a7ab0\" "
                   "stroke-width=\"");
    num(o, f, 0.5 * f->scale);
    qc__out_str(o, "\">\n<path fill-rule=\"evenodd\" d=\"");
    for (k = 0; k < r->nrings; k++) {
        for (i = start; i < r->ring_end[k]; i++) {
            qc__out_char(o, i == start ? 'M' : 'L');
            point(o, f, r->v[i]);
        }
        qc__out_char(o, 'Z');
        start = r->ring_end[k];
    }
    qc__out_str(o, "\"/>\n</g>\n");
}

static void path_layer(qc__out *o, const frame *f, const qc_plan *plan)
{
    size_t i, jumps = 0;

    qc__out_str(o, "<g id=\"path\" fill=\"none\" stroke=\"#c0392b\" "
                   "stroke-width=\"");
    num(o, f, 0.35 * f->scale);
    qc__out_str(o, "\" stroke-linejoin=\"round\" stroke-linecap=\"round\">\n"
                   "<path d=\"");
    for (i = 0; i < plan->n; i++) {
        int start = i == 0 || (plan->flags[i] & QC_ST_JUMP);

        qc__out_char(o, start ? 'M' : 'L');
        point(o, f, plan->p[i]);
        jumps += i > 0 && start;
    }
    qc__out_str(o, "\"/>\n");
    if (jumps > 0) {
        qc__out_str(o, "<path stroke=\"#888888\" stroke-dasharray=\"");
        num(o, f, 2 * f->scale);
        qc__out_char(o, ' ');
        num(o, f, 1 * f->scale);
        qc__out_str(o, "\" d=\"");
        for (i = 1; i < plan->n; i++) {
            if (!(plan->flags[i] & QC_ST_JUMP))
                continue;
            qc__out_char(o, 'M');
            point(o, f, plan->p[i - 1]);
            qc__out_char(o, 'L');
            point(o, f, plan->p[i]);
        }
        qc__out_str(o, "\"/>\n");
    }
    qc__out_str(o, "</g>\n");
}

static void ditch_layer(qc__out *o, const frame *f, const qc_path *t)
{
    size_t c, k = 0;

    qc__out_str(o, "<g id=\"ditch\" fill=\"none\" stroke=\"#27ae60\" stroke-width=\"");
    num(o, f, 0.5 * f->scale);
    qc__out_str(o, "\" stroke-linejoin=\"round\" stroke-linecap=\"round\">\n<path d=\"");
    for (c = 0; c < t->ncmd; c++) {
        size_t np = qc_path_cmd_points(t->cmd[c]);

        qc__out_char(o, t->cmd[c] == QC_PATH_MOVE ? 'M' : 'L');
        point(o, f, t->pt[k + np - 1]); /* a cubic is drawn as its chord */
        k += np;
    }
    qc__out_str(o, "\"/>\n</g>\n");
}

int qc__write_svg(qc_ctx *ctx, const qc_plan *plan, const qc_io_opts *opts,
                  qc__out *o)
{
    const qc_region *r = opts->region;
    const char *unit = opts->svg_inches ? "in" : "mm";
    qc_bbox b;
    frame f;
    double w, h;
    size_t i;

    (void)ctx;
    b.min = b.max = plan->p[0];
    for (i = 1; i < plan->n; i++)
        grow(&b, plan->p[i]);
    if (r != NULL)
        for (i = 0; i < r->nv; i++)
            grow(&b, r->v[i]);
    f.minx = b.min.x;
    f.maxy = b.max.y;
    f.scale = opts->svg_inches ? 1 / QC__MM_PER_IN : 1;
    f.unit = opts->svg_inches ? 10000 : 1000;
    f.decimals = opts->svg_inches ? 4 : 3;
    w = (b.max.x - b.min.x + 2 * SVG_MARGIN_MM) * f.scale;
    h = (b.max.y - b.min.y + 2 * SVG_MARGIN_MM) * f.scale;

    qc__out_str(o, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                   "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"");
    num(o, &f, w);
    qc__out_str(o, unit);
    qc__out_str(o, "\" height=\"");
    num(o, &f, h);
    qc__out_str(o, unit);
    qc__out_str(o, "\" viewBox=\"0 0 ");
    num(o, &f, w);
    qc__out_char(o, ' ');
    num(o, &f, h);
    /* where the plan's (0, 0) lies on the page, in mm from its bottom-left
     * corner, so reading this file back undoes the margin and the move */
    qc__out_str(o, "\" data-quiltc-origin-mm=\"");
    qc__out_fixed(o, qc__round((SVG_MARGIN_MM - b.min.x) * 1e6), 6, 1);
    qc__out_char(o, ' ');
    qc__out_fixed(o, qc__round((SVG_MARGIN_MM - b.min.y) * 1e6), 6, 1);
    qc__out_str(o, "\">\n");
    if (r != NULL && r->nrings > 0)
        region_layer(o, &f, r);
    path_layer(o, &f, plan);
    if (opts->travel != NULL && opts->travel->ncmd > 0)
        ditch_layer(o, &f, opts->travel);
    qc__out_str(o, "</svg>\n");
    return QC_OK;
}
