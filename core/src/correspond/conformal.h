/* The conformal correspondence (CM_CORRESPOND_AUTO on polygons without
 * holes): every polygon mapped conformally onto the disk, the maps made to
 * agree up to an automorphism of the disk, and the crowding that a
 * conformal map forces on long thin parts tempered towards arc length. */
#ifndef CM_CORRESPOND_CONFORMAL_H
#define CM_CORRESPOND_CONFORMAL_H

#include "base/error.h"
#include "correspond/arclength.h"

/* For every polygon g and counter-clockwise position c (c = 0 the input's
 * vertex 0), params[g][c] in [0, 1): where the vertex sits on polygon 0's
 * boundary, as a share of its perimeter counter-clockwise from its vertex 0
 * (polygon 0's own vertices at their arc length). params: k arrays of
 * counts[g] doubles, filled. *found = 0 (params left partly written) when
 * a polygon's mesh has a triangle of no area in doubles, and the caller
 * chooses some other way. orientation as from cm_input_check_polygons.
 *
 * How: on a mesh of each polygon alone (fe.h), the harmonic measure seen
 * from its deepest node puts the boundary on the unit circle (the boundary
 * values of a conformal map onto the disk). Each disk is turned by the
 * automorphism that puts the barycentre of arc length at the centre
 * (Douady-Earle), which spreads every polygon's crowding evenly around the
 * circle and leaves two similar polygons' disks one rotation apart; the
 * rotation between polygon 0's disk and polygon g's is the one under
 * which the two arc lengths at each point of the circle differ least
 * (variance over the circle). A conformal map crowds a long thin part by
 * a factor exponential in its length over its width, beyond doubles and
 * beyond any mesh, so the polygons are matched not by angle but by a
 * tempered parameter: the running integral of (d angle / d arc
 * length)^power, normalised, which keeps the order and place of the parts
 * the conformal map sees and takes the power of its crowding (0: arc
 * length from where the map puts vertex 0; 1: the conformal map itself); a
 * similar copy gets the same parameter. The power (CM_CONFORMAL_POWER, and
 * auto's rescues' others) and the rest were chosen by measurement
 * (bench/CORRESPONDENCE.md). Where turns far apart fit alike (a disc, a
 * regular polygon), the holes choose among them (hole_centres: NULL, or k
 * arrays of `holes` centres, x y each: the turns that put polygon 0's
 * nearest to polygon g's under the similarity closest to the pairing),
 * then the turn of the plane nearest polygon g - 1's (none for polygon 1):
 * two sections of a pipe pair without a twist, sections of a part that
 * twists as it goes each a little further round. */
#define CM_CONFORMAL_POWER 0.25
/* fine: NULL, or k arrays of counts[g] * CM_PARAM_FINE doubles (fine[0]
 * may be NULL: polygon 0's parameter is its arc length): fine[g][c *
 * CM_PARAM_FINE + l], the same parameter at the point l / CM_PARAM_FINE of
 * the way along the counter-clockwise edge from position c (l = 0: the
 * vertex, params[g][c]). The tempered conformal parameter is not linear
 * along an edge: a long edge beside a corner the map crowds gathers its
 * points towards that corner, where linear interpolation between the
 * vertices would put a jump of the stretch at the corner. */
cm_status cm_correspond_conformal(const double *const *polygons, const size_t *counts, size_t k,
                                  const int *orientation, const double *const *hole_centres, size_t holes,
                                  double power, double *const *params, double *const *fine, int *found,
                                  cm_error *err);

/* The last few conformal correspondences made in one run, recalled when
 * the same polygons ask again at the same power (auto's rescues read the
 * same parameter linearly between the vertices, and come back to it after
 * other powers). */
typedef struct cm_conformal_memo cm_conformal_memo;
/* An empty memo (NULL out of memory: nothing is then recalled). */
cm_conformal_memo *cm_conformal_memo_new(void);
void cm_conformal_memo_free(cm_conformal_memo *memo);

/* cm_correspond_conformal, recalled from memo (NULL: none) when the
 * polygons (coordinates, counts, orientation), the hole centres and the
 * power are those of one of its last calls with fine given. */
cm_status cm_correspond_conformal_memo(cm_conformal_memo *memo, const double *const *polygons, const size_t *counts,
                                       size_t k, const int *orientation, const double *const *hole_centres,
                                       size_t holes, double power, double *const *params, double *const *fine,
                                       int *found, cm_error *err);

#endif
