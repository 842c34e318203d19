/*
 * The document walk: containers (svg, g, a, switch) compose their
 * transforms; shapes (path, rect, circle, ellipse, polygon, polyline, line)
 * become paths in mm, y up, handed to the caller one by one in document
 * order; <use> walks its source again (tokenized from its byte offset, found
 * in the index) under the use's transform and x/y, its style inherited from
 * the use, within a budget of depth, clones, elements and bytes. Not drawn
 * and skipped with their whole subtree: display:none, defs, symbol (unless
 * cloned), clipPath, mask, marker, pattern, text, image and every other
 * element, and elements outside the SVG namespace (sodipodi:namedview,
 * metadata); visibility:hidden hides shapes but not descendants that set it
 * back. fill, fill-rule, stroke-dasharray and visibility are inherited. A
 * property comes from the style attribute, else the <style> sheets' rules
 * (highest specificity, then the last), else the attribute of its name.
 * clip-path (on a shape, group or use; nested clips intersect) is applied
 * where exact (svg_clip.c: one convex straight-edged clip; the shape inside,
 * beyond or itself convex); what is not honoured (other clips, mask, text,
 * images, unresolved clones) is a warning naming the element.
 */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "svg_internal.h"

typedef struct frame {
    qc__svg_mat m; /* this element's user units -> mm, y up */
    int evenodd;
    int unfilled;  /* fill:none */
    int dashed;    /* stroke-dasharray other than none (inherited) */
    int in_region; /* inside id="region" or id="ditch" (quiltc's outline and travel layers) */
    int fill_rgb;  /* fill is a colour, in fill (inherited) */
    uint32_t fill;
    int hidden;    /* visibility:hidden or collapse (inherited; children may undo it) */
    size_t clip;   /* 1 + the walker's clip in force (its own or a group's), or 0 */
    int skip;      /* this element and its subtree draw nothing */
} frame;

typedef struct walker {
    qc_ctx *ctx;
    qc__xml *x;    /* the tokenizer walked: the document's, or a clone's */
    qc__xml doc;
    frame *st;     /* st[d] for the element at depth d of x (1 = root or clone source) */
    frame *doc_st;
    qc_path shape;
    double vp_w, vp_h;
    qc__svg_shape_fn fn;
    void *ud;
    qc__svg_where w;
    char elem[24];
    size_t shapes;   /* shape elements so far */
    size_t elements; /* elements of the document so far (names them in warnings) */
    const qc__svg_index *ix;
    qc__svg_warner *warn;
    qc__css_match css; /* the current element's rules */
    /* <use> clones: the sources being walked (a cycle check), a tokenizer
     * and frame stack per level, and the budget spent */
    size_t use_depth, use_count, use_elements, use_bytes;
    size_t use_src[QC__SVG_USE_MAX_DEPTH];
    unsigned long use_line; /* the outermost <use>'s line while cloning */
    int use_sized[QC__SVG_USE_MAX_DEPTH]; /* that use gave width or height */
    qc__xml *sub_x[QC__SVG_USE_MAX_DEPTH];
    frame *sub_st[QC__SVG_USE_MAX_DEPTH];
    /* clip-path: a clipPath's shapes are collected, not emitted */
    int collecting;
    size_t collect_depth; /* the clone level of the clipPath being read */
    qc_path clip_shapes;
    size_t nclip_shapes;
    qc__svg_clip clip; /* the clipPath just read */
    qc__svg_clip *clips; /* the clips in force, a stack in document order */
    size_t nclips, clips_hw, clips_cap; /* hw: entries ever used (their v kept) */
} walker;

static int name_is(const walker *k, const char *name)
{
    size_t n = strlen(name);

    return k->x->local_len == n && memcmp(k->x->local, name, n) == 0;
}

/* ---- style and presentation attributes ---- */

/* A presentation property p: the style attribute's declaration, else the
 * style sheets' rules, else the attribute of the same name. */
static int property(const walker *k, int p, const char **val, size_t *vlen)
{
    const char *prop = qc__css_prop_name[p];
    const qc__xml_attr *a = qc__xml_attr_get(k->x, "style");

    if (a != NULL && qc__css_decl(a->value, a->value_len, prop, val, vlen))
        return 1;
    if (qc__css_get(&k->css, p, val, vlen))
        return 1;
    a = qc__xml_attr_get(k->x, prop);
    if (a == NULL)
        return 0;
    *val = a->value;
    *vlen = a->value_len;
    qc__svg_trim(val, vlen);
    return 1;
}

static int value_is(const char *v, size_t n, const char *w)
{
    return n == strlen(w) && memcmp(v, w, n) == 0;
}

static int value_is_attr(const walker *k, const char *name, const char *w)
{
    const qc__xml_attr *a = qc__xml_attr_get(k->x, name);

    return a != NULL && value_is(a->value, a->value_len, w);
}

/* ---- transform lists ---- */

