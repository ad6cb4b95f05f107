/* The error sink (error.h) and the status strings of the public API. */
#include <stdarg.h>
#include <stdio.h>

#include "base/error.h"
#include "base/gmp_memory.h"

const char *cm_status_string(cm_status status)
{
    switch (status) {
    case CM_OK: return "ok";
    case CM_ERR_ARGUMENT: return "invalid argument";
    case CM_ERR_TOO_FEW_VERTICES: return "too few vertices";
    case CM_ERR_COUNT_MISMATCH: return "vertex count mismatch";
    case CM_ERR_NOT_FINITE: return "non-finite coordinate";
    case CM_ERR_REPEATED_VERTEX: return "repeated vertex";
    case CM_ERR_SELF_INTERSECTION: return "self-intersection";
    case CM_ERR_ZERO_AREA: return "zero area";
    case CM_ERR_ORIENTATION_MISMATCH: return "orientation mismatch";
    case CM_ERR_NO_MEMORY: return "out of memory";
    case CM_ERR_CANCELLED: return "cancelled";
    case CM_ERR_INTERNAL: return "internal error";
    case CM_ERR_PRECISION: return "beyond double precision";
    }
    return "unknown status";
}

void cm_error_init(cm_error *e)
{
    e->status = CM_OK;
    e->message[0] = '\0';
    e->polygon = e->vertex = e->other = -1;
}

cm_status cm_fail(cm_error *e, cm_status status, const char *fmt, ...)
{
    if (status == CM_ERR_CANCELLED && cm_gmp_memory_exhausted()) /* progress.c stopped the run */
        return cm_fail_status(e, CM_ERR_NO_MEMORY);
    e->status = status;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(e->message, sizeof e->message, fmt, ap);
    va_end(ap);
    return status;
}

cm_status cm_fail_status(cm_error *e, cm_status status)
{
    return cm_fail(e, status, "%s", cm_status_string(status));
}

cm_status cm_error_close(cm_error *e, cm_status status)
{
    if (status == CM_ERR_CANCELLED && cm_gmp_memory_exhausted()) status = cm_fail_status(e, CM_ERR_NO_MEMORY);
    if (status == CM_OK) cm_error_init(e);
    else if (e->message[0] == '\0') cm_fail_status(e, status);
    e->status = status;
    return status;
}

void cm_fail_at(cm_error *e, long polygon, long vertex, long other)
{
    e->polygon = polygon;
    e->vertex = vertex;
    e->other = other;
}
