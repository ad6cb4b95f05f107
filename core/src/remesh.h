/* Compatible remeshing (paper sections 3 and 4): the local operations on a
 * cm_kmesh and Algorithm 1. Every operation keeps every geometry valid: a
 * change is made only after each affected triangle was found strictly
 * counter-clockwise in every geometry with the exact orient2d. */
#ifndef CM_REMESH_H
#define CM_REMESH_H

#include "kmesh.h"

/* Improvements smaller than this (radians) do not count: they would let
 * rounding noise drive endless flips and moves. */
#define CM_ANGLE_EPS 1e-9

/* ---- flip.c ---------------------------------------------------------------
 * Flips the interior edge opposite corner c if the quad is strictly convex
 * in every geometry and the smallest angle of its two triangles, over all
 * geometries, improves. Returns 1 if flipped. */
int cm_flip_try(cm_kmesh *km, int32_t c);
/* Flips the interior edge opposite c whatever the angles, if the quad is
 * strictly convex in every geometry. Returns 1 if flipped. */
int cm_flip_if_valid(cm_kmesh *km, int32_t c);
/* Flips until no edge in `edges` (corners; emptied) can improve; new
 * candidates are queued as flips happen. The vertices of flipped quads go
 * to `touched` (may be NULL). Returns the number of flips, -1 out of memory. */
long cm_flip_queue(cm_kmesh *km, cm_work *edges, cm_work *touched);
/* Queues every interior edge of the mesh. 0 or -1 out of memory. */
int cm_flip_queue_all(const cm_kmesh *km, cm_work *edges);
/* Queues the edges of the triangles around v. 0 or -1. */
int cm_flip_queue_around(const cm_kmesh *km, int32_t v, cm_work *edges, cm_ibuf *star);

/* ---- smooth.c -------------------------------------------------------------
 * Moves Steiner vertex v in geometry g to the position `method` proposes
 * (CM_SMOOTH_COMBINED: weighted angle-based, then Laplacian). Always only
 * if every triangle around v stays valid; if smart, only if the smallest
 * angle around v also improves. Returns 1 moved, 0 not, -1 out of memory.
 * star is scratch. */
int cm_smooth_vertex(cm_kmesh *km, size_t g, int32_t v, cm_smoothing method, int smart,
                     cm_ibuf *star);
/* The position `method` proposes for Steiner vertex v in geometry g, from
 * its star (corners from cm_kmesh_star). Returns 0, or -1 when undefined. */
int cm_smooth_target(const cm_kmesh *km, size_t g, int32_t v, cm_smoothing method,
                     const cm_ibuf *star, double out[2]);
/* Moves Steiner vertex v in geometry g to where the smallest angle of its
 * triangles is largest, by a short pattern search, if that gains. The
 * fallback when the smoothing formulas are stuck near a bad triangle.
 * Returns 1 moved, 0 not, -1 out of memory. */
int cm_smooth_optimize(cm_kmesh *km, size_t g, int32_t v, cm_ibuf *star);
/* One sweep over all Steiner vertices in every geometry. Returns the number
 * of moves, -1 out of memory. */
long cm_smooth_sweep(cm_kmesh *km, cm_smoothing method, int smart);

/* ---- areaeq.c -------------------------------------------------------------
 * Area equalisation (eq. 4): moves Steiner vertex v in geometry g to the
 * least-squares position that equalises the areas of its triangles, if all
 * of them stay valid. Returns 1 moved, 0 not, -1 out of memory. */
int cm_areaeq_vertex(cm_kmesh *km, size_t g, int32_t v, cm_ibuf *star);
/* One iteration over all Steiner vertices in every geometry; moved
 * vertices go to `touched` (may be NULL). Returns moves or -1. */
long cm_areaeq_sweep(cm_kmesh *km, cm_work *touched);

/* ---- refine.c -------------------------------------------------------------
 * Splits up to k_split pairwise non-adjacent interior edges at their
 * midpoints in every geometry, the candidates of the mesh with the best
 * scores (eq. 5: |e| relative to the geometry's size, the largest over
 * geometries, over the smallest angle beside e squared). The new vertices
 * go to `touched`. Returns the number of splits, -1 out of memory. */
long cm_refine_step(cm_kmesh *km, long k_split, cm_work *touched);
/* Marks the four vertices of the quad around the edge opposite c with
 * stamp, so that splits of one round share no vertex; 0 (nothing marked)
 * if one was marked already. */
int cm_refine_take_quad(cm_kmesh *km, int32_t c, uint32_t stamp);
/* The up to max best candidate edges (corners), best first, into out
 * (room for 3 * max). Returns how many. */
long cm_refine_candidates(const cm_kmesh *km, long max, int32_t *out);
/* Splits the interior edge opposite c at its midpoint in every geometry if
 * the four new triangles are valid in all: returns the new vertex, -2 when
 * invalid, -1 out of memory. */
int32_t cm_refine_split(cm_kmesh *km, int32_t c);
/* Caps from the boundary, per geometry the smallest (radians, n entries):
 * bcap[i], the best smallest angle of an isosceles triangle on boundary
 * edge i -> i+1 that fits inside the polygon (a boundary edge is never
 * split, so its triangle can do no better, near enough); vcap[i], half the
 * corner angle at vertex i (a corner split in two). */
void cm_boundary_caps(const cm_mesh *mesh, size_t n, double *bcap, double *vcap);

/* ---- collapse.c -----------------------------------------------------------
 * Removes Steiner vertices by collapsing each into a neighbour, best
 * resulting angle first, while valid in every geometry and the smallest
 * angle of the new triangles is at least min(old smallest angle around the
 * vertex, threshold) (radians; 0 accepts any valid collapse, pi only those
 * that do not make the neighbourhood worse). At most max_collapses (< 0: no
 * limit). The vertices around each collapse go to `touched` (may be NULL).
 * Returns the number of collapses, -1 out of memory. */
/* Collapses v = tri[c] (a Steiner vertex) onto u = tri[next(c)] if the
 * result is valid in every geometry and a disk, whatever the angles.
 * Returns 1 done, 0 not, -1 out of memory. star is scratch. */
int cm_collapse_try(cm_kmesh *km, int32_t c, cm_ibuf *star);
long cm_collapse_pass(cm_kmesh *km, double threshold, long max_collapses, cm_work *touched);

/* ---- remesh.c ------------------------------------------------------------- */
typedef struct cm_remesh_report {
    size_t iterations;    /* refinement rounds */
    long splits, split_attempts, collapses, flips;
    double target_deg;    /* the lowest triangle target after the boundary caps */
    double min_angle_deg; /* smallest angle of the result, all geometries */
} cm_remesh_report;

/* Algorithm 1 on mesh (polygon vertices 0..n-1 counter-clockwise, each
 * geometry valid), in place. o: the validated options. Returns CM_OK,
 * CM_ERR_NO_MEMORY, CM_ERR_CANCELLED or CM_ERR_INTERNAL (message on r). */
cm_status cm_remesh(cm_mesh *mesh, size_t n, const cm_options *o, cm_remesh_report *report,
                    cm_result *r);

#endif
