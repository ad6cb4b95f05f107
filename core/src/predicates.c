/* Filtered exact predicates.
 *
 * Each predicate first evaluates its determinant in double precision and
 * trusts the sign only if it exceeds a static forward error bound
 * (Shewchuk, "Adaptive Precision Floating-Point Arithmetic and Fast Robust
 * Geometric Predicates", 1997, the "A" bounds). Those bounds assume that no
 * operation overflows or underflows, so the filter is used only when its
 * inputs (coordinate differences; coordinates for the polygon area) lie in
 * a range that makes both impossible; otherwise, and whenever the bound
 * cannot decide, the determinant is evaluated exactly with GMP integers.
 *
 * Exact evaluation: every finite double is m * 2^e with an integer m, so
 * scaling all inputs of one call by 2^-emin (emin the smallest such e)
 * turns them into integers without changing any sign. NaN and infinity
 * have no such form; for them the predicates return 0 rather than let GMP
 * trap (callers are expected to reject them first). */
#include "predicates.h"

#include <float.h>
#include <gmp.h>
#include <math.h>

/* The error bounds count one rounding to double per operation. */
#if FLT_EVAL_METHOD != 0
#error "predicates.c needs doubles evaluated in double (e.g. -mfpmath=sse)"
#endif
#ifdef __clang__
#pragma STDC FP_CONTRACT OFF /* no fused a*b+c (GCC: off in ISO C mode) */
#endif

/* Unit roundoff of IEEE double with round-to-nearest. */
#define EPS 0x1p-53

static const double orient_errbound = (3.0 + 16.0 * EPS) * EPS;
static const double incircle_errbound = (10.0 + 96.0 * EPS) * EPS;

/* Bounds on the magnitude of the filters' inputs; see the callers. */
#define ORIENT_MIN 0x1p-500
#define ORIENT_MAX 0x1p+500
#define INCIRCLE_MIN 0x1p-200
#define INCIRCLE_MAX 0x1p+200

/* True if v is zero or min <= |v| <= max (false for NaN and infinity). */
static int magnitude_within(double v, double min, double max)
{
    double m = fabs(v);
    return m == 0.0 || (m >= min && m <= max);
}

static int all_within(const double *v, int count, double min, double max)
{
    for (int i = 0; i < count; i++)
        if (!magnitude_within(v[i], min, max)) return 0;
    return 1;
}

static int sign_of(double v)
{
    return (v > 0.0) - (v < 0.0);
}

static int all_finite(const double *v, long count)
{
    for (long i = 0; i < count; i++)
        if (!isfinite(v[i])) return 0;
    return 1;
}

/* ---- exact evaluation ------------------------------------------------ */

/* Exponent of the lowest bit v may have: v = m * 2^result, m integer. */
static long lowest_exponent(double v)
{
    int e;
    frexp(v, &e);
    return (long)e - 53;
}

/* Smallest lowest_exponent over the nonzero values (0 if none). */
static long common_exponent(const double *v, long count)
{
    long emin = 0;
    int found = 0;
    for (long i = 0; i < count; i++) {
        if (v[i] == 0.0) continue;
        long e = lowest_exponent(v[i]);
        if (!found || e < emin) emin = e;
        found = 1;
    }
    return emin;
}

/* z = v * 2^-emin, exactly (an integer since emin <= lowest_exponent(v)). */
static void set_scaled(mpz_t z, double v, long emin)
{
    if (v == 0.0) {
        mpz_set_ui(z, 0);
        return;
    }
    int e;
    double mantissa = ldexp(frexp(v, &e), 53); /* integer, |.| < 2^53 */
    mpz_set_d(z, mantissa);
    mpz_mul_2exp(z, z, (mp_bitcnt_t)((long)e - 53 - emin));
}

