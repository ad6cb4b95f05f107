/* Triangle angles. The plain double formulas square edge lengths, which
 * overflows beyond about 1e154 and underflows below 1e-154; where the sum
 * of the squared lengths leaves [2^-1000, 2^1000] the same formulas run in
 * long double (a wider exponent), so angles do not depend on the scale. */
#include <math.h>
#include <stddef.h>

#include "geom/angle.h"


static int in_safe_range(double squared_lengths)
{
    return squared_lengths > CM_ANGLE_SAFE_LO && squared_lengths < CM_ANGLE_SAFE_HI;
}

static double angle_at_wide(const double p[2], const double q[2], const double r[2])
{
    long double ux = (long double)q[0] - p[0], uy = (long double)q[1] - p[1];
    long double vx = (long double)r[0] - p[0], vy = (long double)r[1] - p[1];
    return (double)atan2l(fabsl(ux * vy - uy * vx), ux * vx + uy * vy);
}

double cm_angle_at_below(const double p[2], const double q[2], const double r[2], double bound, double tan_bound)
{
    double ux = q[0] - p[0], uy = q[1] - p[1], vx = r[0] - p[0], vy = r[1] - p[1];
    if (!in_safe_range(ux * ux + uy * uy + vx * vx + vy * vy)) return angle_at_wide(p, q, r);
    double y = fabs(ux * vy - uy * vx), x = ux * vx + uy * vy;
    /* atan2(y, x) >= bound: x <= 0 (bound below a right angle), or y / x
     * above tan(bound) by far more than atan2's and tan's rounding */
    if (bound < 0.5 * CM_PI && (x <= 0 || y > x * tan_bound * (1 + 0x1p-30))) return HUGE_VAL;
    return atan2(y, x);
}

/* Below no bound: always the atan2. */
double cm_angle_at(const double p[2], const double q[2], const double r[2]) { return cm_angle_at_below(p, q, r, CM_PI, 0); }

/* The smallest angle is the one opposite the shortest edge. */
static double min_angle_wide(const double a[2], const double b[2], const double c[2])
{
    long double abx = (long double)b[0] - a[0], aby = (long double)b[1] - a[1];
    long double bcx = (long double)c[0] - b[0], bcy = (long double)c[1] - b[1];
    long double cax = (long double)a[0] - c[0], cay = (long double)a[1] - c[1];
    long double lab = abx * abx + aby * aby, lbc = bcx * bcx + bcy * bcy, lca = cax * cax + cay * cay;
    long double area2 = fabsl(abx * cay - aby * cax), dot;
    if (lab <= lbc && lab <= lca) dot = -(cax * bcx + cay * bcy);
    else if (lbc <= lca) dot = -(abx * cax + aby * cay);
    else dot = -(bcx * abx + bcy * aby);
    return (double)atan2l(area2, dot);
}

/* The smallest angle as atan2(*area2, *dot); 0 outside the safe range
 * (the caller then takes min_angle_wide). */
static int min_angle_terms(const double a[2], const double b[2], const double c[2], double *area2, double *dot)
{
    double abx = b[0] - a[0], aby = b[1] - a[1];
    double bcx = c[0] - b[0], bcy = c[1] - b[1];
    double cax = a[0] - c[0], cay = a[1] - c[1];
    double lab = abx * abx + aby * aby, lbc = bcx * bcx + bcy * bcy, lca = cax * cax + cay * cay;
    if (!in_safe_range(lab + lbc + lca)) return 0;
    *area2 = fabs(abx * cay - aby * cax);
    if (lab <= lbc && lab <= lca) *dot = -(cax * bcx + cay * bcy);      /* at c */
    else if (lbc <= lca) *dot = -(abx * cax + aby * cay);               /* at a */
    else *dot = -(bcx * abx + bcy * aby);                               /* at b */
    return 1;
}

double cm_corner_angle(const double prev[2], const double v[2], const double next[2])
{
    double ux = next[0] - v[0], uy = next[1] - v[1], wx = prev[0] - v[0], wy = prev[1] - v[1];
    double t = atan2(ux * wy - uy * wx, ux * wx + uy * wy);
    return t < 0 ? t + 2 * CM_PI : t;
}

double cm_triangle_min_angle(const double a[2], const double b[2], const double c[2])
{
    double area2, dot;
    return min_angle_terms(a, b, c, &area2, &dot) ? atan2(area2, dot) : min_angle_wide(a, b, c);
}

