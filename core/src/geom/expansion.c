/* Expansion arithmetic. Everything is built on Grow-Expansion: the exact
 * value of a sum or product is a sequence of doubles from Two-Sum and
 * Two-Product, and growing an expansion by them one at a time keeps it
 * nonoverlapping under any rounding tie-breaking. That costs O(m n) per
 * sum where the paper's merging sums cost O(m + n), but it rests on the
 * one theorem with the fewest preconditions, and only the rare exact stage
 * of a predicate comes here. */
#include "geom/expansion.h"

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

static int sum_signed(int elen, const double *e, int flen, const double *f,
                      double sign, double *h)
{
    int n = 0;
    for (int i = 0; i < elen; i++) h[n++] = e[i];
    for (int j = 0; j < flen; j++) n = cm_expansion_grow(n, h, sign * f[j]);
    return n;
}

int cm_expansion_sum(int elen, const double *e, int flen, const double *f,
                     double *h)
{
    return sum_signed(elen, e, flen, f, 1.0, h);
}

int cm_expansion_diff(int elen, const double *e, int flen, const double *f,
                      double *h)
{
    return sum_signed(elen, e, flen, f, -1.0, h);
}

int cm_expansion_add_product(int n, double *h, int elen, const double *e,
                             int flen, const double *f, double sign)
{
    for (int i = 0; i < elen; i++)
        for (int j = 0; j < flen; j++) {
            double hi, lo;
            cm_two_product(e[i], sign * f[j], &hi, &lo);
            n = cm_expansion_grow(n, h, lo);
            n = cm_expansion_grow(n, h, hi);
        }
    return n;
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
