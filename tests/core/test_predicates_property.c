/* The predicates on doubles against exact integer evaluation with GMP, on
 * 2.3 million inputs built to reach every stage of the adaptive
 * evaluation: random coordinates over the whole double range, exactly degenerate ones
 * (collinear, cocircular, coplanar, a blend through a flat triangle) whose
 * coordinate differences are exact (lattice points times a power of two)
 * or not (points of lines and rectangles with coordinates of unrelated
 * magnitudes), the same moved by one unit in the last place, and nearly
 * degenerate ones rounded onto a line. Each family runs at ordinary, huge
 * and tiny scales. Any sign that differs from the reference fails. */
#include "check.h"
#include "geom/expansion.h"
#include "geom/predicates.h"
#include "random_polygons.h"

#include <gmp.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>

/* ---- reference: integers scaled by one power of two -------------------- */

#define MAX_VALUES 16

/* z[i] = v[i] 2^-emin, integers: every finite double is m 2^e with an
 * integer m, and emin is the smallest such e among the values. */
static void to_integers(const double *v, int count, mpz_t *z)
{
    long mant[MAX_VALUES];
    int exp2[MAX_VALUES], emin = INT_MAX;
    for (int i = 0; i < count; i++) {
        int e = 0;
        mant[i] = v[i] == 0.0 ? 0 : (long)ldexp(frexp(v[i], &e), 53);
        exp2[i] = e - 53;
        if (mant[i] != 0 && exp2[i] < emin) emin = exp2[i];
    }
    for (int i = 0; i < count; i++) {
        mpz_set_si(z[i], mant[i]);
        if (mant[i] != 0) mpz_mul_2exp(z[i], z[i], (mp_bitcnt_t)(exp2[i] - emin));
    }
}

static mpz_t zv[MAX_VALUES], t0, t1, t2, t3, t4;

static void ref_init(void)
{
    for (int i = 0; i < MAX_VALUES; i++) mpz_init(zv[i]);
    mpz_inits(t0, t1, t2, t3, t4, NULL);
}

static void ref_clear(void)
{
    for (int i = 0; i < MAX_VALUES; i++) mpz_clear(zv[i]);
    mpz_clears(t0, t1, t2, t3, t4, NULL);
}

/* out = p q - r s */
static void cross(mpz_t out, const mpz_t p, const mpz_t q, const mpz_t r, const mpz_t s)
{
    mpz_mul(out, p, q);
    mpz_submul(out, r, s);
}

/* det | x y 1 | over the rows a, b, c, expanded along the last column */
static int ref_orient2d(const double a[2], const double b[2], const double c[2])
{
    double v[6] = {a[0], a[1], b[0], b[1], c[0], c[1]};
    to_integers(v, 6, zv);
    cross(t0, zv[2], zv[5], zv[4], zv[3]);  /* bx cy - cx by */
    mpz_submul(t0, zv[0], zv[5]);           /* - (ax cy - cx ay) */
    mpz_addmul(t0, zv[4], zv[1]);
    mpz_addmul(t0, zv[0], zv[3]);           /* + ax by - bx ay */
    mpz_submul(t0, zv[2], zv[1]);
    return mpz_sgn(t0);
}

/* det | x - dx, y - dy, (x - dx)^2 + (y - dy)^2 | over a, b, c */
static int ref_incircle(const double a[2], const double b[2], const double c[2],
                        const double d[2])
{
    double v[8] = {a[0], a[1], b[0], b[1], c[0], c[1], d[0], d[1]};
    to_integers(v, 8, zv);
    for (int i = 0; i < 6; i++) mpz_sub(zv[i], zv[i], zv[6 + i % 2]);
    mpz_set_ui(t4, 0);
    for (int r = 0; r < 3; r++) {
        int p = 2 * ((r + 1) % 3), q = 2 * ((r + 2) % 3);
        cross(t0, zv[p], zv[q + 1], zv[q], zv[p + 1]);
        mpz_mul(t1, zv[2 * r], zv[2 * r]);
        mpz_addmul(t1, zv[2 * r + 1], zv[2 * r + 1]);
        mpz_addmul(t4, t0, t1);
    }
    return mpz_sgn(t4);
}

