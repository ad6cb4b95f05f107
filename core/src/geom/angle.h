/* Triangle angles, the one place they are computed: the remesher's
 * quality keys, the reports' statistics and the morph's frames all agree. */
#ifndef CM_GEOM_ANGLE_H
#define CM_GEOM_ANGLE_H

#define CM_PI 3.14159265358979323846

/* The angle at p of triangle pqr (radians), by atan2(|cross|, dot):
 * accurate for slivers. */
double cm_angle_at(const double p[2], const double q[2], const double r[2]);
/* Smallest angle (radians) of triangle abc, the one opposite the shortest
 * edge; 0 for a degenerate one. */
double cm_triangle_min_angle(const double a[2], const double b[2], const double c[2]);
/* Largest angle (radians) of triangle abc. */
double cm_triangle_max_angle(const double a[2], const double b[2], const double c[2]);
/* sin^2 of the smallest angle of triangle abc: cheaper, same order. */
double cm_triangle_min_angle_sin2(const double a[2], const double b[2], const double c[2]);

#endif
