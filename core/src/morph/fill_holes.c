/* Filling a result's holes (fill_holes.h). */
#include <stdlib.h>
#include <string.h>

#include "morph/fill_holes.h"

/* One hole's fill, appended to out (vertices from out->nv on, triangles
 * from out->nt on; out's arrays hold the room). */
static void append_fill(const cm_result *hole, size_t first, size_t m, cm_mesh *out)
{
    size_t nv = cm_result_num_vertices(hole), nt = cm_result_num_triangles(hole);
    for (size_t g = 0; g < out->k; g++)
        memcpy(out->xy[g] + 2 * out->nv, cm_result_vertices(hole, g) + 2 * m, 2 * (nv - m) * sizeof(double));
    const int32_t *tri = cm_result_triangles(hole);
    for (size_t j = 0; j < 3 * nt; j++) {
        size_t v = (size_t)tri[j];
        out->tri[3 * out->nt + j] = (int32_t)(v < m ? first + v : out->nv + v - m);
    }
    out->nv += nv - m, out->nt += nt;
}

cm_status cm_fill_holes(const cm_result *r, cm_mesh *out, cm_error *err)
{
    size_t k = r->mesh.k, holes = r->num_loops ? r->num_loops - 1 : 0;
    cm_result **fill = calloc(holes + 1, sizeof *fill);
    const double **xy = calloc(k, sizeof *xy);
    size_t *counts = calloc(k, sizeof *counts);
    cm_status s = fill && xy && counts ? CM_OK : cm_fail_status(err, CM_ERR_NO_MEMORY);
    size_t nv = r->mesh.nv, nt = r->mesh.nt;
    for (size_t h = 0; s == CM_OK && h < holes; h++) {
        size_t first = r->loop_start[h + 1], m = r->loop_start[h + 2] - first;
        for (size_t g = 0; g < k; g++) xy[g] = r->mesh.xy[g] + 2 * first, counts[g] = m;
        cm_options o;
        cm_options_init(&o);
        o.ceiling = 0; /* the fill's angles only condition the morph's weights */
        s = cm_triangulate_polygons(xy, counts, k, &o, &fill[h]);
        if (s == CM_ERR_NO_MEMORY || s == CM_ERR_CANCELLED) cm_fail_status(err, s);
        else if (s != CM_OK)
            cm_fail(err, s, "morph: hole %zu could not be filled: %s", h + 1,
                    fill[h] ? cm_result_message(fill[h]) : "out of memory");
        else nv += cm_result_num_vertices(fill[h]) - m, nt += cm_result_num_triangles(fill[h]);
    }
    *out = (cm_mesh){0};
    if (s == CM_OK) {
        out->k = k;
        out->xy = calloc(k, sizeof *out->xy);
        out->tri = malloc(3 * nt * sizeof *out->tri);
        if (!out->xy || !out->tri) s = cm_fail_status(err, CM_ERR_NO_MEMORY);
        for (size_t g = 0; s == CM_OK && g < k; g++) {
            if (!(out->xy[g] = malloc(2 * nv * sizeof(double)))) s = cm_fail_status(err, CM_ERR_NO_MEMORY);
            else memcpy(out->xy[g], r->mesh.xy[g], 2 * r->mesh.nv * sizeof(double));
        }
    }
    if (s == CM_OK) {
        memcpy(out->tri, r->mesh.tri, 3 * r->mesh.nt * sizeof *out->tri);
        out->nv = r->mesh.nv, out->nt = r->mesh.nt;
        for (size_t h = 0; h < holes; h++)
            append_fill(fill[h], r->loop_start[h + 1], r->loop_start[h + 2] - r->loop_start[h + 1], out);
    }
    if (s != CM_OK) cm_mesh_clear(out);
    for (size_t h = 0; fill && h < holes; h++) cm_result_free(fill[h]);
    free(fill), free(xy), free(counts);
    return s;
}
