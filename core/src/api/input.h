/* Validation of the caller's polygons, before anything is built. */
#ifndef CM_API_INPUT_H
#define CM_API_INPUT_H

#include "base/error.h"

/* Checks the k polygons (counts, finiteness, repeated vertices,
 * simplicity, orientation), with the culprit's location on err; sets
 * *clockwise when all are clockwise. */
cm_status cm_input_validate(const double *const *polygons, const size_t *counts,
                            size_t k, cm_error *err, int *clockwise);

#endif
