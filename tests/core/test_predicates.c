/* Exact predicates against an independent GMP reference (rational Gaussian
 * elimination of the textbook determinants), on inputs where plain double
 * evaluation gets the sign wrong, at ordinary, huge and tiny scales. */
#include "check.h"
#include "geom/predicates.h"

#include <float.h>
#include <gmp.h>
#include <math.h>
#include <stdint.h>

/* ---- reference ------------------------------------------------------- */

/* Sign of the determinant of the size x size rational matrix m (row-major),
 * by Gaussian elimination; m is destroyed. */
static int rational_det_sign(mpq_t *m, int size)
{
    int sign = 1;
    mpq_t factor;
    mpq_init(factor);
    for (int col = 0; col < size && sign != 0; col++) {
        int pivot = col;
        while (pivot < size && mpq_sgn(m[pivot * size + col]) == 0) pivot++;
        if (pivot == size) {
            sign = 0;
            break;
        }
        if (pivot != col) {
            for (int k = 0; k < size; k++)
                mpq_swap(m[pivot * size + k], m[col * size + k]);
            sign = -sign;
        }
        sign *= mpq_sgn(m[col * size + col]);
        for (int row = col + 1; row < size; row++) {
            mpq_div(factor, m[row * size + col], m[col * size + col]);
            for (int k = col; k < size; k++) {
                mpq_t t;
                mpq_init(t);
                mpq_mul(t, factor, m[col * size + k]);
                mpq_sub(m[row * size + k], m[row * size + k], t);
                mpq_clear(t);
            }
        }
    }
    mpq_clear(factor);
    return sign;
}

/* det | x y 1 | over the rows a, b, c. */
static int ref_orient2d(const double a[2], const double b[2], const double c[2])
{
    const double *p[3] = {a, b, c};
    mpq_t m[9];
    for (int r = 0; r < 3; r++) {
        for (int k = 0; k < 3; k++) mpq_init(m[3 * r + k]);
        mpq_set_d(m[3 * r], p[r][0]);
        mpq_set_d(m[3 * r + 1], p[r][1]);
        mpq_set_ui(m[3 * r + 2], 1, 1);
    }
    int s = rational_det_sign(m, 3);
    for (int k = 0; k < 9; k++) mpq_clear(m[k]);
    return s;
}

/* det | x y x^2+y^2 1 | over the rows a, b, c, d. */
static int ref_incircle(const double a[2], const double b[2],
                        const double c[2], const double d[2])
{
    const double *p[4] = {a, b, c, d};
    mpq_t m[16], t;
    mpq_init(t);
    for (int r = 0; r < 4; r++) {
        for (int k = 0; k < 4; k++) mpq_init(m[4 * r + k]);
        mpq_set_d(m[4 * r], p[r][0]);
        mpq_set_d(m[4 * r + 1], p[r][1]);
        mpq_mul(m[4 * r + 2], m[4 * r], m[4 * r]);
        mpq_mul(t, m[4 * r + 1], m[4 * r + 1]);
        mpq_add(m[4 * r + 2], m[4 * r + 2], t);
        mpq_set_ui(m[4 * r + 3], 1, 1);
    }
    int s = rational_det_sign(m, 4);
    for (int k = 0; k < 16; k++) mpq_clear(m[k]);
    mpq_clear(t);
    return s;
}

static int ref_polygon_orientation(const double *xy, long n)
{
    mpq_t sum, x0, y1, t;
    mpq_inits(sum, x0, y1, t, NULL);
    for (long i = 0; i < n; i++) {
        long j = (i + 1) % n;
        mpq_set_d(x0, xy[2 * i]);
        mpq_set_d(y1, xy[2 * j + 1]);
        mpq_mul(t, x0, y1);
        mpq_add(sum, sum, t);
        mpq_set_d(x0, xy[2 * j]);
        mpq_set_d(y1, xy[2 * i + 1]);
        mpq_mul(t, x0, y1);
        mpq_sub(sum, sum, t);
    }
    int s = mpq_sgn(sum);
    mpq_clears(sum, x0, y1, t, NULL);
    return s;
}

/* ---- plain double evaluation, to show what the filter protects -------- */

static int sign_of(double v)
{
    return (v > 0) - (v < 0);
}

