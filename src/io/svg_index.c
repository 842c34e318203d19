/*
 * One pass over an SVG document before the walk: the byte offset and line
 * of every element with an id (so <use> finds its source, before or after
 * it), the text of every <style> element (parsed into CSS rules) and the
 * root's namespace bindings (a clone is tokenized on its own). Also the
 * readers' warnings, delivered through the caller's callback.
 */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "svg_internal.h"

static void deliver(const qc__svg_warner *w, const char *fmt, va_list ap)
{
    char text[320];
    size_t i;

    vsnprintf(text, sizeof text, fmt, ap);
    for (i = 0; text[i] != '\0'; i++) /* one line, whatever the file quoted */
        if ((unsigned char)text[i] < 0x20 || text[i] == 0x7f)
            text[i] = ' ';
    w->fn(w->ud, text);
}

void qc__svg_warn(qc__svg_warner *w, const char *fmt, ...)
{
    va_list ap;

    if (w == NULL)
        return;
    w->count++;
    if (w->fn == NULL || w->count > QC__SVG_MAX_WARNINGS)
        return;
    va_start(ap, fmt);
    deliver(w, fmt, ap);
    va_end(ap);
}

static void deliver_f(const qc__svg_warner *w, const char *fmt, ...) QC__PRINTF(2, 3);
static void deliver_f(const qc__svg_warner *w, const char *fmt, ...)
{
    va_list ap;

    va_start(ap, fmt);
    deliver(w, fmt, ap);
    va_end(ap);
}

void qc__svg_warn_done(qc__svg_warner *w)
{
    if (w != NULL && w->fn != NULL && w->count > QC__SVG_MAX_WARNINGS)
        deliver_f(w, "svg: %lu more warnings not shown",
                  (unsigned long)(w->count - QC__SVG_MAX_WARNINGS));
}

static size_t hash(const char *s, size_t n)
{
    size_t h = 2166136261u, i;

    for (i = 0; i < n; i++)
        h = (h ^ (unsigned char)s[i]) * 16777619u;
    return h;
}

static int same(const qc__svg_id *e, const char *s, size_t n)
{
    return e->len == n && memcmp(e->id, s, n) == 0;
}

const qc__svg_id *qc__svg_index_find(const qc__svg_index *ix, const char *id, size_t n)
{
    size_t mask, i;

    if (ix->nslot == 0)
        return NULL;
    mask = ix->nslot - 1;
    for (i = hash(id, n) & mask; ix->slot[i] != 0; i = (i + 1) & mask)
        if (same(&ix->ids[ix->slot[i] - 1], id, n))
            return &ix->ids[ix->slot[i] - 1];
    return NULL;
}

/* The hash of ids, at most half full; the first of duplicate ids wins. */
static int build_slots(qc__svg_index *ix)
{
    size_t nslot = 16, k;

    if (ix->nids == 0)
        return QC_OK;
    while (nslot < 2 * ix->nids)
        nslot *= 2;
    ix->slot = (size_t *)qc__alloc_array(ix->ctx, nslot, sizeof *ix->slot);
    if (ix->slot == NULL)
        return QC_ENOMEM;
    memset(ix->slot, 0, nslot * sizeof *ix->slot);
    ix->nslot = nslot;
    for (k = 0; k < ix->nids; k++) {
        const qc__svg_id *e = &ix->ids[k];
        size_t i = hash(e->id, e->len) & (nslot - 1);

        while (ix->slot[i] != 0 && !same(&ix->ids[ix->slot[i] - 1], e->id, e->len))
            i = (i + 1) & (nslot - 1);
        if (ix->slot[i] == 0)
            ix->slot[i] = k + 1;
    }
    return QC_OK;
}

static int add_id(qc__svg_index *ix, qc__xml *x)
{
    const qc__xml_attr *a = qc__xml_attr_get(x, "id");
    qc__svg_id *e;

    if (a == NULL || a->value_len == 0 || a->raw_len != a->value_len)
        return QC_OK; /* no id, or one written with entity references */
    QC__TRY(QC__RESERVE(ix->ctx, ix->ids, ix->ids_cap, ix->nids + 1));
    e = &ix->ids[ix->nids++];
    e->id = x->buf + a->at;
    e->len = a->raw_len;
    e->at = x->at;
    e->line = qc__xml_line_at(x, x->at);
    return QC_OK;
}

static int keep_root_ns(qc__svg_index *ix, const qc__xml *x)
{
    size_t k;

    if (x->nns == 0)
        return QC_OK;
    ix->ns = (qc__xml_ns *)qc__alloc_array(ix->ctx, x->nns, sizeof *ix->ns);
    if (ix->ns == NULL)
        return QC_ENOMEM;
    for (k = 0; k < x->nns; k++) {
        ix->ns[k] = x->ns[k];
        ix->ns[k].depth = 0; /* in scope for the whole clone */
    }
    ix->nns = x->nns;
    return QC_OK;
}

static int is_style(const qc__xml *x)
{
    return x->svg && x->local_len == 5 && memcmp(x->local, "style", 5) == 0;
}

int qc__svg_index_build(qc__svg_index *ix, qc_ctx *ctx, const char *buf, size_t len,
                        qc__svg_warner *warn)
{
    qc__xml x;
    size_t style_from = 0, style_depth = 0;
    unsigned long style_line = 0;
    int rc;

    memset(ix, 0, sizeof *ix);
    ix->ctx = ctx;
    ix->css.ctx = ctx;
    qc__xml_init(&x, ctx, buf, len);
    for (;;) {
        rc = qc__xml_next(&x);
        if (rc < 0 || rc == QC__XML_DONE)
            break;
        if (rc == QC__XML_OPEN) {
            rc = add_id(ix, &x);
            if (rc == QC_OK && x.depth == 1)
                rc = keep_root_ns(ix, &x);
            if (rc < 0)
                break;
            if (style_depth == 0 && is_style(&x) && !x.close_pending) {
                style_depth = x.depth;
                style_from = x.pos;
                style_line = qc__xml_line_at(&x, x.at);
            }
        } else if (style_depth != 0 && x.depth == style_depth - 1) {
            size_t end = x.pos; /* just past "</style>": back to its '<' */

            while (end > style_from && buf[end - 1] != '<')
                end--;
            rc = qc__css_add(&ix->css, buf + style_from, end > style_from ? end - 1 - style_from : 0,
                             style_line);
            style_depth = 0;
            if (rc < 0)
                break;
        }
    }
    qc__xml_free(&x);
    if (rc == QC_ENOMEM) {
        qc__svg_index_free(ix);
        return rc;
    }
    /* a malformed document: what was indexed stands; the walk names the fault */
    rc = build_slots(ix);
    if (rc == QC_OK)
        rc = qc__css_parse(&ix->css, warn);
    if (rc < 0)
        qc__svg_index_free(ix);
    return rc;
}

void qc__svg_index_free(qc__svg_index *ix)
{
    qc__free(ix->ctx, ix->ids, ix->ids_cap * sizeof *ix->ids);
    qc__free(ix->ctx, ix->slot, ix->nslot * sizeof *ix->slot);
    qc__free(ix->ctx, ix->ns, ix->nns * sizeof *ix->ns);
    qc__css_free(&ix->css);
    ix->ids = NULL;
    ix->slot = NULL;
    ix->ns = NULL;
    ix->nids = ix->ids_cap = ix->nslot = ix->nns = 0;
}
