/*
 * CSS from <style> elements, as far as a quilting outline needs it: rules
 * whose selectors are a class (.name), an id (#name), an element type
 * (name) or *, and of their declarations only the properties the reader
 * looks up (fill, fill-rule, stroke-dasharray, display, visibility,
 * clip-path, mask). Other selectors and at-rules are skipped with a
 * warning, so a drawing is never silently misread. Rules are sorted by
 * selector, so an element finds its rules by binary search.
 */
#include <stdlib.h>
#include <string.h>

#include "svg_internal.h"

const char *const qc__css_prop_name[QC__CSS_NPROPS] = {
    "fill", "fill-rule", "stroke-dasharray", "display", "visibility", "clip-path", "mask"};

void qc__svg_trim(const char **s, size_t *n)
{
    while (*n > 0 && qc__is_space(**s)) {
        (*s)++;
        (*n)--;
    }
    while (*n > 0 && qc__is_space((*s)[*n - 1]))
        (*n)--;
}

int qc__css_decl(const char *s, size_t n, const char *prop, const char **val, size_t *vlen)
{
    size_t i = 0, plen = strlen(prop);
    int found = 0;

    while (i < n) {
        size_t j = i, colon;
        const char *name, *v;
        size_t nn, vn;

        while (j < n && s[j] != ';')
            j++;
        for (colon = i; colon < j && s[colon] != ':'; colon++)
            ;
        if (colon < j) {
            name = s + i;
            nn = colon - i;
            v = s + colon + 1;
            vn = j - colon - 1;
            qc__svg_trim(&name, &nn);
            qc__svg_trim(&v, &vn);
            if (vn >= 10 && memcmp(v + vn - 10, "!important", 10) == 0) {
                vn -= 10;
                qc__svg_trim(&v, &vn);
            }
            if (nn == plen && memcmp(name, prop, plen) == 0) {
                *val = v;
                *vlen = vn;
                found = 1;
            }
        }
        i = j + 1;
    }
    return found;
}

static int starts(const char *s, size_t n, size_t at, const char *w)
{
    size_t k = strlen(w);

    return n - at >= k && memcmp(s + at, w, k) == 0;
}

static void blank(char *s, size_t from, size_t to)
{
    memset(s + from, ' ', to - from);
}

int qc__css_add(qc__css *c, const char *s, size_t n, unsigned long line)
{
    size_t start = c->text_len, i;
    char *t;

    QC__TRY(QC__RESERVE(c->ctx, c->text, c->text_cap, c->text_len + n + 1));
    QC__TRY(QC__RESERVE(c->ctx, c->chunk, c->chunk_cap, c->nchunk + 1));
    t = c->text + start;
    memcpy(t, s, n);
    /* comments, CDATA marks and SGML comment marks are white space to CSS here */
    for (i = 0; i < n;) {
        size_t e;

        if (starts(t, n, i, "/*")) {
            for (e = i + 2; e < n && !starts(t, n, e, "*/"); e++)
                ;
            e = e < n ? e + 2 : n;
        } else if (starts(t, n, i, "<![CDATA[")) {
            e = i + 9;
        } else if (starts(t, n, i, "]]>") || starts(t, n, i, "-->")) {
            e = i + 3;
        } else if (starts(t, n, i, "<!--")) {
            e = i + 4;
        } else {
            i++;
            continue;
        }
        blank(t, i, e);
        i = e;
    }
    c->text_len += n;
    c->text[c->text_len++] = '\n'; /* sheets never run into each other */
    c->chunk[c->nchunk].start = start;
    c->chunk[c->nchunk].end = start + n;
    c->chunk[c->nchunk].line = line;
    c->nchunk++;
    return QC_OK;
}

