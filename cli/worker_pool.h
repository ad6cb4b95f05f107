/* Jobs run in forked processes, at most a given number at a time. Each
 * job writes what it has to say to a pipe; the parent collects it with the
 * process's exit status and CPU time. A crashing job takes only itself
 * down. On SIGINT/SIGTERM no new job starts, the running ones get SIGTERM
 * (they stop as the commands do, leaving no output) and are waited for. */
#ifndef CM_CLI_WORKER_POOL_H
#define CM_CLI_WORKER_POOL_H

#include <stddef.h>

#include "cli_common.h"

typedef struct worker_result {
    int exit_code;       /* the process's, or CLI_EXIT_INTERNAL if it did not exit */
    const char *failure; /* NULL, or why the process did not run or exit normally */
    const char *record;  /* what the job wrote to its channel, NUL-terminated */
    size_t record_length;
    double cpu_seconds;  /* user + system time of the process */
} worker_result;

/* In the child: runs job `index`, writing its record to the file
 * descriptor `channel`, and returns the process's exit code. */
typedef int (*worker_job)(void *context, size_t index, int channel);
/* In the parent, as each job ends (in the order they end). */
typedef void (*worker_done)(void *context, size_t index, const worker_result *result);

/* Runs jobs 0 .. count - 1 on at most `workers` processes. Returns
 * CLI_EXIT_OK once all ended, or CLI_EXIT_INTERRUPTED once the jobs that
 * were running when the signal came have ended (the others never start). */
int run_workers(size_t count, long workers, worker_job job, worker_done done, void *context);

#endif
