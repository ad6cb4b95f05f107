#include <math.h>

#include "geom/angle.h"

double cm_angle_at(const double p[2], const double q[2], const double r[2])
{
    double ux = q[0] - p[0], uy = q[1] - p[1], vx = r[0] - p[0], vy = r[1] - p[1];
    return atan2(fabs(ux * vy - uy * vx), ux * vx + uy * vy);
}

double cm_triangle_min_angle(const double a[2], const double b[2], const double c[2])
{
    double abx = b[0] - a[0], aby = b[1] - a[1];
    double bcx = c[0] - b[0], bcy = c[1] - b[1];
    double cax = a[0] - c[0], cay = a[1] - c[1];
    double lab = abx * abx + aby * aby, lbc = bcx * bcx + bcy * bcy, lca = cax * cax + cay * cay;
    double area2 = fabs(abx * cay - aby * cax);
    double dot;
    if (lab <= lbc && lab <= lca) dot = -(cax * bcx + cay * bcy);      /* at c */
    else if (lbc <= lca) dot = -(abx * cax + aby * cay);               /* at a */
    else dot = -(bcx * abx + bcy * aby);                               /* at b */
    return atan2(area2, dot);
}

double cm_triangle_max_angle(const double a[2], const double b[2], const double c[2])
{
    return fmax(cm_angle_at(a, b, c), fmax(cm_angle_at(b, c, a), cm_angle_at(c, a, b)));
}

double cm_triangle_min_angle_sin2(const double a[2], const double b[2], const double c[2])
{
    double abx = b[0] - a[0], aby = b[1] - a[1];
    double bcx = c[0] - b[0], bcy = c[1] - b[1];
    double cax = a[0] - c[0], cay = a[1] - c[1];
    double lab = abx * abx + aby * aby, lbc = bcx * bcx + bcy * bcy, lca = cax * cax + cay * cay;
    double cross = abx * cay - aby * cax, den;
    if (lab <= lbc && lab <= lca) den = lbc * lca;
    else if (lbc <= lca) den = lab * lca;
    else den = lab * lbc;
    return den > 0 ? cross * cross / den : 0.0;
}
