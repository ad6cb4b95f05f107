/* The sweep's volume mesh as a VTK XML unstructured grid (.vtu, ParaView's
 * own format). Written here: Gmsh 4.8 writes only the legacy .vtk, and the
 * VTK library would add a few hundred megabytes of dependencies for one
 * plain XML file. */
#ifndef CM_CLI_WRITE_VTU_H
#define CM_CLI_WRITE_VTU_H

#include "cli_common.h"
#include "write_volume.h"

/* Writes mesh to path (ASCII data arrays, coordinates with 17 significant
 * digits, wedges in VTK's corner order). Returns CLI_EXIT_OK or, with
 * error set naming `target` (the user's file name), CLI_EXIT_INTERNAL. */
int write_vtu(const char *path, const char *target, const volume_mesh *mesh, cli_error *error);

#endif
