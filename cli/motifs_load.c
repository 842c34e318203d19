/* --motif: a comma-separated list of built-in motif names and SVG files. */
#include <stdlib.h>
#include <string.h>

#include "cli.h"

#define MAX_MOTIF_BYTES ((size_t)4 << 20)

static int add_svg(qc_ctx *ctx, const char *path, qc_motif_set *set)
{
    char *buf;
    size_t len;
    int rc;

    if (cli_read_file(path, MAX_MOTIF_BYTES, &buf, &len) != 0)
        return CLI_RUNTIME;
    rc = qc_motif_from_svg(ctx, buf, len, path, set);
    free(buf);
    if (rc < 0) {
        cli_error("--motif %s: %s", path, qc_errmsg(ctx));
        return CLI_RUNTIME;
    }
    return CLI_OK;
}

int cli_load_motifs(qc_ctx *ctx, const char *spec, qc_motif_set *set)
{
    char *copy = malloc(strlen(spec) + 1), *item, *save = NULL;
    int rc = CLI_OK;

    if (copy == NULL) {
        cli_error("out of memory");
        return CLI_RUNTIME;
    }
    strcpy(copy, spec);
    for (item = strtok_r(copy, ",", &save); item != NULL && rc == CLI_OK;
         item = strtok_r(NULL, ",", &save)) {
        size_t n = strlen(item);
        if (n > 4 && strcmp(item + n - 4, ".svg") == 0)
            rc = add_svg(ctx, item, set);
        else if (qc_motif_builtin(ctx, item, set) < 0) {
            cli_error("--motif: %s", qc_errmsg(ctx));
            rc = CLI_USAGE;
        }
    }
    free(copy);
    return rc;
}
