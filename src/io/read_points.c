/*
 * Point files: CSV "x,y" lines (one header line, '#' comments and blank
 * lines allowed, LF or CRLF) or TSPLIB (keyword lines, then
 * NODE_COORD_SECTION with "id x y" lines, ids 1..DIMENSION in order, then
 * EOF). Numbers are read strictly by qc__scan_number (no hex, no locale,
 * correctly rounded whatever the locale's decimal point).
 */
#include <string.h>

#include "io_internal.h"

#define MAX_COORD 1e9
#define MAX_TOKEN 128  /* longest number accepted, characters */
#define QUOTE_MAX 40   /* characters of a bad line quoted in a message */

typedef struct reader {
    qc_ctx *ctx;
    const char *buf, *end; /* the input */
    const char *at;        /* start of the next line */
    const char *s, *e;     /* the current line, without its line end */
    unsigned long line;    /* its number, from 1 */
    const char *fmt;       /* "csv" or "tsplib", for messages */
} reader;

static int next_line(reader *r)
{
    const char *nl;

    if (r->at >= r->end)
        return 0;
    nl = memchr(r->at, '\n', (size_t)(r->end - r->at));
    r->s = r->at;
    r->e = nl ? nl : r->end;
    r->at = nl ? nl + 1 : r->end;
    if (r->e > r->s && r->e[-1] == '\r')
        r->e--;
    r->line++;
    return 1;
}

/* A blank within a line: a CR or form feed there is an error, not a
 * separator (so not qc__is_space). */
static int is_space(char c)
{
    return c == ' ' || c == '\t';
}

static const char *skip_space(const char *s, const char *e)
{
    while (s < e && is_space(*s))
        s++;
    return s;
}

static int is_digit(char c)
{
    return c >= '0' && c <= '9';
}

static char upper(char c)
{
    return c >= 'a' && c <= 'z' ? (char)(c - 'a' + 'A') : c;
}

static int is_word_char(char c)
{
    char u = upper(c);
    return is_digit(c) || (u >= 'A' && u <= 'Z') || c == '_';
}

/* Whether [s, e) starts with word w (upper case; matched in any case) not
 * followed by another letter, digit or '_'. */
static int word_is(const char *s, const char *e, const char *w)
{
    size_t n = strlen(w), i;

    if ((size_t)(e - s) < n)
        return 0;
    for (i = 0; i < n; i++)
        if (upper(s[i]) != w[i])
            return 0;
    return s + n == e || !is_word_char(s[n]);
}

/* The current line, quoted for a message: printable ASCII, shortened. */
static void quote(const reader *r, char *out, size_t cap)
{
    const char *s = r->s;
    size_t w = 0;

    while (s < r->e && w + 4 < cap && w < QUOTE_MAX) {
        char c = *s++;
        out[w++] = c >= 32 && c < 127 ? c : '?';
    }
    if (s < r->e && w + 4 <= cap) {
        memcpy(out + w, "...", 3);
        w += 3;
    }
    out[w] = '\0';
}

static int syntax(const reader *r, const char *what)
{
    char q[QUOTE_MAX + 8];

    quote(r, q, sizeof q);
    return qc__fail(r->ctx, QC_EFORMAT, "%s line %lu: %s, found \"%s\"", r->fmt, r->line, what,
                    q);
}

static int wrong_id(const reader *r, unsigned long want)
{
    char q[QUOTE_MAX + 8];

    quote(r, q, sizeof q);
    return qc__fail(r->ctx, QC_EFORMAT, "tsplib line %lu: expected node %lu, found \"%s\"",
                    r->line, want, q);
}

/* ---- numbers ---- */

enum { NUM_OK = 0, NUM_BAD = -1, NUM_NONFINITE = -2 };

/* Whether a "nan"/"inf"/"infinity" token (any case, optional sign) starts at s. */
static int nonfinite_token(const char *s, const char *e)
{
    if (s < e && (*s == '+' || *s == '-'))
        s++;
    return word_is(s, e, "NAN") || word_is(s, e, "INF") || word_is(s, e, "INFINITY");
}

