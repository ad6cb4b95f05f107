/* The swept volume's boundary as faces in named groups, for boundary
 * conditions: the first section (bottom), the last (top), and the wall
 * over each loop of the polygons (the side over the outer loop, one per
 * hole). */
#ifndef CM_SWEEP_BOUNDARY_H
#define CM_SWEEP_BOUNDARY_H

#include <stddef.h>
#include <stdint.h>

#include "api/result.h"
#include "base/error.h"

typedef struct cm_sweep_boundary {
    size_t nf;
    int32_t *faces;  /* 4 node indices per face, the 4th -1 for a triangle */
    int32_t *groups; /* nf: the face's group, faces sorted by group */
} cm_sweep_boundary;

/* The boundary of the sweep of r's triangles over ns sections (node
 * s * nv + v is vertex v of section s; prism p = s * nt + t over triangle
 * t). Walls are the prisms' quads, or with tets (3 per prism, as
 * cm_prism_split_tets makes them) the two triangles of each quad that the
 * tetrahedra have. Every face is ordered so that its normal (right-hand
 * rule) points out of the volume. */
cm_status cm_sweep_boundary_build(cm_sweep_boundary *b, const cm_result *r, size_t ns, const int32_t *tets,
                                  cm_error *error);
void cm_sweep_boundary_free(cm_sweep_boundary *b);

#endif
