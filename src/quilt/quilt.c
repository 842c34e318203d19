/*
 * qc_quilt: a pattern per patch, joined into one line along the seams.
 *
 * The sewing order is greedy on the seams: from where the line is, the
 * unsewn patch nearest along the seam graph is next, its pattern starting
 * at the seam vertex where the travel reaches it. Every piece of a pattern
 * is linked by a straight stitch from and to the nearest point of its
 * patch's boundary (inside the patch: nothing of the boundary is nearer),
 * and between two such points the line follows the shortest way along the
 * seams. Where no seam leads on (patches apart), or with QC_JOIN_JUMP, the
 * line jumps instead.
 */
#include <math.h>
#include <string.h>

#include "quilt_internal.h"

typedef struct quilter {
    qc_ctx *ctx;
    const qc_patches *ps;
    const qc_patch_job *jobs;
    int join;
    double seam_tol;
    qc__seams seams;
    qc__seam_dist sd;
    qc_points travel;     /* one travel's points */
    qc__seam_pt at;       /* where the line is (valid when started) */
    int started;
    unsigned char *sewn;
    uint32_t *hub;        /* per seam vertex: unsewn quilted patches touching it */
    uint32_t *stamp;      /* per seam vertex: last patch counted + 1 */
    qc_quilt_result *out;
} quilter;

/* Counts, for every seam vertex, the unsewn quilted patches on it. */
static void count_hubs(quilter *q)
{
    const qc__seams *s = &q->seams;
    size_t i, j, r;

    memset(q->hub, 0, s->nv * sizeof *q->hub);
    memset(q->stamp, 0, s->nv * sizeof *q->stamp);
    for (i = 0; i < q->ps->n; i++) {
        if (q->sewn[i] || q->jobs[i].params == NULL)
            continue;
        for (r = i ? s->patch_end[i - 1] : 0; r < s->patch_end[i]; r++)
            for (j = r ? s->ring_end[r - 1] : 0; j < s->ring_end[r]; j++) {
                uint32_t k = s->bnd[j];
                if (q->stamp[k] != i + 1) {
                    q->stamp[k] = (uint32_t)i + 1;
                    q->hub[k]++;
                }
            }
    }
}

static double dist(qc_vec2 a, qc_vec2 b)
{
    return qc_hypot(a.x - b.x, a.y - b.y);
}

void qc_quilt_result_free(qc_ctx *ctx, qc_quilt_result *r)
{
    if (r == NULL)
        return;
    qc_path_free(ctx, &r->path);
    qc_path_free(ctx, &r->ditch);
    qc__free(ctx, r->patch, r->npatch * sizeof *r->patch);
    qc__free(ctx, r->order, r->npatch * sizeof *r->order);
    memset(r, 0, sizeof *r);
}

/* The next patch and where to enter it (*entry): the unsewn one whose
 * boundary costs least to reach along the seams per unsewn patch meeting
 * there (travel / hub count), so the line goes to corners where several
 * patches meet and sews them one after the other with no travel between
 * them; where the line stands on one of its seams, the cost is 0. With no
 * seam leading on, the nearest as the crow flies; the first patch is entered
 * at the top's biggest hub. SIZE_MAX when every patch is sewn. */
static size_t next_patch(quilter *q, qc_vec2 *entry)
{
    const qc__seams *s = &q->seams;
    size_t i, best = SIZE_MAX, r, j;
    double bd = HUGE_VAL, be = HUGE_VAL;

    entry->x = entry->y = 0;
    count_hubs(q);
    for (i = 0; i < q->ps->n; i++) {
        if (q->sewn[i] || q->jobs[i].params == NULL)
            continue;
        for (r = i ? s->patch_end[i - 1] : 0; r < s->patch_end[i]; r++) {
            size_t start = r ? s->ring_end[r - 1] : 0, end = s->ring_end[r];

            for (j = start; j < end; j++) {
                uint32_t k = s->bnd[j], k2 = s->bnd[j + 1 < end ? j + 1 : start];
                double d = q->started ? q->sd.d[k] / (double)q->hub[k] : 1.0 / (double)q->hub[k];
                double e = q->started ? dist(q->at.p, s->v[k]) : (double)k;
                qc_vec2 at = s->v[k];

                if (q->started && q->at.u != q->at.v &&
                    ((k == q->at.u && k2 == q->at.v) || (k == q->at.v && k2 == q->at.u))) {
                    d = e = 0; /* the line stands on this patch's seam */
                    at = q->at.p;
                }
                if (d < bd || (d == bd && e < be)) {
                    bd = d;
                    be = e;
                    best = i;
                    *entry = at;
                }
            }
        }
    }
    return best;
}