static int naive_orient2d(const double a[2], const double b[2],
                          const double c[2])
{
    return sign_of((b[0] - a[0]) * (c[1] - a[1]) -
                   (b[1] - a[1]) * (c[0] - a[0]));
}

static int naive_incircle(const double a[2], const double b[2],
                          const double c[2], const double d[2])
{
    double adx = a[0] - d[0], ady = a[1] - d[1], bdx = b[0] - d[0];
    double bdy = b[1] - d[1], cdx = c[0] - d[0], cdy = c[1] - d[1];
    return sign_of((adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) +
                   (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy) +
                   (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady));
}

/* ---- random inputs (xorshift64*, local state) ------------------------- */

static uint64_t next_random(uint64_t *state)
{
    *state ^= *state >> 12;
    *state ^= *state << 25;
    *state ^= *state >> 27;
    return *state * 0x2545f4914f6cdd1dULL;
}

static long random_below(uint64_t *state, long bound)
{
    return (long)(next_random(state) % (uint64_t)bound);
}

/* Random sign and 53-bit mantissa, times 2^e with e in [emin, emax]. */
static double random_double(uint64_t *state, int emin, int emax)
{
    double mantissa = (double)(next_random(state) >> 11) * 0x1p-53;
    int e = emin + (int)random_below(state, emax - emin + 1);
    double v = ldexp(mantissa, e);
    return next_random(state) & 1 ? -v : v;
}

/* ---- orient2d -------------------------------------------------------- */

/* Kettner et al., "Classroom examples of robustness problems": p walks a
 * 128 x 128 grid of doubles next to (0.5, 0.5), on and around the line
 * y = x through q and r. Scaling by 2^scale is exact, so the signs must
 * not change with it. */
static void test_orient_grid(int scale)
{
    double q[2] = {ldexp(12, scale), ldexp(12, scale)};
    double r[2] = {ldexp(24, scale), ldexp(24, scale)};
    int mismatches = 0, naive_wrong = 0, zeros = 0, scale_changes = 0;
    int cyclic_breaks = 0;
    for (int i = 0; i < 128; i++) {
        for (int j = 0; j < 128; j++) {
            double u[2] = {0.5 + i * 0x1p-53, 0.5 + j * 0x1p-53};
            double p[2] = {ldexp(u[0], scale), ldexp(u[1], scale)};
            double uq[2] = {12, 12}, ur[2] = {24, 24};
            int exact = cm_orient2d(p, q, r);
            mismatches += exact != ref_orient2d(p, q, r);
            naive_wrong += exact != naive_orient2d(p, q, r);
            zeros += exact == 0;
            scale_changes += exact != cm_orient2d(u, uq, ur);
            cyclic_breaks += exact != cm_orient2d(q, r, p) ||
                             exact != cm_orient2d(r, p, q) ||
                             exact != -cm_orient2d(q, p, r);
        }
    }
    CHECK_MSG(mismatches == 0, "scale 2^%d: %d", scale, mismatches);
    CHECK_MSG(zeros == 128, "scale 2^%d: %d collinear", scale, zeros);
    CHECK_MSG(scale_changes == 0, "scale 2^%d: %d", scale, scale_changes);
    CHECK_MSG(cyclic_breaks == 0, "scale 2^%d: %d", scale, cyclic_breaks);
    /* The point of the exercise: doubles alone get it wrong here (and at
     * 2^+-1000 they overflow or underflow outright). */
    CHECK_MSG(naive_wrong > 100, "scale 2^%d: naive wrong only %d times",
              scale, naive_wrong);
}

/* Points x0 + k*h (small integers, times a common power of two) lie exactly
 * on one line at any scale. */
