/*
 * Internals of the SVG reader: a strict XML tokenizer (svg_xml.c), numbers,
 * path data and arcs (svg_path.c), lengths, units and the root viewport
 * (svg_units.c), and the document walk that turns elements into shapes
 * (svg_shapes.c). read_svg.c holds the two public readers.
 */
#ifndef QC_SVG_INTERNAL_H
#define QC_SVG_INTERNAL_H

#include "io_internal.h"

/* ---- XML tokenizer ---- */

#define QC__XML_MAX_DEPTH 256 /* deeper nesting is QC_ELIMIT */
#define QC__XML_MAX_ATTRS 256 /* attributes per element */
#define QC__XML_MAX_NS 128    /* namespace declarations in scope */

typedef struct qc__xml_attr {
    const char *name;  /* qualified name, in the document (not NUL-terminated) */
    size_t name_len;
    const char *value; /* entity-decoded, NUL-terminated, in the tokenizer's text buffer */
    size_t value_len;
    size_t at;         /* byte offset of the value's first character */
    size_t raw_len;    /* bytes of the value in the document (entities undecoded) */
} qc__xml_attr;

typedef struct qc__xml_ns {
    const char *prefix; /* NULL (len 0) for the default namespace */
    size_t prefix_len;
    size_t depth;       /* element depth that declared it */
    int svg;            /* bound to the SVG namespace */
} qc__xml_ns;

typedef struct qc__xml_open {
    const char *name;
    size_t len, at;
} qc__xml_open;

typedef struct qc__xml {
    qc_ctx *ctx;
    const char *buf;
    size_t len, pos;
    size_t depth;                /* elements open */
    qc__xml_open open[QC__XML_MAX_DEPTH];
    int started, root_seen, root_done, close_pending;
    /* the current element (after QC__XML_OPEN or QC__XML_CLOSE) */
    const char *name;            /* qualified name, not NUL-terminated */
    size_t name_len, at;         /* at: byte offset of its '<' */
    const char *local;           /* local part of the name */
    size_t local_len;
    int svg;                     /* in the SVG namespace */
    qc__xml_attr *attr;
    size_t nattr, attr_cap;
    char *text;                  /* decoded attribute values */
    size_t text_len, text_cap;
    qc__xml_ns *ns;
    size_t nns, ns_cap;
    size_t line_pos;             /* qc__xml_line_at's cache: line_no at line_pos */
    unsigned long line_no;
} qc__xml;

enum { QC__XML_DONE = 0, QC__XML_OPEN = 1, QC__XML_CLOSE = 2 };

QC__HIDDEN void qc__xml_init(qc__xml *x, qc_ctx *ctx, const char *buf, size_t len);
/* A tokenizer over the element starting at byte at of the same buffer
 * (a <use>'s source): the root's namespace bindings ns[0..nns) stay in
 * scope, line is the line of byte at; its walk ends when that element
 * closes (depth back to 0). */
QC__HIDDEN int qc__xml_init_at(qc__xml *x, qc_ctx *ctx, const char *buf, size_t len, size_t at,
                               unsigned long line, const qc__xml_ns *ns, size_t nns);
QC__HIDDEN void qc__xml_free(qc__xml *x);
/* The next event: QC__XML_OPEN (x->name, x->attr valid; x->depth counts
 * it), QC__XML_CLOSE (x->name; a self-closing element gets OPEN then
 * CLOSE), QC__XML_DONE after the root element closed and only comments,
 * processing instructions and white space followed; or QC_EFORMAT,
 * QC_ELIMIT, QC_ENOMEM. */
QC__HIDDEN int qc__xml_next(qc__xml *x);
/* 1-based line number of byte offset at (counts from the start: for errors). */
QC__HIDDEN unsigned long qc__xml_line(const qc__xml *x, size_t at);
/* The same, counting on from the previous call when at has not gone back,
 * so asking for every element in document order stays linear. */
QC__HIDDEN unsigned long qc__xml_line_at(qc__xml *x, size_t at);
/* The unprefixed attribute name of the current element, or NULL. */
QC__HIDDEN const qc__xml_attr *qc__xml_attr_get(const qc__xml *x, const char *name);

/* ---- numbers, affine matrices, error locations ---- */

#define QC__SVG_MAX_NUMBER 1e7   /* |user units| beyond are QC_ERANGE */
#define QC__SVG_MAX_MM 1e6       /* final coordinates, as qc_region_normalize */
#define QC__SVG_PX_MM (25.4 / 96.0)

/* x' = a x + c y + e, y' = b x + d y + f (SVG's matrix(a b c d e f)). */
typedef struct qc__svg_mat {
    double a, b, c, d, e, f;
} qc__svg_mat;