/* det [b - a, c - a, d - a], along the first row */
static int ref_orient3d(const double a[3], const double b[3], const double c[3],
                        const double d[3])
{
    double v[12] = {b[0], b[1], b[2], c[0], c[1], c[2], d[0], d[1], d[2], a[0], a[1], a[2]};
    to_integers(v, 12, zv);
    for (int i = 0; i < 9; i++) mpz_sub(zv[i], zv[i], zv[9 + i % 3]);
    cross(t0, zv[4], zv[8], zv[5], zv[7]);
    mpz_mul(t4, zv[0], t0);
    cross(t0, zv[3], zv[8], zv[5], zv[6]);
    mpz_submul(t4, zv[1], t0);
    cross(t0, zv[3], zv[7], zv[4], zv[6]);
    mpz_addmul(t4, zv[2], t0);
    return mpz_sgn(t4);
}

/* doubled area of the triangle with integer corners z[i], z[j], z[k] */
static void area2(mpz_t out, int i, int j, int k, mpz_t *z)
{
    mpz_sub(t0, z[2 * j], z[2 * i]);
    mpz_sub(t1, z[2 * j + 1], z[2 * i + 1]);
    mpz_sub(t2, z[2 * k], z[2 * i]);
    mpz_sub(t3, z[2 * k + 1], z[2 * i + 1]);
    cross(out, t0, t3, t1, t2);
}

/* The doubled area of the blend is the quadratic q(s) = A0 (1-s)^2 +
 * 2 M s(1-s) + A1 s^2; q(1/2) from the midpoint triangle (corners doubled,
 * area times 4) gives 2M = 4 q(1/2) - A0 - A1. q > 0 on [0, 1] iff A0 > 0,
 * A1 > 0 and, if M < 0, its vertex value A0 - M^2 / A1 > 0 (the vertex
 * s / (1 - s) = -M / A1 lies in (0, 1) then). */
static int ref_blend_positive(const double a0[2], const double b0[2], const double c0[2],
                              const double a1[2], const double b1[2], const double c1[2])
{
    const double *p[6] = {a0, b0, c0, a1, b1, c1};
    double v[12];
    for (int i = 0; i < 6; i++) v[2 * i] = p[i][0], v[2 * i + 1] = p[i][1];
    to_integers(v, 12, zv);
    mpz_t end0, end1, m2, mid[6];
    mpz_inits(end0, end1, m2, NULL);
    for (int i = 0; i < 6; i++) {
        mpz_init(mid[i]);
        mpz_add(mid[i], zv[i], zv[6 + i]);
    }
    area2(end0, 0, 1, 2, zv);
    area2(end1, 3, 4, 5, zv);
    area2(m2, 0, 1, 2, mid);
    mpz_sub(m2, m2, end0);
    mpz_sub(m2, m2, end1);
    int positive = mpz_sgn(end0) > 0 && mpz_sgn(end1) > 0;
    if (positive && mpz_sgn(m2) < 0) {
        mpz_mul(t4, m2, m2); /* 4 M^2 < 4 A0 A1 */
        mpz_mul(t0, end0, end1);
        mpz_mul_2exp(t0, t0, 2);
        positive = mpz_cmp(t4, t0) < 0;
    }
    for (int i = 0; i < 6; i++) mpz_clear(mid[i]);
    mpz_clears(end0, end1, m2, NULL);
    return positive;
}

