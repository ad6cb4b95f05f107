/* Writing the sweep's volume mesh as a finite-element file, the format
 * chosen by the file name's extension: through Gmsh (export/gmsh_volume.h),
 * .vtu by write_vtu.c. */
#ifndef CM_CLI_WRITE_VOLUME_H
#define CM_CLI_WRITE_VOLUME_H

#include <stddef.h>
#include <stdint.h>

#include "cli_common.h"
#include "volume_mesh.h"

/* The extensions Gmsh writes for us, lower case, without the dot. */
#define VOLUME_EXTENSIONS "msh, vtk, vtu, inp (Abaqus), bdf (Nastran), unv"

/* The extension of path's file name, without the dot; NULL without one. */
const char *volume_extension(const char *path);

/* Returns 0 if path ends in one of VOLUME_EXTENSIONS (any case), else -1. */
int volume_extension_known(const char *path);

/* 1 if this build can write volume files (it was built with Gmsh). */
int volume_writer_available(void);


typedef struct volume_format {
    double msh_version; /* 4.1 or 2.2, for .msh only */
    int order;          /* 1, or 2: second-order cells (the caller refuses .vtu) */
} volume_format;

/* Writes mesh to path, first to a temporary file beside it, renamed into
 * place once complete. Returns CLI_EXIT_OK, or with error set
 * CLI_EXIT_INTERNAL, or
 * CLI_EXIT_INTERRUPTED when interrupted meanwhile (then nothing is left). */
int write_volume(const char *path, const volume_mesh *mesh, const volume_format *format, cli_error *error);

#endif