QC__HIDDEN qc__svg_mat qc__svg_mat_identity(void);
/* l then r applied to a point is l(r(p)): SVG's "l r" transform list. */
QC__HIDDEN qc__svg_mat qc__svg_mat_mul(qc__svg_mat l, qc__svg_mat r);
QC__HIDDEN qc_vec2 qc__svg_mat_apply(const qc__svg_mat *m, qc_vec2 p);

/* Where a value came from, for error messages: "svg line 12, <path d>". */
typedef struct qc__svg_where {
    qc_ctx *ctx;
    const qc__xml *x; /* when set, messages name the document byte too */
    unsigned long line;
    const char *elem; /* element local name, NUL-terminated */
    const char *attr; /* attribute name */
} qc__svg_where;

/* SVG numbers are read by qc__scan_number (src/core/number.c); the value
 * may be huge or inf: see qc__svg_check_number. */
/* QC_OK, or QC_ERANGE when |v| > QC__SVG_MAX_NUMBER (or inf), naming w and
 * the characters at s[at..). */
QC__HIDDEN int qc__svg_check_number(const qc__svg_where *w, double v, const char *s,
                                    size_t n, size_t at);
/* QC_EFORMAT: "svg line L, <elem attr> char K: what, found "text"" */
QC__HIDDEN int qc__svg_syntax(const qc__svg_where *w, const char *s, size_t n, size_t at,
                              const char *what);
/* Skips white space and at most one comma (SVG comma-wsp); returns 1 when
 * a comma was skipped. */
QC__HIDDEN int qc__svg_skip_sep(const char *s, size_t n, size_t *pos);

/* ---- path data (svg_path.c) ---- */

/* Appends the path data d[0..n) to *out in the element's own user units:
 * one MOVE per subpath that draws something, LINE and CUBIC (quadratics
 * and arcs become cubics), Z as a LINE back to the start unless already
 * there. Errors: QC_EFORMAT naming the character and text, QC_ERANGE. */
QC__HIDDEN int qc__svg_parse_path(const qc__svg_where *w, const char *d, size_t n,
                                  qc_path *out);
/* Appends the elliptical arc from p0 to p1 (SVG's A parameters, phi in
 * degrees) as at most 4 cubics per full turn; a zero radius is a line,
 * p0 == p1 nothing. */
QC__HIDDEN int qc__svg_arc_to(qc_ctx *ctx, qc_path *out, qc_vec2 p0, double rx, double ry,
                              double phi_deg, int large, int sweep, qc_vec2 p1);
/* sin and cos of an angle in degrees, exact at multiples of 90. */
QC__HIDDEN void qc__svg_sincos_deg(double deg, double *s, double *c);

/* ---- lengths and the viewport (svg_units.c) ---- */

enum { QC__SVG_AXIS_X, QC__SVG_AXIS_Y, QC__SVG_AXIS_OTHER };

/* A <length> attribute in user units: a number with an optional unit (px,
 * mm, cm, in, pt, pc, or % of the viewport size vp_w/vp_h along axis).
 * Errors: QC_EFORMAT (unknown unit, trailing text), QC_ERANGE. */
QC__HIDDEN int qc__svg_length(const qc__svg_where *w, const char *s, size_t n, int axis,
                              double vp_w, double vp_h, double *out);

/* The root <svg>'s mapping from its user units to mm, y up: width/height
 * (units; absent or % means the viewBox size in px) and viewBox with
 * preserveAspectRatio (default xMidYMid meet); then y_mm' = H - y_mm where
 * H is the document height in mm (0 when neither height nor viewBox is
 * given, so y is simply negated). vp_w/vp_h receive the viewport in user
 * units (for % lengths). */
QC__HIDDEN int qc__svg_root_viewport(const qc__svg_where *w, const qc__xml *x,
                                     qc__svg_mat *m, double *vp_w, double *vp_h);
/* A nested <svg>: translate(x, y), then its viewBox into width/height. */
QC__HIDDEN int qc__svg_nested_viewport(const qc__svg_where *w, const qc__xml *x,
                                       double vp_w, double vp_h, qc__svg_mat *m);

/* ---- warnings (svg_index.c) ---- */

#define QC__SVG_MAX_WARNINGS 50 /* then only counted */

typedef struct qc__svg_warner {
    qc_warn_fn fn; /* NULL: dropped */
    void *ud;
    size_t count;  /* warnings so far, shown or not */
} qc__svg_warner;

/* Formats one warning (one line) and hands it to w->fn, the first
 * QC__SVG_MAX_WARNINGS times. */
QC__HIDDEN void qc__svg_warn(qc__svg_warner *w, const char *fmt, ...) QC__PRINTF(2, 3);
/* After the walk: "N more warnings not shown" when some were held back. */
QC__HIDDEN void qc__svg_warn_done(qc__svg_warner *w);

