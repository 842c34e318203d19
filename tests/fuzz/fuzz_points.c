/* Fuzz target: a CSV or TSPLIB point file (qc_io_read_points); when it holds
 * a few hundred points or fewer, they go through the graph and tour stages
 * (Delaunay, both MST modes, the tree walk, the TSP), which must take any
 * finite set of allowed coordinates (0 or 1e-40 to 1e30 mm in magnitude;
 * others refused by name): duplicates, collinear, clustered, huge or tiny. */
#include "fuzz_common.h"

#define STAGE_MAX 300

static void stages(qc_ctx *ctx, const qc_points *pts)
{
    qc_mesh mesh;
    qc_edges tree = {0}, full = {0};
    qc_order walk = {0}, tour = {0};
    qc_tsp_params tp;
    int rc;

    rc = qc_delaunay(ctx, pts->v, pts->n, &mesh);
    fuzz_check_status(ctx, rc, "delaunay status");
    qc_mesh_free(ctx, &mesh);
    rc = qc_mst(ctx, pts->v, pts->n, QC_MST_MODE_DELAUNAY, &tree);
    fuzz_check_status(ctx, rc, "mst status");
    if (rc == QC_OK) {
        FUZZ_CHECK(tree.n == (pts->n ? pts->n - 1 : 0), "mst has n-1 edges");
        if (pts->n <= 60 && qc_mst(ctx, pts->v, pts->n, QC_MST_MODE_COMPLETE, &full) == QC_OK) {
            size_t i;
            double wt = 0, wf = 0;
            FUZZ_CHECK(full.n == tree.n, "both MST modes give n-1 edges");
            for (i = 0; i < tree.n; i++) {
                const qc_vec2 *v = pts->v;
                wt += qc_hypot(v[tree.e[i].a].x - v[tree.e[i].b].x, v[tree.e[i].a].y - v[tree.e[i].b].y);
                wf += qc_hypot(v[full.e[i].a].x - v[full.e[i].b].x, v[full.e[i].a].y - v[full.e[i].b].y);
                FUZZ_CHECK(full.e[i].a == tree.e[i].a && full.e[i].b == tree.e[i].b,
                           "both MST modes give the same tree");
            }
            FUZZ_CHECK(fabs(wt - wf) <= 1e-9 * (wt + wf) + 1e-300, "both MST modes weigh the same");
        }
        if (pts->n > 0) {
            rc = qc_tree_walk(ctx, pts->v, pts->n, tree.e, tree.n,
                              qc_nearest_point(pts->v, pts->n, pts->v[pts->n - 1]), &walk);
            fuzz_check_status(ctx, rc, "walk status");
            if (rc == QC_OK)
                FUZZ_CHECK(walk.n == 2 * (pts->n - 1) + 1, "walk has 2(n-1)+1 entries");
        }
    }
    memset(&tp, 0, sizeof tp);
    tp.method = QC_TSP_METHOD_OROPT;
    tp.perturb_iterations = 50;
    rc = qc_tsp(ctx, pts->v, pts->n, &tp, &tour);
    fuzz_check_status(ctx, rc, "tsp status");
    if (rc == QC_OK) {
        size_t i;
        unsigned char *seen = calloc(pts->n + 1, 1);
        FUZZ_CHECK(tour.n == pts->n, "tour visits every point");
        for (i = 0; seen != NULL && i < tour.n; i++) {
            FUZZ_CHECK(tour.i[i] < pts->n && !seen[tour.i[i]], "tour visits each point once");
            seen[tour.i[i]] = 1;
        }
        free(seen);
    }
    qc_order_free(ctx, &tour);
    qc_order_free(ctx, &walk);
    qc_edges_free(ctx, &full);
    qc_edges_free(ctx, &tree);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_alloc a;
    qc_ctx ctx;
    qc_points pts = {0};
    char *buf = fuzz_copy(data, size);
    int rc;

    if (buf == NULL)
        return 0;
    fuzz_ctx_init(&ctx, &a);
    rc = qc_io_read_points(&ctx, buf, size, &pts);
    fuzz_check_status(&ctx, rc, "read_points status");
    if (rc == QC_OK) {
        size_t i;
        int tiny = 0;

        FUZZ_CHECK(pts.n > 0, "QC_OK with no point");
        for (i = 0; i < pts.n; i++)
            FUZZ_CHECK(fabs(pts.v[i].x) <= 1e9 && fabs(pts.v[i].y) <= 1e9,
                       "a point NaN or beyond the reader's 1e9 cap");
        for (i = 0; i < pts.n; i++) /* open finding: squared lengths of tiny differences underflow */
            tiny |= (pts.v[i].x != 0 && fabs(pts.v[i].x) < 1e-100) ||
                    (pts.v[i].y != 0 && fabs(pts.v[i].y) < 1e-100);
        if (pts.n <= STAGE_MAX && !(tiny && fuzz_known("mst-underflow")))
            stages(&ctx, &pts);
    }
    qc_points_free(&ctx, &pts);
    fuzz_check_clean(&a, "points leaked");
    free(buf);
    return 0;
}
