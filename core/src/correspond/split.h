/* Boundary edges split compatibly to a largest length (the element size
 * finite-element users ask for along the boundary). */
#ifndef CM_CORRESPOND_SPLIT_H
#define CM_CORRESPOND_SPLIT_H

#include "base/error.h"
#include "correspond/arclength.h"

/* Splits every edge j -> j + 1 of the common boundary into the same number
 * of equal-parameter pieces in every polygon, the fewest with no piece
 * longer than max_edge in any polygon. The points added lie on the input
 * edge the segment lies on, at the parameter map->t reports
 * (P[e] + t (P[e + 1] - P[e]), input numbering), so every polygon keeps
 * its input vertices and its shape. polygons, counts, orientation as given
 * to cm_correspond_arclength. A boundary that would pass CM_MAX_BOUNDARY
 * vertices is CM_ERR_ARGUMENT. */
cm_status cm_boundary_map_split(cm_boundary_map *map, const double *const *polygons, const size_t *counts,
                                const int *orientation, double max_edge, cm_error *err);

/* Splits edge j -> j + 1 of the common boundary into pieces[j] >= 1
 * equal-parameter pieces in every polygon, as cm_boundary_map_split does. */
cm_status cm_boundary_map_split_edges(cm_boundary_map *map, const double *const *polygons, const size_t *counts,
                                      const int *orientation, const size_t *pieces, cm_error *err);

/* A piece of the common boundary from a vertex at (edge, t) to the next
 * at (next_edge, next_t) in one polygon (count input vertices, reversed:
 * the input is clockwise): the input edge e it lies on and the
 * parameters t0, t1 of its ends there (input direction). */
void cm_boundary_piece(int32_t edge, double t, int32_t next_edge, double next_t, size_t count, int reversed,
                       int32_t *e, double *t0, double *t1);
/* The point at parameter t of input edge e -> e + 1 of a polygon of count
 * vertices: P[e] + t (P[e + 1] - P[e]), the one formula every point added
 * on an input edge comes from. */
void cm_edge_point(const double *polygon, size_t count, int32_t e, double t, double xy[2]);

/* The most boundary vertices a split may make. */
#define CM_MAX_BOUNDARY ((size_t)1 << 24)

#endif
