/* quiltc motifs [--svg NAME|FILE.svg [-o OUT.svg]]: the motif library, and a picture of one. */
#include <string.h>

#include "cli.h"

#define DRAW_RADIUS_MM 20.0 /* the unit bounding circle drawn 40 mm wide */

static int list(void)
{
    qc_ctx ctx;
    qc_motif_set set = {0};
    size_t i;

    qc_ctx_init(&ctx, NULL, NULL);
    for (i = 0; i < qc_motif_builtin_count(); i++) {
        const char *name = qc_motif_builtin_name(i);
        if (qc_motif_builtin(&ctx, name, &set) < 0)
            return cli_fail(&ctx, name, ctx.status);
        printf("%-16s %s\n", name,
               set.m[set.n - 1].legs == 2 ? "wanderer primitive (two legs)" : "motif");
    }
    qc_motif_set_free(&ctx, &set);
    return CLI_OK;
}

/* The motif in its unit frame, scaled and moved into a 44 mm square. */
static int draw(const char *spec, const char *out)
{
    qc_ctx ctx;
    qc_motif_set set = {0};
    qc_plan plan = {0};
    qc_io_opts io;
    size_t i;
    int rc;

    qc_ctx_init(&ctx, NULL, NULL);
    rc = cli_load_motifs(&ctx, spec, &set);
    if (rc == CLI_OK && set.n != 1) {
        cli_error("motifs --svg: give one motif, not '%s'", spec);
        rc = CLI_USAGE;
    }
    if (rc == CLI_OK && qc_stitch_plan(&ctx, &set.m[0].path, NULL, NULL, &plan) < 0)
        rc = cli_fail(&ctx, spec, ctx.status);
    for (i = 0; rc == CLI_OK && i < plan.n; i++) {
        plan.p[i].x = (plan.p[i].x + 1.1) * DRAW_RADIUS_MM;
        plan.p[i].y = (plan.p[i].y + 1.1) * DRAW_RADIUS_MM;
    }
    memset(&io, 0, sizeof io);
    if (rc == CLI_OK)
        rc = cli_write_plan(&ctx, out, QC_FORMAT_SVG, &plan, &io);
    qc_plan_free(&ctx, &plan);
    qc_motif_set_free(&ctx, &set);
    return rc;
}

int cmd_motifs(int argc, char **argv)
{
    if (argc == 1)
        return list();
    if (argc == 2 && strcmp(argv[1], "--help") == 0) {
        puts("usage: quiltc motifs                      list the built-in motifs\n"
             "       quiltc motifs --svg NAME|FILE.svg [-o OUT.svg]   draw one (stdout)");
        return CLI_OK;
    }
    if (argc >= 3 && strcmp(argv[1], "--svg") == 0) {
        if (argc == 3)
            return draw(argv[2], "-");
        if (argc == 5 && strcmp(argv[3], "-o") == 0)
            return draw(argv[2], argv[4]);
    }
    cli_error("motifs: unexpected arguments (see 'quiltc motifs --help')");
    return CLI_USAGE;
}
