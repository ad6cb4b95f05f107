/* The conformal correspondence (conformal.h). The measurements behind its
 * choices (the power, the automorphism's criterion) are in
 * bench/CORRESPONDENCE.md. */
#include "correspond/conformal.h"

#include <complex.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "correspond/arclength.h"
#include "correspond/fe.h"

#define PI 3.14159265358979323846
/* The mesh of each polygon is split into four until it has this many
 * triangles. */
#define MIN_TRIANGLES 4000
/* Samples of sigma along polygon 0: for the automorphism search, and for
 * the correspondence it gives. */
#define SEARCH_SAMPLES 512
#define SAMPLES 2048
/* The search: starting rotations, and Nelder-Mead's iterations and
 * tolerances (on the parameters and on the criterion). */
#define ROTATIONS 16
#define ITERATIONS 400
#define XTOL 1e-4
#define FTOL 1e-7
/* Stretches below this are taken as this (doubles resolve no less). */
#define STRETCH_FLOOR 1e-12

/* A polygon's boundary on the unit circle: per boundary node of its mesh
 * (counter-clockwise from vertex 0), the normalised arc length s and the
 * angle theta, both non-decreasing; s[nb] = 1, theta[nb] = 2 pi. */
typedef struct disk {
    size_t nb;
    double *s, *theta;
} disk;

static void disk_free(disk *d)
{
    free(d->s), free(d->theta);
    memset(d, 0, sizeof *d);
}

static cm_status disk_build(const double *input, size_t n, int reversed, disk *d, int *usable, cm_error *err)
{
    memset(d, 0, sizeof *d);
    cm_fe_mesh m;
    memset(&m, 0, sizeof m);
    double *xy = malloc(2 * n * sizeof *xy), *w = NULL;
    cm_status s = xy ? CM_OK : cm_fail_status(err, CM_ERR_NO_MEMORY);
    for (size_t c = 0; s == CM_OK && c < n; c++) {
        const double *p = input + 2 * cm_ccw_input(c, n, reversed);
        xy[2 * c] = p[0], xy[2 * c + 1] = p[1];
    }
    if (s == CM_OK) s = cm_fe_build(&m, xy, NULL, n, MIN_TRIANGLES, usable, err);
    long sample[CM_FE_SAMPLE], ns = s == CM_OK && *usable ? cm_fe_sample_interior(&m, sample) : 0;
    if (s == CM_OK && ns == 0) *usable = 0;
    if (s == CM_OK && *usable) {
        size_t nb = (size_t)m.nb;
        d->nb = nb;
        d->s = malloc((nb + 1) * sizeof *d->s);
        d->theta = malloc((nb + 1) * sizeof *d->theta);
        w = malloc(nb * sizeof *w);
        if (!d->s || !d->theta || !w) s = cm_fail_status(err, CM_ERR_NO_MEMORY);
        if (s == CM_OK) s = cm_fe_harmonic_measure(&m, cm_fe_deepest(&m, n, sample, ns), 1, w, err);
        if (s == CM_OK) {
            double acc = 0, first = PI * w[0];
            d->s[0] = 0;
            for (size_t j = 0; j < nb; j++) {
                const double *p = m.xy + 2 * m.bnode[j], *q = m.xy + 2 * m.bnode[(j + 1) % nb];
                d->s[j + 1] = d->s[j] + hypot(q[0] - p[0], q[1] - p[1]);
                /* node j at the middle of its share of the measure */
                double t = 2 * PI * (acc + 0.5 * w[j]) - first;
                d->theta[j] = j ? fmax(t, d->theta[j - 1]) : 0.0;
                acc += w[j];
            }
            double total = d->s[nb];
            for (size_t j = 0; j <= nb; j++) d->s[j] /= total;
            d->s[nb] = 1.0, d->theta[nb] = 2 * PI;
        }
    }
    free(xy), free(w);
    cm_fe_free(&m);
    if (s != CM_OK || !*usable) disk_free(d);
    return s;
}

/* The largest j < len with a[j] <= x (a non-decreasing, a[0] <= x). */
static size_t below(const double *a, size_t len, double x)
{
    size_t lo = 0, hi = len;
    while (hi - lo > 1) {
        size_t mid = (lo + hi) / 2;
        if (a[mid] <= x) lo = mid;
        else hi = mid;
    }
    return lo;
}

/* y at x of the piecewise-linear table (xs, ys), len + 1 points, x in
 * [xs[0], xs[len]]. */