static int ref_polygon_orientation(const double *xy, long n)
{
    mpz_t *z = malloc(sizeof *z * (size_t)(2 * n));
    int emin = INT_MAX;
    for (long i = 0; i < 2 * n; i++) {
        int e;
        if (xy[i] != 0.0 && (frexp(xy[i], &e), e - 53 < emin)) emin = e - 53;
    }
    for (long i = 0; i < 2 * n; i++) {
        int e = 0;
        long m = xy[i] == 0.0 ? 0 : (long)ldexp(frexp(xy[i], &e), 53);
        mpz_init_set_si(z[i], m);
        if (m != 0) mpz_mul_2exp(z[i], z[i], (mp_bitcnt_t)(e - 53 - emin));
    }
    mpz_set_ui(t4, 0);
    for (long i = 0; i < n; i++) {
        long j = (i + 1) % n;
        mpz_addmul(t4, z[2 * i], z[2 * j + 1]);
        mpz_submul(t4, z[2 * j], z[2 * i + 1]);
    }
    for (long i = 0; i < 2 * n; i++) mpz_clear(z[i]);
    free(z);
    return mpz_sgn(t4);
}

/* ---- inputs ------------------------------------------------------------- */

/* Random sign and 53-bit mantissa times 2^e, e uniform in [emin, emax]. */
static double random_double(rp_rng *rng, int emin, int emax)
{
    double m = ldexp((double)((rp_next(rng) >> 11) | (1ull << 52)), -53);
    double v = ldexp(m, emin + (int)rp_below(rng, (uint64_t)(emax - emin + 1)));
    return rp_next(rng) & 1 ? -v : v;
}

/* A random double with `bits` significant bits (odd mantissa), 2^e scale. */
static double random_short(rp_rng *rng, int bits, int e)
{
    double m = (double)((rp_next(rng) >> (64 - bits)) | 1);
    double v = ldexp(m, e);
    return rp_next(rng) & 1 ? -v : v;
}

static long random_int(rp_rng *rng, long half)
{
    return (long)rp_below(rng, (uint64_t)(2 * half + 1)) - half;
}

/* One unit in the last place up or down (0 stays 0 half the time, else
 * becomes the smallest subnormal). */
static double nudge(rp_rng *rng, double v)
{
    return nextafter(v, rp_next(rng) & 1 ? INFINITY : -INFINITY);
}

/* The scales the families run at: ordinary, then towards both ends of the
 * double range (the caller keeps the values finite). */
static int random_scale(rp_rng *rng, int spread)
{
    switch (rp_below(rng, 4)) {
    case 0: return (int)random_int(rng, 8);
    case 1: return (int)random_int(rng, spread);
    case 2: return spread - (int)rp_below(rng, 40);
    default: return -spread + (int)rp_below(rng, 40);
    }
}

/* [lo, hi]: the whole exponent range every fourth time, else a window of
 * up to `width` binades anywhere in it. */
static void random_window(rp_rng *rng, long round, int width, int *lo, int *hi)
{
    if (round % 4 == 0) {
        *lo = -1074, *hi = 1020;
        return;
    }
    *lo = -1074 + (int)rp_below(rng, 2094 - (uint64_t)width);
    *hi = *lo + (int)rp_below(rng, (uint64_t)width);
}

/* ---- orient2d ------------------------------------------------------------- */

typedef struct {
    long cases, mismatches, zeros;
} tally;

static void count(tally *t, int got, int want)
{
    t->cases++;
    t->mismatches += got != want;
    t->zeros += want == 0;
}

static void report(const char *what, const tally *t, double min_zero_share)
{
    CHECK_MSG(t->mismatches == 0, "%s: %ld of %ld signs wrong", what, t->mismatches, t->cases);
    /* the family is degenerate as built (guards the generator itself) */
    CHECK_MSG(t->zeros >= min_zero_share * (double)t->cases, "%s: only %ld zeros of %ld", what,
              t->zeros, t->cases);
}

static void check_orient2d(tally *t, double p[3][2])
{
    count(t, cm_orient2d(p[0], p[1], p[2]), ref_orient2d(p[0], p[1], p[2]));
}

