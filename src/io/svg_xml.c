/*
 * A small strict XML tokenizer for SVG documents: elements, attributes in
 * ' or " quotes, the five predefined entities and character references,
 * comments, CDATA, processing instructions and a DOCTYPE that is skipped.
 * Nothing is expanded: a DOCTYPE declaring entities is refused (no billion
 * laughs), an undeclared entity is an error. Iterative, with a fixed stack
 * of QC__XML_MAX_DEPTH open elements. Namespace prefixes are resolved
 * enough to tell SVG elements from foreign ones (sodipodi:namedview).
 */
#include <string.h>

#include "svg_internal.h"

#define SVG_NS "http://www.w3.org/2000/svg"

void qc__xml_init(qc__xml *x, qc_ctx *ctx, const char *buf, size_t len)
{
    memset(x, 0, sizeof *x);
    x->ctx = ctx;
    x->buf = buf;
    x->len = len;
}

int qc__xml_init_at(qc__xml *x, qc_ctx *ctx, const char *buf, size_t len, size_t at,
                    unsigned long line, const qc__xml_ns *ns, size_t nns)
{
    qc__xml_init(x, ctx, buf, len);
    x->started = 1; /* the document's bytes were checked by its own walk */
    x->root_seen = 1;
    x->pos = at;
    x->line_pos = at;
    x->line_no = line;
    if (nns > 0) {
        QC__TRY(QC__RESERVE(ctx, x->ns, x->ns_cap, nns));
        memcpy(x->ns, ns, nns * sizeof *ns);
        x->nns = nns;
    }
    return QC_OK;
}

void qc__xml_free(qc__xml *x)
{
    qc__free(x->ctx, x->attr, x->attr_cap * sizeof *x->attr);
    qc__free(x->ctx, x->text, x->text_cap);
    qc__free(x->ctx, x->ns, x->ns_cap * sizeof *x->ns);
    x->attr = NULL;
    x->text = NULL;
    x->ns = NULL;
    x->attr_cap = x->text_cap = x->ns_cap = 0;
    x->nattr = x->text_len = x->nns = 0;
}

unsigned long qc__xml_line(const qc__xml *x, size_t at)
{
    unsigned long line = 1;
    size_t i;

    if (at > x->len)
        at = x->len;
    for (i = 0; i < at; i++)
        if (x->buf[i] == '\n')
            line++;
    return line;
}

unsigned long qc__xml_line_at(qc__xml *x, size_t at)
{
    size_t i;

    if (at > x->len)
        at = x->len;
    if (x->line_no == 0 || at < x->line_pos) {
        x->line_pos = 0;
        x->line_no = 1;
    }
    for (i = x->line_pos; i < at; i++)
        if (x->buf[i] == '\n')
            x->line_no++;
    x->line_pos = at;
    return x->line_no;
}

static int name_start(unsigned char c)
{
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || c == ':' ||
           c >= 0x80;
}

static int name_char(unsigned char c)
{
    return name_start(c) || (c >= '0' && c <= '9') || c == '-' || c == '.';
}

static int starts(const qc__xml *x, size_t at, const char *w)
{
    size_t n = strlen(w);

    return x->len - at >= n && memcmp(x->buf + at, w, n) == 0;
}

/* Offset of the first w at or after from, or len. */
static size_t find(const qc__xml *x, size_t from, const char *w)
{
    size_t n = strlen(w), i;

    for (i = from; i + n <= x->len; i++)
        if (x->buf[i] == w[0] && memcmp(x->buf + i, w, n) == 0)
            return i;
    return x->len;
}

static int fail_at(const qc__xml *x, size_t at, const char *what)
{
    return qc__fail(x->ctx, QC_EFORMAT, "svg line %lu (byte %lu): %s",
                    qc__xml_line(x, at), (unsigned long)at, what);
}

/* XML forbids control characters other than tab, LF and CR anywhere. */
static int check_bytes(const qc__xml *x)
{
    size_t i;

    if (starts(x, 0, "\xFF\xFE") || starts(x, 0, "\xFE\xFF"))
        return qc__fail(x->ctx, QC_EFORMAT, "svg: UTF-16 text is not supported: save as UTF-8");

    for (i = 0; i < x->len; i++) {
        unsigned char c = (unsigned char)x->buf[i];

        if (c < 0x20 && c != '\t' && c != '\n' && c != '\r')
            return qc__fail(x->ctx, QC_EFORMAT,
                            "svg line %lu (byte %lu): control character 0x%02x: not an "
                            "XML text document",
                            qc__xml_line(x, i), (unsigned long)i, c);
    }
    return QC_OK;
}

