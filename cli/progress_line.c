#define _POSIX_C_SOURCE 200809L /* clock_gettime */

#include "progress_line.h"

#include <stdio.h>
#include <time.h>
#include <unistd.h>

#include "interrupt.h"

#define QUIET_SECONDS 2.0  /* short runs print nothing */
#define EVERY_SECONDS 0.5

static double started = -1, last_shown;
volatile sig_atomic_t progress_line_shown;

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

int cli_progress(void *user, double fraction, const char *stage)
{
    (void)user;
    static int terminal = -1;
    if (terminal < 0) terminal = isatty(STDERR_FILENO);
    if (terminal && !interrupted) {
        double t = now();
        if (started < 0) started = t;
        if (t - started >= QUIET_SECONDS && t - last_shown >= EVERY_SECONDS) {
            fprintf(stderr, "\rcompatmesh: %s %3.0f%%  (%.0f s)   ", stage, 100 * fraction, t - started);
            fflush(stderr);
            last_shown = t, progress_line_shown = 1;
        }
    }
    return interrupted;
}

void cli_progress_done(void)
{
    if (progress_line_shown) fputs("\r\033[K", stderr); /* back to the start, erase the line */
    progress_line_shown = 0, started = -1, last_shown = 0;
}
