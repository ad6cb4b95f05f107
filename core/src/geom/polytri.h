/* Triangulation of one simple polygon. */
#ifndef CM_GEOM_POLYTRI_H
#define CM_GEOM_POLYTRI_H

#include <stdint.h>

struct cm_progress;

/* Triangulates the simple counter-clockwise polygon whose
 * vertices are xy[idx[0]], ..., xy[idx[m-1]] (xy holds 2 doubles per vertex)
 * into m - 2 triangles written to tri_out (3 * (m - 2) entries, values from
 * idx), by ear clipping followed by Delaunay edge flips (the result is the
 * constrained Delaunay triangulation of the polygon). Exact predicates.
 * Returns 0 on success, CM_NO_MEMORY, CM_CANCELLED (progress may be
 * NULL), or 1 if no ear was found (the polygon was not simple). */
int cm_polygon_triangulate(const double *xy, const int32_t *idx, long m, int32_t *tri_out,
                           struct cm_progress *progress);

/* The same by ear clipping alone, without the flips: any triangulation,
 * for uses that only walk it (visibility). 0, CM_NO_MEMORY, CM_CANCELLED
 * or 1. */
int cm_polygon_ear_clip(const double *xy, const int32_t *idx, long m, int32_t *tri_out,
                        struct cm_progress *progress);

/* Lawson flips of any triangulation to the constrained Delaunay one: the
 * edges without a neighbour and those fixed(user, a, b) calls fixed (may be
 * NULL) stay. 0, or CM_NO_MEMORY. */
int cm_tri_make_delaunay(const double *xy, int32_t *tri, long nt, int (*fixed)(const void *, int32_t, int32_t),
                         const void *user);

/* Triangle adjacency: nbr[3t + i] is the triangle across the edge opposite
 * corner i of triangle t, -1 on the boundary. 0, or CM_NO_MEMORY. */
int cm_tri_adjacency(const int32_t *tri, long nt, int32_t *nbr);

#endif
