/* The swept volume's boundary groups as an Abaqus (and CalculiX) deck
 * takes them, appended after the deck's nodes and elements: a node set
 * (*NSET) per group, for boundary conditions, and an element-face surface
 * (*SURFACE, TYPE=ELEMENT) per group, for pressures and fluxes (*DSLOAD).
 * Nodes and elements numbered from 1 in the volume_mesh's order, as the
 * deck numbers them. */
#ifndef CM_EXPORT_ABAQUS_SETS_H
#define CM_EXPORT_ABAQUS_SETS_H

#include <stdio.h>

#include "volume_mesh.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The node sets from the groups' faces, or where nodes is not NULL from
 * nodes[g] (counts[g] node numbers from 1, sorted, unique: a
 * second-order deck's, whose mid-edge nodes the faces do not list).
 * 0, or -1 with errno set (a write failed, or out of memory: ENOMEM). */
int abaqus_write_sets(FILE *file, const volume_mesh *mesh, const size_t *const *nodes, const size_t *counts);

#ifdef __cplusplus
}
#endif

#endif
