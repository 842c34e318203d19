/*
 * The SVG readers: qc_io_read_svg_region and qc_io_read_svg_path.
 *
 * Coordinates: the root's user units map to mm through width/height and
 * viewBox (svg_units.c); y is flipped as y_mm' = H - y_mm, H being the
 * document's height in mm, so the document's bottom-left corner is the
 * origin and what Inkscape shows (y up, origin bottom-left) is what we
 * read. Without a height and viewBox, H = 0 (y simply negated).
 *
 * Region: every closed shape (path, rect, circle, ellipse, polygon) gives
 * one ring per subpath, curves flattened to the tolerance; an open subpath
 * (one not ending at its start) is closed, as SVG fills it, unless the
 * shape's fill is none: then it is only a stroke and is left out (so
 * quiltc's own preview reads back as its region layer). polyline and line
 * have no inside and are ignored. Rings with fewer than 3 distinct
 * vertices or no area are dropped. Holes: the region is even-odd by nesting (region.h). A shape
 * with fill-rule evenodd keeps all its rings. With nonzero (SVG's default)
 * a ring is kept only where the fill changes across it: the winding number
 * just inside it (the sum of the orientations of the shape's rings that
 * contain it, its own included) and just outside differ in being zero. So
 * a same-direction ring inside another (filled under nonzero) is dropped,
 * an opposite-direction one stays a hole, and even-odd nesting of the
 * kept rings reproduces the nonzero fill, provided the rings do not cross
 * (crossing rings are qc_region_normalize's QC_EINTERSECT). A shape whose
 * ring-containment tests would exceed QC__SVG_WINDING_BUDGET edge tests keeps
 * all its rings. Separate shapes are not merged: overlapping shapes
 * combine even-odd.
 */
#include <math.h>
#include <string.h>

#include "svg_internal.h"

#define DEFAULT_TOLERANCE 0.05
#define DEFAULT_MAX_BYTES ((size_t)16 << 20)
#define QC__SVG_WINDING_BUDGET 50000000.0

typedef struct ring_set {
    qc_vec2 *v;
    size_t nv, v_cap;
    size_t *end; /* ring k: v[k ? end[k-1] : 0 .. end[k]) */
    size_t n, end_cap;
} ring_set;

typedef struct region_sink {
    qc_ctx *ctx;
    qc_region *out;
    double tol;
    qc_points flat;   /* one cubic flattened */
    ring_set rings;   /* the current shape's rings */
    qc_vec2 *cur;     /* the ring being built */
    size_t ncur, cur_cap;
    signed char *keep;
    size_t keep_cap;
    size_t open_shapes, stroke_only; /* left out, for the QC_EEMPTY message */
    qc_region guides;                /* closed shapes with fill:none */
    size_t nguides;
    unsigned long guide_line;        /* the first one's line, element and id */
    char guide_elem[48];
    qc__svg_rings_fn per_shape;      /* set: each shape's rings go to it, then out is emptied */
    void *per_shape_ud;
} region_sink;

static int resolve_opts(qc_ctx *ctx, const char *buf, size_t len, const qc_svg_opts *opts,
                        double *tol)
{
    size_t max_bytes = opts != NULL && opts->max_bytes > 0 ? opts->max_bytes : DEFAULT_MAX_BYTES;
    size_t i;

    *tol = opts != NULL && opts->tolerance != 0 ? opts->tolerance : DEFAULT_TOLERANCE;
    if (!(*tol > 0) || !(*tol <= 1e3))
        return qc__fail(ctx, QC_ERANGE, "svg: flattening tolerance %g mm must be in (0, 1000]",
                        *tol);
    if (buf == NULL && len > 0)
        return qc__fail(ctx, QC_EINVAL, "svg: NULL buffer of %lu bytes", (unsigned long)len);
    if (len > max_bytes)
        return qc__fail(ctx, QC_ELIMIT, "svg: %lu bytes exceed the limit of %lu",
                        (unsigned long)len, (unsigned long)max_bytes);
    for (i = 0; i < len; i++)
        if (buf[i] != ' ' && buf[i] != '\t' && buf[i] != '\n' && buf[i] != '\r')
            return QC_OK;
    return qc__fail(ctx, QC_EEMPTY, "svg: the document is empty");
}

