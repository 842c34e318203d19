/*
 * Issue 16's goals on pieced shapes: every family at two spacings and two
 * seeds on triangles, star points, diamonds, strips, a crescent, a ring, a
 * block with holes, a C-shape and a heart. QC_COVERAGE_TABLE=1 prints the
 * measures (docs/coverage.md has the table).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "pieced.h"
#include "quiltc.h"
#include "retrace.h"
#include "testalloc.h"
#include "unity.h"

#define IN 25.4
#define TOL_OUT (0.02 * IN) /* measures-and-peers.md: region grown by 0.02 in */
#define NBIN 4

static const double bin_deg[NBIN] = {90, 45, 36, 31};
static const double bin_lo[NBIN] = {80, 41, 34, 25}, bin_hi[NBIN] = {100, 50, 41, 34};
static const double spacings_in[2] = {0.35, 0.6};
static const uint64_t seeds[2] = {1, 2};

typedef struct figs {
    int runs, failed;
    char why[QC_ERRMSG_MAX + 8];
    double corner[NBIN]; /* worst corner reach / d per bin, -1 none */
    double farthest;     /* / d */
    double seam;
    size_t outside;      /* segments outside, summed over runs */
    int runs_outside;
    double outside_mm;
    size_t crossings;    /* worst run */
    double retrace;
    size_t passes;
    size_t beyond_box;   /* points of the flattened path beyond the region's box */
} figs;

static figs table[QC_FAMILY_COUNT][16];
static size_t nshapes;
static const pieced_shape *shapes;
static int measured;

void setUp(void) {}
void tearDown(void) {}

static void figs_init(figs *f)
{
    int b;
    memset(f, 0, sizeof *f);
    for (b = 0; b < NBIN; b++)
        f->corner[b] = -1;
}

static void measure_one(qc_ctx *ctx, const qc_region *r, const qc_result *res, double d,
                        figs *f)
{
    qc_points flat = {0};
    qc_order ends = {0};
    qc_fabric fab;
    double *corner = malloc((r->nv ? r->nv : 1) * sizeof *corner), share = 0, worst = 0;
    qc_bbox box = qc_region_bbox(r);
    size_t i, out = 0, cross = 0, passes = 1, b = 0, q;
    int k;

    TEST_ASSERT_NOT_NULL(corner);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_curve_flatten(ctx, &res->path, 0.01, &flat, &ends));
    for (i = 0; i < flat.n; i++) {
        qc_vec2 p = flat.v[i];
        f->beyond_box += p.x < box.min.x || p.y < box.min.y || p.x > box.max.x || p.y > box.max.y;
    }
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_fabric_measure(ctx, r, flat.v, flat.n, ends.i, ends.n,
                                                   fmin(d / 10, 0.5), 0, corner, &fab));
    for (i = 0; i < r->nv; i++) {
        double a = qc_region_corner_angle(r, i);
        for (k = 0; k < NBIN; k++)
            if (a >= bin_lo[k] && a < bin_hi[k])
                f->corner[k] = fmax(f->corner[k], corner[i] / d);
    }
    f->farthest = fmax(f->farthest, fab.farthest_mm / d);
    f->seam = fmax(f->seam, fab.seam_bare);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_outside(ctx, r, flat.v, flat.n, ends.i, ends.n,
                                                 TOL_OUT, 0.254, &out, &worst, NULL));
    f->outside += out;
    f->runs_outside += out > 0;
    f->outside_mm = fmax(f->outside_mm, worst);
    for (q = 0; q < ends.n; q++) { /* crossings within each sewn piece */
        size_t c = 0;
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_self_crossings(ctx, flat.v + b, ends.i[q] - b, 0, &c));
        cross += c;
        b = ends.i[q];
    }
    if (cross > f->crossings)
        f->crossings = cross;
    TEST_ASSERT_EQUAL_INT(0, retrace_measure(flat.v, flat.n, ends.i, ends.n, &share, &passes));
    f->retrace = fmax(f->retrace, share);
    if (passes > f->passes)
        f->passes = passes;
    free(corner);
    qc_points_free(ctx, &flat);
    qc_order_free(ctx, &ends);
}