/*
 * A number at *ps (qc__scan_number: strict, correctly rounded, no locale),
 * at most MAX_TOKEN characters; *ps moves past it. "1e" is refused here,
 * where a point file has no use for a trailing 'e'.
 */
static int number(const char **ps, const char *e, double *v)
{
    size_t at = 0, n = (size_t)(e - *ps);

    if (nonfinite_token(*ps, e))
        return NUM_NONFINITE;
    if (!qc__scan_number(*ps, n, &at, v) || at > MAX_TOKEN ||
        (at < n && ((*ps)[at] == 'e' || (*ps)[at] == 'E')))
        return NUM_BAD;
    *ps += at;
    return NUM_OK;
}

/* A coordinate at *ps: QC_OK, or the error naming the line. */
static int coord(const reader *r, const char **ps, double *v, const char *what)
{
    const char *s = *ps;
    int k = number(ps, r->e, v);

    if (k == NUM_NONFINITE || (k == NUM_OK && !(*v >= -MAX_COORD && *v <= MAX_COORD))) {
        const char *t = s;
        char tok[24];
        size_t w = 0;

        while (t < r->e && !is_space(*t) && *t != ',' && w + 1 < sizeof tok) {
            tok[w++] = *t >= 32 && *t < 127 ? *t : '?';
            t++;
        }
        tok[w] = '\0';
        return qc__fail(r->ctx, QC_ERANGE, "%s line %lu: %s %s is not a finite number within "
                        "+-1e9", r->fmt, r->line, what, tok);
    }
    if (k != NUM_OK)
        return syntax(r, what[0] == 'x' ? "expected a number for x" : "expected a number for y");
    return QC_OK;
}

static int push(reader *r, qc_points *out, size_t n0, double x, double y)
{
    qc_vec2 p;

    if (out->n - n0 >= QC_MAX_POINTS)
        return qc__fail(r->ctx, QC_ELIMIT, "%s line %lu: more than %lu points", r->fmt, r->line,
                        (unsigned long)QC_MAX_POINTS);
    p.x = x;
    p.y = y;
    return qc_points_push(r->ctx, out, p);
}

/* ---- CSV ---- */

static int blank_or_comment(const reader *r)
{
    const char *s = skip_space(r->s, r->e);
    return s == r->e || *s == '#';
}

/* x, y [# comment] */
static int csv_point(reader *r, double *x, double *y)
{
    const char *s = skip_space(r->s, r->e);

    QC__TRY(coord(r, &s, x, "x"));
    s = skip_space(s, r->e);
    if (s >= r->e || *s != ',')
        return syntax(r, "expected \"x,y\"");
    s = skip_space(s + 1, r->e);
    QC__TRY(coord(r, &s, y, "y"));
    s = skip_space(s, r->e);
    if (s < r->e && *s != '#')
        return syntax(r, "expected the end of the line after \"x,y\"");
    return QC_OK;
}

static int read_csv(reader *r, qc_points *out, size_t n0)
{
    int first = 1;

    r->fmt = "csv";
    while (next_line(r)) {
        double x, y;
        int rc;

        if (blank_or_comment(r))
            continue;
        rc = csv_point(r, &x, &y);
        if (rc == QC_EFORMAT && first) { /* a header: text where the first number goes */
            const char *s = skip_space(r->s, r->e);
            char c = upper(*s);
            if ((c >= 'A' && c <= 'Z') || c == '"' || c == '\'' || c == '_') {
                qc_clear_error(r->ctx);
                first = 0;
                continue;
            }
        }
        first = 0;
        QC__TRY(rc);
        QC__TRY(push(r, out, n0, x, y));
    }
    return QC_OK;
}

/* ---- TSPLIB ---- */

static const char *const tsplib_keys[] = {
    "NAME", "TYPE", "COMMENT", "DIMENSION", "EDGE_WEIGHT_TYPE", "NODE_COORD_SECTION",
    "CAPACITY", "NODE_COORD_TYPE", "DISPLAY_DATA_TYPE", "EDGE_WEIGHT_FORMAT",
    "EDGE_DATA_FORMAT"};

