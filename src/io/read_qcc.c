/*
 * QuiltEZ .qcc: the header line "c s", then "p X<in> Y<in>" per point,
 * inches, y up. The format has no travel: the file is one sewn line.
 */
#include <string.h>

#include "read_common.h"

static int bad(qc__reader *r, const char *what, const char *s, size_t n)
{
    return qc__fail(r->ctx, QC_EFORMAT, "qcc line %lu: %s, found \"%.*s\"", r->where, what,
                    (int)(n > 40 ? 40 : n), s);
}

static int coord(const char *s, size_t n, size_t *i, char axis, double *v)
{
    qc__skip_blanks(s, n, i);
    if (*i >= n || (s[*i] != axis && s[*i] != axis + ('a' - 'A')))
        return 0;
    (*i)++;
    return qc__scan_num(s, n, i, v);
}

int qc__read_qcc(qc_ctx *ctx, const char *buf, size_t len, qc_plan *out)
{
    qc__lines it;
    qc__reader r;
    const char *s;
    size_t n;
    int header = 0;

    qc__lines_init(&it, buf, len);
    qc__reader_init(&r, ctx, out, "qcc");
    while (qc__lines_next(&it, &s, &n)) {
        size_t i = 0;
        double x, y;

        r.where = it.line;
        qc__trim_blanks(&s, &n);
        if (n == 0)
            continue;
        if (!header) {
            if (n - i != 3 || memcmp(s + i, "c s", 3) != 0)
                return bad(&r, "expected the header \"c s\"", s + i, n - i);
            header = 1;
            continue;
        }
        if (s[i] != 'p')
            return bad(&r, "expected \"p X<in> Y<in>\"", s + i, n - i);
        i++;
        if (!coord(s, n, &i, 'X', &x) || !coord(s, n, &i, 'Y', &y) || i != n)
            return bad(&r, "expected \"p X<in> Y<in>\"", s, n);
        QC__TRY(qc__reader_sew(&r, QC__V2(x * 25.4, y * 25.4)));
    }
    return qc__reader_finish(&r);
}
