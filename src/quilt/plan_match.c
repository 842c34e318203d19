/* A plan's rules against patches (qc_patch_matches), and the top as drawn
 * for writing: its outlines, moved with the line to the origin. */
#include <string.h>

#include "quilt_internal.h"

int qc_glob(const char *p, const char *s)
{
    const char *star = NULL, *resume = NULL;

    while (*s != '\0') {
        if (*p == '*') {
            star = p++;
            resume = s;
        } else if (*p == *s) {
            p++;
            s++;
        } else if (star != NULL) {
            p = star + 1;
            s = ++resume;
        } else
            return 0;
    }
    while (*p == '*')
        p++;
    return *p == '\0';
}

static int glob_opt(const char *pattern, const char *s)
{
    return pattern == NULL || qc_glob(pattern, s != NULL ? s : "");
}

/* class is a space-separated list: the pattern may match any one. */
static int class_match(const char *pattern, const char *cls)
{
    char one[128];
    const char *s = cls;

    if (pattern == NULL)
        return 1;
    while (s != NULL && *s != '\0') {
        size_t n = strcspn(s, " \t\n");
        if (n > 0 && n < sizeof one) {
            memcpy(one, s, n);
            one[n] = '\0';
            if (qc_glob(pattern, one))
                return 1;
        }
        s += n;
        while (*s == ' ' || *s == '\t' || *s == '\n')
            s++;
    }
    return 0;
}

int qc_patch_matches(const qc_patch_match *m, const qc_patch *p)
{
    return glob_opt(m->id, p->id) && class_match(m->cls, p->cls) &&
           glob_opt(m->label, p->label) && (!m->has_fill || (p->has_fill && p->fill == m->fill));
}

int qc_patches_outlines(qc_ctx *ctx, const qc_patches *ps, qc_region *out)
{
    size_t i, k;

    memset(out, 0, sizeof *out);
    for (i = 0; i < ps->n; i++) {
        const qc_region *r = &ps->p[i].region;
        for (k = 0; k < r->nrings; k++) {
            size_t s = k ? r->ring_end[k - 1] : 0;
            int rc = qc_region_add_ring(ctx, out, r->v + s, r->ring_end[k] - s);
            if (rc < 0) {
                qc_region_free(ctx, out);
                return rc;
            }
        }
    }
    return QC_OK;
}

static void shift(qc_path *p, double dx, double dy)
{
    size_t i;

    for (i = 0; i < p->npt; i++) {
        p->pt[i].x += dx;
        p->pt[i].y += dy;
    }
}

void qc_quilt_to_origin(qc_quilt_result *r, qc_region *outlines)
{
    qc_bbox b = qc_region_bbox(outlines);
    double dx = -b.min.x, dy = -b.min.y;

    qc_region_translate(outlines, dx, dy);
    shift(&r->path, dx, dy);
    shift(&r->ditch, dx, dy);
}
