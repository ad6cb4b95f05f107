/* The guaranteed construction for polygons with holes. */
#ifndef CM_CONSTRUCT_HOLES_OVERLAY_H
#define CM_CONSTRUCT_HOLES_OVERLAY_H

#include "base/error.h"
#include "base/mesh.h"

/* A compatible triangulation of k polygons with holes, for any valid input
 * (loops as for cm_holes_cut: loop l is vertices loop_start[l] ..
 * loop_start[l + 1] - 1 of every geometry, the outer loop counter-clockwise,
 * the holes clockwise, simple, disjoint, the holes inside and not nested):
 * one bridge per hole, routed in each geometry through its own
 * triangulation, cuts the polygon open into one disc, the same in every
 * geometry, and the overlay construction triangulates that compatibly.
 * Writes *out (the N loop vertices first, then the Steiner vertices: the
 * bends first) and the number of bridges (one per hole) to *bridges.
 * Returns CM_OK, CM_ERR_NO_MEMORY, or CM_ERR_PRECISION when rounding
 * leaves no position for a bend or an overlay vertex (message on err). */
cm_status cm_holes_overlay(const double *const *geoms, size_t k, const size_t *loop_start, size_t num_loops,
                           cm_mesh *out, size_t *bridges, cm_error *err);

#endif