static void test_orient2d(long rounds)
{
    rp_rng rng = {0x0123456789abcdefull};
    tally random = {0}, lattice = {0}, line = {0}, moved = {0}, rounded = {0};
    double p[3][2];
    for (long r = 0; r < rounds; r++) {
        /* random over the whole range, or within one random window */
        int lo, hi;
        random_window(&rng, r, 60, &lo, &hi);
        for (int m = 0; m < 3; m++)
            for (int k = 0; k < 2; k++) p[m][k] = random_double(&rng, lo, hi);
        check_orient2d(&random, p);

        /* lattice points base + t step times 2^e: exact differences */
        int e = random_scale(&rng, 960);
        long base[2] = {random_int(&rng, 1L << 40), random_int(&rng, 1L << 40)};
        long step[2] = {random_int(&rng, 1L << 10), random_int(&rng, 1L << 10)};
        for (int m = 0; m < 3; m++) {
            long s = random_int(&rng, 1L << 10);
            for (int k = 0; k < 2; k++) p[m][k] = ldexp((double)(base[k] + s * step[k]), e);
        }
        check_orient2d(&lattice, p);
        {
            double *q = &p[rp_below(&rng, 3)][rp_below(&rng, 2)];
            *q = nudge(&rng, *q);
        }
        check_orient2d(&moved, p);

        /* (q t, p t) on a line through 0, t of unrelated magnitudes: the
         * differences are not exact; then translated by a lattice vector
         * when that stays exact */
        long slope[2] = {random_int(&rng, 1L << 11), random_int(&rng, 1L << 11)};
        int e0 = random_scale(&rng, 900);
        for (int m = 0; m < 3; m++) {
            double tv = random_short(&rng, 40, e0 - (int)rp_below(&rng, 120));
            for (int k = 0; k < 2; k++) p[m][k] = (double)slope[k] * tv;
        }
        check_orient2d(&line, p);
        int m = (int)rp_below(&rng, 3), k = (int)rp_below(&rng, 2);
        p[m][k] = nudge(&rng, p[m][k]);
        check_orient2d(&moved, p);

        /* rounded onto the line through two random points */
        int er = random_scale(&rng, 900);
        for (int m2 = 0; m2 < 2; m2++)
            for (int k2 = 0; k2 < 2; k2++) p[m2][k2] = random_double(&rng, er - 30, er);
        double s = rp_uniform(&rng) * 4.0 - 1.5;
        for (int k2 = 0; k2 < 2; k2++) p[2][k2] = p[0][k2] + s * (p[1][k2] - p[0][k2]);
        check_orient2d(&rounded, p);
    }
    report("orient2d random", &random, 0.0);
    report("orient2d lattice collinear", &lattice, 0.99);
    report("orient2d collinear, inexact differences", &line, 0.99);
    report("orient2d collinear moved one ulp", &moved, 0.0);
    report("orient2d rounded onto a line", &rounded, 0.0);
    CHECK_MSG(moved.zeros < moved.cases / 20, "%ld of %ld moved triples still collinear",
              moved.zeros, moved.cases);
}

/* ---- incircle ----------------------------------------------------------- */

static void check_incircle(tally *t, double p[4][2])
{
    count(t, cm_incircle(p[0], p[1], p[2], p[3]), ref_incircle(p[0], p[1], p[2], p[3]));
}

/* The 12 lattice points on the circle of radius 5 around the origin. */
static const int circle5[12][2] = {{5, 0},  {4, 3},   {3, 4},   {0, 5},  {-3, 4}, {-4, 3},
                                   {-5, 0}, {-4, -3}, {-3, -4}, {0, -5}, {3, -4}, {4, -3}};