/* ---- region ---- */

static int cur_push(region_sink *s, qc_vec2 p)
{
    if (s->ncur > 0 && s->cur[s->ncur - 1].x == p.x && s->cur[s->ncur - 1].y == p.y)
        return QC_OK;
    if (s->out->nv + s->guides.nv + s->rings.nv + s->ncur >= QC_MAX_POINTS)
        return qc__fail(s->ctx, QC_ELIMIT, "svg: the region has more than %lu vertices",
                        (unsigned long)QC_MAX_POINTS);
    QC__TRY(QC__RESERVE(s->ctx, s->cur, s->cur_cap, s->ncur + 1));
    s->cur[s->ncur++] = p;
    return QC_OK;
}

static double area2(const qc_vec2 *v, size_t n)
{
    double a = 0;
    size_t i, j = n - 1;

    for (i = 0; i < n; j = i++)
        a += (v[j].x - v[0].x) * (v[i].y - v[0].y) - (v[i].x - v[0].x) * (v[j].y - v[0].y);
    return a;
}

/* Ends the ring being built: kept when it has 3 distinct vertices and area. */
static int ring_done(region_sink *s)
{
    size_t n = s->ncur, i;
    double a, size, minx, maxx, miny, maxy;

    s->ncur = 0;
    if (n > 1 && s->cur[0].x == s->cur[n - 1].x && s->cur[0].y == s->cur[n - 1].y)
        n--;
    if (n < 3)
        return QC_OK;
    minx = maxx = s->cur[0].x;
    miny = maxy = s->cur[0].y;
    for (i = 1; i < n; i++) {
        minx = fmin(minx, s->cur[i].x);
        maxx = fmax(maxx, s->cur[i].x);
        miny = fmin(miny, s->cur[i].y);
        maxy = fmax(maxy, s->cur[i].y);
    }
    size = fmax(maxx - minx, maxy - miny);
    a = fabs(area2(s->cur, n)) / 2;
    if (!(a > 1e-10 * size * size) || a < 1e-12) {
        /* no net area; with unsigned area it is a figure-8 whose lobes
         * cancel: it crosses itself (normalizing would say so for any other) */
        double fan = 0;
        for (i = 1; i + 1 < n; i++)
            fan += fabs((s->cur[i].x - s->cur[0].x) * (s->cur[i + 1].y - s->cur[0].y) -
                        (s->cur[i].y - s->cur[0].y) * (s->cur[i + 1].x - s->cur[0].x));
        if (fan / 2 > 1e-6 * size * size && fan / 2 > 1e-12)
            return qc__fail(s->ctx, QC_EINTERSECT,
                            "svg: a shape crosses itself (its lobes cancel to zero area)");
        return QC_OK;
    }
    QC__TRY(QC__RESERVE(s->ctx, s->rings.v, s->rings.v_cap, s->rings.nv + n));
    QC__TRY(QC__RESERVE(s->ctx, s->rings.end, s->rings.end_cap, s->rings.n + 1));
    memcpy(s->rings.v + s->rings.nv, s->cur, n * sizeof *s->cur);
    s->rings.nv += n;
    s->rings.end[s->rings.n++] = s->rings.nv;
    return QC_OK;
}

static int flatten_cubic(region_sink *s, qc_vec2 p0, const qc_vec2 *c)
{
    unsigned char cmd[2] = {QC_PATH_MOVE, QC_PATH_CUBIC};
    qc_vec2 pt[4];
    qc_path one;
    size_t i;

    pt[0] = p0;
    pt[1] = c[0];
    pt[2] = c[1];
    pt[3] = c[2];
    memset(&one, 0, sizeof one);
    one.cmd = cmd;
    one.ncmd = 2;
    one.pt = pt;
    one.npt = 4;
    s->flat.n = 0;
    QC__TRY(qc_curve_flatten(s->ctx, &one, s->tol, &s->flat, NULL));
    for (i = 1; i < s->flat.n; i++)
        QC__TRY(cur_push(s, s->flat.v[i]));
    return QC_OK;
}

typedef struct ring_info {
    qc_bbox box;
    int sign;
} ring_info;

