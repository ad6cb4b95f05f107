/* An exact check of a result from its public arrays only, independent of
 * the core's own check: the fuzz harness, the soak test and the
 * near-degenerate tests use it to catch a wrong answer reported as CM_OK.
 *
 *   rc_check(r, polygons, k, n, why, size) returns 1 when r is a valid
 *   compatible triangulation of the k polygons of n vertices, else 0 with
 *   the first violation written to why.
 *
 * What it checks, for every geometry: the n input vertices come back
 * bit-identical and every vertex is finite; every triangle is strictly
 * counter-clockwise (exact orientation, core/src/geom/predicates.h); every
 * directed edge is used once at most; the edges used by one triangle only
 * are exactly the polygon's edges, counter-clockwise around it (the input's
 * order, or its reverse for clockwise input); V - E + F = 1; and the
 * triangle areas add up exactly (GMP rationals) to the polygon's area.
 * A triangulated disk whose triangles are all positive and whose boundary
 * runs once around a simple polygon covers it exactly once, so together
 * these mean a valid triangulation of every polygon. */
#ifndef CM_TEST_RESULT_CHECK_H
#define CM_TEST_RESULT_CHECK_H

#include <gmp.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "compatmesh/compatmesh.h"
#include "geom/predicates.h"

static inline int rc_fail(char *why, size_t size, const char *format, ...)
{
    if (why && size) {
        va_list args;
        va_start(args, format);
        vsnprintf(why, size, format, args);
        va_end(args);
    }
    return 0;
}

/* Twice the signed area of triangle abc, added to sum exactly. */
static inline void rc_add_area2(mpq_t sum, const double *a, const double *b, const double *c,
                                mpq_t t0, mpq_t t1, mpq_t t2, mpq_t t3)
{
    mpq_set_d(t0, b[0]); mpq_set_d(t1, a[0]); mpq_sub(t0, t0, t1);     /* bx - ax */
    mpq_set_d(t2, c[1]); mpq_set_d(t1, a[1]); mpq_sub(t2, t2, t1);     /* cy - ay */
    mpq_mul(t0, t0, t2);
    mpq_set_d(t2, b[1]); mpq_set_d(t1, a[1]); mpq_sub(t2, t2, t1);     /* by - ay */
    mpq_set_d(t3, c[0]); mpq_set_d(t1, a[0]); mpq_sub(t3, t3, t1);     /* cx - ax */
    mpq_mul(t2, t2, t3);
    mpq_sub(t0, t0, t2);
    mpq_add(sum, sum, t0);
}

/* Directed edge key for sorting: (from, to). */
static inline int rc_edge_cmp(const void *a, const void *b)
{
    const int64_t x = *(const int64_t *)a, y = *(const int64_t *)b;
    return (x > y) - (x < y);
}

/* Twice the signed area of loop poly[0..n-1], added to sum exactly (a fan
 * from its first vertex: the shoelace sum). */
static inline void rc_add_loop_area2(mpq_t sum, const double *poly, size_t n, mpq_t t0, mpq_t t1,
                                     mpq_t t2, mpq_t t3)
{
    for (size_t i = 1; i + 1 < n; i++)
        rc_add_area2(sum, poly, poly + 2 * i, poly + 2 * (i + 1), t0, t1, t2, t3);
}

/* The triangles' areas add up to the outer loop's minus the holes'. */
static inline int rc_area_matches(const double *xy, const int32_t *tri, size_t nt,
                                  const cm_loops *poly, const int *orientation)
{
    mpq_t tris, ring, loop, t0, t1, t2, t3;
    mpq_inits(tris, ring, loop, t0, t1, t2, t3, NULL);
    for (size_t t = 0; t < nt; t++)
        rc_add_area2(tris, xy + 2 * tri[3 * t], xy + 2 * tri[3 * t + 1], xy + 2 * tri[3 * t + 2],
                     t0, t1, t2, t3);
    const double *at = poly->xy;
    for (size_t l = 0; l < poly->num_loops; l++) {
        mpq_set_ui(loop, 0, 1);
        rc_add_loop_area2(loop, at, poly->loop_sizes[l], t0, t1, t2, t3);
        /* the outer loop counts positive, the holes negative */
        if ((orientation[l] < 0) != (l > 0)) mpq_neg(loop, loop);
        mpq_add(ring, ring, loop);
        at += 2 * poly->loop_sizes[l];
    }
    int equal = mpq_equal(tris, ring) != 0;
    mpq_clears(tris, ring, loop, t0, t1, t2, t3, NULL);
    return equal;
}

