/* Hole bridges: polygons with holes cut open into simple pieces. */
#ifndef CM_CONSTRUCT_HOLES_H
#define CM_CONSTRUCT_HOLES_H

#include "base/error.h"
#include "base/mesh.h"

/* Simple pieces of a polygon with holes, the same in every geometry. */
typedef struct cm_pieces {
    size_t count;
    size_t *start;    /* count + 1 offsets into vertex */
    int32_t *vertex;  /* each piece's vertices, counter-clockwise: loop
                         vertices (< N) and bends (N + b) */
    size_t chords;    /* paths cut, two per hole */
    size_t bends;     /* Steiner vertices on the paths */
    size_t k;
    double **bend_xy; /* k arrays of 2 * bends: bend b in geometry g */
} cm_pieces;

/* Cuts every hole open by two paths between loop vertices: straight
 * chords, or where none is valid two segments through a Steiner vertex
 * (a bend) placed in each geometry on its own.
 *   geoms:      k arrays of 2 N doubles, N = loop_start[num_loops]; loop l
 *               is vertices loop_start[l] .. loop_start[l + 1] - 1, the outer
 *               loop (l = 0) counter-clockwise, the holes clockwise, already
 *               validated (simple, disjoint, holes inside).
 * Every path joins two vertices not used by another path, lies in the
 * material in every geometry (exact tests) and touches no loop and no other
 * path; hole h's two paths go to the outer loop or to holes already
 * joined, so each cut splits one simple piece in two and the pieces
 * (num_loops of them) are simple polygons with the same vertex cycles in
 * every geometry. Returns CM_OK, CM_ERR_NO_MEMORY, or CM_ERR_INTERNAL when
 * some hole has no two such paths (message on err). */
cm_status cm_holes_cut(const double *const *geoms, size_t k, const size_t *loop_start,
                       size_t num_loops, cm_pieces *out, cm_error *err);
void cm_pieces_free(cm_pieces *p);

/* Appends a piece's compatible triangulation to whole: piece vertex i < m
 * is whole's vertex ids[i], the piece's Steiner vertices (m..) become new
 * vertices of whole. Returns CM_OK or CM_ERR_NO_MEMORY. */
cm_status cm_holes_glue(cm_mesh *whole, const int32_t *ids, size_t m, const cm_mesh *piece);

#endif
