/* The start of a restart: the remesher's result with the triangles whose
 * maps between the geometries are most distorted split, so that a second
 * run has vertices where the connectivity's map holds the angle (each
 * triangle's affine map caps its smallest angle, whatever the positions:
 * bench/REMESH.md, "What holds the plateau"). */
#ifndef CM_REMESH_RESTART_H
#define CM_REMESH_RESTART_H

#include "base/error.h"
#include "base/mesh.h"

/* *out (empty on entry, the caller's to clear) becomes in with every
 * interior edge of the triangles among the `share` (in (0, 1]) with the
 * largest dilatation (of the affine map from geometry 0 to any other)
 * split at its midpoint in every geometry, each triangle cut by the
 * pattern of its split edges (into 2, 3 or 4). Midpoints of valid
 * triangles keep every piece valid, and the map is unchanged; boundary
 * edges stay whole. in's vertices keep their numbers; the new ones
 * follow. CM_OK or CM_ERR_NO_MEMORY. */
cm_status cm_restart_refine(const cm_mesh *in, double share, cm_mesh *out);

#endif
