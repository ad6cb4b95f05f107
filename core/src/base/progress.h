/* Progress and cancellation: the stages of a run, the share of the
 * caller's progress bar each one takes, and the one cancel check every
 * stage and every long loop calls. */
#ifndef CM_BASE_PROGRESS_H
#define CM_BASE_PROGRESS_H

#include "compatmesh/compatmesh.h"

typedef enum cm_stage {
    /* cm_triangulate */
    CM_STAGE_VALIDATE,
    CM_STAGE_TRIANGULATE,  /* each polygon alone, by ear clipping */
    CM_STAGE_PARTITION,    /* or the overlay: the first compatible mesh */
    CM_STAGE_REMESH,
    CM_STAGE_CHECK,
    CM_STAGE_DONE,
    /* cm_morph_create */
    CM_STAGE_ENCLOSURE,
    CM_STAGE_MORPH_SYSTEM,
    /* cm_sweep_create */
    CM_STAGE_SWEEP,
} cm_stage;

typedef struct cm_progress {
    cm_progress_fn fn; /* NULL: nobody listens, nothing cancels */
    void *user;
    double last;       /* clock of the last throttled report */
    cm_stage stage;    /* what was reported last */
    double within;
    int cancelled;     /* the caller asked to cancel, or GMP ran out of memory
                        (gmp_memory.h): every check says so */
    unsigned checks;   /* cm_progress_check looks at the clock every 32nd call */
} cm_progress;

void cm_progress_init(cm_progress *p, cm_progress_fn fn, void *user);
/* Reports `within` (0..1) of stage s, mapped into the stage's range, and
 * returns 1 when the caller asks to cancel. */
int cm_progress_report(cm_progress *p, cm_stage s, double within);
/* The same for loops: reports at most every 0.2 s, 0 in between (1 once
 * cancelled). */
int cm_progress_poll(cm_progress *p, cm_stage s, double within);
/* The cancel check of a long loop that does not know how far it is:
 * cm_progress_poll at the stage and fraction reported last. Every loop
 * that can run longer than about 50 ms calls it; p may be NULL. */
int cm_progress_check(cm_progress *p);

/* One bar for several runs of the pipeline (auto's pairings, each run
 * reporting its own stages from the start): the first run takes the bar
 * up to CM_RELAY_FIRST, each later run half of what is then left, its
 * stages named "pairing N: stage" (or by the label given), and the end is
 * reported once, by cm_progress_relay_done. Pass cm_progress_relay_fn and
 * the relay as the runs' callback and user; the bar never goes back. */
#define CM_RELAY_FIRST 0.6
typedef struct cm_progress_relay {
    cm_progress_fn fn; /* the caller's (not NULL) */
    void *user;
    int run;           /* 0: the first */
    const char *label; /* NULL: "pairing N" */
    double from, to;   /* the bar's range for this run */
    char name[64];
} cm_progress_relay;

void cm_progress_relay_init(cm_progress_relay *relay, cm_progress_fn fn, void *user);
int cm_progress_relay_fn(void *user, double fraction, const char *stage);
/* The next run, named by label (NULL: its number, "pairing N"). */
void cm_progress_relay_next(cm_progress_relay *relay, const char *label);
/* The end of all runs ("done", the whole bar): 1 when the caller asks to
 * cancel. */
int cm_progress_relay_done(cm_progress_relay *relay);

#endif
