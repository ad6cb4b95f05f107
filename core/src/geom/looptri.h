/* Triangulation of one polygon with holes, without Steiner vertices. */
#ifndef CM_GEOM_LOOPTRI_H
#define CM_GEOM_LOOPTRI_H

#include <stddef.h>
#include <stdint.h>

/* Triangulates the polygon whose loops are xy's vertices loop_start[l] ..
 * loop_start[l + 1] - 1 (the outer loop, l = 0, counter-clockwise, the
 * holes clockwise; simple, disjoint, the holes inside the outer loop and
 * not nested) into n + 2 h - 2 counter-clockwise triangles over its n
 * vertices (h holes), written to tri_out: the constrained Delaunay
 * triangulation. Exact predicates. Returns 0, CM_NO_MEMORY, or 1 when the
 * loops are not valid after all. */
int cm_loops_triangulate(const double *xy, const size_t *loop_start, size_t num_loops, int32_t *tri_out);

/* Makes segment a-b (vertices of the triangulation; no vertex lies on it
 * between them, and it crosses only edges of tri) an edge of the nt
 * triangles tri: the triangles it crosses go, and the polygons left and
 * right of it, simple as the crossed triangles' union is, are ear clipped
 * into the same slots. 0 (also when a-b is an edge already), CM_NO_MEMORY,
 * or 1 when a-b is not such a segment. */
int cm_tri_insert_edge(const double *xy, int32_t *tri, long nt, int32_t a, int32_t b);

#endif