static void test_orient_exactly_collinear(void)
{
    uint64_t state = 0x1234567;
    int nonzero = 0;
    for (int trial = 0; trial < 3000; trial++) {
        int e = -1074 + (int)random_below(&state, 1074 + 970);
        double base[2], step[2], p[3][2];
        for (int k = 0; k < 2; k++) {
            base[k] = (double)(random_below(&state, 1L << 21) - (1L << 20));
            step[k] = (double)(random_below(&state, 1L << 11) - (1L << 10));
        }
        for (int m = 0; m < 3; m++) {
            double t = (double)(random_below(&state, 1L << 10) - (1L << 9));
            for (int k = 0; k < 2; k++)
                p[m][k] = ldexp(base[k] + t * step[k], e);
        }
        nonzero += cm_orient2d(p[0], p[1], p[2]) != 0;
        nonzero += cm_orient2d(p[2], p[0], p[1]) != 0;
    }
    CHECK_MSG(nonzero == 0, "%d collinear triples not 0", nonzero);

    double o[2] = {0, 0}, big[2] = {1e300, 1e300}, neg[2] = {-1e300, -1e300};
    double tiny[2] = {1e-300, 1e-300}, sub[2] = {4e-320, 4e-320};
    double max[2] = {DBL_MAX, DBL_MAX}, negmax[2] = {-DBL_MAX, -DBL_MAX};
    CHECK(cm_orient2d(big, neg, o) == 0);
    CHECK(cm_orient2d(tiny, sub, o) == 0);
    CHECK(cm_orient2d(max, negmax, tiny) == 0);
    CHECK(cm_orient2d(big, tiny, sub) == 0);
}

/* Nearly collinear points with 30-bit integer coordinates (times a common
 * power of two): the differences are exact but the products are not, the
 * case the exact-differences stage decides without GMP. */
static void test_orient_exact_differences(void)
{
    uint64_t state = 0xabcdef12;
    int mismatches = 0, zeros = 0;
    for (int trial = 0; trial < 20000; trial++) {
        int e = -440 + (int)random_below(&state, 900);
        double p[3][2], d[2];
        for (int k = 0; k < 2; k++) {
            p[0][k] = (double)(random_below(&state, 1L << 29) - (1L << 28));
            d[k] = (double)(random_below(&state, 1L << 19) - (1L << 18));
        }
        for (int m = 1; m < 3; m++) { /* on the line, give or take a unit */
            double j = (double)((long)random_below(&state, 1024) - 512);
            for (int k = 0; k < 2; k++)
                p[m][k] = p[0][k] + j * d[k] + (double)((int)random_below(&state, 3) - 1) * (trial % 2 == 0);
        }
        for (int m = 0; m < 3; m++)
            for (int k = 0; k < 2; k++) p[m][k] = ldexp(p[m][k], e);
        int s = cm_orient2d(p[0], p[1], p[2]);
        mismatches += s != ref_orient2d(p[0], p[1], p[2]);
        mismatches += cm_orient2d(p[1], p[2], p[0]) != s || cm_orient2d(p[1], p[0], p[2]) != -s;
        zeros += s == 0;
    }
    CHECK_MSG(mismatches == 0, "%d", mismatches);
    CHECK_MSG(zeros > 5000 && zeros < 15000, "%d exactly collinear of 20000", zeros);
}

/* Triples where some points share a coordinate (outline points on
 * axis-parallel lines, at any scale), against the reference: where a zero
 * difference sits in each product the sign is 0 without expansions, and
 * where only one product has one it is not. */
static void test_orient_shared_coordinates(void)
{
    uint64_t state = 0x5eed1234;
    int mismatches = 0, zeros = 0;
    for (int trial = 0; trial < 20000; trial++) {
        int e = -1074 + (int)random_below(&state, 1074 + 970);
        double p[3][2];
        for (int m = 0; m < 3; m++)
            for (int k = 0; k < 2; k++)
                p[m][k] = ldexp((double)(random_below(&state, 1L << 30) - (1L << 29)), e);
        /* one to three of the points take another's x or y */
        for (int c = 0, n = 1 + (int)random_below(&state, 3); c < n; c++) {
            int to = (int)random_below(&state, 3), from = (int)random_below(&state, 3), k = (int)random_below(&state, 2);
            p[to][k] = p[from][k];
        }
        int s = cm_orient2d(p[0], p[1], p[2]);
        mismatches += s != ref_orient2d(p[0], p[1], p[2]);
        mismatches += cm_orient2d_adaptive(p[2], p[0], p[1]) != s;
        zeros += s == 0;
    }
    CHECK_MSG(mismatches == 0, "%d", mismatches);
    CHECK_MSG(zeros > 1000 && zeros < 19000, "%d of 20000 on one line", zeros);
}

