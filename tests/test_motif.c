/* Motifs: the built-in library in its unit frame, hulls, names, allocation failures. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "quiltc.h"
#include "testalloc.h"
#include "unity.h"
#include "../src/deco/deco_internal.h"

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

static void all_names(char *buf, size_t cap)
{
    size_t i;
    buf[0] = '\0';
    for (i = 0; i < qc_motif_builtin_count(); i++) {
        if (i)
            strncat(buf, ",", cap - strlen(buf) - 1);
        strncat(buf, qc_motif_builtin_name(i), cap - strlen(buf) - 1);
    }
}

static void library_should_hold_at_least_eight_motifs_and_wanderer_variants(void)
{
    size_t i, legs = 0;
    qc_motif_set set = {0};
    char names[512];

    TEST_ASSERT_GREATER_OR_EQUAL_UINT(8, qc_motif_builtin_count());
    TEST_ASSERT_NULL(qc_motif_builtin_name(qc_motif_builtin_count()));
    all_names(names, sizeof names);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_motif_builtin(&ctx, names, &set));
    TEST_ASSERT_EQUAL_UINT(qc_motif_builtin_count(), set.n);
    for (i = 0; i < set.n; i++) {
        const qc_motif *m = &set.m[i];
        TEST_ASSERT_EQUAL_STRING(qc_motif_builtin_name(i), m->name);
        TEST_ASSERT_EQUAL_INT(QC_PATH_MOVE, m->path.cmd[0]);
        TEST_ASSERT_EQUAL_UINT(1, qc_path_pieces(&m->path));
        if (m->legs == 0) { /* a closed detour: back at the attachment */
            TEST_ASSERT_DOUBLE_WITHIN(1e-12, m->entry.x, m->exit.x);
            TEST_ASSERT_DOUBLE_WITHIN(1e-12, m->entry.y, m->exit.y);
        } else {
            legs++;
            TEST_ASSERT_EQUAL_INT(2, m->legs);
            TEST_ASSERT_DOUBLE_WITHIN(1e-12, 1, qc_hypot(m->entry_dir.x, m->entry_dir.y));
            TEST_ASSERT_DOUBLE_WITHIN(1e-12, 1, qc_hypot(m->exit_dir.x, m->exit_dir.y));
        }
    }
    TEST_ASSERT_GREATER_OR_EQUAL_UINT(6, legs);
    qc_motif_set_free(&ctx, &set);
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

static void motifs_should_have_unit_bounding_circle_and_hull_containing_points(void)
{
    size_t i, j, k;
    qc_motif_set set = {0};
    char names[512];

    all_names(names, sizeof names);
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_motif_builtin(&ctx, names, &set));
    for (i = 0; i < set.n; i++) {
        const qc_motif *m = &set.m[i];
        qc_points pts = {0};
        qc_vec2 c, *scr;
        double r;
        TEST_ASSERT_EQUAL_INT(QC_OK, qc_curve_flatten(&ctx, &m->path, 1e-4, &pts, NULL));
        scr = malloc(pts.n * sizeof *scr);
        qc__min_circle(pts.v, pts.n, scr, &c, &r);
        free(scr);
        TEST_ASSERT_DOUBLE_WITHIN(1e-9, 1, r);
        TEST_ASSERT_DOUBLE_WITHIN(1e-9, 0, c.x);
        TEST_ASSERT_DOUBLE_WITHIN(1e-9, 0, c.y);
        TEST_ASSERT_GREATER_OR_EQUAL_UINT(3, m->nhull);
        for (k = 0; k < m->nhull; k++) { /* CCW and convex */
            qc_vec2 a = m->hull[k], b = m->hull[(k + 1) % m->nhull], d = m->hull[(k + 2) % m->nhull];
            TEST_ASSERT_TRUE((b.x - a.x) * (d.y - a.y) - (b.y - a.y) * (d.x - a.x) > 0);
        }
        for (j = 0; j < pts.n; j++) {
            TEST_ASSERT_TRUE(qc_hypot(pts.v[j].x, pts.v[j].y) <= 1 + 1e-9);
            for (k = 0; k < m->nhull; k++) {
                qc_vec2 a = m->hull[k], b = m->hull[(k + 1) % m->nhull];
                double cr = (b.x - a.x) * (pts.v[j].y - a.y) - (b.y - a.y) * (pts.v[j].x - a.x);
                TEST_ASSERT_TRUE(cr >= -1e-9);
            }
        }
        qc_points_free(&ctx, &pts);
    }
    qc_motif_set_free(&ctx, &set);
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

