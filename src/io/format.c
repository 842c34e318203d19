/* Format names and extensions, and qc_io_write's dispatch and plan checks. */
#include <math.h>
#include <string.h>

#include "io_internal.h"

typedef struct format_info {
    const char *name, *ext;
    const char *aliases; /* space-separated, lower case */
    qc__writer_fn write;
} format_info;

static const format_info formats[QC_FORMAT_COUNT] = {
    {NULL, NULL, "", NULL},
    {"pat", ".pat", "pat", qc__write_pat},
    {"qli", ".qli", "qli", qc__write_qli},
    {"dxf", ".dxf", "dxf", qc__write_dxf},
    {"hpgl", ".plt", "hpgl plt hpg hgl", qc__write_hpgl},
    {"qcc", ".qcc", "qcc", qc__write_qcc},
    {"iqp", ".iqp", "iqp", qc__write_iqp},
    {"bqm", ".bqm", "bqm", qc__write_bqm},
    {"gcode", ".gcode", "gcode nc ngc g", qc__write_gcode},
    {"svg", ".svg", "svg", qc__write_svg},
};

/* Whether word (len bytes, any case) is one of the space-separated aliases. */
static int alias_match(const char *aliases, const char *word, size_t len)
{
    const char *a = aliases;

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
        if (alias_match(formats[f].aliases, name, strlen(name)))
            return f;
    return -1;
}

const char *qc_format_name(int format)
{
    return format > 0 && format < QC_FORMAT_COUNT ? formats[format].name : NULL;
}

const char *qc_format_ext(int format)
{
    return format > 0 && format < QC_FORMAT_COUNT ? formats[format].ext : NULL;
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
                        formats[format].name);
    for (i = 0; i < plan->n; i++)
        if (!(fabs(plan->p[i].x) <= 1e6 && fabs(plan->p[i].y) <= 1e6))
            return qc__fail(ctx, QC_ERANGE,
                            "%s: point %lu (%g, %g) mm is not finite or beyond 1e6 mm",
                            formats[format].name, (unsigned long)i,
                            plan->p[i].x, plan->p[i].y);
    if (opts == NULL) {
        memset(&zero, 0, sizeof zero);
        opts = &zero;
    }
    qc__out_init(&o, ctx, write, ud);
    rc = formats[format].write(ctx, plan, opts, &o);
    if (rc < 0)
        return rc;
    return qc__out_finish(&o);
}
