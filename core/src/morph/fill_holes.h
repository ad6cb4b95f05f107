/* The holes of a result filled for the morph.
 *
 * The convex-combination morph needs a triangulated disk inside its convex
 * enclosure. A result of polygons with holes becomes one when every hole
 * gets a compatible triangulation of its own (the hole loop in every
 * geometry, vertex i on vertex i, as cm_triangulate makes it): the morph
 * moves the fill with the material, keeping both valid, and the sections
 * drop it again (they are the result's triangles only). */
#ifndef CM_MORPH_FILL_HOLES_H
#define CM_MORPH_FILL_HOLES_H

#include "api/result.h"

/* out: the result's vertices first (numbering kept), then the fills'
 * Steiner vertices; the result's triangles first, then the fills'.
 * Returns CM_OK, CM_ERR_NO_MEMORY, CM_ERR_CANCELLED or the status of a
 * hole that could not be triangulated (message on err naming it). */
cm_status cm_fill_holes(const cm_result *r, cm_mesh *out, cm_error *err);

#endif
