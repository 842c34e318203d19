/* Fuzz target: a .pat through the strict reader (qc_io_read_pat) and the
 * linter (qc_io_check_pat); a plan the reader accepts is written back as
 * PAT and must read again. */
#include "fuzz_common.h"

typedef struct findings {
    size_t n;
} findings;

static void on_finding(void *ud, size_t line, const char *kind, const char *text)
{
    findings *f = ud;

    (void)line;
    FUZZ_CHECK(kind != NULL && text != NULL, "a finding without text");
    FUZZ_CHECK(strlen(kind) < 64 && strchr(text, '\n') == NULL, "a finding of several lines");
    f->n++;
}

static void check_plan(const qc_plan *pl)
{
    size_t i;

    FUZZ_CHECK(pl->n > 0 && (pl->flags[0] & QC_ST_JUMP), "p[0] must be a jump");
    for (i = 0; i < pl->n; i++)
        FUZZ_CHECK(isfinite(pl->p[i].x) && isfinite(pl->p[i].y), "a plan point NaN/inf");
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_alloc a;
    qc_ctx ctx;
    qc_plan plan = {0}, lint = {0}, again = {0};
    findings f = {0};
    size_t counted = 0;
    char *buf = fuzz_copy(data, size);
    int rc;

    if (buf == NULL)
        return 0;
    fuzz_ctx_init(&ctx, &a);
    rc = qc_io_read_pat(&ctx, buf, size, &plan);
    fuzz_check_status(&ctx, rc, "read_pat status");
    if (rc == QC_OK) {
        fuzz_grow g = {0};

        check_plan(&plan);
        rc = qc_io_write(&ctx, QC_FORMAT_PAT, &plan, NULL, fuzz_grow_fn, &g);
        fuzz_check_status(&ctx, rc, "write_pat status");
        if (rc == QC_OK) {
            rc = qc_io_read_pat(&ctx, g.b, g.n, &again);
            fuzz_check_status(&ctx, rc, "re-read status");
            FUZZ_CHECK(rc == QC_OK, "a PAT the writer made does not read back");
            FUZZ_CHECK(again.n <= plan.n, "the round trip grew");
        }
        free(g.b);
    } else {
        FUZZ_CHECK(plan.n == 0, "a failed read left points");
    }
    rc = qc_io_check_pat(&ctx, buf, size, on_finding, &f, &lint, &counted);
    fuzz_check_status(&ctx, rc, "check_pat status");
    FUZZ_CHECK(rc == QC_OK || rc == QC_ENOMEM, "the linter fails only for memory");
    FUZZ_CHECK(counted == f.n, "findings counted and reported disagree");
    qc_plan_free(&ctx, &again);
    qc_plan_free(&ctx, &lint);
    qc_plan_free(&ctx, &plan);
    fuzz_check_clean(&a, "pat leaked");
    free(buf);
    return 0;
}
