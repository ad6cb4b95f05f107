/* The loops of a polygon from the edges of a polyline file (OBJ `l`
 * elements, PLY edge elements): the edges, in any order and either
 * direction, must form closed loops (the outer boundary and its holes). */
#ifndef CM_CLI_EDGE_LOOP_H
#define CM_CLI_EDGE_LOOP_H

#include <float.h>
#include <math.h>
#include <stddef.h>

#include "cli_common.h"

/* Does a vertex (x, y, z) of a polyline file lie in the plane z = z0 of the
 * first? Up to the rounding of coordinates computed and written in single
 * precision (MeshLab's sections differ in the last float digits): within
 * 16 float epsilons of the largest of |x|, |y|, |z| and |z0|. The polygon
 * is meshed in x and y; z is only checked. */
static inline int in_plane_z(double x, double y, double z, double z0)
{
    double scale = fmax(fmax(fabs(x), fabs(y)), fmax(fabs(z), fabs(z0)));
    return fabs(z - z0) <= 16 * FLT_EPSILON * scale;
}

/* An edge between vertices a and b (0-based), read at `where`: a line
 * number, or with binary files the edge's index in the file. */
typedef struct loop_edge {
    long a, b;
    long where;
} loop_edge;

/* Chains edges[0..count) over vertex_count vertices (vertex v at
 * xy[stride * v], xy[stride * v + 1]; messages number vertices from base: 1 for OBJ, 0 for PLY) into
 * closed loops. Each loop starts at the first edge (in file order) not on
 * an earlier one and leaves along it, so a file listing a loop in order
 * keeps that order; the loop of largest area comes first (the outer one),
 * the others follow in file order. Vertices no edge touches are ignored.
 * On success *loops (malloc'ed) holds the vertices, loop after loop, and
 * *sizes (malloc'ed) the *loop_count loop lengths. Errors ("PATH:WHERE:
 * ...", or "PATH: edge WHERE: ..." when by_index) name the edge where the
 * problem shows: an index out of range, an edge from a vertex to itself or
 * repeated, a branching vertex, an open end, no edge at all. Returns
 * CLI_EXIT_OK, CLI_EXIT_USAGE or CLI_EXIT_INTERNAL (out of memory). */
int edge_loops(const char *path, const loop_edge *edges, size_t count, const double *xy, size_t stride,
               size_t vertex_count,
               int base, int by_index, long **loops, size_t **sizes, size_t *loop_count, cli_error *error);

#endif