static size_t scan_name(const qc__xml *x, size_t at)
{
    size_t i = at;

    if (i < x->len && name_start((unsigned char)x->buf[i]))
        for (i++; i < x->len && name_char((unsigned char)x->buf[i]); i++)
            ;
    return i - at;
}

/* Reads the entity or character reference at x->buf[at] == '&' into *cp;
 * *end receives the offset after ';'. */
static int entity(const qc__xml *x, size_t at, unsigned long *cp, size_t *end)
{
    static const struct {
        const char *name;
        char c;
    } named[] = {{"amp;", '&'}, {"lt;", '<'}, {"gt;", '>'}, {"quot;", '"'}, {"apos;", '\''}};
    size_t i = at + 1, k;

    if (i < x->len && x->buf[i] == '#') {
        int hex = 0, digits = 0;
        unsigned long v = 0;

        i++;
        if (i < x->len && x->buf[i] == 'x') {
            hex = 1;
            i++;
        }
        for (; i < x->len && x->buf[i] != ';'; i++) {
            char c = x->buf[i];
            unsigned d;

            if (c >= '0' && c <= '9')
                d = (unsigned)(c - '0');
            else if (hex && c >= 'a' && c <= 'f')
                d = (unsigned)(c - 'a' + 10);
            else if (hex && c >= 'A' && c <= 'F')
                d = (unsigned)(c - 'A' + 10);
            else
                return fail_at(x, at, "malformed character reference");
            if (++digits > 8)
                return fail_at(x, at, "character reference out of range");
            v = v * (hex ? 16u : 10u) + d;
        }
        if (i >= x->len || digits == 0)
            return fail_at(x, at, "malformed character reference");
        if (v > 0x10FFFFul || (v >= 0xD800ul && v <= 0xDFFFul) ||
            (v < 0x20 && v != 9 && v != 10 && v != 13) || v == 0xFFFEul || v == 0xFFFFul)
            return fail_at(x, at, "character reference to a character XML forbids");
        *cp = v;
        *end = i + 1;
        return QC_OK;
    }
    for (k = 0; k < sizeof named / sizeof named[0]; k++)
        if (starts(x, i, named[k].name)) {
            *cp = (unsigned char)named[k].c;
            *end = i + strlen(named[k].name);
            return QC_OK;
        }
    k = scan_name(x, i);
    if (k > 0 && i + k < x->len && x->buf[i + k] == ';')
        return qc__fail(x->ctx, QC_EFORMAT,
                        "svg line %lu (byte %lu): undeclared entity &%.*s; (only &amp; &lt; "
                        "&gt; &quot; &apos; and &#N; are known)",
                        qc__xml_line(x, at), (unsigned long)at, (int)(k > 40 ? 40 : k),
                        x->buf + i);
    return fail_at(x, at, "'&' must start an entity reference such as &amp;");
}

static int put_text(qc__xml *x, const char *s, size_t n)
{
    QC__TRY(QC__RESERVE(x->ctx, x->text, x->text_cap, x->text_len + n));
    memcpy(x->text + x->text_len, s, n);
    x->text_len += n;
    return QC_OK;
}

static int put_utf8(qc__xml *x, unsigned long cp)
{
    char u[4];
    size_t n;

    if (cp < 0x80) {
        u[0] = (char)cp;
        n = 1;
    } else if (cp < 0x800) {
        u[0] = (char)(0xC0 | (cp >> 6));
        u[1] = (char)(0x80 | (cp & 0x3F));
        n = 2;
    } else if (cp < 0x10000) {
        u[0] = (char)(0xE0 | (cp >> 12));
        u[1] = (char)(0x80 | ((cp >> 6) & 0x3F));
        u[2] = (char)(0x80 | (cp & 0x3F));
        n = 3;
    } else {
        u[0] = (char)(0xF0 | (cp >> 18));
        u[1] = (char)(0x80 | ((cp >> 12) & 0x3F));
        u[2] = (char)(0x80 | ((cp >> 6) & 0x3F));
        u[3] = (char)(0x80 | (cp & 0x3F));
        n = 4;
    }
    return put_text(x, u, n);
}

