/* The common boundary's edges split where the remesher could not reach
 * its aim with them whole (arclength and auto only: the index
 * correspondence keeps its boundary). Here rather than in correspond/:
 * it reads the remesher's edge caps. */
#ifndef CM_API_CAPSPLIT_H
#define CM_API_CAPSPLIT_H

#include "base/error.h"
#include "base/progress.h"
#include "correspond/arclength.h"

/* The ceiling to aim no higher than, in radians (negative: none can be
 * had), asked at most once, when some edge binds the target; a failure
 * in *s (CM_ERR_NO_MEMORY, CM_ERR_CANCELLED). */
typedef double (*cm_cap_ceiling)(void *ctx, cm_status *s);

/* Halves, in every polygon at the same parameter, the edges whose edge cap
 * (remesh/criteria.h, with its margin, the smallest over the polygons)
 * lies below the aim (aim, radians, lowered to ceiling(ctx) when some edge
 * binds; ceiling may be NULL) and below half the corner at either end,
 * for a few rounds or until max_added vertices were added. Caps never
 * fall by a split, so an edge is split only where no triangle on it could
 * reach the aim. *tris_out: NULL, or the k triangulations of the final
 * polygons made on the way (cm_polygon_triangulate's, 3 (n - 2) indices
 * each; free with cm_cap_tris_free). A boundary that is not simple (the
 * rounding of points added on edges) is left as it is, for the pipeline's
 * check to report. CM_OK, CM_ERR_NO_MEMORY or CM_ERR_CANCELLED (message
 * on err). */
cm_status cm_boundary_map_split_caps(cm_boundary_map *map, const double *const *polygons, const size_t *counts,
                                     const int *orientation, double aim, cm_cap_ceiling ceiling, void *ctx,
                                     size_t max_added, cm_progress *progress, int32_t ***tris_out, cm_error *err);
void cm_cap_tris_free(int32_t **tris, size_t k);

#endif
