#define _GNU_SOURCE /* ppoll, wait4 */

#include "worker_pool.h"

#include <errno.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "interrupt.h"

typedef struct slot {
    pid_t pid;
    int fd;            /* read end of the job's channel */
    size_t index;
    char *data;        /* the record so far */
    size_t length, capacity;
    int out_of_memory; /* the record did not fit: the job counts as failed */
} slot;

static void report_failure(worker_done done, void *context, size_t index, const char *failure)
{
    worker_result result = {CLI_EXIT_INTERNAL, failure, "", 0, 0};
    done(context, index, &result);
}

/* Forks the process of job `index` into s. Signals are blocked here; the
 * child restores `unblocked` once its watchdog is set, so that a signal
 * already pending cancels it at once. Returns 0, or -1 with errno set. */
static int start(slot *s, size_t index, const slot *running, size_t running_count,
                 worker_job job, void *context, const sigset_t *unblocked)
{
    int channel[2];
    if (pipe(channel) != 0) return -1;
    fflush(NULL); /* nothing buffered is written twice */
    pid_t pid = fork();
    if (pid < 0) {
        int saved = errno;
        close(channel[0]), close(channel[1]);
        errno = saved;
        return -1;
    }
    if (pid == 0) {
        close(channel[0]);
        for (size_t i = 0; i < running_count; i++) close(running[i].fd);
        catch_interrupts_in_child();
        sigprocmask(SIG_SETMASK, unblocked, NULL);
        int code = interrupted ? CLI_EXIT_INTERRUPTED : job(context, index, channel[1]);
        _exit(code);
    }
    close(channel[1]);
    memset(s, 0, sizeof *s);
    s->pid = pid, s->fd = channel[0], s->index = index;
    return 0;
}

/* Reads what is there; returns 1 at end of file (the job closed it by
 * ending), 0 to come back later. */
static int read_some(slot *s)
{
    char scratch[4096];
    if (!s->out_of_memory && s->capacity - s->length < sizeof scratch) {
        size_t grown = s->capacity ? 2 * s->capacity : sizeof scratch * 2;
        char *more = realloc(s->data, grown);
        if (more) s->data = more, s->capacity = grown;
        else s->out_of_memory = 1;
    }
    char *into = s->out_of_memory ? scratch : s->data + s->length;
    size_t room = s->out_of_memory ? sizeof scratch : s->capacity - s->length - 1;
    ssize_t got = read(s->fd, into, room);
    if (got < 0) return errno == EINTR || errno == EAGAIN ? 0 : 1;
    if (got == 0) return 1;
    if (!s->out_of_memory) s->length += (size_t)got;
    return 0;
}

/* Waits for the process that closed its channel and hands on its result. */
static void finish(slot *s, worker_done done, void *context)
{
    close(s->fd);
    int status = 0;
    struct rusage usage;
    memset(&usage, 0, sizeof usage);
    while (wait4(s->pid, &status, 0, &usage) < 0 && errno == EINTR) continue;
    char failure[128];
    worker_result result = {CLI_EXIT_INTERNAL, NULL, "", 0, 0};
    result.cpu_seconds = (double)usage.ru_utime.tv_sec + 1e-6 * (double)usage.ru_utime.tv_usec +
                         (double)usage.ru_stime.tv_sec + 1e-6 * (double)usage.ru_stime.tv_usec;
    if (WIFEXITED(status)) {
        result.exit_code = WEXITSTATUS(status);
    } else if (WIFSIGNALED(status)) {
        snprintf(failure, sizeof failure, "the job's process was ended by signal %d (%s)",
                 WTERMSIG(status), strsignal(WTERMSIG(status)));
        result.failure = failure;
    }
    if (s->out_of_memory) result.failure = "out of memory for the job's result";
    if (s->data && !s->out_of_memory) {
        s->data[s->length] = '\0';
        result.record = s->data, result.record_length = s->length;
    }
    done(context, s->index, &result);
    free(s->data);
}

int run_workers(size_t count, long workers, worker_job job, worker_done done, void *context)
{
    sigset_t blocked, previous, unblocked;
    sigemptyset(&blocked);
    sigaddset(&blocked, SIGINT);
    sigaddset(&blocked, SIGTERM);
    sigprocmask(SIG_BLOCK, &blocked, &previous);
    unblocked = previous;
    sigdelset(&unblocked, SIGINT);
    sigdelset(&unblocked, SIGTERM);
    size_t most = workers < 1 ? 1 : (size_t)workers < count ? (size_t)workers : count;
    slot *slots = calloc(most ? most : 1, sizeof *slots);
    struct pollfd *polls = calloc(most ? most : 1, sizeof *polls);
    if (!slots || !polls) most = 0;
    size_t next = 0, running = 0;
    int forwarded = 0;
    /* Without memory for the table, every job fails alike. */
    for (; most == 0 && next < count; next++) report_failure(done, context, next, "out of memory");
    while (running > 0 || (next < count && !interrupted)) {
        while (!interrupted && running < most && next < count) {
            size_t index = next++;
            if (start(&slots[running], index, slots, running, job, context, &unblocked) == 0) {
                running++;
            } else {
                char failure[160];
                snprintf(failure, sizeof failure, "cannot start the job's process: %s",
                         strerror(errno));
                report_failure(done, context, index, failure);
            }
        }
        if (interrupted && !forwarded) {
            for (size_t i = 0; i < running; i++) kill(slots[i].pid, SIGTERM);
            forwarded = 1;
        }
        if (running == 0) continue;
        for (size_t i = 0; i < running; i++) polls[i] = (struct pollfd){slots[i].fd, POLLIN, 0};
        /* Signals are let in only while waiting, so none is missed. */
        if (ppoll(polls, running, NULL, &unblocked) < 0) continue; /* EINTR: look again */
        for (size_t i = running; i-- > 0;) {
            if (!polls[i].revents || !read_some(&slots[i])) continue;
            finish(&slots[i], done, context);
            slots[i] = slots[--running];
        }
    }
    free(slots);
    free(polls);
    sigprocmask(SIG_SETMASK, &previous, NULL);
    return interrupted ? CLI_EXIT_INTERRUPTED : CLI_EXIT_OK;
}
