#define _POSIX_C_SOURCE 200809L /* clock_gettime, CLOCK_THREAD_CPUTIME_ID */
/* The call's time limit (deadline.h). */
#include <time.h>

#include "base/deadline.h"

static _Thread_local cm_deadline current;

/* CPU seconds this thread has run: batch jobs run one call per thread. */
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
    if (!current.passed && current.at > 0 && thread_seconds() >= current.at) current.passed = 1;
    return current.passed;
}
