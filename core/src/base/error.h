/* The core's one error convention.
 *
 * A public call returns a cm_status; the handle it fills (result, morph,
 * sweep) owns a cm_error that says what went wrong and, for bad input,
 * where. The stages below the API report into the cm_error they are given,
 * never into a handle of their own.
 *
 * Internal functions that return a count, an index or a flag use negative
 * values for failures, and only these: CM_NO_MEMORY and CM_CANCELLED
 * everywhere, and where
 * a function can also give up for another reason, a named value of its own
 * (e.g. CM_SPLIT_NO_FIT in remesh/refine.h). Longer chains (a stage that
 * can be cancelled) return cm_status. */
#ifndef CM_BASE_ERROR_H
#define CM_BASE_ERROR_H

#include "compatmesh/compatmesh.h"

#define CM_NO_MEMORY (-1)
/* The caller cancelled through the progress callback. */
#define CM_CANCELLED (-3)

typedef struct cm_error {
    cm_status status;
    char message[512];
    long polygon, vertex, other; /* where bad input is; -1 where unknown */
} cm_error;

/* A fresh sink: CM_OK, no message, no location. */
void cm_error_init(cm_error *e);
/* Sets status and a printf-style message; returns status. */
cm_status cm_fail(cm_error *e, cm_status status, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
/* cm_fail with the standard message of CM_ERR_NO_MEMORY or
 * CM_ERR_CANCELLED (any other status: its cm_status_string). */
cm_status cm_fail_status(cm_error *e, cm_status status);
/* The status a public call returns, recorded on its handle: CM_OK clears
 * the sink; a failure that has no message yet gets the standard one. */
cm_status cm_error_close(cm_error *e, cm_status status);
/* Where bad input is: polygon, vertex and the other vertex involved. */
void cm_fail_at(cm_error *e, long polygon, long vertex, long other);

#endif
