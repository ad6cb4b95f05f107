/* Near-optimal compatible triangulation by partition along minimum-link
 * paths (Surazhsky & Gotsman, section 2). */
#ifndef CM_PARTITION_H
#define CM_PARTITION_H

#include "base/error.h"
#include "base/mesh.h"
#include "base/progress.h"

/* Sub-polygons up to this many vertices always get the exact Steiner-free
 * dynamic program (O(m^3) at worst); larger ones get it when the number of
 * common diagonals c keeps its O(m (m + c)) cost small, otherwise they are
 * first split along the most balanced common diagonal. */
#define CM_DP_MAX_VERTICES 300

/* A common-diagonal set takes m^2 / 8 bytes and O(k m^2) time to build:
 * a sub-polygon above this many vertices gets none, so that the sets cost
 * O(n) in all. It is fanned from one Steiner vertex when star-shaped in
 * every geometry, else split into pieces that shrink geometrically: along
 * a common diagonal that leaves a fair share on either side (looked for at
 * the ends of its triangulations' most balanced diagonals and at spread
 * vertices), else along a minimum-link path between two far-apart
 * vertices (the overlay construction takes it only when neither, nor any
 * shorter cut, exists). */
#define CM_PARTITION_MAX_VERTICES 2048

typedef struct cm_partition_stats {
    size_t steiner;        /* Steiner vertices of the result */
    size_t fallback_count; /* sub-problems handed to the overlay construction */
    size_t dp_runs;        /* Steiner-free programs run */
    size_t steinerfree;    /* of those, sub-polygons triangulated without
                              Steiner vertices */
    size_t greedy_splits;  /* splits along a balanced common diagonal */
    size_t sampled_splits; /* of sub-polygons too large for a table */
    size_t link_splits;    /* splits along minimum-link paths with bends */
    size_t fans;           /* faces triangulated from one Steiner vertex */
    double seconds_visibility, seconds_dp, seconds_link, seconds_fallback;
} cm_partition_stats;

/* Where the boundary vertices lie on the inputs (cm_boundary_map's edge
 * and t): boundary vertex b of geometry g is input vertex edge[g][b] when
 * t[g][b] == 0, else a point inside input edge edge[g][b], the edge from
 * that vertex to the next of its loop; geometry g's input loops are its
 * vertices loop_start[g][l] .. loop_start[g][l + 1] - 1 (num_loops of
 * them; one for a polygon without holes). vertex: NULL when vertex i of
 * the partitioned polygon is boundary vertex i; else boundary vertex
 * vertex[i], or -1 for a point on no input edge (a bridge's bend). */
typedef struct cm_on_edges {
    const int32_t *const *edge;
    const double *const *t;
    const size_t *const *loop_start;
    size_t num_loops;
    const int32_t *vertex;
} cm_on_edges;

/* geoms: k arrays of 2n doubles, counter-clockwise simple polygons with
 * corresponding vertices; tris: a triangulation of each (3 (n - 2) vertex
 * indices). Writes a compatible triangulation into *out: the n polygon
 * vertices first, then the Steiner vertices. o (may be NULL) supplies the
 * progress callback. Returns CM_OK, CM_ERR_NO_MEMORY, CM_ERR_CANCELLED or
 * CM_ERR_INTERNAL (message on err). The result is checked by the caller. */
cm_status cm_partition(const double *const *geoms, const int32_t *const *tris, size_t k, size_t n,
                       cm_progress *progress, cm_mesh *out, cm_partition_stats *stats,
                       cm_error *err);

/* The same for boundaries with points added on the input edges (on): no
 * two boundary vertices on one input edge of some geometry are joined (the
 * segment would run along the edge, a sliver beside it at best). */
cm_status cm_partition_on_edges(const double *const *geoms, const int32_t *const *tris, size_t k, size_t n,
                                const cm_on_edges *on, cm_progress *progress, cm_mesh *out,
                                cm_partition_stats *stats, cm_error *err);

/* The same with another table limit in place of CM_PARTITION_MAX_VERTICES
 * (the tests reach the large-input steps at small sizes). */
cm_status cm_partition_limited(const double *const *geoms, const int32_t *const *tris, size_t k, size_t n,
                               long table_limit, cm_progress *progress, cm_mesh *out,
                               cm_partition_stats *stats, cm_error *err);

#endif
