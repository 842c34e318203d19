/* Graph stage: exact predicates, Delaunay invariants, EMST agreement. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "quiltc.h"
#include "../src/graph/graph_internal.h"
#include "testalloc.h"
#include "testgeom.h"
#include "unity.h"

__extension__ typedef __int128 i128;

static testalloc ta;
static qc_ctx ctx;

void setUp(void)
{
    memset(&ta, 0, sizeof ta);
    qc_ctx_init(&ctx, testalloc_fn, &ta);
}

void tearDown(void)
{
}

static int sgn(double v)
{
    return (v > 0) - (v < 0);
}

/* ---- point sets (caller frees with free()) ---- */

static qc_vec2 *random_points(size_t n, uint64_t seed)
{
    qc_vec2 *p = malloc(n * sizeof *p);
    qc_rng r;
    size_t i;

    qc_rng_seed(&r, seed);
    for (i = 0; i < n; i++)
        p[i] = rng_v2(&r, 0, 100, 0, 100);
    return p;
}

/* kind 0 square, 1 triangle (sheared square with diagonals), 2 hex lattice */
static qc_vec2 *lattice(int kind, int w, int h, size_t *n)
{
    qc_vec2 *p = malloc((size_t)w * h * sizeof *p);
    int i, j;

    *n = 0;
    for (j = 0; j < h; j++)
        for (i = 0; i < w; i++) {
            double x = i, y = j;
            if (kind == 1)
                x = i + 0.5 * j;
            if (kind == 2) {
                x = i + 0.5 * (j & 1);
                y = j * sqrt(3.0) / 2;
                if ((i + 2 * (j & 1)) % 3 == 2)
                    continue; /* hexagonal (honeycomb) lattice */
            }
            p[(*n)++] = v2(x, y);
        }
    return p;
}

static qc_vec2 *circle_points(size_t n)
{
    qc_vec2 *p = malloc(n * sizeof *p);
    size_t i;

    for (i = 0; i < n; i++)
        p[i] = v2(10 * qc_cos(2 * QC_PI * (double)i / (double)n),
                  10 * qc_sin(2 * QC_PI * (double)i / (double)n));
    return p;
}

/* ---- invariants ---- */

static int cmp_u64(const void *a, const void *b)
{
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return (x > y) - (x < y);
}

/* Proper Delaunay triangulation of the distinct points of p. */
static void check_mesh(const qc_vec2 *p, size_t n, const qc_mesh *m)
{
    size_t t, i, k, nv = 0, nd = m->ntri * 3;
    uint64_t *dir = malloc((nd + 1) * sizeof *dir), *und = malloc((m->edges.n + 1) * sizeof *und);
    size_t *use = calloc(n, sizeof *use);

    TEST_ASSERT_EQUAL_INT(QC_MESH_OK, m->status);
    TEST_ASSERT_EQUAL_size_t(n, m->n);
    for (i = 0; i < n; i++) {
        TEST_ASSERT_TRUE(m->dup_of[i] <= i);
        TEST_ASSERT_EQUAL_UINT32(m->dup_of[m->dup_of[i]], m->dup_of[i]);
        TEST_ASSERT_TRUE(p[i].x == p[m->dup_of[i]].x && p[i].y == p[m->dup_of[i]].y);
        nv += m->dup_of[i] == i;
    }
    TEST_ASSERT_EQUAL_size_t(n - m->ndup, nv);
    for (t = 0; t < m->ntri; t++) {
        const uint32_t *v = m->tri + 3 * t;
        for (k = 0; k < 3; k++) {
            TEST_ASSERT_TRUE(v[k] < n);
            TEST_ASSERT_EQUAL_UINT32(v[k], m->dup_of[v[k]]);
            use[v[k]]++;
            dir[3 * t + k] = (uint64_t)v[k] << 32 | v[(k + 1) % 3];
        }
        TEST_ASSERT_TRUE(qc_orient2d(p[v[0]], p[v[1]], p[v[2]]) > 0);
        for (i = 0; i < n; i++)
            if (m->dup_of[i] == i && i != v[0] && i != v[1] && i != v[2])
                TEST_ASSERT_TRUE_MESSAGE(qc_incircle(p[v[0]], p[v[1]], p[v[2]], p[i]) <= 0,
                                         "point inside a circumcircle");
    }
    for (i = 0; i < n; i++)
        TEST_ASSERT_TRUE(m->dup_of[i] != i || use[i] > 0); /* every point used */
    /* no directed edge twice: triangles do not overlap or fold */
    qsort(dir, nd, sizeof *dir, cmp_u64);
    for (i = 1; i < nd; i++)
        TEST_ASSERT_TRUE(dir[i] != dir[i - 1]);
    /* edges: a < b, unique, each a side of some triangle */
    for (i = 0; i < m->edges.n; i++) {
        qc_edge e = m->edges.e[i];
        uint64_t f = (uint64_t)e.a << 32 | e.b, r = (uint64_t)e.b << 32 | e.a;
        TEST_ASSERT_TRUE(e.a < e.b);
        und[i] = f;
        TEST_ASSERT_TRUE(bsearch(&f, dir, nd, sizeof *dir, cmp_u64) != NULL ||
                         bsearch(&r, dir, nd, sizeof *dir, cmp_u64) != NULL);
    }
    qsort(und, m->edges.n, sizeof *und, cmp_u64);
    for (i = 1; i < m->edges.n; i++)
        TEST_ASSERT_TRUE(und[i] != und[i - 1]);
    /* every triangle side is an edge */
    TEST_ASSERT_TRUE(nd <= 2 * m->edges.n);
    /* Euler with the outer face: V - E + F = 2 */
    TEST_ASSERT_EQUAL_INT(2, (long)nv - (long)m->edges.n + (long)m->ntri + 1);
    free(dir);
    free(und);
    free(use);
}

