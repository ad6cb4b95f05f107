/* Edge-split refinement (paper eq. 5). Candidates are the interior edges
 * beside a triangle that falls short of its target (kmesh.h keeps them by
 * score). Boundary edges are split only where the caller allows it (the
 * arc-length and auto correspondences, whose boundaries take points on
 * the input edges anyway): at the middle parameter of the input edge
 * each geometry's piece lies on, so that the boundary map stays as it
 * was; without that, a bad corner ear is refined through its one
 * interior edge. */
#include <math.h>
#include <stdlib.h>

#include "geom/predicates.h"
#include "remesh/refine.h"

/* Where to put the new vertex of a split, per geometry: the edge's
 * midpoint, or, where the rounded midpoint leaves one of the four new
 * triangles flat or folded (beside a triangle that is itself nearly
 * flat, e.g. an ear of three almost collinear boundary vertices), a point
 * pushed from it towards one of the two far vertices. */
static const double split_push[] = {0.0, 1.0 / 16, 1.0 / 4};

static int split_point_ok(const double *p0, const double *p1, const double *p2, const double *p3,
                          const double *m)
{
    return cm_orient2d(p0, p1, m) > 0 && cm_orient2d(p0, m, p2) > 0 && cm_orient2d(p3, p2, m) > 0 &&
           cm_orient2d(p3, m, p1) > 0;
}

/* Split points per geometry; 1 if the four new triangles are all valid. */
static int midpoints_ok(const cm_kmesh *km, int32_t c, double *pts)
{
    int32_t o = km->opp[c];
    int32_t v0 = km->tri[c], v1 = km->tri[cm_next(c)], v2 = km->tri[cm_prev(c)], v3 = km->tri[o];
    for (size_t g = 0; g < km->k; g++) {
        const double *p0 = cm_kmesh_pos(km, g, v0), *p1 = cm_kmesh_pos(km, g, v1),
                     *p2 = cm_kmesh_pos(km, g, v2), *p3 = cm_kmesh_pos(km, g, v3);
        double *m = pts + 2 * g, mid[2] = {0.5 * (p1[0] + p2[0]), 0.5 * (p1[1] + p2[1])};
        int found = 0;
        for (size_t i = 0; i < sizeof split_push / sizeof *split_push && !found; i++)
            for (int side = 0; side < (i ? 2 : 1) && !found; side++) {
                const double *far = side ? p3 : p0;
                m[0] = mid[0] + split_push[i] * (far[0] - mid[0]);
                m[1] = mid[1] + split_push[i] * (far[1] - mid[1]);
                found = split_point_ok(p0, p1, p2, p3, m);
            }
        if (!found) return 0;
    }
    return 1;
}

/* Nudges of a boundary split point whose rounding leaves it outside the
 * edge's line (cm_kmesh_between's steps). */
#define CM_BOUNDARY_NUDGES 16

/* The point on boundary edge v1 -> v2 (opposite c, v0 the third vertex)
 * in geometry g: on the input edge at the middle parameter (or nudged),
 * inside the triangle or on its boundary edge, the two new triangles
 * strictly counter-clockwise. 1 found, 0 none. */
static int boundary_point_ok(const cm_kmesh *km, int32_t c, size_t g, double *m, int32_t *e, double *t)
{
    int32_t v0 = km->tri[c], v1 = km->tri[cm_next(c)], v2 = km->tri[cm_prev(c)];
    const double *p0 = cm_kmesh_pos(km, g, v0), *p1 = cm_kmesh_pos(km, g, v1), *p2 = cm_kmesh_pos(km, g, v2);
    size_t a = km->k * (size_t)v1 + g, b = km->k * (size_t)v2 + g;
    for (int step = 0; step <= CM_BOUNDARY_NUDGES; step++) {
        if (!km->between(km->between_ctx, g, km->bedge[a], km->bt[a], km->bedge[b], km->bt[b], step, e, t, m))
            return 0;
        if (cm_orient2d(p1, p2, m) >= 0 && cm_orient2d(p0, p1, m) > 0 && cm_orient2d(p0, m, p2) > 0) return 1;
    }
    return 0;
}

static int32_t split_boundary(cm_kmesh *km, int32_t c, double *pts)
{
    int32_t *edge = malloc(km->k * sizeof *edge);
    double *t = malloc(km->k * sizeof *t);
    int32_t m = edge && t ? -2 : -1;
    int ok = m == -2;
    for (size_t g = 0; ok && g < km->k; g++) ok = boundary_point_ok(km, c, g, pts + 2 * g, edge + g, t + g);
    if (ok) m = cm_kmesh_split_boundary(km, c, pts, edge, t);
    free(edge), free(t);
    return m;
}

long cm_refine_candidates(cm_kmesh *km, long max, int32_t *out)
{
    if (max > INT32_MAX / 4) max = INT32_MAX / 4;
    return cm_heap_smallest(cm_kmesh_candidates(km), (int32_t)max, 0.0, out, out + max);
}

int32_t cm_refine_split(cm_kmesh *km, int32_t c)
{
    if (km->tri[c] < 0 || (km->opp[c] < 0 && !km->between)) return -2;
    double *pts = malloc(2 * km->k * sizeof *pts);
    if (!pts) return -1;
    int32_t m = km->opp[c] < 0 ? split_boundary(km, c, pts) : midpoints_ok(km, c, pts) ? cm_kmesh_split(km, c, pts) : -2;
    free(pts);
    return m;
}

int cm_refine_take_quad(cm_kmesh *km, int32_t c, uint32_t stamp)
{
    int32_t q[4] = {km->tri[c], km->tri[cm_next(c)], km->tri[cm_prev(c)], km->opp[c] >= 0 ? km->tri[km->opp[c]] : -1};
    int nq = q[3] >= 0 ? 4 : 3;
    for (int i = 0; i < nq; i++)
        if (km->mark[q[i]] == stamp) return 0;
    for (int i = 0; i < nq; i++) km->mark[q[i]] = stamp;
    return 1;
}

long cm_refine_step(cm_kmesh *km, long k_split, cm_work *touched)
{
    long want = k_split < 1000000 ? 4 * k_split + 8 : 4000008;
    int32_t *cand = malloc((size_t)want * 3 * sizeof *cand);
    if (!cand) return -1;
    long nc = cm_refine_candidates(km, want, cand), splits = 0;
    /* Quads of this round share no vertex, so the splits are independent. */
    uint32_t stamp = cm_kmesh_new_stamp(km);
    for (long i = 0; i < nc && splits < k_split; i++) {
        int32_t c = cand[i];
        if (km->tri[c] < 0 || (km->opp[c] < 0 && !km->between) || !cm_refine_take_quad(km, c, stamp)) continue;
        int32_t m = cm_refine_split(km, c);
        if (m == -2) continue;
        if (m < 0 || cm_work_push(touched, m)) {
            free(cand);
            return -1;
        }
        km->mark[m] = stamp;
        splits++;
    }
    free(cand);
    return splits;
}
