/*
 * qc_io_read_svg_patches: the closed shapes of a pieced top, each separate
 * piece one patch, kept where drawn, with the names a quilt plan matches
 * (id, class, inkscape:label, fill colour) and where it is in the file.
 */
#include <string.h>

#include "svg_internal.h"
#include "quiltc.h"

typedef struct patch_sink {
    qc_ctx *ctx;
    qc_patches *out;
    size_t nv; /* vertices so far, for QC_MAX_POINTS */
} patch_sink;

static char *dup_str(qc_ctx *ctx, const char *s)
{
    size_t n = s != NULL ? strlen(s) : 0;
    char *d = (char *)qc__alloc(ctx, n + 1);

    if (d == NULL)
        return NULL;
    if (n > 0)
        memcpy(d, s, n);
    d[n] = '\0';
    return d;
}

static void patch_free(qc_ctx *ctx, qc_patch *p)
{
    qc_region_free(ctx, &p->region);
    if (p->id != NULL)
        qc__free(ctx, p->id, strlen(p->id) + 1);
    if (p->cls != NULL)
        qc__free(ctx, p->cls, strlen(p->cls) + 1);
    if (p->label != NULL)
        qc__free(ctx, p->label, strlen(p->label) + 1);
    memset(p, 0, sizeof *p);
}

void qc_patches_free(qc_ctx *ctx, qc_patches *ps)
{
    size_t i;

    if (ps == NULL)
        return;
    for (i = 0; i < ps->n; i++)
        patch_free(ctx, &ps->p[i]);
    qc__free(ctx, ps->p, ps->cap * sizeof *ps->p);
    memset(ps, 0, sizeof *ps);
}

/* One patch per piece of the shape; the shape's rings are normalized
 * together first (a shape may not cross itself). */
static int take_shape(void *ud, const qc_region *rings, const qc__svg_elem *el)
{
    patch_sink *s = (patch_sink *)ud;
    qc_ctx *ctx = s->ctx;
    qc_region shape = {0}, *pieces = NULL;
    size_t npieces = 0, i;
    int rc;

    s->nv += rings->nv;
    if (s->nv > QC_MAX_POINTS)
        return qc__fail(ctx, QC_ELIMIT, "svg: the top has more than %lu vertices",
                        (unsigned long)QC_MAX_POINTS);
    rc = qc_region_copy(ctx, &shape, rings);
    if (rc >= 0)
        rc = qc_region_normalize(ctx, &shape);
    if (rc < 0 && rc != QC_ENOMEM) {
        char msg[QC_ERRMSG_MAX];

        memcpy(msg, ctx->msg, sizeof msg);
        msg[sizeof msg - 1] = '\0';
        rc = qc__fail(ctx, rc, "svg line %lu, <%s%s%s>: %s", el->line,
                      el->id != NULL ? "id=\"" : "element ", el->id != NULL ? el->id : "",
                      el->id != NULL ? "\"" : "", msg);
    }
    if (rc >= 0)
        rc = qc_region_pieces(ctx, &shape, &pieces, &npieces);
    if (rc >= 0)
        rc = QC__RESERVE(ctx, s->out->p, s->out->cap, s->out->n + npieces);
    for (i = 0; i < npieces && rc >= 0; i++) {
        qc_patch *p = &s->out->p[s->out->n];

        memset(p, 0, sizeof *p);
        p->region = pieces[i];
        memset(&pieces[i], 0, sizeof pieces[i]);
        s->out->n++;
        p->id = dup_str(ctx, el->id);
        p->cls = dup_str(ctx, el->cls);
        p->label = dup_str(ctx, el->label);
        if (p->id == NULL || p->cls == NULL || p->label == NULL)
            rc = QC_ENOMEM;
        p->fill = el->fill;
        p->has_fill = el->fill_rgb;
        p->element = el->index;
        p->line = el->line;
        p->piece = i + 1;
    }
    qc_region_pieces_free(ctx, pieces, npieces);
    qc_region_free(ctx, &shape);
    return rc < 0 ? rc : QC_OK;
}

int qc_io_read_svg_patches(qc_ctx *ctx, const char *buf, size_t len, const qc_svg_opts *opts,
                           qc_patches *out)
{
    patch_sink s;
    int rc;

    if (out == NULL)
        return qc__fail(ctx, QC_EINVAL, "svg: no output patches");
    memset(out, 0, sizeof *out);
    s.ctx = ctx;
    s.out = out;
    s.nv = 0;
    rc = qc__svg_walk_rings(ctx, buf, len, opts, take_shape, &s);
    if (rc >= 0 && out->n == 0)
        rc = qc__fail(ctx, QC_EEMPTY, "svg: no closed filled shape to make a patch of");
    if (rc < 0)
        qc_patches_free(ctx, out);
    return rc < 0 ? rc : QC_OK;
}

int qc_color_parse(const char *s, uint32_t *rgb)
{
    if (s == NULL || rgb == NULL)
        return 0;
    return qc__svg_color(s, strlen(s), rgb);
}
