/*
 * cmd_rtl_sim.c - `edgeflag rtl-sim`: one command from vectors to a verdict
 * (docs/cli.md): builds the whole-pipeline bench around rtl/'s ef_raster (or
 * a user's own top), cached per configuration, runs it on the vectors'
 * cmd.stim.hex and runs `edgeflag check` on its dumps.  The work is
 * dv/rtl-sim.sh of the source tree this edgeflag was built from (the RTL and
 * the bench live there; EDGEFLAG_SOURCE names another tree); this command
 * runs it with this very binary as the checker.
 */
#include "cli.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#ifndef EF_SOURCE_ROOT
#define EF_SOURCE_ROOT "."
#endif

enum { MAX_ARGS = 256 };

static void usage(FILE *f)
{
    fputs("usage: edgeflag rtl-sim VECTORS_DIR [--sim verilator|icarus] [--ns N] [--top FILE]... [--fast]\n"
          "                        [--out DIR] [--w-max W] [--h-max H] [--e-max E] [--transactions]\n"
          "                        [--cache DIR]\n"
          "\n"
          "Builds the RTL bench (dv/tb/tb_raster.v around rtl/'s ef_raster, or around your own\n"
          "top with ef_raster's ports given with --top), warning-clean and cached per\n"
          "configuration, runs it on VECTORS_DIR/cmd.stim.hex, dumps every interface and runs\n"
          "`edgeflag check` on the dumps against VECTORS_DIR.\n"
          "\n"
          "options:\n"
          "  --sim S         verilator (default) or icarus\n"
          "  --ns N          the build's samples per pixel (default: the vectors' own)\n"
          "  --top FILE      your DUT's Verilog instead of rtl/ (repeat for every file)\n"
          "  --fast          rtl/'s ef_raster SCHEDULE=1 (the overlap schedule): give it vectors\n"
          "                  of `edgeflag vectors --schedule overlap` (or --transactions)\n"
          "  --out DIR       where the dumps go (default CACHE/out/NAME)\n"
          "  --w-max W, --h-max H, --e-max E   the build's limits (default 2048, 2048, 8192)\n"
          "  --transactions  compare in order only (a DUT with other timing)\n"
          "  --cache DIR     the build cache (default build/rtl-sim of the source tree)\n"
          "  -h, --help      show this text\n"
          "\n"
          "exit codes: edgeflag check's when the bench ran (0 PASS, 1 mismatches, 2 its input\n"
          "errors); 2 usage; 3 the DUT refused the case (its reason printed); 4 the bench\n"
          "failed; 5 the build failed, a tool is missing or the source tree is not found.\n",
          f);
}

int ef_cli_rtl_sim(int argc, char **argv)
{
    static char script[4096], self[4096];
    char *args[MAX_ARGS];
    const char *root = getenv("EDGEFLAG_SOURCE");
    int n = 0, have_ef = 0;

    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            usage(stdout);
            return EF_CLI_EXIT_OK;
        }
        if (strcmp(argv[i], "--edgeflag") == 0)
            have_ef = 1;
    }
    if (argc + 6 > MAX_ARGS) {
        ef_cli_error("rtl-sim: too many arguments");
        return EF_CLI_EXIT_USAGE;
    }
    if (!root || !*root)
        root = EF_SOURCE_ROOT;
    if ((size_t)snprintf(script, sizeof script, "%s/dv/rtl-sim.sh", root) >= sizeof script ||
        access(script, R_OK) != 0) {
        ef_cli_error("rtl-sim: no %s: rtl-sim runs the RTL and bench of the source tree edgeflag was built "
                     "from (EDGEFLAG_SOURCE names another)",
                     script);
        return 5;
    }
    args[n++] = (char *)"bash";
    args[n++] = script;
    for (int i = 1; i < argc; i++)
        args[n++] = argv[i];
    if (!have_ef) {
        ssize_t len = readlink("/proc/self/exe", self, sizeof self - 1);
        if (len > 0) {
            self[len] = '\0';
            args[n++] = (char *)"--edgeflag";
            args[n++] = self;
        }
    }
    args[n] = NULL;
    fflush(stdout);
    execvp("bash", args);
    ef_cli_error("rtl-sim: cannot run bash: %s", strerror(errno));
    return 5;
}
