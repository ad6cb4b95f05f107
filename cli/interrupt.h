/* Ctrl-C and SIGTERM: stop the computation within a second, leaving no
 * output. */
#ifndef CM_CLI_INTERRUPT_H
#define CM_CLI_INTERRUPT_H

#include <signal.h>

/* Set by the handler; checked between output files. */
extern volatile sig_atomic_t interrupted;
/* Set while a staged output is open (outdir.c): the watchdog waits. */
extern volatile sig_atomic_t writing_output;
/* While a library writes one temporary file and polls no flag (Gmsh's
 * writers, write_volume.c): its path, which the watchdog removes before
 * it ends the process, so a long write stops within a second too. */
extern const char *volatile output_temporary;

void catch_interrupts(void);

/* For a process that only waits for others (batch): a signal just sets
 * `interrupted`, no watchdog ends the process before its workers are done. */
void catch_interrupts_without_watchdog(void);

/* In a child after fork(): a watchdog of its own, as timers are not
 * inherited. */
void catch_interrupts_in_child(void);

#endif