/* The first line with content is a TSPLIB keyword followed by ':' or by
 * nothing ("NAME : a280", "NODE_COORD_SECTION"); a CSV header such as
 * "name,x" is not. */
static int is_tsplib(const reader *r)
{
    const char *s = skip_space(r->s, r->e);
    size_t i;

    for (i = 0; i < sizeof tsplib_keys / sizeof *tsplib_keys; i++)
        if (word_is(s, r->e, tsplib_keys[i])) {
            const char *t = skip_space(s + strlen(tsplib_keys[i]), r->e);
            return t == r->e || *t == ':';
        }
    return 0;
}

/* Splits "KEY : value" (the colon optional): *key, *kend, *val, *vend. */
static int key_value(const reader *r, const char **key, const char **kend, const char **val,
                     const char **vend)
{
    const char *s = skip_space(r->s, r->e), *e = r->e;

    *key = s;
    while (s < e && (is_digit(*s) || *s == '_' || (upper(*s) >= 'A' && upper(*s) <= 'Z')))
        s++;
    if (s == *key)
        return 0;
    *kend = s;
    s = skip_space(s, e);
    if (s < e && *s == ':')
        s = skip_space(s + 1, e);
    while (e > s && is_space(e[-1]))
        e--;
    *val = s;
    *vend = e;
    return 1;
}

static int key_is(const char *key, const char *kend, const char *w)
{
    return (size_t)(kend - key) == strlen(w) && word_is(key, kend, w);
}

static int value_in(const char *v, const char *ve, const char *const *list, size_t n)
{
    size_t i;

    for (i = 0; i < n; i++)
        if ((size_t)(ve - v) == strlen(list[i]) && word_is(v, ve, list[i]))
            return 1;
    return 0;
}

/* Unsigned decimal integer filling [s, e) entirely (saturating). */
static int whole_uint(const char *s, const char *e, unsigned long *v)
{
    *v = 0;
    if (s == e)
        return 0;
    for (; s < e; s++) {
        if (!is_digit(*s))
            return 0;
        *v = *v > 100000000ul ? 1000000000ul : *v * 10 + (unsigned long)(*s - '0');
    }
    return 1;
}

static int tsplib_header(reader *r, unsigned long *dim)
{
    static const char *const planar[] = {"EUC_2D", "CEIL_2D", "ATT", "MAX_2D", "MAN_2D"};
    static const char *const twod[] = {"TWOD_COORDS"};
    static const char *const tsp[] = {"TSP"};
    int have_dim = 0;

    while (next_line(r)) {
        const char *k, *ke, *v, *ve;

        if (blank_or_comment(r))
            continue;
        if (!key_value(r, &k, &ke, &v, &ve))
            return syntax(r, "expected \"KEYWORD : value\"");
        if (key_is(k, ke, "NODE_COORD_SECTION")) {
            if (!have_dim)
                return syntax(r, "NODE_COORD_SECTION before DIMENSION");
            return QC_OK;
        }
        if (key_is(k, ke, "EOF"))
            return syntax(r, "EOF before NODE_COORD_SECTION");
        if ((size_t)(ke - k) > 8 && key_is(ke - 8, ke, "_SECTION"))
            return syntax(r, "only NODE_COORD_SECTION is supported");
        if (key_is(k, ke, "TYPE") && !value_in(v, ve, tsp, 1))
            return syntax(r, "only TYPE : TSP is supported");
        if (key_is(k, ke, "EDGE_WEIGHT_TYPE") && !value_in(v, ve, planar, 5))
            return syntax(r, "EDGE_WEIGHT_TYPE must be planar (EUC_2D, CEIL_2D, ATT, MAX_2D, "
                             "MAN_2D)");
        if (key_is(k, ke, "NODE_COORD_TYPE") && !value_in(v, ve, twod, 1))
            return syntax(r, "only NODE_COORD_TYPE : TWOD_COORDS is supported");
        if (key_is(k, ke, "DIMENSION")) {
            if (!whole_uint(v, ve, dim))
                return syntax(r, "DIMENSION needs a whole number");
            if (*dim == 0)
                return qc__fail(r->ctx, QC_EEMPTY, "tsplib line %lu: DIMENSION 0", r->line);
            if (*dim > QC_MAX_POINTS) /* as written: the value saturates at 1e9 */
                return qc__fail(r->ctx, QC_ELIMIT, "tsplib line %lu: DIMENSION %.*s is above "
                                "%lu points", r->line, (int)(ve - v > 40 ? 40 : ve - v), v,
                                (unsigned long)QC_MAX_POINTS);
            have_dim = 1;
        }
    }
    return qc__fail(r->ctx, QC_EFORMAT, "tsplib line %lu: the input ends before "
                    "NODE_COORD_SECTION", r->line);
}

