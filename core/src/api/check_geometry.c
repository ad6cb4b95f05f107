/* Exact re-check of a triangulation whose coordinates changed after
 * cm_triangulate: rounded to float by a mesh format, or moved by a morph.
 * With one connectivity, a simple boundary and every triangle strictly
 * counter-clockwise, the triangles tile the polygon without overlap, so
 * these two tests are all validity needs; with holes, loops that are
 * each simple and meet no other loop (a hole cannot then leave the outer
 * loop: the triangles' winding there would be negative). */
#include "compatmesh/compatmesh.h"
#include "base/gmp_memory.h"
#include "geom/polygon_check.h"
#include "geom/predicates.h"

#include <math.h>
#include <stdlib.h>

static int compare_points(const void *a, const void *b)
{
    const double *p = *(const double *const *)a, *q = *(const double *const *)b;
    if (p[0] != q[0]) return p[0] < q[0] ? -1 : 1;
    if (p[1] != q[1]) return p[1] < q[1] ? -1 : 1;
    return 0;
}

cm_status cm_check_geometry(const double *xy, size_t n, size_t num_vertices,
                            const int32_t *triangles, size_t num_triangles,
                            long *where, long *other)
{
    return cm_check_geometry_loops(xy, &n, 1, num_vertices, triangles, num_triangles, where, other);
}

cm_status cm_check_geometry_loops(const double *xy, const size_t *loop_sizes, size_t num_loops,
                                  size_t num_vertices, const int32_t *triangles, size_t num_triangles,
                                  long *where, long *other)
{
    long w = -1, o = -1;
    cm_status status = CM_OK;
    size_t n = 0;
    cm_gmp_memory_begin();
    for (size_t l = 0; loop_sizes && l < num_loops; l++) {
        if (loop_sizes[l] < 3) n = num_vertices + 1; /* refused below */
        n += loop_sizes[l];
    }
    if (!xy || !triangles || !loop_sizes || num_loops == 0 || n < 3 || n > num_vertices) {
        status = CM_ERR_ARGUMENT;
        goto done;
    }
    for (size_t i = 0; i < 2 * num_vertices; i++)
        if (!isfinite(xy[i])) {
            status = CM_ERR_NOT_FINITE, w = (long)(i / 2);
            goto done;
        }
    for (size_t t = 0; t < num_triangles; t++) {
        const int32_t *v = triangles + 3 * t;
        if (v[0] < 0 || v[1] < 0 || v[2] < 0 || (size_t)v[0] >= num_vertices ||
            (size_t)v[1] >= num_vertices || (size_t)v[2] >= num_vertices) {
            status = CM_ERR_ARGUMENT, w = (long)t;
            goto done;
        }
        if (cm_orient2d(xy + 2 * v[0], xy + 2 * v[1], xy + 2 * v[2]) <= 0) {
            status = CM_ERR_ZERO_AREA, w = (long)t;
            goto done;
        }
    }
    /* Repeated boundary vertices first: the simplicity scan assumes none. */
    const double **sorted = malloc(n * sizeof *sorted);
    if (!sorted) {
        status = CM_ERR_NO_MEMORY;
        goto done;
    }
    for (size_t i = 0; i < n; i++) sorted[i] = xy + 2 * i;
    qsort(sorted, n, sizeof *sorted, compare_points);
    for (size_t i = 1; i < n; i++)
        if (compare_points(&sorted[i - 1], &sorted[i]) == 0) {
            long a = (long)((sorted[i - 1] - xy) / 2), b = (long)((sorted[i] - xy) / 2);
            status = CM_ERR_REPEATED_VERTEX, w = a < b ? a : b, o = a < b ? b : a;
            break;
        }
    free(sorted);
    if (status != CM_OK) goto done;
    int found = num_loops == 1 ? cm_polygon_find_intersection(xy, (long)n, &w, &o)
                               : cm_loops_find_intersection(xy, loop_sizes, num_loops, &w, &o);
    if (found < 0) status = CM_ERR_NO_MEMORY, w = o = -1;
    else if (found > 0) status = CM_ERR_SELF_INTERSECTION;
    else w = o = -1;
done:
    if (where) *where = w;
    if (other) *other = o;
    return status;
}

cm_status cm_check_tetrahedra(const double *nodes, size_t num_nodes, const int32_t *tets, size_t num_tets,
                              long *where)
{
    long w = -1;
    cm_status status = CM_OK;
    cm_gmp_memory_begin();
    if (!nodes || (!tets && num_tets)) {
        status = CM_ERR_ARGUMENT;
        goto done;
    }
    for (size_t i = 0; i < 3 * num_nodes && status == CM_OK; i++)
        if (!isfinite(nodes[i])) status = CM_ERR_NOT_FINITE, w = (long)(i / 3);
    for (size_t t = 0; t < num_tets && status == CM_OK; t++) {
        const int32_t *v = tets + 4 * t;
        for (int c = 0; c < 4; c++)
            if (v[c] < 0 || (size_t)v[c] >= num_nodes) status = CM_ERR_ARGUMENT, w = (long)t;
        if (status == CM_OK && cm_orient3d(nodes + 3 * v[0], nodes + 3 * v[1], nodes + 3 * v[2], nodes + 3 * v[3]) <= 0)
            status = CM_ERR_ZERO_AREA, w = (long)t;
    }
done:
    if (cm_gmp_memory_exhausted() && status == CM_OK) status = CM_ERR_NO_MEMORY;
    if (where) *where = w;
    return status;
}
