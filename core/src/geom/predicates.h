/* Exact geometric predicates on double coordinates.
 * Each evaluates in floating point with a forward error bound and falls back
 * to exact rational arithmetic (GMP) only when the bound cannot decide, so
 * the sign returned is always the sign of the exact real expression. */
#ifndef CM_PREDICATES_H
#define CM_PREDICATES_H

#include <float.h>
#include <math.h>

/* Unit roundoff of IEEE double with round-to-nearest. */
#define CM_EPS 0x1p-53

/* Bounds on the magnitude of orient2d's differences: 0 or within these,
 * products are 0 or within 2^[-1000, 1000], so nothing overflows or
 * underflows. */
#define CM_ORIENT_MIN 0x1p-500
#define CM_ORIENT_MAX 0x1p+500

/* True if v is zero or min <= |v| <= max (false for NaN and infinity). */
static inline int cm_magnitude_within(double v, double min, double max)
{
    double m = fabs(v);
    return m == 0.0 || (m >= min && m <= max);
}

/* Shewchuk's bound A on the differences: the sign, or 2 when it cannot
 * decide. Valid when each difference is 0 or within CM_ORIENT_MIN..MAX. */
static inline int cm_orient2d_bound_a(double acx, double bcx, double acy, double bcy)
{
#ifdef __clang__
#pragma STDC FP_CONTRACT OFF
#endif
    double detleft = acx * bcy, detright = acy * bcx, det = detleft - detright;
    double errbound = (3.0 + 16.0 * CM_EPS) * CM_EPS * (fabs(detleft) + fabs(detright));
    if (fabs(det) > errbound) return (det > 0.0) - (det < 0.0);
    return 2;
}

/* cm_orient2d's floating-point filter (Shewchuk's bound A): the sign, or
 * 2 when the bound cannot decide. Its error bound counts one rounding per
 * operation: it is only inline where no compiler may fuse a*b - c*d (see
 * CM_ORIENT2D_INLINE), else it runs inside predicates.c. */
static inline int cm_orient2d_filter(const double a[2], const double b[2], const double c[2])
{
#ifdef __clang__
#pragma STDC FP_CONTRACT OFF
#endif
    double acx = a[0] - c[0], bcx = b[0] - c[0], acy = a[1] - c[1], bcy = b[1] - c[1];
    if (cm_magnitude_within(acx, CM_ORIENT_MIN, CM_ORIENT_MAX) &&
        cm_magnitude_within(bcx, CM_ORIENT_MIN, CM_ORIENT_MAX) &&
        cm_magnitude_within(acy, CM_ORIENT_MIN, CM_ORIENT_MAX) &&
        cm_magnitude_within(bcy, CM_ORIENT_MIN, CM_ORIENT_MAX))
        return cm_orient2d_bound_a(acx, bcx, acy, bcy);
    return 2;
}

/* Coordinates each 0 or within 2^[-400, 400] ("tame"): all are multiples
 * of 2^-452, so a nonzero difference of two, rounded or not, lies within
 * 2^[-452, 401], inside the filter's bounds: for points all tame the
 * filter need not check its differences (cm_orient2d_tame). */
#define CM_TAME_MIN 0x1p-400
#define CM_TAME_MAX 0x1p+400

static inline int cm_coords_tame(const double *v, long count)
{
    for (long i = 0; i < count; i++)
        if (!cm_magnitude_within(v[i], CM_TAME_MIN, CM_TAME_MAX)) return 0;
    return 1;
}

/* The stages after the filter (any input; exact). */
int cm_orient2d_adaptive(const double a[2], const double b[2], const double c[2]);
/* Filter and stages, compiled in predicates.c. */
int cm_orient2d_compiled(const double a[2], const double b[2], const double c[2]);

/* The filter inline (it decides almost every call of the geometric loops)
 * only where products are rounded separately: clang (the pragma above),
 * or GCC compiling ISO C (fp-contract off), with doubles evaluated in
 * double precision. */
#if FLT_EVAL_METHOD == 0 && !defined(__cplusplus) && \
    (defined(__clang__) || (defined(__GNUC__) && defined(__STRICT_ANSI__)))
#define CM_ORIENT2D_INLINE 1
#endif

/* +1 if a, b, c turn counter-clockwise, -1 clockwise, 0 collinear. */
static inline int cm_orient2d(const double a[2], const double b[2], const double c[2])
{
#ifdef CM_ORIENT2D_INLINE
    int s = cm_orient2d_filter(a, b, c);
    return s != 2 ? s : cm_orient2d_adaptive(a, b, c);
#else
    return cm_orient2d_compiled(a, b, c);
#endif
}

/* cm_orient2d for tame points (cm_coords_tame): the same sign. */
static inline int cm_orient2d_tame(const double a[2], const double b[2], const double c[2])
{
#ifdef CM_ORIENT2D_INLINE
#ifdef __clang__
#pragma STDC FP_CONTRACT OFF
#endif
    int s = cm_orient2d_bound_a(a[0] - c[0], b[0] - c[0], a[1] - c[1], b[1] - c[1]);
    return s != 2 ? s : cm_orient2d_adaptive(a, b, c);
#else
    return cm_orient2d_compiled(a, b, c);
#endif
}

/* cm_orient2d_tame where the points are known tame, else cm_orient2d. */
static inline int cm_orient2d_either(int tame, const double a[2], const double b[2], const double c[2])
{
    return tame ? cm_orient2d_tame(a, b, c) : cm_orient2d(a, b, c);
}

/* +1 if d lies strictly inside the circle through a, b, c (given
 * counter-clockwise), -1 outside, 0 on it. */
int cm_incircle(const double a[2], const double b[2], const double c[2],
                const double d[2]);

/* Closed segments ab and cd: 0 disjoint, 1 proper crossing (one interior
 * point, not an endpoint of either), 2 any other contact (an endpoint on the
 * other segment, or collinear overlap). */
int cm_segments_intersect(const double a[2], const double b[2],
                          const double c[2], const double d[2]);
/* The same for tame points (cm_coords_tame). */
int cm_segments_intersect_tame(const double a[2], const double b[2], const double c[2], const double d[2]);

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
