#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "correspond/split.h"

void cm_boundary_piece(int32_t edge, double t, int32_t next_edge, double next_t, size_t count, int reversed,
                       int32_t *e, double *t0, double *t1)
{
    if (reversed) {
        /* Counter-clockwise runs against the input: from input vertex v the
         * piece runs down edge v - 1 (from its end, t = 1). */
        *e = t == 0 ? (int32_t)(((size_t)edge + count - 1) % count) : edge;
        *t0 = t == 0 ? 1.0 : t;
        *t1 = next_t; /* the next vertex is on edge *e, or its start */
    } else {
        *e = edge, *t0 = t;
        *t1 = next_edge == edge ? next_t : 1.0;
    }
}

void cm_edge_point(const double *polygon, size_t count, int32_t e, double t, double xy[2])
{
    const double *a = polygon + 2 * e, *b = polygon + 2 * (((size_t)e + 1) % count);
    xy[0] = a[0] + t * (b[0] - a[0]);
    xy[1] = a[1] + t * (b[1] - a[1]);
}

/* Polygon g's segment from common vertex j to j + 1. */
static void segment(const cm_boundary_map *map, size_t g, size_t j, size_t count, int reversed, int32_t *e,
                    double *t0, double *t1)
{
    size_t next = (j + 1) % map->n;
    cm_boundary_piece(map->edge[g][j], map->t[g][j], map->edge[g][next], map->t[g][next], count, reversed, e, t0,
                      t1);
}

cm_status cm_boundary_map_split_edges(cm_boundary_map *map, const double *const *polygons, const size_t *counts,
                                      const int *orientation, const size_t *pieces, cm_error *err)
{
    const size_t k = map->k, n = map->n;
    size_t total = 0;
    for (size_t j = 0; j < n; j++) total += pieces[j];
    if (total == n) return CM_OK;
    cm_boundary_map out = {k, total, calloc(k, sizeof(double *)), calloc(k, sizeof(int32_t *)),
                           calloc(k, sizeof(double *))};
    cm_status s = out.xy && out.edge && out.t ? CM_OK : cm_fail_status(err, CM_ERR_NO_MEMORY);
    for (size_t g = 0; s == CM_OK && g < k; g++) {
        out.xy[g] = malloc(2 * total * sizeof **out.xy);
        out.edge[g] = malloc(total * sizeof **out.edge);
        out.t[g] = malloc(total * sizeof **out.t);
        if (!out.xy[g] || !out.edge[g] || !out.t[g]) {
            s = cm_fail_status(err, CM_ERR_NO_MEMORY);
            break;
        }
        const double *P = polygons[g];
        size_t at = 0, m = counts[g];
        for (size_t j = 0; j < n; j++) {
            out.xy[g][2 * at] = map->xy[g][2 * j], out.xy[g][2 * at + 1] = map->xy[g][2 * j + 1];
            out.edge[g][at] = map->edge[g][j], out.t[g][at] = map->t[g][j];
            at++;
            int32_t e;
            double t0, t1;
            segment(map, g, j, m, orientation[g] < 0, &e, &t0, &t1);
            for (size_t i = 1; i < pieces[j]; i++) {
                double t = t0 + (t1 - t0) * ((double)i / (double)pieces[j]);
                cm_edge_point(P, m, e, t, out.xy[g] + 2 * at);
                out.edge[g][at] = e, out.t[g][at] = t;
                at++;
            }
        }
    }
    if (s != CM_OK) {
        cm_boundary_map_clear(&out);
        return s;
    }
    cm_boundary_map_clear(map);
    *map = out;
    return CM_OK;
}

cm_status cm_boundary_map_split(cm_boundary_map *map, const double *const *polygons, const size_t *counts,
                                const int *orientation, double max_edge, cm_error *err)
{
    const size_t k = map->k, n = map->n;
    size_t *pieces = malloc(n * sizeof *pieces), total = 0;
    if (!pieces) return cm_fail_status(err, CM_ERR_NO_MEMORY);
    for (size_t j = 0; j < n; j++) {
        double longest = 0;
        for (size_t g = 0; g < k; g++) {
            const double *a = map->xy[g] + 2 * j, *b = map->xy[g] + 2 * ((j + 1) % n);
            longest = fmax(longest, hypot(b[0] - a[0], b[1] - a[1]));
        }
        double p = ceil(longest / max_edge);
        if (!(p < (double)CM_MAX_BOUNDARY) || total + (size_t)p > CM_MAX_BOUNDARY) {
            free(pieces);
            return cm_fail(err, CM_ERR_ARGUMENT,
                           "max_edge %g would put more than %zu vertices on the boundary", max_edge,
                           (size_t)CM_MAX_BOUNDARY);
        }
        pieces[j] = p < 1 ? 1 : (size_t)p;
        total += pieces[j];
    }
    cm_status s = cm_boundary_map_split_edges(map, polygons, counts, orientation, pieces, err);
    free(pieces);
    return s;
}
