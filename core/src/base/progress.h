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

#endif
