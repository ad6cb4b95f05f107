/* Input validation: every rule of the public header's contract, checked
 * exactly, each failure with its own status and location. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "api/input.h"
#include "base/error.h"
#include "base/mesh.h"
#include "geom/polygon_check.h"
#include "geom/predicates.h"


/* The vertices as events sorted by cm_vertex_events_sort, or NULL out of
 * memory. */
static cm_vertex_event *sorted_vertices(const double *xy, long n)
{
    cm_vertex_event *p = malloc((size_t)n * sizeof *p);
    if (!p) return NULL;
    for (long i = 0; i < n; i++) p[i] = (cm_vertex_event){xy[2 * i], xy[2 * i + 1], i};
    if (cm_vertex_events_sort(p, n) == 0) return p;
    free(p);
    return NULL;
}

/* Two vertices with identical coordinates, adjacent in the sorted events.
 * Returns 1 (and *first < *second) or 0 if none. */
static int repeated_in(const cm_vertex_event *p, long n, long *first, long *second)
{
    for (long i = 1; i < n; i++) {
        if (p[i].x == p[i - 1].x && p[i].y == p[i - 1].y) {
            *first = p[i - 1].vertex;
            *second = p[i].vertex;
            return 1;
        }
    }
    return 0;
}

/* Finds two vertices with identical coordinates in O(n log n).
 * Returns 1 (and *first < *second), 0 if none, -1 out of memory. */
static int first_repeated_vertex(const double *xy, long n, long *first, long *second)
{
    cm_vertex_event *p = sorted_vertices(xy, n);
    if (!p) return -1;
    int found = repeated_in(p, n, first, second);
    free(p);
    return found;
}

/* What a repeat of vertex a by vertex b (a < b) of one loop of n
 * vertices adds to its message: the closing repeat of a ring, as GIS
 * formats write polygons, is named as such. */