static int orient2d_exact(const double a[2], const double b[2],
                          const double c[2])
{
    double in[6] = {a[0], a[1], b[0], b[1], c[0], c[1]};
    if (!all_finite(in, 6)) return 0;
    long emin = common_exponent(in, 6);

    mpz_t p[6], acx, bcy, acy, bcx, det;
    for (int i = 0; i < 6; i++) {
        mpz_init(p[i]);
        set_scaled(p[i], in[i], emin);
    }
    mpz_inits(acx, bcy, acy, bcx, det, NULL);
    mpz_sub(acx, p[0], p[4]);
    mpz_sub(bcy, p[3], p[5]);
    mpz_sub(acy, p[1], p[5]);
    mpz_sub(bcx, p[2], p[4]);
    mpz_mul(det, acx, bcy);
    mpz_submul(det, acy, bcx);
    int s = mpz_sgn(det);
    mpz_clears(acx, bcy, acy, bcx, det, NULL);
    for (int i = 0; i < 6; i++) mpz_clear(p[i]);
    return s;
}

/* lift = dx^2 + dy^2 */
static void lift(mpz_t out, const mpz_t dx, const mpz_t dy)
{
    mpz_mul(out, dx, dx);
    mpz_addmul(out, dy, dy);
}

static int incircle_exact(const double a[2], const double b[2],
                          const double c[2], const double d[2])
{
    double in[8] = {a[0], a[1], b[0], b[1], c[0], c[1], d[0], d[1]};
    if (!all_finite(in, 8)) return 0;
    long emin = common_exponent(in, 8);

    /* diff[0..5] = adx, ady, bdx, bdy, cdx, cdy */
    mpz_t dcoord, diff[6], alift, blift, clift, minor, det;
    mpz_init(dcoord);
    for (int i = 0; i < 6; i++) {
        mpz_init(diff[i]);
        set_scaled(diff[i], in[i], emin);
        set_scaled(dcoord, in[6 + i % 2], emin);
        mpz_sub(diff[i], diff[i], dcoord);
    }
    mpz_inits(alift, blift, clift, minor, det, NULL);
    lift(alift, diff[0], diff[1]);
    lift(blift, diff[2], diff[3]);
    lift(clift, diff[4], diff[5]);

    mpz_mul(minor, diff[2], diff[5]); /* bdx*cdy - cdx*bdy */
    mpz_submul(minor, diff[4], diff[3]);
    mpz_mul(det, alift, minor);
    mpz_mul(minor, diff[4], diff[1]); /* cdx*ady - adx*cdy */
    mpz_submul(minor, diff[0], diff[5]);
    mpz_addmul(det, blift, minor);
    mpz_mul(minor, diff[0], diff[3]); /* adx*bdy - bdx*ady */
    mpz_submul(minor, diff[2], diff[1]);
    mpz_addmul(det, clift, minor);

    int s = mpz_sgn(det);
    mpz_clears(alift, blift, clift, minor, det, NULL);
    for (int i = 0; i < 6; i++) mpz_clear(diff[i]);
    mpz_clear(dcoord);
    return s;
}

static int polygon_orientation_exact(const double *xy, long n)
{
    if (!all_finite(xy, 2 * n)) return 0;
    long emin = common_exponent(xy, 2 * n);

    mpz_t x0, y0, x1, y1, area2;
    mpz_inits(x0, y0, x1, y1, area2, NULL);
    set_scaled(x0, xy[0], emin);
    set_scaled(y0, xy[1], emin);
    for (long i = 0; i < n; i++) {
        long j = (i + 1) % n;
        set_scaled(x1, xy[2 * j], emin);
        set_scaled(y1, xy[2 * j + 1], emin);
        mpz_addmul(area2, x0, y1);
        mpz_submul(area2, x1, y0);
        mpz_swap(x0, x1);
        mpz_swap(y0, y1);
    }
    int s = mpz_sgn(area2);
    mpz_clears(x0, y0, x1, y1, area2, NULL);
    return s;
}

/* ---- filtered predicates --------------------------------------------- */

int cm_orient2d(const double a[2], const double b[2], const double c[2])
{
    double acx = a[0] - c[0], bcx = b[0] - c[0];
    double acy = a[1] - c[1], bcy = b[1] - c[1];
    double diff[4] = {acx, bcx, acy, bcy};
    /* Differences 0 or within 2^[-500, 500]: products 0 or within
     * 2^[-1000, 1000], so nothing below overflows or underflows. */
    if (all_within(diff, 4, ORIENT_MIN, ORIENT_MAX)) {
        double detleft = acx * bcy;
        double detright = acy * bcx;
        double det = detleft - detright;
        double errbound = orient_errbound * (fabs(detleft) + fabs(detright));
        if (fabs(det) > errbound) return sign_of(det);
    }
    return orient2d_exact(a, b, c);
}

