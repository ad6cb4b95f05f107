/* compatmesh: the command-line tool's entry point, which hands the
 * arguments to one command (triangulate, morph, sweep, batch). */
#include <stdio.h>
#include <string.h>

#include <compatmesh/compatmesh.h>

#include "cli_common.h"
#include "commands.h"
#include "interrupt.h"

const char *const cli_exit_status_help =
    "Exit status:\n"
    "  0    success\n"
    "  1    internal failure: the library failed or ran out of memory, or an\n"
    "       output could not be written (DIR or its parent not writable, ...)\n"
    "  2    bad input or usage: unknown option, fewer than two inputs,\n"
    "       unreadable or malformed input file, vertex counts that differ\n"
    "       with --correspondence index, a polygon that is not simple, or DIR\n"
    "       exists and is not a directory\n"
    "  130  interrupted\n";

/* ---- subcommands --------------------------------------------------------- */

typedef struct subcommand {
    const char *name;
    const char *summary;
    int (*run)(int argc, char **argv); /* argv[0] is the subcommand's name */
} subcommand;

static const subcommand subcommands[] = {
    {"triangulate", "compatibly triangulate k >= 2 polygons", run_triangulate},
    {"morph", "valid intermediate sections between the polygons", run_morph},
    {"sweep", "the volume between them as a prism/tet mesh (FEA formats)", run_sweep},
    {"batch", "triangulate many sets of polygons, one per line of a list, in parallel", run_batch},
};
static const size_t subcommand_count = sizeof subcommands / sizeof subcommands[0];

static void print_main_help(FILE *out)
{
    fputs("Usage: compatmesh COMMAND [ARGUMENTS]\n"
          "       compatmesh --help | --version\n"
          "\n"
          "Compatible triangulations of planar polygons whose vertices correspond\n"
          "by index or by arc length (Surazhsky & Gotsman, \"High Quality\n"
          "Compatible Triangulations\").\n"
          "\n"
          "Commands:\n", out);
    for (size_t i = 0; i < subcommand_count; i++)
        fprintf(out, "  %-14s%s\n", subcommands[i].name, subcommands[i].summary);
    fputs("\n"
          "Options:\n"
          "  -h, --help    show this help and exit\n"
          "      --version show the version and exit\n"
          "\n"
          "Run 'compatmesh COMMAND --help' for the arguments of a command.\n"
          "\n", out);
    fputs(cli_exit_status_help, out);
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fputs("compatmesh: missing command (see 'compatmesh --help')\n", stderr);
        return CLI_EXIT_USAGE;
    }
    const char *command = argv[1];
    if (strcmp(command, "--help") == 0 || strcmp(command, "-h") == 0) {
        print_main_help(stdout);
        return CLI_EXIT_OK;
    }
    if (strcmp(command, "--version") == 0) {
        printf("compatmesh %d.%d.%d\n", CM_VERSION_MAJOR, CM_VERSION_MINOR,
               CM_VERSION_PATCH);
        return CLI_EXIT_OK;
    }
    for (size_t i = 0; i < subcommand_count; i++) {
        if (strcmp(command, subcommands[i].name) == 0) {
            catch_interrupts();
            return subcommands[i].run(argc - 1, argv + 1);
        }
    }
    fprintf(stderr, "compatmesh: unknown %s '%s' (see 'compatmesh --help')\n",
            command[0] == '-' ? "option" : "command", command);
    return CLI_EXIT_USAGE;
}