static void delaunay_ok(const qc_vec2 *p, size_t n)
{
    qc_mesh m;

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_delaunay(&ctx, p, n, &m));
    check_mesh(p, n, &m);
    qc_mesh_free(&ctx, &m);
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
    TEST_ASSERT_FALSE(ta.size_mismatch);
}

/* ---- predicates ---- */

static void orient2d_should_be_exact_near_collinear(void)
{
    const double u = 0x1p-53; /* ulp of 0.5 */
    int i, j, wrong = 0, zeros = 0;

    for (i = -64; i <= 64; i++)
        for (j = -64; j <= 64; j++) {
            qc_vec2 a = v2(0.5 + i * u, 0.5 + j * u), b = v2(12, 12), c = v2(24, 24);
            /* exact, in units of 2^-53 */
            i128 ax = ((i128)1 << 52) + i, ay = ((i128)1 << 52) + j;
            i128 bx = (i128)12 << 53, cx = (i128)24 << 53;
            i128 det = (ax - cx) * (bx - cx) - (ay - cx) * (bx - cx);
            int ref = (det > 0) - (det < 0);

            wrong += sgn(qc_orient2d(a, b, c)) != ref;
            wrong += sgn(qc_orient2d(b, c, a)) != ref;
            wrong += sgn(qc_orient2d(b, a, c)) != -ref;
            zeros += ref == 0;
        }
    TEST_ASSERT_EQUAL_INT(0, wrong);
    TEST_ASSERT_EQUAL_INT(129, zeros); /* the diagonal i == j */
}

static void orient2d_should_match_integer_arithmetic(void)
{
    qc_rng r;
    int k;

    qc_rng_seed(&r, 7);
    for (k = 0; k < 20000; k++) {
        /* near-collinear triples of large integers: the filter often fails */
        int64_t ax = (int64_t)qc_rng_below(&r, 1u << 26), ay = (int64_t)qc_rng_below(&r, 1u << 26);
        int64_t dx = (int64_t)qc_rng_below(&r, 1u << 20) - (1 << 19);
        int64_t dy = (int64_t)qc_rng_below(&r, 1u << 20) - (1 << 19);
        int64_t t = (int64_t)qc_rng_below(&r, 1u << 25);
        int64_t bx = ax + dx, by = ay + dy;
        int64_t cx = ax + t * dx + (int64_t)qc_rng_below(&r, 3) - 1;
        int64_t cy = ay + t * dy + (int64_t)qc_rng_below(&r, 3) - 1;
        i128 det = (i128)(ax - cx) * (by - cy) - (i128)(ay - cy) * (bx - cx);
        double s = 0x1p-30; /* exact power-of-two scaling keeps the sign */
        double o = qc_orient2d(v2((double)ax * s, (double)ay * s), v2((double)bx * s, (double)by * s),
                               v2((double)cx * s, (double)cy * s));
        TEST_ASSERT_EQUAL_INT((det > 0) - (det < 0), sgn(o));
    }
}