static int transform(walker *k, const char *s, size_t n, qc__svg_mat *out)
{
    static const struct {
        const char *name;
        int min, max;
    } fns[] = {{"matrix", 6, 6}, {"translate", 1, 2}, {"scale", 1, 2},
               {"rotate", 1, 3}, {"skewX", 1, 1},     {"skewY", 1, 1}};
    qc__svg_where *w = &k->w;
    size_t i = 0;

    *out = qc__svg_mat_identity();
    w->attr = "transform";
    while (i < n && qc__is_space(s[i]))
        i++;
    while (i < n) {
        size_t j = i, f, at;
        double a[6] = {0, 0, 0, 0, 0, 0}, sn, cs;
        int na = 0;
        qc__svg_mat t = qc__svg_mat_identity();

        while (j < n && ((s[j] >= 'a' && s[j] <= 'z') || (s[j] >= 'A' && s[j] <= 'Z')))
            j++;
        for (f = 0; f < sizeof fns / sizeof fns[0]; f++)
            if (value_is(s + i, j - i, fns[f].name))
                break;
        if (f == sizeof fns / sizeof fns[0])
            return qc__svg_syntax(w, s, n, i,
                                  "expected matrix, translate, scale, rotate, skewX or skewY");
        while (j < n && qc__is_space(s[j]))
            j++;
        if (j >= n || s[j] != '(')
            return qc__svg_syntax(w, s, n, j, "expected '('");
        j++;
        while (j < n && qc__is_space(s[j]))
            j++;
        while (j < n && s[j] != ')') {
            if (na > 0)
                qc__svg_skip_sep(s, n, &j);
            at = j;
            if (na == 6 || !qc__scan_number(s, n, &j, &a[na]))
                return qc__svg_syntax(w, s, n, at, na == 6 ? "expected ')'" : "expected a number");
            QC__TRY(qc__svg_check_number(w, a[na], s, n, at));
            na++;
            while (j < n && qc__is_space(s[j]))
                j++;
        }
        if (j >= n)
            return qc__svg_syntax(w, s, n, j, "expected ')'");
        if (na < fns[f].min || na > fns[f].max || (f == 3 && na == 2))
            return qc__svg_syntax(w, s, n, i, "wrong number of arguments");
        j++;
        switch (f) {
        case 0:
            t.a = a[0];
            t.b = a[1];
            t.c = a[2];
            t.d = a[3];
            t.e = a[4];
            t.f = a[5];
            break;
        case 1:
            t.e = a[0];
            t.f = a[1];
            break;
        case 2:
            t.a = a[0];
            t.d = na == 2 ? a[1] : a[0];
            break;
        case 3:
            qc__svg_sincos_deg(a[0], &sn, &cs);
            t.a = cs;
            t.b = sn;
            t.c = -sn;
            t.d = cs;
            /* about (cx, cy): translate(c) rotate translate(-c) */
            t.e = a[1] - cs * a[1] + sn * a[2];
            t.f = a[2] - sn * a[1] - cs * a[2];
            break;
        default:
            qc__svg_sincos_deg(a[0], &sn, &cs);
            if (fabs(cs) < 1e-9)
                return qc__fail(k->ctx, QC_ERANGE,
                                "svg line %lu, <%s transform>: skew angle %g has no tangent",
                                w->line, w->elem, a[0]);
            if (f == 4)
                t.c = sn / cs;
            else
                t.b = sn / cs;
            break;
        }
        *out = qc__svg_mat_mul(*out, t);
        i = j;
        if (qc__svg_skip_sep(s, n, &i) && i >= n)
            return qc__svg_syntax(w, s, n, i, "expected a transform after ','");
    }
    return QC_OK;
}

/* ---- shapes in their own user units ---- */

/* A <length> attribute; *v keeps its default when absent. */
static int length(walker *k, const char *name, int axis, double *v, int *given)
{
    const qc__xml_attr *a = qc__xml_attr_get(k->x, name);

    if (given != NULL)
        *given = 0;
    if (a == NULL || value_is(a->value, a->value_len, "auto"))
        return QC_OK; /* SVG 2's auto: as if absent */
    if (given != NULL)
        *given = 1;
    k->w.attr = name;
    return qc__svg_length(&k->w, a->value, a->value_len, axis, k->vp_w, k->vp_h, v);
}

static int move(walker *k, double x, double y)
{
    return qc_path_move_to(k->ctx, &k->shape, QC__V2(x, y));
}

static int line(walker *k, double x, double y)
{
    return qc_path_line_to(k->ctx, &k->shape, QC__V2(x, y));
}

/* Quarter arcs of an ellipse from (x0, y0) to (x1, y1), sweep positive. */
static int quarter(walker *k, double x0, double y0, double rx, double ry, double x1, double y1)
{
    return qc__svg_arc_to(k->ctx, &k->shape, QC__V2(x0, y0), rx, ry, 0, 0, 1, QC__V2(x1, y1));
}

