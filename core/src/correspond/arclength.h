/* The arc-length correspondence: polygons of any vertex counts made into
 * polygons of one count whose vertices correspond by index. */
#ifndef CM_CORRESPOND_ARCLENGTH_H
#define CM_CORRESPOND_ARCLENGTH_H

#include "base/error.h"

/* Boundaries in correspondence: k counter-clockwise polygons of n vertices
 * each; vertex i of polygon g is input vertex edge[g][i] of polygon g when
 * t[g][i] == 0 (its coordinates bit-identical), else the point at
 * parameter t[g][i] in (0, 1) of input edge edge[g][i] -> edge[g][i] + 1
 * (input numbering and input direction, so for clockwise input the edge
 * runs from edge + 1 back to edge in the counter-clockwise boundary). */
typedef struct cm_boundary_map {
    size_t k, n;
    double **xy;    /* k arrays of 2n */
    int32_t **edge; /* k arrays of n */
    double **t;     /* k arrays of n */
} cm_boundary_map;

void cm_boundary_map_clear(cm_boundary_map *map);

/* The shortest boundary edge of any polygon of the map as a share of that
 * polygon's size (its bounding box's diagonal); HUGE_VAL for an empty map. */
double cm_boundary_map_least_piece(const cm_boundary_map *map);

/* The input index of counter-clockwise position c of a polygon of n
 * vertices (reversed: the input is clockwise; vertex 0 stays first). */
static inline size_t cm_ccw_input(size_t c, size_t n, int reversed) { return reversed ? (n - c) % n : c; }

/* Cumulative arc lengths, n + 1 of them, along the counter-clockwise order
 * from position start (the last one the perimeter). NULL out of memory. */
double *cm_arc_lengths(const double *xy, size_t n, int reversed, size_t start);

/* The common refinement of the k validated polygons (orientation[g] +1 or
 * -1 as cm_input_check_polygons found it) under normalised arc length
 * between pins: num_pins k-tuples, pins[j * k + g] the input vertex of
 * polygon g in pin j, in the same cyclic order along every polygon; none:
 * the first vertex of every polygon. Every polygon keeps all its vertices
 * and gets the others' as points on its edges; vertices of different
 * polygons whose parameters are closer than half the gap to their
 * neighbours are one boundary vertex (no sliver edges; polygons sampled
 * alike keep a one-to-one correspondence). Pins out of range, repeated or crossing are CM_ERR_ARGUMENT
 * naming the pin and polygon. */
cm_status cm_correspond_arclength(const double *const *polygons, const size_t *counts, size_t k,
                                  const int *orientation, const size_t *pins, size_t num_pins,
                                  cm_boundary_map *out, cm_error *err);

/* The common refinement as cm_correspond_arclength's (same merge, same
 * output), with every vertex's parameter given: params[g][c] in [0, 1) for
 * counter-clockwise position c of polygon g (c = 0 its input vertex 0),
 * increasing along the polygon from wherever it is least (cyclically).
 * The boundary starts at the first vertex that is every polygon's own;
 * where the given parameters leave none, each polygon is turned to put
 * its vertex nearest to 0 there (joined at 0). Parameters that round
 * together are nudged apart by an ulp; ones that cannot be are
 * CM_ERR_ARGUMENT naming the polygon and vertex. fine: NULL (the parameter
 * linear along every edge), or per polygon NULL or counts[g] *
 * CM_PARAM_FINE parameters, fine[g][c * CM_PARAM_FINE + l] at the point
 * l / CM_PARAM_FINE along the counter-clockwise edge from position c
 * (fine[g][c * CM_PARAM_FINE] = params[g][c]): the others' points go on
 * polygon g's edges where this piecewise-linear parameter puts them. */
#define CM_PARAM_FINE 16
cm_status cm_correspond_params(const double *const *polygons, const size_t *counts, size_t k,
                               const int *orientation, const double *const *params, const double *const *fine,
                               cm_boundary_map *out, cm_error *err);

#endif