static size_t rs_start(const ring_set *r, size_t k)
{
    return k ? r->end[k - 1] : 0;
}

/* 1 inside, 0 outside, -1 on the boundary of ring q. */
static int ring_side(const ring_set *r, size_t q, qc_vec2 p)
{
    size_t s0 = rs_start(r, q), e = r->end[q], i, j = e - 1;
    int inside = 0;

    for (i = s0; i < e; j = i++) {
        qc_vec2 a = r->v[j], b = r->v[i];
        double cross = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);

        if (cross == 0 && p.x >= fmin(a.x, b.x) && p.x <= fmax(a.x, b.x) &&
            p.y >= fmin(a.y, b.y) && p.y <= fmax(a.y, b.y))
            return -1;
        if ((a.y > p.y) != (b.y > p.y) && ((cross > 0) == (b.y > a.y)))
            inside = !inside;
    }
    return inside;
}

/* Whether ring k lies inside ring q (rings assumed not to cross); a ring
 * lying wholly on another counts as inside the earlier one. */
static int ring_in(const ring_set *r, const ring_info *info, size_t k, size_t q, double *work)
{
    size_t i, s0 = rs_start(r, k);

    if (info[k].box.min.x < info[q].box.min.x || info[k].box.min.y < info[q].box.min.y ||
        info[k].box.max.x > info[q].box.max.x || info[k].box.max.y > info[q].box.max.y)
        return 0;
    for (i = s0; i < r->end[k]; i++) {
        int side = ring_side(r, q, r->v[i]);

        *work += (double)(r->end[q] - rs_start(r, q));
        if (side >= 0)
            return side;
    }
    return q < k;
}

/* Marks in s->keep the rings whose two sides differ in nonzero fill. */
static int nonzero_filter(region_sink *s)
{
    const ring_set *r = &s->rings;
    ring_info *info;
    size_t k, q;
    double work = 0;

    info = (ring_info *)qc__alloc_array(s->ctx, r->n, sizeof *info);
    if (info == NULL)
        return QC_ENOMEM;
    for (k = 0; k < r->n; k++) {
        size_t i;

        info[k].box.min = info[k].box.max = r->v[rs_start(r, k)];
        for (i = rs_start(r, k); i < r->end[k]; i++) {
            info[k].box.min.x = fmin(info[k].box.min.x, r->v[i].x);
            info[k].box.min.y = fmin(info[k].box.min.y, r->v[i].y);
            info[k].box.max.x = fmax(info[k].box.max.x, r->v[i].x);
            info[k].box.max.y = fmax(info[k].box.max.y, r->v[i].y);
        }
        info[k].sign = area2(r->v + rs_start(r, k), r->end[k] - rs_start(r, k)) > 0 ? 1 : -1;
    }
    for (k = 0; k < r->n && work <= QC__SVG_WINDING_BUDGET; k++) {
        long w_in = info[k].sign, w_out;

        for (q = 0; q < r->n && work <= QC__SVG_WINDING_BUDGET; q++) {
            work += 1;
            if (q != k && ring_in(r, info, k, q, &work))
                w_in += info[q].sign;
        }
        w_out = w_in - info[k].sign;
        s->keep[k] = (signed char)((w_in != 0) != (w_out != 0));
    }
    if (work > QC__SVG_WINDING_BUDGET)
        memset(s->keep, 1, r->n); /* too costly to decide: keep every ring */
    qc__free(s->ctx, info, r->n * sizeof *info);
    return QC_OK;
}

/* Whether the subpath starting at command c (a MOVE, point index k) ends
 * where it starts. */
static int subpath_closed(const qc_path *shape, size_t c, size_t k)
{
    qc_vec2 first = shape->pt[k++], last = first;

    for (c++; c < shape->ncmd && shape->cmd[c] != QC_PATH_MOVE; c++) {
        k += qc_path_cmd_points(shape->cmd[c]);
        last = shape->pt[k - 1];
    }
    return last.x == first.x && last.y == first.y;
}

