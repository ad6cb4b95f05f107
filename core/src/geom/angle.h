/* Triangle angles, the one place they are computed: the remesher's
 * quality keys, the reports' statistics and the morph's frames all agree. */
#ifndef CM_GEOM_ANGLE_H
#define CM_GEOM_ANGLE_H

#include <stddef.h>
#include <stdint.h>

#define CM_PI 3.14159265358979323846

/* The angle at p of triangle pqr (radians), by atan2(|cross|, dot):
 * accurate for slivers. */
double cm_angle_at(const double p[2], const double q[2], const double r[2]);
/* cm_angle_at(p, q, r) where that is below bound (< pi / 2), else any
 * value >= bound (HUGE_VAL), decided from the very products cm_angle_at
 * gives atan2 (tan_bound = tan(bound)): the atan2 only where the angle may
 * be below bound. */
double cm_angle_at_below(const double p[2], const double q[2], const double r[2], double bound, double tan_bound);
/* The corner of a boundary at v between its neighbours prev and next,
 * the material to the left of prev -> v -> next: radians in [0, 2 pi). */
double cm_corner_angle(const double prev[2], const double v[2], const double next[2]);
/* Smallest angle (radians) of triangle abc, the one opposite the shortest
 * edge; 0 for a degenerate one. */
double cm_triangle_min_angle(const double a[2], const double b[2], const double c[2]);
/* Smallest angle (radians) of the nt triangles tri (three vertex indices
 * each) at the positions xy (x, y per vertex); HUGE_VAL when nt is 0. */
double cm_triangles_min_angle(const int32_t *tri, size_t nt, const double *xy);
/* 1 when cm_triangle_min_angle(a, b, c) > bound, exactly as that
 * comparison, for bound in [0, pi/2) and tan_bound = tan(bound): the
 * tangents decide without the atan2 unless they are within rounding of
 * each other. */
int cm_triangle_min_angle_above(const double a[2], const double b[2], const double c[2], double bound,
                                double tan_bound);
/* How many of bound[0..n) (ascending, each as for
 * cm_triangle_min_angle_above) cm_triangle_min_angle(a, b, c) is above,
 * exactly as those comparisons: one atan2 at most. */
int cm_triangle_min_angle_rank(const double a[2], const double b[2], const double c[2], const double *bound,
                               const double *tan_bound, int n);
/* Largest angle (radians) of triangle abc. */
double cm_triangle_max_angle(const double a[2], const double b[2], const double c[2]);
/* 1 when cm_triangle_max_angle(a, b, c) < bound, exactly as that
 * comparison, for cos_bound = cos(bound): the cosines decide without the
 * atan2 unless they are within 1e-9 of each other, or the largest angle
 * is not clear from the edges. */
int cm_triangle_max_angle_below(const double a[2], const double b[2], const double c[2], double bound,
                                double cos_bound);
/* Squared lengths inside [2^-1000, 2^1000] neither overflow nor underflow
 * in the plain formulas; outside, long double takes over. */
#define CM_ANGLE_SAFE_LO 0x1p-1000
#define CM_ANGLE_SAFE_HI 0x1p1000

double cm_triangle_min_angle_sin2_wide(const double a[2], const double b[2], const double c[2]);

/* The product of the two largest of a triangle's three squared side
 * lengths: the largest of the three products (rounding is monotone), the
 * same bits as picking the pair by comparisons, without those branches
 * (data-dependent, so mispredicted: most of the position search's time). */
static inline double cm_sin2_den(double lab, double lbc, double lca)
{
    double a = lab * lbc, b = lab * lca, c = lbc * lca;
    a = a > b ? a : b;
    return a > c ? a : c;
}

/* sin^2 of the smallest angle of triangle abc: cheaper, same order. Inline:
 * the smoothing's position searches call it for every trial point. */
static inline double cm_triangle_min_angle_sin2(const double a[2], const double b[2],
                                                const double c[2])
{
    double abx = b[0] - a[0], aby = b[1] - a[1];
    double bcx = c[0] - b[0], bcy = c[1] - b[1];
    double cax = a[0] - c[0], cay = a[1] - c[1];
    double lab = abx * abx + aby * aby, lbc = bcx * bcx + bcy * bcy, lca = cax * cax + cay * cay;
    double cross = abx * cay - aby * cax, den = cm_sin2_den(lab, lbc, lca);
    /* den, the product of the two longest squared lengths, bounds cross^2:
     * in range, nothing above overflowed. */
    if (!(den > CM_ANGLE_SAFE_LO && den < CM_ANGLE_SAFE_HI) && den != 0)
        return cm_triangle_min_angle_sin2_wide(a, b, c);
    return den > 0 ? cross * cross / den : 0.0;
}

#endif