static void incircle_should_be_exact_near_cocircular(void)
{
    const double u = 0x1p-50;
    qc_vec2 a = v2(5, 0), b = v2(0, 5), c = v2(-5, 0);
    int i, j, wrong = 0;

    for (i = -8; i <= 8; i++)
        for (j = -8; j <= 8; j++) {
            /* |d|^2 - 25 = (6i + 8j) u + (i^2 + j^2) u^2 */
            qc_vec2 d = v2(3 + i * u, 4 + j * u);
            int lin = 6 * i + 8 * j, ref = lin != 0 ? (lin > 0) - (lin < 0) : (i || j);

            ref = -ref; /* outside the circle: negative */
            wrong += sgn(qc_incircle(a, b, c, d)) != ref;
            wrong += sgn(qc_incircle(b, c, a, d)) != ref;
            wrong += sgn(qc_incircle(b, a, c, d)) != -ref;
        }
    TEST_ASSERT_EQUAL_INT(0, wrong);
    TEST_ASSERT_TRUE(qc_incircle(a, b, c, v2(0, 0)) > 0);
    TEST_ASSERT_TRUE(qc_incircle(a, b, c, v2(0, -5)) == 0);
    TEST_ASSERT_TRUE(qc_incircle(a, b, c, v2(0, -5 - 0x1p-50)) < 0);
}

static void incircle_should_match_integer_arithmetic(void)
{
    qc_rng r;
    int k;

    qc_rng_seed(&r, 11);
    for (k = 0; k < 20000; k++) {
        /* lattice-like points near a common circle: many exact zeros */
        int64_t q[4][2];
        int i;
        i128 det;
        qc_vec2 v[4];
        const int64_t circ[8][2] = {{5, 0}, {0, 5}, {-5, 0}, {0, -5}, {3, 4}, {-4, 3}, {-3, -4}, {4, -3}};
        int64_t scale = (int64_t)qc_rng_below(&r, 1u << 20) + 1;
        int64_t ox = (int64_t)qc_rng_below(&r, 1u << 24), oy = (int64_t)qc_rng_below(&r, 1u << 24);

        for (i = 0; i < 4; i++) {
            const int64_t *cp = circ[qc_rng_below(&r, 8)];
            q[i][0] = ox + cp[0] * scale + (int64_t)qc_rng_below(&r, 3) - 1;
            q[i][1] = oy + cp[1] * scale + (int64_t)qc_rng_below(&r, 3) - 1;
            v[i] = v2((double)q[i][0] * 0x1p-20, (double)q[i][1] * 0x1p-20);
        }
        {
            i128 adx = q[0][0] - q[3][0], ady = q[0][1] - q[3][1];
            i128 bdx = q[1][0] - q[3][0], bdy = q[1][1] - q[3][1];
            i128 cdx = q[2][0] - q[3][0], cdy = q[2][1] - q[3][1];
            det = (adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) +
                  (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy) +
                  (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady);
        }
        TEST_ASSERT_EQUAL_INT((det > 0) - (det < 0), sgn(qc_incircle(v[0], v[1], v[2], v[3])));
    }
}

/* Rectangles on a triangular lattice's rounded coordinates: exactly
 * cocircular (0), and a corner one ulp out (negative) or in (positive):
 * decided by the double-double stage or the expansions, never the filter. */
static void incircle_should_be_exact_on_lattice_rectangles(void)
{
    const double h = 10 * 1.7320508075688772 / 2;
    int i, j, w, wrong = 0;

    for (i = 0; i < 12; i++)
        for (j = 0; j < 12; j++)
            for (w = 1; w <= 3; w++) {
                double x0 = (i + 0.5 * j) * 10, y0 = j * h;
                double x1 = x0 + w * 10 + 5, y1 = y0 + w * h;
                qc_vec2 a = v2(x0, y0), b = v2(x1, y0), c = v2(x1, y1);

                wrong += qc_incircle(a, b, c, v2(x0, y1)) != 0;
                wrong += !(qc_incircle(a, b, c, v2(x0, nextafter(y1, 1e300))) < 0);
                wrong += !(qc_incircle(a, b, c, v2(x0, nextafter(y1, 0))) > 0);
                wrong += !(qc_incircle(b, a, c, v2(x0, nextafter(y1, 0))) < 0);
            }
    TEST_ASSERT_EQUAL_INT(0, wrong);
}

