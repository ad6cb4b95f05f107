/* The time limit of a call (cm_options.time_limit): once the thread has
 * spent that much CPU time since the call began, the remesher's stages
 * stop at their next safe point (between refinement rounds, forced-move
 * rounds, polish iterations and moves; before a restart, a map-aware
 * rescue or another of auto's pairings), every one of which leaves a
 * valid mesh. One per thread, so that auto's pairings, each with its own
 * progress, share their call's; a call made inside another keeps the
 * earlier deadline. */
#ifndef CM_BASE_DEADLINE_H
#define CM_BASE_DEADLINE_H

typedef struct cm_deadline {
    double at;  /* the thread's CPU clock at which the call's time is up; 0: no limit */
    int passed; /* seen passed */
} cm_deadline;

/* Starts a call's limit of `seconds` (0: none); returns the deadline to
 * give back to cm_deadline_end. */
cm_deadline cm_deadline_begin(double seconds);
/* Ends the call's limit, the outer one (from cm_deadline_begin) in force
 * again: 1 if the call's limit was reached. */
int cm_deadline_end(cm_deadline outer);
/* 1 once the running call's limit has passed (it looks at the clock only
 * where a limit is set). */
int cm_deadline_passed(void);

#endif