static void run_all(void)
{
    qc_ctx ctx;
    size_t k, s, e;
    int fam;

    if (measured)
        return;
    measured = 1;
    shapes = pieced_shapes(&nshapes);
    qc_ctx_init(&ctx, NULL, NULL);
    for (fam = 1; fam < QC_FAMILY_COUNT; fam++)
        for (k = 0; k < nshapes; k++) {
            qc_region r;
            figs *f = &table[fam][k];

            figs_init(f);
            TEST_ASSERT_EQUAL_INT(QC_OK, pieced_build(&ctx, k, &r));
            for (s = 0; s < 2; s++)
                for (e = 0; e < 2; e++) {
                    qc_params p;
                    qc_result res;
                    int rc;

                    memset(&p, 0, sizeof p);
                    p.skip_gap_stat = 1;
                    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "family", fam));
                    TEST_ASSERT_EQUAL_INT(QC_OK, qc_params_set(&ctx, &p, "spacing",
                                                               spacings_in[s] * IN));
                    p.seed = seeds[e];
                    f->runs++;
                    rc = qc_generate(&ctx, &r, &p, NULL, NULL, &res);
                    if (rc < 0) {
                        f->failed++;
                        snprintf(f->why, sizeof f->why, "%s", ctx.msg);
                        continue;
                    }
                    measure_one(&ctx, &r, &res, spacings_in[s] * IN, f);
                    qc_result_free(&ctx, &res);
                }
            qc_region_free(&ctx, &r);
        }
}

/* Worst over shapes, spacings and seeds, per family: docs/coverage.md's table. */
static void print_summary(void)
{
    size_t k;
    int fam, b;

    printf("\n| family | failed runs | 90 deg | 45 deg | 36 deg | 31 deg | farthest / d (no sharp "
           "points) | farthest / d (all) | seam > 1/4 in (no sharp points) | seam > 1/4 in (all) | "
           "segments outside (runs) | worst outside mm | self-crossings (worst run) | "
           "retrace (worst) | most passes |\n");
    printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (fam = 1; fam < QC_FAMILY_COUNT; fam++) {
        double corner[NBIN] = {-1, -1, -1, -1}, far_plain = 0, far_all = 0, seam_plain = 0;
        double seam_all = 0, out_mm = 0, retrace = 0;
        size_t outside = 0, crossings = 0, passes = 0;
        int failed = 0, runs = 0, runs_outside = 0;

        for (k = 0; k < nshapes; k++) {
            const figs *f = &table[fam][k];
            for (b = 0; b < NBIN; b++)
                corner[b] = fmax(corner[b], f->corner[b]);
            failed += f->failed;
            runs += f->runs;
            far_all = fmax(far_all, f->farthest);
            seam_all = fmax(seam_all, f->seam);
            if (!shapes[k].sharp) {
                far_plain = fmax(far_plain, f->farthest);
                seam_plain = fmax(seam_plain, f->seam);
            }
            outside += f->outside;
            runs_outside += f->runs_outside;
            out_mm = fmax(out_mm, f->outside_mm);
            crossings = f->crossings > crossings ? f->crossings : crossings;
            retrace = fmax(retrace, f->retrace);
            passes = f->passes > passes ? f->passes : passes;
        }
        printf("| %s | %d/%d |", qc_family_name(fam), failed, runs);
        for (b = 0; b < NBIN; b++)
            printf(" %.2f |", corner[b]);
        printf(" %.2f | %.2f | %.0f%% | %.0f%% | %lu (%d) | %.2f | %lu | %.0f%% | %lu |\n",
               far_plain, far_all, 100 * seam_plain, 100 * seam_all, (unsigned long)outside,
               runs_outside, out_mm, (unsigned long)crossings, 100 * retrace,
               (unsigned long)passes);
    }
}

static void print_table(void)
{
    size_t k;
    int fam, b;

    if (getenv("QC_COVERAGE_TABLE") == NULL)
        return;
    printf("\n| family | shape | fail | 90 | 45 | 36 | 31 | farthest/d | seam>1/4in | "
           "outside segs (runs) | out mm | crossings | retrace | passes |\n");
    printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (fam = 1; fam < QC_FAMILY_COUNT; fam++)
        for (k = 0; k < nshapes; k++) {
            const figs *f = &table[fam][k];
            printf("| %s | %s | %d/%d | ", qc_family_name(fam), shapes[k].name, f->failed,
                   f->runs);
            for (b = 0; b < NBIN; b++)
                if (f->corner[b] >= 0)
                    printf("%.2f | ", f->corner[b]);
                else
                    printf("- | ");
            printf("%.2f | %.0f%% | %lu (%d) | %.2f | %lu | %.0f%% | %lu |%s%s\n", f->farthest,
                   100 * f->seam, (unsigned long)f->outside, f->runs_outside, f->outside_mm,
                   (unsigned long)f->crossings, 100 * f->retrace, (unsigned long)f->passes,
                   f->failed ? " " : "", f->failed ? f->why : "");
        }
    print_summary();
}

static void corpus_should_generate_and_measure(void)
{
    run_all();
    print_table();
    TEST_ASSERT_TRUE(nshapes >= 13);
}

/* Goal: points or segments outside (sampled every 0.01 in against the
 * region grown by 0.02 in): 0, every family, every shape, spacing and seed. */
