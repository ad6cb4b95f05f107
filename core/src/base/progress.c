/* The stage table (progress.h). Stages whose work is not known in advance
 * (the partition) report one fraction throughout. */
#include <stdio.h>

#include "base/progress.h"
#include "base/clock.h"
#include "base/gmp_memory.h"

static const struct {
    const char *name;
    double from, to;
} stages[] = {
    [CM_STAGE_VALIDATE] = {"validate", 0.0, 0.1},
    [CM_STAGE_TRIANGULATE] = {"triangulate polygons", 0.1, 0.4},
    [CM_STAGE_PARTITION] = {"partition", 0.4, 0.4},
    [CM_STAGE_REMESH] = {"remesh", 0.4, 0.8},
    [CM_STAGE_CHECK] = {"check", 0.8, 1.0},
    [CM_STAGE_DONE] = {"done", 1.0, 1.0},
    [CM_STAGE_ENCLOSURE] = {"enclosure", 0.0, 0.9},
    [CM_STAGE_MORPH_SYSTEM] = {"morph system", 0.9, 1.0},
    [CM_STAGE_SWEEP] = {"sweep", 0.0, 1.0},
};

void cm_progress_init(cm_progress *p, cm_progress_fn fn, void *user)
{
    p->fn = fn;
    p->user = user;
    p->last = fn ? cm_seconds_now() : 0.0;
    p->stage = CM_STAGE_VALIDATE;
    p->within = 0.0;
    p->cancelled = 0;
    p->checks = 0;
    cm_gmp_memory_begin();
}

/* GMP ran on its reserve: stop as if cancelled (the status becomes
 * CM_ERR_NO_MEMORY, error.c). */
static int starved(cm_progress *p)
{
    if (p && cm_gmp_memory_exhausted()) p->cancelled = 1;
    return p && p->cancelled;
}

int cm_progress_report(cm_progress *p, cm_stage s, double within)
{
    if (starved(p)) return 1;
    if (!p || !p->fn) return 0;
    if (s == p->stage && within < p->within) within = p->within; /* a stage's later parts start again at 0 */
    p->stage = s;
    p->within = within;
    double f = stages[s].from + (stages[s].to - stages[s].from) * within;
    p->cancelled = p->fn(p->user, f, stages[s].name) != 0;
    return p->cancelled;
}

int cm_progress_poll(cm_progress *p, cm_stage s, double within)
{
    if (starved(p)) return 1;
    if (!p || !p->fn) return 0;
    double now = cm_seconds_now();
    if (now - p->last < 0.2) return 0;
    p->last = now;
    return cm_progress_report(p, s, within);
}

int cm_progress_check(cm_progress *p)
{
    if (starved(p)) return 1;
    if (!p || !p->fn) return 0;
    if (++p->checks % 32 != 0) return p->cancelled; /* the clock costs more than most loop bodies */
    return cm_progress_poll(p, p->stage, p->within);
}

void cm_progress_relay_init(cm_progress_relay *relay, cm_progress_fn fn, void *user)
{
    *relay = (cm_progress_relay){fn, user, 0, NULL, 0.0, CM_RELAY_FIRST, ""};
}

void cm_progress_relay_next(cm_progress_relay *relay, const char *label)
{
    relay->run++, relay->label = label;
    relay->from = relay->to, relay->to += 0.5 * (1.0 - relay->to);
}

int cm_progress_relay_fn(void *user, double fraction, const char *stage)
{
    cm_progress_relay *relay = user;
    if (fraction >= 1.0) return 0; /* a run's "done": the relay's is the end */
    double at = relay->from + (relay->to - relay->from) * fraction;
    if (relay->run == 0) return relay->fn(relay->user, at, stage);
    if (relay->label) snprintf(relay->name, sizeof relay->name, "%s: %s", relay->label, stage);
    else snprintf(relay->name, sizeof relay->name, "pairing %d: %s", relay->run + 1, stage);
    return relay->fn(relay->user, at, relay->name);
}

int cm_progress_relay_done(cm_progress_relay *relay)
{
    return relay->fn(relay->user, 1.0, stages[CM_STAGE_DONE].name) != 0;
}
