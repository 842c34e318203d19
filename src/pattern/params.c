/*
 * The parameter table: one row per field of qc_params, the single place
 * where names, units, ranges and defaults live (the CLI and the web page
 * build their controls from it), and qc_params_resolve.
 */
#include <math.h>
#include <stddef.h>
#include <string.h>

#include "internal.h"

#define OFF(field) offsetof(qc_params, field)
#define ID(name) QC_PARAM_ID_##name
#define BIT(name) QC_PARAM_BIT(QC_PARAM_ID_##name)

/* Parameters every family takes, and those of the skeleton (families with
 * QC_FAMILY_NEEDS_POINTS); the rest belong to the families that list them. */
#define P_EVERY (BIT(FAMILY) | BIT(SEED) | BIT(SPACING) | BIT(MARGIN) | BIT(START_X) | \
                 BIT(START_Y))
#define P_SKELETON (BIT(POINTS) | BIT(SKELETON) | BIT(MST) | BIT(TSP) | BIT(TSP_TIME))

/* "|vine|branching|...": the family row's choices, after the first bar. */
#define FAMILY_CHOICE(id, name) "|" #name
static const char family_choices[] = QC_FAMILY_MAP(FAMILY_CHOICE);
#undef FAMILY_CHOICE
#define FAMILY_NAMES (family_choices + 1)

static const qc_param_info table[] = {
    {"family", "pattern family (default stipple)", "", QC_PARAM_ENUM, FAMILY_NAMES,
     1, QC_FAMILY_COUNT - 1, QC_FAMILY_STIPPLE, 0, ID(FAMILY), OFF(family)},
    {"points", "point distribution (default: snub for pebbling/packing, else poisson)", "",
     QC_PARAM_ENUM, "triangle|square|hex|snub|poisson|given", 1, 6, QC_POINTS_POISSON, 0,
     ID(POINTS),
     OFF(points)},
    {"skeleton", "skeleton path (default: tsp for wanderer, else mst)", "", QC_PARAM_ENUM,
     "mst|tsp", 1, 2, QC_SKELETON_MST, 0, ID(SKELETON), OFF(skeleton)},
    {"mst", "spanning tree graph", "", QC_PARAM_ENUM, "delaunay|complete", 1, 2,
     QC_MST_MODE_DELAUNAY, 0, ID(MST), OFF(mst)},
    {"tsp", "tour improvement", "", QC_PARAM_ENUM, "greedy|2opt|oropt|or3opt", 1, 4,
     QC_TSP_METHOD_OR3OPT, 0, ID(TSP), OFF(tsp)},
    {"edge", "pebbles at the boundary", "", QC_PARAM_ENUM, "strict|overgrow", 1, 2,
     QC_EDGE_STRICT, 0, ID(EDGE), OFF(edge)},
    {"tile", "repeatable tile", "", QC_PARAM_ENUM, "none|edge-to-edge|all-over", 1, 3,
     QC_TILE_NONE, 0, ID(TILE), OFF(tile)},
    {"tip", "decoration at branch tips", "", QC_PARAM_ENUM, "none|circle", 1, 2,
     QC_TIP_NONE, 0, ID(TIP), OFF(tip)},
    {"spiral", "spiral kind", "", QC_PARAM_ENUM, "archimedean|fermat", 1, 2,
     QC_SPIRAL_ARCHIMEDEAN, 0, ID(SPIRAL), OFF(spiral)},
    {"echo-join", "how echo rings join", "", QC_PARAM_ENUM, "spiral|rings", 1, 2,
     QC_ECHO_RINGS, 0, ID(ECHO_JOIN), OFF(echo_join)},
    {"seed", "random seed", "", QC_PARAM_SEED, NULL, 0, 18446744073709551615.0, 1, 0,
     ID(SEED), OFF(seed)},
    {"spacing", "point distance d", "mm", QC_PARAM_LENGTH, NULL, 0.5, 1000, 12.7, 0,
     ID(SPACING), OFF(spacing)},
    {"margin", "distance kept from the boundary", "mm", QC_PARAM_LENGTH, NULL, 0, 1000,
     0, 0.3, ID(MARGIN), OFF(margin)},
    {"size", "motif size s", "mm", QC_PARAM_LENGTH, NULL, 0.1, 1000, 0, 0.5, ID(SIZE),
     OFF(size)},
    {"gap", "gap l between motifs along the vine", "mm", QC_PARAM_LENGTH, NULL, 0, 1000,
     0, 0.2, ID(GAP), OFF(gap)},
    {"angle", "motif angle alpha to the vine", "deg", QC_PARAM_REAL, NULL, -90, 90, 45, 0,
     ID(ANGLE), OFF(angle)},
    {"tangent", "tangent length l of the joins, times the join's length", "ratio",
     QC_PARAM_REAL, NULL, 0, 2, 0.5, 0, ID(TANGENT), OFF(tangent)},
    {"r-seed", "root pebble radius, times d", "ratio", QC_PARAM_REAL, NULL, 0.5, 1, 0.7, 0,
     ID(R_SEED), OFF(r_seed)},
    {"width", "fill width w (default d/5; stipple d/3)", "mm", QC_PARAM_LENGTH, NULL, 0.05,
     1000, 0, 0.2, ID(WIDTH), OFF(width)},
    {"tsp-time", "extra tour improvement (perturbation budget)", "ms", QC_PARAM_REAL, NULL,
     0, 600000, 0, 0, ID(TSP_TIME), OFF(tsp_time_ms)},
    {"repeat-cols", "tiles across", "count", QC_PARAM_INT, NULL, 1, 100, 1, 0, ID(REPEAT_COLS),
     OFF(repeat_cols)},
    {"repeat-rows", "tiles down", "count", QC_PARAM_INT, NULL, 1, 100, 1, 0, ID(REPEAT_ROWS),
     OFF(repeat_rows)},
    {"start-x", "start near this x (the nearest point becomes the root)", "mm",
     QC_PARAM_LENGTH, NULL, -1e6, 1e6, 0, 0, ID(START_X), OFF(start_x)},
    {"start-y", "start near this y", "mm", QC_PARAM_LENGTH, NULL, -1e6, 1e6, 0, 0, ID(START_Y),
     OFF(start_y)},
    {"wiggle", "meander irregularity: 0 smooth, 1 restless", "ratio", QC_PARAM_REAL, NULL, 0, 1,
     0.5, 0, ID(WIGGLE), OFF(wiggle)},
    {"turn-radius", "meander's smallest turn radius (default d/4)", "mm", QC_PARAM_LENGTH, NULL,
     0.05, 1000, 0, 0.25, ID(TURN_RADIUS), OFF(turn_radius)},
    {"iterations", "meander: rounds of curve evolution (work, not time)", "count", QC_PARAM_INT,
     NULL, 0, 100000, 60, 0, ID(ITERATIONS), OFF(iterations)},
    {"offset", "pantograph rows: every other row moved by this fraction of a tile's width",
     "ratio", QC_PARAM_REAL, NULL, 0, 0.95, 0, 0, ID(ROW_OFFSET), OFF(row_offset)},
};

