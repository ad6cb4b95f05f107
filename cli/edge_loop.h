/* What the polygon readers share: the loops of a polygon from the edges
 * of a polyline file (OBJ `l` elements, PLY edge elements: in any order
 * and either direction, they must form closed loops, the outer boundary
 * and its holes), the plane check of every vertex's z and the closing
 * repeat of a ring. */
#ifndef CM_CLI_EDGE_LOOP_H
#define CM_CLI_EDGE_LOOP_H

#include <stddef.h>

#include "cli_common.h"

/* The plane z = constant of a file's vertices: the first vertex's z (0
 * where none is given), every later one checked against it up to the
 * rounding of single precision (MeshLab's sections differ in the last
 * float digits).
 * by_index: vertices are named by their index (binary files, GeoJSON),
 * else by their line. */
typedef struct plane_z {
    double z;
    long where;  /* the first vertex's line or index */
    int started; /* a vertex was taken */
    int given;   /* some vertex gave z */
    int first_given; /* the first vertex gave z */
    int by_index;
    int off;     /* plane_z_note: some vertex left the plane (a section in another plane) */
} plane_z;

/* Takes vertex (x, y, z), read at `where` (given: the file wrote its z),
 * into the plane, or says where it leaves it ("PATH:LINE: z = ... differs
 * from z = ... on line L; ...", or "PATH: vertex I: ... of vertex J; ...").
 * Returns CLI_EXIT_OK or CLI_EXIT_USAGE. */
int plane_z_take(plane_z *plane, double x, double y, double z, int given, const char *path, long where,
                 cli_error *error);

/* The same without an error: notes whether the vertex leaves the plane
 * (plane->off), for readers that take sections in any plane. */
void plane_z_note(plane_z *plane, double x, double y, double z, int given, long where);

/* Does a vertex read at `where` give z (given) as the first vertex did?
 * A line without z among lines with one is a typo, which read as z = 0
 * would be blamed on the plane. CLI_EXIT_OK, or CLI_EXIT_USAGE with
 * "PATH:LINE: no z here, while line L gives one; ...". */
int plane_z_same_columns(const plane_z *plane, int given, const char *path, long where, cli_error *error);

/* A ring's vertex count without its closing repeat: size - 1 where the
 * last of its size vertices (stride doubles each, all compared) repeats
 * the first exactly, as GMT, WKT, shapefiles and GeoJSON close rings; a
 * ring of three or fewer keeps them all, for the messages on too few
 * vertices. */
static inline size_t ring_size_without_repeat(const double *p, size_t stride, size_t size)
{
    if (size < 4) return size;
    for (size_t c = 0; c < stride; c++)
        if (p[c] != p[stride * (size - 1) + c]) return size;
    return size - 1;
}

/* An edge between vertices a and b (0-based), read at `where`: a line
 * number, or with binary files the edge's index in the file. */
typedef struct loop_edge {
    long a, b;
    long where;
} loop_edge;

/* Chains edges[0..count) over vertex_count vertices (vertex v at
 * xy[stride * v], xy[stride * v + 1], and with stride 3 its z next;
 * messages number vertices from base: 1 for OBJ, 0 for PLY) into
 * closed loops. Each loop starts at the first edge (in file order) not on
 * an earlier one and leaves along it, so a file listing a loop in order
 * keeps that order; the loop of largest area (with stride 3 its area in
 * space, Newell's, so that a section in any plane is measured in it) comes
 * first (the outer one),
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

/* Copies token (text from an input file) into out for an error message:
 * its first max_chars bytes (then "..."), those that are not printable
 * ASCII shown as \xNN so the message stays one line; returns out. */
const char *quote_token(const char *token, size_t max_chars, char *out, size_t size);

#endif
