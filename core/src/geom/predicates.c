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
#include "geom/predicates.h"

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


static const double orient_errbound = (3.0 + 16.0 * CM_EPS) * CM_EPS;
static const double incircle_errbound = (10.0 + 96.0 * CM_EPS) * CM_EPS;

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

/* ---- error-free transformations (Shewchuk 1997, section 2) ------------- */

/* With round-to-nearest and no overflow: a - b = x + tail exactly. */
static double diff_tail(double a, double b, double x)
{
    double bvirt = a - x, avirt = x + bvirt;
    return (a - avirt) + (bvirt - b);
}

static void two_sum(double a, double b, double *x, double *y)
{
    *x = a + b;
    double bvirt = *x - a, avirt = *x - bvirt;
    *y = (a - avirt) + (b - bvirt);
}

static void two_diff(double a, double b, double *x, double *y)
{
    *x = a - b;
    *y = diff_tail(a, b, *x);
}

/* a = hi + lo, each with at most 26 significant bits (|a| < 2^996). */
static void split(double a, double *hi, double *lo)
{
    double c = 134217729.0 * a; /* 2^27 + 1 */
    *hi = c - (c - a);
    *lo = a - *hi;
}

/* a * b = *x + *y exactly, when the product's error term does not
 * underflow (|a b| >= 2^-916 or a b = 0). */
static void two_product(double a, double b, double *x, double *y)
{
    double ahi, alo, bhi, blo;
    *x = a * b;
    split(a, &ahi, &alo);
    split(b, &bhi, &blo);
    double err = *x - ahi * bhi;
    err -= alo * bhi;
    err -= ahi * blo;
    *y = alo * blo - err;
}

/* The sign of (a1 + a0) - (b1 + b0), exactly: the four-term expansion of
 * Two_Two_Diff, whose largest nonzero term carries the sign. */
static int two_two_diff_sign(double a1, double a0, double b1, double b0)
{
    double i, j, zero, x0, x1, x2, x3;
    two_diff(a0, b0, &i, &x0);
    two_sum(a1, i, &j, &zero);
    two_diff(zero, b1, &i, &x1);
    two_sum(j, i, &x3, &x2);
    return x3 != 0 ? sign_of(x3) : x2 != 0 ? sign_of(x2) : x1 != 0 ? sign_of(x1) : sign_of(x0);
}

/* Differences 0 or within 2^[-458, 500] keep every product and error term
 * below clear of overflow and underflow. */
#define ORIENT_EXACT_MIN 0x1p-458

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
        /* Shewchuk's stage B: when the differences are exact (collinear
         * points of an outline usually are), the determinant is the exact
         * difference of two exact products, without GMP. */
        if (all_within(diff, 4, ORIENT_EXACT_MIN, ORIENT_MAX) && diff_tail(a[0], c[0], acx) == 0 &&
            diff_tail(b[0], c[0], bcx) == 0 && diff_tail(a[1], c[1], acy) == 0 &&
            diff_tail(b[1], c[1], bcy) == 0) {
            double l1, l0, r1, r0;
            two_product(acx, bcy, &l1, &l0);
            two_product(acy, bcx, &r1, &r0);
            return two_two_diff_sign(l1, l0, r1, r0);
        }
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
/* p on the closed segment ab, given that a, b, p are collinear. Along a
 * line, (x, y) order is the order of the points on it. */
static int between_collinear(const double a[2], const double b[2],
                             const double p[2])
{
    const double *lo = cm_point_less(b, a) ? b : a;
    const double *hi = cm_point_less(b, a) ? a : b;
    return !cm_point_less(p, lo) && !cm_point_less(hi, p);
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
     * below (n + 1) * CM_EPS * (1 + 2^-18) * sum|products| while n < 2^30
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
            double errbound = (2.0 * (double)n + 4.0) * CM_EPS * absolute;
            if (fabs(sum) > errbound) return sign_of(sum);
        }
    }
    return polygon_orientation_exact(xy, n);
}

/* ---- 3D orientation and blended triangles ---------------------------- */

static const double orient3d_errbound = (7.0 + 56.0 * CM_EPS) * CM_EPS;
#define ORIENT3D_MIN 0x1p-300
#define ORIENT3D_MAX 0x1p+300

static int orient3d_exact(const double a[3], const double b[3], const double c[3],
                          const double d[3])
{
    double in[12] = {a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2], d[0], d[1], d[2]};
    if (!all_finite(in, 12)) return 0;
    long emin = common_exponent(in, 12);
    mpz_t p[12], u[9], det, t;
    for (int i = 0; i < 12; i++) {
        mpz_init(p[i]);
        set_scaled(p[i], in[i], emin);
    }
    for (int i = 0; i < 9; i++) { /* rows b - a, c - a, d - a */
        mpz_init(u[i]);
        mpz_sub(u[i], p[3 + i], p[i % 3]);
    }
    mpz_inits(det, t, NULL);
    mpz_mul(t, u[4], u[8]), mpz_submul(t, u[5], u[7]), mpz_mul(det, u[0], t);
    mpz_mul(t, u[3], u[8]), mpz_submul(t, u[5], u[6]), mpz_submul(det, u[1], t);
    mpz_mul(t, u[3], u[7]), mpz_submul(t, u[4], u[6]), mpz_addmul(det, u[2], t);
    int s = mpz_sgn(det);
    mpz_clears(det, t, NULL);
    for (int i = 0; i < 9; i++) mpz_clear(u[i]);
    for (int i = 0; i < 12; i++) mpz_clear(p[i]);
    return s;
}

