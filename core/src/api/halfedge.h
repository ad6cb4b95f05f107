/* The result's half-edges, and the exact check that makes a result valid. */
#ifndef CM_API_HALFEDGE_H
#define CM_API_HALFEDGE_H

#include "api/result.h"

/* Builds the result's half-edge arrays from r->mesh and checks
 * exactly that the mesh is a valid compatible triangulation of the polygon
 * whose counter-clockwise boundary is the vertex cycle boundary[0..n-1]:
 * the boundary edges are exactly boundary[i] -> boundary[i+1], every
 * triangle is strictly counter-clockwise in every geometry, and the mesh is
 * a manifold disk.
 * With loop_start (num_loops + 1 offsets, NULL for one loop) boundary holds
 * several cycles, the outer one counter-clockwise and the holes clockwise,
 * boundary[loop_start[l] ..] each; the mesh must then be a manifold surface
 * with Euler characteristic 2 - num_loops, its boundary edges exactly
 * those cycles. (With a simple boundary this makes every geometry a
 * valid triangulation: an orientation-preserving map of a disk that is
 * injective on its boundary is injective.) Returns CM_OK, CM_ERR_NO_MEMORY
 * or CM_ERR_INTERNAL (message on r->error). */
cm_status cm_halfedge_build_and_check(cm_result *r, const int32_t *boundary,
                                      const size_t *loop_start, size_t num_loops);

#endif
