/* The start of every polygon's arc length, chosen by Procrustes alignment:
 * with z_j the points of polygon 0 and w_j those of polygon g (both M
 * points evenly spaced by arc length, counter-clockwise, centred), the best
 * similarity w ~ a z (a complex) leaves |w|^2 - |<z, w>|^2 / |z|^2; the start
 * with the smallest share of |w|^2 left is taken. A start that sends every
 * point near its counterpart up to a similarity leaves the map between the
 * polygons little to distort, which is what the meshes' angles need. */
#include <complex.h>
#include <math.h>
#include <stdlib.h>

#include "correspond/choose.h"
#include "correspond/arclength.h"

#define SAMPLES 64
#define COARSE_CANDIDATES 256

/* SAMPLES points evenly spaced by arc length from counter-clockwise vertex
 * start, centred. arc: cumulative lengths along the counter-clockwise
 * order from vertex 0 (n + 1 entries). */
static void sample(const double *xy, size_t n, int reversed, const double *arc, size_t start,
                   double complex *out)
{
    double total = arc[n];
    double complex mean = 0;
    for (int j = 0; j < SAMPLES; j++) {
        double s = fmod(arc[start] + total * j / SAMPLES, total);
        size_t lo = 0, hi = n; /* the edge c -> c + 1 with arc[c] <= s < arc[c + 1] */
        while (hi - lo > 1) {
            size_t mid = (lo + hi) / 2;
            if (arc[mid] <= s) lo = mid;
            else hi = mid;
        }
        const double *a = xy + 2 * cm_ccw_input(lo, n, reversed), *b = xy + 2 * cm_ccw_input((lo + 1) % n, n, reversed);
        double length = arc[lo + 1] - arc[lo], t = length > 0 ? (s - arc[lo]) / length : 0;
        out[j] = (a[0] + t * (b[0] - a[0])) + I * (a[1] + t * (b[1] - a[1]));
        mean += out[j];
    }
    mean /= SAMPLES;
    for (int j = 0; j < SAMPLES; j++) out[j] -= mean;
}

/* The share of |w|^2 the best similarity image of z leaves. */
static double residual(const double complex *z, const double complex *w)
{
    double complex zw = 0;
    double zz = 0, ww = 0;
    for (int j = 0; j < SAMPLES; j++) zw += conj(z[j]) * w[j], zz += creal(z[j] * conj(z[j])), ww += creal(w[j] * conj(w[j]));
    if (!(zz > 0) || !(ww > 0)) return HUGE_VAL;
    double left = ww - creal(zw * conj(zw)) / zz;
    return left / ww;
}

cm_status cm_correspond_choose_starts(const double *const *polygons, const size_t *counts, size_t k,
                                      const int *orientation, size_t *pins, cm_error *err)
{
    double complex z[SAMPLES], w[SAMPLES];
    double *arc0 = cm_arc_lengths(polygons[0], counts[0], orientation[0] < 0, 0);
    if (!arc0) return cm_fail_status(err, CM_ERR_NO_MEMORY);
    sample(polygons[0], counts[0], orientation[0] < 0, arc0, 0, z);
    pins[0] = cm_ccw_input(0, counts[0], orientation[0] < 0);
    free(arc0);
    for (size_t g = 1; g < k; g++) {
        size_t n = counts[g];
        int reversed = orientation[g] < 0;
        double *arc = cm_arc_lengths(polygons[g], n, reversed, 0);
        if (!arc) return cm_fail_status(err, CM_ERR_NO_MEMORY);
        /* Coarse: every vertex, or COARSE_CANDIDATES of them; then the
         * neighbourhood of the best. */
        size_t stride = n > COARSE_CANDIDATES ? n / COARSE_CANDIDATES : 1, best = 0;
        double best_left = HUGE_VAL;
        for (size_t c = 0; c < n; c += stride) {
            sample(polygons[g], n, reversed, arc, c, w);
            double left = residual(z, w);
            if (left < best_left) best_left = left, best = c;
        }
        size_t centre = best;
        for (size_t d = 1; stride > 1 && d < stride; d++)
            for (int side = -1; side <= 1; side += 2) {
                size_t c = (centre + n + (size_t)side * d) % n;
                sample(polygons[g], n, reversed, arc, c, w);
                double left = residual(z, w);
                if (left < best_left) best_left = left, best = c;
            }
        pins[g] = cm_ccw_input(best, n, reversed);
        free(arc);
    }
    return CM_OK;
}