int cm_orient3d(const double a[3], const double b[3], const double c[3], const double d[3])
{
    double u[9];
    for (int i = 0; i < 3; i++)
        u[i] = b[i] - a[i], u[3 + i] = c[i] - a[i], u[6 + i] = d[i] - a[i];
    if (all_within(u, 9, ORIENT3D_MIN, ORIENT3D_MAX)) {
        double m0 = u[4] * u[8] - u[5] * u[7], m1 = u[3] * u[8] - u[5] * u[6];
        double m2 = u[3] * u[7] - u[4] * u[6];
        double det = u[0] * m0 - u[1] * m1 + u[2] * m2;
        double perm = fabs(u[0]) * (fabs(u[4] * u[8]) + fabs(u[5] * u[7])) +
                      fabs(u[1]) * (fabs(u[3] * u[8]) + fabs(u[5] * u[6])) +
                      fabs(u[2]) * (fabs(u[3] * u[7]) + fabs(u[4] * u[6]));
        if (fabs(det) > orient3d_errbound * perm) return sign_of(det);
    }
    return orient3d_exact(a, b, c, d);
}

/* The blend's doubled area is the Bernstein quadratic
 * A0 (1-s)^2 + 2 M s (1-s) + A1 s^2, with A0, A1 the end areas and
 * 2M = cross(b0 - a0, c1 - a1) + cross(b1 - a1, c0 - a0). With A0, A1 > 0
 * it is positive on [0, 1] iff M >= 0 or M^2 < A0 A1 (divide by (1-s)^2:
 * A0 + 2 M u + A1 u^2 > 0 for all u >= 0). */
static int blend_positive_exact(const double *const pts[6])
{
    double in[12];
    for (int i = 0; i < 6; i++) in[2 * i] = pts[i][0], in[2 * i + 1] = pts[i][1];
    if (!all_finite(in, 12)) return 0;
    long emin = common_exponent(in, 12);
    mpz_t p[12], d[8], a0, a1, m, t;
    for (int i = 0; i < 12; i++) {
        mpz_init(p[i]);
        set_scaled(p[i], in[i], emin);
    }
    /* d: b0-a0, c0-a0, b1-a1, c1-a1 (x, y each) */
    for (int e = 0; e < 2; e++)
        for (int j = 0; j < 2; j++)
            for (int c = 0; c < 2; c++) {
                mpz_init(d[4 * e + 2 * j + c]);
                mpz_sub(d[4 * e + 2 * j + c], p[6 * e + 2 * (j + 1) + c], p[6 * e + c]);
            }
    mpz_inits(a0, a1, m, t, NULL);
    mpz_mul(a0, d[0], d[3]), mpz_submul(a0, d[1], d[2]);
    mpz_mul(a1, d[4], d[7]), mpz_submul(a1, d[5], d[6]);
    mpz_mul(m, d[0], d[7]), mpz_submul(m, d[1], d[6]); /* cross(b0-a0, c1-a1) */
    mpz_addmul(m, d[4], d[3]), mpz_submul(m, d[5], d[2]); /* + cross(b1-a1, c0-a0) */
    int ok = mpz_sgn(a0) > 0 && mpz_sgn(a1) > 0;
    if (ok && mpz_sgn(m) < 0) {
        /* (2M)^2 < 4 A0 A1 */
        mpz_mul(t, a0, a1);
        mpz_mul_2exp(t, t, 2);
        mpz_mul(m, m, m);
        ok = mpz_cmp(m, t) < 0;
    }
    mpz_clears(a0, a1, m, t, NULL);
    for (int i = 0; i < 8; i++) mpz_clear(d[i]);
    for (int i = 0; i < 12; i++) mpz_clear(p[i]);
    return ok;
}

int cm_blend_positive(const double a0[2], const double b0[2], const double c0[2],
                      const double a1[2], const double b1[2], const double c1[2])
{
    const double *pts[6] = {a0, b0, c0, a1, b1, c1};
    double d[8] = {b0[0] - a0[0], b0[1] - a0[1], c0[0] - a0[0], c0[1] - a0[1],
                   b1[0] - a1[0], b1[1] - a1[1], c1[0] - a1[0], c1[1] - a1[1]};
    if (all_within(d, 8, ORIENT_MIN, ORIENT_MAX)) {
        /* Filter: each cross product has relative error below 4 CM_EPS of
         * its permanent (two roundings of the differences, products, sum);
         * decide only with a wide margin, else go exact. */
        double a0f = d[0] * d[3] - d[1] * d[2], a0p = fabs(d[0] * d[3]) + fabs(d[1] * d[2]);
        double a1f = d[4] * d[7] - d[5] * d[6], a1p = fabs(d[4] * d[7]) + fabs(d[5] * d[6]);
        double mf = d[0] * d[7] - d[1] * d[6] + d[4] * d[3] - d[5] * d[2];
        double mp = fabs(d[0] * d[7]) + fabs(d[1] * d[6]) + fabs(d[4] * d[3]) + fabs(d[5] * d[2]);
        const double rel = 16.0 * CM_EPS;
        if (a0f > rel * a0p && a1f > rel * a1p) {
            if (mf > rel * mp) return 1;
            double a0lo = a0f - rel * a0p, a1lo = a1f - rel * a1p;
            double mhi = fabs(mf) + rel * mp;
            if (mhi * mhi * (1.0 + rel) < 4.0 * a0lo * a1lo * (1.0 - rel)) return 1;
        }
    }
    return blend_positive_exact(pts);
}
