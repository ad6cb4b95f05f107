/* A swept volume written through Gmsh's C API, the one writer the command
 * line, the MeshLab plugin and the Python module share. Gmsh is loaded by
 * its soname on the first write, not linked: it brings about a hundred
 * shared libraries (OpenCascade, FLTK, GL) that every other use would pay
 * for. Its state is global: each write initialises and finalises it. */
#ifndef CM_EXPORT_GMSH_VOLUME_H
#define CM_EXPORT_GMSH_VOLUME_H

#include "volume_mesh.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct gmsh_write_options {
    double msh_version;  /* 4.1 or 2.2, for .msh */
    /* Load Gmsh with its own symbols first (RTLD_DEEPBIND), for hosts that
     * define symbols Gmsh also does (MeshLab's class PluginManager); not
     * under AddressSanitizer, which refuses it. */
    int deep_bind;
    /* Called once Gmsh has started (it may install signal handlers of its
     * own; the command line puts its own back); may be NULL. */
    void (*started)(void);
    /* 1 (0 counts as 1): the cells as given; 2: second-order cells, a node
     * at the middle of every edge, straight-sided (Gmsh's setOrder: 10-node
     * tetrahedra, 15-node prisms; Abaqus C3D10, C3D15). Gmsh numbers the
     * nodes anew then; the cells keep their numbers. */
    int order;
    /* An Abaqus deck's title (*Heading), e.g. the file's final name when
     * file is a temporary one; NULL: Gmsh's, the name written to. */
    const char *title;
} gmsh_write_options;

/* Writes mesh to file, the format chosen by Gmsh from the name's extension
 * (.msh, .vtk, .inp, .bdf, .unv): the cells as one discrete volume with
 * the physical group "sweep", numbered from 1 as given. A .msh file also
 * gets the boundary: one discrete surface per group bounding the volume,
 * each with a physical group of the group's name. Gmsh 4.8 writes surface
 * groups to the other formats as shell elements, which would join the
 * analysis, so there the groups are added to Gmsh's file instead: an
 * Abaqus deck (.inp) gets them as node sets and element-face surfaces
 * (abaqus_sets.h); a Nastran file (.bdf) gets the BEGIN BULK line readers
 * look for. Returns 0, or -1 with a one-line reason in message (size
 * bytes). */
int gmsh_write_volume(const char *file, const volume_mesh *mesh, const gmsh_write_options *options, char *message,
                      size_t size);

#ifdef __cplusplus
}
#endif

#endif
