/* Boundary edges split where their edge cap binds. A triangle on a
 * boundary edge cannot have a smallest angle above the edge's cap
 * (remesh/criteria.h), and the remesher never splits a boundary edge; so
 * where the points a correspondence added leave an edge long beside a
 * close stretch of boundary, the aim is out of reach there however the
 * interior is refined. Halving such an edge at the same parameter in
 * every polygon keeps the correspondence (the segments stay on their
 * input edges, the map along them linear) and raises the cap: the
 * isosceles triangle of a given base angle on a half lies inside the one
 * on the whole edge, so caps never fall, and the half's is at least twice
 * as tall for the same obstacle. */
#include <math.h>
#include <stdlib.h>

#include "api/capsplit.h"
#include "correspond/split.h"
#include "geom/polytri.h"
#include "remesh/criteria.h"

/* Rounds of halving: an edge shrinks by at most 2^CAP_SPLIT_ROUNDS. */
#define CAP_SPLIT_ROUNDS 6

/* The smallest edge and vertex caps over the polygons of map (radians,
 * unscaled), each polygon triangulated on its own. *simple = 0 when one
 * is not simple (rounding of the points added): the pipeline's check
 * then says where. */
static cm_status caps_of(const cm_boundary_map *map, cm_progress *progress, double *bcap, double *vcap,
                         int *simple, cm_error *err)
{
    size_t n = map->n;
    int32_t *idx = malloc(n * sizeof *idx), *tri = malloc(3 * n * sizeof *tri);
    double *b = malloc(2 * n * sizeof *b), *v = b ? b + n : NULL;
    cm_status s = idx && tri && b ? CM_OK : cm_fail_status(err, CM_ERR_NO_MEMORY);
    *simple = 1;
    for (size_t i = 0; s == CM_OK && i < n; i++) idx[i] = (int32_t)i, bcap[i] = vcap[i] = INFINITY;
    for (size_t g = 0; s == CM_OK && *simple && g < map->k; g++) {
        int t = cm_polygon_triangulate(map->xy[g], idx, (long)n, tri, progress);
        cm_mesh one = {1, n, n - 2, &map->xy[g], tri, NULL, 0};
        if (t == 0) t = cm_boundary_caps(&one, n, progress, b, v);
        if (t == CM_CANCELLED) s = cm_fail_status(err, CM_ERR_CANCELLED);
        else if (t == CM_NO_MEMORY) s = cm_fail_status(err, CM_ERR_NO_MEMORY);
        else if (t != 0) *simple = 0;
        for (size_t i = 0; s == CM_OK && *simple && i < n; i++)
            bcap[i] = fmin(bcap[i], b[i]), vcap[i] = fmin(vcap[i], v[i]);
    }
    free(idx), free(tri), free(b);
    return s;
}

cm_status cm_boundary_map_split_caps(cm_boundary_map *map, const double *const *polygons, const size_t *counts,
                                     const int *orientation, double aim, size_t max_added, cm_progress *progress,
                                     size_t *added, cm_error *err)
{
    size_t start = map->n;
    cm_status s = CM_OK;
    *added = 0;
    for (int round = 0; s == CM_OK && round < CAP_SPLIT_ROUNDS; round++) {
        size_t n = map->n, more = 0;
        double *bcap = malloc(2 * n * sizeof *bcap), *vcap = bcap ? bcap + n : NULL;
        size_t *pieces = malloc(n * sizeof *pieces);
        int simple = 0;
        s = bcap && pieces ? caps_of(map, progress, bcap, vcap, &simple, err) : cm_fail_status(err, CM_ERR_NO_MEMORY);
        for (size_t j = 0; s == CM_OK && simple && j < n; j++) {
            /* Where half a corner at an end is lower, the corner binds first. */
            double at_most = fmin(aim, fmin(vcap[j], vcap[(j + 1) % n]));
            pieces[j] = CM_EDGE_CAP_MARGIN * bcap[j] < at_most && map->n + more < start + max_added ? 2 : 1;
            more += pieces[j] - 1;
        }
        if (s == CM_OK && more) s = cm_boundary_map_split_edges(map, polygons, counts, orientation, pieces, err);
        free(bcap), free(pieces);
        if (more == 0) break;
    }
    if (s == CM_OK) *added = map->n - start;
    return s;
}