/* ---- CSS style sheets (svg_css.c) ---- */

/* The properties the reader looks up. */
enum {
    QC__CSS_FILL,
    QC__CSS_FILL_RULE,
    QC__CSS_DASHARRAY,
    QC__CSS_DISPLAY,
    QC__CSS_VISIBILITY,
    QC__CSS_CLIP_PATH,
    QC__CSS_MASK,
    QC__CSS_NPROPS
};
QC__HIDDEN extern const char *const qc__css_prop_name[QC__CSS_NPROPS];

#define QC__CSS_MAX_RULES 10000 /* selectors kept; more are warned about */
#define QC__CSS_MAX_MATCH 32    /* rules applying to one element (the last ones) */

typedef struct qc__css_rule {
    char kind;          /* '*', '.' (class), '#' (id), 't' (element type) */
    const char *name;   /* in the sheet's text; "" for '*' */
    size_t name_len;
    unsigned spec;      /* specificity: id 100, class 10, type 1, * 0 */
    size_t order;       /* position in the sheets: later wins a tie */
    unsigned has;       /* bit p: the rule declares property p */
    const char *val[QC__CSS_NPROPS];
    size_t val_len[QC__CSS_NPROPS];
} qc__css_rule;

typedef struct qc__css_chunk {
    size_t start, end;  /* in text */
    unsigned long line; /* of its <style> */
} qc__css_chunk;

/* The document's <style> sheets: their text (comments and CDATA marks
 * blanked), then rules sorted by selector for lookup. */
typedef struct qc__css {
    qc_ctx *ctx;
    char *text;
    size_t text_len, text_cap;
    qc__css_chunk *chunk;
    size_t nchunk, chunk_cap;
    qc__css_rule *rule;
    size_t n, cap;
} qc__css;

typedef struct qc__css_match {
    const qc__css_rule *r[QC__CSS_MAX_MATCH];
    size_t n;
} qc__css_match;

/* Appends a <style> element's text s[0..n) (line: the element's). */
QC__HIDDEN int qc__css_add(qc__css *c, const char *s, size_t n, unsigned long line);
/* Parses every sheet added into rules; what it cannot honour (at-rules,
 * combinators, attribute selectors, pseudo-classes) is warned about. */
QC__HIDDEN int qc__css_parse(qc__css *c, qc__svg_warner *warn);
QC__HIDDEN void qc__css_free(qc__css *c);
/* The rules that select an element of local name type, id and class list
 * (either may be NULL). */
QC__HIDDEN void qc__css_match_element(const qc__css *c, const char *type, size_t type_len,
                                      const char *id, const char *cls, qc__css_match *m);
/* The cascaded value of property p among the matched rules: 1 and *val. */
QC__HIDDEN int qc__css_get(const qc__css_match *m, int p, const char **val, size_t *vlen);
/* Drops white space (newlines too) from both ends of s[0..n). */
QC__HIDDEN void qc__svg_trim(const char **s, size_t *n);
/* The last declaration of prop in a declaration list ("a:b; c:d"), value
 * trimmed and without !important: 1 and *val. */
QC__HIDDEN int qc__css_decl(const char *s, size_t n, const char *prop, const char **val,
                            size_t *vlen);

/* ---- the document index (svg_index.c) ---- */

typedef struct qc__svg_id {
    const char *id; /* in the document (ids with entity references are not indexed) */
    size_t len;
    size_t at;      /* byte offset of the element's '<' */
    unsigned long line;
} qc__svg_id;

/* One pass over the document before the walk: every element's id (for
 * <use>), the <style> sheets and the root's namespace bindings. */
typedef struct qc__svg_index {
    qc_ctx *ctx;
    qc__svg_id *ids;
    size_t nids, ids_cap;
    size_t *slot;       /* open addressing: 1 + index into ids, 0 empty */
    size_t nslot;       /* a power of two, or 0 */
    qc__css css;
    qc__xml_ns *ns;     /* the root element's bindings */
    size_t nns;
} qc__svg_index;

/* Builds the index; a malformed document is indexed up to the fault (the
 * walk reports it). Errors: QC_ENOMEM. */
QC__HIDDEN int qc__svg_index_build(qc__svg_index *ix, qc_ctx *ctx, const char *buf, size_t len,
                                   qc__svg_warner *warn);
QC__HIDDEN void qc__svg_index_free(qc__svg_index *ix);
/* The element whose id is id[0..n), or NULL (the first of duplicates). */
QC__HIDDEN const qc__svg_id *qc__svg_index_find(const qc__svg_index *ix, const char *id,
                                                size_t n);

/* ---- clip-path where exact (svg_clip.c) ---- */

