/* The command line's progress hook: cancels once interrupted, and on a
 * terminal shows the stage and how far it is after the first two seconds,
 * on one line of stderr that is cleared when the step ends. */
#ifndef CM_CLI_PROGRESS_LINE_H
#define CM_CLI_PROGRESS_LINE_H

#include <signal.h>

/* 1 while a progress line is on the terminal (the watchdog clears it). */
extern volatile sig_atomic_t progress_line_shown;

/* A cm_progress_fn. */
int cli_progress(void *user, double fraction, const char *stage);

/* Clears the progress line, if one is shown. */
void cli_progress_done(void);

#endif
