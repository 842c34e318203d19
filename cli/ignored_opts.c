/*
 * Options the chosen family does not read (--angle with stipple, --motif
 * with vine): one warning line naming them, so a typo'd family or a
 * forgotten option does not pass in silence. A warning, not an error: the
 * pattern is still the one asked for, and a script that sets one option
 * for every family (a job's shared params) keeps working.
 */
#include <string.h>

#include "cli.h"

#define MAX_NAMES 64

/* How the message names option `name`: "--angle", or "params.angle" after
 * "job: blocks[1]: ". */
static void name_of(const cli_pattern_opts *o, const char *name, int param, char *buf,
                    size_t size)
{
    if (o->where == NULL)
        snprintf(buf, size, "--%s", name);
    else
        snprintf(buf, size, "%s%s", param ? "params." : "", name);
}

void cli_pattern_warn_ignored(const cli_pattern_opts *o)
{
    size_t nrows, i, n = 0, at = 0;
    const qc_param_info *t = qc_param_table(&nrows);
    const qc_family_desc *fam;
    qc_params r = o->params;
    char names[MAX_NAMES][80], line[MAX_NAMES * (80 + 5)];
    qc_ctx ctx;

    qc_ctx_init(&ctx, NULL, NULL);
    if (qc_params_resolve(&ctx, &o->params, &r) < 0 || r.family <= 0)
        return; /* cli_pattern_finish reported it */
    fam = qc_family_info((size_t)r.family - 1);
    if (fam == NULL)
        return;
    if (o->motifs != NULL && !(fam->needs & QC_FAMILY_NEEDS_MOTIFS))
        name_of(o, "motif", 0, names[n++], sizeof names[0]);
    for (i = 0; i < nrows && n < MAX_NAMES; i++) {
        const char *name = t[i].name;
        if (o->raw[i] == NULL || (qc_param_families(&t[i]) & (1u << r.family)) != 0)
            continue;
        if (o->raw[i] == o->repeat[1])
            continue; /* --repeat CxR: named once, by its columns */
        if (o->raw[i] == o->repeat[0])
            name = "repeat";
        name_of(o, name, o->raw[i] != o->repeat[0], names[n++], sizeof names[0]);
    }
    if (n == 0)
        return;
    for (i = 0; i < n && at < sizeof line; i++)
        at += (size_t)snprintf(line + at, sizeof line - at, "%s%s",
                               i == 0 ? "" : i + 1 == n ? " and " : ", ", names[i]);
    cli_error("warning: %s%s%s %s ignored by family %s", o->where != NULL ? o->where : "",
              o->where != NULL ? ": " : "", line, n == 1 ? "is" : "are", fam->name);
}
