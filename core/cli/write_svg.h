/* preview.svg: the k meshes side by side, worst triangles highlighted. */
#ifndef CM_CLI_WRITE_SVG_H
#define CM_CLI_WRITE_SVG_H

#include <compatmesh/compatmesh.h>

#include "cli_common.h"

/* Writes one panel per geometry of the successful result, each scaled to the
 * same height with y pointing up: interior edges thin, the input boundary
 * thick, Steiner vertices as dots, triangles whose smallest angle is below
 * 20 degrees filled orange and each panel's worst triangle red, and a caption
 * "NAME: n=.., Steiner .., min angle .. deg" from names[g].
 * Returns CLI_EXIT_OK or, with error set, CLI_EXIT_INTERNAL. */
int write_svg(const char *path, const cm_result *result,
              const char *const *names, cli_error *error);

#endif
