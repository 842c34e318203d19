/* Format names and extensions, and qc_io_write's dispatch and plan checks. */
#include <math.h>
#include <string.h>

#include "io_internal.h"

/* Plain char arrays, not pointers: the tables need no relocation and stay
 * in read-only memory (make lint). */
static const char names[QC_FORMAT_COUNT][8] = {
    "", "pat", "qli", "dxf", "hpgl", "qcc", "iqp", "bqm", "gcode", "svg"};
static const char exts[QC_FORMAT_COUNT][8] = {
    "", ".pat", ".qli", ".dxf", ".plt", ".qcc", ".iqp", ".bqm", ".gcode", ".svg"};
/* space-separated, lower case */
static const char aliases[QC_FORMAT_COUNT][20] = {
    "", "pat", "qli", "dxf", "hpgl plt hpg hgl", "qcc", "iqp", "bqm",
    "gcode nc ngc g", "svg"};

static int dispatch(qc_ctx *ctx, int format, const qc_plan *plan,
                    const qc_io_opts *opts, qc__out *o)
{
    switch (format) {
    case QC_FORMAT_PAT: return qc__write_pat(ctx, plan, opts, o);
    case QC_FORMAT_QLI: return qc__write_qli(ctx, plan, opts, o);
    case QC_FORMAT_DXF: return qc__write_dxf(ctx, plan, opts, o);
    case QC_FORMAT_HPGL: return qc__write_hpgl(ctx, plan, opts, o);
    case QC_FORMAT_QCC: return qc__write_qcc(ctx, plan, opts, o);
    case QC_FORMAT_IQP: return qc__write_iqp(ctx, plan, opts, o);
    case QC_FORMAT_BQM: return qc__write_bqm(ctx, plan, opts, o);
    case QC_FORMAT_GCODE: return qc__write_gcode(ctx, plan, opts, o);
    case QC_FORMAT_SVG: return qc__write_svg(ctx, plan, opts, o);
    default: return qc__fail(ctx, QC_EINVAL, "unknown output format %d", format);
    }
}

/* Whether word (len bytes, any case) is one of the space-separated aliases. */
static int alias_match(const char *list, const char *word, size_t len)
{
    const char *a = list;

    while (*a != '\0') {
        size_t k = strcspn(a, " "), i;

        if (k == len) {
            for (i = 0; i < len; i++) {
                char c = word[i];
                if (c >= 'A' && c <= 'Z')
                    c = (char)(c - 'A' + 'a');
                if (c != a[i])
                    break;
            }
            if (i == len)
                return 1;
        }
        a += k;
        while (*a == ' ')
            a++;
    }
    return 0;
}

int qc_format_from_name(const char *name)
{
    const char *dot;
    int f;

    if (name == NULL)
        return -1;
    dot = strrchr(name, '.'); /* "out.pat", ".pat" -> "pat" */
    if (dot != NULL)
        name = dot + 1;
    for (f = 1; f < QC_FORMAT_COUNT; f++)
        if (alias_match(aliases[f], name, strlen(name)))
            return f;
    return -1;
}

const char *qc_format_name(int format)
{
    return format > 0 && format < QC_FORMAT_COUNT ? names[format] : NULL;
}

const char *qc_format_ext(int format)
{
    return format > 0 && format < QC_FORMAT_COUNT ? exts[format] : NULL;
}

int qc_io_write(qc_ctx *ctx, int format, const qc_plan *plan,
                const qc_io_opts *opts, qc_write_fn write, void *ud)
{
    qc_io_opts zero;
    qc__out o;
    size_t i;
    int rc;

    if (format <= 0 || format >= QC_FORMAT_COUNT)
        return qc__fail(ctx, QC_EINVAL, "unknown output format %d", format);
    if (write == NULL || plan == NULL)
        return qc__fail(ctx, QC_EINVAL, "qc_io_write: NULL %s",
                        write == NULL ? "write callback" : "plan");
    if (plan->n == 0)
        return qc__fail(ctx, QC_EEMPTY, "%s: the plan has no point",
                        names[format]);
    qc__out_init(&o, ctx, write, ud);
    o.lo = plan->p[0];
    for (i = 0; i < plan->n; i++) { /* one pass: the check and the least x and y */
        qc_vec2 p = plan->p[i];

        if (!(fabs(p.x) <= 1e6 && fabs(p.y) <= 1e6))
            return qc__fail(ctx, QC_ERANGE,
                            "%s: point %lu (%g, %g) mm is not finite or beyond 1e6 mm",
                            names[format], (unsigned long)i, p.x, p.y);
        o.lo.x = p.x < o.lo.x ? p.x : o.lo.x;
        o.lo.y = p.y < o.lo.y ? p.y : o.lo.y;
    }
    if (opts == NULL) {
        memset(&zero, 0, sizeof zero);
        opts = &zero;
    }
    rc = dispatch(ctx, format, plan, opts, &o);
    if (rc < 0)
        return rc;
    return qc__out_finish(&o);
}
