/* Ctrl-C and SIGTERM: stop the computation cleanly, leaving no output. */
#ifndef CM_CLI_INTERRUPT_H
#define CM_CLI_INTERRUPT_H

#include <signal.h>

/* Set by the handler; checked between output files. */
extern volatile sig_atomic_t interrupted;

void catch_interrupts(void);

/* A cm_progress_fn that cancels the core's work once interrupted. */
int cancel_if_interrupted(void *user, double fraction, const char *stage);

#endif
