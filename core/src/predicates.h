/* Exact geometric predicates on double coordinates.
 * Each evaluates in floating point with a forward error bound and falls back
 * to exact rational arithmetic (GMP) only when the bound cannot decide, so
 * the sign returned is always the sign of the exact real expression. */
#ifndef CM_PREDICATES_H
#define CM_PREDICATES_H

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

#endif
