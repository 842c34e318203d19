/*
 * The parameter table: one row per field of qc_params, the single place
 * where names, units, ranges and defaults live (the CLI and the web page
 * build their controls from it), and qc_params_resolve.
 */
#include <math.h>
#include <stddef.h>
#include <string.h>

#include "internal.h"

#define FAM(f) (1u << QC_FAMILY_##f)
#define F_ALL 0xFFFFFFFFu
#define F_TREE (FAM(VINE) | FAM(BRANCHING) | FAM(PEBBLING) | FAM(PACKING) | FAM(FILL) | FAM(STIPPLE))
#define F_POINTS (F_TREE | FAM(WANDERER))
#define F_MOTIF (FAM(BRANCHING) | FAM(WANDERER))
#define OFF(field) offsetof(qc_params, field)

static const char family_names[] =
    "vine|branching|wanderer|pebbling|packing|fill|stipple|echo|spiral|meander";

static const qc_param_info table[] = {
    {"family", "pattern family (default stipple)", "", QC_PARAM_ENUM, family_names,
     1, QC_FAMILY_COUNT - 1, QC_FAMILY_STIPPLE, 0, F_ALL, OFF(family)},
    {"points", "point distribution (default: snub for pebbling/packing, else poisson)", "",
     QC_PARAM_ENUM, "triangle|square|hex|snub|poisson|given", 1, 6, 0, 0, F_POINTS, OFF(points)},
    {"skeleton", "skeleton path (default: tsp for wanderer, else mst)", "", QC_PARAM_ENUM,
     "mst|tsp", 1, 2, 0, 0, F_POINTS, OFF(skeleton)},
    {"mst", "spanning tree graph", "", QC_PARAM_ENUM, "delaunay|complete", 1, 2,
     QC_MST_DELAUNAY, 0, F_POINTS, OFF(mst)},
    {"tsp", "tour improvement", "", QC_PARAM_ENUM, "greedy|2opt|oropt", 1, 3,
     QC_TSP_OROPT, 0, F_POINTS, OFF(tsp)},
    {"edge", "pebbles at the boundary", "", QC_PARAM_ENUM, "strict|overgrow", 1, 2,
     QC_EDGE_STRICT, 0, FAM(PEBBLING) | FAM(PACKING), OFF(edge)},
    {"tile", "repeatable tile", "", QC_PARAM_ENUM, "none|edge-to-edge|all-over", 1, 3,
     QC_TILE_NONE, 0, FAM(FILL) | FAM(STIPPLE) | FAM(BRANCHING) | FAM(MEANDER), OFF(tile)},
    {"tip", "decoration at branch tips", "", QC_PARAM_ENUM, "none|circle", 1, 2,
     QC_TIP_NONE, 0, FAM(FILL) | FAM(STIPPLE), OFF(tip)},
    {"spiral", "spiral kind", "", QC_PARAM_ENUM, "archimedean|fermat", 1, 2,
     QC_SPIRAL_ARCHIMEDEAN, 0, FAM(SPIRAL), OFF(spiral)},
    {"echo-join", "how echo rings join", "", QC_PARAM_ENUM, "spiral|rings", 1, 2,
     QC_ECHO_RINGS, 0, FAM(ECHO), OFF(echo_join)},
    {"seed", "random seed", "", QC_PARAM_SEED, NULL, 0, 18446744073709551615.0, 1, 0,
     F_ALL, OFF(seed)},
    {"spacing", "point distance d", "mm", QC_PARAM_LENGTH, NULL, 0.5, 1000, 12.7, 0,
     F_ALL, OFF(spacing)},
    {"margin", "distance kept from the boundary", "mm", QC_PARAM_LENGTH, NULL, 0, 1000,
     0, 0.3, F_ALL, OFF(margin)},
    {"size", "motif size s", "mm", QC_PARAM_LENGTH, NULL, 0.1, 1000, 0, 0.5,
     F_MOTIF, OFF(size)},
    {"gap", "gap l between motifs along the vine", "mm", QC_PARAM_LENGTH, NULL, 0, 1000,
     0, 0.2, FAM(BRANCHING), OFF(gap)},
    {"angle", "motif angle alpha to the vine", "deg", QC_PARAM_REAL, NULL, -90, 90, 45, 0,
     FAM(BRANCHING), OFF(angle)},
    {"tangent", "tangent length l of the joins, times the join's length", "ratio",
     QC_PARAM_REAL, NULL, 0, 2, 0.5, 0, FAM(WANDERER), OFF(tangent)},
    {"r-seed", "root pebble radius, times d", "ratio", QC_PARAM_REAL, NULL, 0.5, 1, 0.7, 0,
     FAM(PEBBLING) | FAM(PACKING), OFF(r_seed)},
    {"width", "fill width w (default d/5; stipple d/3)", "mm", QC_PARAM_LENGTH, NULL, 0.05,
     1000, 0, 0.2, FAM(FILL) | FAM(STIPPLE), OFF(width)},
    {"tsp-time", "extra tour improvement (perturbation budget)", "ms", QC_PARAM_REAL, NULL,
     0, 600000, 0, 0, F_POINTS, OFF(tsp_time_ms)},
    {"repeat-cols", "tiles across", "count", QC_PARAM_INT, NULL, 1, 100, 1, 0,
     FAM(FILL) | FAM(STIPPLE) | FAM(BRANCHING) | FAM(MEANDER), OFF(repeat_cols)},
    {"repeat-rows", "tiles down", "count", QC_PARAM_INT, NULL, 1, 100, 1, 0,
     FAM(FILL) | FAM(STIPPLE) | FAM(BRANCHING) | FAM(MEANDER), OFF(repeat_rows)},
    {"start-x", "start near this x (the nearest point becomes the root)", "mm",
     QC_PARAM_LENGTH, NULL, -1e6, 1e6, 0, 0, F_ALL, OFF(start_x)},
    {"start-y", "start near this y", "mm", QC_PARAM_LENGTH, NULL, -1e6, 1e6, 0, 0, F_ALL,
     OFF(start_y)},
    {"wiggle", "meander irregularity: 0 smooth, 1 restless", "ratio", QC_PARAM_REAL, NULL, 0, 1,
     0.5, 0, FAM(MEANDER), OFF(wiggle)},
    {"turn-radius", "meander's smallest turn radius (default d/4)", "mm", QC_PARAM_LENGTH, NULL,
     0.05, 1000, 0, 0.25, FAM(MEANDER), OFF(turn_radius)},
    {"iterations", "meander: rounds of curve evolution (work, not time)", "count", QC_PARAM_INT,
     NULL, 0, 100000, 60, 0, FAM(MEANDER), OFF(iterations)},
};

