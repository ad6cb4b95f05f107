/* A loop's boundary on the unit circle, as the conformal correspondences
 * (conformal.c: a polygon onto the disk; annulus.c: a polygon with one
 * hole onto a round annulus, each loop onto one of its circles) give it,
 * and what they share: how far two loops' arc lengths are apart under a
 * turn, and the tempered parameter that pairs them. */
#ifndef CM_CORRESPOND_CIRCLE_H
#define CM_CORRESPOND_CIRCLE_H

#include <complex.h>
#include <stddef.h>

#include "base/error.h"

/* Per boundary node of a loop's mesh (counter-clockwise from the loop's
 * vertex 0), the normalised arc length s and the angle theta, both
 * non-decreasing; s[nb] = 1, theta[nb] = 2 pi; and the node's place in the
 * plane, z[nb] = z[0]. */
typedef struct cm_circle {
    size_t nb;
    double *s, *theta;
    double complex *z;
} cm_circle;

void cm_circle_free(cm_circle *d);

/* The largest j < len with a[j] <= x (a non-decreasing, a[0] <= x). */
size_t cm_circle_below(const double *a, size_t len, double x);
/* The same, sought from *near on (that j, found again when x moves
 * little: it is unique), which becomes the j found. */
size_t cm_circle_below_near(const double *a, size_t len, double x, size_t *near);
/* y at j, x of the piecewise-linear table (xs, ys), j below x. */
double cm_circle_lookup_at(const double *xs, const double *ys, size_t j, double x);
/* y at x of the piecewise-linear table (xs, ys), len + 1 points, x in
 * [xs[0], xs[len]]. */
double cm_circle_lookup(const double *xs, const double *ys, size_t len, double x);

/* How far the correspondence is from arc length with loop g turned by rho
 * onto loop 0: the variance, over the m points w of the circle (loop 0's
 * arc length there: s0), of loop g's arc length less loop 0's at the same
 * point (lifted). Zero for a similar copy turned right. */
double cm_circle_cost(const double complex *w, const double *s0, size_t m, const cm_circle *g, double rho);

/* Turns whose costs' square roots (the arc lengths' spread, a share of
 * the perimeter) lie within this of the least one's fit alike: a turn
 * search chooses among them by the turn of the plane. */
#define CM_CIRCLE_TURN_TIE 1e-4

#define CM_CIRCLE_FIT_MAX 512

/* The point at normalised arc length u of the loop. */
double complex cm_circle_point_at(const cm_circle *d, double u);

/* The similarity of the plane closest to a correspondence: loop 0's m
 * (at most CM_CIRCLE_FIT_MAX) points z0 (centred), at the points w of its circle, times *a plus
 * *centre nearest, in least squares, loop g's points at the same points
 * of its circle turned by rho. */
void cm_circle_plane_fit(const double complex *w, const double complex *z0, size_t m, const cm_circle *g,
                         double rho, double complex *a, double complex *centre);

/* The golden-section search, steps steps, for the least of f(ctx, x)
 * within [lo, hi]: the x found, *least its value. */
double cm_circle_golden_least(double (*f)(const void *ctx, double x), const void *ctx, double lo, double hi, int steps,
                              double *least);

/* params of loop g (n vertices, counter-clockwise positions): where its
 * vertices sit on loop 0 (a share of its perimeter from its vertex 0) when
 * both are read by their tempered parameters, the running integral of (d
 * theta / d s)^power over arc length, normalised (a part the map crowds by
 * e^-x is crowded by e^-(power x); a similar copy gets the same
 * parameter), g's circle turned onto loop 0's by rho; fine (NULL, or
 * CM_PARAM_FINE per edge): the same at the points evenly spaced along
 * each edge. */
cm_status cm_circle_place(const cm_circle *d0, const cm_circle *dg, double rho, size_t n, double power,
                          double *params, double *fine, cm_error *err);

#endif
