/*
 * The measures' distance raster (qc__gap_transform, src/measure/gap.c):
 * every cell's squared distance to the nearest seeded cell, capped at
 * QC__GAP_FAR, checked cell by cell against brute force on rasters whose
 * seeds are scattered, in one column, one row, one cell, round the border
 * (a region's outline: the rows switch to the envelope) or absent.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "../src/measure/measure_internal.h"
#include "quiltc.h"
#include "testalloc.h"
#include "unity.h"

static testalloc ta;
static qc_ctx ctx;

void setUp(void)
{
    memset(&ta, 0, sizeof ta);
    qc_ctx_init(&ctx, testalloc_fn, &ta);
}

void tearDown(void)
{
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

/* A deterministic scatter: roughly one cell in `every` seeded. */
static int seeded(size_t i, size_t j, unsigned every, unsigned salt)
{
    unsigned h = (unsigned)(i * 2654435761u) ^ (unsigned)(j * 40503u) ^ salt;

    h ^= h >> 13;
    h *= 0x5bd1e995u;
    h ^= h >> 15;
    return every > 0 && h % every == 0;
}

/* qc__gap_transform_far on a copy of g's seeds: every row (rows NULL),
 * then only the rows flagged (two in three), each equal to want there. */
static void check_far(const qc__gap_grid *g, const float *want)
{
    size_t i, j, cells = g->nx * g->ny;
    qc__gap_grid c = *g;
    unsigned char *rows = (unsigned char *)testalloc_fn(&ta, NULL, 0, g->ny);
    int pass;

    c.f = (float *)testalloc_fn(&ta, NULL, 0, cells * sizeof *c.f);
    TEST_ASSERT_NOT_NULL(c.f);
    TEST_ASSERT_NOT_NULL(rows);
    for (j = 0; j < g->ny; j++)
        rows[j] = (unsigned char)(j % 3 != 1);
    for (pass = 0; pass < 2; pass++) {
        memcpy(c.f, g->f, cells * sizeof *c.f);
        TEST_ASSERT_EQUAL_INT(QC_OK, qc__gap_transform_far(&ctx, &c, pass ? rows : NULL));
        for (j = 0; j < g->ny; j++)
            for (i = 0; i < g->nx && (pass == 0 || rows[j]); i++)
                TEST_ASSERT_EQUAL_FLOAT(want[j * g->nx + i], c.f[j * g->nx + i]);
    }
    testalloc_fn(&ta, c.f, cells * sizeof *c.f, 0);
    testalloc_fn(&ta, rows, g->ny, 0);
}

/* qc__edt_1d against the minimum over every cell of (q - p)^2 + f[p], on
 * rows of integer values (FAR among them) as the transforms give it. */
void test_edt_1d_should_match_brute_force(void)
{
    static const size_t len[] = {1, 2, 3, 17, 64, 139};
    double f[139], d[139], z[140];
    int v[139];
    size_t t, n, q, p;
    unsigned salt;

    for (t = 0; t < sizeof len / sizeof *len; t++)
        for (salt = 0; salt < 8; salt++) {
            n = len[t];
            for (q = 0; q < n; q++) {
                unsigned h = (unsigned)seeded(q, n, 1, salt) + (unsigned)(q * 2654435761u ^ salt);
                h ^= h >> 11;
                f[q] = seeded(q, salt, 5, (unsigned)n) ? QC__GAP_FAR : (double)(h % 900u);
            }
            qc__edt_1d(f, n, d, v, z);
            for (q = 0; q < n; q++) {
                double best = HUGE_VAL;
                for (p = 0; p < n; p++) {
                    double dq = (double)q - (double)p, e = dq * dq + f[p];
                    best = e < best ? e : best;
                }
                TEST_ASSERT_EQUAL_DOUBLE(best, d[q]);
            }
        }
}

/* qc__raster_inside against qc_region_contains at every sample, on a comb
 * whose teeth give rows of 2 to 4 * TEETH crossings (sorted by insertion
 * when few, by qsort when many) and a square hole among the teeth' roots. */
