/* Points with exact predicates: input points (doubles, exact) and points
 * constructed as the intersection of two lines through earlier points (the
 * window end points of a window partition). A constructed point keeps its
 * exact homogeneous coordinates (GMP integers) and a double approximation
 * with an error bound; cm_xorient decides from the approximation when the
 * bound allows and from the exact coordinates otherwise, so the sign is
 * always the sign for the exact points. */
#ifndef CM_XPOINT_H
#define CM_XPOINT_H

#include "geom/predicates.h"

typedef struct cm_xpool cm_xpool;

/* NULL when out of memory. */
cm_xpool *cm_xpool_create(void);
void cm_xpool_free(cm_xpool *pool);

long cm_xpool_count(const cm_xpool *pool);
/* Forgets the points with ids >= count. */
void cm_xpool_truncate(cm_xpool *pool, long count);

/* Adds the double point (x, y), exact; returns its id, -1 out of memory. */
long cm_xpool_add(cm_xpool *pool, double x, double y);
/* Adds the intersection of line(a, b) with line(c, d), exactly. Returns
 * its id, -1 out of memory, -2 if the lines are parallel or degenerate. */
long cm_xpool_intersect(cm_xpool *pool, long a, long b, long c, long d);

/* Approximate coordinates: exact for added points, within a relative
 * 1e-15 for constructed ones. Valid until the next add. */
const double *cm_xpool_xy(const cm_xpool *pool, long id);
/* 1 if the point was added as a double (its coordinates are exact). */
int cm_xpool_is_input(const cm_xpool *pool, long id);

/* Exact sign of the orientation of (a, b, c): +1 counter-clockwise. */
int cm_xorient(cm_xpool *pool, long a, long b, long c);

/* The ids below n of a pool as the caller's own copy of their coordinates
 * (xy[2 id], added to the pool as they are; tame: every coordinate
 * cm_coords_tame). Of three such points cm_xorient takes cm_orient2d of
 * these coordinates: cm_xorient_in does that here, without a call and a
 * look-up per point, and calls cm_xorient for the others. n = 0: none. */
typedef struct {
    const double *xy;
    long n;
    int tame;
} cm_xinputs;

static inline int cm_xorient_in(const cm_xinputs *in, cm_xpool *pool, long a, long b, long c)
{
    if (a == b || b == c || a == c) return 0; /* as cm_xorient: no exact path */
    if (a < in->n && b < in->n && c < in->n) {
        const double *pa = in->xy + 2 * a, *pb = in->xy + 2 * b, *pc = in->xy + 2 * c;
        return in->tame ? cm_orient2d_tame(pa, pb, pc) : cm_orient2d(pa, pb, pc);
    }
    return cm_xorient(pool, a, b, c);
}
/* Exact sign of p[axis] - q[axis], axis 0 (x) or 1 (y). */
int cm_xcompare(cm_xpool *pool, long p, long q, int axis);

#endif