static void builtin_should_refuse_unknown_names(void)
{
    qc_motif_set set = {0};

    TEST_ASSERT_EQUAL_INT(QC_EINVAL, qc_motif_builtin(&ctx, "leaf,rose", &set));
    TEST_ASSERT_TRUE(strstr(qc_errmsg(&ctx), "rose") != NULL);
    TEST_ASSERT_EQUAL_UINT(0, set.n); /* as on entry: leaf rolled back (core.h) */
    TEST_ASSERT_EQUAL_INT(QC_EINVAL, qc_motif_builtin(&ctx, NULL, &set));
    qc_motif_set_free(&ctx, &set);
    qc_motif_set_free(&ctx, &set); /* twice: a no-op */
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

static void hull_and_circle_should_handle_known_sets(void)
{
    qc_vec2 sq[9] = {{0, 0}, {2, 0}, {2, 2}, {0, 2}, {1, 1}, {1, 0}, {0.5, 1.5}, {2, 1}, {1, 2}};
    qc_vec2 out[18], scr[18], c;
    double r;
    size_t n = qc__convex_hull(sq, 9, out, scr);

    TEST_ASSERT_EQUAL_UINT(4, n); /* collinear points dropped */
    qc__min_circle(sq, 9, scr, &c, &r);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 1, c.x);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 1, c.y);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, sqrt(2), r);
}

static void convex_touch_should_separate_and_detect(void)
{
    qc_vec2 a[3] = {{0, 0}, {1, 0}, {0, 1}};
    qc_vec2 b[3] = {{0.6, 0.6}, {2, 0.6}, {0.6, 2}};  /* beyond the hypotenuse */
    qc_vec2 c[3] = {{0.4, 0.4}, {2, 0.4}, {0.4, 2}};  /* overlapping */
    qc_vec2 seg[2] = {{-1, 0.5}, {2, 0.5}};

    TEST_ASSERT_FALSE(qc__convex_touch(a, 3, b, 3, 0));
    TEST_ASSERT_TRUE(qc__convex_touch(a, 3, c, 3, 0));
    TEST_ASSERT_TRUE(qc__convex_touch(a, 3, seg, 2, 0));
    TEST_ASSERT_FALSE(qc__convex_touch(b, 3, seg, 2, 0));
}

/* The separating-axis test in full, every projection worked out (as
 * shared_collide.c did before its shortcuts): the answers its
 * certificate and early exits must keep. */
static void ref_project(const qc_vec2 *p, size_t n, double ax, double ay, double *lo, double *hi)
{
    size_t i;
    *lo = *hi = p[0].x * ax + p[0].y * ay;
    for (i = 1; i < n; i++) {
        double d = p[i].x * ax + p[i].y * ay;
        *lo = d < *lo ? d : *lo;
        *hi = d > *hi ? d : *hi;
    }
}

static int ref_separated(const qc_vec2 *a, size_t na, const qc_vec2 *b, size_t nb, double eps)
{
    size_t i;
    for (i = 0; i < na; i++) {
        qc_vec2 p = a[i], q = a[(i + 1) % na];
        double ax = q.y - p.y, ay = p.x - q.x, alo, ahi, blo, bhi, len, e;
        ref_project(a, na, ax, ay, &alo, &ahi);
        ref_project(b, nb, ax, ay, &blo, &bhi);
        len = sqrt(ax * ax + ay * ay);
        if (len < 1e-15)
            continue;
        e = eps * len;
        if (ahi + e < blo || bhi + e < alo)
            return 1;
    }
    return 0;
}

