/* A loop on the unit circle (circle.h). */
#include "correspond/circle.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/order.h"
#include "correspond/arclength.h"
#include "geom/angle.h"

/* Stretches below this are taken as this (doubles resolve no less). */
#define STRETCH_FLOOR 1e-12

void cm_circle_free(cm_circle *d)
{
    free(d->s), free(d->theta), free(d->z);
    memset(d, 0, sizeof *d);
}

size_t cm_circle_below(const double *a, size_t len, double x)
{
    size_t lo = 0, hi = len;
    while (hi - lo > 1) {
        size_t mid = (lo + hi) / 2;
        if (a[mid] <= x) lo = mid;
        else hi = mid;
    }
    return lo;
}

size_t cm_circle_below_near(const double *a, size_t len, double x, size_t *near)
{
    size_t j = *near;
    if (j < len && a[j] <= x) {
        for (int step = 0; step < 8 && j + 1 < len && a[j + 1] <= x; step++) j++;
        if (j + 1 < len && a[j + 1] <= x) j += cm_circle_below(a + j, len - j, x);
    } else {
        j = cm_circle_below(a, len, x);
    }
    return *near = j;
}

double cm_circle_lookup_at(const double *xs, const double *ys, size_t j, double x)
{
    double dx = xs[j + 1] - xs[j];
    return dx > 0 ? ys[j] + (x - xs[j]) / dx * (ys[j + 1] - ys[j]) : ys[j];
}

double cm_circle_lookup(const double *xs, const double *ys, size_t len, double x)
{
    return cm_circle_lookup_at(xs, ys, cm_circle_below(xs, len, x), x);
}

double cm_circle_cost(const double complex *w, const double *s0, size_t m, const cm_circle *g, double rho)
{
    double prev = 0, sum = 0, sum2 = 0;
    size_t near = 0; /* the points go round: each lands at or after the last */
    for (size_t i = 0; i < m; i++) {
        double t = carg(w[i] * cexp(-I * rho));
        if (i == 0) t = t < 0 ? t + 2 * CM_PI : t;
        else t = prev + remainder(t - prev, 2 * CM_PI);
        prev = t;
        double turns = floor(t / (2 * CM_PI));
        double x = t - 2 * CM_PI * turns;
        size_t j = cm_circle_below_near(g->theta, g->nb, x, &near);
        double d = turns + cm_circle_lookup_at(g->theta, g->s, j, x) - s0[i];
        sum += d, sum2 += d * d;
    }
    double mean = sum / (double)m;
    return sum2 / (double)m - mean * mean;
}

double cm_circle_golden_least(double (*f)(const void *ctx, double x), const void *ctx, double lo, double hi, int steps,
                              double *least)
{
    const double golden = 0.5 * (sqrt(5.0) - 1);
    double x1 = hi - golden * (hi - lo), x2 = lo + golden * (hi - lo), f1 = f(ctx, x1), f2 = f(ctx, x2);
    for (int it = 0; it < steps; it++) {
        if (f1 < f2) hi = x2, x2 = x1, f2 = f1, x1 = hi - golden * (hi - lo), f1 = f(ctx, x1);
        else lo = x1, x1 = x2, f1 = f2, x2 = lo + golden * (hi - lo), f2 = f(ctx, x2);
    }
    *least = fmin(f1, f2);
    return f1 < f2 ? x1 : x2;
}

/* The tempered parameter of a loop's boundary nodes (nb + 1 values from 0
 * to 1), as circle.h says. */
static void tempered(const cm_circle *d, const double *theta, double power, double *p)
{
    p[0] = 0;
    for (size_t j = 0; j < d->nb; j++) {
        double ds = d->s[j + 1] - d->s[j], density = ds > 0 ? (theta[j + 1] - theta[j]) / (2 * CM_PI * ds) : 1.0;
        p[j + 1] = p[j] + pow(fmax(density, STRETCH_FLOOR), power) * ds;
    }
    double total = p[d->nb];
    for (size_t j = 0; j <= d->nb; j++) p[j] /= total;
    p[d->nb] = 1.0;
}

/* Where tempered parameter q (modulo 1) lands on polygon 0 (p0: its
 * tempered parameter per node), as a share of its perimeter below 1. */