#define NPARAMS (sizeof table / sizeof table[0])

const qc_param_info *qc_param_table(size_t *count)
{
    *count = NPARAMS;
    return table;
}

const qc_param_info *qc_param_find(const char *name)
{
    size_t i;

    for (i = 0; i < NPARAMS; i++)
        if (strcmp(table[i].name, name) == 0)
            return &table[i];
    return NULL;
}

/* 1-based index of choice in a '|'-separated list, or -1. */
static int choice_index(const char *choices, const char *choice)
{
    size_t len = strlen(choice);
    int k = 1;
    const char *s = choices;

    while (s != NULL && *s != '\0') {
        const char *bar = strchr(s, '|');
        size_t n = bar != NULL ? (size_t)(bar - s) : strlen(s);

        if (n == len && len > 0 && strncmp(s, choice, n) == 0)
            return k;
        s = bar != NULL ? bar + 1 : NULL;
        k++;
    }
    return -1;
}

int qc_param_choice(const qc_param_info *info, const char *choice)
{
    return info->choices != NULL ? choice_index(info->choices, choice) : -1;
}

int qc_family_from_name(const char *name)
{
    return choice_index(family_names, name);
}

const char *qc_family_name(int family)
{
    static const char *const names[QC_FAMILY_COUNT] = {
        "default", "vine", "branching", "wanderer", "pebbling",
        "packing", "fill", "stipple", "echo", "spiral", "meander"};

    return family >= 0 && family < QC_FAMILY_COUNT ? names[family] : NULL;
}

static size_t row_index(const qc_param_info *info)
{
    return (size_t)(info - table);
}

double qc_params_get(const qc_params *p, const qc_param_info *info)
{
    const char *base = (const char *)p + info->offset;
    int iv;
    uint64_t u;
    double d;

    switch (info->type) {
    case QC_PARAM_ENUM:
        memcpy(&iv, base, sizeof iv);
        return iv;
    case QC_PARAM_SEED:
        memcpy(&u, base, sizeof u);
        return (double)u;
    default:
        memcpy(&d, base, sizeof d);
        return d;
    }
}

