#define _POSIX_C_SOURCE 200809L /* clock_gettime */

#include "progress_line.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "interrupt.h"

#define QUIET_SECONDS 2.0  /* short runs print nothing (unless --progress) */
#define EVERY_SECONDS 0.5

static progress_mode mode = PROGRESS_AUTO;
static double started = -1, last_shown;
/* Plain lines (--progress off a terminal): the stage and tenth last printed. */
static char last_stage[64];
static int last_tenth = -1;
volatile sig_atomic_t progress_line_shown;

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

void cli_progress_set_mode(progress_mode new_mode) { mode = new_mode; }

int cli_quiet(void) { return mode == PROGRESS_QUIET; }

/* A log, not a terminal: one line whenever the stage or the tenth changes. */
static void plain_line(double t, double fraction, const char *stage)
{
    int tenth = (int)floor(10 * fmin(fmax(fraction, 0.0), 1.0));
    if (tenth == last_tenth && strncmp(stage, last_stage, sizeof last_stage - 1) == 0) return;
    snprintf(last_stage, sizeof last_stage, "%s", stage);
    last_tenth = tenth;
    fprintf(stderr, "compatmesh: %s %3.0f%%  (%.1f s)\n", stage, 100 * fraction, t - started);
    fflush(stderr);
}

int cli_progress(void *user, double fraction, const char *stage)
{
    (void)user;
    static int terminal = -1;
    if (terminal < 0) terminal = isatty(STDERR_FILENO);
    if (interrupted || mode == PROGRESS_QUIET || (!terminal && mode == PROGRESS_AUTO))
        return interrupted;
    double t = now();
    if (started < 0) started = t;
    if (!terminal) {
        plain_line(t, fraction, stage);
        return interrupted;
    }
    double wait = mode == PROGRESS_ALWAYS ? 0.0 : QUIET_SECONDS;
    if (t - started >= wait && (!progress_line_shown || t - last_shown >= EVERY_SECONDS)) {
        fprintf(stderr, "\rcompatmesh: %s %3.0f%%  (%.0f s)   ", stage, 100 * fraction, t - started);
        fflush(stderr);
        last_shown = t, progress_line_shown = 1;
    }
    return interrupted;
}

void cli_progress_done(void)
{
    if (progress_line_shown) fputs("\r\033[K", stderr); /* back to the start, erase the line */
    progress_line_shown = 0, started = -1, last_shown = 0;
    last_stage[0] = '\0', last_tenth = -1;
}