static void test_orient_extreme_random(void)
{
    static const int ranges[][2] = {
        {990, 1023}, {-1074, -990}, {-1074, 1023}, {480, 520}, {-520, -480},
    };
    uint64_t state = 0xfeedbeef;
    for (int r = 0; r < 5; r++) {
        int mismatches = 0, antisymmetry_breaks = 0;
        for (int trial = 0; trial < 2000; trial++) {
            double p[3][2];
            for (int m = 0; m < 3; m++)
                for (int k = 0; k < 2; k++)
                    p[m][k] = random_double(&state, ranges[r][0], ranges[r][1]);
            if (trial % 2) { /* nearly collinear: c near the midpoint */
                p[2][0] = p[0][0] / 2 + p[1][0] / 2;
                p[2][1] = p[0][1] / 2 + p[1][1] / 2;
            }
            int s = cm_orient2d(p[0], p[1], p[2]);
            mismatches += s != ref_orient2d(p[0], p[1], p[2]);
            antisymmetry_breaks += s != -cm_orient2d(p[1], p[0], p[2]);
        }
        CHECK_MSG(mismatches == 0, "range %d: %d", r, mismatches);
        CHECK_MSG(antisymmetry_breaks == 0, "range %d: %d", r,
                  antisymmetry_breaks);
    }
}

/* cm_orient2d_tame skips the filter's magnitude checks for coordinates
 * 0 or within 2^[-400, 400]: the same signs as the reference there,
 * extremes of the range and nearly collinear triples included. */
static void test_orient_tame(void)
{
    double edge[] = {0.0, 0x1p-400, -0x1p-400, 0x1p+400, -0x1p+400};
    CHECK(cm_coords_tame(edge, 5));
    double out_low = 0x1.fffffffffffffp-401, out_high = 0x1.0000000000001p+400;
    CHECK(!cm_coords_tame(&out_low, 1) && !cm_coords_tame(&out_high, 1));
    static const int ranges[][2] = {{-400, -360}, {360, 399}, {-400, 399}, {-60, 60}};
    uint64_t state = 0x7a3e5;
    int tested = 0, mismatches = 0;
    for (int r = 0; r < 4; r++)
        for (int trial = 0; trial < 4000; trial++) {
            double p[3][2];
            for (int m = 0; m < 3; m++)
                for (int k = 0; k < 2; k++)
                    p[m][k] = trial % 7 == 0 && k ? 0.0 : random_double(&state, ranges[r][0], ranges[r][1]);
            if (trial % 2) { /* nearly collinear: c near the midpoint */
                p[2][0] = p[0][0] / 2 + p[1][0] / 2;
                p[2][1] = p[0][1] / 2 + p[1][1] / 2;
            }
            if (!cm_coords_tame(&p[0][0], 6)) continue;
            tested++;
            mismatches += cm_orient2d_tame(p[0], p[1], p[2]) != ref_orient2d(p[0], p[1], p[2]);
            mismatches += cm_orient2d_tame(p[1], p[0], p[2]) != -ref_orient2d(p[0], p[1], p[2]);
        }
    for (int i = 0; i < 128; i++) /* the grid next to (0.5, 0.5) */
        for (int j = 0; j < 128; j++) {
            double p[2] = {0.5 + i * 0x1p-53, 0.5 + j * 0x1p-53}, q[2] = {12, 12}, c[2] = {24, 24};
            tested++;
            mismatches += cm_orient2d_tame(p, q, c) != ref_orient2d(p, q, c);
        }
    CHECK_MSG(tested > 20000, "only %d tame triples", tested);
    CHECK_MSG(mismatches == 0, "%d of %d", mismatches, tested);
}

/* ---- incircle -------------------------------------------------------- */

/* d walks a grid next to the fourth corner of the square through a, b, c;
 * spacing 2^-49 is the spacing of doubles near 12. */
