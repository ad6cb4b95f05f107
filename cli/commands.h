/* The subcommands, each in its own file; argv[0] is the subcommand's name.
 * They return the exit code. */
#ifndef CM_CLI_COMMANDS_H
#define CM_CLI_COMMANDS_H

int run_triangulate(int argc, char **argv);
int run_morph(int argc, char **argv);
int run_sweep(int argc, char **argv);
int run_batch(int argc, char **argv);

/* The exit codes, for the help of the tool and of its commands. */
extern const char *const cli_exit_status_help;

#endif
