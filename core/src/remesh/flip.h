/* Compatible edge flips. Like every remeshing
 * operation, a change is made only after each affected triangle was found
 * strictly counter-clockwise in every geometry (exact orient2d). */
#ifndef CM_REMESH_FLIP_H
#define CM_REMESH_FLIP_H

#include "remesh/kmesh.h"

/* Flips the interior edge opposite corner c if the quad is strictly convex
 * in every geometry and the smallest angle of its two triangles, over all
 * geometries, improves. Returns 1 if flipped. */
int cm_flip_try(cm_kmesh *km, int32_t c);
/* Flips the interior edge opposite c whatever the angles, if the quad is
 * strictly convex in every geometry. Returns 1 if flipped. */
int cm_flip_if_valid(cm_kmesh *km, int32_t c);
/* Flips until no edge in `edges` (corners; emptied) can improve; new
 * candidates are queued as flips happen. The vertices of flipped quads go
 * to `touched` (may be NULL). Returns the number of flips, -1 out of memory. */
long cm_flip_queue(cm_kmesh *km, cm_work *edges, cm_work *touched);
/* Queues every interior edge of the mesh. 0 or -1 out of memory. */
int cm_flip_queue_all(const cm_kmesh *km, cm_work *edges);
/* Queues the edges of the triangles around v. 0 or -1. */
int cm_flip_queue_around(const cm_kmesh *km, int32_t v, cm_work *edges, cm_ibuf *star);

#endif