/* Character data between tags: white space only outside the root; entity
 * references must be valid. */
static int text(qc__xml *x)
{
    size_t i = x->pos;

    for (; i < x->len && x->buf[i] != '<'; i++) {
        if (x->depth == 0 && !qc__is_space(x->buf[i]))
            return fail_at(x, i, x->root_done ? "text after the root element"
                                              : "text before the root element");
        if (x->buf[i] == '&') {
            unsigned long cp;
            size_t end;

            QC__TRY(entity(x, i, &cp, &end));
            i = end - 1;
        }
    }
    x->pos = i;
    return QC_OK;
}

/* <!DOCTYPE name [external id] [ '[' internal subset ']' ] > */
static int doctype(qc__xml *x)
{
    size_t at = x->pos, i = at + 9;
    int subset = 0;

    if (x->root_seen)
        return fail_at(x, at, "DOCTYPE after the root element started");
    while (i < x->len) {
        char c = x->buf[i];

        if (c == '"' || c == '\'') {
            size_t j = i + 1;

            while (j < x->len && x->buf[j] != c)
                j++;
            if (j >= x->len)
                break;
            i = j + 1;
        } else if (subset && starts(x, i, "<!--")) {
            size_t j = find(x, i + 4, "-->");

            if (j >= x->len)
                break;
            i = j + 3;
        } else if (subset && starts(x, i, "<!ENTITY")) {
            return fail_at(x, i, "the DOCTYPE declares an entity (<!ENTITY ...>); entity "
                                 "declarations are refused: save as plain SVG");
        } else if (c == '[' && !subset) {
            subset = 1;
            i++;
        } else if (c == ']' && subset) {
            subset = 0;
            i++;
        } else if (c == '>' && !subset) {
            x->pos = i + 1;
            return QC_OK;
        } else {
            i++;
        }
    }
    return fail_at(x, at, "unterminated DOCTYPE");
}

static int push_ns(qc__xml *x, const char *prefix, size_t plen, const char *uri, size_t ulen)
{
    qc__xml_ns *b;

    if (x->nns >= QC__XML_MAX_NS)
        return qc__fail(x->ctx, QC_ELIMIT,
                        "svg line %lu: more than %d namespace declarations in scope",
                        qc__xml_line(x, x->at), QC__XML_MAX_NS);
    QC__TRY(QC__RESERVE(x->ctx, x->ns, x->ns_cap, x->nns + 1));
    b = &x->ns[x->nns++];
    b->prefix = prefix;
    b->prefix_len = plen;
    b->depth = x->depth + 1;
    b->svg = ulen == sizeof SVG_NS - 1 && memcmp(uri, SVG_NS, ulen) == 0;
    return QC_OK;
}

/* Whether the prefix (len 0: default namespace) is bound to SVG. An
 * undeclared default counts as SVG (hand-written files often omit xmlns);
 * an undeclared prefix does not. */
static int ns_svg(const qc__xml *x, const char *prefix, size_t plen)
{
    size_t k = x->nns;

    while (k-- > 0)
        if (x->ns[k].prefix_len == plen &&
            (plen == 0 || memcmp(x->ns[k].prefix, prefix, plen) == 0))
            return x->ns[k].svg;
    return plen == 0;
}

