/* getopt_long without abbreviations: "--spi" must not silently mean "--spiral". */
#include <getopt.h>
#include <string.h>

#include "cli.h"

int cli_getopt(int argc, char **argv, const char *shortopts, const struct option *opts)
{
    int idx = -1, c = getopt_long(argc, argv, shortopts, opts, &idx);
    const char *typed, *eq;
    size_t len;

    if (c == -1 || c == '?' || c == ':' || idx < 0)
        return c;
    /* the element getopt took: "--name=value", or "--name" before its value */
    typed = optarg != NULL && optind >= 2 && optarg == argv[optind - 1] ? argv[optind - 2]
                                                                         : argv[optind - 1];
    if (strncmp(typed, "--", 2) != 0)
        return c;
    typed += 2;
    eq = strchr(typed, '=');
    len = eq != NULL ? (size_t)(eq - typed) : strlen(typed);
    if (len == strlen(opts[idx].name) && strncmp(typed, opts[idx].name, len) == 0)
        return c;
    cli_error("unknown option '--%.*s' (did you mean '--%s'?)", (int)len, typed, opts[idx].name);
    return CLI_GETOPT_REPORTED;
}