static double lookup(const double *xs, const double *ys, size_t len, double x)
{
    size_t j = below(xs, len, x);
    double dx = xs[j + 1] - xs[j];
    return dx > 0 ? ys[j] + (x - xs[j]) / dx * (ys[j + 1] - ys[j]) : ys[j];
}

/* The search's view of one pair: polygon 0's sample points on the circle
 * and the disk of polygon g. */
typedef struct search {
    const double complex *w0;
    size_t m;
    const disk *g;
    double *sigma; /* m: scratch, then the result */
} search;

/* sigma at the m samples under the automorphism x = (z, rho), a = z / (1 +
 * |z|) (any z is a point of the disk): polygon 0's angle, moved onto
 * polygon g's circle, read as g's arc length, lifted to increase. */
static void correspond(const search *q, const double *x)
{
    double complex z = x[0] + I * x[1], a = z / (1 + cabs(z)), turn = cexp(-I * x[2]);
    double prev = 0;
    for (size_t i = 0; i < q->m; i++) {
        double complex w = q->w0[i] * turn;
        double t = carg((w + a) / (1 + conj(a) * w));
        if (i == 0) t = t < 0 ? t + 2 * PI : t;
        else t = prev + remainder(t - prev, 2 * PI);
        prev = t;
        double turns = floor(t / (2 * PI));
        q->sigma[i] = turns + lookup(q->g->theta, q->g->s, q->g->nb, t - 2 * PI * turns);
    }
}

/* Mean square log stretch of sigma (the crowding it forces). */
static double stretch_cost(const search *q, const double *x)
{
    correspond(q, x);
    double sum = 0;
    for (size_t i = 0; i < q->m; i++) {
        double d = (i + 1 < q->m ? q->sigma[i + 1] : q->sigma[0] + 1) - q->sigma[i];
        double l = log(fmax(d, STRETCH_FLOOR) * (double)q->m);
        sum += l * l;
    }
    return sum / (double)q->m;
}

/* Nelder-Mead on stretch_cost from x (3 parameters; the simplex and
 * coefficients of scipy's default). x receives the best vertex; returns
 * its cost. */
static double nelder_mead(const search *q, double *x)
{
    enum { N = 3 };
    double p[N + 1][N], f[N + 1], c[N], r[N], e[N];
    for (int v = 0; v <= N; v++) {
        memcpy(p[v], x, sizeof p[v]);
        if (v) p[v][v - 1] = p[v][v - 1] != 0 ? 1.05 * p[v][v - 1] : 0.00025;
        f[v] = stretch_cost(q, p[v]);
    }
    for (int it = 0; it < ITERATIONS; it++) {
        /* order by cost */
        for (int v = 1; v <= N; v++)
            for (int u = v; u > 0 && f[u] < f[u - 1]; u--) {
                double t = f[u];
                f[u] = f[u - 1], f[u - 1] = t;
                for (int j = 0; j < N; j++) t = p[u][j], p[u][j] = p[u - 1][j], p[u - 1][j] = t;
            }
        double xs = 0, fs = 0;
        for (int v = 1; v <= N; v++) {
            fs = fmax(fs, fabs(f[v] - f[0]));
            for (int j = 0; j < N; j++) xs = fmax(xs, fabs(p[v][j] - p[0][j]));
        }
        if (xs <= XTOL && fs <= FTOL) break;
        for (int j = 0; j < N; j++) {
            c[j] = 0;
            for (int v = 0; v < N; v++) c[j] += p[v][j] / N;
            r[j] = 2 * c[j] - p[N][j];
        }
        double fr = stretch_cost(q, r);
        if (fr < f[0]) {
            for (int j = 0; j < N; j++) e[j] = 3 * c[j] - 2 * p[N][j];
            double fe = stretch_cost(q, e);
            if (fe < fr) memcpy(p[N], e, sizeof e), f[N] = fe;
            else memcpy(p[N], r, sizeof r), f[N] = fr;
            continue;
        }
        if (fr < f[N - 1]) {
            memcpy(p[N], r, sizeof r), f[N] = fr;
            continue;
        }
        int outside = fr < f[N];
        for (int j = 0; j < N; j++) e[j] = outside ? 1.5 * c[j] - 0.5 * p[N][j] : 0.5 * c[j] + 0.5 * p[N][j];
        double fc = stretch_cost(q, e);
        if (outside ? fc <= fr : fc < f[N]) {
            memcpy(p[N], e, sizeof e), f[N] = fc;
            continue;
        }
        for (int v = 1; v <= N; v++) { /* shrink towards the best */
            for (int j = 0; j < N; j++) p[v][j] = p[0][j] + 0.5 * (p[v][j] - p[0][j]);
            f[v] = stretch_cost(q, p[v]);
        }
    }
    int best = 0;
    for (int v = 1; v <= N; v++)
        if (f[v] < f[best]) best = v;
    memcpy(x, p[best], sizeof p[best]);
    return f[best];
}

