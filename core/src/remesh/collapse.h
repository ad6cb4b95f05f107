/* Removal of Steiner vertices by edge collapse. Like every remeshing
 * operation, a change is made only after each affected triangle was found
 * strictly counter-clockwise in every geometry (exact orient2d). */
#ifndef CM_REMESH_COLLAPSE_H
#define CM_REMESH_COLLAPSE_H

#include "remesh/kmesh.h"

/* Removes Steiner vertices by collapsing each into a neighbour, best
 * resulting angle first, while valid in every geometry and the smallest
 * angle of the new triangles is at least min(old smallest angle around the
 * vertex, threshold) (radians; 0 accepts any valid collapse, pi only those
 * that do not make the neighbourhood worse). At most max_collapses (< 0: no
 * limit). The vertices around each collapse go to `touched` (may be NULL).
 * Returns the number of collapses, -1 out of memory. */
long cm_collapse_pass(cm_kmesh *km, double threshold, long max_collapses, cm_work *touched);
/* Collapses v = tri[c] (a Steiner vertex) onto u = tri[next(c)] if the
 * result is valid in every geometry and a disk, whatever the angles.
 * Returns 1 done, 0 not, -1 out of memory. star is scratch. */
int cm_collapse_try(cm_kmesh *km, int32_t c, cm_ibuf *star);

#endif