static int rect(walker *k)
{
    double x = 0, y = 0, wd = 0, ht = 0, rx = 0, ry = 0;
    int hrx, hry;

    QC__TRY(length(k, "x", QC__SVG_AXIS_X, &x, NULL));
    QC__TRY(length(k, "y", QC__SVG_AXIS_Y, &y, NULL));
    QC__TRY(length(k, "width", QC__SVG_AXIS_X, &wd, NULL));
    QC__TRY(length(k, "height", QC__SVG_AXIS_Y, &ht, NULL));
    QC__TRY(length(k, "rx", QC__SVG_AXIS_X, &rx, &hrx));
    QC__TRY(length(k, "ry", QC__SVG_AXIS_Y, &ry, &hry));
    if (!(wd > 0) || !(ht > 0))
        return QC_OK; /* not rendered */
    /* a missing or negative radius is auto: the other one */
    hrx = hrx && rx >= 0;
    hry = hry && ry >= 0;
    if (!hrx)
        rx = hry ? ry : 0;
    if (!hry)
        ry = hrx ? rx : 0;
    rx = rx > wd / 2 ? wd / 2 : rx;
    ry = ry > ht / 2 ? ht / 2 : ry;
    if (rx > 0 && ry > 0) {
        QC__TRY(move(k, x + rx, y));
        if (wd > 2 * rx)
            QC__TRY(line(k, x + wd - rx, y));
        QC__TRY(quarter(k, x + wd - rx, y, rx, ry, x + wd, y + ry));
        if (ht > 2 * ry)
            QC__TRY(line(k, x + wd, y + ht - ry));
        QC__TRY(quarter(k, x + wd, y + ht - ry, rx, ry, x + wd - rx, y + ht));
        if (wd > 2 * rx)
            QC__TRY(line(k, x + rx, y + ht));
        QC__TRY(quarter(k, x + rx, y + ht, rx, ry, x, y + ht - ry));
        if (ht > 2 * ry)
            QC__TRY(line(k, x, y + ry));
        return quarter(k, x, y + ry, rx, ry, x + rx, y);
    }
    QC__TRY(move(k, x, y));
    QC__TRY(line(k, x + wd, y));
    QC__TRY(line(k, x + wd, y + ht));
    QC__TRY(line(k, x, y + ht));
    return line(k, x, y);
}

static int ellipse(walker *k, double cx, double cy, double rx, double ry)
{
    if (!(rx > 0) || !(ry > 0))
        return QC_OK;
    QC__TRY(move(k, cx + rx, cy));
    QC__TRY(quarter(k, cx + rx, cy, rx, ry, cx, cy + ry));
    QC__TRY(quarter(k, cx, cy + ry, rx, ry, cx - rx, cy));
    QC__TRY(quarter(k, cx - rx, cy, rx, ry, cx, cy - ry));
    return quarter(k, cx, cy - ry, rx, ry, cx + rx, cy);
}

static int circle(walker *k)
{
    double cx = 0, cy = 0, r = 0;

    QC__TRY(length(k, "cx", QC__SVG_AXIS_X, &cx, NULL));
    QC__TRY(length(k, "cy", QC__SVG_AXIS_Y, &cy, NULL));
    QC__TRY(length(k, "r", QC__SVG_AXIS_OTHER, &r, NULL));
    return ellipse(k, cx, cy, r, r);
}

static int ellipse_el(walker *k)
{
    double cx = 0, cy = 0, rx = 0, ry = 0;
    int hrx, hry;

    QC__TRY(length(k, "cx", QC__SVG_AXIS_X, &cx, NULL));
    QC__TRY(length(k, "cy", QC__SVG_AXIS_Y, &cy, NULL));
    QC__TRY(length(k, "rx", QC__SVG_AXIS_X, &rx, &hrx));
    QC__TRY(length(k, "ry", QC__SVG_AXIS_Y, &ry, &hry));
    if (!hrx)
        rx = ry; /* SVG 2: auto takes the other radius */
    if (!hry)
        ry = rx;
    return ellipse(k, cx, cy, rx, ry);
}

static int line_el(walker *k)
{
    double c[4] = {0, 0, 0, 0};

    QC__TRY(length(k, "x1", QC__SVG_AXIS_X, &c[0], NULL));
    QC__TRY(length(k, "y1", QC__SVG_AXIS_Y, &c[1], NULL));
    QC__TRY(length(k, "x2", QC__SVG_AXIS_X, &c[2], NULL));
    QC__TRY(length(k, "y2", QC__SVG_AXIS_Y, &c[3], NULL));
    QC__TRY(move(k, c[0], c[1]));
    return line(k, c[2], c[3]);
}

static int poly(walker *k, int closed)
{
    const qc__xml_attr *a = qc__xml_attr_get(k->x, "points");
    const char *s;
    size_t n, i = 0, count = 0;
    double xy[2];
    qc_vec2 first = {0, 0}, last = {0, 0};

    if (a == NULL)
        return QC_OK;
    s = a->value;
    n = a->value_len;
    k->w.attr = "points";
    while (i < n && qc__is_space(s[i]))
        i++;
    while (i < n) {
        size_t at = i;

        if (!qc__scan_number(s, n, &i, &xy[count % 2]))
            return qc__svg_syntax(&k->w, s, n, at, "expected a number");
        QC__TRY(qc__svg_check_number(&k->w, xy[count % 2], s, n, at));
        if (count % 2 == 1) {
            last = QC__V2(xy[0], xy[1]);
            if (count == 1) {
                first = last;
                QC__TRY(move(k, xy[0], xy[1]));
            } else {
                QC__TRY(line(k, xy[0], xy[1]));
            }
            if (k->shape.npt > QC_MAX_POINTS)
                return qc__fail(k->ctx, QC_ELIMIT, "svg line %lu, <%s points>: more than %lu points",
                                k->w.line, k->w.elem, (unsigned long)QC_MAX_POINTS);
        }
        count++;
        if (qc__svg_skip_sep(s, n, &i) && i >= n)
            return qc__svg_syntax(&k->w, s, n, i, "expected a number after ','");
    }
    if (count % 2 == 1)
        return qc__svg_syntax(&k->w, s, n, n, "odd number of coordinates");
    if (count < 4) {
        k->shape.ncmd = k->shape.npt = 0; /* a single point draws nothing */
        return QC_OK;
    }
    if (closed && (last.x != first.x || last.y != first.y))
        QC__TRY(line(k, first.x, first.y));
    return QC_OK;
}