/* ---- Delaunay ---- */

static void delaunay_should_triangulate_random_points(void)
{
    qc_vec2 *p = random_points(400, 1);
    delaunay_ok(p, 400);
    free(p);
}

static void delaunay_should_triangulate_lattices(void)
{
    int kind;
    for (kind = 0; kind < 3; kind++) {
        size_t n;
        qc_vec2 *p = lattice(kind, 17, 13, &n);
        delaunay_ok(p, n);
        free(p);
    }
}

static void delaunay_should_triangulate_cocircular_points(void)
{
    qc_vec2 *p = circle_points(97), *q = malloc(98 * sizeof *q);

    delaunay_ok(p, 97);
    memcpy(q, p, 97 * sizeof *q);
    q[97] = v2(0, 0); /* plus the centre */
    delaunay_ok(q, 98);
    free(p);
    free(q);
}

static void delaunay_should_handle_near_degenerate_input(void)
{
    qc_vec2 p[301];
    qc_rng r;
    size_t i, n;
    qc_vec2 *l = lattice(0, 15, 15, &n);

    /* 300 points on a line (exact multiples) plus one just off it */
    for (i = 0; i < 300; i++)
        p[i] = v2(0.1 * (double)i, 0.3 * (double)i);
    p[300] = v2(15, 45.000000000001);
    delaunay_ok(p, 301);
    /* points off a line by an ulp or so */
    qc_rng_seed(&r, 3);
    for (i = 0; i < 200; i++) {
        double t = qc_rng_unit(&r);
        p[i] = v2(t, t * 0.7 + (double)((int)qc_rng_below(&r, 5) - 2) * 0x1p-54);
    }
    delaunay_ok(p, 200);
    /* a lattice perturbed by tiny amounts */
    for (i = 0; i < n; i++) {
        l[i].x += ((double)qc_rng_below(&r, 3) - 1) * 1e-14;
        l[i].y += ((double)qc_rng_below(&r, 3) - 1) * 1e-14;
    }
    delaunay_ok(l, n);
    free(l);
}

static void delaunay_should_report_duplicates(void)
{
    size_t n, i;
    qc_vec2 *l = lattice(0, 8, 8, &n), *p = malloc(3 * n * sizeof *p);
    qc_mesh m;

    for (i = 0; i < 3 * n; i++)
        p[i] = l[(i * 7) % n];
    p[5].x = -0.0 * p[5].x; /* -0 and +0 are the same point */
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_delaunay(&ctx, p, 3 * n, &m));
    TEST_ASSERT_EQUAL_size_t(2 * n, m.ndup);
    check_mesh(p, 3 * n, &m);
    qc_mesh_free(&ctx, &m);
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
    free(l);
    free(p);
}

static void delaunay_should_chain_collinear_points(void)
{
    qc_vec2 p[6] = {{3, 3}, {1, 1}, {4, 4}, {1, 1}, {0, 0}, {2, 2}};
    qc_vec2 v[3] = {{5, 2}, {5, -1}, {5, 0}};
    qc_edge want[4] = {{1, 4}, {1, 5}, {0, 5}, {0, 2}};
    qc_mesh m;
    size_t i, j;

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_delaunay(&ctx, p, 6, &m));
    TEST_ASSERT_EQUAL_INT(QC_MESH_COLLINEAR, m.status);
    TEST_ASSERT_EQUAL_size_t(0, m.ntri);
    TEST_ASSERT_EQUAL_size_t(1, m.ndup);
    TEST_ASSERT_EQUAL_UINT32(1, m.dup_of[3]);
    TEST_ASSERT_EQUAL_size_t(4, m.edges.n);
    for (i = 0; i < 4; i++) {
        int found = 0;
        for (j = 0; j < 4; j++)
            found += m.edges.e[j].a == want[i].a && m.edges.e[j].b == want[i].b;
        TEST_ASSERT_EQUAL_INT(1, found);
    }
    qc_mesh_free(&ctx, &m);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_delaunay(&ctx, v, 3, &m)); /* vertical */
    TEST_ASSERT_EQUAL_INT(QC_MESH_COLLINEAR, m.status);
    TEST_ASSERT_EQUAL_size_t(2, m.edges.n);
    TEST_ASSERT_EQUAL_UINT32(1, m.edges.e[0].a);
    TEST_ASSERT_EQUAL_UINT32(2, m.edges.e[0].b);
    TEST_ASSERT_EQUAL_UINT32(0, m.edges.e[1].a);
    TEST_ASSERT_EQUAL_UINT32(2, m.edges.e[1].b);
    qc_mesh_free(&ctx, &m);
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

