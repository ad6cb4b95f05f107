/* Exact simplicity test of one closed polygon. */
#ifndef CM_POLYGON_CHECK_H
#define CM_POLYGON_CHECK_H

#include <stddef.h>

/* Looks for two edges of the closed polygon xy[0..n-1] (edge i joins vertex
 * i and i+1 mod n) that cross or touch, other than consecutive edges meeting
 * at their shared vertex. Consecutive edges that overlap (a spike doubling
 * back) count. Runs a Shamos-Hoey scan-line in O(n log n) with exact
 * predicates. Assumes finite coordinates and no repeated vertex.
 * Returns 1 and sets *edge_a < *edge_b if such a pair exists, 0 if the
 * polygon is simple, -1 if out of memory. */
int cm_polygon_find_intersection(const double *xy, long n, long *edge_a,
                                 long *edge_b);

/* The same for several closed loops stored one after another in xy
 * (loop l has loop_sizes[l] >= 3 vertices; its edges join consecutive
 * vertices and its last vertex to its first): edges of one loop or of
 * different loops that cross or touch. Edge e runs from vertex e (an index
 * into the whole array) to the next vertex of its loop. Same returns. */
int cm_loops_find_intersection(const double *xy, const size_t *loop_sizes, size_t num_loops,
                               long *edge_a, long *edge_b);

/* A vertex of a polygon, for sorting by x, then y, then index: a total
 * order for finite coordinates, so every sort gives the same result. */
typedef struct cm_vertex_event {
    double x, y;
    long vertex;
} cm_vertex_event;

/* Sorts e[0..n-1] in that order (merge sort, O(n log n), the comparisons
 * inline). 0, or -1 out of memory. */
int cm_vertex_events_sort(cm_vertex_event *e, long n);

/* cm_polygon_find_intersection with the polygon's n vertex events already
 * sorted by cm_vertex_events_sort (NULL: sorted here): a caller that
 * sorted them to look for repeated vertices sorts once. */
int cm_polygon_find_intersection_sorted(const double *xy, long n, const cm_vertex_event *sorted, long *edge_a,
                                        long *edge_b);

#endif
