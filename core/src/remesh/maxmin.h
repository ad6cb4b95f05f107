/* The joint max-min polish: every Steiner vertex of one geometry moved
 * at once to raise that geometry's smallest angle (maxmin.c says how). */
#ifndef CM_REMESH_MAXMIN_H
#define CM_REMESH_MAXMIN_H

#include "base/error.h"
#include "base/mesh.h"
#include "base/progress.h"

/* Boundary points that may slide along their input edge: those the
 * correspondence put on an input edge (t > 0) when the correspondence is
 * the tool's to choose. Labels as cm_remesh_boundary's, updated in
 * place; place writes the point at parameter t of input edge e of
 * geometry g (the one formula the labels' points come from). max_piece >
 * 0: a slid point's boundary edges stay at most this long. */
typedef struct cm_maxmin_slide {
    int32_t *const *edge;
    double *const *t;
    void (*place)(void *ctx, size_t g, int32_t e, double t, double xy[2]);
    void *ctx;
    double max_piece;
    size_t slid; /* out: how many boundary points moved */
    /* cm_maxmin_local only, with max_piece > 0: each boundary vertex's
     * neighbours along its loop (the joint polish finds them itself) */
    const int32_t *next, *prev;
} cm_maxmin_slide;

/* Moves the vertices nb .. nv - 1 of every geometry of mesh (the first nb
 * are the boundary, fixed unless slide allows them along their edges) so
 * that each geometry's smallest angle rises, keeping every triangle
 * counter-clockwise by the exact predicates. The connectivity is
 * unchanged, so the meshes stay compatible; no geometry's smallest angle
 * falls. At most max_iterations L-BFGS iterations per geometry. With
 * lowest_first, the geometry lowest at the start goes first and the others
 * stop once their smallest angle is a little above the least reached (the
 * result's cannot rise more); else every geometry is polished fully. CM_OK,
 * CM_ERR_NO_MEMORY or CM_ERR_CANCELLED. */
cm_status cm_maxmin_polish(cm_mesh *mesh, size_t nb, cm_maxmin_slide *slide, int lowest_first, int max_iterations,
                           cm_progress *progress);

/* The same ascent on a part of geometry g, xy (nv vertices, triangles
 * tri): the vertices var[0 .. nvar) move at once, everything else stays,
 * to raise the smallest angle of the triangles tris[0 .. ntris) (indices
 * into tri; every triangle touching a moving vertex must be listed).
 * With slide, a listed vertex v with slide->edge[g][v] >= 0 is a
 * boundary point that slides along that input edge from parameter
 * slide->t[g][v] (the others move freely); without, every listed vertex
 * moves freely. Returns 1 with the new positions in out (2 nvar doubles)
 * and a slid point's parameter in out_t (nvar doubles; the others' are
 * left as they were) when they are exactly valid (every listed triangle
 * strictly counter-clockwise, slid pieces short enough) and that
 * smallest angle did not fall; 0 when there is nothing better to write;
 * -CM_ERR_NO_MEMORY or -CM_ERR_CANCELLED. */
int cm_maxmin_local(const int32_t *tri, const double *xy, size_t nv, const int32_t *var, size_t nvar,
                    const int32_t *tris, size_t ntris, const cm_maxmin_slide *slide, size_t g, int max_iterations,
                    cm_progress *progress, double *out, double *out_t);

#endif