static void every_family_should_keep_every_stitch_inside(void)
{
    char msg[200];
    size_t k;
    int fam;

    run_all();
    for (fam = 1; fam < QC_FAMILY_COUNT; fam++)
        for (k = 0; k < nshapes; k++) {
            snprintf(msg, sizeof msg, "%s on %s: %lu segments outside, up to %.2f mm",
                     qc_family_name(fam), shapes[k].name, (unsigned long)table[fam][k].outside,
                     table[fam][k].outside_mm);
            TEST_ASSERT_EQUAL_size_t_MESSAGE(0, table[fam][k].outside, msg);
        }
}

/* Goal: corner to nearest stitch, worst over shapes, spacings and seeds:
 * 90 deg <= 0.9 d, 45 <= 1.3 d, 36 <= 1.5 d, 31 <= 1.6 d (exact distances
 * from the corner vertex to the path flattened to 0.01 mm; no tolerance).
 * Pebbling and packing put a pebble into each corner (shared_pebble_pack.c,
 * phase 3): measured 0.39, 0.61, 0.72 and 0.87 d at worst. */
static void families_should_reach_into_corners(void)
{
    static const double goal[NBIN] = {0.9, 1.3, 1.5, 1.6};
    static const int meets[] = {QC_FAMILY_VINE, QC_FAMILY_BRANCHING, QC_FAMILY_WANDERER,
                                QC_FAMILY_FILL, QC_FAMILY_STIPPLE, QC_FAMILY_ECHO,
                                QC_FAMILY_SPIRAL, QC_FAMILY_MEANDER, QC_FAMILY_PEBBLING,
                                QC_FAMILY_PACKING};
    char msg[200];
    size_t k, m;
    int fam, b;

    run_all();
    for (m = 0; m < sizeof meets / sizeof meets[0]; m++) {
        fam = meets[m];
        for (k = 0; k < nshapes; k++)
            for (b = 0; b < NBIN; b++) {
                snprintf(msg, sizeof msg, "%s on %s: %.0f deg corner %.2f d from a stitch",
                         qc_family_name(fam), shapes[k].name, bin_deg[b], table[fam][k].corner[b]);
                if (!(table[fam][k].corner[b] <= goal[b]))
                    TEST_FAIL_MESSAGE(msg);
            }
    }
}

/* The families built on the points' tree or tour, which the row along the
 * seams (src/sample/contour.c) carries out to them, and the two whose
 * pebbles go into the corners and along the seams themselves. */
static const int to_seams[] = {QC_FAMILY_VINE, QC_FAMILY_BRANCHING, QC_FAMILY_WANDERER,
                               QC_FAMILY_FILL, QC_FAMILY_STIPPLE, QC_FAMILY_PEBBLING,
                               QC_FAMILY_PACKING};
#define NTO_SEAMS (sizeof to_seams / sizeof to_seams[0])

/* Goal: no fabric farther than 1.0 d from a stitch (worst over spacings and
 * seeds) on the shapes without points sharper than 60 deg; 1.6 d with them
 * (the margin keeps a tip bare: a 23 deg horn 1.5 d deep). Measured 0.98 and
 * 1.55 d at worst (vine; docs/coverage.md); pebbling 0.84 and 0.87 d,
 * packing 0.73 and 0.87 d. */
static void families_should_leave_no_fabric_far_from_a_stitch(void)
{
    char msg[200];
    size_t k, m;

    run_all();
    for (m = 0; m < NTO_SEAMS; m++)
        for (k = 0; k < nshapes; k++) {
            const figs *f = &table[to_seams[m]][k];
            snprintf(msg, sizeof msg, "%s on %s: fabric %.2f d from a stitch",
                     qc_family_name(to_seams[m]), shapes[k].name, f->farthest);
            if (!(f->farthest <= (shapes[k].sharp ? 1.6 : 1.0)))
                TEST_FAIL_MESSAGE(msg);
        }
}

/* Goal: at most 15% of the seams farther than 1/4 in from a stitch at
 * d = 0.35 and 0.6 in; asserted 12% on shapes without sharp points and 15%
 * with them (a margin of 0.3 d keeps the last d or so of a 30-45 deg tip
 * bare). Measured 10% (wanderer, the heart's cusp) and 13% (vine, fill:
 * the crescent and the 5-point star at 0.6 in) at worst (docs/coverage.md);
 * pebbling 1% and 6%, packing 8% and 9% (its motifs fill a pebble less
 * than its circle). */
static void families_should_stitch_along_the_seams(void)
{
    char msg[200];
    size_t k, m;

    run_all();
    for (m = 0; m < NTO_SEAMS; m++)
        for (k = 0; k < nshapes; k++) {
            const figs *f = &table[to_seams[m]][k];
            snprintf(msg, sizeof msg, "%s on %s: %.0f%% of the seams farther than 1/4 in",
                     qc_family_name(to_seams[m]), shapes[k].name, 100 * f->seam);
            if (!(f->seam <= (shapes[k].sharp ? 0.15 : 0.12)))
                TEST_FAIL_MESSAGE(msg);
        }
}