static int attributes(qc__xml *x, int *self_close)
{
    size_t k;

    x->nattr = 0;
    x->text_len = 0;
    for (;;) {
        size_t i = x->pos, nlen, vstart, off;
        int ws = 0;
        char q;
        qc__xml_attr *a;

        while (i < x->len && qc__is_space(x->buf[i])) {
            i++;
            ws = 1;
        }
        if (i >= x->len)
            return qc__fail(x->ctx, QC_EFORMAT,
                            "svg line %lu (byte %lu): unterminated <%.*s> tag at end of input",
                            qc__xml_line(x, x->at), (unsigned long)x->at,
                            (int)(x->name_len > 40 ? 40 : x->name_len), x->name);
        if (x->buf[i] == '>') {
            x->pos = i + 1;
            break;
        }
        if (x->buf[i] == '/') {
            if (i + 1 >= x->len || x->buf[i + 1] != '>')
                return fail_at(x, i, "expected '>' after '/' in a tag");
            x->pos = i + 2;
            *self_close = 1;
            break;
        }
        nlen = scan_name(x, i);
        if (nlen == 0)
            return fail_at(x, i, "expected an attribute name, '>' or '/>'");
        if (!ws)
            return fail_at(x, i, "expected white space before an attribute");
        if (x->nattr >= QC__XML_MAX_ATTRS)
            return qc__fail(x->ctx, QC_ELIMIT,
                            "svg line %lu: <%.*s> has more than %d attributes",
                            qc__xml_line(x, x->at), (int)(x->name_len > 40 ? 40 : x->name_len),
                            x->name, QC__XML_MAX_ATTRS);
        for (k = 0; k < x->nattr; k++)
            if (x->attr[k].name_len == nlen && memcmp(x->attr[k].name, x->buf + i, nlen) == 0)
                return fail_at(x, i, "duplicate attribute");
        QC__TRY(QC__RESERVE(x->ctx, x->attr, x->attr_cap, x->nattr + 1));
        a = &x->attr[x->nattr];
        a->name = x->buf + i;
        a->name_len = nlen;
        i += nlen;
        while (i < x->len && qc__is_space(x->buf[i]))
            i++;
        if (i >= x->len || x->buf[i] != '=')
            return fail_at(x, i, "expected '=' after an attribute name");
        i++;
        while (i < x->len && qc__is_space(x->buf[i]))
            i++;
        if (i >= x->len || (x->buf[i] != '"' && x->buf[i] != '\''))
            return fail_at(x, i, "expected a quoted attribute value");
        q = x->buf[i++];
        vstart = i;
        off = x->text_len;
        while (i < x->len && x->buf[i] != q) {
            if (x->buf[i] == '<')
                return fail_at(x, i, "'<' inside an attribute value");
            if (x->buf[i] == '&') {
                unsigned long cp;
                size_t end;

                QC__TRY(entity(x, i, &cp, &end));
                QC__TRY(put_utf8(x, cp));
                i = end;
            } else {
                size_t j = i;

                while (j < x->len && x->buf[j] != q && x->buf[j] != '<' && x->buf[j] != '&')
                    j++;
                QC__TRY(put_text(x, x->buf + i, j - i));
                i = j;
            }
        }
        if (i >= x->len)
            return fail_at(x, vstart - 1, "unterminated attribute value");
        QC__TRY(put_text(x, "", 1));
        /* value is set once text stops moving: values lie back to back */
        a->value = NULL;
        a->value_len = x->text_len - 1 - off;
        a->at = vstart;
        a->raw_len = i - vstart;
        x->nattr++;
        x->pos = i + 1;
    }
    /* values lie back to back in text, each NUL-terminated */
    {
        size_t off = 0;

        for (k = 0; k < x->nattr; k++) {
            x->attr[k].value = x->text + off;
            off += x->attr[k].value_len + 1;
        }
    }
    return QC_OK;
}

static int start_tag(qc__xml *x)
{
    size_t at = x->pos, nlen = scan_name(x, at + 1), k;
    int self_close = 0;
    const char *colon;

    if (x->root_done)
        return fail_at(x, at, "element after the root element");
    if (x->depth >= QC__XML_MAX_DEPTH)
        return qc__fail(x->ctx, QC_ELIMIT,
                        "svg line %lu: elements nested more than %d deep",
                        qc__xml_line(x, at), QC__XML_MAX_DEPTH);
    x->at = at;
    x->name = x->buf + at + 1;
    x->name_len = nlen;
    x->pos = at + 1 + nlen;
    QC__TRY(attributes(x, &self_close));
    for (k = 0; k < x->nattr; k++) {
        const qc__xml_attr *a = &x->attr[k];

        if (a->name_len == 5 && memcmp(a->name, "xmlns", 5) == 0)
            QC__TRY(push_ns(x, NULL, 0, a->value, a->value_len));
        else if (a->name_len > 6 && memcmp(a->name, "xmlns:", 6) == 0)
            QC__TRY(push_ns(x, a->name + 6, a->name_len - 6, a->value, a->value_len));
    }
    colon = (const char *)memchr(x->name, ':', nlen);
    if (colon != NULL) {
        x->local = colon + 1;
        x->local_len = nlen - (size_t)(colon + 1 - x->name);
        x->svg = ns_svg(x, x->name, (size_t)(colon - x->name));
    } else {
        x->local = x->name;
        x->local_len = nlen;
        x->svg = ns_svg(x, NULL, 0);
    }
    x->open[x->depth].name = x->name;
    x->open[x->depth].len = nlen;
    x->open[x->depth].at = at;
    x->depth++;
    x->root_seen = 1;
    x->close_pending = self_close;
    return QC__XML_OPEN;
}