static void test_incircle_grid(int scale)
{
    double a[2] = {ldexp(12, scale), ldexp(12, scale)};
    double b[2] = {ldexp(-12, scale), ldexp(12, scale)};
    double c[2] = {ldexp(-12, scale), ldexp(-12, scale)};
    double ua[2] = {12, 12}, ub[2] = {-12, 12}, uc[2] = {-12, -12};
    int mismatches = 0, naive_wrong = 0, zeros = 0, scale_changes = 0;
    int symmetry_breaks = 0;
    for (int i = -40; i < 40; i++) {
        for (int j = -40; j < 40; j++) {
            double u[2] = {12 + i * 0x1p-49, -12 + j * 0x1p-49};
            double d[2] = {ldexp(u[0], scale), ldexp(u[1], scale)};
            int exact = cm_incircle(a, b, c, d);
            mismatches += exact != ref_incircle(a, b, c, d);
            naive_wrong += exact != naive_incircle(a, b, c, d);
            zeros += exact == 0;
            scale_changes += exact != cm_incircle(ua, ub, uc, u);
            symmetry_breaks += exact != cm_incircle(b, c, a, d) ||
                               exact != -cm_incircle(b, a, c, d);
        }
    }
    CHECK_MSG(mismatches == 0, "scale 2^%d: %d", scale, mismatches);
    CHECK_MSG(zeros == 1, "scale 2^%d: %d cocircular", scale, zeros);
    CHECK_MSG(scale_changes == 0, "scale 2^%d: %d", scale, scale_changes);
    CHECK_MSG(symmetry_breaks == 0, "scale 2^%d: %d", scale, symmetry_breaks);
    CHECK_MSG(naive_wrong > 20, "scale 2^%d: naive wrong only %d times",
              scale, naive_wrong);
}

/* The 36 integer points on the circle of radius 65 (65^2 = 16^2 + 63^2 =
 * 25^2 + 60^2 = 33^2 + 56^2 = 39^2 + 52^2 = 0^2 + 65^2), shifted and scaled
 * exactly: any four are cocircular. Moving d one step inward or outward
 * must agree with the reference. */
static void test_incircle_exactly_cocircular(void)
{
    static const int legs[][2] = {{16, 63}, {25, 60}, {33, 56}, {39, 52}};
    double circle[36][2];
    int count = 0;
    for (int l = 0; l < 4; l++)
        for (int sx = -1; sx <= 1; sx += 2)
            for (int sy = -1; sy <= 1; sy += 2) {
                circle[count][0] = sx * legs[l][0];
                circle[count++][1] = sy * legs[l][1];
                circle[count][0] = sx * legs[l][1];
                circle[count++][1] = sy * legs[l][0];
            }
    for (int s = -1; s <= 1; s += 2) {
        circle[count][0] = 65 * s;
        circle[count++][1] = 0;
        circle[count][0] = 0;
        circle[count++][1] = 65 * s;
    }
    static const int scales[] = {-1000, -600, -300, 0, 300, 600, 900};
    uint64_t state = 42;
    int nonzero = 0, mismatches = 0, off_circle_zero = 0;
    for (int trial = 0; trial < 2000; trial++) {
        int scale = scales[trial % 7];
        double shift = (double)(random_below(&state, 2001) - 1000);
        double p[4][2];
        for (int m = 0; m < 4; m++) {
            long pick = random_below(&state, 36);
            for (int k = 0; k < 2; k++)
                p[m][k] = ldexp(circle[pick][k] + shift, scale);
        }
        nonzero += cm_incircle(p[0], p[1], p[2], p[3]) != 0;
        /* nudge d one representable step towards or away from the centre */
        double centre = ldexp(shift, scale);
        int away = trial & 1;
        int k = (int)(trial / 2 % 2);
        p[3][k] = nextafter(p[3][k], (p[3][k] > centre) == away ? INFINITY
                                                                 : -INFINITY);
        int s = cm_incircle(p[0], p[1], p[2], p[3]);
        mismatches += s != ref_incircle(p[0], p[1], p[2], p[3]);
        off_circle_zero += s == 0 && ref_orient2d(p[0], p[1], p[2]) != 0;
    }
    CHECK_MSG(nonzero == 0, "%d cocircular quadruples not 0", nonzero);
    CHECK_MSG(mismatches == 0, "%d nudged quadruples wrong", mismatches);
    CHECK_MSG(off_circle_zero == 0, "%d nudged points still on the circle",
              off_circle_zero);
}

static void test_incircle_extreme_random(void)
{
    static const int ranges[][2] = {
        {990, 1023}, {-1074, -990}, {-1074, 1023}, {180, 220}, {-220, -180},
    };
    uint64_t state = 0xabcdef;
    for (int r = 0; r < 5; r++) {
        int mismatches = 0, symmetry_breaks = 0;
        for (int trial = 0; trial < 1000; trial++) {
            double p[4][2];
            for (int m = 0; m < 4; m++)
                for (int k = 0; k < 2; k++)
                    p[m][k] = random_double(&state, ranges[r][0], ranges[r][1]);
            int s = cm_incircle(p[0], p[1], p[2], p[3]);
            mismatches += s != ref_incircle(p[0], p[1], p[2], p[3]);
            symmetry_breaks += s != cm_incircle(p[2], p[0], p[1], p[3]) ||
                               s != -cm_incircle(p[0], p[2], p[1], p[3]);
        }
        CHECK_MSG(mismatches == 0, "range %d: %d", r, mismatches);
        CHECK_MSG(symmetry_breaks == 0, "range %d: %d", r, symmetry_breaks);
    }
}