static const char *ring_hint(long a, long b, long n)
{
    return a == 0 && b == n - 1 ? " (a closed ring: give each vertex once, without the closing repeat)" : "";
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
    /* sorted once: for repeated vertices, then for the scan line */
    cm_vertex_event *sorted = sorted_vertices(xy, n);
    if (!sorted) return cm_fail_status(err, CM_ERR_NO_MEMORY);
    if (repeated_in(sorted, n, &a, &b)) {
        free(sorted);
        cm_fail_at(err, g, b, a);
        return cm_fail(err, CM_ERR_REPEATED_VERTEX,
                       "polygon %ld: vertex %ld repeats vertex %ld (%.17g, %.17g)%s",
                       g, b, a, xy[2 * a], xy[2 * a + 1], ring_hint(a, b, n));
    }
    /* All vertices on one line: say so, rather than report the overlap. */
    if (all_collinear(xy, n)) {
        free(sorted);
        cm_fail_at(err, g, -1, -1);
        return cm_fail(err, CM_ERR_ZERO_AREA, "polygon %ld has zero area (all vertices on one line)", g);
    }
    int hit = cm_polygon_find_intersection_sorted(xy, n, sorted, &a, &b);
    free(sorted);
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

/* ---- polygons with holes ----------------------------------------------- */

/* "the outer loop" or "hole 2 (loop 2)": how messages name loop l. */
static const char *loop_name(char *buf, size_t size, size_t l)
{
    if (l == 0) snprintf(buf, size, "the outer loop (loop 0)");
    else snprintf(buf, size, "hole %zu (loop %zu)", l, l);
    return buf;
}

/* Winding number of the closed loop xy[0..m-1] around p (Sunday's rule with
 * exact orientation); p must not lie on the loop. */
static int winding_number(const double p[2], const double *xy, long m)
{
    int w = 0;
    for (long i = 0; i < m; i++) {
        const double *a = xy + 2 * i, *b = xy + 2 * ((i + 1) % m);
        if (a[1] <= p[1]) {
            if (b[1] > p[1] && cm_orient2d(a, b, p) > 0) w++;
        } else if (b[1] <= p[1] && cm_orient2d(a, b, p) < 0) {
            w--;
        }
    }
    return w;
}

/* The loop and the index within it of vertex v of a polygon. */
static size_t loop_of(const size_t *start, size_t num_loops, long v, long *within)
{
    size_t l = cm_loop_of(start, num_loops, (size_t)v);
    *within = v - (long)start[l];
    return l;
}

static cm_status check_loops_arguments(const cm_loops *polygons, size_t k, int same_sizes, cm_error *err)
{
    if (!polygons) return cm_fail(err, CM_ERR_ARGUMENT, "no polygons given");
    if (k < 2) return cm_fail(err, CM_ERR_ARGUMENT, "need at least 2 polygons, got %zu", k);
    char name[64];
    for (size_t g = 0; g < k; g++) {
        const cm_loops *p = &polygons[g];
        if (!p->xy || !p->loop_sizes || p->num_loops == 0)
            return cm_fail(err, CM_ERR_ARGUMENT, "polygon %zu has no loops (NULL xy or loop_sizes, or num_loops 0)", g);
        if (p->num_loops != polygons[0].num_loops) {
            cm_fail_at(err, (long)g, -1, -1);
            return cm_fail(err, CM_ERR_COUNT_MISMATCH, "polygon %zu has %zu hole%s but polygon 0 has %zu", g,
                           p->num_loops - 1, p->num_loops == 2 ? "" : "s", polygons[0].num_loops - 1);
        }
        size_t total = 0;
        for (size_t l = 0; l < p->num_loops; l++) {
            size_t m = p->loop_sizes[l];
            if (m < 3) {
                cm_fail_at(err, (long)g, -1, -1);
                return cm_fail(err, CM_ERR_TOO_FEW_VERTICES, "polygon %zu: %s has %zu vertices, needs at least 3",
                               g, loop_name(name, sizeof name, l), m);
            }
            if (same_sizes && m != polygons[0].loop_sizes[l]) {
                cm_fail_at(err, (long)g, -1, -1);
                return cm_fail(err, CM_ERR_COUNT_MISMATCH, "polygon %zu: %s has %zu vertices but in polygon 0 it has %zu",
                               g, loop_name(name, sizeof name, l), m, polygons[0].loop_sizes[l]);
            }
            if (m > (size_t)INT32_MAX / 8 || total > (size_t)INT32_MAX / 8 - m)
                return cm_fail(err, CM_ERR_ARGUMENT, "polygon %zu is too large", g);
            total += m;
        }
    }
    return CM_OK;
}

/* One polygon with holes on its own: finite, no repeated vertex, no loop on
 * one line, no edges crossing or touching (within a loop or between loops),
 * every hole inside the outer loop and outside every other hole.
 * orientation[l] receives +1 / -1 per loop. */
static cm_status check_one_loops(const double *xy, const size_t *start, size_t num_loops, long g,
                                 cm_error *err, int *orientation)
{
    long n = (long)start[num_loops], a, b, wa, wb;
    char name[64], other[64];
    for (long i = 0; i < n; i++)
        if (!isfinite(xy[2 * i]) || !isfinite(xy[2 * i + 1])) {
            size_t l = loop_of(start, num_loops, i, &wa);
            cm_fail_at(err, g, i, -1);
            return cm_fail(err, CM_ERR_NOT_FINITE, "polygon %ld: %s: vertex %ld has a coordinate that is not finite",
                           g, loop_name(name, sizeof name, l), wa);
        }
    int rep = first_repeated_vertex(xy, n, &a, &b);
    if (rep < 0) return cm_fail_status(err, CM_ERR_NO_MEMORY);
    if (rep) {
        size_t la = loop_of(start, num_loops, a, &wa), lb = loop_of(start, num_loops, b, &wb);
        cm_fail_at(err, g, b, a);
        long size = (long)(start[lb + 1] - start[lb]);
        return cm_fail(err, CM_ERR_REPEATED_VERTEX, "polygon %ld: %s: vertex %ld repeats vertex %ld of %s (%.17g, %.17g)%s",
                       g, loop_name(name, sizeof name, lb), wb, wa, loop_name(other, sizeof other, la),
                       xy[2 * a], xy[2 * a + 1], la == lb ? ring_hint(wa, wb, size) : "");
    }
    for (size_t l = 0; l < num_loops; l++)
        if (all_collinear(xy + 2 * start[l], (long)(start[l + 1] - start[l]))) {
            cm_fail_at(err, g, (long)start[l], -1);
            return cm_fail(err, CM_ERR_ZERO_AREA, "polygon %ld: %s has zero area (all vertices on one line)",
                           g, loop_name(name, sizeof name, l));
        }
    size_t *sizes = malloc(num_loops * sizeof *sizes);
    if (!sizes) return cm_fail_status(err, CM_ERR_NO_MEMORY);
    for (size_t l = 0; l < num_loops; l++) sizes[l] = start[l + 1] - start[l];
    int hit = cm_loops_find_intersection(xy, sizes, num_loops, &a, &b);
    free(sizes);
    if (hit < 0) return cm_fail_status(err, CM_ERR_NO_MEMORY);
    if (hit) {
        size_t la = loop_of(start, num_loops, a, &wa), lb = loop_of(start, num_loops, b, &wb);
        long ma = (long)(start[la + 1] - start[la]), mb = (long)(start[lb + 1] - start[lb]);
        cm_fail_at(err, g, a, b);
        if (la == lb)
            return cm_fail(err, CM_ERR_SELF_INTERSECTION,
                           "polygon %ld: %s: edges %ld-%ld and %ld-%ld cross or touch (not a simple loop)",
                           g, loop_name(name, sizeof name, la), wa, (wa + 1) % ma, wb, (wb + 1) % mb);
        return cm_fail(err, CM_ERR_SELF_INTERSECTION,
                       "polygon %ld: edge %ld-%ld of %s and edge %ld-%ld of %s cross or touch",
                       g, wa, (wa + 1) % ma, loop_name(name, sizeof name, la), wb, (wb + 1) % mb,
                       loop_name(other, sizeof other, lb));
    }
    for (size_t l = 0; l < num_loops; l++)
        orientation[l] = cm_polygon_orientation(xy + 2 * start[l], (long)(start[l + 1] - start[l]));
    /* No loop touches another, so one vertex tells on which side of a loop
     * a whole other loop lies. */
    for (size_t h = 1; h < num_loops; h++) {
        const double *p = xy + 2 * start[h];
        if (winding_number(p, xy, (long)start[1]) == 0) {
            cm_fail_at(err, g, (long)start[h], -1);
            return cm_fail(err, CM_ERR_SELF_INTERSECTION, "polygon %ld: %s lies outside the outer loop (vertex 0 at (%.17g, %.17g))",
                           g, loop_name(name, sizeof name, h), p[0], p[1]);
        }
        for (size_t o = 1; o < num_loops; o++)
            if (o != h && winding_number(p, xy + 2 * start[o], (long)(start[o + 1] - start[o])) != 0) {
                cm_fail_at(err, g, (long)start[h], (long)start[o]);
                return cm_fail(err, CM_ERR_SELF_INTERSECTION, "polygon %ld: %s lies inside %s (holes must not nest)",
                               g, loop_name(name, sizeof name, h), loop_name(other, sizeof other, o));
            }
    }
    return CM_OK;
}

cm_status cm_input_check_loops(const cm_loops *polygons, size_t k, int *orientation, cm_error *err)
{
    cm_status s = check_loops_arguments(polygons, k, 0, err);
    size_t num_loops = s == CM_OK ? polygons[0].num_loops : 0;
    size_t *start = s == CM_OK ? malloc((num_loops + 1) * sizeof *start) : NULL;
    if (s == CM_OK && !start) s = cm_fail_status(err, CM_ERR_NO_MEMORY);
    for (size_t g = 0; s == CM_OK && g < k; g++) {
        start[0] = 0;
        for (size_t l = 0; l < num_loops; l++) start[l + 1] = start[l] + polygons[g].loop_sizes[l];
        s = check_one_loops(polygons[g].xy, start, num_loops, (long)g, err, orientation + g * num_loops);
    }
    free(start);
    return s;
}

cm_status cm_input_validate_loops(const cm_loops *polygons, size_t k, cm_error *err, int *reversed)
{
    cm_status s = check_loops_arguments(polygons, k, 1, err);
    if (s != CM_OK) return s;
    size_t num_loops = polygons[0].num_loops;
    size_t *start = malloc((num_loops + 1) * sizeof *start);
    int *orientation = malloc(num_loops * sizeof *orientation), *first = malloc(num_loops * sizeof *first);
    if (!start || !orientation || !first) s = cm_fail_status(err, CM_ERR_NO_MEMORY);
    if (s == CM_OK) {
        start[0] = 0;
        for (size_t l = 0; l < num_loops; l++) start[l + 1] = start[l] + polygons[0].loop_sizes[l];
    }
    char name[64];
    for (size_t g = 0; s == CM_OK && g < k; g++) {
        s = check_one_loops(polygons[g].xy, start, num_loops, (long)g, err, g ? orientation : first);
        for (size_t l = 0; s == CM_OK && g > 0 && l < num_loops; l++)
            if (orientation[l] != first[l]) {
                cm_fail_at(err, (long)g, (long)start[l], -1);
                s = cm_fail(err, CM_ERR_ORIENTATION_MISMATCH,
                            "polygon %zu: %s is %s but in polygon 0 it is %s: the vertex correspondence "
                            "would mirror it", g, loop_name(name, sizeof name, l),
                            orientation[l] > 0 ? "counter-clockwise" : "clockwise",
                            first[l] > 0 ? "counter-clockwise" : "clockwise");
            }
    }
    /* The material lies left of every loop: outer counter-clockwise, holes clockwise. */
    for (size_t l = 0; s == CM_OK && l < num_loops; l++) reversed[l] = l == 0 ? first[l] < 0 : first[l] > 0;
    free(start), free(orientation), free(first);
    return s;
}
