/* A polygon with randomly placed interior vertices, triangulated (the mesh
 * of the paper's Fig. 7(e) and Table 1): for the smoothing tests and the
 * Table 1 bench. Uses the core's internal headers.
 *
 *   rm_build(poly, n, extra, seed, k, out) triangulates the simple
 *   counter-clockwise polygon poly[2n] (ear clipping + Delaunay flips),
 *   inserts `extra` interior vertices one by one at uniformly random points
 *   (each splits the triangle it falls in, checked exactly), then flips to
 *   the max-min-angle triangulation. The mesh has k identical geometries.
 *   Returns 0, -1 out of memory.
 */
#ifndef CM_TEST_RANDOM_MESH_H
#define CM_TEST_RANDOM_MESH_H

#include <stdlib.h>
#include <string.h>

#include "base/mesh.h"
#include "geom/polytri.h"
#include "remesh/kmesh.h"
#include "geom/predicates.h"
#include "random_polygons.h"
#include "remesh/flip.h"
#include "remesh/remesh.h"

static inline double rm_area2(const double *a, const double *b, const double *c)
{
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

/* A uniformly random point strictly inside triangle t, exactly checked. */
static inline int rm_point_in(const double *xy, const int32_t *t, rp_rng *rng, double p[2])
{
    for (int attempt = 0; attempt < 100; attempt++) {
        double u = rp_uniform(rng), v = rp_uniform(rng);
        if (u + v > 1) u = 1 - u, v = 1 - v;
        const double *a = xy + 2 * t[0], *b = xy + 2 * t[1], *c = xy + 2 * t[2];
        p[0] = a[0] + u * (b[0] - a[0]) + v * (c[0] - a[0]);
        p[1] = a[1] + u * (b[1] - a[1]) + v * (c[1] - a[1]);
        if (cm_orient2d(a, b, p) > 0 && cm_orient2d(b, c, p) > 0 && cm_orient2d(c, a, p) > 0) return 0;
    }
    return -1;
}

/* Picks a triangle with probability proportional to its area. */
static inline size_t rm_pick(const double *xy, const int32_t *tri, size_t nt, rp_rng *rng)
{
    double total = 0;
    for (size_t t = 0; t < nt; t++)
        total += rm_area2(xy + 2 * tri[3 * t], xy + 2 * tri[3 * t + 1], xy + 2 * tri[3 * t + 2]);
    double r = rp_uniform(rng) * total;
    for (size_t t = 0; t < nt; t++) {
        r -= rm_area2(xy + 2 * tri[3 * t], xy + 2 * tri[3 * t + 1], xy + 2 * tri[3 * t + 2]);
        if (r <= 0) return t;
    }
    return nt - 1;
}

static inline int rm_build(const double *poly, size_t n, size_t extra, uint64_t seed, size_t k,
                           cm_mesh *out)
{
    size_t nv = n + extra, nt = n - 2 + 2 * extra;
    double *xy = malloc(2 * nv * sizeof *xy);
    int32_t *tri = malloc(3 * nt * sizeof *tri), *idx = malloc(n * sizeof *idx);
    double **geoms = calloc(k, sizeof *geoms);
    rp_rng rng = {seed};
    int status = -1;
    if (!xy || !tri || !idx || !geoms) goto done;
    memcpy(xy, poly, 2 * n * sizeof *xy);
    for (size_t i = 0; i < n; i++) idx[i] = (int32_t)i;
    if (cm_polygon_triangulate(xy, idx, (long)n, tri, NULL) != 0) goto done;
    size_t count = n - 2;
    for (size_t v = n; v < nv; v++, count += 2) {
        size_t t = rm_pick(xy, tri, count, &rng);
        int32_t a = tri[3 * t], b = tri[3 * t + 1], c = tri[3 * t + 2];
        if (rm_point_in(xy, tri + 3 * t, &rng, xy + 2 * v)) goto done;
        int32_t m = (int32_t)v;
        tri[3 * t + 2] = m; /* (a b m) (b c m) (c a m) */
        int32_t *s = tri + 3 * count;
        s[0] = b, s[1] = c, s[2] = m, s[3] = c, s[4] = a, s[5] = m;
    }
    for (size_t g = 0; g < k; g++) {
        if (!(geoms[g] = malloc(2 * nv * sizeof *geoms[g]))) goto done;
        memcpy(geoms[g], xy, 2 * nv * sizeof *xy);
    }
    out->k = k, out->nv = nv, out->nt = nt, out->xy = geoms, out->tri = tri;
    geoms = NULL, tri = NULL;
    /* Delaunay (max-min angle) connectivity, as the paper's starting mesh. */
    cm_kmesh km;
    status = cm_kmesh_build(&km, out, n) == CM_OK ? 0 : -1;
    if (status == 0) {
        cm_work edges = {0};
        status = cm_flip_queue_all(&km, &edges) || cm_flip_queue(&km, &edges, NULL) < 0 ||
                 cm_kmesh_write(&km, out) != CM_OK ? -1 : 0;
        cm_work_free(&edges);
        cm_kmesh_free(&km);
    }
done:
    if (geoms)
        for (size_t g = 0; g < k; g++) free(geoms[g]);
    free(geoms), free(xy), free(tri), free(idx);
    return status;
}

#endif