#define TEETH 12
void test_raster_inside_should_agree_with_contains(void)
{
    qc_vec2 comb[4 * TEETH + 2], hole[4] = {{3, 2}, {3, 5}, {9, 5}, {9, 2}};
    qc_region r;
    unsigned char *mask;
    size_t k = 0, t, i, j, nx = 140, ny = 90;
    double x0 = -1.013, y0 = -1.007, h = 0.37;

    comb[k++] = QC__V2(0, 0);
    for (t = 0; t < TEETH; t++) { /* along the top: up a tooth, across, down */
        comb[k++] = QC__V2(4.0 * (double)t + 1.0, 8.0);
        comb[k++] = QC__V2(4.0 * (double)t + 1.0, 20.0 + (double)(t % 5));
        comb[k++] = QC__V2(4.0 * (double)t + 3.0, 20.0 + (double)(t % 5));
        comb[k++] = QC__V2(4.0 * (double)t + 3.0, 8.0);
    }
    comb[k++] = QC__V2(4.0 * TEETH + 1.0, 0);
    memset(&r, 0, sizeof r);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, &r, comb, k));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_region_add_ring(&ctx, &r, hole, 4));
    mask = (unsigned char *)testalloc_fn(&ta, NULL, 0, nx * ny);
    TEST_ASSERT_NOT_NULL(mask);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc__raster_inside(&ctx, &r, x0, y0, h, nx, ny, mask));
    for (j = 0; j < ny; j++)
        for (i = 0; i < nx; i++) {
            qc_vec2 p = QC__V2(x0 + (double)i * h, y0 + (double)j * h);
            TEST_ASSERT_EQUAL_INT(qc_region_contains(&r, p), mask[j * nx + i]);
        }
    testalloc_fn(&ta, mask, nx * ny, 0);
    qc_region_free(&ctx, &r);
}

/* Seeds the nx x ny raster by kind, transforms it and compares each cell
 * with the minimum over all seeds of the squared distance (FAR if none). */
static void check(size_t nx, size_t ny, int kind, unsigned every)
{
    const float far = (float)QC__GAP_FAR;
    qc__gap_grid g;
    float *want;
    size_t i, j, a, b, cells = nx * ny;

    memset(&g, 0, sizeof g);
    g.nx = nx;
    g.ny = ny;
    g.h = 1.0;
    g.f = (float *)testalloc_fn(&ta, NULL, 0, cells * sizeof *g.f);
    want = (float *)testalloc_fn(&ta, NULL, 0, cells * sizeof *want);
    TEST_ASSERT_NOT_NULL(g.f);
    TEST_ASSERT_NOT_NULL(want);
    for (j = 0; j < ny; j++)
        for (i = 0; i < nx; i++) {
            int s = kind == 0 ? seeded(i, j, every, (unsigned)nx)
                  : kind == 1 ? i == nx / 3
                  : kind == 2 ? j == ny - 1
                  : kind == 3 ? (i == nx - 1 && j == 0)
                  : kind == 5 ? (i == 0 || j == 0 || i == nx - 1 || j == ny - 1 ||
                                 (j > 2 * ny / 3 && seeded(i, j, every, 7u)))
                              : 0;
            g.f[j * nx + i] = s ? 0.0f : far;
        }
    for (j = 0; j < ny; j++)
        for (i = 0; i < nx; i++) {
            double best = (double)far;
            for (b = 0; b < ny; b++)
                for (a = 0; a < nx; a++)
                    if (g.f[b * nx + a] == 0.0f) {
                        double dx = (double)a - (double)i, dy = (double)b - (double)j;
                        double d2 = dx * dx + dy * dy;
                        best = d2 < best ? d2 : best;
                    }
            want[j * nx + i] = (float)best;
        }
    check_far(&g, want);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc__gap_transform(&ctx, &g));
    for (i = 0; i < cells; i++)
        if (want[i] != g.f[i]) {
            char msg[128];
            snprintf(msg, sizeof msg, "cell %lu of %lu x %lu, kind %d: %.1f, not %.1f",
                     (unsigned long)i, (unsigned long)nx, (unsigned long)ny, kind,
                     (double)g.f[i], (double)want[i]);
            TEST_FAIL_MESSAGE(msg);
        }
    testalloc_fn(&ta, g.f, cells * sizeof *g.f, 0);
    testalloc_fn(&ta, want, cells * sizeof *want, 0);
}

/* qc__gap_transform_above against the full transform on the same seeds and
 * a scattered mask: the same first greatest cell over the mask (raise), the
 * exact value wherever a masked cell exceeds the floor (no raise), and an
 * upper bound everywhere. */