/* Polygon 0's m sample points (evenly spaced by arc length) on its circle. */
static void circle_samples(const disk *d0, size_t m, double complex *w0)
{
    for (size_t i = 0; i < m; i++) w0[i] = cexp(I * lookup(d0->s, d0->theta, d0->nb, (double)i / (double)m));
}

/* params of polygon g: its vertices' places on polygon 0 under sigma
 * (SAMPLES values along polygon 0, lifted, increasing) tempered to the
 * power CM_CONFORMAL_POWER. */
static cm_status place(const double *xy, size_t n, int reversed, double *sigma, double *params, cm_error *err)
{
    const size_t m = SAMPLES;
    double *cum = malloc((m + 1) * sizeof *cum), *arc = cm_arc_lengths(xy, n, reversed, 0);
    if (!cum || !arc) {
        free(cum), free(arc);
        return cm_fail_status(err, CM_ERR_NO_MEMORY);
    }
    cum[0] = 0;
    for (size_t i = 0; i < m; i++) {
        double d = (i + 1 < m ? sigma[i + 1] : sigma[0] + 1) - sigma[i];
        cum[i + 1] = cum[i] + pow(fmax(d * (double)m, STRETCH_FLOOR), CM_CONFORMAL_POWER);
    }
    double offset = 0, total = cum[m];
    for (size_t i = 0; i <= m; i++) cum[i] /= total;
    for (size_t i = 0; i < m; i++) offset += (sigma[i] - cum[i]) / (double)m;
    for (size_t i = 0; i <= m; i++) cum[i] += offset; /* tempered sigma, cum[m] = cum[0] + 1 */
    for (size_t c = 0; c < n; c++) {
        double s = arc[c] / arc[n];
        s -= floor(s - cum[0]); /* lifted into [cum[0], cum[0] + 1) */
        size_t i = below(cum, m, s);
        double u = ((double)i + (s - cum[i]) / (cum[i + 1] - cum[i])) / (double)m;
        params[c] = u < 1.0 ? u : nextafter(1.0, 0.0);
    }
    free(cum), free(arc);
    return CM_OK;
}

cm_status cm_correspond_conformal(const double *const *polygons, const size_t *counts, size_t k,
                                  const int *orientation, double *const *params, int *found, cm_error *err)
{
    *found = 0;
    disk *disks = calloc(k, sizeof *disks);
    double complex *w0 = malloc(SAMPLES * sizeof *w0);
    double *sigma = malloc(SAMPLES * sizeof *sigma);
    cm_status s = disks && w0 && sigma ? CM_OK : cm_fail_status(err, CM_ERR_NO_MEMORY);
    int usable = 1;
    for (size_t g = 0; s == CM_OK && usable && g < k; g++)
        s = disk_build(polygons[g], counts[g], orientation[g] < 0, &disks[g], &usable, err);
    if (s == CM_OK && usable) {
        double *arc = cm_arc_lengths(polygons[0], counts[0], orientation[0] < 0, 0);
        if (!arc) s = cm_fail_status(err, CM_ERR_NO_MEMORY);
        for (size_t c = 0; arc && c < counts[0]; c++) params[0][c] = arc[c] / arc[counts[0]];
        free(arc);
    }
    for (size_t g = 1; s == CM_OK && usable && g < k; g++) {
        search coarse = {w0, SEARCH_SAMPLES, &disks[g], sigma};
        circle_samples(&disks[0], SEARCH_SAMPLES, w0);
        double best[3] = {0, 0, 0}, best_cost = HUGE_VAL;
        for (int r = 0; r < ROTATIONS; r++) {
            double x[3] = {0, 0, 2 * PI * r / ROTATIONS};
            double cost = nelder_mead(&coarse, x);
            if (cost < best_cost) best_cost = cost, memcpy(best, x, sizeof best);
        }
        search fine = {w0, SAMPLES, &disks[g], sigma};
        circle_samples(&disks[0], SAMPLES, w0);
        correspond(&fine, best);
        s = place(polygons[g], counts[g], orientation[g] < 0, sigma, params[g], err);
    }
    if (s == CM_OK) *found = usable;
    for (size_t g = 0; disks && g < k; g++) disk_free(&disks[g]);
    free(disks), free(w0), free(sigma);
    return s;
}