#define NPARAMS (sizeof table / sizeof table[0])

const qc_param_info *qc_param_table(size_t *count)
{
    *count = NPARAMS;
    return table;
}

const qc_param_info *qc_param_by_id(int id)
{
    size_t i;

    for (i = 0; i < NPARAMS; i++)
        if ((int)table[i].id == id)
            return &table[i];
    return NULL;
}

uint32_t qc_param_families(const qc_param_info *row)
{
    uint64_t bit = QC_PARAM_BIT(row->id);
    uint32_t mask = 0;
    const qc_family_desc *f;
    size_t i;

    for (i = 0; (f = qc_family_info(i)) != NULL; i++) {
        uint64_t takes = P_EVERY | f->params;

        if (f->needs & QC_FAMILY_NEEDS_POINTS)
            takes |= P_SKELETON;
        if (takes & bit)
            mask |= 1u << f->id;
    }
    return mask;
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
    return choice_index(FAMILY_NAMES, name);
}

const char *qc_family_name(int family)
{
    const qc_family_desc *f = qc__family(family);

    if (family == QC_FAMILY_DEFAULT)
        return "default";
    return f != NULL ? f->name : NULL;
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
    p->given |= QC_PARAM_BIT(info->id);
    return QC_OK;
}

void qc_params_set_seed(qc_params *p, uint64_t seed)
{
    p->seed = seed;
    p->given |= BIT(SEED);
}

int qc_params_given(const qc_params *p, int id)
{
    return id >= 0 && id < QC_PARAM_ID_COUNT && ((p->given >> id) & 1) != 0;
}

static int is_given(const qc_params *p, const qc_param_info *info)
{
    return qc_params_given(p, (int)info->id);
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

int qc__param_check(qc_ctx *ctx, int id, double value)
{
    const qc_param_info *info = qc_param_by_id(id);

    return info != NULL ? check_range(ctx, info, value)
                        : qc__fail(ctx, QC_EINVAL, "unknown parameter id %d", id);
}

/* Defaults: the family's own (its descriptor's param_default), else the
 * table's, which may scale with the spacing. */
static double family_default(const qc_params *p, const qc_param_info *info)
{
    const qc_family_desc *f = qc__family(p->family);
    double v;

    if (f != NULL && f->param_default != NULL && f->param_default(p, (int)info->id, &v))
        return v;
    if (info->def_per_spacing != 0.0)
        return info->def_per_spacing * p->spacing;
    return info->def;
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
            int early = info->id == ID(FAMILY) || info->id == ID(SPACING);

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
