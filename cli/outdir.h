/* Output that appears all at once or not at all. Files are written into a
 * temporary directory beside the target directory (same parent, hence the
 * same file system, so rename is atomic) and moved in on commit; on failure
 * the temporary directory is removed and the target is left as it was. */
#ifndef CM_CLI_OUTDIR_H
#define CM_CLI_OUTDIR_H

#include <stddef.h>
#include <stdio.h>

#include "cli_common.h"

typedef struct staged_output {
    char *target;  /* the output directory, without trailing slashes */
    const char *const *inputs; /* files no output may replace (borrowed) */
    size_t input_count;
    char *staging; /* the temporary directory; NULL once committed */
    char **names;  /* files requested so far, and their staging paths */
    char **paths;
    size_t count;
    const char *const *removed; /* files of target that commit removes (borrowed) */
    size_t removed_count;
} staged_output;

/* Checks, before any work is done, that target can become the output
 * directory. Returns CLI_EXIT_USAGE if target is empty or exists and is not
 * a directory, CLI_EXIT_INTERNAL if it or its parent cannot be written. */
int staged_output_check(const char *target, cli_error *error);

/* Creates the temporary directory for target; the inputs (input_count
 * paths, borrowed) are files no output may replace. On failure *out is left
 * empty and staged_output_discard on it does nothing. */
int staged_output_begin(staged_output *out, const char *target, const char *const *inputs,
                        size_t input_count, cli_error *error);

/* The path under which to write file `name` (no slashes); it is moved to
 * target/name on commit. Owned by *out. NULL if out of memory. */
const char *staged_output_path(staged_output *out, const char *name);

/* Files (no slashes) that commit removes from target when it is there:
 * an earlier run's output this run does not write, which report.json would
 * otherwise sit beside without describing. names are borrowed. */
void staged_output_remove(staged_output *out, const char *const *names, size_t count);

/* Moves every requested file into target, creating target if missing;
 * files of the same name are replaced, other files in target are kept.
 * Refused, before anything is moved, when a file would replace an input,
 * or when SIGINT/SIGTERM arrived (CLI_EXIT_INTERRUPTED).
 * report.json is the set's manifest: an old one is removed before the
 * first move and the new one moved in last, so a report.json always
 * describes the files beside it, even if the run is killed midway. */
int staged_output_commit(staged_output *out, cli_error *error);

/* Removes the temporary directory (if still there) and frees *out. Call it
 * after commit too. */
void staged_output_discard(staged_output *out);

/* CLI_EXIT_USAGE with a message when path is one of the inputs (the same
 * file: device and inode), else CLI_EXIT_OK (also when path does not
 * exist). An output never replaces an input. */
int refuse_input_as_output(const char *path, const char *const *inputs, size_t count,
                           cli_error *error);

/* dir + "/" + name in new memory (free it), NULL if out of memory. */
char *path_join(const char *dir, const char *name);

/* fopen for writing / fclose with an error message naming the path.
 * output_close reports a failure of any earlier write to the stream too. */
FILE *output_open(const char *path, cli_error *error);
int output_close(FILE *file, const char *path, cli_error *error);

#endif