static int pop(qc__xml *x)
{
    x->depth--;
    x->name = x->open[x->depth].name;
    x->name_len = x->open[x->depth].len;
    while (x->nns > 0 && x->ns[x->nns - 1].depth > x->depth)
        x->nns--;
    if (x->depth == 0)
        x->root_done = 1;
    x->nattr = 0;
    return QC__XML_CLOSE;
}

static int end_tag(qc__xml *x)
{
    size_t at = x->pos, nlen = scan_name(x, at + 2), i = at + 2 + nlen;
    const qc__xml_open *o;

    if (x->depth == 0)
        return fail_at(x, at, "end tag without a matching start tag");
    o = &x->open[x->depth - 1];
    if (nlen != o->len || memcmp(x->buf + at + 2, o->name, nlen) != 0)
        return qc__fail(x->ctx, QC_EFORMAT,
                        "svg line %lu (byte %lu): </%.*s> does not close <%.*s> of line %lu",
                        qc__xml_line(x, at), (unsigned long)at, (int)(nlen > 40 ? 40 : nlen),
                        x->buf + at + 2, (int)(o->len > 40 ? 40 : o->len), o->name,
                        qc__xml_line(x, o->at));
    while (i < x->len && qc__is_space(x->buf[i]))
        i++;
    if (i >= x->len || x->buf[i] != '>')
        return fail_at(x, at, "malformed end tag");
    x->pos = i + 1;
    return pop(x);
}

int qc__xml_next(qc__xml *x)
{
    if (!x->started) {
        x->started = 1;
        QC__TRY(check_bytes(x));
        if (starts(x, 0, "\xEF\xBB\xBF"))
            x->pos = 3;
    }
    if (x->close_pending) {
        x->close_pending = 0;
        return pop(x);
    }
    for (;;) {
        size_t at;

        QC__TRY(text(x));
        at = x->pos;
        if (at >= x->len) {
            if (x->depth > 0) {
                const qc__xml_open *o = &x->open[x->depth - 1];

                return qc__fail(x->ctx, QC_EFORMAT,
                                "svg: <%.*s> of line %lu is not closed at the end of input",
                                (int)(o->len > 40 ? 40 : o->len), o->name,
                                qc__xml_line(x, o->at));
            }
            if (!x->root_seen)
                return fail_at(x, at, "no root element");
            return QC__XML_DONE;
        }
        if (starts(x, at, "<?")) {
            size_t e = find(x, at + 2, "?>");

            if (e >= x->len)
                return fail_at(x, at, "unterminated processing instruction");
            x->pos = e + 2;
        } else if (starts(x, at, "<!--")) {
            size_t e = find(x, at + 4, "-->");

            if (e >= x->len)
                return fail_at(x, at, "unterminated comment");
            x->pos = e + 3;
        } else if (starts(x, at, "<![CDATA[")) {
            size_t e = find(x, at + 9, "]]>");

            if (x->depth == 0)
                return fail_at(x, at, "CDATA outside the root element");
            if (e >= x->len)
                return fail_at(x, at, "unterminated CDATA section");
            x->pos = e + 3;
        } else if (starts(x, at, "<!DOCTYPE")) {
            QC__TRY(doctype(x));
        } else if (starts(x, at, "</")) {
            return end_tag(x);
        } else if (at + 1 < x->len && name_start((unsigned char)x->buf[at + 1])) {
            return start_tag(x);
        } else {
            return fail_at(x, at, "'<' not followed by a name, '/', '!' or '?'");
        }
    }
}

const qc__xml_attr *qc__xml_attr_get(const qc__xml *x, const char *name)
{
    size_t n = strlen(name), k;

    for (k = 0; k < x->nattr; k++)
        if (x->attr[k].name_len == n && memcmp(x->attr[k].name, name, n) == 0)
            return &x->attr[k];
    return NULL;
}
