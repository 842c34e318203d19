/*
 * Quilt tops for the page (see quiltc_wasm.h): the steps of quiltc quilt
 * (cli/quilt_sew.c, cli/cmd_quilt.c) over the same core calls, so a top
 * sewn here gives the CLI's bytes: patches read, overlaps refused, a rule
 * per patch (qc_patch_matches, first fit), qc_quilt, the outlines and the
 * line moved to the origin (qc_quilt_to_origin), qc_stitch_plan_taking.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qcw_internal.h"

void qcw_rules_clear(qcw_job *job)
{
    size_t i, k;

    for (i = 0; i < job->nrules; i++)
        for (k = 0; k < 3; k++)
            free(job->rule[i].text[k]);
    free(job->rule);
    job->rule = NULL;
    job->nrules = 0;
}

void qcw__drop_top(qcw_job *job)
{
    qcw__drop_result(job);
    qcw_rules_clear(job);
    qc_patches_free(&job->ctx, &job->patches);
    free(job->chosen);
    job->chosen = NULL;
}

/* How messages name a patch, as the CLI does: its id, else its element and line. */
static void patch_name(const qc_patch *p, char *buf, size_t size)
{
    if (p->id[0] != '\0')
        snprintf(buf, size, "id \"%s\" (line %lu)", p->id, p->line);
    else
        snprintf(buf, size, "shape %lu (line %lu)", (unsigned long)p->element, p->line);
}

int qcw_top_svg(qcw_job *job, const char *svg, size_t len, double mm_per_unit,
                const char *units)
{
    size_t a, b;
    qc_vec2 at;
    char an[160], bn[160], line[512];
    qc_svg_opts opts;
    int rc;

    qcw__drop_top(job);
    qc_region_free(&job->ctx, &job->region);
    qc_clear_error(&job->ctx);
    if (!(mm_per_unit > 0))
        return qcw__fail(job, QC_EINVAL, "units: %s", "mm per unit must be positive");
    qcw__svg_opts(job, &opts);
    rc = qc_io_read_svg_patches(&job->ctx, svg, len, &opts, &job->patches);
    if (rc == QC_OK && qc_patches_overlap(&job->patches, 0, &a, &b, &at)) {
        patch_name(&job->patches.p[a], an, sizeof an);
        patch_name(&job->patches.p[b], bn, sizeof bn);
        snprintf(line, sizeof line, "patches %s and %s overlap near (%.3f, %.3f) %s", an, bn,
                 at.x / mm_per_unit, at.y / mm_per_unit, units);
        rc = qcw__fail(job, QC_EINTERSECT, "%s", line);
    }
    if (rc == QC_OK) {
        job->chosen = calloc(job->patches.n, sizeof *job->chosen);
        if (job->chosen == NULL)
            rc = qcw__fail(job, QC_ENOMEM, "out of memory%s", "");
    }
    if (rc < 0)
        qcw__drop_top(job);
    return rc;
}

/* The lower-left corner of every patch: the sewn top's origin. */
static qc_vec2 top_corner(const qc_patches *ps)
{
    qc_vec2 c = {0.0, 0.0};
    size_t i, k;

    for (i = 0; i < ps->n; i++)
        for (k = 0; k < ps->p[i].region.nv; k++) {
            const qc_vec2 *v = &ps->p[i].region.v[k];
            if ((i == 0 && k == 0) || v->x < c.x)
                c.x = v->x;
            if ((i == 0 && k == 0) || v->y < c.y)
                c.y = v->y;
        }
    return c;
}

const char *qcw_patches_json(qcw_job *job)
{
    qc_vec2 o = top_corner(&job->patches);
    qcw_text out = {0};
    size_t i, k, v;

    qcw__add(&out, "[");
    for (i = 0; i < job->patches.n; i++) {
        const qc_patch *p = &job->patches.p[i];

        qcw__add(&out, "%s{\"id\":", i ? "," : "");
        qcw__add_str(&out, p->id);
        qcw__add(&out, ",\"class\":");
        qcw__add_str(&out, p->cls);
        qcw__add(&out, ",\"label\":");
        qcw__add_str(&out, p->label);
        if (p->has_fill)
            qcw__add(&out, ",\"fill\":\"#%06lx\"", (unsigned long)p->fill);
        else
            qcw__add(&out, ",\"fill\":null");
        qcw__add(&out, ",\"element\":%lu,\"line\":%lu,\"rings\":[", (unsigned long)p->element,
                 p->line);
        for (k = 0, v = 0; k < p->region.nrings; k++) {
            size_t first = v;
            qcw__add(&out, "%s[", k ? "," : "");
            for (; v < p->region.ring_end[k]; v++)
                qcw__add(&out, "%s%.3f,%.3f", v > first ? "," : "", p->region.v[v].x - o.x,
                         p->region.v[v].y - o.y);
            qcw__add(&out, "]");
        }
        qcw__add(&out, "]}");
    }
    qcw__add(&out, "]");
    return qcw__finish_json(job, &out);
}

