/* The joint max-min polish: every Steiner vertex of one geometry moved
 * at once to raise that geometry's smallest angle (maxmin.c says how). */
#ifndef CM_REMESH_MAXMIN_H
#define CM_REMESH_MAXMIN_H

#include "base/error.h"
#include "base/mesh.h"
#include "base/progress.h"

/* Moves the vertices nb .. nv - 1 of every geometry of mesh (the first nb
 * are the boundary, fixed) so that each geometry's smallest angle rises,
 * keeping every triangle counter-clockwise by the exact predicates. The
 * connectivity is unchanged, so the meshes stay compatible; no geometry's
 * smallest angle falls. At most max_iterations L-BFGS iterations per
 * geometry. CM_OK, CM_ERR_NO_MEMORY or CM_ERR_CANCELLED. */
cm_status cm_maxmin_polish(cm_mesh *mesh, size_t nb, int max_iterations, cm_progress *progress);

#endif
