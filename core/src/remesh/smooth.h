/* Smoothing of Steiner vertices, one geometry at a time. Like every remeshing
 * operation, a change is made only after each affected triangle was found
 * strictly counter-clockwise in every geometry (exact orient2d). */
#ifndef CM_REMESH_SMOOTH_H
#define CM_REMESH_SMOOTH_H

#include "remesh/kmesh.h"

/* Moves Steiner vertex v in geometry g to the position `method` proposes
 * (CM_SMOOTH_COMBINED: weighted angle-based, then Laplacian). Always only
 * if every triangle around v stays valid; if smart, only if the smallest
 * angle around v also improves. Returns 1 moved, 0 not, -1 out of memory.
 * star is scratch. */
int cm_smooth_vertex(cm_kmesh *km, size_t g, int32_t v, cm_smoothing method, int smart,
                     cm_ibuf *star);
/* The position `method` proposes for Steiner vertex v in geometry g, from
 * its star (corners from cm_kmesh_star). Returns 0, or -1 when undefined. */
int cm_smooth_target(const cm_kmesh *km, size_t g, int32_t v, cm_smoothing method,
                     const cm_ibuf *star, double out[2]);
/* Moves Steiner vertex v in geometry g to where the smallest angle of its
 * triangles is largest, by a short pattern search, if that gains. The
 * fallback when the smoothing formulas are stuck near a bad triangle.
 * Returns 1 moved, 0 not, -1 out of memory. */
int cm_smooth_optimize(cm_kmesh *km, size_t g, int32_t v, cm_ibuf *star);
/* Interior live v in geometry g, its star given (corners from
 * cm_kmesh_star): the smart move by
 * method where its smoothing flag says something changed (the flag then
 * cleared if it stayed), then, if it stayed and `search`, the position
 * search, both from one reading of the star. Returns 1 moved, 0 not. */
int cm_smooth_then_search(cm_kmesh *km, size_t g, int32_t v, cm_smoothing method, const cm_ibuf *star, int search);
/* The smallest sin^2 of the angles of interior v's triangles in geometry
 * g with v at q, as the position search scans them: from the triangle of
 * star corner `start`, stopping at the first at or below `floor`. Above
 * floor it is the smallest cm_triangle_min_angle_sin2(q, ...) to the bit;
 * else some value at or below floor. NaN for a degree the smoothing
 * leaves alone. For tests of the scan's shortcuts. */
double cm_smooth_star_sin2(const cm_kmesh *km, size_t g, int32_t v, const cm_ibuf *star, const double q[2],
                           double floor, long start);
/* One sweep over all Steiner vertices in every geometry. Returns the number
 * of moves, -1 out of memory. */
long cm_smooth_pass(cm_kmesh *km, cm_smoothing method, int smart);
/* One sweep of plain moves to the angle-based target with weights
 * 1 / alpha_i^power, alpha_i the link polygon's angle at neighbour i
 * (power 0: eq. 1, 2: eq. 2), for bench/table1.c's study of the weights.
 * Returns the number of moves, -1 out of memory. */
long cm_smooth_pass_power(cm_kmesh *km, double power);

#endif
