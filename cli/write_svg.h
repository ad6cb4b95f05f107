/* preview.svg: the k meshes side by side, worst triangles highlighted (also
 * the strip of a morph's frames). */
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

/* k geometries of one triangle list, e.g. the sections of a morph. */
typedef struct svg_meshes {
    const int32_t *triangles; /* 3 * count, counter-clockwise */
    size_t count;
    size_t n;                 /* boundary vertices 0 .. n-1; the rest: Steiner */
    size_t vertices;
    const double *const *xy;  /* k arrays of 2 * vertices doubles */
    const char *const *names; /* k captions */
    size_t k;
} svg_meshes;

/* The same drawing for any such set of geometries. */
int write_svg_meshes(const char *path, const svg_meshes *meshes, cli_error *error);

#endif