int cm_incircle(const double a[2], const double b[2], const double c[2],
                const double d[2])
{
    double adx = a[0] - d[0], bdx = b[0] - d[0], cdx = c[0] - d[0];
    double ady = a[1] - d[1], bdy = b[1] - d[1], cdy = c[1] - d[1];
    double diff[6] = {adx, bdx, cdx, ady, bdy, cdy};
    /* Differences 0 or within 2^[-200, 200]: two-factor products are 0 or
     * within 2^[-400, 400], hence multiples of 2^-452, so their differences
     * are 0 or at least 2^-452; times a lift (0 or within 2^[-400, 401])
     * that stays within 2^[-852, 802]. No overflow, no underflow. */
    if (all_within(diff, 6, INCIRCLE_MIN, INCIRCLE_MAX)) {
        double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
        double cdxady = cdx * ady, adxcdy = adx * cdy;
        double adxbdy = adx * bdy, bdxady = bdx * ady;
        double alift = adx * adx + ady * ady;
        double blift = bdx * bdx + bdy * bdy;
        double clift = cdx * cdx + cdy * cdy;
        double det = alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) +
                     clift * (adxbdy - bdxady);
        double permanent = (fabs(bdxcdy) + fabs(cdxbdy)) * alift +
                           (fabs(cdxady) + fabs(adxcdy)) * blift +
                           (fabs(adxbdy) + fabs(bdxady)) * clift;
        if (fabs(det) > incircle_errbound * permanent) return sign_of(det);
    }
    return incircle_exact(a, b, c, d);
}

/* a < b in (x, then y) order. */
static int lex_less(const double a[2], const double b[2])
{
    return a[0] < b[0] || (a[0] == b[0] && a[1] < b[1]);
}

/* p on the closed segment ab, given that a, b, p are collinear. Along a
 * line, (x, y) order is the order of the points on it. */
static int between_collinear(const double a[2], const double b[2],
                             const double p[2])
{
    const double *lo = lex_less(b, a) ? b : a;
    const double *hi = lex_less(b, a) ? a : b;
    return !lex_less(p, lo) && !lex_less(hi, p);
}

int cm_segments_intersect(const double a[2], const double b[2],
                          const double c[2], const double d[2])
{
    int abc = cm_orient2d(a, b, c), abd = cm_orient2d(a, b, d);
    int cda = cm_orient2d(c, d, a), cdb = cm_orient2d(c, d, b);
    if (abc * abd < 0 && cda * cdb < 0) return 1;
    if ((abc == 0 && between_collinear(a, b, c)) ||
        (abd == 0 && between_collinear(a, b, d)) ||
        (cda == 0 && between_collinear(c, d, a)) ||
        (cdb == 0 && between_collinear(c, d, b)))
        return 2;
    return 0;
}

int cm_polygon_orientation(const double *xy, long n)
{
    if (n < 3) return 0;
    /* Recursive summation of n terms of two products each: the error is
     * below (n + 1) * EPS * (1 + 2^-18) * sum|products| while n < 2^30
     * (Higham, Accuracy and Stability, 3.1); 2n + 4 leaves room for the
     * rounding of `absolute` itself and of the bound. Coordinates within
     * 2^+-500 rule out underflow; a finite `absolute` rules out overflow,
     * as every partial sum is bounded by the matching one of `absolute`. */
    if (n < (1L << 30)) {
        double sum = 0.0, absolute = 0.0;
        int in_range = 1;
        for (long i = 0; i < n && in_range; i++) {
            const double *p = xy + 2 * i, *q = xy + 2 * ((i + 1) % n);
            in_range = all_within(p, 2, ORIENT_MIN, ORIENT_MAX);
            double left = p[0] * q[1], right = q[0] * p[1];
            sum += left - right;
            absolute += fabs(left) + fabs(right);
        }
        if (in_range && isfinite(absolute)) {
            double errbound = (2.0 * (double)n + 4.0) * EPS * absolute;
            if (fabs(sum) > errbound) return sign_of(sum);
        }
    }
    return polygon_orientation_exact(xy, n);
}