/* Travels from q->at along the seams to b; 0 when no seam leads there. */
static int travel_to(quilter *q, qc__seam_pt b, int *ok)
{
    double len;
    size_t i;
    int rc;

    q->travel.n = 0;
    len = qc__seam_travel(q->ctx, &q->seams, &q->sd, b, &q->travel, &rc);
    QC__TRY(rc);
    *ok = len < HUGE_VAL;
    if (!*ok)
        return QC_OK;
    q->out->ditch_mm += len;
    for (i = 0; i < q->travel.n; i++) {
        QC__TRY(qc_path_line_to(q->ctx, &q->out->path, q->travel.v[i]));
        QC__TRY(i == 0 ? qc_path_move_to(q->ctx, &q->out->ditch, q->travel.v[i])
                       : qc_path_line_to(q->ctx, &q->out->ditch, q->travel.v[i]));
    }
    return QC_OK;
}

/* The seam point a link from p reaches: the nearest with QC_JOIN_JUMP (no
 * link is sewn), else one whose link crosses none of the pattern. */
static qc__seam_pt link_pt(const quilter *q, size_t i, const qc__links *lk, qc_vec2 p)
{
    if (q->join == QC_JOIN_JUMP)
        return qc__seams_nearest(&q->seams, i, p);
    return qc__links_seam_pt(lk, &q->seams, &q->ps->p[i].region, i, p);
}

/* Sews one piece of patch i's pattern (path commands [c0, c1), their
 * points from k0): along the seams from where the line is to the boundary
 * point nearest the piece's start, a straight stitch in, the piece, a
 * straight stitch out to the boundary point nearest its end. */
static int sew_piece(quilter *q, size_t i, const qc_path *pat, size_t c0, size_t c1, size_t k0,
                     const qc__links *lk)
{
    qc_vec2 s = pat->pt[k0], t;
    qc__seam_pt b = link_pt(q, i, lk, s), e;
    size_t c, k = k0 + 1;
    int ok = 0, jump = q->join == QC_JOIN_JUMP || !q->started;

    if (!jump) {
        QC__TRY(qc__seam_dist_from(q->ctx, &q->seams, &q->sd, q->at));
        QC__TRY(travel_to(q, b, &ok));
        jump = !ok;
        q->out->jumps += (size_t)jump;
    }
    if (q->join == QC_JOIN_JUMP) {
        QC__TRY(qc_path_move_to(q->ctx, &q->out->path, s));
    } else {
        if (jump)
            QC__TRY(qc_path_move_to(q->ctx, &q->out->path, b.p));
        QC__TRY(qc_path_line_to(q->ctx, &q->out->path, s));
        q->out->link_mm += dist(b.p, s);
    }
    for (c = c0 + 1; c < c1; c++) {
        if (pat->cmd[c] == QC_PATH_CUBIC) {
            QC__TRY(qc_path_cubic_to(q->ctx, &q->out->path, pat->pt[k], pat->pt[k + 1],
                                     pat->pt[k + 2]));
            k += 3;
        } else {
            QC__TRY(qc_path_line_to(q->ctx, &q->out->path, pat->pt[k]));
            k++;
        }
    }
    t = pat->pt[k - 1];
    e = link_pt(q, i, lk, t);
    if (q->join != QC_JOIN_JUMP) {
        QC__TRY(qc_path_line_to(q->ctx, &q->out->path, e.p));
        q->out->link_mm += dist(t, e.p);
    }
    q->at = e;
    q->started = 1;
    return QC_OK;
}

/* The position in seam ring order of seam point b of patch i: *ring and
 * *j with b on the edge bnd[j] -> bnd[j + 1] (or at vertex bnd[j]). 0 when
 * b lies on none of the patch's rings (it always does: b came from them). */
static int find_on_ring(const qc__seams *s, size_t i, qc__seam_pt b, size_t *ring, size_t *j)
{
    size_t r, k;

    for (r = i ? s->patch_end[i - 1] : 0; r < s->patch_end[i]; r++) {
        size_t start = r ? s->ring_end[r - 1] : 0, end = s->ring_end[r];

        for (k = start; k < end; k++) {
            uint32_t u = s->bnd[k], v = s->bnd[k + 1 < end ? k + 1 : start];

            if ((b.u == b.v && u == b.u) || (u == b.u && v == b.v) || (u == b.v && v == b.u)) {
                *ring = r;
                *j = k;
                return 1;
            }
        }
    }
    return 0;
}

