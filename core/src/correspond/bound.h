/* The ceiling: certified upper bounds on the smallest angle that any
 * compatible triangulation of the given polygons can have, whatever its
 * Steiner vertices. Two caps (bound.c explains why each holds):
 * - the corner fan: at a boundary vertex the same triangles split the
 *   corner in every polygon;
 * - the correspondence bound: a compatible triangulation whose angles are
 *   all at least alpha is a K(alpha)-quasiconformal map between the
 *   polygons, so it cannot change the conformal modulus of a quadrilateral
 *   (four marked boundary vertices) by more than that factor. */
#ifndef CM_CORRESPOND_BOUND_H
#define CM_CORRESPOND_BOUND_H

#include <stdint.h>

#include "base/error.h"
#include "base/progress.h"

typedef struct cm_bound {
    double corner_fan_deg;     /* 60 when nothing binds */
    double correspondence_deg; /* 60 when nothing binds or no mesh could certify */
    double distortion;         /* certified modulus ratio K >= 1 behind it */
    long quad[4];              /* the marked boundary vertices; -1 when K == 1 */
} cm_bound;

/* The corner-fan cap, in degrees, of k counter-clockwise polygons whose n
 * vertices correspond by index: geoms[g] holds 2 n doubles. */
double cm_corner_fan_cap(const double *const *geoms, size_t k, size_t n);

/* Both caps of k counter-clockwise simple polygons whose n vertices
 * correspond by index.
 *   geoms: k arrays of 2 n doubles
 *   tris:  NULL, or k triangulations of the polygons alone (3 (n - 2)
 *          vertex indices each, as from cm_polygon_triangulate); NULL
 *          triangulates them here
 *   out:   receives the caps
 * Returns CM_OK, CM_ERR_NO_MEMORY or CM_ERR_CANCELLED (message on err), or
 * CM_ERR_INTERNAL when the sparse solver fails. */
cm_status cm_bound_compute(const double *const *geoms, const int32_t *const *tris, size_t k,
                           size_t n, cm_progress *progress, cm_bound *out, cm_error *err);

/* The caps of polygons already seen in one run: an auto run asks for the
 * same boundaries more than once (the correspondence it chose, then the
 * pipeline on it; a second pairing's run on the same input). Entries are
 * keyed by the polygons' coordinates and the triangulations the finite
 * element meshes start from, so a hit is the very value a computation
 * would give. */
typedef struct cm_bound_memo cm_bound_memo;

/* An empty memo (NULL out of memory: cm_bound_compute_memo then computes
 * every time). */
cm_bound_memo *cm_bound_memo_new(void);
void cm_bound_memo_free(cm_bound_memo *memo);

/* cm_bound_compute, recalled from memo (NULL: none) when the polygons and
 * their triangulations (tris, or those cm_polygon_triangulate makes when
 * NULL) were computed before. */
cm_status cm_bound_compute_memo(cm_bound_memo *memo, const double *const *geoms, const int32_t *const *tris,
                                size_t k, size_t n, cm_progress *progress, cm_bound *out, cm_error *err);

/* K(alpha): the largest dilatation of an affine map between two triangles
 * whose angles are all at least alpha (radians), vertex to vertex. */
double cm_bound_dilatation(double alpha);
/* The largest alpha, in degrees, with cm_bound_dilatation(alpha) >= K
 * (rounded up: never below the exact value); 60 for K <= 1. */
double cm_bound_angle(double K);

/* Certified bounds on the conformal modulus of the quadrilateral made by
 * marking boundary vertices a, b, c, d (counter-clockwise order) of one
 * counter-clockwise polygon of n vertices: the Dirichlet energy of the
 * harmonic function equal to 0 on the boundary from a to b and 1 from c
 * to d, Neumann elsewhere, satisfies *lower <= M <= *upper. tri: NULL or a
 * triangulation of the polygon. For tests and benchmarks. */
cm_status cm_bound_modulus(const double *xy, const int32_t *tri, size_t n, const long quad[4],
                           double *lower, double *upper, cm_error *err);

#endif
