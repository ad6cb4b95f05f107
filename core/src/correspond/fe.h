/* Linear finite elements on one polygon, with or without holes: a mesh of
 * the polygon alone, split into four until fine enough, its stiffness
 * matrix, and solves by CHOLMOD (the ceiling's moduli, the conformal
 * correspondence's harmonic measure, the annulus correspondence's harmonic
 * function). */
#ifndef CM_CORRESPOND_FE_H
#define CM_CORRESPOND_FE_H

#include <stdint.h>
#include <cholmod.h>

#include "base/error.h"

typedef struct cm_fe_mesh {
    long nv, nt;
    double *xy;      /* 2 nv */
    int32_t *tri;    /* 3 nt, counter-clockwise */
    long nb;         /* boundary nodes: n << levels */
    int32_t *bnode;  /* boundary nodes in order, bnode[i << levels] = vertex i */
    int levels;
    size_t num_loops;
    long *loop_first; /* num_loops + 1: loop l's boundary nodes are bnode[loop_first[l] .. loop_first[l + 1] - 1] */
    /* stiffness matrix, upper triangle by columns (kx), and the matrix
     * being solved (a: the same pattern, fixed rows and columns replaced
     * by the identity), its analysis (CHOLMOD) */
    cholmod_common cc;
    int started;
    cholmod_sparse *a;
    double *kx;
    cholmod_factor *factor;
    unsigned char *fixed;
    double *u, *rhs;
} cm_fe_mesh;

/* The mesh of the counter-clockwise polygon xy (n vertices; tri its
 * triangulation, 3 (n - 2) indices, or NULL to ear-clip one here), split
 * until it has at least min_triangles, and its stiffness matrix, analysed
 * with the boundary fixed. *usable = 0 when a triangle has no positive
 * area in doubles (nothing can be solved). cm_fe_free releases it, also
 * after a failure. */
cm_status cm_fe_build(cm_fe_mesh *m, const double *xy, const int32_t *tri, size_t n, long min_triangles,
                      int *usable, cm_error *err);

/* The same for a polygon with holes: its loops are xy's vertices
 * loop_start[l] .. loop_start[l + 1] - 1 (the outer loop counter-clockwise,
 * the holes clockwise, validated), triangulated here (cm_loops_triangulate).
 * The boundary nodes run loop by loop, each loop in its input direction. */
cm_status cm_fe_build_loops(cm_fe_mesh *m, const double *xy, const size_t *loop_start, size_t num_loops,
                            long min_triangles, int *usable, cm_error *err);

/* The boundary node after boundary node j along its loop. */
long cm_fe_next_boundary(const cm_fe_mesh *m, long j);
void cm_fe_free(cm_fe_mesh *m);

/* Twice the signed area and the opposite-edge vectors of triangle t. */
double cm_fe_tri(const cm_fe_mesh *m, long t, double d[3][2]);

/* Solves K u = rhs on the free nodes, u given on the fixed ones (m->fixed,
 * m->u); rhs on free nodes: a unit load at node `source` (-1: none) minus
 * the fixed values' contribution. u holds the result. refactor: 0 when
 * the fixed set is that of the last call (its factorization is reused). */
cm_status cm_fe_solve(cm_fe_mesh *m, long source, int refactor, cm_error *err);

/* K u, the stiffness times m->u (every row, fixed ones too), into out
 * (nv values): at a fixed node the flux of u out of the domain there. */
void cm_fe_residual(const cm_fe_mesh *m, double *out);

/* Up to CM_FE_SAMPLE interior nodes spread over the node numbering, into
 * sample; how many (0: none). Leaves the boundary fixed at 0 (m->fixed,
 * m->u). */
#define CM_FE_SAMPLE 64
long cm_fe_sample_interior(cm_fe_mesh *m, long *sample);

/* The node of sample (ns >= 1) farthest from the polygon (n vertices). */
long cm_fe_deepest(const cm_fe_mesh *m, size_t n, const long *sample, long ns);

/* The discrete harmonic measure of the boundary seen from interior node
 * source: w[j] (m->nb entries, boundary node order, non-negative, summing
 * to 1) is the flux -(K G) out of boundary node j of the Green's function
 * G (K G = unit load at source, G = 0 on the boundary); its running sum,
 * times 2 pi, places the boundary on the unit circle as a conformal map
 * taking source to the centre does. refactor as cm_fe_solve (the boundary
 * is fixed here). */
cm_status cm_fe_harmonic_measure(cm_fe_mesh *m, long source, int refactor, double *w, cm_error *err);

#endif