static void delaunay_should_report_too_few_points(void)
{
    qc_vec2 p[3] = {{1, 1}, {1, 1}, {2, 5}};
    qc_mesh m;

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_delaunay(&ctx, p, 0, &m));
    TEST_ASSERT_EQUAL_INT(QC_MESH_TOO_FEW, m.status);
    qc_mesh_free(&ctx, &m);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_delaunay(&ctx, p, 2, &m));
    TEST_ASSERT_EQUAL_INT(QC_MESH_TOO_FEW, m.status);
    TEST_ASSERT_EQUAL_size_t(0, m.edges.n);
    TEST_ASSERT_EQUAL_size_t(1, m.ndup);
    qc_mesh_free(&ctx, &m);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_delaunay(&ctx, p, 3, &m));
    TEST_ASSERT_EQUAL_INT(QC_MESH_TOO_FEW, m.status);
    TEST_ASSERT_EQUAL_size_t(1, m.edges.n);
    TEST_ASSERT_EQUAL_UINT32(0, m.edges.e[0].a);
    TEST_ASSERT_EQUAL_UINT32(2, m.edges.e[0].b);
    qc_mesh_free(&ctx, &m);
    qc_mesh_free(&ctx, &m);
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

static void delaunay_should_refuse_nan(void)
{
    qc_vec2 p[4] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
    qc_mesh m;
    qc_edges e = {0};

    p[2].y = (double)NAN;
    TEST_ASSERT_EQUAL_INT(QC_ERANGE, qc_delaunay(&ctx, p, 4, &m));
    TEST_ASSERT_TRUE(strstr(qc_errmsg(&ctx), "point 2") != NULL);
    p[2].y = 1;
    p[3].x = (double)INFINITY;
    TEST_ASSERT_EQUAL_INT(QC_ERANGE, qc_mst(&ctx, p, 4, QC_MST_MODE_DELAUNAY, &e));
    TEST_ASSERT_TRUE(strstr(qc_errmsg(&ctx), "point 3") != NULL);
    TEST_ASSERT_EQUAL_size_t(0, e.n);
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

/* ---- MST ---- */

static double prim_weight(const qc_vec2 *p, size_t n)
{
    double *d = malloc(n * sizeof *d), w = 0;
    char *in = calloc(n, 1);
    size_t i, k, v = 0;

    for (i = 0; i < n; i++)
        d[i] = (double)INFINITY;
    in[0] = 1;
    for (k = 1; k < n; k++) {
        size_t b = n;
        for (i = 0; i < n; i++) {
            if (in[i])
                continue;
            d[i] = fmin(d[i], hypot(p[i].x - p[v].x, p[i].y - p[v].y));
            if (b == n || d[i] < d[b])
                b = i;
        }
        in[b] = 1;
        w += d[b];
        v = b;
    }
    free(d);
    free(in);
    return w;
}

static void mst_check(const qc_vec2 *p, size_t n)
{
    qc_edges a = {0}, b = {0};
    double w = 0;
    size_t i;

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_mst(&ctx, p, n, QC_MST_MODE_DELAUNAY, &a));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_mst(&ctx, p, n, QC_MST_MODE_COMPLETE, &b));
    TEST_ASSERT_EQUAL_size_t(n - 1, a.n);
    TEST_ASSERT_EQUAL_size_t(n - 1, b.n);
    TEST_ASSERT_EQUAL_MEMORY(b.e, a.e, a.n * sizeof *a.e);
    for (i = 0; i < a.n; i++) {
        qc_edge e = a.e[i];
        TEST_ASSERT_TRUE(e.a < e.b && e.b < n);
        w += hypot(p[e.a].x - p[e.b].x, p[e.a].y - p[e.b].y);
        if (i > 0) { /* sorted by (exact length, a, b): computed lengths may tie */
            qc_edge f = a.e[i - 1];
            double lf = (p[f.a].x - p[f.b].x) * (p[f.a].x - p[f.b].x) + (p[f.a].y - p[f.b].y) * (p[f.a].y - p[f.b].y);
            double le = (p[e.a].x - p[e.b].x) * (p[e.a].x - p[e.b].x) + (p[e.a].y - p[e.b].y) * (p[e.a].y - p[e.b].y);
            TEST_ASSERT_TRUE(lf <= le * (1 + 1e-14));
        }
    }
    TEST_ASSERT_DOUBLE_WITHIN(1e-9 * (1 + w), prim_weight(p, n), w);
    qc_edges_free(&ctx, &a);
    qc_edges_free(&ctx, &b);
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