/* Remembers the first guide for the warning: id="g1" or shape 3. */
static void note_guide(region_sink *s, const qc__svg_elem *el)
{
    size_t n = 0, i;
    const char *src = el->id;

    if (s->nguides++ > 0)
        return;
    s->guide_line = el->line;
    if (src != NULL) {
        static const char pre[] = "id=\"";

        memcpy(s->guide_elem, pre, sizeof pre - 1);
        n = sizeof pre - 1;
        for (i = 0; src[i] != '\0' && n < sizeof s->guide_elem - 2; i++)
            s->guide_elem[n++] = src[i];
        s->guide_elem[n++] = '"';
    } else {
        /* the shape's number, written by hand (no printf for one integer) */
        char digits[24];
        size_t v = el->index, nd = 0;

        memcpy(s->guide_elem, "shape ", 6);
        n = 6;
        do {
            digits[nd++] = (char)('0' + v % 10);
            v /= 10;
        } while (v > 0);
        while (nd > 0)
            s->guide_elem[n++] = digits[--nd];
    }
    s->guide_elem[n] = '\0';
}

static int region_shape(void *ud, const qc_path *shape, unsigned flags, const qc__svg_elem *el)
{
    region_sink *s = (region_sink *)ud;
    qc_region *to = s->out;
    size_t c, k = 0;
    qc_vec2 cur = {0, 0};
    int skip = 0;

    if (!(flags & QC__SVG_CLOSED)) {
        s->open_shapes++;
        return QC_OK;
    }
    s->rings.nv = s->rings.n = 0;
    s->ncur = 0;
    for (c = 0; c < shape->ncmd; c++) {
        if (shape->cmd[c] == QC_PATH_MOVE) {
            QC__TRY(ring_done(s));
            if (!(flags & QC__SVG_FILLED)) {
                skip = !subpath_closed(shape, c, k);
                s->stroke_only += (size_t)skip;
            }
        }
        if (skip) {
            k += qc_path_cmd_points(shape->cmd[c]);
            continue;
        }
        if (shape->cmd[c] == QC_PATH_CUBIC) {
            QC__TRY(flatten_cubic(s, cur, shape->pt + k));
            cur = shape->pt[k + 2];
            k += 3;
            continue;
        }
        cur = shape->pt[k++];
        QC__TRY(cur_push(s, cur));
    }
    QC__TRY(ring_done(s));
    if (s->rings.n == 0)
        return QC_OK;
    if (!(flags & QC__SVG_FILLED) && s->per_shape == NULL) {
        to = &s->guides; /* kept aside: the region only if nothing is filled */
        note_guide(s, el);
    }
    if (s->out->nrings + s->guides.nrings + s->rings.n > QC_MAX_REGION_RINGS)
        return qc__fail(s->ctx, QC_ELIMIT, "svg: the region has more than %u outlines and holes",
                        QC_MAX_REGION_RINGS);
    QC__TRY(QC__RESERVE(s->ctx, s->keep, s->keep_cap, s->rings.n));
    if ((flags & QC__SVG_EVENODD) || s->rings.n == 1)
        memset(s->keep, 1, s->rings.n);
    else
        QC__TRY(nonzero_filter(s));
    for (k = 0; k < s->rings.n; k++)
        if (s->keep[k])
            QC__TRY(qc_region_add_ring(s->ctx, to, s->rings.v + rs_start(&s->rings, k),
                                       s->rings.end[k] - rs_start(&s->rings, k)));
    if (s->per_shape != NULL && s->out->nrings > 0) {
        int rc = s->per_shape(s->per_shape_ud, s->out, el);

        s->out->nv = s->out->nrings = 0;
        return rc;
    }
    return QC_OK;
}

/* The region reader, or with per_shape set the shape-by-shape walk. */
static void warner_of(const qc_svg_opts *opts, qc__svg_warner *w)
{
    w->fn = opts != NULL ? opts->warn : NULL;
    w->ud = opts != NULL ? opts->warn_ud : NULL;
    w->count = 0;
}

/* Shapes with fill:none are guides and strokes beside filled shapes, but
 * the outlines of a drawing that fills nothing (a quiltc preview). */
static void settle_guides(region_sink *s, qc__svg_warner *warn)
{
    if (s->guides.nrings == 0)
        return;
    if (s->out->nrings == 0) {
        qc_region t = *s->out;

        *s->out = s->guides;
        s->guides = t;
        return;
    }
    qc__svg_warn(warn, "svg: %lu closed shapes with fill:none (guides or strokes; the first: "
                       "%s, line %lu) are left out: the filled shapes are the region",
                 (unsigned long)s->nguides, s->guide_elem, s->guide_line);
}

