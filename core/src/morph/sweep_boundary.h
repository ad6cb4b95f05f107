/* The swept volume's boundary as faces in named groups, for boundary
 * conditions: the first section (bottom), the last (top), and the walls
 * over the polygons' loops: one per loop ("side" over the outer loop,
 * "hole_j" over hole j), or with a corner angle one per stretch of a loop
 * between its corners ("side_1", ..., "hole_j_1", ...), as the faces of a
 * swept profile. */
#ifndef CM_SWEEP_BOUNDARY_H
#define CM_SWEEP_BOUNDARY_H

#include <stddef.h>
#include <stdint.h>

#include "api/result.h"
#include "base/error.h"

/* The groups, and the wall group of each boundary edge. */
typedef struct cm_sweep_walls {
    size_t groups;         /* 2 (bottom, top) + the walls */
    char (*names)[32];     /* groups names */
    /* result->n: the group of the boundary edge from vertex i to the next
     * vertex of its loop (in the result's order). */
    int32_t *edge_group;
} cm_sweep_walls;

/* The walls of r's loops: a loop is split at the boundary vertices where
 * some geometry's boundary turns by more than corner_deg degrees (0: not
 * split); its stretches numbered from the first such corner in the loop's
 * order. */
cm_status cm_sweep_walls_build(cm_sweep_walls *walls, const cm_result *r, double corner_deg, cm_error *error);
void cm_sweep_walls_free(cm_sweep_walls *walls);

typedef struct cm_sweep_boundary {
    size_t nf;
    int32_t *faces;  /* 4 node indices per face, the 4th -1 for a triangle */
    int32_t *groups; /* nf: the face's group, faces sorted by group */
    /* 2 per face: the cell it is a face of (the prism, or the tetrahedron)
     * and which face of it, numbered as Abaqus numbers them from S1, here
     * from 0 (prisms: bottom, top, then the quad over edge 0, 1, 2 of the
     * triangle; tetrahedra: 1-2-3, 1-4-2, 2-4-3, 3-4-1) */
    int64_t *cells;
    /* walls->groups + 1: group g's faces are [offsets[g], offsets[g + 1]) */
    size_t *offsets;
} cm_sweep_boundary;

/* The boundary of the sweep of r's triangles over ns sections (node
 * s * nv + v is vertex v of section s; prism p = s * nt + t over triangle
 * t). Walls are the prisms' quads, or with tets (3 per prism, as
 * cm_prism_split_tets makes them) the two triangles of each quad that the
 * tetrahedra have. Every face is ordered so that its normal (right-hand
 * rule) points out of the volume. */
cm_status cm_sweep_boundary_build(cm_sweep_boundary *b, const cm_result *r, const cm_sweep_walls *walls, size_t ns,
                                  const int32_t *tets, cm_error *error);
void cm_sweep_boundary_free(cm_sweep_boundary *b);

#endif
