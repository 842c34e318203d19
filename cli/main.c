/* quiltc: the command-line front end over libquiltc. */
#include <stdio.h>
#include <string.h>

#include "cli.h"

static const struct command {
    const char *name;
    int (*fn)(int argc, char **argv);
    const char *help;
} commands[] = {
    {"generate", cmd_generate, "make a pattern for a block and write machine files"},
    {"skeleton", cmd_skeleton, "write the points and their tree or tour (JSON or SVG)"},
    {"convert", cmd_convert, "convert a pattern between machine formats (any quiltc writes)"},
    {"check", cmd_check, "lint a pattern file (any format) and check its geometry"},
    {"job", cmd_job, "generate a whole quilt of blocks from a JSON job file"},
    {"motifs", cmd_motifs, "list the motif library, or draw one motif as SVG"},
    {"list", cmd_list, "list families, parameters, motifs or formats"},
    {"devices", cmd_devices, "list USB devices that could take a pattern"},
    {"upload", cmd_upload, "send a pattern file to a machine over USB"},
    {"udev-rule", cmd_udev_rule, "print a udev rule giving access to a machine"},
};

static void usage(FILE *f)
{
    size_t i;

    fputs("usage: quiltc COMMAND [options]   (quiltc COMMAND --help for its options)\n"
          "Free-motion quilting patterns for computer-guided long-arm machines.\n\n",
          f);
    for (i = 0; i < sizeof commands / sizeof commands[0]; i++)
        fprintf(f, "  %-10s %s\n", commands[i].name, commands[i].help);
    fputs("\n  --version  print the version\n"
          "Example: quiltc generate --region heart:10 --family stipple -o heart.pat\n",
          f);
}

int main(int argc, char **argv)
{
    size_t i;

    if (argc < 2) {
        usage(stderr);
        return CLI_USAGE;
    }
    if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0 ||
        strcmp(argv[1], "help") == 0) {
        usage(stdout);
        return CLI_OK;
    }
    if (strcmp(argv[1], "--version") == 0 || strcmp(argv[1], "version") == 0) {
        printf("quiltc %s\n", qc_version());
        return CLI_OK;
    }
    for (i = 0; i < sizeof commands / sizeof commands[0]; i++)
        if (strcmp(argv[1], commands[i].name) == 0)
            return commands[i].fn(argc - 1, argv + 1);
    cli_error("unknown command '%s' (try 'quiltc --help')", argv[1]);
    return CLI_USAGE;
}
