/* The common boundary's edges split where the remesher could not reach
 * its aim with them whole, beside a far shorter edge or under their edge
 * cap (arclength and auto only: the index correspondence keeps its
 * boundary). Here rather than in correspond/: it reads the remesher's
 * edge caps. */
#ifndef CM_API_CAPSPLIT_H
#define CM_API_CAPSPLIT_H

#include "base/error.h"
#include "base/progress.h"
#include "correspond/arclength.h"

/* The ceiling to aim no higher than, in radians (negative: none can be
 * had), asked at most once, when some edge binds the target, with the
 * boundary as it is then (xy: k arrays, the loops one after another, each
 * with the material to its left, loop_start their num_loops + 1 offsets);
 * a failure in *s (CM_ERR_NO_MEMORY, CM_ERR_CANCELLED). */
typedef double (*cm_cap_ceiling)(void *ctx, const double *const *xy, const size_t *loop_start, size_t num_loops,
                                 cm_status *s);

/* One loop of the common boundary: its map (counter-clockwise, as
 * cm_correspond_arclength makes it; for a hole, the material lies to its
 * right) and the k input loops it came from (polygons, counts,
 * orientation as given to cm_correspond_arclength). */
typedef struct cm_cap_loop {
    cm_boundary_map *map;
    const double *const *polygons;
    const size_t *counts;
    const int *orientation;
} cm_cap_loop;

/* Halves, in every polygon at the same parameter, first the edges far
 * longer than the edge beside them, round after round, until the fan of
 * triangles at their shared vertex allows the aim (capsplit.c says why),
 * then the edges whose edge cap (remesh/criteria.h, with its margin, the
 * smallest over the polygons, each polygon taken whole: the outer loop,
 * loops[0], and the holes) lies below the aim (aim, radians, lowered to
 * the ceiling when some edge binds either way; ceiling may be NULL) and
 * below half the corner at either end, for a few rounds or until
 * max_added vertices were added; each loop's map gets its own points.
 * Caps never fall by a split, so an edge is split only where no triangle
 * on it could reach the aim. *tris_out (tris_out may be NULL): NULL, or,
 * for one loop, the k triangulations of the final polygons made on the
 * way (cm_polygon_triangulate's, 3 (n - 2) indices each; free with
 * cm_cap_tris_free). A boundary that is not simple (the rounding of points
 * added on edges) is left as it is, for the pipeline's check to report.
 * CM_OK, CM_ERR_NO_MEMORY or CM_ERR_CANCELLED (message on err). */
cm_status cm_boundary_maps_split_caps(cm_cap_loop *loops, size_t num_loops, double aim, cm_cap_ceiling ceiling,
                                      void *ctx, size_t max_added, cm_progress *progress, int32_t ***tris_out,
                                      cm_error *err);
void cm_cap_tris_free(int32_t **tris, size_t k);

#endif
