/* Fuzz target: an SVG document as a block region (qc_io_read_svg_region,
 * then qc_region_normalize as the CLI does) and as a path
 * (qc_io_read_svg_path). Checks: no crash, leak or hang; statuses in range
 * with a one-line message; a normalized region is finite and within 1e6 mm;
 * warnings are single non-empty lines. */
#include "fuzz_common.h"

static void check_warning(void *ud, const char *text)
{
    (void)ud;
    FUZZ_CHECK(text[0] != '\0' && strchr(text, '\n') == NULL, "a warning not one line");
}

static void read_region(const char *buf, size_t size, double tol)
{
    fuzz_alloc a;
    qc_ctx ctx;
    qc_region r = {0};
    qc_svg_opts opts;
    int rc;

    fuzz_ctx_init(&ctx, &a);
    memset(&opts, 0, sizeof opts);
    opts.tolerance = tol;
    opts.warn = check_warning;
    rc = qc_io_read_svg_region(&ctx, buf, size, &opts, &r);
    fuzz_check_status(&ctx, rc, "svg region status");
    if (rc == QC_OK) {
        size_t i;

        FUZZ_CHECK(r.nrings > 0 && r.nv >= 3 * r.nrings, "a region without rings");
        FUZZ_CHECK(r.ring_end[r.nrings - 1] == r.nv, "ring ends disagree with nv");
        rc = qc_region_normalize(&ctx, &r);
        fuzz_check_status(&ctx, rc, "normalize status");
        if (rc == QC_OK)
            for (i = 0; i < r.nv; i++)
                FUZZ_CHECK(fabs(r.v[i].x) <= 1e6 && fabs(r.v[i].y) <= 1e6,
                           "a normalized vertex beyond 1e6 mm or NaN");
    }
    qc_region_free(&ctx, &r);
    fuzz_check_clean(&a, "svg region leaked");
}

static void read_path(const char *buf, size_t size)
{
    fuzz_alloc a;
    qc_ctx ctx;
    qc_path p = {0};
    int rc;

    fuzz_ctx_init(&ctx, &a);
    rc = qc_io_read_svg_path(&ctx, buf, size, NULL, &p);
    fuzz_check_status(&ctx, rc, "svg path status");
    if (rc == QC_OK) {
        size_t i, npt = 0;

        FUZZ_CHECK(p.ncmd > 0 && p.cmd[0] == QC_PATH_MOVE, "a path not starting with MOVE");
        for (i = 0; i < p.ncmd; i++)
            npt += qc_path_cmd_points(p.cmd[i]);
        FUZZ_CHECK(npt == p.npt, "command and point counts disagree");
        for (i = 0; i < p.npt; i++)
            FUZZ_CHECK(isfinite(p.pt[i].x) && isfinite(p.pt[i].y), "a path point NaN/inf");
    }
    qc_path_free(&ctx, &p);
    fuzz_check_clean(&a, "svg path leaked");
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *buf = fuzz_copy(data, size);

    if (buf == NULL)
        return 0;
    /* the last byte picks a coarser flattening now and then */
    read_region(buf, size, size > 0 && data[size - 1] == '\n' ? 1.0 : 0.0);
    read_path(buf, size);
    free(buf);
    return 0;
}