static void test_incircle(long rounds)
{
    rp_rng rng = {0xfedcba9876543210ull};
    tally random = {0}, lattice = {0}, rectangle = {0}, moved = {0}, rounded = {0};
    double p[4][2];
    for (long r = 0; r < rounds; r++) {
        int lo, hi;
        random_window(&rng, r, 60, &lo, &hi);
        for (int m = 0; m < 4; m++)
            for (int k = 0; k < 2; k++) p[m][k] = random_double(&rng, lo, hi);
        check_incircle(&random, p);

        /* lattice circle, scaled and shifted: exact differences */
        int e = random_scale(&rng, 900);
        long radius = 1 + (long)rp_below(&rng, 1L << 20);
        long centre[2] = {random_int(&rng, 1L << 28), random_int(&rng, 1L << 28)};
        for (int m = 0; m < 4; m++) {
            const int *c = circle5[rp_below(&rng, 12)];
            for (int k = 0; k < 2; k++) p[m][k] = ldexp((double)(centre[k] + radius * c[k]), e);
        }
        check_incircle(&lattice, p);
        {
            double *q = &p[rp_below(&rng, 4)][rp_below(&rng, 2)];
            *q = nudge(&rng, *q);
        }
        check_incircle(&moved, p);

        /* corners of a rectangle with sides of unrelated magnitudes, in any
         * order: cocircular, the differences not exact */
        int er = random_scale(&rng, 200);
        double x[2] = {random_double(&rng, er - 100, er), random_double(&rng, er - 100, er)};
        double y[2] = {random_double(&rng, er - 100, er), random_double(&rng, er - 100, er)};
        static const int corner_xy[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        int order[4] = {0, 1, 2, 3};
        for (int m = 3; m > 0; m--) { /* shuffled */
            int j = (int)rp_below(&rng, (uint64_t)m + 1), swap = order[m];
            order[m] = order[j], order[j] = swap;
        }
        for (int m = 0; m < 4; m++) {
            p[m][0] = x[corner_xy[order[m]][0]];
            p[m][1] = y[corner_xy[order[m]][1]];
        }
        check_incircle(&rectangle, p);
        int m = (int)rp_below(&rng, 4), k = (int)rp_below(&rng, 2);
        p[m][k] = nudge(&rng, p[m][k]);
        check_incircle(&moved, p);

        /* d rounded onto the circle through a, b, c centred at 0 */
        int ec = random_scale(&rng, 200);
        double radius_d = ldexp(1.0 + rp_uniform(&rng), ec);
        for (int m2 = 0; m2 < 4; m2++) {
            double angle = rp_uniform(&rng) * 6.283185307179586;
            p[m2][0] = radius_d * cos(angle);
            p[m2][1] = radius_d * sin(angle);
        }
        check_incircle(&rounded, p);
    }
    report("incircle random", &random, 0.0);
    report("incircle lattice cocircular", &lattice, 0.99);
    report("incircle rectangle, inexact differences", &rectangle, 0.99);
    report("incircle cocircular moved one ulp", &moved, 0.0);
    report("incircle rounded onto a circle", &rounded, 0.0);
    /* a quadruple with a repeated lattice point stays degenerate */
    CHECK_MSG(moved.zeros < moved.cases / 4, "%ld of %ld moved quadruples still cocircular",
              moved.zeros, moved.cases);
}

/* ---- orient3d ----------------------------------------------------------- */

static void check_orient3d(tally *t, double p[4][3])
{
    count(t, cm_orient3d(p[0], p[1], p[2], p[3]), ref_orient3d(p[0], p[1], p[2], p[3]));
}

static void test_orient3d(long rounds)
{
    rp_rng rng = {0x5555aaaa3333ccccull};
    tally random = {0}, lattice = {0}, plane = {0}, moved = {0};
    double p[4][3];
    for (long r = 0; r < rounds; r++) {
        int lo, hi;
        random_window(&rng, r, 60, &lo, &hi);
        for (int m = 0; m < 4; m++)
            for (int k = 0; k < 3; k++) p[m][k] = random_double(&rng, lo, hi);
        check_orient3d(&random, p);

        /* lattice plane base + s u + t v, times 2^e */
        int e = random_scale(&rng, 940);
        long base[3], u[3], v[3];
        for (int k = 0; k < 3; k++)
            base[k] = random_int(&rng, 1L << 30), u[k] = random_int(&rng, 1L << 8),
            v[k] = random_int(&rng, 1L << 8);
        for (int m = 0; m < 4; m++) {
            long s = random_int(&rng, 1L << 8), t = random_int(&rng, 1L << 8);
            for (int k = 0; k < 3; k++)
                p[m][k] = ldexp((double)(base[k] + s * u[k] + t * v[k]), e);
        }
        check_orient3d(&lattice, p);
        {
            double *q = &p[rp_below(&rng, 4)][rp_below(&rng, 3)];
            *q = nudge(&rng, *q);
        }
        check_orient3d(&moved, p);

        /* the plane z = a x + b y (small integers a, b; x, y of unrelated
         * magnitudes with few bits, so z is exact) */
        long ca = random_int(&rng, 8), cb = random_int(&rng, 8);
        int ep = random_scale(&rng, 300);
        for (int m = 0; m < 4; m++) {
            int em = ep - (int)rp_below(&rng, 100);
            double x = random_short(&rng, 24, em), y = random_short(&rng, 24, em);
            p[m][0] = x, p[m][1] = y, p[m][2] = (double)ca * x + (double)cb * y;
        }
        if (ref_orient3d(p[0], p[1], p[2], p[3]) == 0) { /* the sum was exact */
            check_orient3d(&plane, p);
            int m = (int)rp_below(&rng, 4), k = (int)rp_below(&rng, 3);
            p[m][k] = nudge(&rng, p[m][k]);
            check_orient3d(&moved, p);
        }
    }
    report("orient3d random", &random, 0.0);
    report("orient3d lattice coplanar", &lattice, 0.99);
    report("orient3d coplanar, inexact differences", &plane, 1.0);
    report("orient3d coplanar moved one ulp", &moved, 0.0);
    CHECK_MSG(plane.cases > rounds / 4, "only %ld coplanar quadruples", plane.cases);
}

/* ---- blended triangles --------------------------------------------------- */

static void check_blend(tally *t, double p[6][2])
{
    count(t, cm_blend_positive(p[0], p[1], p[2], p[3], p[4], p[5]),
          ref_blend_positive(p[0], p[1], p[2], p[3], p[4], p[5]));
}

static void test_blend(long rounds)
{
    rp_rng rng = {0x0f0f0f0f12345678ull};
    tally small = {0}, flat = {0}, turned = {0}, moved = {0}, random = {0};
    double p[6][2];
    for (long r = 0; r < rounds; r++) {
        /* small lattice triangles (many exact ties), scaled and shifted */
        int e = random_scale(&rng, 900);
        long shift[2] = {random_int(&rng, 1L << 30), random_int(&rng, 1L << 30)};
        for (int m = 0; m < 6; m++)
            for (int k = 0; k < 2; k++)
                p[m][k] = ldexp((double)(shift[k] + random_int(&rng, 3)), e);
        check_blend(&small, p);

        /* flat at s = 1/2: midpoints on a line through 0, of unrelated
         * magnitudes; the ends are a midpoint -+ an offset aligned with its
         * lowest bit (so both are exact). Never positive. */
        long slope[2] = {random_int(&rng, 1L << 8), random_int(&rng, 1L << 8)};
        int em = random_scale(&rng, 200);
        for (int m = 0; m < 3; m++) {
            int et = em - (int)rp_below(&rng, 60);
            double tv = random_short(&rng, 24, et);
            for (int k = 0; k < 2; k++) {
                double mid = (double)slope[k] * tv;
                double off = ldexp((double)random_int(&rng, 1L << 8), et);
                p[m][k] = mid - off;
                p[3 + m][k] = mid + off;
            }
        }
        check_blend(&flat, p);
        {
            double *q = &p[rp_below(&rng, 6)][rp_below(&rng, 2)];
            *q = nudge(&rng, *q);
        }
        check_blend(&moved, p);

        /* turned half a turn about c: p1 = 2c - p0, so the area is
         * A0 (1 - 2s)^2, zero at s = 1/2 and M^2 = A0 A1 exactly; c and
         * the offsets have few bits, so both ends are exact */
        int ec = random_scale(&rng, 200);
        for (int k = 0; k < 2; k++) {
            double c = random_short(&rng, 20, ec);
            for (int m = 0; m < 3; m++) {
                double off = random_short(&rng, 20, ec - (int)rp_below(&rng, 30));
                p[m][k] = c + off;
                p[3 + m][k] = c - off;
            }
        }
        check_blend(&turned, p);
        {
            double *q = &p[rp_below(&rng, 6)][rp_below(&rng, 2)];
            *q = nudge(&rng, *q);
        }
        check_blend(&moved, p);

        int lo, hi;
        random_window(&rng, r, 40, &lo, &hi);
        for (int m = 0; m < 6; m++)
            for (int k = 0; k < 2; k++) p[m][k] = random_double(&rng, lo, hi);
        check_blend(&random, p);
    }
    report("blend small lattice", &small, 0.5);
    report("blend flat at s = 1/2", &flat, 1.0);
    report("blend turned half a turn", &turned, 1.0);
    report("blend flat or turned, moved one ulp", &moved, 0.0);
    report("blend random", &random, 0.0);
}

/* ---- polygon orientation ------------------------------------------------- */

static void test_polygon_orientation(long rounds)
{
    rp_rng rng = {0x7777000011112222ull};
    tally there_and_back = {0}, moved = {0}, random = {0};
    double xy[2 * 40];
    for (long r = 0; r < rounds; r++) {
        /* a path and the same path back: area exactly 0 */
        int half = 2 + (int)rp_below(&rng, 19), n = 2 * half - 2;
        int e = random_scale(&rng, 450);
        for (int i = 0; i < half; i++)
            for (int k = 0; k < 2; k++)
                xy[2 * i + k] = random_double(&rng, e - 200, e);
        for (int i = half; i < n; i++)
            for (int k = 0; k < 2; k++) xy[2 * i + k] = xy[2 * (n - i) + k];
        if (n >= 3) {
            count(&there_and_back, cm_polygon_orientation(xy, n), ref_polygon_orientation(xy, n));
            int i = (int)rp_below(&rng, (uint64_t)n);
            xy[2 * i] = nudge(&rng, xy[2 * i]);
            count(&moved, cm_polygon_orientation(xy, n), ref_polygon_orientation(xy, n));
        }
        n = 3 + (int)rp_below(&rng, 30);
        int lo, hi;
        random_window(&rng, r, 40, &lo, &hi);
        for (int i = 0; i < 2 * n; i++) xy[i] = random_double(&rng, lo, hi);
        count(&random, cm_polygon_orientation(xy, n), ref_polygon_orientation(xy, n));
    }
    report("polygon there and back", &there_and_back, 1.0);
    report("polygon there and back moved one ulp", &moved, 0.0);
    report("polygon random", &random, 0.0);
}

/* ---- the expansion module on its own ----------------------------------- */

/* out = v 2^1074, an integer for every finite double */
static void scaled_integer(mpz_t out, double v)
{
    int e = 0;
    long m = v == 0.0 ? 0 : (long)ldexp(frexp(v, &e), 53);
    mpz_set_si(out, m);
    if (m == 0) return;
    if (e - 53 + 1074 >= 0)
        mpz_mul_2exp(out, out, (mp_bitcnt_t)(e - 53 + 1074));
    else
        mpz_tdiv_q_2exp(out, out, (mp_bitcnt_t)(53 - 1074 - e));
}

/* out = (e[0] + ... + e[n-1]) 2^1074 (times 2^1074 again if `product`) */
static void exact_sum(mpz_t out, const double *e, int n)
{
    mpz_set_ui(out, 0);
    for (int i = 0; i < n; i++) {
        scaled_integer(t0, e[i]);
        mpz_add(out, out, t0);
    }
}

/* Sums, differences, scalings, products and compression keep the exact
 * value; the sign is that of the exact sum, also for sequences that are
 * not expansions at all (unordered, overlapping, cancelling), where the
 * largest-component shortcut does not apply. */
static void test_expansion_arithmetic(long rounds)
{
    rp_rng rng = {0x1357924680aceull};
    long wrong_value = 0, wrong_sign = 0, regrown = 0, not_shorter = 0;
    double raw[24], e[25], f[25], h[2 * 25 * 25], scratch[2 * 25 * 26], copy[24];
    mpz_t want, got;
    mpz_inits(want, got, NULL);
    for (long r = 0; r < rounds; r++) {
        int n = 1 + (int)rp_below(&rng, 24), centre = (int)random_int(&rng, 400);
        for (int i = 0; i < n; i++) {
            switch (rp_below(&rng, 4)) {
            case 0: raw[i] = random_double(&rng, centre - 60, centre); break;
            case 1: raw[i] = i > 0 ? -raw[rp_below(&rng, (uint64_t)i)] : 1.0; break;
            case 2: raw[i] = i > 0 ? ldexp(raw[i - 1], -(int)rp_below(&rng, 3)) : 3.0; break;
            default: raw[i] = random_short(&rng, 8, centre - (int)rp_below(&rng, 120));
            }
        }
        exact_sum(want, raw, n);

        /* the sign of an arbitrary sequence */
        for (int i = 0; i < n; i++) copy[i] = raw[i];
        wrong_sign += cm_expansion_sign(n, copy) != mpz_sgn(want);
        exact_sum(got, copy, n); /* the sign may rewrite, not change, it */
        wrong_value += mpz_cmp(got, want) != 0;
        double rest = 0.0;
        for (int i = 0; i < n - 1; i++) rest += fabs(raw[i]);
        regrown += fabs(raw[n - 1]) <= rest;

        /* grown from nothing: an expansion, its sign read off the top */
        int en = 0;
        for (int i = 0; i < n; i++) en = cm_expansion_grow(en, e, raw[i]);
        exact_sum(got, e, en);
        wrong_value += mpz_cmp(got, want) != 0;
        wrong_sign += cm_expansion_sign_ordered(en, e) != mpz_sgn(want);

        /* compressed */
        for (int i = 0; i < en; i++) f[i] = e[i];
        int cn = cm_expansion_compress(en, f);
        exact_sum(got, f, cn);
        wrong_value += mpz_cmp(got, want) != 0;
        not_shorter += cn > en;

        /* a second expansion, then e + f, e - f, e b, e f */
        int fn = 0, m = 1 + (int)rp_below(&rng, 8);
        for (int i = 0; i < m; i++)
            fn = cm_expansion_grow(fn, f, random_double(&rng, centre - 80, centre));
        mpz_t fe;
        mpz_init(fe);
        exact_sum(fe, f, fn);
        int hn = cm_expansion_sum(en, e, fn, f, h);
        exact_sum(got, h, hn);
        mpz_add(t1, want, fe);
        wrong_value += mpz_cmp(got, t1) != 0;
        hn = cm_expansion_diff(en, e, fn, f, h);
        exact_sum(got, h, hn);
        mpz_sub(t1, want, fe);
        wrong_value += mpz_cmp(got, t1) != 0;
        wrong_sign += cm_expansion_sign(hn, h) != mpz_sgn(t1);
        double b = random_double(&rng, -300, 300);
        hn = cm_expansion_scale(en, e, b, h);
        exact_sum(got, h, hn);
        scaled_integer(t2, b);
        mpz_mul(t1, want, t2);
        mpz_mul_2exp(got, got, 1074); /* both sides times 2^2148 */
        wrong_value += mpz_cmp(got, t1) != 0;
        hn = cm_expansion_product(en, e, fn, f, h, scratch);
        exact_sum(got, h, hn);
        mpz_mul(t1, want, fe);
        mpz_mul_2exp(got, got, 1074);
        wrong_value += mpz_cmp(got, t1) != 0;
        wrong_sign += cm_expansion_sign(hn, h) != mpz_sgn(t1);
        mpz_clear(fe);
    }
    mpz_clears(want, got, NULL);
    CHECK_MSG(wrong_value == 0, "%ld results with a wrong value", wrong_value);
    CHECK_MSG(wrong_sign == 0, "%ld wrong signs", wrong_sign);
    CHECK_MSG(not_shorter == 0, "%ld compressions grew", not_shorter);
    /* the sequences reach the sign's regrowing branch */
    CHECK_MSG(regrown > rounds / 10, "only %ld of %ld signs regrown", regrown, rounds);
}

int main(void)
{
    ref_init();
    test_expansion_arithmetic(30000);
    test_orient2d(250000);
    test_incircle(100000);
    test_orient3d(60000);
    test_blend(40000);
    test_polygon_orientation(15000);
    ref_clear();
    return check_summary("test_predicates_property");
}