/* Builds the current shape element into k->shape (own user units);
 * *closed says whether it has an inside. */
static int build_shape(walker *k, int *closed)
{
    *closed = 1;
    if (name_is(k, "path")) {
        const qc__xml_attr *a = qc__xml_attr_get(k->x, "d");

        if (a == NULL)
            return QC_OK;
        k->w.attr = "d";
        return qc__svg_parse_path(&k->w, a->value, a->value_len, &k->shape);
    }
    if (name_is(k, "rect"))
        return rect(k);
    if (name_is(k, "circle"))
        return circle(k);
    if (name_is(k, "ellipse"))
        return ellipse_el(k);
    if (name_is(k, "polygon"))
        return poly(k, 1);
    *closed = 0;
    if (name_is(k, "polyline"))
        return poly(k, 0);
    return line_el(k);
}

static int is_shape(const walker *k)
{
    return name_is(k, "path") || name_is(k, "rect") || name_is(k, "circle") ||
           name_is(k, "ellipse") || name_is(k, "polygon") || name_is(k, "polyline") ||
           name_is(k, "line");
}

static int is_container(const walker *k)
{
    return name_is(k, "g") || name_is(k, "a") || name_is(k, "switch") || name_is(k, "svg");
}

/* An attribute by its qualified name (prefix included), or NULL. */
static const char *qualified_attr(const walker *k, const char *qname)
{
    size_t i, n = strlen(qname);

    for (i = 0; i < k->x->nattr; i++)
        if (k->x->attr[i].name_len == n && memcmp(k->x->attr[i].name, qname, n) == 0)
            return k->x->attr[i].value;
    return NULL;
}

static const char *attr_value(const walker *k, const char *name)
{
    const qc__xml_attr *a = qc__xml_attr_get(k->x, name);

    return a != NULL ? a->value : NULL;
}

static void warn_el(walker *k, const char *fmt, ...) QC__PRINTF(2, 3);

/* Maps the shape to mm, clips it to the clip in force and hands it over. */
static int emit(walker *k, const frame *f, int closed)
{
    const qc__svg_clip *clip = f->clip > 0 ? &k->clips[f->clip - 1] : NULL;
    qc__svg_elem el;
    size_t i;

    if (k->shape.ncmd == 0)
        return QC_OK;
    for (i = 0; i < k->shape.npt; i++) {
        qc_vec2 p = qc__svg_mat_apply(&f->m, k->shape.pt[i]);

        if (!isfinite(p.x) || !isfinite(p.y)) /* nested scales overflowed: no "(-nan, -nan)" */
            return qc__fail(k->ctx, QC_ERANGE,
                            "svg line %lu, <%s>: a point overflows after transforms (nested "
                            "scales beyond any size)", k->w.line, k->w.elem);
        if (!(fabs(p.x) <= QC__SVG_MAX_MM) || !(fabs(p.y) <= QC__SVG_MAX_MM))
            return qc__fail(k->ctx, QC_ERANGE,
                            "svg line %lu, <%s>: point (%g, %g) mm after transforms is "
                            "beyond %g mm",
                            k->w.line, k->w.elem, p.x, p.y, QC__SVG_MAX_MM);
        k->shape.pt[i] = p;
    }
    if (k->collecting) {
        k->nclip_shapes++;
        return qc_path_append(k->ctx, &k->clip_shapes, &k->shape, 0);
    }
    if (clip != NULL) {
        int where = qc__svg_clip_where(clip, &k->shape), done = 1;

        if (where < 0)
            return QC_OK; /* wholly clipped away */
        if (where == 0)
            QC__TRY(qc__svg_clip_cut(k->ctx, clip, &k->shape, &done));
        if (!done)
            warn_el(k, "its clip-path (or its group's) is not applied to a curved or concave "
                       "shape: read unclipped");
        if (k->shape.ncmd == 0)
            return QC_OK;
    }
    el.index = k->shapes;
    el.line = k->w.line;
    el.id = attr_value(k, "id");
    el.cls = attr_value(k, "class");
    el.label = qualified_attr(k, "inkscape:label");
    el.fill = f->fill;
    el.fill_rgb = f->fill_rgb;
    return k->fn(k->ud, &k->shape,
                 (closed ? QC__SVG_CLOSED : 0u) | (f->evenodd ? QC__SVG_EVENODD : 0u) |
                     (f->unfilled ? 0u : QC__SVG_FILLED) | (f->dashed ? QC__SVG_DASHED : 0u) |
                     (f->in_region ? QC__SVG_REGION_LAYER : 0u),
                 &el);
}

/* A warning about the current element: "svg line L, <path id="a">: ..."
 * (without an id, its number among the document's elements; in a clone,
 * the line of the <use> that made it). */