/* A patch too small for its pattern: once round the ring the line enters
 * by (from the boundary point nearest entry), in the ditch, back to where
 * it began. */
static int sew_ditch_only(quilter *q, size_t i, qc_vec2 entry)
{
    const qc__seams *s = &q->seams;
    qc__seam_pt b = qc__seams_nearest(s, i, entry);
    size_t r = 0, j = 0, k, start, end, n;
    double len = 0;
    qc_vec2 last = b.p;
    int ok = 0;

    if (!find_on_ring(s, i, b, &r, &j))
        return qc__fail(q->ctx, QC_EINVAL, "quilt: patch %lu has no seam to sew",
                        (unsigned long)i + 1);
    if (q->started) {
        QC__TRY(qc__seam_dist_from(q->ctx, s, &q->sd, q->at));
        QC__TRY(travel_to(q, b, &ok));
    }
    if (!ok) {
        q->out->jumps += (size_t)q->started;
        QC__TRY(qc_path_move_to(q->ctx, &q->out->path, b.p));
    }
    QC__TRY(qc_path_move_to(q->ctx, &q->out->ditch, b.p));
    start = r ? s->ring_end[r - 1] : 0;
    end = s->ring_end[r];
    n = end - start;
    /* from bnd[j + 1] round to bnd[j] (b itself when at a vertex, else
     * b lies between them and the line closes on it) */
    for (k = 1; k <= n; k++) {
        size_t at = start + (j - start + k) % n;
        qc_vec2 v = s->v[s->bnd[at]];

        len += dist(last, v);
        last = v;
        QC__TRY(qc_path_line_to(q->ctx, &q->out->path, v));
        QC__TRY(qc_path_line_to(q->ctx, &q->out->ditch, v));
    }
    if (b.u != b.v) {
        len += dist(last, b.p);
        QC__TRY(qc_path_line_to(q->ctx, &q->out->path, b.p));
        QC__TRY(qc_path_line_to(q->ctx, &q->out->ditch, b.p));
    }
    q->out->patch[i].length_mm = len;
    q->out->patch[i].pieces = 1;
    q->out->patch[i].ditch_only = 1;
    q->at = b;
    q->started = 1;
    return QC_OK;
}

/* Patch i takes its place in the sewing order, with the family used. */
static void mark_sewn(quilter *q, size_t i, int family)
{
    q->out->patch[i].family = family;
    q->out->patch[i].order = q->out->norder;
    q->out->order[q->out->norder++] = (uint32_t)i;
    q->sewn[i] = 1;
}

static int sew_patch(quilter *q, size_t i, qc_vec2 entry)
{
    const qc_patch_job *job = &q->jobs[i];
    qc_params p = *job->params;
    qc_result res;
    qc__links lk;
    qc_patch_result *pr = &q->out->patch[i];
    size_t c, c0 = 0, k = 0, k0 = 0;
    int rc;

    memset(&res, 0, sizeof res);
    memset(&lk, 0, sizeof lk);
    p.seed += (uint64_t)i; /* equal patches get different patterns */
    QC__TRY(qc_params_set(q->ctx, &p, "start-x", entry.x));
    QC__TRY(qc_params_set(q->ctx, &p, "start-y", entry.y));
    rc = qc_generate(q->ctx, &q->ps->p[i].region, &p, NULL, job->motifs, &res);
    if (rc == QC_EEMPTY) {
        qc_params resolved;

        QC__TRY(qc_params_resolve(q->ctx, &p, &resolved));
        mark_sewn(q, i, resolved.family);
        return sew_ditch_only(q, i, entry);
    }
    if (rc < 0) {
        char msg[QC_ERRMSG_MAX];
        const qc_patch *pa = &q->ps->p[i];

        memcpy(msg, q->ctx->msg, sizeof msg);
        msg[sizeof msg - 1] = '\0';
        return qc__fail(q->ctx, rc, "patch %lu%s%s%s: %s", (unsigned long)i + 1,
                        pa->id != NULL && pa->id[0] ? " (id \"" : "",
                        pa->id != NULL && pa->id[0] ? pa->id : "",
                        pa->id != NULL && pa->id[0] ? "\")" : "", msg);
    }
    mark_sewn(q, i, res.params.family);
    pr->length_mm = res.stats.length_mm; /* qc_generate measured it */
    pr->largest_gap_mm = res.stats.largest_gap_mm;
    pr->farthest_fabric_mm = res.stats.farthest_fabric_mm;
    pr->seam_bare = res.stats.seam_bare;
    pr->pieces = res.stats.pieces;
    rc = q->join == QC_JOIN_JUMP ? QC_OK : qc__links_init(q->ctx, &res.path, &lk);
    for (c = 0; c <= res.path.ncmd && rc >= 0; c++) {
        if (c == res.path.ncmd || (res.path.cmd[c] == QC_PATH_MOVE && c > c0)) {
            if (c > c0)
                rc = sew_piece(q, i, &res.path, c0, c, k0, &lk);
            c0 = c;
            k0 = k;
        }
        if (c < res.path.ncmd)
            k += qc_path_cmd_points(res.path.cmd[c]);
    }
    qc__links_free(q->ctx, &lk);
    qc_result_free(q->ctx, &res);
    return rc;
}

