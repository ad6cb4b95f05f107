/* Writing the sweep's volume mesh as a finite-element file through Gmsh's
 * C API (.vtu by write_vtu.c), the format chosen by the file name's
 * extension. This file is the only one that touches Gmsh, whose state is
 * global: each write initialises and finalises it. */
#ifndef CM_CLI_WRITE_VOLUME_H
#define CM_CLI_WRITE_VOLUME_H

#include <stddef.h>
#include <stdint.h>

#include "cli_common.h"

/* The extensions Gmsh writes for us, lower case, without the dot. */
#define VOLUME_EXTENSIONS "msh, vtk, vtu, inp (Abaqus), bdf (Nastran), unv"

/* Returns 0 if path ends in one of VOLUME_EXTENSIONS (any case), else -1. */
int volume_extension_known(const char *path);

/* 1 if this build can write volume files (it was built with Gmsh). */
int volume_writer_available(void);

typedef struct volume_mesh {
    const double *nodes;      /* 3 * num_nodes: x y z */
    size_t num_nodes;
    /* Either 6-node prisms (Gmsh wedge order: bottom a b c counter-clockwise
     * seen from +z, then the top a' b' c') or 4-node tetrahedra of positive
     * volume; node indices from 0. */
    const int32_t *cells;
    size_t num_cells;
    int tetrahedra;           /* 1: cells are tetrahedra, 0: prisms */
    /* The boundary faces in groups (cm_sweep_boundary_faces and _groups:
     * 4 node indices per face, the 4th -1 for a triangle), written to .msh
     * files as surfaces with a physical group each; num_faces 0: none. */
    const int32_t *faces, *face_groups;
    size_t num_faces, num_groups;
} volume_mesh;

/* Writes mesh to path, first to a temporary file beside it, renamed into
 * place once complete. msh_version (4.1 or 2.2) applies to .msh only.
 * Returns CLI_EXIT_OK, or with error set CLI_EXIT_INTERNAL, or
 * CLI_EXIT_INTERRUPTED when interrupted meanwhile (then nothing is left). */
int write_volume(const char *path, const volume_mesh *mesh, double msh_version,
                 cli_error *error);

#endif
