/* Steiner-free compatible triangulation by dynamic programming over the
 * diagonals common to all geometries.
 *
 * A set of pairwise non-crossing common diagonals cuts the polygon into
 * faces that are simple in every geometry; if every face is a triangle the
 * result is a compatible triangulation without Steiner vertices, and every
 * such triangulation arises this way. The program decides exactly whether
 * one exists (the diagonals' validity is decided exactly by the caller)
 * and, among all of them, returns one maximising the smallest angle over
 * all geometries. When none exists it returns the decomposition along
 * common diagonals whose faces of four or more vertices ("stuck" faces, no
 * common diagonal inside) have the fewest vertices beyond three in total:
 * those faces are where Steiner vertices are needed.
 *
 * Optionally with fan points (each one point per geometry): a face may
 * instead be a fan from one of them, costing 1 whatever its size (one
 * Steiner vertex at that point triangulates it); an edge may bound a fan
 * face only if the point lies strictly on its inner side in every
 * geometry, so the face is star-shaped from it and the fan is valid (and
 * a point lies inside at most one face).
 *
 * Cost: O(m * (c + m)) time for m vertices and c common diagonals, so
 * O(m^3) at worst, O(m + c) memory; each fan point multiplies both. */
#ifndef CM_STEINERFREE_H
#define CM_STEINERFREE_H

#include <stddef.h>
#include <stdint.h>

#include "construct/diagset.h"

typedef struct cm_sf_plan {
    long cost;            /* sum over stuck faces of (vertices - 3), plus 1
                             for a fan face; 0 iff Steiner-free */
    double min_angle_deg; /* smallest angle of the triangles, all geometries
                             (180 when there are none) */
    int32_t *tri;         /* nt triangles, local indices, counter-clockwise */
    long nt;
    int32_t *face;        /* stuck faces: face[face_start[f] .. face_start[f+1]) */
    long *face_start;     /* nf + 1 entries */
    long nf;
    int32_t *face_fan;    /* per face: the fan point it is a fan from, or
                             -1 for a stuck face */
} cm_sf_plan;

/* m >= 3 local vertices 0..m-1 forming a polygon that is simple and
 * counter-clockwise in every geometry; cm_diagview_has(common, i, j) iff
 * (i, j) is a diagonal in every geometry (polygon edges are ignored);
 * xy[g] holds the 2m coordinates of geometry g; fans holds nfans fan
 * points, point x of geometry g at fans[2 (x k + g)] (NULL or 0: none).
 * At most CM_SF_MAX_FANS fan points. Returns 0, or -1 (out of memory, or
 * too many fan points). */
#define CM_SF_MAX_FANS 64
int cm_steinerfree_plan(long m, const cm_diagview *common, const double *const *xy, size_t k,
                        const double *fans, size_t nfans, cm_sf_plan *plan);
void cm_sf_plan_clear(cm_sf_plan *plan);

/* Buffers kept from one run to the next: many small programs (the link
 * cuts' halves) without allocations of their own. cm_steinerfree_plan_in
 * is cm_steinerfree_plan without fan points, every array (the plan's too)
 * in work: the plan lives until work's next run or cm_sf_work_free, and is
 * not cleared. */
typedef struct cm_sf_work cm_sf_work;
cm_sf_work *cm_sf_work_new(void);
void cm_sf_work_free(cm_sf_work *work);
int cm_steinerfree_plan_in(cm_sf_work *work, long m, const cm_diagview *common, const double *const *xy, size_t k,
                           cm_sf_plan *plan);

/* A run without fan points can leave what a later run with them over the
 * same polygon reuses: its links, and the values of the rows whose
 * sub-polygons hold none of the fan points (those admit no fan face).
 * cm_steinerfree_plan_memo is cm_steinerfree_plan without fan points,
 * keeping *memo (free with cm_sf_memo_free; NULL on failure);
 * cm_steinerfree_plan_fans is then cm_steinerfree_plan with fan points
 * (the same plan), over the memo's polygon and table, which must live as
 * long. */
typedef struct cm_sf_memo cm_sf_memo;
int cm_steinerfree_plan_memo(long m, const cm_diagview *common, const double *const *xy, size_t k,
                             cm_sf_plan *plan, cm_sf_memo **memo);
int cm_steinerfree_plan_fans(const cm_sf_memo *memo, const double *fans, size_t nfans, cm_sf_plan *plan);
void cm_sf_memo_free(cm_sf_memo *memo);

/* Number of common diagonals in the table (each counted once); _to: the
 * same, or limit if there are at least limit. */
long cm_steinerfree_count(long m, const cm_diagview *common);
long cm_steinerfree_count_to(long m, const cm_diagview *common, long limit);

#endif