static int run(quilter *q)
{
    size_t i, n = q->ps->n;
    qc_vec2 entry;

    q->out->patch = (qc_patch_result *)qc__alloc_array(q->ctx, n, sizeof *q->out->patch);
    q->out->order = (uint32_t *)qc__alloc_array(q->ctx, n, sizeof *q->out->order);
    q->sewn = (unsigned char *)qc__alloc_array(q->ctx, n, 1);
    q->out->npatch = n; /* the sizes qc_quilt_result_free frees (NULL frees nothing) */
    if (q->out->patch == NULL || q->out->order == NULL || q->sewn == NULL)
        return QC_ENOMEM;
    memset(q->out->patch, 0, n * sizeof *q->out->patch);
    memset(q->sewn, 0, n);
    for (i = 0; i < n; i++)
        q->out->patch[i].order = SIZE_MAX;
    QC__TRY(qc__seams_build(q->ctx, q->ps, q->seam_tol, &q->seams));
    QC__TRY(qc__seam_dist_init(q->ctx, &q->seams, &q->sd));
    q->hub = (uint32_t *)qc__alloc_array(q->ctx, q->seams.nv, sizeof *q->hub);
    q->stamp = (uint32_t *)qc__alloc_array(q->ctx, q->seams.nv, sizeof *q->stamp);
    if (q->hub == NULL || q->stamp == NULL)
        return QC_ENOMEM;
    for (;;) {
        if (q->started)
            QC__TRY(qc__seam_dist_from(q->ctx, &q->seams, &q->sd, q->at));
        i = next_patch(q, &entry);
        if (i == SIZE_MAX)
            break;
        QC__TRY(sew_patch(q, i, entry));
    }
    if (q->out->norder == 0)
        return qc__fail(q->ctx, QC_EEMPTY, "every patch is left unquilted (family none)");
    return QC_OK;
}

int qc_quilt(qc_ctx *ctx, const qc_patches *ps, const qc_patch_job *jobs,
             const qc_quilt_params *params, qc_quilt_result *out)
{
    quilter q;
    int rc;

    if (out == NULL)
        return qc__fail(ctx, QC_EINVAL, "quilt: no output");
    memset(out, 0, sizeof *out);
    if (ps == NULL || jobs == NULL || ps->n == 0)
        return qc__fail(ctx, QC_EINVAL, "quilt: no patches or no jobs");
    memset(&q, 0, sizeof q);
    q.ctx = ctx;
    q.ps = ps;
    q.jobs = jobs;
    q.out = out;
    q.join = params != NULL ? params->join : QC_JOIN_DITCH;
    q.seam_tol = params != NULL && params->seam_tol != 0 ? params->seam_tol : QC_QUILT_SEAM_TOL;
    if (q.join != QC_JOIN_DITCH && q.join != QC_JOIN_JUMP)
        return qc__fail(ctx, QC_EINVAL, "quilt: join %d is neither ditch nor jump", q.join);
    if (!(q.seam_tol > 0) || q.seam_tol > QC_QUILT_MAX_SEAM_TOL)
        return qc__fail(ctx, QC_EINVAL, "quilt: seam tolerance %g mm must be in (0, %g]",
                        q.seam_tol, QC_QUILT_MAX_SEAM_TOL);
    rc = run(&q);
    qc__free(ctx, q.hub, q.seams.nv * sizeof *q.hub);
    qc__free(ctx, q.stamp, q.seams.nv * sizeof *q.stamp);
    qc__seam_dist_free(ctx, &q.seams, &q.sd);
    qc__seams_free(ctx, &q.seams);
    qc_points_free(ctx, &q.travel);
    qc__free(ctx, q.sewn, ps->n);
    if (rc < 0)
        qc_quilt_result_free(ctx, out);
    return rc;
}
