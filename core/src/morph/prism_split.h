/* Splitting a layer of prisms (one triangle mesh between a bottom and a
 * top section) into tetrahedra that conform across the prisms' shared quad
 * faces and avoid slivers where the prisms allow.
 *
 * A prism splits into 3 tetrahedra once each of its quad faces has a
 * diagonal; the diagonal of the face over edge uv runs from the bottom of
 * the earlier of u, v to the top of the later, so a split is an order of
 * the triangle's corners, and conforming splits are the orientations of
 * the mesh edges in which no triangle is a directed cycle. The choice:
 * triangles in increasing order of the best smallest dihedral angle their
 * prism admits (the worst first, so the bottleneck gets its best split),
 * each takes its best order among those its already oriented edges allow;
 * when two edges of a triangle form a path, the third is forced at once,
 * which keeps every triangle acyclic. */
#ifndef CM_PRISM_SPLIT_H
#define CM_PRISM_SPLIT_H

#include <stddef.h>
#include <stdint.h>

#include "base/error.h"

typedef struct cm_split_rank {
    float best; /* the best smallest dihedral angle of the triangle's prism */
    int32_t tri;
} cm_split_rank;

typedef struct cm_prism_split {
    size_t nv, nt, ne;
    const int32_t *tri;     /* 3 * nt, counter-clockwise */
    int32_t *tri_edge;      /* 3 * nt: edge of corners (c, c + 1) */
    int32_t *edge_tri;      /* 2 * ne: its triangles, -1 on the boundary */
    int32_t *edge_end;      /* 2 * ne: its vertices, lower index first */
    size_t *vertex_start;   /* nv + 1: vertex v's edges are */
    int32_t *vertex_edge;   /* vertex_edge[vertex_start[v] .. vertex_start[v + 1]) */
    /* scratch per layer */
    signed char *dir;       /* ne: 1 lower index first, 0 the other, -1 open */
    float *score;           /* 6 * nt: smallest dihedral of each order */
    cm_split_rank *order;   /* nt */
    int32_t *queue;         /* ne: the edges oriented by a trial */
    size_t logged;
    signed char *saved;     /* ne: directions before a trial move */
} cm_prism_split;

/* The edges of the mesh (tri stays borrowed). */
cm_status cm_prism_split_init(cm_prism_split *split, const int32_t *tri, size_t nt, size_t nv,
                              cm_error *error);
void cm_prism_split_free(cm_prism_split *split);

/* Chooses the split of the layer between bottom[3 * nv] and top[3 * nv]
 * (x y z per vertex): order[t] in 0..5 for each triangle (an index into
 * the 6 corner orders). Returns the smallest dihedral angle of the chosen
 * tetrahedra in degrees (-1 if one is not positive in floating point). */
double cm_prism_split_choose(cm_prism_split *split, const double *bottom, const double *top,
                             unsigned char *order);

/* The 3 tetrahedra (12 node indices, positive when the prism is valid) of
 * prism v[6] (bottom a b c counter-clockwise, top a' b' c') for order. */
void cm_prism_split_tets(const int32_t v[6], unsigned char order, int32_t out[12]);

#endif