/* Whether the boxes of a and b come within eps (qc__convex_touch's first test). */
static int ref_boxes_meet(const qc_vec2 *a, size_t na, const qc_vec2 *b, size_t nb, double eps)
{
    double ax0 = 1e300, ay0 = 1e300, ax1 = -1e300, ay1 = -1e300;
    double bx0 = 1e300, by0 = 1e300, bx1 = -1e300, by1 = -1e300;
    size_t i;
    for (i = 0; i < na; i++) {
        ax0 = fmin(ax0, a[i].x), ay0 = fmin(ay0, a[i].y);
        ax1 = fmax(ax1, a[i].x), ay1 = fmax(ay1, a[i].y);
    }
    for (i = 0; i < nb; i++) {
        bx0 = fmin(bx0, b[i].x), by0 = fmin(by0, b[i].y);
        bx1 = fmax(bx1, b[i].x), by1 = fmax(by1, b[i].y);
    }
    return !(ax1 + eps < bx0 || bx1 + eps < ax0 || ay1 + eps < by0 || by1 + eps < ay0);
}

static int ref_touch(const qc_vec2 *a, size_t na, const qc_vec2 *b, size_t nb, double eps)
{
    return ref_boxes_meet(a, na, b, nb, eps) && !ref_separated(a, na, b, nb, eps) &&
           !ref_separated(b, nb, a, na, eps);
}

/* A random convex CCW polygon: n points on a circle, angles sorted. */
static size_t random_convex(qc_rng *rng, qc_vec2 c, double r, qc_vec2 *out)
{
    size_t n = 3 + (size_t)qc_rng_below(rng, 18), i, j;
    double ang[24];
    for (i = 0; i < n; i++) {
        double t = qc_rng_unit(rng) * 2 * QC_PI;
        for (j = i; j > 0 && ang[j - 1] > t; j--)
            ang[j] = ang[j - 1];
        ang[j] = t;
    }
    for (i = 0; i < n; i++) {
        out[i].x = c.x + r * cos(ang[i]);
        out[i].y = c.y + r * sin(ang[i]);
    }
    return n;
}

/* b: a mirrored across its edge k's line and moved gap along the edge's
 * outward normal (reversed: CCW again), so the two meet edge to edge. */
static void mirror_across(const qc_vec2 *a, size_t n, size_t k, double gap, qc_vec2 *b)
{
    qc_vec2 p = a[k], q = a[(k + 1) % n];
    double ex = q.x - p.x, ey = q.y - p.y, l = sqrt(ex * ex + ey * ey), nx = ey / l,
           ny = -ex / l;
    size_t i;
    for (i = 0; i < n; i++) {
        double d = (a[i].x - p.x) * nx + (a[i].y - p.y) * ny;
        b[n - 1 - i].x = a[i].x - 2 * d * nx + gap * nx;
        b[n - 1 - i].y = a[i].y - 2 * d * ny + gap * ny;
    }
}

static void convex_touch_should_agree_with_the_full_sat(void)
{
    static const double gaps[] = {0, 1e-10, -1e-10, 5e-10, 2e-9, -2e-9, 1e-6, -1e-6, 0.05};
    qc_rng rng;
    qc_vec2 a[24], b[24];
    int touch = 0, apart = 0, k;

    qc_rng_seed(&rng, 21);
    for (k = 0; k < 20000; k++) {
        qc_vec2 ca = {300 + qc_rng_unit(&rng), 200 + qc_rng_unit(&rng)}, cb;
        double ra = 1 + 9 * qc_rng_unit(&rng), rb = 1 + 9 * qc_rng_unit(&rng);
        double eps = (k & 1) ? 1e-9 : 0, t = qc_rng_unit(&rng) * 2 * QC_PI;
        size_t na = random_convex(&rng, ca, ra, a), nb;
        int want;

        if (k % 3 == 0) { /* edge to edge, within rounding of the eps margin */
            nb = na;
            mirror_across(a, na, (size_t)qc_rng_below(&rng, na),
                          gaps[qc_rng_below(&rng, sizeof gaps / sizeof gaps[0])], b);
        } else {
            double f = 0.2 + 0.9 * qc_rng_unit(&rng);
            cb.x = ca.x + (ra + rb) * f * cos(t);
            cb.y = ca.y + (ra + rb) * f * sin(t);
            nb = random_convex(&rng, cb, rb, b);
        }
        want = ref_touch(a, na, b, nb, eps);
        touch += want;
        apart += !want;
        TEST_ASSERT_EQUAL_INT_MESSAGE(want, qc__convex_touch(a, na, b, nb, eps), "a, b");
        TEST_ASSERT_EQUAL_INT_MESSAGE(want, qc__convex_touch(b, nb, a, na, eps), "b, a");
    }
    TEST_ASSERT_GREATER_THAN_INT(3000, touch); /* both answers, many times */
    TEST_ASSERT_GREATER_THAN_INT(3000, apart);
}

