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

static cm_status build_checked(cm_result *r, const double *const *xy, size_t k, size_t n, size_t nv,
                       const int32_t *triangles, size_t nt)
{
    if (!xy || !triangles) return cm_fail(&r->error, CM_ERR_ARGUMENT, "NULL coordinates or triangles");
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
        s = cm_check_geometry(r->mesh.xy[g], n, nv, r->mesh.tri, nt, &w, &o);
        if (s == CM_ERR_NO_MEMORY) return cm_fail(&r->error, s, "out of memory");
        if (s != CM_OK) return geometry_failure(r, g, s, w, o, clockwise);
    }
    /* Counter-clockwise boundary cycle: reversed for clockwise input. */
    int32_t *boundary = malloc(n * sizeof *boundary);
    if (!boundary) return cm_fail_status(&r->error, CM_ERR_NO_MEMORY);
    for (size_t j = 0; j < n; j++) boundary[j] = (int32_t)(clockwise && j > 0 ? n - j : j);
    cm_fail_at(&r->error, -1, -1, -1);
    s = cm_halfedge_build_and_check(r, boundary, NULL, 1);
    free(boundary);
    if (s == CM_ERR_NO_MEMORY) return cm_fail(&r->error, s, "out of memory");
    if (s != CM_OK) {
        /* Built elsewhere: a topology failure is the caller's input. */
        char detail[sizeof r->error.message];
        const char *m = strncmp(r->error.message, "check: ", 7) == 0 ? r->error.message + 7 : r->error.message;
        memcpy(detail, m, strlen(m) + 1);
        return cm_fail(&r->error, CM_ERR_ARGUMENT, "not a compatible triangulation: %s", detail);
    }
    r->stats.steiner_before_remesh = nv - n;
    s = cm_result_measure(r);
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
    if (!result) return CM_ERR_ARGUMENT;
    cm_gmp_memory_begin();
    cm_result *r = calloc(1, sizeof *r);
    *result = r;
    if (!r) return CM_ERR_NO_MEMORY;
    cm_error_init(&r->error);
    double t0 = cm_seconds_now();
    cm_status s = build_checked(r, xy, k, n, num_vertices, triangles, num_triangles);
    if (s != CM_OK) cm_result_clear_geometry(r);
    else r->stats.seconds_check = cm_seconds_now() - t0;
    return cm_error_close(&r->error, s);
}
