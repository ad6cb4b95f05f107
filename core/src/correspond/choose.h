/* Choosing the correspondence (CM_CORRESPOND_AUTO): where the arc-length
 * parametrisation of every polygon starts. */
#ifndef CM_CORRESPOND_CHOOSE_H
#define CM_CORRESPOND_CHOOSE_H

#include "base/error.h"
#include "correspond/arclength.h"

/* pins (k entries, input numbering): pins[0] = 0, and for every other
 * polygon the vertex to start its arc length from so that the two
 * parametrisations agree best up to a similarity (rotation, scale,
 * translation): of M points evenly spaced by arc length on each polygon,
 * the start whose points are the least-squares similar image of polygon
 * 0's (Procrustes residual). Candidates: every vertex, or evenly spaced
 * ones on large polygons and then their neighbourhood. orientation as from
 * cm_input_check_polygons. loops: NULL, or for the outer loops of
 * polygons with holes the polygons themselves: each start's residual then
 * also counts polygon 0's hole centroids under its similarity against
 * polygon g's nearest ones, so that where a turn takes the outer loop onto
 * itself (a rectangle) the holes choose; with holes_tie, the holes only
 * choose among the starts whose outer loops fit alike. Of starts far
 * apart that fit alike (a disc, a regular polygon, a rectangle whose holes
 * a turn takes onto themselves) the one whose similarity turns least from
 * the one chosen for polygon g - 1. */
cm_status cm_correspond_choose_starts(const double *const *polygons, const size_t *counts, size_t k,
                                      const int *orientation, const cm_loops *loops, int holes_tie, size_t *pins,
                                      cm_error *err);

/* The centroids of a polygon's holes (its loops after the first), x y
 * each, into out (2 (num_loops - 1) doubles). */
void cm_correspond_hole_centres(const cm_loops *loops, double *out);

/* For polygons with holes: similarity (4 per polygon: a then b, complex,
 * re and im) such that b + a z, z on polygon 0's outer loop, is the
 * least-squares image on polygon g's outer loop over the outer loops'
 * corresponding boundary vertices (centroid to centroid). Polygon 0's is
 * the identity up to rounding. */
void cm_correspond_outer_similarity(const cm_boundary_map *outer, double *similarity);

/* pins (k entries, input numbering) for one hole of polygons with holes,
 * jointly with the outer loop: pins[0] polygon 0's first vertex; for every
 * other polygon the vertex to start the hole's arc length from whose
 * points lie nearest (sum of squared distances) to polygon 0's hole points
 * carried into it, both sampled at equal normalised arc length (as many
 * points as the larger loop has vertices, at most 1024). A point is
 * carried radially through the outer loops' map `outer` (the outer point
 * nearest in direction from the hole's vertex mean, the same share of the
 * way out from the other hole's; where that is not defined, by the outer
 * loops' similarity): the outer loops' correspondence where it is, not
 * one similarity for the whole outline. A hole chosen on its own may turn
 * against the outer loop; this way the holes keep their place in the
 * frame the outer loops set. Candidates as cm_correspond_choose_starts.
 * orientation as from cm_input_check_loops for this hole. */
cm_status cm_correspond_choose_hole_starts(const double *const *holes, const size_t *counts, size_t k,
                                           const int *orientation, const cm_boundary_map *outer,
                                           const double *similarity, size_t *pins, cm_error *err);

/* For polygons with holes (num_loops L the same in each, validated): which
 * hole of every polygon pairs with each hole of polygon 0. Polygon 0's
 * hole centroids are carried into polygon g by their mean value
 * coordinates over the outer loops' correspondence `outer`; where every
 * carried centroid and one of polygon g's hole centroids are each other's
 * nearest (a one-to-one match), polygon g's holes are taken in that order,
 * else in the input's. order (k L entries): order[g L + l] the input loop
 * of polygon g placed at loop l (0 for l = 0; polygon 0's the identity).
 * *moved: how many holes, over all polygons, the match takes from another
 * place than their input's. */
cm_status cm_correspond_match_holes(const cm_loops *polygons, size_t k, const cm_boundary_map *outer,
                                    size_t *order, size_t *moved, cm_error *err);

/* Does the outer loops' correspondence `outer` take every hole where a
 * hole is? *land = 1 when, for every polygon g, polygon 0's hole
 * centroids carried into g (as cm_correspond_match_holes carries them)
 * match g's holes one to one, each within its hole's radius (that of the
 * disc of its area) of the hole's centroid; else 0. A pairing of the outer
 * loops turned against the holes (a rectangle's two ways) takes them
 * elsewhere. */
cm_status cm_correspond_holes_land(const cm_loops *polygons, size_t k, const cm_boundary_map *outer, int *land,
                                   cm_error *err);

/* Polygons of one count that are affine images of polygon 0 up to where
 * they start: if for every polygon g some start makes its vertices, walked
 * counter-clockwise, the least-squares affine image of polygon 0's within
 * a relative RMS of 1e-9, *found = 1 and pins (counts[0] k-tuples, as
 * cm_options.pins) tie every vertex to its image; the map between them is
 * then affine and forces no distortion at all. Else *found = 0 (also for
 * more than 4096 vertices, where the check costs too much). loops: NULL,
 * or for the outer loops of polygons with holes the polygons themselves:
 * where several starts make an exact affine image (an outer loop an
 * affine map takes onto itself), the one whose map takes polygon 0's hole
 * centroids nearest to polygon g's is taken. */
cm_status cm_correspond_affine_shift(const double *const *polygons, const size_t *counts, size_t k,
                                     const int *orientation, const cm_loops *loops, size_t *pins, int *found,
                                     cm_error *err);

#endif
