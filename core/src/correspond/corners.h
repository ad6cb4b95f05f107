/* Pins at corners: every vertex whose boundary turns by more than a given
 * angle (its corner angle deviates from 180 degrees by more than that) is
 * pinned to a corner of every other polygon, in order. */
#ifndef CM_CORRESPOND_CORNERS_H
#define CM_CORRESPOND_CORNERS_H

#include "base/error.h"

/* The corner pins of k validated polygons (orientation as from
 * cm_input_check_polygons). starts[g]: the input vertex of polygon g from
 * which its arc length is measured (vertex 0 for the arc-length
 * correspondence, the chosen start for auto). With m the smallest corner
 * count, every polygon keeps its m most prominent corners (largest turn;
 * the lower counter-clockwise position first on ties), and the corners of
 * polygon g are matched to polygon 0's in counter-clockwise order with the
 * cyclic shift that brings them closest in normalised arc length from the
 * starts (least sum of squared distances around the loop; the smallest
 * shift on ties). *pins (malloc'ed, m k-tuples as in cm_options.pins) and
 * *num_pins = m. A polygon with no corner is CM_ERR_ARGUMENT naming it. */
cm_status cm_correspond_corner_pins(const double *const *polygons, const size_t *counts, size_t k,
                                    const int *orientation, const size_t *starts, double degrees,
                                    size_t **pins, size_t *num_pins, cm_error *err);

#endif