static void mst_should_agree_between_modes_on_random_points(void)
{
    qc_vec2 *p = random_points(500, 5);
    mst_check(p, 500);
    free(p);
}

static void mst_should_agree_between_modes_on_lattices(void)
{
    int kind;
    for (kind = 0; kind < 3; kind++) {
        size_t n;
        qc_vec2 *p = lattice(kind, 14, 11, &n);
        mst_check(p, n);
        free(p);
    }
}

static void mst_should_join_duplicates_and_collinear_points(void)
{
    qc_vec2 p[7] = {{3, 3}, {1, 1}, {4, 4}, {1, 1}, {0, 0}, {2, 2}, {1, 1}};
    qc_vec2 *c = circle_points(60);
    qc_edges e = {0};

    mst_check(p, 7);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_mst(&ctx, p, 7, QC_MST_MODE_DELAUNAY, &e));
    TEST_ASSERT_EQUAL_UINT32(1, e.e[0].a); /* zero-length edges first */
    TEST_ASSERT_EQUAL_UINT32(3, e.e[0].b);
    TEST_ASSERT_EQUAL_UINT32(1, e.e[1].a);
    TEST_ASSERT_EQUAL_UINT32(6, e.e[1].b);
    qc_edges_free(&ctx, &e);
    mst_check(c, 60);
    mst_check(p, 2);
    free(c);
}

static void mst_should_append_and_refuse_large_complete_graphs(void)
{
    qc_vec2 p[3] = {{0, 0}, {1, 0}, {3, 0}};
    qc_edges e = {0};

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_edges_push(&ctx, &e, 7, 8));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_mst(&ctx, p, 3, QC_MST_MODE_DELAUNAY, &e));
    TEST_ASSERT_EQUAL_size_t(3, e.n);
    TEST_ASSERT_EQUAL_UINT32(7, e.e[0].a);
    TEST_ASSERT_EQUAL_UINT32(1, e.e[2].a);
    TEST_ASSERT_EQUAL_UINT32(2, e.e[2].b);
    TEST_ASSERT_EQUAL_INT(QC_ELIMIT, qc_mst(&ctx, p, 20001, QC_MST_MODE_COMPLETE, &e));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_mst(&ctx, p, 1, QC_MST_MODE_COMPLETE, &e));
    TEST_ASSERT_EQUAL_size_t(3, e.n);
    qc_edges_free(&ctx, &e);
    TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
}

