/* Input validation: every rule of the public header's contract, checked
 * exactly, each failure with its own status and location. */
#include <math.h>
#include <stdlib.h>

#include "api/input.h"
#include "base/error.h"
#include "geom/polygon_check.h"
#include "geom/predicates.h"


/* qsort has no context argument in C11: sort (index, coords) records. */
typedef struct { double x, y; long i; } indexed_point;

static int compare_indexed(const void *pa, const void *pb)
{
    const indexed_point *a = pa, *b = pb;
    if (a->x != b->x) return a->x < b->x ? -1 : 1;
    if (a->y != b->y) return a->y < b->y ? -1 : 1;
    return a->i < b->i ? -1 : (a->i > b->i);
}

/* Finds two vertices with identical coordinates in O(n log n).
 * Returns 1 (and *first < *second), 0 if none, -1 out of memory. */
static int first_repeated_vertex(const double *xy, long n, long *first, long *second)
{
    indexed_point *p = malloc((size_t)n * sizeof *p);
    if (!p) return -1;
    for (long i = 0; i < n; i++) p[i] = (indexed_point){xy[2 * i], xy[2 * i + 1], i};
    qsort(p, (size_t)n, sizeof *p, compare_indexed);
    int found = 0;
    for (long i = 1; i < n && !found; i++) {
        if (p[i].x == p[i - 1].x && p[i].y == p[i - 1].y) {
            *first = p[i - 1].i;
            *second = p[i].i;
            found = 1;
        }
    }
    free(p);
    return found;
}

static int all_collinear(const double *xy, long n)
{
    for (long i = 2; i < n; i++)
        if (cm_orient2d(xy, xy + 2, xy + 2 * i) != 0) return 0;
    return 1;
}

static cm_status check_one_polygon(const double *xy, long n, long g, cm_error *err,
                                   int *orientation)
{
    for (long i = 0; i < n; i++) {
        if (!isfinite(xy[2 * i]) || !isfinite(xy[2 * i + 1])) {
            cm_fail_at(err, g, i, -1);
            return cm_fail(err, CM_ERR_NOT_FINITE,
                           "polygon %ld: vertex %ld has a coordinate that is not finite", g, i);
        }
    }
    long a, b;
    int rep = first_repeated_vertex(xy, n, &a, &b);
    if (rep < 0) return cm_fail_status(err, CM_ERR_NO_MEMORY);
    if (rep) {
        cm_fail_at(err, g, b, a);
        return cm_fail(err, CM_ERR_REPEATED_VERTEX,
                       "polygon %ld: vertex %ld repeats vertex %ld (%.17g, %.17g)",
                       g, b, a, xy[2 * a], xy[2 * a + 1]);
    }
    /* All vertices on one line: say so, rather than report the overlap. */
    if (all_collinear(xy, n)) {
        cm_fail_at(err, g, -1, -1);
        return cm_fail(err, CM_ERR_ZERO_AREA, "polygon %ld has zero area (all vertices on one line)", g);
    }
    int hit = cm_polygon_find_intersection(xy, n, &a, &b);
    if (hit < 0) return cm_fail_status(err, CM_ERR_NO_MEMORY);
    if (hit) {
        cm_fail_at(err, g, a, b);
        return cm_fail(err, CM_ERR_SELF_INTERSECTION,
                       "polygon %ld: edges %ld-%ld and %ld-%ld cross or touch (not a simple polygon)",
                       g, a, (a + 1) % n, b, (b + 1) % n);
    }
    /* A simple polygon has non-zero area; kept as a guard. */
    *orientation = cm_polygon_orientation(xy, n);
    if (*orientation == 0) {
        cm_fail_at(err, g, -1, -1);
        return cm_fail(err, CM_ERR_ZERO_AREA, "polygon %ld has zero area", g);
    }
    return CM_OK;
}

cm_status cm_input_check_polygons(const double *const *polygons, const size_t *counts, size_t k,
                                  int same_count, int *orientation, cm_error *err)
{
    if (!polygons || !counts) return cm_fail(err, CM_ERR_ARGUMENT, "no polygons given");
    if (k < 2) return cm_fail(err, CM_ERR_ARGUMENT, "need at least 2 polygons, got %zu", k);
    for (size_t g = 0; g < k; g++) {
        if (counts[g] < 3) {
            cm_fail_at(err, (long)g, -1, -1);
            return cm_fail(err, CM_ERR_TOO_FEW_VERTICES,
                           "polygon %zu has %zu vertices, needs at least 3", g, counts[g]);
        }
        if (same_count && counts[g] != counts[0]) {
            cm_fail_at(err, (long)g, -1, -1);
            return cm_fail(err, CM_ERR_COUNT_MISMATCH,
                           "polygon %zu has %zu vertices but polygon 0 has %zu", g,
                           counts[g], counts[0]);
        }
        if (!polygons[g]) return cm_fail(err, CM_ERR_ARGUMENT, "polygon %zu is NULL", g);
        if (counts[g] > (size_t)INT32_MAX / 8)
            return cm_fail(err, CM_ERR_ARGUMENT, "polygon %zu is too large", g);
    }
    for (size_t g = 0; g < k; g++) {
        cm_status s = check_one_polygon(polygons[g], (long)counts[g], (long)g, err, &orientation[g]);
        if (s != CM_OK) return s;
    }
    return CM_OK;
}

cm_status cm_input_validate(const double *const *polygons, const size_t *counts,
                            size_t k, cm_error *err, int *clockwise)
{
    int *orientation = k ? malloc(k * sizeof *orientation) : NULL;
    if (k && !orientation) return cm_fail_status(err, CM_ERR_NO_MEMORY);
    cm_status s = cm_input_check_polygons(polygons, counts, k, 1, orientation, err);
    for (size_t g = 1; s == CM_OK && g < k; g++) {
        if (orientation[g] != orientation[0]) {
            cm_fail_at(err, (long)g, -1, -1);
            s = cm_fail(err, CM_ERR_ORIENTATION_MISMATCH,
                        "polygon %zu is %s but polygon 0 is %s: the vertex correspondence "
                        "would mirror the shape",
                        g, orientation[g] > 0 ? "counter-clockwise" : "clockwise",
                        orientation[0] > 0 ? "counter-clockwise" : "clockwise");
        }
    }
    if (s == CM_OK) *clockwise = orientation[0] < 0;
    free(orientation);
    return s;
}
