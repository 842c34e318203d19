/* The line per file written that generate, job and convert print on stderr. */
#include <string.h>

#include "stats_json.h"

void cli_say_written(const char *const *paths, const int *formats, size_t n,
                     const qc_plan *plan, const cli_sewing *sew, int inches)
{
    qc_plan_estimate est;
    double thread, bobbins;
    long secs;
    size_t i;
    char extra[48] = "";

    qc_plan_estimate_get(plan, sew->spi, sew->speed_mm_s, &est);
    thread = est.thread_mm / (inches ? 914.4 : 1000.0);
    secs = (long)(est.seconds + 0.5);
    bobbins = cli_bobbins(&est, sew);
    if (bobbins > 0)
        snprintf(extra, sizeof extra, ", %.1f bobbin%s", bobbins, bobbins == 1 ? "" : "s");
    for (i = 0; i < n; i++) {
        fputs("wrote ", stderr);
        cli_put_escaped(stderr, strcmp(paths[i], "-") == 0 ? "stdout" : paths[i]);
        fprintf(stderr, " (%s): %lu stitches at %g spi, %.1f %s of thread%s, about %ld min %02ld s\n",
                qc_format_name(formats[i]), (unsigned long)est.stitches, sew->spi, thread,
                inches ? "yd" : "m", extra, secs / 60, secs % 60);
    }
}