/* Products that underflow lose their relative accuracy: here bdx*cdy is
 * 0.55 * 2^-1074 but rounds to 2^-1074, and the huge lift of a turns that
 * into the wrong sign. A bound that trusts relative errors alone, or any
 * double evaluation, says +1. */
static void test_incircle_partial_underflow(void)
{
    double a[2] = {0x1p300, 0x1p300}, b[2] = {0x1p-1074, 0};
    double c[2] = {0x1.3988p150, 0.55}, d[2] = {0, 0};
    CHECK(ref_incircle(a, b, c, d) == -1);
    CHECK(naive_incircle(a, b, c, d) == 1);
    CHECK(cm_incircle(a, b, c, d) == -1);
}

/* ---- small integer grids: every kind of degeneracy --------------------- */

static void test_grid_symmetries(void)
{
    uint64_t state = 7;
    int orient_wrong = 0, incircle_wrong = 0, broken = 0;
    for (int trial = 0; trial < 5000; trial++) {
        double p[4][2];
        for (int m = 0; m < 4; m++)
            for (int k = 0; k < 2; k++)
                p[m][k] = (double)random_below(&state, 4) * 0.1;
        int o = cm_orient2d(p[0], p[1], p[2]);
        orient_wrong += o != ref_orient2d(p[0], p[1], p[2]);
        broken += o != cm_orient2d(p[1], p[2], p[0]) ||
                  o != -cm_orient2d(p[1], p[0], p[2]) ||
                  o != -cm_orient2d(p[0], p[2], p[1]);
        int c = cm_incircle(p[0], p[1], p[2], p[3]);
        incircle_wrong += c != ref_incircle(p[0], p[1], p[2], p[3]);
        broken += c != cm_incircle(p[1], p[2], p[0], p[3]) ||
                  c != -cm_incircle(p[1], p[0], p[2], p[3]);
    }
    CHECK_MSG(orient_wrong == 0, "%d", orient_wrong);
    CHECK_MSG(incircle_wrong == 0, "%d", incircle_wrong);
    CHECK_MSG(broken == 0, "%d", broken);
}

static void test_incircle_basics(void)
{
    double a[2] = {1, 0}, b[2] = {0, 1}, c[2] = {-1, 0};
    double inside[2] = {0, 0}, outside[2] = {2, 2}, on[2] = {0, -1};
    CHECK(cm_incircle(a, b, c, inside) == 1);
    CHECK(cm_incircle(a, b, c, outside) == -1);
    CHECK(cm_incircle(a, b, c, on) == 0);
    CHECK(cm_incircle(c, b, a, inside) == -1); /* clockwise flips the sign */
    CHECK(cm_orient2d(a, b, c) == 1);
    CHECK(cm_orient2d(c, b, a) == -1);
}

/* ---- segments -------------------------------------------------------- */

static int segments(double ax, double ay, double bx, double by, double cx,
                    double cy, double dx, double dy)
{
    double a[2] = {ax, ay}, b[2] = {bx, by}, c[2] = {cx, cy}, d[2] = {dx, dy};
    int r = cm_segments_intersect(a, b, c, d);
    /* the answer must not depend on the order of segments or endpoints */
    if (cm_segments_intersect(c, d, a, b) != r ||
        cm_segments_intersect(b, a, d, c) != r)
        return -1;
    return r;
}

