/* The command line's progress hook: cancels once interrupted, and shows the
 * stage and how far it is on stderr. By default only on a terminal and after
 * the first two seconds, on one line cleared when the step ends; --progress
 * shows it from the start (off a terminal as plain lines, one per stage and
 * per tenth done); --quiet shows nothing, nor the summary on stdout. */
#ifndef CM_CLI_PROGRESS_LINE_H
#define CM_CLI_PROGRESS_LINE_H

#include <signal.h>

typedef enum progress_mode {
    PROGRESS_AUTO,   /* on a terminal, for runs longer than two seconds */
    PROGRESS_ALWAYS, /* --progress */
    PROGRESS_QUIET   /* --quiet */
} progress_mode;

/* 1 while a progress line is on the terminal (the watchdog clears it). */
extern volatile sig_atomic_t progress_line_shown;

void cli_progress_set_mode(progress_mode mode);

/* 1 under --quiet: the commands print nothing on stdout. */
int cli_quiet(void);

/* A cm_progress_fn. */
int cli_progress(void *user, double fraction, const char *stage);

/* Clears the progress line, if one is shown. */
void cli_progress_done(void);

#endif
