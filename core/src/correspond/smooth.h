/* Smoothing the stretch of a common boundary: the points that are not a
 * polygon's own input vertices slide along their input edges. */
#ifndef CM_CORRESPOND_SMOOTH_H
#define CM_CORRESPOND_SMOOTH_H

#include "base/error.h"
#include "correspond/arclength.h"

/* The stretch of edge j -> j + 1 of the common boundary in polygon g >= 1
 * is its length there over its length in polygon 0. Moves every vertex
 * that is not polygon g's own input vertex (t != 0) along its input edge,
 * keeping the boundary's order and every input vertex where it is, to
 * lower the sum over polygons g >= 1 and common vertices j of
 * (ln stretch_j - ln stretch_{j-1})^2: a jump of the stretch at a vertex is
 * graded over the pieces beside it. sweeps Gauss-Seidel sweeps, each vertex
 * placed at its best given its neighbours. Moved points keep the contract
 * of cm_boundary_map (xy from edge and t by cm_edge_point). polygons,
 * counts, orientation as given to cm_correspond_arclength. */
cm_status cm_boundary_map_smooth(cm_boundary_map *map, const double *const *polygons, const size_t *counts,
                                 const int *orientation, int sweeps, cm_error *err);

#endif