static void test_segments_intersect(void)
{
    CHECK(segments(0, 0, 2, 2, 0, 2, 2, 0) == 1);       /* X */
    CHECK(segments(0, 0, 2, 0, 1, 0, 1, 5) == 2);       /* T */
    CHECK(segments(0, 0, 2, 0, 2, 0, 3, 1) == 2);       /* shared endpoint */
    CHECK(segments(0, 0, 4, 0, 1, 0, 3, 0) == 2);       /* contained */
    CHECK(segments(0, 0, 4, 0, 2, 0, 6, 0) == 2);       /* overlap */
    CHECK(segments(0, 0, 1, 0, 1, 0, 2, 0) == 2);       /* collinear touch */
    CHECK(segments(0, 0, 1, 0, 2, 0, 3, 0) == 0);       /* collinear apart */
    CHECK(segments(0, 0, 0, 1, 0, 2, 0, 3) == 0);       /* vertical apart */
    CHECK(segments(0, 0, 0, 2, 0, 1, 0, 3) == 2);       /* vertical overlap */
    CHECK(segments(0, 0, 2, 0, 0, 1, 2, 1) == 0);       /* parallel */
    CHECK(segments(0, 0, 2, 2, 3, 0, 1.6, 1.4) == 0);   /* near miss */
    CHECK(segments(0, 0, 2, 2, 1, 1, 1, 1) == 2);       /* point on it */
    CHECK(segments(0, 0, 2, 2, 1, 1.5, 1, 1.5) == 0);   /* point off it */
    CHECK(segments(1, 1, 1, 1, 1, 1, 1, 1) == 2);       /* same point */
    /* crossing right next to an endpoint: only exact arithmetic tells */
    CHECK(segments(0.5, 0.5, 24, 24, 0.5 + 0x1p-52, 0.5, 0.5,
                   0.5 + 0x1p-52) == 1);
    CHECK(segments(0.5 + 0x1p-52, 0.5 + 0x1p-52, 24, 24, 0.5 + 0x1p-52, 0.5,
                   0.5, 0.5 + 0x1p-52) == 0);
    CHECK(segments(-1e300, -1e300, 1e300, 1e300, -1e300, 1e300, 1e300,
                   -1e300) == 1);
    CHECK(segments(1e-300, 0, 3e-300, 0, 2e-300, 0, 2e-300, 1e-310) == 2);
}

/* Every pair of segments with ends on a 4 x 4 integer grid (collinear,
 * touching, overlapping, with bounding boxes that only touch), scaled by
 * 2^scale, against the textbook classification in integer arithmetic:
 * 1 proper crossing, 2 a common point otherwise, 0 none. */
static long cross_sign(const long *a, const long *b, const long *c)
{
    long v = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    return (v > 0) - (v < 0);
}

static int on_collinear(const long *a, const long *b, const long *p)
{
    return p[0] >= (a[0] < b[0] ? a[0] : b[0]) && p[0] <= (a[0] > b[0] ? a[0] : b[0]) &&
           p[1] >= (a[1] < b[1] ? a[1] : b[1]) && p[1] <= (a[1] > b[1] ? a[1] : b[1]);
}

static int ref_segments(const long *a, const long *b, const long *c, const long *d)
{
    long o1 = cross_sign(a, b, c), o2 = cross_sign(a, b, d), o3 = cross_sign(c, d, a), o4 = cross_sign(c, d, b);
    if (o1 * o2 < 0 && o3 * o4 < 0) return 1;
    if ((o1 == 0 && on_collinear(a, b, c)) || (o2 == 0 && on_collinear(a, b, d)) ||
        (o3 == 0 && on_collinear(c, d, a)) || (o4 == 0 && on_collinear(c, d, b)))
        return 2;
    return 0;
}

static void test_segments_grid(int scale)
{
    long p[16][2];
    for (int i = 0; i < 16; i++) p[i][0] = i % 4, p[i][1] = i / 4;
    long mismatches = 0, counts[3] = {0, 0, 0};
    for (int a = 0; a < 16; a++)
        for (int b = 0; b < 16; b++)
            for (int c = 0; c < 16; c++)
                for (int d = 0; d < 16; d++) {
                    double x[4][2];
                    const int at[4] = {a, b, c, d};
                    for (int i = 0; i < 4; i++)
                        x[i][0] = ldexp((double)p[at[i]][0], scale), x[i][1] = ldexp((double)p[at[i]][1], scale);
                    int want = ref_segments(p[a], p[b], p[c], p[d]);
                    mismatches += cm_segments_intersect(x[0], x[1], x[2], x[3]) != want;
                    counts[want]++;
                }
    CHECK_MSG(mismatches == 0, "scale 2^%d: %ld of 65536", scale, mismatches);
    /* all three outcomes occur often */
    CHECK_MSG(counts[0] > 10000 && counts[1] > 1000 && counts[2] > 10000, "scale 2^%d: %ld %ld %ld", scale,
              counts[0], counts[1], counts[2]);
}

