/* Command-line options: one table per subcommand drives both the parsing
 * (getopt_long) and the --help listing. */
#ifndef CM_CLI_OPTIONS_H
#define CM_CLI_OPTIONS_H

#include <stddef.h>
#include <stdio.h>

#include "cli_common.h"

typedef struct option_spec {
    const char *name;  /* long name, without "--" */
    int key;           /* the short letter, or >= 256 for long-only options */
    const char *value; /* what the value is called in --help; NULL: a flag */
    const char *help;  /* may hold '\n' to continue on an indented line */
} option_spec;

enum { MAX_OPTIONS = 32, OPTION_HELP_COLUMN = 24 };

/* Receives each option (key) or positional argument (key 0) in order. */
typedef int (*option_handler)(void *context, int key, const char *value,
                              cli_error *error);

/* Calls handle for each option and positional argument of argv (argv[0] is
 * the subcommand's name); every problem becomes one message naming command.
 * Returns CLI_EXIT_OK or the first non-OK code. */
int parse_options(int argc, char **argv, const char *command,
                  const option_spec *specs, size_t count,
                  option_handler handle, void *context, cli_error *error);

/* The --help listing of specs, help texts aligned in one column. */
void print_options(FILE *out, const option_spec *specs, size_t count);

/* The whole number text in [low, high] (low >= 0), or -1. */
long parse_whole_number(const char *text, long low, long high);

#endif