static void check_above(size_t nx, size_t ny, unsigned every, double floor)
{
    const float far = (float)QC__GAP_FAR;
    qc__gap_grid full, lazy;
    unsigned char *mask;
    size_t i, cells = nx * ny, at, want_at = SIZE_MAX;
    double best = -1.0;
    int raise;

    mask = (unsigned char *)testalloc_fn(&ta, NULL, 0, cells);
    TEST_ASSERT_NOT_NULL(mask);
    for (raise = 0; raise < 2; raise++) {
        memset(&full, 0, sizeof full);
        full.nx = nx;
        full.ny = ny;
        full.h = 1.0;
        lazy = full;
        full.f = (float *)testalloc_fn(&ta, NULL, 0, cells * sizeof *full.f);
        lazy.f = (float *)testalloc_fn(&ta, NULL, 0, cells * sizeof *lazy.f);
        TEST_ASSERT_NOT_NULL(full.f);
        TEST_ASSERT_NOT_NULL(lazy.f);
        for (i = 0; i < cells; i++) {
            int s = every > 0 ? seeded(i % nx, i / nx, every, 3u)
                              : (i % nx) % 7 == 0 && (i / nx) % 5 == 0; /* ties */
            full.f[i] = lazy.f[i] = s ? 0.0f : far;
            mask[i] = (unsigned char)!seeded(i % nx, i / nx, 4, 9u);
        }
        TEST_ASSERT_EQUAL_INT(QC_OK, qc__gap_transform(&ctx, &full));
        TEST_ASSERT_EQUAL_INT(QC_OK, qc__gap_transform_above(&ctx, &lazy, mask,
                                                             raise ? -1.0 : floor, raise, &at));
        for (i = 0; i < cells; i++) {
            TEST_ASSERT_TRUE(lazy.f[i] >= full.f[i]);
            if (!raise && mask[i] && (double)full.f[i] > floor)
                TEST_ASSERT_EQUAL_FLOAT(full.f[i], lazy.f[i]);
            if (raise && mask[i] && (double)full.f[i] > best) {
                best = (double)full.f[i];
                want_at = i;
            }
        }
        if (raise) {
            TEST_ASSERT_EQUAL_size_t(want_at, at);
            TEST_ASSERT_EQUAL_FLOAT(full.f[want_at], lazy.f[at]);
        }
        testalloc_fn(&ta, full.f, cells * sizeof *full.f, 0);
        testalloc_fn(&ta, lazy.f, cells * sizeof *lazy.f, 0);
    }
    testalloc_fn(&ta, mask, cells, 0);
}

void test_gap_transform_above_should_agree_where_it_matters(void)
{
    check_above(61, 47, 23, 9.0);
    check_above(47, 61, 150, 30.0);
    check_above(300, 4, 900, 2.0); /* rows past the looking-out budget */
    check_above(50, 40, 0, 5.0);   /* a lattice of seeds: the greatest value ties */
}

void test_gap_transform_should_match_brute_force_on_scattered_seeds(void)
{
    check(37, 23, 0, 11);
    check(23, 37, 0, 40);
    check(50, 50, 0, 300);
    check(1, 29, 0, 7);
    check(29, 1, 0, 7);
}

void test_gap_transform_should_carry_a_lone_column_row_or_cell_across(void)
{
    check(31, 17, 1, 0);
    check(31, 17, 2, 0);
    check(31, 17, 3, 0);
    check(5, 1, 3, 0);   /* the far end of a row is looked at */
    check(200, 3, 3, 0); /* seeds too far apart for looking out: the envelope */
    check(200, 3, 1, 0);
}

/* Seeded round the border only (medial.c's raster), the middle rows run
 * past the looking-out budget and those after skip it; the rows near the
 * foot, scattered seeds, must come out the same. */
void test_gap_transform_should_match_brute_force_seeded_round_the_border(void)
{
    check(90, 70, 5, 9);
    check(70, 90, 5, 40);
    check(200, 40, 5, 0);
}

void test_gap_transform_should_leave_an_unseeded_raster_far(void)
{
    check(13, 9, 4, 0);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_gap_transform_should_match_brute_force_on_scattered_seeds);
    RUN_TEST(test_gap_transform_should_carry_a_lone_column_row_or_cell_across);
    RUN_TEST(test_gap_transform_should_match_brute_force_seeded_round_the_border);
    RUN_TEST(test_gap_transform_should_leave_an_unseeded_raster_far);
    RUN_TEST(test_gap_transform_above_should_agree_where_it_matters);
    RUN_TEST(test_edt_1d_should_match_brute_force);
    RUN_TEST(test_raster_inside_should_agree_with_contains);
    return UNITY_END();
}
