/* Milliseconds per stage of qc_generate, through the context's trace hook. */
#include <string.h>

#include "cli.h"

void cli_timer_start(cli_timer *t, qc_ctx *ctx)
{
    memset(t, 0, sizeof *t);
    t->t0 = t->last = cli_now_ms();
    t->stage = "setup";
    if (ctx != NULL) {
        ctx->trace = cli_timer_trace;
        ctx->trace_ud = t;
    }
}

/* Closes the running stage and starts `stage` (NULL: just close). */
void cli_timer_mark(cli_timer *t, const char *stage)
{
    double now = cli_now_ms();

    if (t->stage != NULL && t->n < sizeof t->ms / sizeof t->ms[0]) {
        t->name[t->n] = t->stage;
        t->ms[t->n++] = now - t->last;
    }
    t->last = now;
    t->stage = stage;
}

/* "done" leaves the last stage running until the caller marks its next:
 * closing it there left the return untimed, so the stages' sum fell short
 * of the total whenever the process was preempted in between. */
void cli_timer_trace(void *ud, const char *stage)
{
    if (strcmp(stage, "done") != 0)
        cli_timer_mark(ud, stage);
}