static void warn_el(walker *k, const char *fmt, ...)
{
    char what[200];
    const char *id = attr_value(k, "id");
    va_list ap;

    if (k->warn == NULL || k->warn->fn == NULL) {
        qc__svg_warn(k->warn, "%s", ""); /* counted all the same */
        return;
    }
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    if (k->use_depth > 0)
        qc__svg_warn(k->warn, "svg line %lu, <%s%s%.40s%s> (cloned by the <use> of line %lu): %s",
                     k->w.line, k->elem, id != NULL ? " id=\"" : "", id != NULL ? id : "",
                     id != NULL ? "\"" : "", k->use_line, what);
    else if (id != NULL)
        qc__svg_warn(k->warn, "svg line %lu, <%s id=\"%.40s\">: %s", k->w.line, k->elem, id, what);
    else
        qc__svg_warn(k->warn, "svg line %lu, <%s> (element %lu): %s", k->w.line, k->elem,
                     (unsigned long)k->elements, what);
}

/* Elements that draw something quiltc cannot sew from: said, not dropped silently. */
static const char *unread_kind(const walker *k)
{
    if (name_is(k, "text"))
        return "text is not read (convert it to a path: Inkscape's Path > Object to Path)";
    if (name_is(k, "image"))
        return "images are not read (trace them to paths)";
    if (name_is(k, "foreignObject"))
        return "foreign content is not read";
    return NULL;
}

/* The use's href (SVG 2's href, else xlink:href or any prefix's href). */
static const char *use_href(const walker *k)
{
    const qc__xml_attr *a = qc__xml_attr_get(k->x, "href");
    size_t i;

    if (a != NULL)
        return a->value;
    for (i = 0; i < k->x->nattr; i++) {
        const qc__xml_attr *b = &k->x->attr[i];

        if (b->name_len > 5 && memcmp(b->name + b->name_len - 5, ":href", 5) == 0)
            return b->value;
    }
    return NULL;
}

static int open_element(walker *k);

/* Walks the clone source src under base (the use's frame, x/y included). */
static int clone(walker *k, const frame *base, const qc__svg_id *src)
{
    size_t d = k->use_depth;
    qc__xml *saved_x = k->x;
    frame *saved_st = k->st;
    unsigned long saved_line = k->use_line;
    qc__xml *sx;
    int rc;

    if (k->sub_x[d] == NULL) {
        k->sub_x[d] = (qc__xml *)qc__alloc(k->ctx, sizeof *k->sub_x[d]);
        if (k->sub_x[d] == NULL)
            return qc__fail(k->ctx, QC_ENOMEM, "out of memory");
    }
    if (k->sub_st[d] == NULL) {
        k->sub_st[d] = (frame *)qc__alloc_array(k->ctx, QC__XML_MAX_DEPTH + 1, sizeof *k->st);
        if (k->sub_st[d] == NULL)
            return QC_ENOMEM;
    }
    sx = k->sub_x[d];
    rc = qc__xml_init_at(sx, k->ctx, k->doc.buf, k->doc.len, src->at, src->line, k->ix->ns,
                         k->ix->nns);
    if (rc == QC_OK) {
        k->sub_st[d][0] = *base;
        k->use_src[d] = src->at;
        if (d == 0)
            k->use_line = k->w.line;
        k->use_depth = d + 1;
        k->x = sx;
        k->st = k->sub_st[d];
        for (;;) {
            rc = qc__xml_next(sx);
            if (rc < 0)
                break;
            if (k->use_bytes + (sx->pos - src->at) > QC__SVG_USE_MAX_BYTES) {
                rc = qc__fail(k->ctx, QC_ELIMIT, "svg line %lu: <use> clones read more than %lu "
                              "MiB again (a budget against hostile files)", k->use_line,
                              (unsigned long)(QC__SVG_USE_MAX_BYTES >> 20));
                break;
            }
            if (rc == QC__XML_OPEN) {
                if (++k->use_elements > QC__SVG_USE_MAX_ELEMENTS) {
                    rc = qc__fail(k->ctx, QC_ELIMIT, "svg line %lu: <use> clones hold more than "
                                  "%d elements (a budget against hostile files)", k->use_line,
                                  QC__SVG_USE_MAX_ELEMENTS);
                    break;
                }
                rc = open_element(k);
                if (rc < 0)
                    break;
            } else if (rc == QC__XML_DONE || sx->depth == 0) {
                rc = QC_OK;
                break;
            }
        }
        k->use_bytes += sx->pos - src->at;
    }
    qc__xml_free(sx);
    k->x = saved_x;
    k->st = saved_st;
    k->use_depth = d;
    k->use_line = saved_line;
    return rc;
}

/* A <use>: its source drawn again under the use's frame. */
static int use_element(walker *k, const frame *f)
{
    const char *href = use_href(k);
    const qc__svg_id *src;
    frame base = *f;
    double x = 0, y = 0;
    qc__svg_mat t = qc__svg_mat_identity();
    size_t i;

    if (href == NULL) {
        warn_el(k, "<use> without href draws nothing");
        return QC_OK;
    }
    while (*href != '\0' && qc__is_space(*href))
        href++;
    if (href[0] != '#') {
        warn_el(k, "href \"%.60s\" is not in this file: the clone is left out", href);
        return QC_OK;
    }
    src = qc__svg_index_find(k->ix, href + 1, strlen(href + 1));
    if (src == NULL) {
        warn_el(k, "href \"%.60s\" names no element: the clone is left out", href);
        return QC_OK;
    }
    if (k->use_depth >= QC__SVG_USE_MAX_DEPTH)
        return qc__fail(k->ctx, QC_ELIMIT, "svg line %lu: <use> clones nested more than %d deep "
                        "(a budget against hostile files)", k->w.line, QC__SVG_USE_MAX_DEPTH);
    for (i = 0; i < k->use_depth; i++)
        if (k->use_src[i] == src->at)
            return qc__fail(k->ctx, QC_EFORMAT, "svg line %lu: <use> href \"%.60s\" clones an "
                            "element that contains the use (a reference cycle)", k->w.line, href);
    if (++k->use_count > QC__SVG_USE_MAX_COUNT)
        return qc__fail(k->ctx, QC_ELIMIT, "svg line %lu: more than %d <use> clones (a budget "
                        "against hostile files)", k->w.line, QC__SVG_USE_MAX_COUNT);
    QC__TRY(length(k, "x", QC__SVG_AXIS_X, &x, NULL));
    QC__TRY(length(k, "y", QC__SVG_AXIS_Y, &y, NULL));
    t.e = x;
    t.f = y;
    base.m = qc__svg_mat_mul(f->m, t);
    base.skip = 0;
    k->use_sized[k->use_depth] = qc__xml_attr_get(k->x, "width") != NULL ||
                                 qc__xml_attr_get(k->x, "height") != NULL;
    return clone(k, &base, src);
}