static int ident_char(unsigned char ch)
{
    return (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') ||
           ch == '-' || ch == '_' || ch >= 0x80;
}

/* Classifies one selector s[0..n) (trimmed): 1 with kind/name when simple. */
static int simple_selector(const char *s, size_t n, char *kind, const char **name, size_t *len)
{
    size_t i, from = 0;

    if (n == 1 && s[0] == '*') {
        *kind = '*';
        *name = "";
        *len = 0;
        return 1;
    }
    if (n > 1 && (s[0] == '.' || s[0] == '#')) {
        *kind = s[0];
        from = 1;
    } else {
        *kind = 't';
    }
    if (from >= n)
        return 0;
    for (i = from; i < n; i++)
        if (!ident_char((unsigned char)s[i]))
            return 0;
    *name = s + from;
    *len = n - from;
    return 1;
}

static int add_rule(qc__css *c, char kind, const char *name, size_t len, const char *decl,
                    size_t dn)
{
    qc__css_rule *r;
    int p;

    QC__TRY(QC__RESERVE(c->ctx, c->rule, c->cap, c->n + 1));
    r = &c->rule[c->n];
    memset(r, 0, sizeof *r);
    r->kind = kind;
    r->name = name;
    r->name_len = len;
    r->spec = kind == '#' ? 100u : kind == '.' ? 10u : kind == 't' ? 1u : 0u;
    r->order = c->n;
    for (p = 0; p < QC__CSS_NPROPS; p++)
        if (qc__css_decl(decl, dn, qc__css_prop_name[p], &r->val[p], &r->val_len[p]))
            r->has |= 1u << p;
    if (r->has != 0)
        c->n++; /* a rule declaring nothing we read changes nothing */
    return QC_OK;
}

/* Offset of the '}' closing the block opened at s[open] == '{' (nested
 * blocks counted), or n. */
static size_t block_end(const char *s, size_t n, size_t open)
{
    size_t i, depth = 0;

    for (i = open; i < n; i++) {
        if (s[i] == '{')
            depth++;
        else if (s[i] == '}' && --depth == 0)
            return i;
    }
    return n;
}

static int short_len(size_t n)
{
    return (int)(n > 40 ? 40 : n);
}

static int parse_chunk(qc__css *c, const qc__css_chunk *ch, qc__svg_warner *warn)
{
    const char *s = c->text;
    size_t i = ch->start, n = ch->end;

    while (i < n) {
        size_t open, close, k, from;

        while (i < n && (qc__is_space(s[i]) || s[i] == ';'))
            i++;
        if (i >= n)
            break;
        for (open = i; open < n && s[open] != '{' && !(s[i] == '@' && s[open] == ';'); open++)
            ;
        if (open >= n || s[open] == ';') {
            const char *w = s + i;
            size_t wn = open - i;

            qc__svg_trim(&w, &wn);
            qc__svg_warn(warn, "svg line %lu, <style>: \"%.*s\" is not a rule quiltc reads: "
                               "skipped", ch->line, short_len(wn), w);
            i = open + 1;
            continue;
        }
        close = block_end(s, n, open);
        if (s[i] == '@') {
            const char *w = s + i;
            size_t wn = open - i;

            qc__svg_trim(&w, &wn);
            qc__svg_warn(warn, "svg line %lu, <style>: \"%.*s\" (an at-rule) is not read: its "
                               "rules are skipped", ch->line, short_len(wn), w);
            i = close + 1;
            continue;
        }
        /* a selector list: each simple selector gets the declarations */
        for (from = i, k = i; k <= open; k++) {
            const char *sel;
            size_t sn, len;
            const char *name;
            char kind;

            if (k < open && s[k] != ',')
                continue;
            sel = s + from;
            sn = k - from;
            qc__svg_trim(&sel, &sn);
            from = k + 1;
            if (simple_selector(sel, sn, &kind, &name, &len)) {
                if (c->n >= QC__CSS_MAX_RULES) {
                    qc__svg_warn(warn, "svg line %lu, <style>: more than %d rules: the rest "
                                       "are skipped", ch->line, QC__CSS_MAX_RULES);
                    return QC_OK;
                }
                QC__TRY(add_rule(c, kind, name, len, s + open + 1, close - open - 1));
            } else {
                qc__svg_warn(warn, "svg line %lu, <style>: selector \"%.*s\" is not read "
                                   "(only .class, #id, element and *): its rule is skipped",
                             ch->line, short_len(sn), sel);
            }
        }
        i = close + 1;
    }
    return QC_OK;
}

static int key_cmp(char ka, const char *na, size_t la, char kb, const char *nb, size_t lb)
{
    int d;

    if (ka != kb)
        return ka < kb ? -1 : 1;
    d = memcmp(na, nb, la < lb ? la : lb);
    if (d != 0)
        return d;
    return la < lb ? -1 : la > lb ? 1 : 0;
}

static int rule_cmp(const void *a, const void *b)
{
    const qc__css_rule *x = (const qc__css_rule *)a, *y = (const qc__css_rule *)b;
    int d = key_cmp(x->kind, x->name, x->name_len, y->kind, y->name, y->name_len);

    if (d != 0)
        return d;
    return x->order < y->order ? -1 : x->order > y->order ? 1 : 0;
}

int qc__css_parse(qc__css *c, qc__svg_warner *warn)
{
    size_t k;

    for (k = 0; k < c->nchunk; k++)
        QC__TRY(parse_chunk(c, &c->chunk[k], warn));
    if (c->n > 1)
        qsort(c->rule, c->n, sizeof *c->rule, rule_cmp);
    return QC_OK;
}

void qc__css_free(qc__css *c)
{
    qc__free(c->ctx, c->text, c->text_cap);
    qc__free(c->ctx, c->chunk, c->chunk_cap * sizeof *c->chunk);
    qc__free(c->ctx, c->rule, c->cap * sizeof *c->rule);
    c->text = NULL;
    c->chunk = NULL;
    c->rule = NULL;
    c->text_len = c->text_cap = c->nchunk = c->chunk_cap = c->n = c->cap = 0;
}

/* The first rule whose selector sorts after (kind, name) when after is
 * set, else the first not before it. */
static size_t bound(const qc__css *c, char kind, const char *name, size_t len, int after)
{
    size_t lo = 0, hi = c->n;

    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        const qc__css_rule *r = &c->rule[mid];
        int d = key_cmp(r->kind, r->name, r->name_len, kind, name, len);

        if (d < 0 || (after && d == 0))
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

/* Adds the rules of selector (kind, name) to m; when more than fit, the
 * last ones (they win ties), dropping the oldest. */
static void match_key(const qc__css *c, char kind, const char *name, size_t len,
                      qc__css_match *m)
{
    size_t lo = bound(c, kind, name, len, 0), hi = bound(c, kind, name, len, 1), k;

    if (hi - lo > QC__CSS_MAX_MATCH)
        lo = hi - QC__CSS_MAX_MATCH;
    for (k = lo; k < hi; k++) {
        if (m->n == QC__CSS_MAX_MATCH) {
            memmove(m->r, m->r + 1, (QC__CSS_MAX_MATCH - 1) * sizeof m->r[0]);
            m->n--;
        }
        m->r[m->n++] = &c->rule[k];
    }
}

void qc__css_match_element(const qc__css *c, const char *type, size_t type_len,
                           const char *id, const char *cls, qc__css_match *m)
{
    m->n = 0;
    if (c->n == 0)
        return;
    match_key(c, '*', "", 0, m);
    if (type != NULL)
        match_key(c, 't', type, type_len, m);
    if (id != NULL)
        match_key(c, '#', id, strlen(id), m);
    if (cls != NULL) {
        size_t i = 0, n = strlen(cls), classes = 0;

        while (i < n && classes < QC__CSS_MAX_MATCH) {
            size_t j;

            while (i < n && qc__is_space(cls[i]))
                i++;
            for (j = i; j < n && !qc__is_space(cls[j]); j++)
                ;
            if (j > i) {
                match_key(c, '.', cls + i, j - i, m);
                classes++;
            }
            i = j;
        }
    }
}

int qc__css_get(const qc__css_match *m, int p, const char **val, size_t *vlen)
{
    const qc__css_rule *best = NULL;
    size_t k;

    for (k = 0; k < m->n; k++) {
        const qc__css_rule *r = m->r[k];

        if (!(r->has & (1u << p)))
            continue;
        if (best == NULL || r->spec > best->spec ||
            (r->spec == best->spec && r->order > best->order))
            best = r;
    }
    if (best == NULL)
        return 0;
    *val = best->val[p];
    *vlen = best->val_len[p];
    return 1;
}
