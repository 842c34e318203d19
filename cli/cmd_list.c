/* quiltc list families|params|motifs|formats: what the library offers. */
#include <string.h>

#include "cli.h"

/* Lengths in the unit mm_per_unit names (the table's own are mm). */
static void list_params(double mm_per_unit)
{
    size_t n, i;
    const qc_param_info *t = qc_param_table(&n);

    for (i = 0; i < n; i++) {
        int length = t[i].type == QC_PARAM_LENGTH;
        double k = length ? mm_per_unit : 1.0;

        printf("%-12s %-6s ", t[i].name, length ? cli_units_name(mm_per_unit) : t[i].unit);
        if (t[i].choices != NULL)
            printf("%s", t[i].choices);
        else if (t[i].def_per_spacing > 0)
            printf(k != 1.0 ? "[%.4g, %.4g] default %g d" : "[%g, %g] default %g d", t[i].min / k,
                   t[i].max / k, t[i].def_per_spacing);
        else if (t[i].type == QC_PARAM_SEED)
            printf("0 .. 2^64-1 default %g", t[i].def);
        else if (k != 1.0) /* converted: four digits, as range errors print them */
            printf("[%.4g, %.4g] default %.4g", t[i].min / k, t[i].max / k, t[i].def / k);
        else
            printf("[%g, %g] default %g", t[i].min, t[i].max, t[i].def);
        printf("  %s\n", t[i].help);
    }
}

int cmd_list(int argc, char **argv)
{
    const char *what = argc > 1 ? argv[1] : "";
    double mm_per_unit = 1.0; /* the library's own */
    size_t i;

    if (argc > 2 && strcmp(what, "params") == 0 && strcmp(argv[2], "--units") == 0) {
        mm_per_unit = argc > 3 ? cli_units_mm(argv[3]) : 0.0;
        if (mm_per_unit == 0.0) {
            cli_error("list params --units: unknown unit '%s' (in, inch, mm or cm)",
                      argc > 3 ? argv[3] : "");
            return CLI_USAGE;
        }
        argv += 2;
        argc -= 2;
    }
    if (argc > 2) {
        cli_error("list: unexpected argument '%s' (see 'quiltc list --help')", argv[2]);
        return CLI_USAGE;
    }
    if (strcmp(what, "families") == 0) {
        const qc_family_desc *f;

        for (i = 0; (f = qc_family_info(i)) != NULL; i++)
            printf("%s\n", f->name);
    } else if (strcmp(what, "params") == 0) {
        list_params(mm_per_unit);
    } else if (strcmp(what, "motifs") == 0) {
        for (i = 0; i < qc_motif_builtin_count(); i++)
            printf("%s\n", qc_motif_builtin_name(i));
    } else if (strcmp(what, "formats") == 0) {
        for (i = 1; i < QC_FORMAT_COUNT; i++)
            printf("%-6s %s\n", qc_format_name((int)i), qc_format_ext((int)i));
    } else if (strcmp(what, "--help") == 0 || what[0] == '\0') {
        puts("usage: quiltc list WHAT, one of:\n"
             "  families   the pattern families (--family)\n"
             "  params     every parameter with its unit, range and default\n"
             "             (lengths in mm; params --units in|mm|cm converts them)\n"
             "  motifs     the built-in motifs (--motif)\n"
             "  formats    the machine formats quiltc writes and reads");
    } else {
        cli_error("list: unknown list '%s' (families, params, motifs or formats)", what);
        return CLI_USAGE;
    }
    return CLI_OK;
}
