/* The conformal correspondence (CM_CORRESPOND_AUTO on polygons without
 * holes): every polygon mapped conformally onto the disk, the maps made to
 * agree up to an automorphism of the disk, and the crowding that a
 * conformal map forces on long thin parts tempered towards arc length. */
#ifndef CM_CORRESPOND_CONFORMAL_H
#define CM_CORRESPOND_CONFORMAL_H

#include "base/error.h"

/* For every polygon g and counter-clockwise position c (c = 0 the input's
 * vertex 0), params[g][c] in [0, 1): where the vertex sits on polygon 0's
 * boundary, as a share of its perimeter counter-clockwise from its vertex 0
 * (polygon 0's own vertices at their arc length). params: k arrays of
 * counts[g] doubles, filled. *found = 0 (params untouched beyond use as
 * scratch) when a polygon's mesh has a triangle of no area in doubles, and
 * the caller chooses some other way. orientation as from
 * cm_input_check_polygons.
 *
 * How: on a mesh of each polygon alone (fe.h), the harmonic measure seen
 * from its deepest node puts the boundary on the unit circle. Between
 * polygon 0 and polygon g the automorphism w -> e^(i rho) (w - a) / (1 -
 * conj(a) w) is chosen (Nelder-Mead from evenly spaced rotations) that
 * makes the correspondence sigma: s_0 -> s_g of normalised arc lengths
 * stretch least: the mean square of log(d s_g / d s_0). The conformal
 * stretch of a long thin part is exponentially small, beyond doubles and
 * beyond any mesh, so the correspondence used has stretch (d sigma / d
 * s_0)^CM_CONFORMAL_POWER (normalised, from 1e-12 up): it keeps where the
 * conformal map sends each part and tempers how much it crowds it. */
#define CM_CONFORMAL_POWER 0.25
cm_status cm_correspond_conformal(const double *const *polygons, const size_t *counts, size_t k,
                                  const int *orientation, double *const *params, int *found, cm_error *err);

#endif
