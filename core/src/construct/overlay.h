/* The guaranteed construction (Aronov, Seidel and Souvaine). */
#ifndef CM_CONSTRUCT_OVERLAY_H
#define CM_CONSTRUCT_OVERLAY_H

#include "base/error.h"
#include "base/mesh.h"

/* The Aronov-Seidel-Souvaine construction.
 *   geoms: k arrays of 2n doubles, counter-clockwise simple polygons;
 *   tris:  k triangulations, 3 * (n - 2) indices each (vertex indices < n).
 * Writes a compatible triangulation into *out (polygon vertices first).
 * *extra_centroids counts faces that needed a centroid vertex.
 * Returns CM_OK, CM_ERR_NO_MEMORY or CM_ERR_INTERNAL (message on err). */
cm_status cm_overlay(const double *const *geoms, const int32_t *const *tris,
                     size_t k, size_t n, cm_mesh *out, size_t *extra_centroids,
                     cm_error *err);

#endif
