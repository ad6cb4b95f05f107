/* Expansion arithmetic (Shewchuk 1997, sections 2.4 to 2.8). Every step is
 * a Two-Sum or a Two-Product, so every result is exactly its value,
 * whatever the order of the components; the order matters only for the
 * length of the results and for reading the sign off the largest
 * component, which cm_expansion_sign checks. */
#include "geom/expansion.h"

#include <string.h>

#include "geom/predicates.h" /* CM_EPS */

double cm_expansion_estimate(int n, const double *e)
{
    double sum = 0.0;
    for (int i = 0; i < n; i++) sum += e[i];
    return sum;
}

int cm_expansion_grow(int n, double *e, double b)
{
    /* e[k] is written after e[i] is read, k <= i: in place is safe */
    int k = 0;
    double q = b, err;
    for (int i = 0; i < n; i++) {
        cm_two_sum(q, e[i], &q, &err);
        if (err != 0.0) e[k++] = err;
    }
    if (q != 0.0) e[k++] = q;
    return k;
}

int cm_expansion_sign(int n, double *e)
{
    while (n > 0 && e[n - 1] == 0.0) n--;
    if (n == 0) return 0;
    /* The rounded sum of the n - 1 smaller magnitudes is within a factor
     * 1 + 2 n CM_EPS of the exact one (all are normal or zero in the
     * callers' range; subnormal additions are exact anyway). */
    double rest = 0.0;
    for (int i = 0; i < n - 1; i++) rest += fabs(e[i]);
    if (fabs(e[n - 1]) > rest * (1.0 + 4.0 * (double)n * CM_EPS))
        return e[n - 1] > 0.0 ? 1 : -1;
    /* regrow: after i components the expansion occupies e[0..i-1] at most,
     * so growing by e[i] (read first) overwrites nothing unread; zeros
     * after it keep the value of e[0..n-1] for the caller */
    int k = 0;
    for (int i = 0; i < n; i++) k = cm_expansion_grow(k, e, e[i]);
    for (int i = k; i < n; i++) e[i] = 0.0;
    return cm_expansion_sign_ordered(k, e);
}

/* h = e + sign * f (sign +1 or -1), merging by magnitude. */
static int merge_sum(int elen, const double *e, int flen, const double *f,
                     double sign, double *h)
{
    int i = 0, j = 0, n = 0;
    double q = 0.0, err;
    while (i < elen || j < flen) {
        double next;
        if (j == flen || (i < elen && fabs(e[i]) < fabs(f[j])))
            next = e[i++];
        else
            next = sign * f[j++];
        cm_two_sum(q, next, &q, &err);
        if (err != 0.0) h[n++] = err;
    }
    if (q != 0.0) h[n++] = q;
    return n;
}

int cm_expansion_sum(int elen, const double *e, int flen, const double *f,
                     double *h)
{
    return merge_sum(elen, e, flen, f, 1.0, h);
}

int cm_expansion_diff(int elen, const double *e, int flen, const double *f,
                      double *h)
{
    return merge_sum(elen, e, flen, f, -1.0, h);
}

int cm_expansion_scale(int elen, const double *e, double b, double *h)
{
    int n = 0;
    double q = 0.0, err;
    for (int i = 0; i < elen; i++) {
        double hi, lo;
        cm_two_product(e[i], b, &hi, &lo);
        cm_two_sum(q, lo, &q, &err);
        if (err != 0.0) h[n++] = err;
        cm_two_sum(hi, q, &q, &err);
        if (err != 0.0) h[n++] = err;
    }
    if (q != 0.0) h[n++] = q;
    return n;
}

int cm_expansion_product(int elen, const double *e, int flen, const double *f,
                         double *h, double *scratch)
{
    double *term = scratch, *sum = scratch + 2 * elen;
    int n = 0;
    for (int j = 0; j < flen; j++) {
        int tn = cm_expansion_scale(elen, e, f[j], term);
        n = cm_expansion_sum(n, h, tn, term, sum);
        memcpy(h, sum, (size_t)n * sizeof *h);
    }
    return n;
}

int cm_expansion_compress(int n, double *e)
{
    if (n == 0) return 0;
    /* downward: the large parts collect at the top (e[bottom + 1 ..]);
     * e[i] is read before e[bottom] is written, bottom > i */
    int bottom = n - 1;
    double q = e[n - 1], err;
    for (int i = n - 2; i >= 0; i--) {
        cm_two_sum(q, e[i], &q, &err);
        if (err != 0.0) {
            e[bottom--] = q;
            q = err;
        }
    }
    e[bottom] = q;
    /* upward: e[top] is written after e[i] is read, top < i */
    int top = 0;
    q = e[bottom];
    for (int i = bottom + 1; i < n; i++) {
        cm_two_sum(e[i], q, &q, &err);
        if (err != 0.0) e[top++] = err;
    }
    e[top++] = q;
    return top;
}

int cm_expansion_of_diff(double a, double b, double *h)
{
    double x, y;
    int n = 0;
    cm_two_diff(a, b, &x, &y);
    if (y != 0.0) h[n++] = y;
    if (x != 0.0) h[n++] = x;
    return n;
}