static void graph_should_survive_out_of_memory(void)
{
    qc_vec2 *p = random_points(300, 9);
    size_t k, i;
    int done = 0;

    for (i = 0; i < 40; i++)
        p[260 + i] = p[i]; /* duplicates */
    for (k = 1; !done && k < 500; k++) {
        qc_mesh m;
        qc_edges a = {0}, b = {0};
        int r1, r2, r3;

        setUp();
        ta.fail_at = k;
        r1 = qc_delaunay(&ctx, p, 300, &m);
        qc_mesh_free(&ctx, &m);
        ta.fail_at = k;
        ta.allocs = 0;
        r2 = qc_mst(&ctx, p, 300, QC_MST_MODE_DELAUNAY, &a);
        ta.fail_at = k;
        ta.allocs = 0;
        r3 = qc_mst(&ctx, p, 300, QC_MST_MODE_COMPLETE, &b);
        TEST_ASSERT_TRUE(r1 == QC_OK || r1 == QC_ENOMEM);
        TEST_ASSERT_TRUE(r2 == QC_OK || r2 == QC_ENOMEM);
        TEST_ASSERT_TRUE(r3 == QC_OK || r3 == QC_ENOMEM);
        TEST_ASSERT_TRUE(r2 == QC_OK ? a.n == 299 : a.n == 0);
        qc_edges_free(&ctx, &a);
        qc_edges_free(&ctx, &b);
        TEST_ASSERT_EQUAL_size_t(0, ta.live_blocks);
        TEST_ASSERT_FALSE(ta.size_mismatch);
        done = r1 == QC_OK && r2 == QC_OK && r3 == QC_OK;
    }
    TEST_ASSERT_TRUE(done);
    TEST_ASSERT_TRUE(k > 5);
    free(p);
}

/* Lengths that round to the same double are still ordered exactly, so the
 * complete graph does not pick 0-1 where the collinear Delaunay chain has
 * only 0-2 and 2-1 (a fuzz finding). */
static void mst_should_order_lengths_exactly(void)
{
    qc_vec2 p[3];
    qc_edges a = {0}, b = {0};
    qc_mesh mesh;

    p[0] = v2(0, 0);
    p[1] = v2(1, 0);
    p[2] = v2(7e-18, 0);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_mst(&ctx, p, 3, QC_MST_MODE_DELAUNAY, &a));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_mst(&ctx, p, 3, QC_MST_MODE_COMPLETE, &b));
    TEST_ASSERT_EQUAL_size_t(2, b.n);
    TEST_ASSERT_EQUAL_MEMORY(a.e, b.e, 2 * sizeof *a.e);
    b.n = 0; /* mode 0 is the default, Delaunay; past COMPLETE is refused */
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_mst(&ctx, p, 3, QC_MST_MODE_DEFAULT, &b));
    TEST_ASSERT_EQUAL_MEMORY(a.e, b.e, 2 * sizeof *a.e);
    TEST_ASSERT_EQUAL_INT(QC_EINVAL, qc_mst(&ctx, p, 3, (qc_mst_mode)(QC_MST_MODE_COMPLETE + 1), &b));
    TEST_ASSERT_EQUAL_UINT32(0, b.e[0].a); /* 0-2, the tiny one, then 1-2 */
    TEST_ASSERT_EQUAL_UINT32(2, b.e[0].b);
    TEST_ASSERT_EQUAL_UINT32(1, b.e[1].a);
    TEST_ASSERT_EQUAL_UINT32(2, b.e[1].b);
    qc_edges_free(&ctx, &a);
    qc_edges_free(&ctx, &b);
    mst_check(p, 3);
    {   /* a tiny and a unit component in one length: 7e-184^2 underflows
         * beside 1, yet 0-4 (7e-184, 1) is shorter than 0-1 (7e-180 -
         * 7e-184, 1): the comparison is exact for any doubles */
        qc_vec2 q[5];
        q[0] = v2(7e-184, 2);
        q[1] = v2(7e-180, 1);
        q[2] = v2(117e-184, 2);
        q[3] = v2(7e-180, 1);
        q[4] = v2(0, 1);
        TEST_ASSERT_EQUAL_INT(-1, qc__cmp_len2(q[0], q[4], q[0], q[1]));
        TEST_ASSERT_EQUAL_INT(1, qc__cmp_len2(q[0], q[1], q[0], q[4]));
        TEST_ASSERT_EQUAL_INT(0, qc__cmp_len2(q[1], q[4], q[3], q[4]));
        TEST_ASSERT_EQUAL_INT(-1, qc__cmp_len2(v2(0x1p-1074, 0), v2(0, 0), v2(0x1p-1073, 0),
                                               v2(0, 0))); /* subnormals */
        TEST_ASSERT_EQUAL_INT(1, qc__cmp_len2(v2(0x1p1000, 0x1p-1074), v2(0, 0),
                                              v2(0x1p1000, 0), v2(0, 0)));
        /* but the triangulation's predicates multiply four differences:
         * such coordinates are refused by name (fuzz findings: the modes
         * chose different trees when the products underflowed) ... */
        TEST_ASSERT_EQUAL_INT(QC_ERANGE, qc_mst(&ctx, q, 5, QC_MST_MODE_DELAUNAY, &a));
        TEST_ASSERT_NOT_NULL(strstr(qc_errmsg(&ctx), "point 0 (7e-184, 2): a coordinate must be "
                                                     "0 or between 1e-40 and 1e+30 mm"));
        TEST_ASSERT_EQUAL_INT(QC_ERANGE, qc_delaunay(&ctx, q, 5, &mesh));
        q[0].x = 2e30;
        TEST_ASSERT_EQUAL_INT(QC_ERANGE, qc_mst(&ctx, q, 5, QC_MST_MODE_COMPLETE, &a));
        /* ... while the same shape at the smallest allowed scale agrees */
        q[0] = v2(7e-40, 2);
        q[1] = v2(7e-36, 1);
        q[2] = v2(117e-40, 2);
        q[3] = v2(7e-36, 1);
        TEST_ASSERT_EQUAL_INT(-1, qc__cmp_len2(q[0], q[4], q[0], q[1]));
        mst_check(q, 5);
    }
}

