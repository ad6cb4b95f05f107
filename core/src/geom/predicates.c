/* Filtered exact predicates.
 *
 * Each predicate first evaluates its determinant in double precision and
 * trusts the sign only if it exceeds a static forward error bound
 * (Shewchuk, "Adaptive Precision Floating-Point Arithmetic and Fast Robust
 * Geometric Predicates", 1997, the "A" bounds), used only while its inputs
 * lie in a range that rules out overflow and underflow.
 *
 * When that filter cannot decide, the determinant is evaluated adaptively
 * on floating-point expansions (geom/expansion.h), as in the paper: the
 * exact determinant of the rounded coordinate differences with the "B"
 * bound, exact outright when the differences are (collinear outline points
 * usually are); for orient2d and incircle the first-order correction by the
 * differences' rounding errors with the "C" bound; finally the exact
 * determinant of the exact differences, whose sign is that of its largest
 * component.
 *
 * Range. Those stages need no overflow, no underflow (the error bounds
 * assume relative rounding errors) and exact Two-Products. The predicates
 * are homogeneous in the coordinates, so a call's inputs are first scaled
 * by one power of two (exact) into [2^L, 2^H) with every nonzero input a
 * multiple of 2^L, L = -892 / d and H = 940 / d - 1 for a determinant of
 * degree d (exact_shift). Then every value the stages compute (sums and
 * products of degree at most d, their rounding errors, expansion
 * components) is a multiple of 2^(d L) >= 2^-892, hence zero or normal:
 * no underflow, and each product's error term is a double. The bounds,
 * about 2^-106 times a nonzero permanent, stay above 2^-1000. Every
 * magnitude stays below a few dozen times 2^(d (H + 1)) <= 2^940 (2^972 for
 * the polygon's 2^31 terms): no overflow. Inputs spanning more binades than
 * H - L less a mantissa (orient2d about 2^860 between the largest and the
 * smallest nonzero coordinate, orient3d 2^550, incircle and the blend
 * 2^400) have no such scaling and are evaluated
 * with GMP integers instead: every finite double is m * 2^e with an integer
 * m, so scaling all inputs of one call by 2^-emin (emin the smallest such
 * e) turns them into integers without changing any sign.
 *
 * NaN and infinity have neither form; for them the predicates return 0
 * (callers are expected to reject them first). */
#include "geom/predicates.h"

#include "geom/expansion.h"

#include <float.h>
#include <gmp.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

/* The error bounds count one rounding to double per operation. */
#if FLT_EVAL_METHOD != 0
#error "predicates.c needs doubles evaluated in double (e.g. -mfpmath=sse)"
#endif
#ifdef __clang__
#pragma STDC FP_CONTRACT OFF /* no fused a*b+c (GCC: off in ISO C mode) */
#endif

/* Shewchuk's bounds (section 4): A for the double evaluation, B for the
 * exact determinant of rounded differences, C for its first-order
 * correction, plus the rounding of the corrected result. */
static const double orient_errbound_b = (2.0 + 12.0 * CM_EPS) * CM_EPS;
static const double orient_errbound_c = (9.0 + 64.0 * CM_EPS) * CM_EPS * CM_EPS;
static const double incircle_errbound = (10.0 + 96.0 * CM_EPS) * CM_EPS;
static const double incircle_errbound_b = (4.0 + 48.0 * CM_EPS) * CM_EPS;
static const double incircle_errbound_c = (44.0 + 576.0 * CM_EPS) * CM_EPS * CM_EPS;
static const double orient3d_errbound = (7.0 + 56.0 * CM_EPS) * CM_EPS;
static const double orient3d_errbound_b = (3.0 + 28.0 * CM_EPS) * CM_EPS;
static const double result_errbound = (3.0 + 8.0 * CM_EPS) * CM_EPS;

/* Bounds on the magnitude of the filters' inputs; see the callers. */
#define INCIRCLE_MIN 0x1p-200
#define INCIRCLE_MAX 0x1p+200
#define ORIENT3D_MIN 0x1p-300
#define ORIENT3D_MAX 0x1p+300

/* The expansion stages' range for a determinant of degree d (top). */
#define EXACT_LOW(d) (-892 / (d))
#define EXACT_HIGH(d) (940 / (d) - 1)