double cm_triangles_min_angle(const int32_t *tri, size_t nt, const double *xy)
{
    double least = HUGE_VAL;
    for (size_t t = 0; t < nt; t++) {
        const int32_t *v = tri + 3 * t;
        least = fmin(least, cm_triangle_min_angle(xy + 2 * v[0], xy + 2 * v[1], xy + 2 * v[2]));
    }
    return least;
}

int cm_triangle_min_angle_rank(const double a[2], const double b[2], const double c[2], const double *bound,
                               const double *tan_bound, int n)
{
    double area2, dot, angle = -1.0; /* -1: the atan2 not taken yet */
    int k = 0;
    if (!min_angle_terms(a, b, c, &area2, &dot)) {
        angle = min_angle_wide(a, b, c);
        while (k < n && angle > bound[k]) k++;
        return k;
    }
    for (; k < n; k++) {
        /* The smallest angle is at most 60 degrees, so dot > 0 but for a
         * degenerate triangle; atan2 and tan are off by an ulp or two, far
         * inside the margin. */
        if (dot > 0) {
            double edge = dot * tan_bound[k];
            if (area2 > edge * (1 + 1e-9)) continue;
            if (area2 < edge * (1 - 1e-9)) break;
        }
        if (angle < 0) angle = atan2(area2, dot);
        if (!(angle > bound[k])) break;
    }
    return k;
}

int cm_triangle_min_angle_above(const double a[2], const double b[2], const double c[2], double bound,
                                double tan_bound)
{
    return cm_triangle_min_angle_rank(a, b, c, &bound, &tan_bound, 1);
}

/* The largest of the three angles as cm_angle_at computes them. When one
 * squared edge length exceeds both others by a factor 1 + 1e-6, the angle
 * opposite it exceeds both others by far more than their rounding (at
 * least about 1e-10 radians, against some 1e-15): it is that one, and the
 * other two need no atan2. */
double cm_triangle_max_angle(const double a[2], const double b[2], const double c[2])
{
    const double wider = 1.0 + 1e-6;
    double lab = (b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]);
    double lbc = (c[0] - b[0]) * (c[0] - b[0]) + (c[1] - b[1]) * (c[1] - b[1]);
    double lca = (a[0] - c[0]) * (a[0] - c[0]) + (a[1] - c[1]) * (a[1] - c[1]);
    if (in_safe_range(lab + lbc + lca)) {
        if (lab > wider * lbc && lab > wider * lca) return cm_angle_at(c, a, b);
        if (lbc > wider * lab && lbc > wider * lca) return cm_angle_at(a, b, c);
        if (lca > wider * lab && lca > wider * lbc) return cm_angle_at(b, c, a);
    }
    return fmax(cm_angle_at(a, b, c), fmax(cm_angle_at(b, c, a), cm_angle_at(c, a, b)));
}

int cm_triangle_max_angle_below(const double a[2], const double b[2], const double c[2], double bound,
                                double cos_bound)
{
    const double wider = 1.0 + 1e-6;
    double lab = (b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]);
    double lbc = (c[0] - b[0]) * (c[0] - b[0]) + (c[1] - b[1]) * (c[1] - b[1]);
    double lca = (a[0] - c[0]) * (a[0] - c[0]) + (a[1] - c[1]) * (a[1] - c[1]);
    const double *p = NULL, *q = NULL, *r = NULL; /* the largest angle at p, as cm_angle_at(p, q, r) */
    if (in_safe_range(lab + lbc + lca)) {
        if (lab > wider * lbc && lab > wider * lca) p = c, q = a, r = b;
        else if (lbc > wider * lab && lbc > wider * lca) p = a, q = b, r = c;
        else if (lca > wider * lab && lca > wider * lbc) p = b, q = c, r = a;
    }
    if (p) {
        double ux = q[0] - p[0], uy = q[1] - p[1], vx = r[0] - p[0], vy = r[1] - p[1];
        double lu = ux * ux + uy * uy, lv = vx * vx + vy * vy;
        /* both sides far from underflow: the cosine of the angle atan2
         * takes is within a few ulps of 1 of dot / (|u| |v|), and angles
         * differ at least as much as their cosines */
        if (lu > 0x1p-900 && lv > 0x1p-900) {
            double cosine = (ux * vx + uy * vy) / (sqrt(lu) * sqrt(lv));
            if (cosine > cos_bound + 1e-9) return 1;
            if (cosine < cos_bound - 1e-9) return 0;
        }
    }
    return cm_triangle_max_angle(a, b, c) < bound;
}

double cm_triangle_min_angle_sin2_wide(const double a[2], const double b[2], const double c[2])
{
    double s = sin(min_angle_wide(a, b, c));
    return s * s;
}