/* A segment against a convex CCW polygon as shared_collide.c tested it
 * before its early exits: both ends beyond an edge, else the segment's
 * own normal with the polygon's whole extent. */
static int ref_seg_touch(const qc_vec2 *s, const qc_vec2 *p, size_t n, double eps)
{
    double dx = s[1].x - s[0].x, dy = s[1].y - s[0].y, sl, lo, hi, c;
    size_t i;
    for (i = 0; i < n; i++) {
        qc_vec2 a = p[i], b = p[(i + 1) % n];
        double ex = b.x - a.x, ey = b.y - a.y, el = sqrt(ex * ex + ey * ey);
        double s0 = ex * (s[0].y - a.y) - ey * (s[0].x - a.x);
        double s1 = ex * (s[1].y - a.y) - ey * (s[1].x - a.x);
        if (s0 < -eps * el && s1 < -eps * el)
            return 0;
    }
    sl = sqrt(dx * dx + dy * dy);
    if (sl < 1e-15)
        return 1;
    ref_project(p, n, -dy, dx, &lo, &hi);
    c = -dy * s[0].x + dx * s[0].y;
    return !(hi + eps * sl < c || c + eps * sl < lo);
}

static void segment_touch_should_agree_with_the_full_test(void)
{
    qc_rng rng;
    qc_vec2 a[24], s[2];
    int touch = 0, apart = 0, k;

    qc_rng_seed(&rng, 4);
    for (k = 0; k < 20000; k++) {
        qc_vec2 ca = {300 + qc_rng_unit(&rng), 200 + qc_rng_unit(&rng)};
        double r = 1 + 9 * qc_rng_unit(&rng), eps = (k & 1) ? 1e-9 : 0;
        double t = qc_rng_unit(&rng) * 2 * QC_PI, u = qc_rng_unit(&rng) * 2 * QC_PI;
        double d = r * (0.5 + 0.7 * qc_rng_unit(&rng)), h = r * 2 * qc_rng_unit(&rng);
        size_t n = random_convex(&rng, ca, r, a);
        int want;

        if (k % 3 == 0) { /* tangent to the circle at a vertex, just off it either side */
            qc_vec2 v = a[qc_rng_below(&rng, n)];
            double rx = (v.x - ca.x) / r, ry = (v.y - ca.y) / r;
            double off = (qc_rng_unit(&rng) - 0.5) * 1e-8;
            s[0].x = v.x + off * rx - h * ry;
            s[0].y = v.y + off * ry + h * rx;
            s[1].x = v.x + off * rx + h * ry;
            s[1].y = v.y + off * ry - h * rx;
            if (qc_rng_below(&rng, 2)) { /* the polygon on either side of its normal */
                qc_vec2 w = s[0];
                s[0] = s[1];
                s[1] = w;
            }
        } else { /* a chord of a circle about the polygon's centre */
            s[0].x = ca.x + d * cos(t) + h * cos(u);
            s[0].y = ca.y + d * sin(t) + h * sin(u);
            s[1].x = ca.x + d * cos(t) - h * cos(u);
            s[1].y = ca.y + d * sin(t) - h * sin(u);
        }
        want = ref_boxes_meet(a, n, s, 2, eps) && ref_seg_touch(s, a, n, eps);
        touch += want;
        apart += !want;
        TEST_ASSERT_EQUAL_INT(want, qc__convex_touch(a, n, s, 2, eps));
        TEST_ASSERT_EQUAL_INT(want, qc__convex_touch(s, 2, a, n, eps));
    }
    TEST_ASSERT_GREATER_THAN_INT(3000, touch);
    TEST_ASSERT_GREATER_THAN_INT(3000, apart);
}

