/* Floating-point expansions (Shewchuk, "Adaptive Precision Floating-Point
 * Arithmetic and Fast Robust Geometric Predicates", 1997): a real number
 * held exactly as the unevaluated sum of doubles e[0] + ... + e[n-1],
 * nonoverlapping and in increasing magnitude, so the last nonzero component
 * carries the sign of the sum.
 *
 * Every operation here is exact under IEEE round-to-nearest provided
 * nothing overflows and every product's exact value is a multiple of
 * 2^-1074 (its rounding error is then a double). Sums need no such
 * condition: the rounding error of a sum of doubles is always a double.
 * The callers (predicates.c) establish both conditions by scaling. */
#ifndef CM_EXPANSION_H
#define CM_EXPANSION_H

#include <float.h>
#include <math.h>

#if FLT_EVAL_METHOD != 0
#error "expansion.h needs doubles evaluated in double (e.g. -mfpmath=sse)"
#endif
#ifdef __clang__
#pragma STDC FP_CONTRACT OFF /* no fused a*b+c (GCC: off in ISO C mode) */
#endif

/* a + b = *x + *y exactly, *x = fl(a + b) (Knuth's Two-Sum). */
static inline void cm_two_sum(double a, double b, double *x, double *y)
{
    double s = a + b;
    double bpart = s - a, apart = s - bpart;
    *y = (a - apart) + (b - bpart);
    *x = s;
}

/* The error of x = fl(a - b): a - b = x + result exactly. */
static inline double cm_diff_tail(double a, double b, double x)
{
    double bpart = a - x, apart = x + bpart;
    return (a - apart) + (bpart - b);
}

/* a - b = *x + *y exactly, *x = fl(a - b). */
static inline void cm_two_diff(double a, double b, double *x, double *y)
{
    double d = a - b;
    *y = cm_diff_tail(a, b, d);
    *x = d;
}

/* a * b = *x + *y exactly, *x = fl(a b): the fused multiply-add rounds
 * a b - *x once, and that error is a double (see the top). */
static inline void cm_two_product(double a, double b, double *x, double *y)
{
    double p = a * b;
    *y = fma(a, b, -p);
    *x = p;
}

/* x[0..3] = (a1 + a0) - (b1 + b0) for two-component expansions (a0, b0 the
 * smaller components), as a four-component expansion that may hold zeros:
 * the two-component one grown by -b0, then by -b1. */
static inline void cm_two_two_diff(double a1, double a0, double b1, double b0,
                                   double x[4])
{
    double q, t1, t2, t0;
    cm_two_diff(a0, b0, &q, &t0); /* grow (a0, a1) by -b0 */
    cm_two_sum(q, a1, &t2, &t1);  /* (t0, t1, t2) */
    cm_two_diff(t0, b1, &q, &x[0]); /* grow by -b1 */
    cm_two_sum(q, t1, &q, &x[1]);
    cm_two_sum(q, t2, &x[3], &x[2]);
}

/* Sign of an expansion whose components are known nonoverlapping and
 * increasing in magnitude (zeros allowed): that of the largest nonzero. */
static inline int cm_expansion_sign_ordered(int n, const double *e)
{
    while (n > 0 && e[n - 1] == 0.0) n--;
    return n == 0 ? 0 : e[n - 1] > 0.0 ? 1 : -1;
}

/* Sign of the exact sum e[0] + ... + e[n-1], for the results of the
 * functions below. Those follow the paper's algorithms, whose outputs are
 * nonoverlapping under its stated conditions; the sign does not rest on
 * that: it takes the largest component's sign only when that component
 * provably outweighs the others, else regrows the components into an
 * expansion in place (Grow-Expansion, which keeps it nonoverlapping under
 * any tie-breaking). May rewrite e[0..n-1] as another sequence of the
 * same sum. */
int cm_expansion_sign(int n, double *e);

/* An approximation of the sum (the components added in increasing
 * magnitude, each addition rounded). */
double cm_expansion_estimate(int n, const double *e);

/* e = e + b in place, zero components dropped (Grow-Expansion, Theorem 10
 * of the paper: e nonoverlapping and increasing in magnitude, zeros
 * allowed, gives the same for the result, whatever b and the rounding's
 * tie-breaking). e holds n + 1; returns the new length. */
int cm_expansion_grow(int n, double *e, double b);

/* h = e + f and h = e - f exactly (Fast-Expansion-Sum: the components
 * merged by magnitude, Two-Sum along them), zero components dropped. h
 * holds elen + flen, distinct from e and f; returns its length. */
int cm_expansion_sum(int elen, const double *e, int flen, const double *f,
                     double *h);
int cm_expansion_diff(int elen, const double *e, int flen, const double *f,
                      double *h);

/* h = e * b exactly (Scale-Expansion), zero components dropped; h holds
 * 2 elen, distinct from e. Returns its length. */
int cm_expansion_scale(int elen, const double *e, double b, double *h);

/* h = e * f exactly: e scaled by each component of f, the results summed.
 * h holds 2 elen flen and scratch 2 elen (flen + 1), distinct from each
 * other and from e and f. Returns the length of h. */
int cm_expansion_product(int elen, const double *e, int flen, const double *f,
                         double *h, double *scratch);

/* e in place as an expansion of the same value, no longer and usually
 * much shorter (Compress: a downward then an upward pass of Two-Sum);
 * returns the new length. */
int cm_expansion_compress(int n, double *e);

/* The exact difference a - b as an expansion of one or two components
 * (none if a = b); h holds 2. */
int cm_expansion_of_diff(double a, double b, double *h);

#endif