static int read_region(qc_ctx *ctx, const char *buf, size_t len, const qc_svg_opts *opts,
                       qc_region *out, qc__svg_rings_fn per_shape, void *ud)
{
    region_sink s;
    qc__svg_warner warn;
    int rc;

    memset(out, 0, sizeof *out);
    memset(&s, 0, sizeof s);
    QC__TRY(resolve_opts(ctx, buf, len, opts, &s.tol));
    warner_of(opts, &warn);
    s.ctx = ctx;
    s.out = out;
    s.per_shape = per_shape;
    s.per_shape_ud = ud;
    rc = qc__svg_walk(ctx, buf, len, &warn, region_shape, &s);
    if (rc >= 0 && per_shape == NULL)
        settle_guides(&s, &warn);
    qc_region_free(ctx, &s.guides);
    if (rc >= 0 && per_shape == NULL && out->nrings == 0)
        rc = qc__fail(ctx, QC_EEMPTY,
                      "svg: no closed shape with an area (ignored: %lu polyline or line "
                      "shapes, %lu unclosed subpaths with fill:none)",
                      (unsigned long)s.open_shapes, (unsigned long)s.stroke_only);
    qc_points_free(ctx, &s.flat);
    qc__free(ctx, s.rings.v, s.rings.v_cap * sizeof *s.rings.v);
    qc__free(ctx, s.rings.end, s.rings.end_cap * sizeof *s.rings.end);
    qc__free(ctx, s.cur, s.cur_cap * sizeof *s.cur);
    qc__free(ctx, s.keep, s.keep_cap * sizeof *s.keep);
    if (rc < 0 || per_shape != NULL)
        qc_region_free(ctx, out);
    return rc < 0 ? rc : QC_OK;
}

int qc_io_read_svg_region(qc_ctx *ctx, const char *buf, size_t len, const qc_svg_opts *opts,
                          qc_region *out)
{
    if (out == NULL)
        return qc__fail(ctx, QC_EINVAL, "svg: no output region");
    return read_region(ctx, buf, len, opts, out, NULL, NULL);
}

int qc__svg_walk_rings(qc_ctx *ctx, const char *buf, size_t len, const qc_svg_opts *opts,
                       qc__svg_rings_fn fn, void *ud)
{
    qc_region scratch;

    return read_region(ctx, buf, len, opts, &scratch, fn, ud);
}

/* ---- path ---- */

typedef struct path_sink {
    qc_ctx *ctx;
    qc_path *out;
} path_sink;

static int path_shape(void *ud, const qc_path *shape, unsigned flags, const qc__svg_elem *el)
{
    path_sink *s = (path_sink *)ud;

    (void)el;
    if (flags & (QC__SVG_DASHED | QC__SVG_REGION_LAYER))
        return QC_OK; /* a jump or the block's outline, not a stitch line */
    if (s->out->npt + shape->npt > QC_MAX_POINTS)
        return qc__fail(s->ctx, QC_ELIMIT, "svg: the path has more than %lu points",
                        (unsigned long)QC_MAX_POINTS);
    return qc_path_append(s->ctx, s->out, shape, 0);
}

int qc_io_read_svg_path(qc_ctx *ctx, const char *buf, size_t len, const qc_svg_opts *opts,
                        qc_path *out)
{
    path_sink s;
    qc__svg_warner warn;
    double tol;
    int rc;

    if (out == NULL)
        return qc__fail(ctx, QC_EINVAL, "svg: no output path");
    memset(out, 0, sizeof *out);
    QC__TRY(resolve_opts(ctx, buf, len, opts, &tol));
    s.ctx = ctx;
    s.out = out;
    warner_of(opts, &warn);
    rc = qc__svg_walk(ctx, buf, len, &warn, path_shape, &s);
    if (rc >= 0 && out->ncmd == 0)
        rc = qc__fail(ctx, QC_EEMPTY, "svg: no shape to read");
    if (rc < 0) {
        qc_path_free(ctx, out);
        return rc;
    }
    return QC_OK;
}
