/* The loft: a sweep whose geometries lie in planes of space that need not
 * be parallel (cm_sweep_options.frames). The sweep is built in (x, y, z)
 * with z the parameter along the loft, then every node is placed between
 * the planes of the two geometries around it, and every cell is checked
 * in space, exactly: straight blends between turned planes fold where the
 * planes come too close or cross inside the polygons. */
#ifndef CM_LOFT_H
#define CM_LOFT_H

#include <stddef.h>
#include <stdint.h>

#include "base/error.h"

/* The floats per geometry in cm_sweep_options.frames: origin, u, v. */
#define CM_LOFT_FRAME 9

/* Checks the k frames (finite, u and v of length 1 within 1e-6 and
 * perpendicular within 1e-6) and writes the loft's levels: 0, then the
 * distances between consecutive sections' centres (centres: 2 per
 * geometry, in its plane coordinates), cumulated. CM_OK, or
 * CM_ERR_ARGUMENT with a message on err (a bad frame, two centres at the
 * same point). */
cm_status cm_loft_levels(const double *frames, const double *centres, size_t k, double *levels, cm_error *err);

/* Places count nodes (x, y, z) with z in [levels[0], levels[k - 1]]: z in
 * segment g at fraction s is placed at (1 - s) F_g(x, y) + s F_g+1(x, y),
 * F_g(x, y) = origin_g + x u_g + y v_g (as cm_loft_section places a morph
 * section, compatmesh.h). */
void cm_loft_place(const double *frames, const double *levels, size_t k, double *nodes, size_t count);

/* The first cell (tetrahedra with tets, else 6-node prisms) not positive
 * in space, exactly, or -1: a tetrahedron's orientation, a prism's at
 * each of its six corners (its corner tetrahedron: the corner and its
 * three neighbours), as finite-element codes check a wedge's Jacobian. */
long cm_loft_first_inverted(const double *nodes, const int32_t *cells, size_t count, int tets);

/* The volume of the prisms as 6-node wedges, the integral of their
 * Jacobian (what a finite-element code integrates); between parallel
 * planes the integral of the section areas, as the sweep's own. */
double cm_loft_volume(const double *nodes, const int32_t *prisms, size_t count);

#endif
