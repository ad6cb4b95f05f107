/* The subcommands besides triangulate, each in its own file; argv[0] is the
 * subcommand's name. They return the exit code. */
#ifndef CM_CLI_COMMANDS_H
#define CM_CLI_COMMANDS_H

int run_morph(int argc, char **argv);
int run_sweep(int argc, char **argv);

#endif
