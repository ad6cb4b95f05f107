/* Choosing the correspondence (CM_CORRESPOND_AUTO): where the arc-length
 * parametrisation of every polygon starts. */
#ifndef CM_CORRESPOND_CHOOSE_H
#define CM_CORRESPOND_CHOOSE_H

#include "base/error.h"

/* pins (k entries, input numbering): pins[0] = 0, and for every other
 * polygon the vertex to start its arc length from so that the two
 * parametrisations agree best up to a similarity (rotation, scale,
 * translation): of M points evenly spaced by arc length on each polygon,
 * the start whose points are the least-squares similar image of polygon
 * 0's (Procrustes residual). Candidates: every vertex, or evenly spaced
 * ones on large polygons and then their neighbourhood. orientation as from
 * cm_input_check_polygons. */
cm_status cm_correspond_choose_starts(const double *const *polygons, const size_t *counts, size_t k,
                                      const int *orientation, size_t *pins, cm_error *err);

/* Polygons of one count that are affine images of polygon 0 up to where
 * they start: if for every polygon g some start makes its vertices, walked
 * counter-clockwise, the least-squares affine image of polygon 0's within
 * a relative RMS of 1e-9, *found = 1 and pins (counts[0] k-tuples, as
 * cm_options.pins) tie every vertex to its image; the map between them is
 * then affine and forces no distortion at all. Else *found = 0 (also for
 * more than 4096 vertices, where the check costs too much). */
cm_status cm_correspond_affine_shift(const double *const *polygons, const size_t *counts, size_t k,
                                     const int *orientation, size_t *pins, int *found, cm_error *err);

#endif
