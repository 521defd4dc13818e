/*
 * main.c - `edgeflag`: dispatches to one subcommand per file (cmd_*.c).
 * The thin main of the tool; docs/cli.md is its user documentation.
 */
#include "cli.h"

#include "edgeflag.h"

#include <stdio.h>
#include <string.h>

typedef struct command {
    const char *name;
    int (*run)(int argc, char **argv);
    const char *summary;
} command;

static const command commands[] = {
    { "render", ef_cli_render, "rasterize an SVG or .scene file to PNG, PAM or PGM" },
    { "patterns", ef_cli_patterns, "search and print the n-rooks sample patterns" },
    { "gen", ef_cli_gen, "write seeded regression scenes (directed corner cases, random)" },
    { "vectors", ef_cli_vectors, "write cycle-level test vectors (hex, VCD, binary) of a scene" },
    { "check", ef_cli_check, "compare an RTL's vector dumps with the expected vectors" },
    { "rtl-sim", ef_cli_rtl_sim, "build and run the RTL bench on vectors, then check its dumps" },
    { "coverage", ef_cli_coverage, "functional coverage of vector sets (the spec's cover points)" },
};
#define NCOMMANDS (sizeof commands / sizeof commands[0])

static void usage(FILE *f)
{
    fputs("usage: edgeflag COMMAND [OPTIONS]\n"
          "       edgeflag help [COMMAND]\n"
          "       edgeflag --version\n"
          "\n"
          "Bit-exact reference model of the scanline edge-flag antialiasing rasterizer.\n"
          "\n"
          "commands:\n",
          f);
    for (size_t i = 0; i < NCOMMANDS; i++)
        fprintf(f, "  %-10s %s\n", commands[i].name, commands[i].summary);
    fputs("  help       show this text, or a command's usage\n"
          "\n"
          "'edgeflag COMMAND --help' shows a command's options.\n"
          "exit codes: 0 ok, 2 usage, 3 bad input, 4 output not written, 70 internal error.\n",
          f);
}

static const command *find(const char *name)
{
    for (size_t i = 0; i < NCOMMANDS; i++)
        if (strcmp(commands[i].name, name) == 0)
            return &commands[i];
    return NULL;
}

int main(int argc, char **argv)
{
    const command *cmd;

    if (argc < 2) {
        usage(stderr);
        return EF_CLI_EXIT_USAGE;
    }
    if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0) {
        usage(stdout);
        return EF_CLI_EXIT_OK;
    }
    if (strcmp(argv[1], "--version") == 0) {
        if (argc != 2) {
            fputs("edgeflag: --version takes no arguments\n", stderr);
            return EF_CLI_EXIT_USAGE;
        }
        printf("edgeflag %s\n", EF_VERSION_STRING);
        return EF_CLI_EXIT_OK;
    }
    if (strcmp(argv[1], "help") == 0) {
        if (argc == 2) {
            usage(stdout);
            return EF_CLI_EXIT_OK;
        }
        if (argc == 3 && (cmd = find(argv[2])) != NULL) {
            /* Reuse the command's own --help so the two never drift apart. */
            char help[] = "--help";
            char *sub[3] = { argv[2], help, NULL };
            return cmd->run(2, sub);
        }
        fprintf(stderr, "edgeflag: help: unknown command '%s'\n", argc > 2 ? argv[2] : "");
        return EF_CLI_EXIT_USAGE;
    }
    cmd = find(argv[1]);
    if (!cmd) {
        fprintf(stderr, "edgeflag: unknown command '%s'\nTry 'edgeflag --help'.\n", argv[1]);
        return EF_CLI_EXIT_USAGE;
    }
    return cmd->run(argc - 1, argv + 1);
}
