/* cm_result_from_meshes: a result from a compatible triangulation built
 * elsewhere, checked exactly with the same checks as cm_triangulate's own
 * output (cm_check_geometry per geometry, then the half-edge build). */
#include <stdlib.h>
#include <string.h>

#include "api/result.h"
#include "api/halfedge.h"
#include "api/quality.h"
#include "base/clock.h"
#include "base/gmp_memory.h"
#include "geom/predicates.h"

/* Copies the input into r->mesh, triangles counter-clockwise. */
static cm_status copy_mesh(cm_result *r, const double *const *xy, size_t k, size_t nv,
                           const int32_t *triangles, size_t nt, int clockwise)
{
    cm_mesh *m = &r->mesh;
    m->k = k, m->nv = nv, m->nt = nt;
    m->xy = calloc(k, sizeof *m->xy);
    m->tri = malloc((3 * nt + 1) * sizeof *m->tri);
    if (!m->xy || !m->tri) return cm_fail_status(&r->error, CM_ERR_NO_MEMORY);
    for (size_t g = 0; g < k; g++) {
        m->xy[g] = malloc(2 * nv * sizeof *m->xy[g]);
        if (!m->xy[g]) return cm_fail_status(&r->error, CM_ERR_NO_MEMORY);
        memcpy(m->xy[g], xy[g], 2 * nv * sizeof *m->xy[g]);
    }
    for (size_t t = 0; t < nt; t++) {
        const int32_t *v = triangles + 3 * t;
        int32_t *w = m->tri + 3 * t;
        w[0] = v[0], w[1] = clockwise ? v[2] : v[1], w[2] = clockwise ? v[1] : v[2];
    }
    return CM_OK;
}

/* cm_check_geometry's failure as a message naming geometry g's culprit. */
static cm_status geometry_failure(cm_result *r, size_t g, cm_status s, long w, long o, int clockwise)
{
    cm_fail_at(&r->error, (long)g, w, o);
    const char *orientation = clockwise ? "counter-clockwise" : "clockwise";
    switch (s) {
    case CM_ERR_NOT_FINITE:
        return cm_fail(&r->error, s, "geometry %zu: vertex %ld has a non-finite coordinate", g, w);
    case CM_ERR_ZERO_AREA: {
        const int32_t *v = r->mesh.tri + 3 * w;
        return cm_fail(&r->error, s, "geometry %zu: triangle %ld (%d %d %d) is flat or %s", g, w,
                       v[0], clockwise ? v[2] : v[1], clockwise ? v[1] : v[2], orientation);
    }
    case CM_ERR_REPEATED_VERTEX:
        return cm_fail(&r->error, s, "geometry %zu: boundary vertices %ld and %ld coincide", g, w, o);
    case CM_ERR_SELF_INTERSECTION:
        return cm_fail(&r->error, s, "geometry %zu: boundary edges %ld and %ld intersect", g, w, o);
    default:
        return cm_fail(&r->error, s, "geometry %zu: %s", g, cm_status_string(s));
    }
}

/* The direction of loop [first, first + m) that has the material on its
 * left: forward when some (counter-clockwise) triangle has the loop's
 * first edge as its own directed edge. The half-edge check then confirms
 * the whole loop. */
static int loop_runs_backward(const cm_mesh *m, size_t first)
{
    int32_t a = (int32_t)first, b = (int32_t)(first + 1);
    for (size_t t = 0; t < m->nt; t++)
        for (int i = 0; i < 3; i++)
            if (m->tri[3 * t + i] == a && m->tri[3 * t + (i + 1) % 3] == b) return 0;
    return 1;
}

