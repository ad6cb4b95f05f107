/* The result handle behind the public accessors. */
#ifndef CM_API_RESULT_H
#define CM_API_RESULT_H

#include "base/error.h"
#include "base/mesh.h"
#include "correspond/arclength.h"
#include "correspond/bound.h"
#include "correspond/conformal.h"
#include "remesh/remesh.h"

struct cm_result {
    cm_error error;   /* status; message and location of a failure */

    size_t n;
    cm_mesh mesh;

    size_t nh;
    int32_t *he_next, *he_to, *he_face, *vertex_he, *face_he;

    cm_stats stats;
    cm_quality *quality; /* k entries */
    cm_quality *quality_before; /* k entries: before remeshing */
    cm_boundary_map boundary;   /* CM_CORRESPOND_ARCLENGTH; empty for index */
    /* Polygons with holes: loop l is boundary vertices loop_start[l] ..
     * loop_start[l + 1] - 1, the outer loop first; NULL without holes. */
    size_t *loop_start;
    size_t num_loops;
    /* The remesher's smallest angle before its final joint polish: auto's
     * second pairings are tried on it, so whether they run does not hang
     * on the polish. */
    double greedy_angle_deg;
    /* The smallest angle after the polish, before the restarts, and
     * whether the restarts would start from that result: auto's pairings
     * are compared on the first and the one kept restarted when the
     * second says so. */
    double polished_angle_deg;
    int restart_wanted;
    /* A rescue's run: the smallest angle after the polish of the result it
     * competes with (0: none), which it cannot beat where its pairing's
     * corner-fan cap is no higher (remesh_stage) and which decides whether
     * its polish-scored moves are worth running (cm_remesh). */
    double beat_deg;
    /* A rescue's run without restarts where restarts are asked for: where
     * they would start from (cm_remesh_resume), for the rerun of the
     * pairing kept; NULL otherwise. Owned. */
    cm_remesh_resume *resume;
    /* The caps and the conformal correspondence already computed in this
     * call (shared by a second pairing's result, owned by the call), or
     * NULL. */
    cm_bound_memo *bounds;
    cm_conformal_memo *conformal;
};

/* Drops all geometry, keeping status and message (a failed result). */
void cm_result_clear_geometry(cm_result *r);
/* Frees a result's resume (NULL: nothing). */
void cm_result_free_resume(cm_remesh_resume *resume);
/* Fills r->quality and the size stats of a checked result. known: NULL,
 * or each geometry's quality already measured on this very mesh (the
 * same triangles in the same order, the vertices at most renumbered). */
cm_status cm_result_measure(cm_result *r, const cm_quality *known);

#endif