/* A copy owned by the rule, or NULL for "" (matches anything). */
static int take_text(qcw_rule *r, int k, const char *s, const char **field)
{
    if (s == NULL || s[0] == '\0')
        return 0;
    r->text[k] = malloc(strlen(s) + 1);
    if (r->text[k] == NULL)
        return -1;
    strcpy(r->text[k], s);
    *field = r->text[k];
    return 0;
}

int qcw_rule_add(qcw_job *job, const char *id, const char *cls, const char *label,
                 const char *fill)
{
    qcw_rule *rules, *r;

    qc_clear_error(&job->ctx);
    if (job->nrules >= 256)
        return qcw__fail(job, QC_ELIMIT, "plan: at most 256 rules%s", "");
    rules = realloc(job->rule, (job->nrules + 1) * sizeof *rules);
    if (rules == NULL)
        return qcw__fail(job, QC_ENOMEM, "out of memory%s", "");
    job->rule = rules;
    r = &rules[job->nrules++];
    memset(r, 0, sizeof *r);
    if (fill != NULL && fill[0] != '\0') {
        if (!qc_color_parse(fill, &r->match.fill))
            return qcw__fail(job, QC_EINVAL,
                             "plan: '%s' is not a colour (#rgb, #rrggbb, rgb(r, g, b) or a name)",
                             fill);
        r->match.has_fill = 1;
    }
    if (take_text(r, 0, id, &r->match.id) < 0 || take_text(r, 1, cls, &r->match.cls) < 0 ||
        take_text(r, 2, label, &r->match.label) < 0)
        return qcw__fail(job, QC_ENOMEM, "out of memory%s", "");
    return QC_OK;
}

int qcw_rule_param(qcw_job *job, const char *name, double value)
{
    qc_clear_error(&job->ctx);
    if (job->nrules == 0)
        return qcw__fail(job, QC_EINVAL, "plan: no rule to set '%s' on", name);
    return qc_params_set(&job->ctx, &job->rule[job->nrules - 1].params, name, value);
}

int qcw_rule_none(qcw_job *job)
{
    qc_clear_error(&job->ctx);
    if (job->nrules == 0)
        return qcw__fail(job, QC_EINVAL, "plan: no rule to leave unquilted%s", "");
    job->rule[job->nrules - 1].none = 1;
    return QC_OK;
}

/* A rule's parameters as the CLI makes them: the defaults, then the rule's own. */
static int rule_params(qcw_job *job, const qcw_rule *r, qc_params *out)
{
    size_t n, i;
    const qc_param_info *t = qc_param_table(&n);

    *out = job->params;
    out->skip_gap_stat = 0; /* the CLI measures every patch's largest gap */
    for (i = 0; i < n; i++)
        if (t[i].type != QC_PARAM_SEED && qc_params_given(&r->params, (int)t[i].id)) {
            int rc = qc_params_set(&job->ctx, out, t[i].name, qc_params_get(&r->params, &t[i]));
            if (rc < 0)
                return rc;
        }
    return qc_params_resolve(&job->ctx, out, &(qc_params){0}) < 0 ? job->ctx.status : QC_OK;
}

/* Every patch's job: the first rule that fits it, or the defaults. */
static int choose(qcw_job *job, qc_patch_job *jobs, qc_params *rp, qc_params *base)
{
    const qc_motif_set *motifs = job->motifs.n ? &job->motifs : NULL;
    size_t i, k;
    int rc;

    *base = job->params;
    base->skip_gap_stat = 0;
    for (k = 0; k < job->nrules; k++) {
        job->rule[k].matched = 0;
        if ((rc = rule_params(job, &job->rule[k], &rp[k])) < 0)
            return rc;
    }
    for (i = 0; i < job->patches.n; i++) {
        for (k = 0; k < job->nrules; k++)
            if (qc_patch_matches(&job->rule[k].match, &job->patches.p[i]))
                break;
        job->chosen[i] = k < job->nrules ? k + 1 : 0;
        jobs[i].motifs = motifs;
        if (k < job->nrules) {
            job->rule[k].matched++;
            jobs[i].params = job->rule[k].none ? NULL : &rp[k];
        } else
            jobs[i].params = base;
    }
    for (k = 0; k < job->nrules; k++)
        if (job->rule[k].matched == 0) {
            char line[64];
            snprintf(line, sizeof line, "plan: rules[%lu] matches no patch", (unsigned long)k);
            return qcw__fail(job, QC_EINVAL, "%s", line);
        }
    return QC_OK;
}