/* The fragment of a url(#id) reference ("url(#c)", quotes allowed): 1 and *id. */
static int url_fragment(const char *v, size_t n, const char **id, size_t *len)
{
    size_t i, e;

    if (n < 6 || memcmp(v, "url(", 4) != 0 || v[n - 1] != ')')
        return 0;
    i = 4;
    e = n - 1;
    while (i < e && (qc__is_space(v[i]) || v[i] == '"' || v[i] == '\''))
        i++;
    while (e > i && (qc__is_space(v[e - 1]) || v[e - 1] == '"' || v[e - 1] == '\''))
        e--;
    if (e - i < 2 || v[i] != '#')
        return 0;
    *id = v + i + 1;
    *len = e - i - 1;
    return 1;
}

/* Reads the clipPath that clip-path v[0..vn) names into k->clip, in the
 * frame f of the clipped shape (userSpaceOnUse): *ok when it can be applied
 * exactly; otherwise a warning and the shape is read unclipped. */
static int collect_clip(walker *k, const frame *f, const char *v, size_t vn, int *ok)
{
    const qc__svg_id *src = NULL;
    const char *id;
    size_t idn, i;
    frame base = *f;
    char elem[sizeof k->elem];
    qc__svg_where w = k->w;
    qc__css_match css = k->css;
    int rc, cycle = 0;

    *ok = 0;
    if (url_fragment(v, vn, &id, &idn))
        src = qc__svg_index_find(k->ix, id, idn);
    for (i = 0; src != NULL && i < k->use_depth; i++)
        cycle |= k->use_src[i] == src->at;
    if (src == NULL || cycle || k->use_depth >= QC__SVG_USE_MAX_DEPTH) {
        warn_el(k, "clip-path %.*s is not applied (%s): read unclipped", (int)(vn > 60 ? 60 : vn),
                v, src == NULL ? "it names no element" : "clips nested too deep");
        return QC_OK;
    }
    if (++k->use_count > QC__SVG_USE_MAX_COUNT)
        return qc__fail(k->ctx, QC_ELIMIT, "svg line %lu: more than %d <use> clones and clip "
                        "paths (a budget against hostile files)", k->w.line, QC__SVG_USE_MAX_COUNT);
    memcpy(elem, k->elem, sizeof elem);
    base.skip = 0;
    base.hidden = 0;
    base.clip = 0; /* the clip's own shapes are not clipped */
    k->clip_shapes.ncmd = k->clip_shapes.npt = 0;
    k->nclip_shapes = 0;
    k->collecting++;
    k->collect_depth = k->use_depth + 1;
    rc = clone(k, &base, src);
    k->collecting--;
    memcpy(k->elem, elem, sizeof elem);
    k->w = w;
    k->css = css;
    QC__TRY(rc);
    QC__TRY(qc__svg_clip_make(k->ctx, &k->clip_shapes, k->nclip_shapes, &k->clip, ok));
    if (!*ok)
        warn_el(k, "clip-path %.*s is not applied (only a clip of one convex shape with straight "
                   "edges is): read unclipped", (int)(vn > 60 ? 60 : vn), v);
    return QC_OK;
}

/* Drops the clips of elements that have closed: those set at a deeper
 * clone level, or at this level at depth d or deeper. */
static void pop_clips(walker *k, size_t d)
{
    while (k->nclips > 0) {
        const qc__svg_clip *c = &k->clips[k->nclips - 1];

        if (c->level < k->use_depth || (c->level == k->use_depth && c->depth < d))
            break;
        k->nclips--;
    }
}

/* The element's clip-path v[0..vn): where it can be applied exactly, the
 * clip in force becomes it (within the inherited one) for the element and
 * its descendants. */
static int push_clip(walker *k, frame *f, size_t d, const char *v, size_t vn)
{
    qc__svg_clip *e;
    int ok;

    QC__TRY(collect_clip(k, f, v, vn, &ok));
    if (!ok)
        return QC_OK;
    if (k->nclips == k->clips_hw) {
        QC__TRY(QC__RESERVE(k->ctx, k->clips, k->clips_cap, k->clips_hw + 1));
        memset(&k->clips[k->clips_hw++], 0, sizeof *k->clips);
    }
    e = &k->clips[k->nclips];
    if (f->clip > 0) {
        QC__TRY(qc__svg_clip_meet(k->ctx, &k->clip, &k->clips[f->clip - 1], e));
    } else {
        QC__TRY(QC__RESERVE(k->ctx, e->v, e->cap, k->clip.n));
        memcpy(e->v, k->clip.v, k->clip.n * sizeof *e->v);
        e->n = k->clip.n;
        e->sign = k->clip.sign;
    }
    e->level = k->use_depth;
    e->depth = d;
    f->clip = ++k->nclips;
    return QC_OK;
}