static cm_status build_checked(cm_result *r, const double *const *xy, size_t k, const size_t *loop_sizes,
                       size_t num_loops, size_t nv, const int32_t *triangles, size_t nt)
{
    if (!xy || !triangles || !loop_sizes || num_loops == 0)
        return cm_fail(&r->error, CM_ERR_ARGUMENT, "NULL coordinates, triangles or loops");
    size_t n = 0;
    for (size_t l = 0; l < num_loops; l++) {
        if (num_loops > 1 && loop_sizes[l] < 3)
            return cm_fail(&r->error, CM_ERR_ARGUMENT, "loop %zu has %zu vertices; need at least 3", l, loop_sizes[l]);
        n += loop_sizes[l];
    }
    if (k < 2) return cm_fail(&r->error, CM_ERR_ARGUMENT, "need at least 2 geometries, got %zu", k);
    if (n < 3 || n > nv)
        return cm_fail(&r->error, CM_ERR_ARGUMENT, "boundary of %zu vertices with %zu vertices in all", n, nv);
    if (nt == 0) return cm_fail(&r->error, CM_ERR_ARGUMENT, "no triangles");
    for (size_t g = 0; g < k; g++)
        if (!xy[g]) return cm_fail(&r->error, CM_ERR_ARGUMENT, "geometry %zu: NULL coordinates", g);
    for (size_t i = 0; i < 3 * nt; i++)
        if (triangles[i] < 0 || (size_t)triangles[i] >= nv) {
            cm_fail_at(&r->error, -1, (long)(i / 3), -1);
            return cm_fail(&r->error, CM_ERR_ARGUMENT, "triangle %zu: vertex index %d out of range [0, %zu)",
                           i / 3, triangles[i], nv);
        }
    /* The orientation of the whole input is the first triangle's in
     * geometry 0; every other triangle and geometry must agree. */
    const int32_t *v = triangles;
    int clockwise = cm_orient2d(xy[0] + 2 * v[0], xy[0] + 2 * v[1], xy[0] + 2 * v[2]) < 0;
    cm_status s = copy_mesh(r, xy, k, nv, triangles, nt, clockwise);
    if (s != CM_OK) return s;
    r->n = n;
    r->stats.n = n, r->stats.k = k, r->stats.reversed_input = clockwise;
    for (size_t g = 0; g < k; g++) {
        long w = -1, o = -1;
        s = cm_check_geometry_loops(r->mesh.xy[g], loop_sizes, num_loops, nv, r->mesh.tri, nt, &w, &o);
        if (s == CM_ERR_NO_MEMORY) return cm_fail(&r->error, s, "out of memory");
        if (s != CM_OK) return geometry_failure(r, g, s, w, o, clockwise);
    }
    /* Boundary cycles with the material on their left: one loop is
     * counter-clockwise (reversed for clockwise input); with holes each
     * loop's direction is read off the triangles. */
    int32_t *boundary = malloc(n * sizeof *boundary);
    size_t *start = malloc((num_loops + 1) * sizeof *start);
    if (!boundary || !start) {
        free(boundary), free(start);
        return cm_fail_status(&r->error, CM_ERR_NO_MEMORY);
    }
    start[0] = 0;
    for (size_t l = 0; l < num_loops; l++) {
        size_t first = start[l], m = loop_sizes[l];
        start[l + 1] = first + m;
        int backward = num_loops == 1 ? clockwise : loop_runs_backward(&r->mesh, first);
        for (size_t j = 0; j < m; j++) boundary[first + j] = (int32_t)(first + (backward ? cm_loop_reversed(m, j) : j));
    }
    cm_fail_at(&r->error, -1, -1, -1);
    s = cm_halfedge_build_and_check(r, boundary, num_loops > 1 ? start : NULL, num_loops);
    free(boundary);
    if (s == CM_OK && num_loops > 1) {
        r->stats.holes = num_loops - 1;
        r->loop_start = start, r->num_loops = num_loops, start = NULL; /* the morph fills the holes */
    }
    free(start);
    if (s == CM_ERR_NO_MEMORY) return cm_fail(&r->error, s, "out of memory");
    if (s != CM_OK) {
        /* Built elsewhere: a topology failure is the caller's input. */
        char detail[sizeof r->error.message];
        const char *m = strncmp(r->error.message, "check: ", 7) == 0 ? r->error.message + 7 : r->error.message;
        memcpy(detail, m, strlen(m) + 1);
        return cm_fail(&r->error, CM_ERR_ARGUMENT, "not a compatible triangulation: %s", detail);
    }
    r->stats.steiner_before_remesh = nv - n;
    s = cm_result_measure(r, NULL);
    if (s != CM_OK) return s;
    r->quality_before = malloc(k * sizeof *r->quality_before);
    if (!r->quality_before) return cm_fail_status(&r->error, CM_ERR_NO_MEMORY);
    memcpy(r->quality_before, r->quality, k * sizeof *r->quality);
    return CM_OK;
}

cm_status cm_result_from_meshes(const double *const *xy, size_t k, size_t n,
                                size_t num_vertices, const int32_t *triangles,
                                size_t num_triangles, cm_result **result)
{
    return cm_result_from_meshes_loops(xy, k, &n, 1, num_vertices, triangles, num_triangles, result);
}

cm_status cm_result_from_meshes_loops(const double *const *xy, size_t k, const size_t *loop_sizes,
                                      size_t num_loops, size_t num_vertices,
                                      const int32_t *triangles, size_t num_triangles,
                                      cm_result **result)
{
    if (!result) return CM_ERR_ARGUMENT;
    cm_gmp_memory_begin();
    cm_result *r = calloc(1, sizeof *r);
    *result = r;
    if (!r) return CM_ERR_NO_MEMORY;
    cm_error_init(&r->error);
    double t0 = cm_seconds_now();
    cm_status s = build_checked(r, xy, k, loop_sizes, num_loops, num_vertices, triangles, num_triangles);
    if (s != CM_OK) cm_result_clear_geometry(r);
    else r->stats.seconds_check = cm_seconds_now() - t0;
    return cm_error_close(&r->error, s);
}
