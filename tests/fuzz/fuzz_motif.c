/* Fuzz target: a motif SVG (qc_motif_from_svg), then, when it loads, the
 * motif used by a small Branching or Wanderer pattern (about 10 points), so
 * hostile motif geometry reaches the families. */
#include "fuzz_common.h"

static void use_motif(qc_ctx *ctx, const qc_motif_set *set, int family)
{
    qc_region r = {0};
    qc_params p;
    qc_result res;
    int rc;

    memset(&p, 0, sizeof p);
    if (qc_region_shape(ctx, "rect:30x30", 1.0, &r) < 0)
        goto out;
    qc_params_set(ctx, &p, "family", family);
    qc_params_set(ctx, &p, "spacing", 10.0);
    rc = qc_generate(ctx, &r, &p, NULL, set, &res);
    fuzz_check_status(ctx, rc, "generate with the motif");
    if (rc == QC_OK)
        FUZZ_CHECK(res.path.ncmd > 0 && res.path.cmd[0] == QC_PATH_MOVE, "an empty pattern");
    else
        FUZZ_CHECK(fuzz_all_zero(&res, sizeof res), "a failed qc_generate left its result");
    qc_result_free(ctx, &res);
out:
    qc_region_free(ctx, &r);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_alloc a;
    qc_ctx ctx;
    qc_motif_set set = {0};
    char *buf = fuzz_copy(data, size);
    int rc;

    if (buf == NULL)
        return 0;
    fuzz_ctx_init(&ctx, &a);
    rc = qc_motif_from_svg(&ctx, buf, size, "fuzz", &set);
    fuzz_check_status(&ctx, rc, "motif status");
    if (rc == QC_OK) {
        const qc_motif *m = &set.m[0];
        size_t i;

        FUZZ_CHECK(set.n == 1, "one motif appended");
        FUZZ_CHECK(m->path.ncmd > 0 && m->path.cmd[0] == QC_PATH_MOVE, "motif path");
        for (i = 0; i < m->path.npt; i++)
            FUZZ_CHECK(isfinite(m->path.pt[i].x) && isfinite(m->path.pt[i].y) &&
                           qc_hypot(m->path.pt[i].x, m->path.pt[i].y) < 1e3,
                       "motif point NaN or far outside the unit frame");
        FUZZ_CHECK(m->nhull == 0 || m->hull != NULL, "hull");
        use_motif(&ctx, &set, size % 2 ? QC_FAMILY_WANDERER : QC_FAMILY_BRANCHING);
    } else {
        FUZZ_CHECK(set.n == 0, "a failed read appended a motif");
    }
    qc_motif_set_free(&ctx, &set);
    fuzz_check_clean(&a, "motif leaked");
    free(buf);
    return 0;
}
