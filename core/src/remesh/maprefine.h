/* Refinement in the middle metric (map-aware remeshing, remesh.c): per
 * triangle, the geometric mean of the metrics its k geometries induce on
 * its barycentric frame, so a triangle that is good there is off by at
 * most the square root of the map's distortion in each geometry. Like
 * every remeshing operation, a change is made only after each affected
 * triangle was found strictly counter-clockwise in every geometry (exact
 * orient2d). */
#ifndef CM_REMESH_MAPREFINE_H
#define CM_REMESH_MAPREFINE_H

#include "remesh/kmesh.h"
#include "remesh/mapopt.h"

/* Smallest angle (radians) of triangle (a, b, c) in the middle metric;
 * 0 when flat in some geometry. */
double cm_mid_angle(const cm_kmesh *km, int32_t a, int32_t b, int32_t c);
/* The middle metric's circumcentre of triangle t in barycentric
 * coordinates (summing to 1; negative outside). 0, or -1 when flat. */
int cm_mid_circumcentre(const cm_kmesh *km, int32_t t, double bary[3]);

/* Inserts a vertex at t's middle circumcentre, at the same barycentric
 * coordinates in every geometry, if it lies inside t (every coordinate
 * at least a small margin) and the three new triangles are valid in all.
 * Returns the vertex, -2 when not, -1 out of memory. */
int32_t cm_mid_insert(cm_kmesh *km, int32_t t);
/* Inserts a vertex inside triangle t at the barycentric coordinates bary
 * in every geometry if the three new triangles are valid in all. Returns
 * the vertex, -2 when not, -1 out of memory. */
int32_t cm_insert_bary(cm_kmesh *km, int32_t t, const double bary[3]);

/* Flips edges from `edges` (corners; emptied) while the smaller middle
 * angle of the two triangles rises and the quad is strictly convex in
 * every geometry (toward the middle metric's Delaunay triangulation).
 * Returns the flips, -1 out of memory. */
long cm_mid_flip_queue(cm_kmesh *km, cm_work *edges);

/* Inserts Steiner vertices while some triangle's middle angle is below
 * share times its target (tkey - slack) and the Steiner vertices (live_v
 * - n) are fewer than `budget`: at the worst triangle's middle
 * circumcentre, at the same barycentric coordinates in every geometry
 * (the maps between the geometries keep), or, when that falls outside,
 * at the midpoint of the interior edge it lies beyond; the new vertex then
 * takes a few Newton steps on the energy w (the midpoint of a poor
 * triangle's long side can be next to its apex) and middle flips follow.
 * Each insertion is a transaction, undone when the smallest angle (all
 * geometries) of the triangles it changed dropped; so is the first round
 * of middle flips over the whole mesh. Triangles thinner than a degree
 * in some geometry are left to Algorithm 1. Not inside a transaction.
 * Returns the insertions, -1 out of memory. */
long cm_mid_refine(cm_kmesh *km, double share, long budget, cm_mapopt_weights w);

#endif
