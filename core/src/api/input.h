/* Validation of the caller's polygons, before anything is built. */
#ifndef CM_API_INPUT_H
#define CM_API_INPUT_H

#include "base/error.h"

/* Checks the k polygons (counts, finiteness, repeated vertices,
 * simplicity, orientation), with the culprit's location on err; sets
 * *clockwise when all are clockwise. */
cm_status cm_input_validate(const double *const *polygons, const size_t *counts,
                            size_t k, cm_error *err, int *clockwise);

/* The same checks of the arguments and of every polygon on its own; the
 * counts must agree only with same_count, and the orientations need not:
 * orientation[g] (k entries) receives +1 for counter-clockwise, -1 for
 * clockwise. */
cm_status cm_input_check_polygons(const double *const *polygons, const size_t *counts, size_t k,
                                  int same_count, int *orientation, cm_error *err);

/* Polygons with holes (cm_triangulate_loops): the same number of loops
 * and the same loop sizes in every polygon, each polygon's loops simple,
 * pairwise disjoint (no edge crossing or touching another), every hole
 * inside the outer loop and outside the other holes, and every loop of the
 * same orientation in every polygon. reversed[l] (num_loops entries)
 * receives 1 for a loop to be reversed so that the material lies to its
 * left (outer counter-clockwise, holes clockwise). The location on err is
 * the polygon and the vertex's index in that polygon's whole array. */
cm_status cm_input_validate_loops(const cm_loops *polygons, size_t k, cm_error *err, int *reversed);

/* The same checks of every polygon on its own, for the arc-length
 * correspondences: the same number of loops, any loop sizes, any
 * orientations; orientation[g * num_loops + l] receives +1 or -1. */
cm_status cm_input_check_loops(const cm_loops *polygons, size_t k, int *orientation, cm_error *err);

#endif