/* Style the element inherits or sets: fill, fill-rule, dashes, visibility. */
static void inherit_style(walker *k, frame *f)
{
    const char *v;
    size_t vn;

    if (property(k, QC__CSS_FILL_RULE, &v, &vn)) {
        if (value_is(v, vn, "evenodd"))
            f->evenodd = 1;
        else if (value_is(v, vn, "nonzero"))
            f->evenodd = 0;
    }
    if (property(k, QC__CSS_FILL, &v, &vn) && !value_is(v, vn, "inherit")) {
        f->unfilled = value_is(v, vn, "none");
        f->fill_rgb = qc__svg_color(v, vn, &f->fill);
    }
    if (property(k, QC__CSS_DASHARRAY, &v, &vn) && !value_is(v, vn, "inherit"))
        f->dashed = !value_is(v, vn, "none");
    if (property(k, QC__CSS_VISIBILITY, &v, &vn)) {
        if (value_is(v, vn, "hidden") || value_is(v, vn, "collapse"))
            f->hidden = 1;
        else if (value_is(v, vn, "visible"))
            f->hidden = 0;
    }
}

/* clip-path and mask are not applied: the element is read whole, and said so. */
static void warn_unapplied(walker *k, const frame *f)
{
    static const int props[2] = {QC__CSS_CLIP_PATH, QC__CSS_MASK};
    size_t i;

    for (i = 0; i < 2; i++) {
        const char *v;
        size_t vn;

        if (i == 0 && !k->collecting)
            continue; /* applied where exact, else warned about, by push_clip and emit */
        if (property(k, props[i], &v, &vn) && vn > 0 && !value_is(v, vn, "none") &&
            !value_is(v, vn, "inherit") && !f->hidden)
            warn_el(k, "%s %.*s is not applied: read unclipped", qc__css_prop_name[props[i]],
                    (int)(vn > 60 ? 60 : vn), v);
    }
}

/* The root <svg>: in the SVG namespace; SVG's initial style; the viewport. */
static int open_root(walker *k, frame *f)
{
    if (!k->x->svg && name_is(k, "svg"))
        return qc__fail(k->ctx, QC_EFORMAT, "svg line %lu: the root element <svg> is not in "
                        "the SVG namespace (xmlns=\"http://www.w3.org/2000/svg\")", k->w.line);
    if (!k->x->svg || !name_is(k, "svg"))
        return qc__fail(k->ctx, QC_EFORMAT, "svg line %lu: the root element is <%.*s>, not <svg>",
                        k->w.line, (int)(k->x->name_len > 40 ? 40 : k->x->name_len), k->x->name);
    f->skip = 0;
    f->evenodd = 0;
    f->unfilled = 0;
    f->dashed = 0;
    f->in_region = 0;
    f->hidden = 0;
    f->clip = 0;
    f->fill_rgb = 1; /* SVG's initial fill is black */
    f->fill = 0;
    return qc__svg_root_viewport(&k->w, k->x, &f->m, &k->vp_w, &k->vp_h);
}

/* Whether the element (not the root) draws nothing, with its subtree:
 * under a skipped parent, foreign, not a kind that draws, or a clip
 * source that is not a usable clipPath. */
static int not_drawn(const walker *k, const frame *parent, int source, int clip_source)
{
    if (parent->skip || !k->x->svg)
        return 1;
    if (clip_source)
        return !name_is(k, "clipPath") || value_is_attr(k, "clipPathUnits", "objectBoundingBox");
    return !(is_container(k) || is_shape(k) || name_is(k, "use") ||
             (source && name_is(k, "symbol")));
}

/* A visible element quiltc does not read (text, image) is worth a warning. */
static void warn_unread(walker *k, frame *f, const frame *parent, size_t ln)
{
    const char *v;
    size_t vn;

    if (parent->skip || !k->x->svg || unread_kind(k) == NULL)
        return;
    qc__css_match_element(&k->ix->css, k->elem, ln, attr_value(k, "id"), attr_value(k, "class"),
                          &k->css);
    inherit_style(k, f);
    if (!(property(k, QC__CSS_DISPLAY, &v, &vn) && value_is(v, vn, "none")) && !f->hidden)
        warn_el(k, "%s", unread_kind(k));
}

/* A drawn element's own coordinates: transform, or a nested viewport. */
static int enter_element(walker *k, frame *f, int source)
{
    const qc__xml_attr *t = qc__xml_attr_get(k->x, "transform");
    qc__svg_mat local;

    if (name_is(k, "svg") || name_is(k, "symbol")) {
        if (source && k->use_sized[k->use_depth - 1])
            warn_el(k, "the <use>'s width and height are not applied: the %s keeps its own "
                       "size", k->elem);
        QC__TRY(qc__svg_nested_viewport(&k->w, k->x, k->vp_w, k->vp_h, &local));
        f->m = qc__svg_mat_mul(f->m, local);
    } else if (t != NULL) {
        QC__TRY(transform(k, t->value, t->value_len, &local));
        f->m = qc__svg_mat_mul(f->m, local);
    }
    return QC_OK;
}

