/* A swept volume as the writers take it: nodes, cells and the boundary's
 * faces in groups (the core's cm_sweep arrays, borrowed). */
#ifndef CM_EXPORT_VOLUME_MESH_H
#define CM_EXPORT_VOLUME_MESH_H

#include <stddef.h>
#include <stdint.h>

typedef struct volume_mesh {
    const double *nodes;      /* 3 * num_nodes: x y z */
    size_t num_nodes;
    /* Either 6-node prisms (Gmsh wedge order: bottom a b c counter-clockwise
     * seen from +z, then the top a' b' c') or 4-node tetrahedra of positive
     * volume; node indices from 0. */
    const int32_t *cells;
    size_t num_cells;
    int tetrahedra;           /* 1: cells are tetrahedra, 0: prisms */
    /* The boundary faces, sorted by group (cm_sweep_boundary_faces: 4
     * node indices per face, the 4th -1 for a triangle); num_faces 0:
     * none. */
    const int32_t *faces;
    size_t num_faces, num_groups;
    const char *const *group_names; /* num_groups (cm_sweep_boundary_group_name) */
    /* num_groups + 1 (cm_sweep_boundary_group_offsets): group g's faces are
     * [group_offsets[g], group_offsets[g + 1]) */
    const size_t *group_offsets;
    /* 2 per face (cm_sweep_boundary_cells): its cell, from 0, and the
     * cell's face as Abaqus numbers them, from 0; NULL: not known. */
    const int64_t *face_cells;
} volume_mesh;

#endif
