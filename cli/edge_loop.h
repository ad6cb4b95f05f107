/* One closed polygon from the edges of a polyline file (OBJ `l` elements,
 * PLY edge elements): the edges, in any order and either direction, must
 * form exactly one closed loop. */
#ifndef CM_CLI_EDGE_LOOP_H
#define CM_CLI_EDGE_LOOP_H

#include <stddef.h>

#include "cli_common.h"

/* An edge between vertices a and b (0-based), read at `where`: a line
 * number, or with binary files the edge's index in the file. */
typedef struct loop_edge {
    long a, b;
    long where;
} loop_edge;

/* Chains edges[0..count) over vertex_count vertices (messages number
 * them from base: 1 for OBJ, 0 for PLY) into one loop, starting
 * at edges[0].a and leaving it along edges[0] (so a file listing the loop
 * in order keeps that order). Vertices no edge touches are ignored. On
 * success *loop (malloc'ed) holds the *length vertices in order. Errors
 * ("PATH:WHERE: ...", or "PATH: edge WHERE: ..." when by_index) name the
 * edge where the problem shows: an index out of range, an edge from a
 * vertex to itself or repeated, a branching vertex, an open end, several
 * loops, no edge at all. Returns CLI_EXIT_OK, CLI_EXIT_USAGE or
 * CLI_EXIT_INTERNAL (out of memory). */
int edge_loop(const char *path, const loop_edge *edges, size_t count, size_t vertex_count, int base, int by_index,
              long **loop, size_t *length, cli_error *error);

#endif
