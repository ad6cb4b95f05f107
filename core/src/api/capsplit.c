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

void cm_cap_tris_free(int32_t **tris, size_t k)
{
    for (size_t g = 0; tris && g < k; g++) free(tris[g]);
    free(tris);
}

/* The smallest edge and vertex caps over the polygons of map (radians,
 * unscaled), each polygon triangulated on its own (into tris[g], 3 (n - 2)
 * each). *simple = 0 when one is not simple (rounding of the points
 * added): the pipeline's check then says where. */
static cm_status caps_of(const cm_boundary_map *map, cm_progress *progress, double *bcap, double *vcap,
                         int32_t **tris, int *simple, cm_error *err)
{
    size_t n = map->n;
    int32_t *idx = malloc(n * sizeof *idx);
    double *b = malloc(2 * n * sizeof *b), *v = b ? b + n : NULL;
    cm_status s = idx && b ? CM_OK : cm_fail_status(err, CM_ERR_NO_MEMORY);
    *simple = 1;
    for (size_t i = 0; s == CM_OK && i < n; i++) idx[i] = (int32_t)i, bcap[i] = vcap[i] = INFINITY;
    for (size_t g = 0; s == CM_OK && *simple && g < map->k; g++) {
        int t = cm_polygon_triangulate(map->xy[g], idx, (long)n, tris[g], progress);
        cm_mesh one = {1, n, n - 2, &map->xy[g], tris[g], NULL, 0};
        if (t == 0) t = cm_boundary_caps(&one, n, progress, b, v);
        if (t == CM_CANCELLED) s = cm_fail_status(err, CM_ERR_CANCELLED);
        else if (t == CM_NO_MEMORY) s = cm_fail_status(err, CM_ERR_NO_MEMORY);
        else if (t != 0) *simple = 0;
        for (size_t i = 0; s == CM_OK && *simple && i < n; i++)
            bcap[i] = fmin(bcap[i], b[i]), vcap[i] = fmin(vcap[i], v[i]);
    }
    free(idx), free(b);
    return s;
}

/* Edge j (of n) caps every triangle on it below the aim: its cap, with the
 * remesher's margin, under the aim and under the vertex caps at its ends
 * (where half a corner is lower, the corner binds first). */
static int binds(const double *bcap, const double *vcap, size_t n, size_t j, double aim)
{
    return CM_EDGE_CAP_MARGIN * bcap[j] < fmin(aim, fmin(vcap[j], vcap[(j + 1) % n]));
}

/* k arrays of 3 (n - 2) indices, or NULL. */
static int32_t **tris_new(size_t k, size_t n)
{
    int32_t **tris = calloc(k, sizeof *tris);
    for (size_t g = 0; tris && g < k; g++)
        if (!(tris[g] = malloc(3 * n * sizeof **tris))) {
            cm_cap_tris_free(tris, k);
            return NULL;
        }
    return tris;
}

cm_status cm_boundary_map_split_caps(cm_boundary_map *map, const double *const *polygons, const size_t *counts,
                                     const int *orientation, double aim, cm_cap_ceiling ceiling, void *ctx,
                                     size_t max_added, cm_progress *progress, int32_t ***tris_out, cm_error *err)
{
    size_t start = map->n;
    cm_status s = CM_OK;
    int32_t **tris = NULL;
    *tris_out = NULL;
    for (int round = 0; s == CM_OK && round < CAP_SPLIT_ROUNDS; round++) {
        size_t n = map->n, more = 0, binding = 0;
        double *bcap = malloc(2 * n * sizeof *bcap), *vcap = bcap ? bcap + n : NULL;
        size_t *pieces = malloc(n * sizeof *pieces);
        int simple = 0;
        cm_cap_tris_free(tris, map->k);
        tris = tris_new(map->k, n);
        s = bcap && pieces && tris ? caps_of(map, progress, bcap, vcap, tris, &simple, err)
                                   : cm_fail_status(err, CM_ERR_NO_MEMORY);
        for (size_t j = 0; s == CM_OK && simple && j < n; j++) binding += binds(bcap, vcap, n, j, aim);
        if (s == CM_OK && simple && binding && round == 0 && ceiling) {
            double c = ceiling(ctx, &s);
            if (s == CM_OK && c < 0) simple = 0; /* no ceiling: leave the boundary to the pipeline's check */
            aim = fmin(aim, c);
        }
        for (size_t j = 0; s == CM_OK && simple && binding && j < n; j++) {
            pieces[j] = binds(bcap, vcap, n, j, aim) && map->n + more < start + max_added ? 2 : 1;
            more += pieces[j] - 1;
        }
        if (s == CM_OK && more) s = cm_boundary_map_split_edges(map, polygons, counts, orientation, pieces, err);
        free(bcap), free(pieces);
        if (s == CM_OK && more == 0) { /* the triangulations are the final boundary's */
            if (simple) *tris_out = tris, tris = NULL;
            break;
        }
    }
    cm_cap_tris_free(tris, map->k);
    return s;
}