/* The loop and position of vertex v (< n) of a polygon with these loops. */
static inline size_t rc_loop_of(const cm_loops *p, size_t v, size_t *first)
{
    size_t l = 0, at = 0;
    while (v >= at + p->loop_sizes[l]) at += p->loop_sizes[l++];
    *first = at;
    return l;
}

/* rc_check for polygons with holes: the boundary edges are exactly the
 * loops' edges, the outer loop counter-clockwise and the holes clockwise
 * (each loop's input order or its reverse), V - E + F = 1 - holes, and the
 * areas add up to the outer loop's minus the holes'. */
static inline int rc_check_loops(const cm_result *r, const cm_loops *polygons, size_t k,
                                 char *why, size_t size)
{
    if (!r || cm_result_status(r) != CM_OK) return rc_fail(why, size, "not a successful result");
    size_t nv = cm_result_num_vertices(r), nt = cm_result_num_triangles(r), n = 0;
    const cm_loops *p0 = &polygons[0];
    for (size_t l = 0; l < p0->num_loops; l++) n += p0->loop_sizes[l];
    const int32_t *tri = cm_result_triangles(r);
    if (cm_result_num_geometries(r) != k) return rc_fail(why, size, "%zu geometries", cm_result_num_geometries(r));
    if (nv < n || !tri || nt == 0) return rc_fail(why, size, "%zu vertices, %zu triangles", nv, nt);
    int orientation[64];
    if (p0->num_loops > 64) return rc_fail(why, size, "too many loops for the checker");
    for (size_t l = 0, at = 0; l < p0->num_loops; at += p0->loop_sizes[l++])
        orientation[l] = cm_polygon_orientation(p0->xy + 2 * at, (long)p0->loop_sizes[l]);

    /* Topology: directed edges once each, boundary = loop edges. */
    int64_t *edges = malloc(3 * nt * sizeof *edges);
    if (!edges) return rc_fail(why, size, "out of memory");
    for (size_t t = 0; t < nt; t++)
        for (int j = 0; j < 3; j++) {
            int32_t a = tri[3 * t + j], b = tri[3 * t + (j + 1) % 3];
            if (a < 0 || b < 0 || (size_t)a >= nv || (size_t)b >= nv || a == b) {
                free(edges);
                return rc_fail(why, size, "triangle %zu has bad indices", t);
            }
            edges[3 * t + j] = (int64_t)a * (int64_t)nv + b;
        }
    qsort(edges, 3 * nt, sizeof *edges, rc_edge_cmp);
    size_t undirected = 0, boundary = 0;
    for (size_t i = 0; i < 3 * nt; i++) {
        if (i > 0 && edges[i] == edges[i - 1]) {
            free(edges);
            return rc_fail(why, size, "a directed edge is used twice");
        }
        int64_t a = edges[i] / (int64_t)nv, b = edges[i] % (int64_t)nv;
        int64_t twin = b * (int64_t)nv + a;
        int paired = bsearch(&twin, edges, 3 * nt, sizeof *edges, rc_edge_cmp) != NULL;
        if (paired) {
            undirected += a < b;
            continue;
        }
        undirected++;
        boundary++;
        /* A boundary edge must be a loop edge, with the material on its left. */
        size_t first = 0, l = (size_t)a < n ? rc_loop_of(p0, (size_t)a, &first) : 0;
        int material_left = (l == 0) == (orientation[l] > 0);
        int64_t from = material_left ? a : b, to = material_left ? b : a, m = (int64_t)p0->loop_sizes[l];
        if (a >= (int64_t)n || b >= (int64_t)n || from < (int64_t)first || from >= (int64_t)first + m ||
            to != (int64_t)first + (from - (int64_t)first + 1) % m) {
            free(edges);
            return rc_fail(why, size, "boundary edge %lld-%lld is not a loop edge",
                           (long long)a, (long long)b);
        }
    }
    free(edges);
    long euler = 2 - (long)p0->num_loops;
    if (boundary != n) return rc_fail(why, size, "%zu boundary edges for %zu loop edges", boundary, n);
    if ((long)nv - (long)undirected + (long)nt != euler)
        return rc_fail(why, size, "Euler characteristic %ld, expected %ld",
                       (long)nv - (long)undirected + (long)nt, euler);

    /* Geometry, every polygon. */
    for (size_t g = 0; g < k; g++) {
        const double *xy = cm_result_vertices(r, g);
        if (!xy) return rc_fail(why, size, "geometry %zu missing", g);
        if (memcmp(xy, polygons[g].xy, 2 * n * sizeof *xy) != 0)
            return rc_fail(why, size, "geometry %zu: input vertices changed", g);
        for (size_t v = 0; v < 2 * nv; v++)
            if (!isfinite(xy[v])) return rc_fail(why, size, "geometry %zu: vertex %zu not finite", g, v / 2);
        for (size_t t = 0; t < nt; t++)
            if (cm_orient2d(xy + 2 * tri[3 * t], xy + 2 * tri[3 * t + 1], xy + 2 * tri[3 * t + 2]) <= 0)
                return rc_fail(why, size, "geometry %zu: triangle %zu is not counter-clockwise", g, t);
        if (!rc_area_matches(xy, tri, nt, &polygons[g], orientation))
            return rc_fail(why, size, "geometry %zu: triangle areas do not add up to the polygon's", g);
    }
    return 1;
}