/* ---- polygon orientation ------------------------------------------------ */

static void test_polygon_orientation(void)
{
    double square[] = {0, 0, 1, 0, 1, 1, 0, 1};
    double clockwise[] = {0, 0, 0, 1, 1, 1, 1, 0};
    double line[] = {0, 0, 1, 1, 3, 3, 2, 2};
    double bowtie[] = {0, 0, 2, 2, 2, 0, 0, 2}; /* lobes cancel exactly */
    double huge[] = {-1e300, -1e300, 1e300, -1e300, 0, 1e300};
    double tiny[] = {0, 0, 1e-310, 0, 0, 1e-310};
    CHECK(cm_polygon_orientation(square, 4) == 1);
    CHECK(cm_polygon_orientation(clockwise, 4) == -1);
    CHECK(cm_polygon_orientation(line, 4) == 0);
    CHECK(cm_polygon_orientation(bowtie, 4) == 0);
    CHECK(cm_polygon_orientation(huge, 3) == 1);
    CHECK(cm_polygon_orientation(tiny, 3) == 1);
    CHECK(cm_polygon_orientation(square, 2) == 0);

    /* three subnormal shoelace products 0.55, 1.2 and 0.55 (times 2^-1074)
     * all round to 2^-1074: in doubles the area is +2^-1074, exactly it is
     * negative */
    double q = 0x1p-537;
    double underflow[] = {0, 0, 0.55 * q, 0, 0, q, 1.2 * q, 0, 0, 0.55 / 1.2 * q};
    CHECK(ref_polygon_orientation(underflow, 5) == -1);
    CHECK(cm_polygon_orientation(underflow, 5) == -1);

    /* near-degenerate triangles from the orient2d grid, far from the
     * origin, and n-gons that repeat them along a line */
    int mismatches = 0;
    for (int i = 0; i < 32; i++) {
        for (int j = 0; j < 32; j++) {
            double tri[] = {0.5 + i * 0x1p-53, 0.5 + j * 0x1p-53, 12, 12, 24, 24};
            mismatches += cm_polygon_orientation(tri, 3) !=
                          cm_orient2d(tri, tri + 2, tri + 4);
            double poly[16];
            for (int k = 0; k < 8; k++) { /* p, then collinear points */
                poly[2 * k] = k == 0 ? tri[0] : 12.0 * k;
                poly[2 * k + 1] = k == 0 ? tri[1] : 12.0 * k;
            }
            mismatches += cm_polygon_orientation(poly, 8) !=
                          ref_polygon_orientation(poly, 8);
        }
    }
    CHECK_MSG(mismatches == 0, "%d", mismatches);

    uint64_t state = 99;
    int random_mismatches = 0;
    for (int trial = 0; trial < 600; trial++) {
        double poly[2 * 40];
        long n = 3 + random_below(&state, 38);
        int e = (int)random_below(&state, 3);
        for (long k = 0; k < 2 * n; k++) {
            poly[k] = e == 0   ? (double)random_below(&state, 3)
                      : e == 1 ? random_double(&state, -1074, 1023)
                               : 1e15 + (double)random_below(&state, 5);
        }
        random_mismatches += cm_polygon_orientation(poly, n) !=
                             ref_polygon_orientation(poly, n);
    }
    CHECK_MSG(random_mismatches == 0, "%d", random_mismatches);
}

int main(void)
{
    test_orient_exact_differences();
    test_incircle_basics();
    test_orient_grid(0);
    test_orient_grid(1000);
    test_orient_grid(-1000);
    test_orient_exactly_collinear();
    test_orient_shared_coordinates();
    test_orient_extreme_random();
    test_orient_tame();
    test_incircle_grid(0);
    test_incircle_grid(900);
    test_incircle_grid(-900);
    test_incircle_exactly_cocircular();
    test_incircle_extreme_random();
    test_incircle_partial_underflow();
    test_grid_symmetries();
    test_segments_intersect();
    test_segments_grid(0);
    test_segments_grid(-1000);
    test_segments_grid(1000);
    test_polygon_orientation();
    return check_summary("test_predicates");
}
