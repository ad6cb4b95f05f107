/* A closed polyline from a PLY edge mesh (ASCII or binary), as MeshLab and
 * vcglib write it: element vertex (x, y, optional z) and element edge
 * (vertex1, vertex2), the edges forming one closed loop. */
#ifndef CM_CLI_READ_PLY_H
#define CM_CLI_READ_PLY_H

#include <stddef.h>

#include "read_polygon.h"

/* data[0..length) is the whole file. Fills polygon (count, xy,
 * source_line: the vertex's line in ASCII files; in binary ones its index,
 * with polygon->by_index set). Returns CLI_EXIT_OK, or CLI_EXIT_USAGE with
 * "PATH:LINE: ..." ("PATH: vertex N: ..." / "PATH: edge N: ..." in binary
 * files), or CLI_EXIT_INTERNAL when out of memory. */
int parse_ply(const char *path, const char *data, size_t length, polygon_input *polygon, cli_error *error);

#endif
