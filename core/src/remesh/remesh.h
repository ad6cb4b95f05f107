/* Compatible remeshing (paper sections 3 and 4): Algorithm 1 and the
 * steps around it (remesh.c explains the loop). The operations it drives
 * live in flip, smooth, areaeq, refine and collapse; what it aims for in
 * criteria. */
#ifndef CM_REMESH_REMESH_H
#define CM_REMESH_REMESH_H

#include "base/error.h"
#include "base/mesh.h"
#include "base/progress.h"
#include "remesh/kmesh.h"

typedef struct cm_remesh_report {
    size_t iterations;    /* refinement rounds */
    long splits, split_attempts, collapses, flips;
    double target_deg;    /* the lowest triangle target after the boundary caps */
    double min_angle_deg; /* smallest angle, all geometries, before the final
                             joint polish (the caller measures the result) */
    double polished_deg;  /* smallest angle after the polish, before any restart */
    int restart_wanted;   /* the result is one the restarts would start from
                             (far below its aim), whether or not they ran */
} cm_remesh_report;

/* Boundary splits: the remesher may split boundary edges (refinement
 * and forced moves) where the caller's boundary takes points on its input
 * edges. edge[g][i], t[g][i]: where boundary vertex i lies in geometry g
 * (k arrays of n, allocated with malloc), carried to the points added
 * through between(). On CM_OK the arrays are replaced by the final
 * boundary's, n of them: mesh vertices 0 .. n - 1, in loop order (vertex
 * 0 first; cm_kmesh_write). place: NULL, or (when the correspondence is
 * the tool's to choose) the point at parameter t of input edge e of
 * geometry g, and the final polish may slide the points with t > 0 along
 * their edges (cm_maxmin_slide), keeping boundary edges at most
 * max_piece long when that is > 0; slid: how many it moved (the
 * correspondence is then no longer the one the ceiling was computed
 * for). */
typedef struct cm_remesh_boundary {
    cm_kmesh_between between;
    void *ctx;
    int32_t **edge;
    double **t;
    size_t n;
    void (*place)(void *ctx, size_t g, int32_t e, double t, double xy[2]);
    double max_piece;
    size_t slid;
} cm_remesh_boundary;

/* Where a run's restarts start from: its result before any restart
 * (written, polished, its polish-scored moves made), with what the
 * restarts and the caller read of it. A run is the same up to there
 * whatever o->restarts says, so auto keeps this for a rescue run without
 * restarts, and the pairing it keeps runs only its restarts after it.
 * mesh.nv == 0: nothing kept. */
typedef struct cm_remesh_resume {
    cm_mesh mesh;
    size_t nb;                 /* its boundary vertices */
    size_t *written;           /* its loops' offsets (num_loops + 1) where points were added to loops, else NULL */
    int32_t **edge;            /* with boundary splits: the labels (cm_remesh_boundary), k arrays of nb, else NULL */
    double **t;
    size_t slid;
    cm_remesh_report report;
} cm_remesh_resume;

void cm_remesh_resume_clear(cm_remesh_resume *resume);

/* Algorithm 1 on mesh (polygon vertices 0..n-1 counter-clockwise, each
 * geometry valid), in place. o: the validated options. ceiling_deg: no
 * compatible triangulation has a larger smallest angle (60 when unknown);
 * refinement aims at min(o->min_angle_deg, ceiling_deg) and spends no
 * budget above it, while the final removal of Steiner vertices keeps
 * every angle at the full target. beat_deg: the smallest angle of a
 * result this run competes with (0: none); a run whose polished result
 * ends far below it (CM_REMESH_BEHIND) skips its polish-scored moves,
 * which could not lift it that far. resume: NULL; or empty, and it
 * receives where the restarts start from when the result would start
 * them (report->restart_wanted); or holding that of a run on this very
 * mesh with these options but for o->restarts, and only the restarts run
 * from it (it is emptied). Returns CM_OK, CM_ERR_NO_MEMORY,
 * CM_ERR_CANCELLED or CM_ERR_INTERNAL (message on err). */
cm_status cm_remesh(cm_mesh *mesh, size_t n, const cm_options *o, double ceiling_deg, double beat_deg,
                    cm_remesh_boundary *splits, cm_remesh_resume *resume, cm_progress *progress,
                    cm_remesh_report *report, cm_error *err);

#endif
