/* The data every stage hands to the next: one triangle list over one
 * vertex numbering with k geometries. */
#ifndef CM_BASE_MESH_H
#define CM_BASE_MESH_H

#include <stddef.h>
#include <stdint.h>

typedef struct cm_mesh {
    size_t k;        /* geometries */
    size_t nv, nt;   /* vertices, triangles */
    double **xy;     /* k arrays of 2 * nv doubles */
    int32_t *tri;    /* 3 * nt indices, counter-clockwise */
    /* The boundary when it has holes: loop l is vertices loop_start[l] ..
     * loop_start[l + 1] - 1 (num_loops + 1 offsets), the outer loop
     * counter-clockwise, the holes clockwise. NULL: one loop, 0 .. n - 1.
     * Not owned. */
    const size_t *loop_start;
    size_t num_loops;
} cm_mesh;

/* The vertex after / before vertex i (< n) along its loop, the loops
 * being loop_start[l] .. loop_start[l + 1] - 1 (NULL: one loop 0 .. n - 1). */
size_t cm_loops_next(const size_t *loop_start, size_t n, size_t i);
size_t cm_loops_prev(const size_t *loop_start, size_t n, size_t i);

/* The loop holding vertex (or edge) v of a polygon whose num_loops loops
 * start at loop_start[0], loop_start[1], ... */
static inline size_t cm_loop_of(const size_t *loop_start, size_t num_loops, size_t v)
{
    size_t l = 0;
    while (l + 1 < num_loops && v >= loop_start[l + 1]) l++;
    return l;
}

/* Position j of an m-vertex loop read the other way round from the same
 * start (0, m - 1, m - 2, ..., 1): a loop listed clockwise against the
 * same loop listed counter-clockwise. */
static inline size_t cm_loop_reversed(size_t m, size_t j) { return j ? m - j : 0; }

/* The corner after c in its triangle (triangle t has corners 3 t,
 * 3 t + 1, 3 t + 2, counter-clockwise): the far end of c's edge is
 * tri[cm_corner_next(c)]. */
static inline size_t cm_corner_next(size_t c) { return c % 3 == 2 ? c - 2 : c + 1; }

/* An edge of a triangle list as its two vertices (lo < hi) and the corner
 * it starts at: corner 3 t + i, the edge from tri[3 t + i] to the next
 * vertex of triangle t. */
typedef struct cm_edge_key {
    int32_t lo, hi, corner;
} cm_edge_key;

/* The edge key of every corner of the nt triangles tri, sorted by (lo,
 * hi, corner): the corners of one edge side by side. NULL out of memory;
 * free() it. */
cm_edge_key *cm_mesh_edge_keys(const int32_t *tri, size_t nt);

/* Frees the arrays; the mesh is empty (k kept). */
void cm_mesh_clear(cm_mesh *mesh);

/* *dst becomes a copy of src's geometries and triangles (its loops, which
 * it does not own, as src's). 0, or -1 out of memory (dst then empty). */
int cm_mesh_copy(cm_mesh *dst, const cm_mesh *src);

#endif
