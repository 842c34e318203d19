/* --stats: the figures of one pattern as a JSON object (cJSON). */
#include <cjson/cJSON.h>
#include <stdlib.h>

#include "stats_json.h"

static void add_bbox(cJSON *obj, const char *name, qc_bbox b)
{
    double v[4];
    v[0] = b.min.x;
    v[1] = b.min.y;
    v[2] = b.max.x;
    v[3] = b.max.y;
    cJSON_AddItemToObject(obj, name, cJSON_CreateDoubleArray(v, 4));
}

static void add_family_figures(cJSON *o, const qc_stats *s)
{
    if (s->motifs_placed + s->motifs_skipped > 0) {
        cJSON_AddNumberToObject(o, "motifs_placed", (double)s->motifs_placed);
        cJSON_AddNumberToObject(o, "motifs_shrunk", (double)s->motifs_shrunk);
        cJSON_AddNumberToObject(o, "motifs_rotated", (double)s->motifs_rotated);
        cJSON_AddNumberToObject(o, "motifs_flipped", (double)s->motifs_flipped);
        cJSON_AddNumberToObject(o, "motifs_skipped", (double)s->motifs_skipped);
        cJSON_AddNumberToObject(o, "joins_unfixed", (double)s->joins_unfixed);
    }
    if (s->pebbles > 0) {
        cJSON_AddNumberToObject(o, "pebbles", (double)s->pebbles);
        cJSON_AddNumberToObject(o, "pebbles_under3", (double)s->pebbles_under3);
        cJSON_AddNumberToObject(o, "radius_min_mm", s->radius_min);
        cJSON_AddNumberToObject(o, "radius_mean_mm", s->radius_mean);
        cJSON_AddNumberToObject(o, "radius_max_mm", s->radius_max);
        cJSON_AddNumberToObject(o, "coverage", s->coverage);
    }
    if (s->farthest_fabric_mm > 0) {
        cJSON_AddNumberToObject(o, "farthest_fabric_mm", s->farthest_fabric_mm);
        cJSON_AddNumberToObject(o, "seam_bare", s->seam_bare);
    }
    if (s->largest_gap_mm > 0)
        cJSON_AddNumberToObject(o, "largest_gap_mm", s->largest_gap_mm);
}

double cli_bobbins(const qc_plan_estimate *est, const cli_sewing *sew)
{
    return sew->bobbin_mm > 0 ? est->sewn_mm * 1.1 / sew->bobbin_mm : 0;
}

void cli_stats_print(FILE *f, const qc_result *res, const qc_plan *plan, const cli_timer *t,
                     const cli_sewing *sew)
{
    cJSON *o = cJSON_CreateObject(), *ms;
    qc_plan_estimate est;
    size_t i;
    char *text;

    if (o == NULL)
        return;
    qc_plan_estimate_get(plan, sew->spi, sew->speed_mm_s, &est);
    cJSON_AddStringToObject(o, "family", qc_family_name(res->params.family));
    cJSON_AddNumberToObject(o, "points", (double)res->stats.points);
    cJSON_AddNumberToObject(o, "edges", (double)res->stats.edges);
    cJSON_AddNumberToObject(o, "order", (double)res->stats.order);
    cJSON_AddNumberToObject(o, "pieces", (double)res->stats.pieces);
    cJSON_AddNumberToObject(o, "length_mm", res->stats.length_mm);
    add_bbox(o, "bbox_mm", res->stats.bbox);
    cJSON_AddNumberToObject(o, "stitch_points", (double)plan->n);
    cJSON_AddNumberToObject(o, "stitches", (double)est.stitches);
    cJSON_AddNumberToObject(o, "thread_mm", est.thread_mm);
    cJSON_AddNumberToObject(o, "spi", sew->spi);
    cJSON_AddNumberToObject(o, "sew_seconds", est.seconds);
    if (sew->bobbin_mm > 0)
        cJSON_AddNumberToObject(o, "bobbins", cli_bobbins(&est, sew));
    add_family_figures(o, &res->stats);
    ms = cJSON_AddObjectToObject(o, "ms");
    for (i = 0; ms != NULL && i < t->n; i++)
        cJSON_AddNumberToObject(ms, t->name[i], t->ms[i]);
    if (ms != NULL) /* wall time, so a stage left untimed would show as a gap */
        cJSON_AddNumberToObject(ms, "total", t->last - t->t0);
    text = cJSON_PrintUnformatted(o);
    if (text != NULL) {
        fprintf(f, "%s\n", text);
        free(text);
    }
    cJSON_Delete(o);
}
