#define _POSIX_C_SOURCE 200809L /* sigaction, timer_create */

#include "interrupt.h"

#include <string.h>
#include <time.h>
#include <unistd.h>

#include "cli_common.h"
#include "progress_line.h"

volatile sig_atomic_t interrupted;
volatile sig_atomic_t writing_output;
const char *volatile output_temporary;

/* The core polls its progress callback in every long loop, so a run
 * normally ends within a fraction of a second of the signal; should one
 * step not poll in time, the watchdog ends the process WATCHDOG_NS after
 * the signal, unless output is being written (the writers check
 * `interrupted` between files and remove what they staged), or then
 * where the output is one temporary file a library is writing, which it
 * removes first. */
#define WATCHDOG_NS 600000000L

static timer_t watchdog;
static int have_watchdog;

static void on_watchdog(int signal_number)
{
    (void)signal_number;
    if (writing_output) {
        const char *temporary = output_temporary;
        if (!temporary) return;
        unlink(temporary);
    }
    static const char erase[] = "\r\033[K", message[] = "compatmesh: interrupted; nothing written\n";
    ssize_t written = progress_line_shown ? write(STDERR_FILENO, erase, sizeof erase - 1) : 0;
    written = write(STDERR_FILENO, message, sizeof message - 1);
    (void)written;
    _exit(CLI_EXIT_INTERRUPTED);
}

static void on_interrupt(int signal_number)
{
    (void)signal_number;
    if (!interrupted && have_watchdog) {
        struct itimerspec when;
        memset(&when, 0, sizeof when);
        when.it_value.tv_nsec = WATCHDOG_NS;
        when.it_interval.tv_nsec = WATCHDOG_NS; /* again while writing */
        timer_settime(watchdog, 0, &when, NULL);
    }
    interrupted = 1;
}

void catch_interrupts(void)
{
    struct sigaction action;
    memset(&action, 0, sizeof action);
    sigemptyset(&action.sa_mask);
    action.sa_handler = on_watchdog;
    sigaction(SIGALRM, &action, NULL);
    struct sigevent event;
    memset(&event, 0, sizeof event);
    event.sigev_notify = SIGEV_SIGNAL;
    event.sigev_signo = SIGALRM;
    if (!have_watchdog) /* once: Gmsh's start makes the sweep call this again */
        have_watchdog = timer_create(CLOCK_MONOTONIC, &event, &watchdog) == 0;
    action.sa_handler = on_interrupt;
    sigaction(SIGINT, &action, NULL);
    sigaction(SIGTERM, &action, NULL);
}

void catch_interrupts_without_watchdog(void)
{
    if (have_watchdog) timer_delete(watchdog);
    have_watchdog = 0;
}

void catch_interrupts_in_child(void)
{
    have_watchdog = 0; /* the parent's timer is not the child's */
    catch_interrupts();
}