static int all_within(const double *v, long count, double min, double max)
{
    for (long i = 0; i < count; i++)
        if (!cm_magnitude_within(v[i], min, max)) return 0;
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

/* ---- the expansion stages' range ---------------------------------------- */

/* The biased exponent field: |v| in [2^(E - 1023), 2^(E - 1022)) for a
 * normal v (E from 1 to 2046), E = 0 for zero and subnormals, 2047 for
 * infinity and NaN. */
static int biased_exponent(double v)
{
    uint64_t bits;
    memcpy(&bits, &v, sizeof bits);
    return (int)(bits >> 52 & 0x7ff);
}

/* A power of two 2^*shift that takes every nonzero v[i] into [2^low,
 * 2^high) as a multiple of 2^low: returns 1 with it, 0 if there is none
 * (the values span more than high - low binades), -1 if a value is not
 * finite. */
static int exact_shift(const double *v, long count, int low, int high,
                       int *shift)
{
    *shift = 0;
    int top = INT_MIN, bottom = INT_MAX;
    for (long i = 0; i < count; i++) {
        if (v[i] == 0.0) continue;
        if (!isfinite(v[i])) return -1;
        int e;
        double m = frexp(fabs(v[i]), &e); /* |v| = m 2^e, 1/2 <= m < 1 */
        uint64_t bits = (uint64_t)ldexp(m, 53); /* |v| = bits 2^(e - 53) */
        int lowest = e - 53;
        while (bits % 2 == 0) bits /= 2, lowest++;
        if (e > top) top = e;
        if (lowest < bottom) bottom = lowest;
    }
    if (top == INT_MIN || (bottom >= low && top <= high)) return 1;
    if (top - bottom > high - low) return 0;
    *shift = high - top;
    return 1;
}

/* out = in * 2^shift for the expansion stages of a determinant of degree
 * `degree`; 0 to go to GMP, -1 if an input is not finite. */
static inline int scale_for_exact(const double *in, double *out, int count,
                                  int degree)
{
    const int low = EXACT_LOW(degree), high = EXACT_HIGH(degree);
    /* Usually every input is 0 or normal with an exponent that keeps its
     * lowest bit (2^(E - 1075) or above) at or above 2^low and the value
     * below 2^high as it is. */
    int as_is = 1;
    for (int i = 0; i < count; i++) {
        int e = biased_exponent(in[i]);
        as_is &= in[i] == 0.0 || (e >= low + 1075 && e <= high + 1022);
        out[i] = in[i];
    }
    if (as_is) return 1;
    int shift;
    int ok = exact_shift(in, count, low, high, &shift);
    if (ok == 1 && shift != 0)
        for (int i = 0; i < count; i++) out[i] = ldexp(in[i], shift);
    return ok;
}

/* An exact coordinate difference, one or two components. */
typedef struct {
    int n;
    double v[2];
} exact_diff;

static exact_diff diff_of(double a, double b)
{
    exact_diff d;
    d.n = cm_expansion_of_diff(a, b, d.v);
    return d;
}

/* h = p q - r s exactly; h holds 16. */
static int cross_exact(const exact_diff *p, const exact_diff *q,
                       const exact_diff *r, const exact_diff *s, double *h)
{
    double pq[8], rs[8], scratch[2 * 2 * 3];
    int npq = cm_expansion_product(p->n, p->v, q->n, q->v, pq, scratch);
    int nrs = cm_expansion_product(r->n, r->v, s->n, s->v, rs, scratch);
    return cm_expansion_diff(npq, pq, nrs, rs, h);
}

/* ---- GMP, for inputs spanning too many binades (see the top) ----------- */

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

static int orient2d_gmp(const double a[2], const double b[2],
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

static int incircle_gmp(const double a[2], const double b[2],
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

static int polygon_orientation_gmp(const double *xy, long n)
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

static int orient3d_gmp(const double a[3], const double b[3], const double c[3],
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

static int blend_positive_gmp(const double *const pts[6])
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

/* ---- orient2d ------------------------------------------------------------ */

/* Nonzero differences within 2^[-458, 500] have their lowest bits at or
 * above 2^-510, so the products of two are exact as two doubles and below
 * 2^1000. */
#define ORIENT_EXACT_MIN 0x1p-458

int cm_orient2d_adaptive(const double a[2], const double b[2], const double c[2])
{
    /* Exact differences (collinear outline points usually have them): the
     * determinant is l - r with l = l1 + l0, r = r1 + r0 exactly, and
     * rounding is monotone, so l1 > r1 implies l > r. */
    double dx[4] = {a[0] - c[0], b[0] - c[0], a[1] - c[1], b[1] - c[1]};
    /* A difference is 0 only where the two coordinates are equal: a zero
     * factor in each product makes both exactly 0 (points on one
     * axis-parallel line, or repeated: the filter's usual undecided case
     * in outlines), the other factors finite. */
    if ((dx[0] == 0.0 || dx[3] == 0.0) && (dx[2] == 0.0 || dx[1] == 0.0) && fabs(dx[0]) <= DBL_MAX &&
        fabs(dx[1]) <= DBL_MAX && fabs(dx[2]) <= DBL_MAX && fabs(dx[3]) <= DBL_MAX)
        return 0;
    if (cm_diff_tail(a[0], c[0], dx[0]) == 0.0 && cm_diff_tail(b[0], c[0], dx[1]) == 0.0 &&
        cm_diff_tail(a[1], c[1], dx[2]) == 0.0 && cm_diff_tail(b[1], c[1], dx[3]) == 0.0 &&
        all_within(dx, 4, ORIENT_EXACT_MIN, CM_ORIENT_MAX)) {
        double l1, l0, r1, r0;
        cm_two_product(dx[0], dx[3], &l1, &l0);
        cm_two_product(dx[2], dx[1], &r1, &r0);
        if (l1 != r1) return l1 > r1 ? 1 : -1;
        return (l0 > r0) - (l0 < r0);
    }

    const double in[6] = {a[0], a[1], b[0], b[1], c[0], c[1]};
    double v[6];
    int ok = scale_for_exact(in, v, 6, 2);
    if (ok <= 0) return ok < 0 ? 0 : orient2d_gmp(a, b, c);

    double acx = v[0] - v[4], bcx = v[2] - v[4];
    double acy = v[1] - v[5], bcy = v[3] - v[5];
    double l1, l0, r1, r0, det_b[4];
    cm_two_product(acx, bcy, &l1, &l0);
    cm_two_product(acy, bcx, &r1, &r0);
    cm_two_two_diff(l1, l0, r1, r0, det_b);
    double det = cm_expansion_estimate(4, det_b);
    double detsum = fabs(l1) + fabs(r1);
    if (fabs(det) > orient_errbound_b * detsum) return sign_of(det);

    double acxt = cm_diff_tail(v[0], v[4], acx), bcxt = cm_diff_tail(v[2], v[4], bcx);
    double acyt = cm_diff_tail(v[1], v[5], acy), bcyt = cm_diff_tail(v[3], v[5], bcy);
    if (acxt == 0.0 && bcxt == 0.0 && acyt == 0.0 && bcyt == 0.0)
        return cm_expansion_sign_ordered(4, det_b); /* exact differences: exact */

    double errbound = orient_errbound_c * detsum + result_errbound * fabs(det);
    det += (acx * bcyt - acy * bcxt) + (bcy * acxt - bcx * acyt);
    if (fabs(det) > errbound) return sign_of(det);

    exact_diff dax = diff_of(v[0], v[4]), dbx = diff_of(v[2], v[4]);
    exact_diff day = diff_of(v[1], v[5]), dby = diff_of(v[3], v[5]);
    double exact[16];
    int n = cross_exact(&dax, &dby, &day, &dbx, exact);
    return cm_expansion_sign(n, exact);
}

int cm_orient2d_compiled(const double a[2], const double b[2], const double c[2])
{
    int s = cm_orient2d_filter(a, b, c);
    return s != 2 ? s : cm_orient2d_adaptive(a, b, c);
}

/* ---- incircle ------------------------------------------------------------ */

/* h = minor * (dx^2 + dy^2) exactly, minor an expansion of up to 4
 * components; h holds 32. */
static int lifted(int mn, const double *minor, double dx, double dy, double *h)
{
    double t[8], x2[16], y2[16];
    int tn = cm_expansion_scale(mn, minor, dx, t);
    int xn = cm_expansion_scale(tn, t, dx, x2);
    tn = cm_expansion_scale(mn, minor, dy, t);
    int yn = cm_expansion_scale(tn, t, dy, y2);
    return cm_expansion_sum(xn, x2, yn, y2, h);
}

/* dx^2 + dy^2 exactly; h holds 16. */
static int lift_exact(const exact_diff *dx, const exact_diff *dy, double *h)
{
    double x2[8], y2[8], scratch[2 * 2 * 3];
    int xn = cm_expansion_product(dx->n, dx->v, dx->n, dx->v, x2, scratch);
    int yn = cm_expansion_product(dy->n, dy->v, dy->n, dy->v, y2, scratch);
    return cm_expansion_sum(xn, x2, yn, y2, h);
}

static int incircle_adapt(const double a[2], const double b[2],
                          const double c[2], const double d[2])
{
    const double in[8] = {a[0], a[1], b[0], b[1], c[0], c[1], d[0], d[1]};
    double v[8];
    int ok = scale_for_exact(in, v, 8, 4);
    if (ok <= 0) return ok < 0 ? 0 : incircle_gmp(a, b, c, d);

    double adx = v[0] - v[6], ady = v[1] - v[7];
    double bdx = v[2] - v[6], bdy = v[3] - v[7];
    double cdx = v[4] - v[6], cdy = v[5] - v[7];

    /* the exact determinant of the rounded differences */
    double p1, p0, q1, q0, bc[4], ca[4], ab[4];
    cm_two_product(bdx, cdy, &p1, &p0);
    cm_two_product(cdx, bdy, &q1, &q0);
    cm_two_two_diff(p1, p0, q1, q0, bc);
    double bc_abs = fabs(p1) + fabs(q1);
    cm_two_product(cdx, ady, &p1, &p0);
    cm_two_product(adx, cdy, &q1, &q0);
    cm_two_two_diff(p1, p0, q1, q0, ca);
    double ca_abs = fabs(p1) + fabs(q1);
    cm_two_product(adx, bdy, &p1, &p0);
    cm_two_product(bdx, ady, &q1, &q0);
    cm_two_two_diff(p1, p0, q1, q0, ab);
    double ab_abs = fabs(p1) + fabs(q1);
    double ta[32], tb[32], tc[32], tab[64], det_b[96];
    int na = lifted(4, bc, adx, ady, ta);
    int nb = lifted(4, ca, bdx, bdy, tb);
    int nc = lifted(4, ab, cdx, cdy, tc);
    int nab = cm_expansion_sum(na, ta, nb, tb, tab);
    int n = cm_expansion_sum(nab, tab, nc, tc, det_b);
    double det = cm_expansion_estimate(n, det_b);
    double alift = adx * adx + ady * ady, blift = bdx * bdx + bdy * bdy;
    double clift = cdx * cdx + cdy * cdy;
    double permanent = bc_abs * alift + ca_abs * blift + ab_abs * clift;
    if (fabs(det) > incircle_errbound_b * permanent) return sign_of(det);

    double adxt = cm_diff_tail(v[0], v[6], adx), adyt = cm_diff_tail(v[1], v[7], ady);
    double bdxt = cm_diff_tail(v[2], v[6], bdx), bdyt = cm_diff_tail(v[3], v[7], bdy);
    double cdxt = cm_diff_tail(v[4], v[6], cdx), cdyt = cm_diff_tail(v[5], v[7], cdy);
    if (adxt == 0.0 && adyt == 0.0 && bdxt == 0.0 && bdyt == 0.0 && cdxt == 0.0 &&
        cdyt == 0.0)
        return cm_expansion_sign(n, det_b); /* exact differences: exact */

    /* first-order terms of the differences' rounding errors */
    double errbound = incircle_errbound_c * permanent + result_errbound * fabs(det);
    det += ((adx * adx + ady * ady) * ((bdx * cdyt + cdy * bdxt) - (bdy * cdxt + cdx * bdyt)) +
            2.0 * (adx * adxt + ady * adyt) * (bdx * cdy - bdy * cdx)) +
           ((bdx * bdx + bdy * bdy) * ((cdx * adyt + ady * cdxt) - (cdy * adxt + adx * cdyt)) +
            2.0 * (bdx * bdxt + bdy * bdyt) * (cdx * ady - cdy * adx)) +
           ((cdx * cdx + cdy * cdy) * ((adx * bdyt + bdy * adxt) - (ady * bdxt + bdx * adyt)) +
            2.0 * (cdx * cdxt + cdy * cdyt) * (adx * bdy - ady * bdx));
    if (fabs(det) > errbound) return sign_of(det);

    /* exact: the lifts times the minors of the exact differences */
    exact_diff ex[6];
    for (int i = 0; i < 6; i++) ex[i] = diff_of(v[i], v[6 + i % 2]);
    double minor[16], lift[16], scratch[2 * 16 * 17], term[3][512], sum2[1024], exact[1536];
    int tn[3];
    for (int r = 0; r < 3; r++) { /* rows a, b, c; minor of the other two */
        const exact_diff *p = &ex[2 * ((r + 1) % 3)], *q = &ex[2 * ((r + 2) % 3)];
        int mn = cm_expansion_compress(cross_exact(&p[0], &q[1], &q[0], &p[1], minor), minor);
        int ln = cm_expansion_compress(lift_exact(&ex[2 * r], &ex[2 * r + 1], lift), lift);
        tn[r] = cm_expansion_product(ln, lift, mn, minor, term[r], scratch);
    }
    int sn = cm_expansion_sum(tn[0], term[0], tn[1], term[1], sum2);
    int en = cm_expansion_sum(sn, sum2, tn[2], term[2], exact);
    return cm_expansion_sign(en, exact);
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
    return incircle_adapt(a, b, c, d);
}

/* ---- segments -------------------------------------------------------------- */

/* p on the closed segment ab, given that a, b, p are collinear. Along a
 * line, (x, y) order is the order of the points on it. */
static int between_collinear(const double a[2], const double b[2],
                             const double p[2])
{
    const double *lo = cm_point_less(b, a) ? b : a;
    const double *hi = cm_point_less(b, a) ? a : b;
    return !cm_point_less(p, lo) && !cm_point_less(hi, p);
}

/* Both ends of ab strictly below both ends of cd along axis x (0) or y
 * (1): then the segments share no point. Exact comparisons; false when a
 * coordinate is NaN, leaving that case to the predicates. */
static int strictly_below(const double a[2], const double b[2], const double c[2],
                          const double d[2], int x)
{
    return a[x] < c[x] && a[x] < d[x] && b[x] < c[x] && b[x] < d[x];
}

/* tame: the four points tame (cm_coords_tame), the filter need not check
 * its differences. */
static inline int segments_intersect(const double a[2], const double b[2], const double c[2], const double d[2],
                                     int tame)
{
    /* Most segment pairs a polygon scan meets are far apart: disjoint
     * bounding boxes settle them without a predicate. */
    if (strictly_below(a, b, c, d, 0) || strictly_below(c, d, a, b, 0) ||
        strictly_below(a, b, c, d, 1) || strictly_below(c, d, a, b, 1))
        return 0;
    /* c and d strictly on one side of line ab (or a and b of line cd):
     * no common point, whatever the other two tests say. */
    int abc = cm_orient2d_either(tame, a, b, c), abd = cm_orient2d_either(tame, a, b, d);
    if (abc * abd > 0) return 0;
    int cda = cm_orient2d_either(tame, c, d, a), cdb = cm_orient2d_either(tame, c, d, b);
    if (cda * cdb > 0) return 0;
    if (abc * abd < 0 && cda * cdb < 0) return 1;
    if ((abc == 0 && between_collinear(a, b, c)) ||
        (abd == 0 && between_collinear(a, b, d)) ||
        (cda == 0 && between_collinear(c, d, a)) ||
        (cdb == 0 && between_collinear(c, d, b)))
        return 2;
    return 0;
}

int cm_segments_intersect(const double a[2], const double b[2],
                          const double c[2], const double d[2])
{
    return segments_intersect(a, b, c, d, 0);
}

int cm_segments_intersect_tame(const double a[2], const double b[2], const double c[2], const double d[2])
{
    return segments_intersect(a, b, c, d, 1);
}

/* ---- polygon orientation --------------------------------------------------- */

/* Components of the polygon's exact doubled area: nonoverlapping nonzero
 * components have distinct lowest set bits, all multiples of 2^-892 and
 * below 2^972 (see the top), so at most 1864 of them. */
#define POLYGON_TERMS 1872

static int polygon_orientation_adapt(const double *xy, long n)
{
    int shift;
    int ok = exact_shift(xy, 2 * n, EXACT_LOW(2), EXACT_HIGH(2), &shift);
    if (ok <= 0) return ok < 0 ? 0 : polygon_orientation_gmp(xy, n);
    double area[POLYGON_TERMS];
    int len = 0;
    for (long i = 0; i < n; i++) {
        const double *p = xy + 2 * i, *q = xy + 2 * ((i + 1) % n);
        double px = p[0], py = p[1], qx = q[0], qy = q[1];
        if (shift != 0)
            px = ldexp(px, shift), py = ldexp(py, shift), qx = ldexp(qx, shift), qy = ldexp(qy, shift);
        double hi, lo;
        cm_two_product(px, qy, &hi, &lo);
        len = cm_expansion_grow(len, area, lo);
        len = cm_expansion_grow(len, area, hi);
        cm_two_product(-qx, py, &hi, &lo);
        len = cm_expansion_grow(len, area, lo);
        len = cm_expansion_grow(len, area, hi);
    }
    return cm_expansion_sign_ordered(len, area);
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
            in_range = all_within(p, 2, CM_ORIENT_MIN, CM_ORIENT_MAX);
            double left = p[0] * q[1], right = q[0] * p[1];
            sum += left - right;
            absolute += fabs(left) + fabs(right);
        }
        if (in_range && isfinite(absolute)) {
            double errbound = (2.0 * (double)n + 4.0) * CM_EPS * absolute;
            if (fabs(sum) > errbound) return sign_of(sum);
        }
        return polygon_orientation_adapt(xy, n);
    }
    return polygon_orientation_gmp(xy, n);
}

/* ---- 3D orientation -------------------------------------------------------- */

static int orient3d_adapt(const double a[3], const double b[3], const double c[3],
                          const double d[3])
{
    const double in[12] = {a[0], a[1], a[2], b[0], b[1], b[2],
                           c[0], c[1], c[2], d[0], d[1], d[2]};
    double v[12];
    int ok = scale_for_exact(in, v, 12, 3);
    if (ok <= 0) return ok < 0 ? 0 : orient3d_gmp(a, b, c, d);

    /* rows b - a, c - a, d - a; det = u0 m0 - u1 m1 + u2 m2 */
    static const int minor_of[3][4] = {{4, 8, 5, 7}, {3, 8, 5, 6}, {3, 7, 4, 6}};
    double u[9];
    for (int i = 0; i < 9; i++) u[i] = v[3 + i] - v[i % 3];
    double term[3][8], t01[16], det_b[24], perm = 0.0;
    int tn[3];
    for (int k = 0; k < 3; k++) {
        const int *m = minor_of[k];
        double p1, p0, q1, q0, minor[4];
        cm_two_product(u[m[0]], u[m[1]], &p1, &p0);
        cm_two_product(u[m[2]], u[m[3]], &q1, &q0);
        cm_two_two_diff(p1, p0, q1, q0, minor);
        tn[k] = cm_expansion_scale(4, minor, u[k], term[k]);
        perm += fabs(u[k]) * (fabs(p1) + fabs(q1));
    }
    int n01 = cm_expansion_diff(tn[0], term[0], tn[1], term[1], t01);
    int n = cm_expansion_sum(n01, t01, tn[2], term[2], det_b);
    double det = cm_expansion_estimate(n, det_b);
    if (fabs(det) > orient3d_errbound_b * perm) return sign_of(det);
    int tails_zero = 1;
    for (int i = 0; i < 9; i++) tails_zero &= cm_diff_tail(v[3 + i], v[i % 3], u[i]) == 0.0;
    if (tails_zero) return cm_expansion_sign(n, det_b); /* exact differences */

    exact_diff ex[9];
    for (int i = 0; i < 9; i++) ex[i] = diff_of(v[3 + i], v[i % 3]);
    double minor[16], scratch[2 * 16 * 3], big[3][64], b01[128], exact[192];
    int bn[3];
    for (int k = 0; k < 3; k++) {
        const int *m = minor_of[k];
        int mn = cross_exact(&ex[m[0]], &ex[m[1]], &ex[m[2]], &ex[m[3]], minor);
        bn[k] = cm_expansion_product(mn, minor, ex[k].n, ex[k].v, big[k], scratch);
    }
    int bn01 = cm_expansion_diff(bn[0], big[0], bn[1], big[1], b01);
    int en = cm_expansion_sum(bn01, b01, bn[2], big[2], exact);
    return cm_expansion_sign(en, exact);
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
    return orient3d_adapt(a, b, c, d);
}

/* ---- blended triangles ------------------------------------------------------ */

/* The blend's doubled area is the Bernstein quadratic
 * A0 (1-s)^2 + 2 M s (1-s) + A1 s^2, with A0, A1 the end areas and
 * 2M = cross(b0 - a0, c1 - a1) + cross(b1 - a1, c0 - a0). With A0, A1 > 0
 * it is positive on [0, 1] iff M >= 0 or M^2 < A0 A1 (divide by (1-s)^2:
 * A0 + 2 M u + A1 u^2 > 0 for all u >= 0). */
static int blend_positive_adapt(const double *const pts[6])
{
    double in[12], v[12];
    for (int i = 0; i < 6; i++) in[2 * i] = pts[i][0], in[2 * i + 1] = pts[i][1];
    int ok = scale_for_exact(in, v, 12, 4);
    if (ok <= 0) return ok < 0 ? 0 : blend_positive_gmp(pts);
    /* d: b0-a0, c0-a0, b1-a1, c1-a1 (x, y each) */
    exact_diff d[8];
    for (int e = 0; e < 2; e++)
        for (int j = 0; j < 2; j++)
            for (int c = 0; c < 2; c++)
                d[4 * e + 2 * j + c] = diff_of(v[6 * e + 2 * (j + 1) + c], v[6 * e + c]);
    double a0[16], a1[16], m1[16], m2[16], m[32];
    int n0 = cross_exact(&d[0], &d[3], &d[1], &d[2], a0);
    int n1 = cross_exact(&d[4], &d[7], &d[5], &d[6], a1);
    if (cm_expansion_sign(n0, a0) <= 0 || cm_expansion_sign(n1, a1) <= 0) return 0;
    int nm1 = cross_exact(&d[0], &d[7], &d[1], &d[6], m1); /* cross(b0-a0, c1-a1) */
    int nm2 = cross_exact(&d[4], &d[3], &d[5], &d[2], m2); /* cross(b1-a1, c0-a0) */
    int nm = cm_expansion_sum(nm1, m1, nm2, m2, m);
    if (cm_expansion_sign(nm, m) >= 0) return 1;
    /* (2M)^2 < 4 A0 A1; times 4 is exact (no overflow, see the top) */
    for (int i = 0; i < n1; i++) a1[i] *= 4.0;
    double scratch[2 * 32 * 33], area[512], square[2048], diff[2560];
    int an = cm_expansion_product(n0, a0, n1, a1, area, scratch);
    int sn = cm_expansion_product(nm, m, nm, m, square, scratch);
    int dn = cm_expansion_diff(an, area, sn, square, diff);
    return cm_expansion_sign(dn, diff) > 0;
}

int cm_blend_positive(const double a0[2], const double b0[2], const double c0[2],
                      const double a1[2], const double b1[2], const double c1[2])
{
    const double *pts[6] = {a0, b0, c0, a1, b1, c1};
    double d[8] = {b0[0] - a0[0], b0[1] - a0[1], c0[0] - a0[0], c0[1] - a0[1],
                   b1[0] - a1[0], b1[1] - a1[1], c1[0] - a1[0], c1[1] - a1[1]};
    if (all_within(d, 8, CM_ORIENT_MIN, CM_ORIENT_MAX)) {
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
    return blend_positive_adapt(pts);
}
