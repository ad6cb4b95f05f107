/* Optimisation of the Steiner vertices' positions in every geometry at
 * once, against a distortion energy of the piecewise-linear maps between
 * the geometries (map-aware remeshing, remesh.c). Every accepted state is
 * valid in every geometry (exact orient2d). */
#ifndef CM_REMESH_MAPOPT_H
#define CM_REMESH_MAPOPT_H

#include "remesh/kmesh.h"

/* The energy, summed over the live triangles (coordinates over each
 * geometry's scale): map times the conformal distortion (MIPS,
 * sigma1/sigma2 + sigma2/sigma1) of the affine map between every two
 * geometries of the triangle, plus shape times that of the map from an
 * equilateral triangle to each geometry's. Both grow without bound as a
 * triangle degenerates in any geometry. */
typedef struct cm_mapopt_weights {
    double map, shape;
    /* each term raised to this power (0 or 1: as is): larger leans
     * toward the worst triangles, as the smallest angle does */
    double power;
} cm_mapopt_weights;

/* Up to `iterations` descent steps on the energy over the Steiner
 * vertices of every geometry, boundary fixed: the gradient preconditioned
 * by a length-weighted graph Laplacian (CHOLMOD, one factorisation per
 * call), a step that never reaches a zero triangle area in any geometry,
 * backtracking until the energy drops enough and the exact predicates say
 * every triangle is counter-clockwise in every geometry. Moves vertices
 * directly: not inside a transaction. Returns the steps taken, or -1 out
 * of memory (the mesh is then valid, with the last accepted state). */
long cm_mapopt_run(cm_kmesh *km, cm_mapopt_weights w, int iterations);

/* Up to `sweeps` sweeps over the Steiner vertices, each moved in each
 * geometry in turn by a Newton step on the energy of its triangles,
 * backtracking until that drops and they stay valid (exact); a sweep
 * without a move ends it. Through cm_kmesh_move: fine inside a
 * transaction. Returns the moves, -1 out of memory. */
long cm_mapopt_local(cm_kmesh *km, cm_mapopt_weights w, int sweeps);

/* Up to `steps` such rounds (every geometry once) on Steiner vertex v
 * alone. Returns 1 moved, 0 not, -1 out of memory. star is scratch. */
int cm_mapopt_vertex(cm_kmesh *km, cm_mapopt_weights w, int32_t v, int steps, cm_ibuf *star);

/* The energy of the mesh, triangles flat in doubles left out (tests,
 * reports). */
double cm_mapopt_energy(const cm_kmesh *km, cm_mapopt_weights w);

#endif
