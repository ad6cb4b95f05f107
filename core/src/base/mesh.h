/* The data every stage hands to the next: one triangle list over one
 * vertex numbering with k geometries. */
#ifndef CM_BASE_MESH_H
#define CM_BASE_MESH_H

#include <stddef.h>
#include <stdint.h>

typedef struct cm_mesh {
    size_t k;        /* geometries */
    size_t nv, nt;   /* vertices, triangles */
    double **xy;     /* k arrays of 2 * nv doubles */
    int32_t *tri;    /* 3 * nt indices, counter-clockwise */
} cm_mesh;

/* Frees the arrays; the mesh is empty (k kept). */
void cm_mesh_clear(cm_mesh *mesh);

#endif