/* Style, layers and clip of a drawn element; 1 in *gone when display:none. */
static int style_element(walker *k, frame *f, size_t d, size_t ln, int *gone)
{
    const qc__xml_attr *id = qc__xml_attr_get(k->x, "id");
    const char *v;
    size_t vn;

    qc__css_match_element(&k->ix->css, k->elem, ln, attr_value(k, "id"), attr_value(k, "class"),
                          &k->css);
    *gone = property(k, QC__CSS_DISPLAY, &v, &vn) && value_is(v, vn, "none");
    if (*gone) {
        f->skip = 1;
        return QC_OK;
    }
    inherit_style(k, f);
    if (id != NULL && (value_is(id->value, id->value_len, "region") ||
                       value_is(id->value, id->value_len, "ditch")))
        f->in_region = 1;
    warn_unapplied(k, f);
    if (!k->collecting && !(is_shape(k) && f->hidden) &&
        property(k, QC__CSS_CLIP_PATH, &v, &vn) && vn > 0 && !value_is(v, vn, "none") &&
        !value_is(v, vn, "inherit"))
        QC__TRY(push_clip(k, f, d, v, vn));
    return QC_OK;
}

static int open_element(walker *k)
{
    size_t d = k->x->depth;
    frame *f = &k->st[d];
    const frame *parent = &k->st[d - 1];
    size_t ln = k->x->local_len < sizeof k->elem - 1 ? k->x->local_len : sizeof k->elem - 1;
    int closed, gone;
    int source = d == 1 && k->use_depth > 0; /* a clone's source element */
    int clip_source = source && k->collecting && k->use_depth == k->collect_depth;

    pop_clips(k, d);
    memcpy(k->elem, k->x->local, ln);
    k->elem[ln] = '\0';
    k->w.line = qc__xml_line_at(k->x, k->x->at);
    k->w.elem = k->elem;
    k->w.attr = "";
    k->w.x = k->x;
    if (k->use_depth == 0)
        k->elements++;
    *f = *parent;
    k->css.n = 0;
    if (d == 1 && k->use_depth == 0) {
        QC__TRY(open_root(k, f));
    } else if (not_drawn(k, parent, source, clip_source)) {
        f->skip = 1;
        warn_unread(k, f, parent, ln);
        return QC_OK;
    } else {
        QC__TRY(enter_element(k, f, source));
    }
    QC__TRY(style_element(k, f, d, ln, &gone));
    if (gone)
        return QC_OK;
    if (name_is(k, "use")) {
        f->skip = 1; /* a use's children draw nothing; its source does */
        return use_element(k, f);
    }
    if (!is_shape(k))
        return QC_OK;
    f->skip = 1; /* children of a shape draw nothing */
    if (!k->collecting)
        k->shapes++;
    if (f->hidden)
        return QC_OK;
    k->shape.ncmd = k->shape.npt = 0;
    QC__TRY(build_shape(k, &closed));
    return emit(k, f, closed);
}

int qc__svg_walk(qc_ctx *ctx, const char *buf, size_t len, qc__svg_warner *warn,
                 qc__svg_shape_fn fn, void *ud)
{
    walker k;
    qc__svg_index ix;
    size_t i;
    int rc;

    memset(&k, 0, sizeof k);
    k.ctx = ctx;
    k.fn = fn;
    k.ud = ud;
    k.w.ctx = ctx;
    k.warn = warn;
    QC__TRY(qc__svg_index_build(&ix, ctx, buf, len, warn));
    k.ix = &ix;
    k.doc_st = (frame *)qc__alloc_array(ctx, QC__XML_MAX_DEPTH + 1, sizeof *k.doc_st);
    if (k.doc_st == NULL) {
        qc__svg_index_free(&ix);
        return QC_ENOMEM;
    }
    k.st = k.doc_st;
    k.x = &k.doc;
    k.w.x = &k.doc;
    k.st[0].m = qc__svg_mat_identity();
    qc__xml_init(&k.doc, ctx, buf, len);
    for (;;) {
        rc = qc__xml_next(&k.doc);
        if (rc < 0 || rc == QC__XML_DONE)
            break;
        if (rc == QC__XML_OPEN) {
            rc = open_element(&k);
            if (rc < 0)
                break;
        }
    }
    qc__xml_free(&k.doc);
    qc_path_free(ctx, &k.shape);
    qc__free(ctx, k.doc_st, (QC__XML_MAX_DEPTH + 1) * sizeof *k.doc_st);
    for (i = 0; i < QC__SVG_USE_MAX_DEPTH; i++) {
        qc__free(ctx, k.sub_x[i], sizeof *k.sub_x[i]);
        qc__free(ctx, k.sub_st[i], (QC__XML_MAX_DEPTH + 1) * sizeof *k.sub_st[i]);
    }
    qc__svg_index_free(&ix);
    qc_path_free(ctx, &k.clip_shapes);
    qc__svg_clip_free(ctx, &k.clip);
    for (i = 0; i < k.clips_hw; i++)
        qc__svg_clip_free(ctx, &k.clips[i]);
    qc__free(ctx, k.clips, k.clips_cap * sizeof *k.clips);
    if (rc >= 0)
        qc__svg_warn_done(warn);
    return rc;
}