static void from_path_should_read_attachment_and_legs(void)
{
    qc_motif_set set = {0};
    qc_path p = {0};
    qc_vec2 a = {100, 50}, b = {105, 53}, c = {112, 70}, d = {100, 75};
    qc_vec2 l0 = {-12, -12}, l1 = {-4, -6};
    qc_vec2 k1 = {10, 4}, k2 = {10, 20}, k3 = {0, 20}, k4 = {-10, 20}, k5 = {-10, 4}, k6 = {4, -6};
    qc_vec2 l2 = {12, -12};

    /* closed: a branching motif attached at its start */
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_move_to(&ctx, &p, a));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_cubic_to(&ctx, &p, b, c, d));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_line_to(&ctx, &p, a));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc__motif_from_path(&ctx, &p, "mine", &set));
    TEST_ASSERT_EQUAL_UINT(0, p.ncmd);
    TEST_ASSERT_EQUAL_INT(0, set.m[0].legs);
    TEST_ASSERT_EQUAL_STRING("mine", set.m[0].name);
    TEST_ASSERT_EQUAL_MEMORY(&set.m[0].entry, &set.m[0].exit, sizeof(qc_vec2));

    /* open with legs: the first and last segments are directions only */
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_move_to(&ctx, &p, l0));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_line_to(&ctx, &p, l1));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_cubic_to(&ctx, &p, k1, k2, k3));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_cubic_to(&ctx, &p, k4, k5, k6));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_line_to(&ctx, &p, l2));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc__motif_from_path(&ctx, &p, "legs", &set));
    TEST_ASSERT_EQUAL_INT(2, set.m[1].legs);
    TEST_ASSERT_EQUAL_UINT(3, set.m[1].path.ncmd); /* MOVE + the two body cubics */
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, -0.8, set.m[1].entry_dir.x);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, -0.6, set.m[1].entry_dir.y);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 0.8, set.m[1].exit_dir.x);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, -0.6, set.m[1].exit_dir.y);
    TEST_ASSERT_TRUE(set.m[1].entry.x < set.m[1].exit.x); /* entry on the left */

    /* open but too short for legs: closed with a straight stitch */
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_move_to(&ctx, &p, a));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_cubic_to(&ctx, &p, b, c, d));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc__motif_from_path(&ctx, &p, "short", &set));
    TEST_ASSERT_EQUAL_INT(0, set.m[2].legs);
    TEST_ASSERT_EQUAL_MEMORY(&set.m[2].entry, &set.m[2].exit, sizeof(qc_vec2));

    /* a lone point has no extent */
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_path_move_to(&ctx, &p, a));
    TEST_ASSERT_EQUAL_INT(QC_EDEGENERATE, qc__motif_from_path(&ctx, &p, "dot", &set));
    TEST_ASSERT_EQUAL_UINT(3, set.n);
    qc_motif_set_free(&ctx, &set);
    TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
}

static void builtin_should_free_everything_when_allocation_fails(void)
{
    size_t k;
    int rc = QC_ENOMEM;

    for (k = 1; rc == QC_ENOMEM && k < 5000; k++) {
        qc_motif_set set = {0};
        memset(&ta, 0, sizeof ta);
        ta.fail_at = k;
        rc = qc_motif_builtin(&ctx, "leaf,flower,spiral,loop60", &set);
        qc_motif_set_free(&ctx, &set);
        TEST_ASSERT_EQUAL_UINT(0, ta.live_blocks);
        TEST_ASSERT_FALSE(ta.size_mismatch);
    }
    TEST_ASSERT_EQUAL_INT(QC_OK, rc);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(library_should_hold_at_least_eight_motifs_and_wanderer_variants);
    RUN_TEST(motifs_should_have_unit_bounding_circle_and_hull_containing_points);
    RUN_TEST(builtin_should_refuse_unknown_names);
    RUN_TEST(hull_and_circle_should_handle_known_sets);
    RUN_TEST(convex_touch_should_separate_and_detect);
    RUN_TEST(convex_touch_should_agree_with_the_full_sat);
    RUN_TEST(segment_touch_should_agree_with_the_full_test);
    RUN_TEST(from_path_should_read_attachment_and_legs);
    RUN_TEST(builtin_should_free_everything_when_allocation_fails);
    return UNITY_END();
}