/* "id x y" with id == want. */
static int tsplib_node(reader *r, unsigned long want, double *x, double *y)
{
    const char *s = skip_space(r->s, r->e), *t = s;
    unsigned long id;

    while (t < r->e && is_digit(*t))
        t++;
    if (!whole_uint(s, t, &id) || t >= r->e || !is_space(*t))
        return syntax(r, "expected \"id x y\"");
    if (id != want)
        return wrong_id(r, want);
    s = skip_space(t, r->e);
    QC__TRY(coord(r, &s, x, "x"));
    if (s >= r->e || !is_space(*s))
        return syntax(r, "expected \"id x y\"");
    s = skip_space(s, r->e);
    QC__TRY(coord(r, &s, y, "y"));
    if (skip_space(s, r->e) != r->e)
        return syntax(r, "expected the end of the line after \"id x y\"");
    return QC_OK;
}

static int read_tsplib(reader *r, qc_points *out, size_t n0)
{
    unsigned long dim = 0, i = 0;

    r->fmt = "tsplib";
    QC__TRY(tsplib_header(r, &dim));
    while (i < dim) {
        double x, y;

        if (!next_line(r))
            return qc__fail(r->ctx, QC_EFORMAT, "tsplib line %lu: the input ends after %lu of "
                            "DIMENSION %lu nodes", r->line, i, dim);
        if (blank_or_comment(r))
            continue;
        if (word_is(skip_space(r->s, r->e), r->e, "EOF"))
            return syntax(r, "EOF before all DIMENSION nodes");
        QC__TRY(tsplib_node(r, i + 1, &x, &y));
        QC__TRY(push(r, out, n0, x, y));
        i++;
    }
    while (next_line(r)) { /* EOF, another section or nothing; not more nodes */
        const char *s = skip_space(r->s, r->e);
        if (s == r->e)
            continue;
        if (is_digit(*s))
            return syntax(r, "more nodes than DIMENSION");
        break;
    }
    return QC_OK;
}

int qc_io_read_points(qc_ctx *ctx, const char *buf, size_t len, qc_points *out)
{
    reader r;
    size_t n0;
    int rc;

    if (out == NULL || (buf == NULL && len > 0))
        return qc__fail(ctx, QC_EINVAL, "points: NULL %s", out == NULL ? "output" : "buffer");
    n0 = out->n;
    if (len == 0)
        return qc__fail(ctx, QC_EEMPTY, "points: empty input");
    memset(&r, 0, sizeof r);
    r.ctx = ctx;
    r.buf = buf;
    r.end = buf + len;
    r.at = buf;
    r.fmt = "points";
    if (len >= 3 && memcmp(buf, "\xEF\xBB\xBF", 3) == 0)
        r.at += 3; /* UTF-8 byte order mark */
    /* the first line with content decides the format */
    {
        reader probe = r;
        int tsplib = 0;

        while (next_line(&probe))
            if (!blank_or_comment(&probe)) {
                tsplib = is_tsplib(&probe);
                break;
            }
        rc = tsplib ? read_tsplib(&r, out, n0) : read_csv(&r, out, n0);
    }
    if (rc == QC_OK && out->n == n0)
        rc = qc__fail(ctx, QC_EEMPTY, "%s: no point in %lu bytes", r.fmt, (unsigned long)len);
    if (rc != QC_OK)
        out->n = n0;
    return rc;
}