/* Echo and spiral (offset rings d apart, caps on the peaks a level
 * misses): no fabric farther than 1.0 d from a stitch on the shapes without
 * points sharper than 60 deg (1.05 d on the C-shape before the caps;
 * measured 0.95 d at worst), 1.5 d with them (the margin's floor at a 23 deg
 * horn); no crossing, at most 2 passes and 1% of the thread over an
 * earlier pass (measured 0.13% at worst). */
static void offset_rings_should_cover_and_never_pile_up(void)
{
    static const int rings[] = {QC_FAMILY_ECHO, QC_FAMILY_SPIRAL};
    char msg[200];
    size_t k, m;

    run_all();
    for (m = 0; m < 2; m++)
        for (k = 0; k < nshapes; k++) {
            const figs *f = &table[rings[m]][k];
            snprintf(msg, sizeof msg, "%s on %s: fabric %.2f d from a stitch, %lu crossings, "
                     "%.2f%% retraced, %lu passes", qc_family_name(rings[m]), shapes[k].name,
                     f->farthest, (unsigned long)f->crossings, 100 * f->retrace,
                     (unsigned long)f->passes);
            if (!(f->farthest <= (shapes[k].sharp ? 1.5 : 1.0)) || f->crossings != 0 ||
                f->passes > 2 || !(f->retrace <= 0.01))
                TEST_FAIL_MESSAGE(msg);
        }
}

/* Stipple and fill outline the tree as one loop that never crosses itself,
 * a row of collinear points along a seam included; pebbling draws the
 * outline of its pebbles, the ones in corners and along seams included
 * (they hang from a pebble they touch, never by a straight stitch). */
static void outlines_should_not_cross_themselves(void)
{
    static const int outline[] = {QC_FAMILY_FILL, QC_FAMILY_STIPPLE, QC_FAMILY_PEBBLING};
    char msg[200];
    size_t k, m;

    run_all();
    for (m = 0; m < sizeof outline / sizeof outline[0]; m++)
        for (k = 0; k < nshapes; k++) {
            snprintf(msg, sizeof msg, "%s on %s: %lu self-crossings", qc_family_name(outline[m]),
                     shapes[k].name, (unsigned long)table[outline[m]][k].crossings);
            TEST_ASSERT_EQUAL_size_t_MESSAGE(0, table[outline[m]][k].crossings, msg);
        }
}

/* Every point of the path flattened to 0.01 mm lies in the region's box:
 * what `quiltc job` and generate's guard check (cli/inside_guard.c). A
 * cubic's control points may lie past the seam (pebbles, leaves along the
 * row) while the curve stays inside; they are no longer pulled in. */
static void every_stitch_should_lie_in_the_box(void)
{
    char msg[200];
    size_t k;
    int fam;

    run_all();
    for (fam = 1; fam < QC_FAMILY_COUNT; fam++)
        for (k = 0; k < nshapes; k++) {
            snprintf(msg, sizeof msg, "%s on %s: %lu points of the flattened path beyond the box",
                     qc_family_name(fam), shapes[k].name,
                     (unsigned long)table[fam][k].beyond_box);
            TEST_ASSERT_EQUAL_size_t_MESSAGE(0, table[fam][k].beyond_box, msg);
        }
}

/* Every family makes a pattern on every shape at both spacings (the 0.75 in
 * border at d = 0.6 in gets one row of points instead of "no point fits"). */
static void every_family_should_fill_every_shape(void)
{
    char msg[QC_ERRMSG_MAX + 100];
    size_t k;
    int fam;

    run_all();
    for (fam = 1; fam < QC_FAMILY_COUNT; fam++)
        for (k = 0; k < nshapes; k++) {
            snprintf(msg, sizeof msg, "%s on %s: %s", qc_family_name(fam), shapes[k].name,
                     table[fam][k].why);
            TEST_ASSERT_EQUAL_INT_MESSAGE(0, table[fam][k].failed, msg);
        }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(corpus_should_generate_and_measure);
    RUN_TEST(every_family_should_keep_every_stitch_inside);
    RUN_TEST(families_should_reach_into_corners);
    RUN_TEST(every_family_should_fill_every_shape);
    RUN_TEST(families_should_leave_no_fabric_far_from_a_stitch);
    RUN_TEST(families_should_stitch_along_the_seams);
    RUN_TEST(offset_rings_should_cover_and_never_pile_up);
    RUN_TEST(outlines_should_not_cross_themselves);
    RUN_TEST(every_stitch_should_lie_in_the_box);
    return UNITY_END();
}
