#define _POSIX_C_SOURCE 200809L /* clock_gettime, CLOCK_THREAD_CPUTIME_ID */
/* The call's time limit (deadline.h). */
#include <time.h>

#include "base/deadline.h"

static _Thread_local cm_deadline current;
/* Reading a thread's CPU clock is a system call: the checks look at it on
 * the first call of a call's limit and every CM_DEADLINE_EVERY-th after,
 * which stops the remesher at most that many safe points late. */
#define CM_DEADLINE_EVERY 16
static _Thread_local unsigned checks;

/* CPU seconds this thread has run (a call runs on one thread). */
static double thread_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

cm_deadline cm_deadline_begin(double seconds)
{
    cm_deadline outer = current;
    if (seconds > 0) {
        double at = thread_seconds() + seconds;
        if (!(current.at > 0) || at < current.at) current.at = at;
    }
    current.passed = outer.passed;
    checks = 0;
    return outer;
}

int cm_deadline_end(cm_deadline outer)
{
    int passed = current.passed;
    if (current.at == outer.at) outer.passed |= passed; /* the outer call's own deadline passed */
    current = outer;
    return passed;
}

int cm_deadline_passed(void)
{
    if (!current.passed && current.at > 0 && checks++ % CM_DEADLINE_EVERY == 0 && thread_seconds() >= current.at)
        current.passed = 1;
    return current.passed;
}
