/* The job list of `compatmesh batch`: one triangulate job per line, its
 * input files separated by blanks, optionally after a "NAME:" field that
 * names the job's folder. Checked whole before any job runs, so that a
 * malformed list starts nothing. */
#ifndef CM_CLI_BATCH_LIST_H
#define CM_CLI_BATCH_LIST_H

#include <stddef.h>

#include "cli_common.h"

typedef struct batch_entry {
    long line;          /* 1-based line of the list */
    char *name;         /* the job's folder in the output directory */
    char **inputs;      /* paths, relative ones resolved against the list's folder */
    size_t input_count;
} batch_entry;

typedef struct batch_list {
    batch_entry *entries;
    size_t count;
} batch_list;

/* Reads and checks the list at path: every line names two or more
 * existing files and a name no other line has ('#' starts a comment; blank
 * lines are ignored). Errors are "LIST:LINE: what" with CLI_EXIT_USAGE,
 * or CLI_EXIT_INTERNAL when out of memory. */
int batch_list_read(const char *path, batch_list *list, cli_error *error);
void batch_list_free(batch_list *list);

#endif