int qcw_quilt(qcw_job *job, int join, int tie_stitches)
{
    qc_patch_job *jobs;
    qc_params *rp, base;
    qc_quilt_params qp;
    qc_stitch_params sp;
    int rc;

    qcw__drop_result(job);
    qc_region_free(&job->ctx, &job->region);
    qc_clear_error(&job->ctx);
    if (job->patches.n == 0)
        return qcw__fail(job, QC_EEMPTY, "no quilt top loaded%s", "");
    jobs = calloc(job->patches.n, sizeof *jobs);
    rp = calloc(job->nrules + 1, sizeof *rp);
    rc = jobs == NULL || rp == NULL ? qcw__fail(job, QC_ENOMEM, "out of memory%s", "")
                                    : choose(job, jobs, rp, &base);
    memset(&qp, 0, sizeof qp);
    qp.join = join;
    if (rc == QC_OK)
        rc = qc_quilt(&job->ctx, &job->patches, jobs, &qp, &job->quilt);
    if (rc == QC_OK)
        rc = qc_patches_outlines(&job->ctx, &job->patches, &job->region);
    if (rc == QC_OK) {
        qc_quilt_to_origin(&job->quilt, &job->region);
        memset(&sp, 0, sizeof sp);
        sp.tie_stitches = tie_stitches;
        job->top_pieces = qc_path_pieces(&job->quilt.path);
        /* the plan takes the line: at a king-size top the path and its
         * flattened stitches are never both whole in the page's memory */
        rc = qc_stitch_plan_taking(&job->ctx, &job->quilt.path, NULL, &sp, &job->plan);
    }
    free(jobs);
    free(rp);
    if (rc < 0) {
        qcw__drop_result(job);
        qc_region_free(&job->ctx, &job->region);
        return rc;
    }
    job->sewn = 1;
    return QC_OK;
}

const char *qcw_ditch_json(qcw_job *job)
{
    const qc_path *d = &job->quilt.ditch;
    qcw_text out = {0};
    size_t c, p = 0;
    int open = 0;

    qcw__add(&out, "[");
    for (c = 0; c < d->ncmd && job->sewn; c++) {
        if (d->cmd[c] == QC_PATH_MOVE) {
            qcw__add(&out, "%s[", open ? "]," : "");
            open = 1;
        } else if (d->cmd[c] != QC_PATH_LINE)
            break; /* the travel is straight runs along seams */
        qcw__add(&out, "%s%.3f,%.3f", d->cmd[c] == QC_PATH_MOVE ? "" : ",", d->pt[p].x, d->pt[p].y);
        p++;
    }
    qcw__add(&out, "%s]", open ? "]" : "");
    return qcw__finish_json(job, &out);
}

/* One patch's figures, as quiltc quilt --stats prints them. */
static void add_patch_stats(qcw_text *out, const qcw_job *job, size_t i)
{
    const qc_patch_result *pr = &job->quilt.patch[i];

    qcw__add(out, "%s{\"patch\":%lu,\"id\":", i ? "," : "", (unsigned long)i + 1);
    qcw__add_str(out, job->patches.p[i].id);
    qcw__add(out, ",\"line\":%lu,\"rule\":", job->patches.p[i].line);
    if (job->chosen[i] != 0)
        qcw__add(out, "\"rules[%lu]\"", (unsigned long)job->chosen[i] - 1);
    else
        qcw__add(out, "\"default\"");
    qcw__add(out, ",\"family\":");
    qcw__add_str(out, pr->order == SIZE_MAX ? "none" : qc_family_name(pr->family));
    if (pr->order != SIZE_MAX)
        qcw__add(out, ",\"order\":%lu,\"length_mm\":%.3f,\"largest_gap_mm\":%.3f,\"pieces\":%lu,"
                 "\"farthest_fabric_mm\":%.3f,\"seam_bare\":%.4f%s",
                 (unsigned long)pr->order + 1, pr->length_mm, pr->largest_gap_mm,
                 (unsigned long)pr->pieces, pr->farthest_fabric_mm, pr->seam_bare,
                 pr->ditch_only ? ",\"ditch_only\":true" : "");
    qcw__add(out, "}");
}

const char *qcw_quilt_stats_json(qcw_job *job)
{
    const qc_quilt_result *r = &job->quilt;
    qc_plan_estimate est;
    qcw_text out = {0};
    double total = 0;
    size_t i, quilted = 0;

    if (!job->sewn)
        return "null";
    qc_plan_estimate_get(&job->plan, 0, 0, &est);
    qcw__add(&out, "{\"patches\":[");
    for (i = 0; i < r->npatch; i++) {
        add_patch_stats(&out, job, i);
        if (r->patch[i].order != SIZE_MAX) {
            total += r->patch[i].length_mm;
            quilted++;
        }
    }
    qcw__add(&out, "],\"quilted\":%lu,\"unquilted\":%lu,\"pattern_mm\":%.3f,\"ditch_mm\":%.3f,"
                   "\"link_mm\":%.3f,\"jumps\":%lu,\"pieces\":%lu,\"sewn_mm\":%.3f,"
                   "\"stitch_points\":%lu,\"stitches\":%lu,\"thread_mm\":%.1f,\"sew_seconds\":%.1f}",
             (unsigned long)quilted, (unsigned long)(r->npatch - quilted), total, r->ditch_mm,
             r->link_mm, (unsigned long)est.jumps, (unsigned long)job->top_pieces,
             est.sewn_mm, (unsigned long)job->plan.n, (unsigned long)est.stitches, est.thread_mm,
             est.seconds);
    return qcw__finish_json(job, &out);
}
