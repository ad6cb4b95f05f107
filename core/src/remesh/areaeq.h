/* Area equalisation (eq. 4 of the paper). Like every remeshing
 * operation, a change is made only after each affected triangle was found
 * strictly counter-clockwise in every geometry (exact orient2d). */
#ifndef CM_REMESH_AREAEQ_H
#define CM_REMESH_AREAEQ_H

#include "remesh/kmesh.h"

/* Area equalisation (eq. 4): moves Steiner vertex v in geometry g to the
 * least-squares position that equalises the areas of its triangles, if all
 * of them stay valid. Returns 1 moved, 0 not, -1 out of memory. */
int cm_areaeq_vertex(cm_kmesh *km, size_t g, int32_t v, cm_ibuf *star);
/* One iteration over all Steiner vertices in every geometry; moved
 * vertices go to `touched` (may be NULL). Returns moves or -1. */
long cm_areaeq_pass(cm_kmesh *km, cm_work *touched);

#endif
