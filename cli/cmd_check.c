/* quiltc check FILE.pat: the dialect linter, one finding a line. */
#include <stdlib.h>
#include <string.h>

#include "cli.h"

static void print_finding(void *ud, size_t line, const char *kind, const char *text)
{
    size_t *count = ud;
    printf("line %lu: %s: %s\n", (unsigned long)line, kind, text);
    (*count)++;
}

int cmd_check(int argc, char **argv)
{
    qc_ctx ctx;
    char *buf;
    size_t len, findings = 0;
    int rc;

    if (argc == 2 && strcmp(argv[1], "--help") == 0) {
        puts("usage: quiltc check FILE.pat\nReports every dialect fault; exit 0 when sewable.");
        return CLI_OK;
    }
    if (argc != 2) {
        cli_error("check: expected one FILE.pat");
        return CLI_USAGE;
    }
    if (cli_read_file(argv[1], (size_t)256 << 20, &buf, &len) != 0)
        return CLI_RUNTIME;
    qc_ctx_init(&ctx, NULL, NULL);
    {
        qc_plan plan = {0};
        size_t counted = 0;
        rc = qc_io_check_pat(&ctx, buf, len, print_finding, &findings, &plan, &counted);
        findings = counted > findings ? counted : findings;
        qc_plan_free(&ctx, &plan);
    }
    free(buf);
    if (rc < 0)
        return cli_fail(&ctx, argv[1], ctx.status);
    printf("%s: %lu finding%s\n", argv[1], (unsigned long)findings, findings == 1 ? "" : "s");
    return findings == 0 ? CLI_OK : CLI_RUNTIME;
}