static void put(qc_params *p, const qc_param_info *info, double value)
{
    char *base = (char *)p + info->offset;

    if (info->type == QC_PARAM_ENUM) {
        int iv = (int)value;
        memcpy(base, &iv, sizeof iv);
    } else if (info->type == QC_PARAM_SEED) {
        uint64_t u = (uint64_t)value;
        memcpy(base, &u, sizeof u);
    } else {
        memcpy(base, &value, sizeof value);
    }
}

int qc_params_set(qc_ctx *ctx, qc_params *p, const char *name, double value)
{
    const qc_param_info *info = qc_param_find(name);

    if (info == NULL)
        return qc__fail(ctx, QC_EINVAL, "unknown parameter '%s'", name);
    if (info->type == QC_PARAM_SEED) {
        if (!(value >= 0.0 && value < 18446744073709551616.0))
            return qc__fail(ctx, QC_ERANGE, "seed %g out of range", value);
    }
    /* enums are stored as int: refuse what no int holds (NaN, inf, huge) */
    if (info->type == QC_PARAM_ENUM && !(value >= info->min && value <= info->max))
        return qc__fail(ctx, QC_EINVAL, "%s %g is not one of %s", info->name, value,
                        info->choices);
    put(p, info, value);
    p->given |= (uint64_t)1 << row_index(info);
    return QC_OK;
}

static int is_given(const qc_params *p, const qc_param_info *info)
{
    return (p->given >> row_index(info)) & 1;
}

static int check_range(qc_ctx *ctx, const qc_param_info *info, double v)
{
    if (info->type == QC_PARAM_SEED)
        return QC_OK;
    if (!isfinite(v) || v < info->min || v > info->max) {
        if (info->type == QC_PARAM_ENUM)
            return qc__fail(ctx, QC_EINVAL, "%s %g is not one of %s", info->name, v,
                            info->choices);
        return qc__fail(ctx, QC_ERANGE, "%s %g %s out of range [%g, %g] %s", info->name,
                        v, info->unit, info->min, info->max, info->unit);
    }
    if (info->type == QC_PARAM_INT && v != floor(v))
        return qc__fail(ctx, QC_ERANGE, "%s %g must be a whole number", info->name, v);
    return QC_OK;
}

/* Defaults that depend on the family or on other parameters. */
static double family_default(const qc_params *p, const qc_param_info *info)
{
    if (info->offset == OFF(points))
        return p->family == QC_FAMILY_PEBBLING || p->family == QC_FAMILY_PACKING
                   ? QC_POINTS_SNUB
                   : QC_POINTS_POISSON;
    if (info->offset == OFF(skeleton))
        return p->family == QC_FAMILY_WANDERER ? QC_SKELETON_TSP : QC_SKELETON_MST;
    if (info->offset == OFF(width) && p->family == QC_FAMILY_STIPPLE)
        return p->spacing / 3.0;
    if (info->def_per_spacing != 0.0)
        return info->def_per_spacing * p->spacing;
    return info->def;
}

int qc__params_given(const qc_params *p, size_t offset)
{
    size_t i;

    for (i = 0; i < NPARAMS; i++)
        if (table[i].offset == offset)
            return is_given(p, &table[i]);
    return 0;
}

int qc_params_resolve(qc_ctx *ctx, const qc_params *in, qc_params *out)
{
    qc_params r = *in;
    size_t i;
    int pass;

    /* pass 0: family and spacing, from which pass 1's defaults derive */
    for (pass = 0; pass < 2; pass++) {
        for (i = 0; i < NPARAMS; i++) {
            const qc_param_info *info = &table[i];
            int early = info->offset == OFF(family) || info->offset == OFF(spacing);

            if (early != (pass == 0))
                continue;
            if (qc_params_get(&r, info) == 0.0 && !is_given(&r, info))
                put(&r, info, family_default(&r, info));
        }
    }
    for (i = 0; i < NPARAMS; i++)
        QC__TRY(check_range(ctx, &table[i], qc_params_get(&r, &table[i])));
    *out = r;
    return QC_OK;
}