static inline int rc_check(const cm_result *r, const double *const *polygons, size_t k, size_t n,
                           char *why, size_t size)
{
    cm_loops *loops = malloc((k + 1) * sizeof *loops);
    if (!loops) return rc_fail(why, size, "out of memory");
    for (size_t g = 0; g < k; g++) loops[g] = (cm_loops){polygons[g], &n, 1};
    int ok = rc_check_loops(r, loops, k, why, size);
    free(loops);
    return ok;
}

/* The half-edge arrays of r agree with its triangles: h and h ^ 1 are
 * opposite (different end vertices), every face's next cycle has length 3
 * within the face, n boundary half-edges, 2 (V + F - (1 - holes)) in all. */
static inline int rc_check_halfedges_holes(const cm_result *r, size_t n, size_t holes, char *why,
                                           size_t size)
{
    size_t nv = cm_result_num_vertices(r), nt = cm_result_num_triangles(r);
    size_t nh = cm_result_num_halfedges(r), boundary = 0;
    const int32_t *next = cm_result_halfedge_next(r), *to = cm_result_halfedge_to_vertex(r),
                  *face = cm_result_halfedge_face(r);
    if (!next || !to || !face) return rc_fail(why, size, "no half-edges");
    for (size_t h = 0; h < nh; h++) {
        if (to[h] == to[h ^ 1]) return rc_fail(why, size, "half-edges %zu and %zu end at one vertex", h, h ^ 1);
        if (face[h] < 0) {
            boundary++;
            continue;
        }
        if (next[next[next[h]]] != (int32_t)h || face[next[h]] != face[h])
            return rc_fail(why, size, "half-edge %zu: its face's next cycle is not a triangle", h);
    }
    if (boundary != n || nh + 2 != 2 * (nv + nt + holes))
        return rc_fail(why, size, "%zu half-edges, %zu on the boundary", nh, boundary);
    return 1;
}

static inline int rc_check_halfedges(const cm_result *r, size_t n, char *why, size_t size)
{
    return rc_check_halfedges_holes(r, n, 0, why, size);
}

/* rc_check and rc_check_halfedges, for a test that wants a yes or no. */
static inline int rc_valid(const cm_result *r, const double *const *polygons, size_t k, size_t n)
{
    return rc_check(r, polygons, k, n, NULL, 0) && rc_check_halfedges(r, n, NULL, 0);
}

/* The smallest angle (degrees) over the k meshes of r; 180 when none has
 * a quality (a failed result). */
static inline double rc_least_angle(const cm_result *r, size_t k)
{
    double least = 180;
    for (size_t g = 0; g < k; g++) {
        cm_quality q;
        if (cm_result_quality(r, g, &q) == CM_OK && q.min_angle_deg < least) least = q.min_angle_deg;
    }
    return least;
}

/* How far r's pairing turns the plane (degrees, signed): the angle of the
 * least-squares rotation taking polygon 0's first n boundary vertices onto
 * polygon g's, both centred. */
static inline double rc_plane_turn_deg(const cm_result *r, size_t g, size_t n)
{
    const double *a = cm_result_vertices(r, 0), *b = cm_result_vertices(r, g);
    double ma[2] = {0, 0}, mb[2] = {0, 0}, re = 0, im = 0;
    for (size_t i = 0; i < n; i++) ma[0] += a[2 * i], ma[1] += a[2 * i + 1], mb[0] += b[2 * i], mb[1] += b[2 * i + 1];
    for (int d = 0; d < 2; d++) ma[d] /= (double)n, mb[d] /= (double)n;
    for (size_t i = 0; i < n; i++) {
        double ax = a[2 * i] - ma[0], ay = a[2 * i + 1] - ma[1], bx = b[2 * i] - mb[0], by = b[2 * i + 1] - mb[1];
        re += ax * bx + ay * by, im += ax * by - ay * bx;
    }
    return atan2(im, re) * 180 / 3.14159265358979323846;
}

#endif
