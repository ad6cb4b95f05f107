/* Refinement: edge splits by the score of eq. 5. Like every remeshing
 * operation, a change is made only after each affected triangle was found
 * strictly counter-clockwise in every geometry (exact orient2d). */
#ifndef CM_REMESH_REFINE_H
#define CM_REMESH_REFINE_H

#include "remesh/kmesh.h"

/* cm_refine_split: the midpoint does not fit in some geometry. */
#define CM_SPLIT_NO_FIT (-2)

/* Splits up to k_split pairwise non-adjacent edges (interior, or boundary
 * with boundary splits allowed) at their midpoints in every geometry, the candidates of the mesh with the best
 * scores (eq. 5: |e| relative to the geometry's size, the largest over
 * geometries, over the smallest angle beside e squared). The new vertices
 * go to `touched`. Returns the number of splits, -1 out of memory. */
long cm_refine_step(cm_kmesh *km, long k_split, cm_work *touched);
/* Marks the four vertices of the quad around the edge opposite c (three
 * for a boundary edge) with
 * stamp, so that splits of one round share no vertex; 0 (nothing marked)
 * if one was marked already. */
int cm_refine_take_quad(cm_kmesh *km, int32_t c, uint32_t stamp);
/* The up to max best candidate edges (corners), best first, into out
 * (room for 3 * max). Returns how many. */
long cm_refine_candidates(cm_kmesh *km, long max, int32_t *out);
/* Splits the edge opposite c at its midpoint in every geometry if the new
 * triangles are valid in all: returns the new vertex, -2 when invalid or
 * a boundary edge without boundary splits (CM_SPLIT_NO_FIT), CM_NO_MEMORY.
 * A boundary edge's point is its piece's middle on the input edge
 * (cm_kmesh_between), on the edge's line or inside. */
int32_t cm_refine_split(cm_kmesh *km, int32_t c);
#endif