static double on_polygon0(const cm_circle *d0, const double *p0, double q)
{
    q -= floor(q);
    double u = cm_circle_lookup(p0, d0->s, d0->nb, q);
    return u < 1.0 ? u : nextafter(1.0, 0.0);
}

cm_status cm_circle_place(const cm_circle *d0, const cm_circle *dg, double rho, size_t n, double power,
                          double *params, double *fine, cm_error *err)
{
    size_t nb = dg->nb, levels = nb / n;
    double *theta = malloc((nb + 1) * sizeof *theta), *p0 = malloc((d0->nb + 1) * sizeof *p0);
    double *pg = malloc((nb + 1) * sizeof *pg);
    if (!theta || !p0 || !pg) {
        free(theta), free(p0), free(pg);
        return cm_fail_status(err, CM_ERR_NO_MEMORY);
    }
    /* g's nodes on polygon 0's circle */
    for (size_t j = 0; j <= nb; j++) theta[j] = dg->theta[j] + rho;
    tempered(d0, d0->theta, power, p0);
    tempered(dg, theta, power, pg);
    /* g's vertex 0 lands at polygon 0's tempered parameter `from`: the
     * median over g's nodes of where each lands less its own parameter
     * (one node alone may sit in a crowded stretch whose angles doubles
     * cannot tell apart) */
    double *offset = theta; /* reused: nb values */
    double base = 0;
    for (size_t j = 0; j < nb; j++) {
        double t = theta[j] - 2 * CM_PI * floor(theta[j] / (2 * CM_PI));
        double o = cm_circle_lookup(d0->s, p0, d0->nb, cm_circle_lookup(d0->theta, d0->s, d0->nb, t)) - pg[j];
        if (j == 0) base = o;
        offset[j] = remainder(o - base, 1.0);
    }
    qsort(offset, nb, sizeof *offset, cm_compare_doubles);
    double from = base + offset[nb / 2];
    for (size_t c = 0; c < n; c++) {
        params[c] = on_polygon0(d0, p0, from + pg[c * levels]);
        /* between the vertices: g's nodes are evenly spaced along its
         * edges (levels of them per edge), read at CM_PARAM_FINE points */
        for (size_t l = 0; fine && l < CM_PARAM_FINE; l++) {
            double at = (double)(c * levels) + (double)(l * levels) / CM_PARAM_FINE;
            size_t j = (size_t)at;
            double f = at - (double)j, pj = j < nb ? pg[j] + f * (pg[j + 1] - pg[j]) : pg[nb];
            fine[c * CM_PARAM_FINE + l] = l == 0 ? params[c] : on_polygon0(d0, p0, from + pj);
        }
    }
    free(theta), free(p0), free(pg);
    return CM_OK;
}

double complex cm_circle_point_at(const cm_circle *d, double u)
{
    size_t j = cm_circle_below(d->s, d->nb, u);
    double ds = d->s[j + 1] - d->s[j], f = ds > 0 ? (u - d->s[j]) / ds : 0;
    return d->z[j] + f * (d->z[j + 1] - d->z[j]);
}

void cm_circle_plane_fit(const double complex *w, const double complex *z0, size_t m, const cm_circle *g,
                         double rho, double complex *a, double complex *centre)
{
    double complex zg[CM_CIRCLE_FIT_MAX], mean = 0, corr = 0;
    double zz = 0;
    size_t near = 0;
    if (m > CM_CIRCLE_FIT_MAX) m = CM_CIRCLE_FIT_MAX;
    for (size_t i = 0; i < m; i++) { /* g's arc length at w[i], its circle turned by rho */
        double t = carg(w[i] * cexp(-I * rho));
        t -= 2 * CM_PI * floor(t / (2 * CM_PI));
        double u = cm_circle_lookup_at(g->theta, g->s, cm_circle_below_near(g->theta, g->nb, t, &near), t);
        mean += zg[i] = cm_circle_point_at(g, u);
    }
    mean /= (double)m;
    for (size_t i = 0; i < m; i++) corr += conj(z0[i]) * (zg[i] - mean), zz += creal(z0[i] * conj(z0[i]));
    *a = zz > 0 ? corr / zz : 1, *centre = mean;
}
