/* Fuzz target: every machine-format reader (qc_io_read). The first byte
 * picks the format (QLI, DXF, HP-GL, QCC, IQP, BQM, G-code), the rest is
 * the file. A plan read must be sane (p[0] a jump, every point finite and
 * within 1e6 mm), and what the same format's writer makes of it must read
 * again with no more points. */
#include "fuzz_common.h"

static const int formats[] = {QC_FORMAT_QLI, QC_FORMAT_DXF, QC_FORMAT_HPGL, QC_FORMAT_QCC,
                              QC_FORMAT_IQP, QC_FORMAT_BQM, QC_FORMAT_GCODE};

static void check_plan(const qc_plan *pl)
{
    size_t i;

    FUZZ_CHECK(pl->n > 0 && (pl->flags[0] & QC_ST_JUMP), "p[0] must be a jump");
    for (i = 0; i < pl->n; i++)
        FUZZ_CHECK(fabs(pl->p[i].x) <= 1e6 && fabs(pl->p[i].y) <= 1e6, "a point NaN or beyond 1e6 mm");
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_alloc a;
    qc_ctx ctx;
    qc_plan plan = {0}, again = {0};
    char *buf;
    int fmt, rc;

    if (size < 1)
        return 0;
    fmt = formats[data[0] % (sizeof formats / sizeof formats[0])];
    buf = fuzz_copy(data + 1, size - 1);
    if (buf == NULL)
        return 0;
    fuzz_ctx_init(&ctx, &a);
    rc = qc_io_read(&ctx, fmt, buf, size - 1, &plan);
    fuzz_check_status(&ctx, rc, "read status");
    if (rc == QC_OK) {
        fuzz_grow g = {0};

        check_plan(&plan);
        rc = qc_io_write(&ctx, fmt, &plan, NULL, fuzz_grow_fn, &g);
        fuzz_check_status(&ctx, rc, "write status");
        if (rc == QC_OK) {
            rc = qc_io_read(&ctx, fmt, g.b, g.n, &again);
            fuzz_check_status(&ctx, rc, "re-read status");
            FUZZ_CHECK(rc == QC_OK || rc == QC_ENOMEM, "a file the writer made does not read back");
            FUZZ_CHECK(again.n <= plan.n, "the round trip grew");
        }
        free(g.b);
    } else {
        FUZZ_CHECK(plan.n == 0 && plan.p == NULL, "a failed read left points");
    }
    qc_plan_free(&ctx, &again);
    qc_plan_free(&ctx, &plan);
    fuzz_check_clean(&a, "read leaked");
    free(buf);
    return 0;
}
