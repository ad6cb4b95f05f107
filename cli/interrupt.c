#define _POSIX_C_SOURCE 200809L /* sigaction */

#include "interrupt.h"

#include <string.h>

volatile sig_atomic_t interrupted;

static void on_interrupt(int signal_number)
{
    (void)signal_number;
    interrupted = 1;
}

void catch_interrupts(void)
{
    struct sigaction action;
    memset(&action, 0, sizeof action);
    action.sa_handler = on_interrupt;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, NULL);
    sigaction(SIGTERM, &action, NULL);
}

int cancel_if_interrupted(void *user, double fraction, const char *stage)
{
    (void)user, (void)fraction, (void)stage;
    return interrupted;
}
