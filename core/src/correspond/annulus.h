/* The annulus correspondence (one of CM_CORRESPOND_AUTO's pairings for
 * polygons with one hole): every polygon mapped conformally onto a round
 * annulus, and the annuli turned onto one another. */
#ifndef CM_CORRESPOND_ANNULUS_H
#define CM_CORRESPOND_ANNULUS_H

#include "base/error.h"
#include "compatmesh/compatmesh.h"

/* k polygons of one hole each (validated; orientation[2 g + l] of loop l
 * of polygon g, +1 counter-clockwise, as cm_input_check_loops finds it).
 * For loop l (0 the outer loop, 1 the hole) of polygon g, params[2 g + l]
 * and fine[2 g + l] as cm_correspond_conformal's params[g] and fine[g] for
 * that loop alone (where the vertex sits on polygon 0's loop l, a share of
 * its perimeter counter-clockwise from its vertex 0); fine[0] and fine[1]
 * may be NULL. *found = 0 (params partly written) when a polygon's mesh
 * has a triangle of no area in doubles.
 *
 * Why: the harmonic function u of a polygon with one hole (0 on the hole,
 * 1 on the outer loop) and its conjugate psi (normalised to period 1) are
 * the log radius and the angle of its conformal map onto a round annulus.
 * psi runs along both loops at once: a point of the hole and a point of
 * the outer loop with the same psi lie on one gradient line of u. Read by
 * psi, two polygons' outer loops and holes pair together, and the map
 * between them is conformal but for the annuli's radial stretch; pairing
 * the outer loops alone (filled) knows nothing of where the hole sits.
 * Only the turn between the annuli is free: the one under which both
 * loops' arc lengths differ least (the variance over each circle, summed
 * over the loops weighted by polygon 0's perimeters). psi crowds where the
 * conformal map does (exponentially into a dead end: the mouth of an e),
 * so the loops are read by a tempered parameter (power, as conformal.h's).
 * Turns that fit alike (a round ring's every turn) have no rule between
 * them: auto runs this pairing only as a rescue, on pairs far below their
 * aim, which a round ring never is.
 *
 * How: linear finite elements on a mesh of each polygon (fe.h); psi along
 * each loop is the running sum of the boundary nodes' fluxes (K u), and
 * the offset between the loops psi's change along a path of triangles
 * from the hole to the outer loop (the conjugate of a discrete harmonic u
 * is a Crouzeix-Raviart function, continuous at the edges' midpoints; its
 * change around a boundary node, midpoint to midpoint, is the node's
 * flux). */
cm_status cm_correspond_annulus(const cm_loops *polygons, size_t k, const int *orientation, double power,
                                double *const *params, double *const *fine, int *found, cm_error *err);

#endif