typedef struct qc__svg_clip {
    qc_vec2 *v;      /* a convex polygon, mm, no closing repeat; n = 0: empty */
    size_t n, cap;
    int sign;        /* +1 counter-clockwise, -1 clockwise */
    size_t level, depth; /* the element that set it: clone level and depth */
} qc__svg_clip;

/* From a clipPath's shapes (nshapes of them, in mm): *ok when they are one
 * closed convex polygon of straight edges. Errors: QC_ENOMEM. */
QC__HIDDEN int qc__svg_clip_make(qc_ctx *ctx, const qc_path *shapes, size_t nshapes,
                                 qc__svg_clip *c, int *ok);
QC__HIDDEN void qc__svg_clip_free(qc_ctx *ctx, qc__svg_clip *c);
/* 1 when every point of shape (control points too) is inside c or on its
 * edge, -1 when all lie beyond one edge, 0 when it crosses. */
QC__HIDDEN int qc__svg_clip_where(const qc__svg_clip *c, const qc_path *shape);
/* Cuts shape to c when it is one closed convex polygon (*done; an empty
 * result empties shape); otherwise leaves it and *done = 0. */
QC__HIDDEN int qc__svg_clip_cut(qc_ctx *ctx, const qc__svg_clip *c, qc_path *shape, int *done);
/* out = a inside b (convex; n = 0 when they do not meet: an empty clip). */
QC__HIDDEN int qc__svg_clip_meet(qc_ctx *ctx, const qc__svg_clip *a, const qc__svg_clip *b,
                                 qc__svg_clip *out);

/* ---- document walk (svg_shapes.c) ---- */

/* Budget of <use> clones against hostile files (a "billion laughs" of
 * nested uses): beyond any of them the document is QC_ELIMIT. */
#define QC__SVG_USE_MAX_DEPTH 10            /* clones of clones */
#define QC__SVG_USE_MAX_COUNT 20000         /* clones made */
#define QC__SVG_USE_MAX_ELEMENTS 500000     /* elements read again for clones */
#define QC__SVG_USE_MAX_BYTES ((size_t)64 << 20) /* bytes read again for clones */

/* How a shape is drawn: it has an inside (path, rect, circle, ellipse,
 * polygon; not polyline, line), its fill-rule is evenodd, its fill is not
 * none, its stroke is dashed, it lies in the element with id="region"
 * (fill, fill-rule and stroke-dasharray are inherited; style wins over
 * attributes). */
enum {
    QC__SVG_CLOSED = 1,
    QC__SVG_EVENODD = 2,
    QC__SVG_FILLED = 4,
    QC__SVG_DASHED = 8,
    QC__SVG_REGION_LAYER = 16
};

/* The element a shape comes from, for naming it: valid during the callback. */
typedef struct qc__svg_elem {
    size_t index;        /* shape elements in document order, 1-based */
    unsigned long line;  /* of its '<' */
    const char *id, *cls, *label; /* id, class, inkscape:label; NULL when absent */
    uint32_t fill;       /* 0xRRGGBB when fill_rgb (inherited like fill) */
    int fill_rgb;        /* the fill is a colour quiltc understood */
} qc__svg_elem;

/* Receives each shape in document order: its path in mm, y up (already
 * transformed, coordinates checked), its QC__SVG_* flags and its element.
 * A negative return stops the walk. */
typedef int (*qc__svg_shape_fn)(void *ud, const qc_path *shape, unsigned flags,
                                const qc__svg_elem *el);

/* Reads the document as qc_io_read_svg_region does, but hands each shape's
 * kept rings (in mm, y up, not normalized) to fn with the shape's element;
 * the rings are only valid during the call. Errors: the reader's, or fn's. */
typedef int (*qc__svg_rings_fn)(void *ud, const qc_region *rings, const qc__svg_elem *el);
QC__HIDDEN int qc__svg_walk_rings(qc_ctx *ctx, const char *buf, size_t len,
                                  const qc_svg_opts *opts, qc__svg_rings_fn fn, void *ud);

/* A CSS colour: #rgb, #rrggbb, rgb(r, g, b) (numbers or %) or one of the
 * 16 basic names plus orange; 1 and *rgb (0xRRGGBB) when understood. */
QC__HIDDEN int qc__svg_color(const char *s, size_t n, uint32_t *rgb);

/* Parses the document and hands every visible shape to fn. Errors: those
 * of the tokenizer and parsers, QC_ERANGE for a coordinate beyond 1e6 mm
 * after transforms, or fn's. */
QC__HIDDEN int qc__svg_walk(qc_ctx *ctx, const char *buf, size_t len,
                            qc__svg_warner *warn, qc__svg_shape_fn fn, void *ud);

#endif