/* The 128-bit comparison of squared lengths agrees with the big-integer
 * one on near ties: a lattice's equal edges (a few ulps apart), reflections
 * that tie exactly, and points whose exponents span too far for 128 bits
 * (then both are the big integers). */
static void cmp_len2_integers_should_match_expansions(void)
{
    qc_rng r;
    int i, k, decided = 0;

    qc_rng_seed(&r, 11);
    for (i = 0; i < 20000; i++) {
        double s = 0.5 + 300.0 * qc_rng_unit(&r), t = 0.1 + 10.0 * qc_rng_unit(&r);
        double ang = 2.0 * QC_PI * qc_rng_unit(&r), c = qc_cos(ang), n = qc_sin(ang);
        qc_vec2 q[4];
        int want, got;

        /* ab and cd: the same length t in two directions, rounded apart */
        q[0] = v2(s, s * 0.5);
        q[1] = v2(s + t * c, s * 0.5 + t * n);
        q[2] = v2(s * 0.7, s);
        q[3] = i % 3 == 0 ? v2(s * 0.7 - t * c, s + t * n) : v2(s * 0.7 + t * n, s - t * c);
        if (i % 7 == 0) /* a tiny coordinate: too wide a span for integers */
            q[2].x = 1e-9 * qc_rng_unit(&r);
        for (k = 0; k < 2; k++) {
            want = qc__cmp_len2_big(q[2 * k], q[1 - k], q[2], q[3]);
            got = qc__cmp_len2(q[2 * k], q[1 - k], q[2], q[3]);
            TEST_ASSERT_EQUAL_INT(want, got);
            decided += want != 0;
        }
    }
    TEST_ASSERT_GREATER_THAN_INT(1000, decided);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(orient2d_should_be_exact_near_collinear);
    RUN_TEST(orient2d_should_match_integer_arithmetic);
    RUN_TEST(incircle_should_be_exact_near_cocircular);
    RUN_TEST(incircle_should_match_integer_arithmetic);
    RUN_TEST(incircle_should_be_exact_on_lattice_rectangles);
    RUN_TEST(delaunay_should_triangulate_random_points);
    RUN_TEST(delaunay_should_triangulate_lattices);
    RUN_TEST(delaunay_should_triangulate_cocircular_points);
    RUN_TEST(delaunay_should_handle_near_degenerate_input);
    RUN_TEST(delaunay_should_report_duplicates);
    RUN_TEST(delaunay_should_chain_collinear_points);
    RUN_TEST(delaunay_should_report_too_few_points);
    RUN_TEST(delaunay_should_refuse_nan);
    RUN_TEST(mst_should_agree_between_modes_on_random_points);
    RUN_TEST(mst_should_agree_between_modes_on_lattices);
    RUN_TEST(mst_should_join_duplicates_and_collinear_points);
    RUN_TEST(mst_should_append_and_refuse_large_complete_graphs);
    RUN_TEST(graph_should_survive_out_of_memory);
    RUN_TEST(mst_should_order_lengths_exactly);
    RUN_TEST(cmp_len2_integers_should_match_expansions);
    return UNITY_END();
}
