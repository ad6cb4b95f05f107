/* Exact geometric predicates on double coordinates.
 * Each evaluates in floating point with a forward error bound and falls back
 * to exact rational arithmetic (GMP) only when the bound cannot decide, so
 * the sign returned is always the sign of the exact real expression. */
#ifndef CM_PREDICATES_H
#define CM_PREDICATES_H

/* Unit roundoff of IEEE double with round-to-nearest. */
#define CM_EPS 0x1p-53

/* +1 if a, b, c turn counter-clockwise, -1 clockwise, 0 collinear. */
int cm_orient2d(const double a[2], const double b[2], const double c[2]);

/* +1 if d lies strictly inside the circle through a, b, c (given
 * counter-clockwise), -1 outside, 0 on it. */
int cm_incircle(const double a[2], const double b[2], const double c[2],
                const double d[2]);

/* Closed segments ab and cd: 0 disjoint, 1 proper crossing (one interior
 * point, not an endpoint of either), 2 any other contact (an endpoint on the
 * other segment, or collinear overlap). */
int cm_segments_intersect(const double a[2], const double b[2],
                          const double c[2], const double d[2]);

/* Sign of the signed area of the closed polygon xy[0..n-1] (exact). */
int cm_polygon_orientation(const double *xy, long n);

/* +1 if d lies above the plane through a, b, c (a, b, c counter-clockwise
 * seen from above, i.e. det[b - a, c - a, d - a] > 0), -1 below, 0 on it. */
int cm_orient3d(const double a[3], const double b[3], const double c[3], const double d[3]);

/* 1 if triangle (a(s), b(s), c(s)), p(s) = (1 - s) p0 + s p1, is strictly
 * counter-clockwise for every s in [0, 1] (its doubled area is a quadratic
 * in s; decided exactly), else 0. */
int cm_blend_positive(const double a0[2], const double b0[2], const double c0[2],
                      const double a1[2], const double b1[2], const double c1[2]);

/* (x, then y) order of points: along a line, the order of the points on it. */
static inline int cm_point_less(const double a[2], const double b[2])
{
    return a[0] < b[0] || (a[0] == b[0] && a[1] < b[1]);
}

#endif
