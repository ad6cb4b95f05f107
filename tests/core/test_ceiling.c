/* The ceiling (correspond/bound.h): fixtures whose answer is known, and a
 * property test that the certified caps are never below what the pipeline
 * reaches. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "correspond/bound.h"
#include "geom/polytri.h"
#include "random_polygons.h"
#include "result_check.h"

#define PI 3.14159265358979323846

/* The rectangle w x h with its four corners marked: the modulus for 0 on
 * the bottom and 1 on the top is w / h exactly (the harmonic function is
 * y / h), and h / w for the other pair of sides. The finite element
 * bracket must contain it, and (the stated discretisation safety) be
 * within 6 % of it. */
static void rectangle_modulus(double w, double h)
{
    double xy[8] = {0, 0, w, 0, w, h, 0, h}, lo, hi;
    long bottom_top[4] = {0, 1, 2, 3}, sides[4] = {1, 2, 3, 0};
    cm_error err;
    cm_error_init(&err);
    CHECK(cm_bound_modulus(xy, NULL, 4, bottom_top, &lo, &hi, &err) == CM_OK);
    CHECK_MSG(lo <= w / h && w / h <= hi && hi / lo < 1.06, "%g x %g: [%.6g, %.6g] vs %.6g", w, h, lo, hi, w / h);
    CHECK(cm_bound_modulus(xy, NULL, 4, sides, &lo, &hi, &err) == CM_OK);
    CHECK_MSG(lo <= h / w && h / w <= hi && hi / lo < 1.06, "%g x %g: [%.6g, %.6g] vs %.6g", w, h, lo, hi, h / w);
}

/* A 3 x 1 rectangle against the unit square, corners corresponding: the
 * only quadrilateral has moduli 3 and 1, so the certified distortion is at
 * most 3 (a lower bound on the true ratio) and, the finite elements being
 * within 6 % each way, at least 3 / 1.06^2; the bound is the angle K^-1
 * gives for it; the corner fan at four right angles is 45. */
static void rectangle_against_square(void)
{
    double rect[8] = {0, 0, 3, 0, 3, 1, 0, 1}, square[8] = {0, 0, 1, 0, 1, 1, 0, 1};
    const double *geoms[2] = {rect, square};
    cm_bound b;
    cm_error err;
    cm_error_init(&err);
    CHECK(cm_bound_compute(geoms, NULL, 2, 4, NULL, &b, &err) == CM_OK);
    CHECK_MSG(b.distortion <= 3.0 && b.distortion >= 3.0 / (1.06 * 1.06), "K = %.6g", b.distortion);
    CHECK(b.correspondence_deg == cm_bound_angle(b.distortion));
    CHECK(b.correspondence_deg >= cm_bound_angle(3.0));
    CHECK(fabs(b.corner_fan_deg - 45.0) < 1e-6);
}

/* D and its inverse agree; D(60) = 1; D grows as alpha shrinks. */
static void dilatation_formula(void)
{
    CHECK(fabs(cm_bound_dilatation(PI / 3) - 1.0) < 1e-9);
    for (double deg = 5; deg < 60; deg += 5) {
        double K = cm_bound_dilatation(deg * PI / 180);
        CHECK(K > 1 && K > cm_bound_dilatation((deg + 1) * PI / 180));
        double back = cm_bound_angle(K);
        CHECK_MSG(back >= deg && back < deg + 1e-6, "%g -> K %g -> %g", deg, K, back);
    }
    CHECK(cm_bound_angle(1.0) == 60.0 && cm_bound_angle(0.5) == 60.0);
}

/* The triangle with angles a at 0 and b at 1, first side (0,0)-(1,0). */
static void triangle_with_angles(double a, double b, double t[6])
{
    double r = sin(b) / sin(a + b);
    t[0] = 0, t[1] = 0, t[2] = 1, t[3] = 0, t[4] = r * cos(a), t[5] = r * sin(a);
}

/* Dilatation (singular value ratio) of the affine map taking triangle p
 * onto triangle q, vertex to vertex. */
static double affine_dilatation(const double p[6], const double q[6])
{
    double P[4] = {p[2] - p[0], p[4] - p[0], p[3] - p[1], p[5] - p[1]};
    double Q[4] = {q[2] - q[0], q[4] - q[0], q[3] - q[1], q[5] - q[1]};
    double det = P[0] * P[3] - P[1] * P[2];
    double inv[4] = {P[3] / det, -P[1] / det, -P[2] / det, P[0] / det};
    double A[4] = {Q[0] * inv[0] + Q[1] * inv[2], Q[0] * inv[1] + Q[1] * inv[3],
                   Q[2] * inv[0] + Q[3] * inv[2], Q[2] * inv[1] + Q[3] * inv[3]};
    double f = A[0] * A[0] + A[1] * A[1] + A[2] * A[2] + A[3] * A[3], d = fabs(A[0] * A[3] - A[1] * A[2]);
    double k = f / d; /* K + 1 / K */
    return 0.5 * (k + sqrt(fmax(k * k - 4, 0.0)));
}

/* cm_bound_dilatation(alpha) is reached between the triangles (alpha,
 * alpha, 180 - 2 alpha) and (alpha, 180 - 2 alpha, alpha), and no pair of
 * triangles with all angles >= alpha exceeds it. */
static void dilatation_is_the_largest_between_triangles(void)
{
    rp_rng rng = {7};
    for (double deg = 5; deg <= 55; deg += 10) {
        double alpha = deg * PI / 180, K = cm_bound_dilatation(alpha), p[6], q[6];
        triangle_with_angles(alpha, alpha, p);
        triangle_with_angles(alpha, PI - 2 * alpha, q);
        CHECK_MSG(fabs(affine_dilatation(p, q) / K - 1) < 1e-9, "%g: corners %.9g, K %.9g", deg, affine_dilatation(p, q), K);
        double worst = 0;
        for (int i = 0; i < 20000; i++) {
            double t[2][6];
            for (int j = 0; j < 2; j++) {
                double a = alpha + rp_uniform(&rng) * (PI - 3 * alpha);
                double b = alpha + rp_uniform(&rng) * (PI - 2 * alpha - a);
                triangle_with_angles(a, b, t[j]);
            }
            worst = fmax(worst, affine_dilatation(t[0], t[1]));
        }
        CHECK_MSG(worst <= K * (1 + 1e-9) && worst > 0.5 * K, "%g: random pairs reach %.9g, K %.9g", deg, worst, K);
    }
}

/* Interior angle in degrees at vertex i, computed independently of bound.c. */
static double corner(const double *xy, int n, int i)
{
    const double *p = xy + 2 * ((i + n - 1) % n), *v = xy + 2 * i, *q = xy + 2 * ((i + 1) % n);
    double ax = p[0] - v[0], ay = p[1] - v[1], bx = q[0] - v[0], by = q[1] - v[1];
    double a = acos(fmax(-1.0, fmin(1.0, (ax * bx + ay * by) / (hypot(ax, ay) * hypot(bx, by))))) * 180 / PI;
    return bx * ay - by * ax >= 0 ? a : 360 - a; /* reflex when p is right of v -> q */
}

/* The corner-fan formula, by brute force over fan sizes 1..1000. */
static double fan_formula(const double *const *geoms, int k, int n)
{
    double cap = 60;
    for (int i = 0; i < n; i++) {
        double lo = 360, hi = 0, best = 0;
        for (int g = 0; g < k; g++) lo = fmin(lo, corner(geoms[g], n, i)), hi = fmax(hi, corner(geoms[g], n, i));
        for (int m = 1; m <= 1000; m++) best = fmax(best, fmin(lo / m, (180 - hi / m) / 2));
        cap = fmin(cap, best);
    }
    return cap;
}

static double min_angle(const cm_result *r)
{
    return rc_least_angle(r, cm_result_num_geometries(r));
}

/* A polygon against an affine image of itself: the corner fan is its
 * formula; every quadrilateral's moduli differ by at most the affine map's
 * dilatation (singular value ratio), so the certified K is at most that;
 * and the pipeline's result is below the ceiling. */
static void affine_image(uint64_t seed)
{
    enum { N = 24 };
    double a[2 * N], b[2 * N];
    if (rp_star(a, N, seed)) return;
    double m00 = 2.0, m01 = 0.7, m10 = 0.1, m11 = 0.8; /* det > 0 */
    for (int i = 0; i < N; i++) {
        b[2 * i] = m00 * a[2 * i] + m01 * a[2 * i + 1] + 5;
        b[2 * i + 1] = m10 * a[2 * i] + m11 * a[2 * i + 1] - 1;
    }
    double t = m00 * m00 + m01 * m01 + m10 * m10 + m11 * m11, det = m00 * m11 - m01 * m10;
    double s1 = sqrt(0.5 * (t + sqrt(t * t - 4 * det * det))), s2 = det / s1;
    const double *geoms[2] = {a, b};
    cm_bound bd;
    cm_error err;
    cm_error_init(&err);
    CHECK(cm_bound_compute(geoms, NULL, 2, N, NULL, &bd, &err) == CM_OK);
    CHECK_MSG(bd.distortion <= s1 / s2 * (1 + 1e-9), "K %.6g above the affine dilatation %.6g", bd.distortion, s1 / s2);
    CHECK_MSG(fabs(bd.corner_fan_deg / fan_formula(geoms, 2, N) - 1) < 1e-8, "fan %.9g vs formula %.9g",
              bd.corner_fan_deg, fan_formula(geoms, 2, N));
    cm_result *r = NULL;
    CHECK(cm_triangulate_polygons(geoms, (size_t[]){N, N}, 2, NULL, &r) == CM_OK);
    const cm_stats *st = cm_result_stats(r);
    CHECK(st->ceiling_deg == fmin(st->corner_fan_cap_deg, st->correspondence_bound_deg));
    CHECK_MSG(min_angle(r) <= st->ceiling_deg, "reached %.4g above the ceiling %.4g", min_angle(r), st->ceiling_deg);
    cm_result_free(r);
}

/* Property: on random pairs (stars, random simple polygons, a star against
 * itself twisted) the ceiling is never below the smallest angle the
 * pipeline reaches, remeshing aimed at the full target (ceiling off) or at
 * the ceiling. */
static void never_below_reached(void)
{
    enum { MAXN = 40 };
    int pairs = 0;
    for (uint64_t seed = 1; pairs < 30; seed++) {
        int n = 8 + (int)(seed * 7 % 21);
        double a[2 * MAXN], b[2 * MAXN];
        int kind = (int)(seed % 3), bad = 0;
        bad |= kind == 2 ? rp_random_simple(a, n, seed) : rp_star(a, n, 11 * seed);
        if (kind == 1) {
            memcpy(b, a, sizeof a);
            rp_twist(b, n, 1 + (int)(seed % 3));
        } else {
            bad |= kind == 2 ? rp_random_simple(b, n, seed + 1000) : rp_star(b, n, 13 * seed + 1);
        }
        if (bad) continue;
        pairs++;
        const double *geoms[2] = {a, b};
        size_t counts[2] = {(size_t)n, (size_t)n};
        cm_options o;
        cm_options_init(&o);
        cm_result *with = NULL, *without = NULL;
        cm_status s1 = cm_triangulate_polygons(geoms, counts, 2, &o, &with);
        o.ceiling = 0;
        cm_status s2 = cm_triangulate_polygons(geoms, counts, 2, &o, &without);
        CHECK(s1 == s2);
        if (s1 == CM_OK && s2 == CM_OK) {
            double ceiling = cm_result_stats(with)->ceiling_deg;
            CHECK(cm_result_stats(without)->ceiling_deg == 0);
            CHECK_MSG(min_angle(with) <= ceiling && min_angle(without) <= ceiling,
                      "seed %llu n %d: reached %.4g / %.4g, ceiling %.4g", (unsigned long long)seed, n,
                      min_angle(with), min_angle(without), ceiling);
            CHECK(ceiling > 0 && ceiling <= 60);
        }
        cm_result_free(with), cm_result_free(without);
    }
}

static int cancel_at_once(void *user, double fraction, const char *stage)
{
    (void)fraction, (void)stage;
    return ++*(int *)user > 3;
}

/* Cancelling while the ceiling runs ends the call cleanly. */
static void cancels(void)
{
    enum { N = 400 };
    double *a = malloc(2 * N * sizeof *a), *b = malloc(2 * N * sizeof *b);
    if (!a || !b || rp_star(a, N, 3) || rp_star(b, N, 4)) {
        free(a), free(b);
        return;
    }
    int calls = 0;
    cm_options o;
    cm_options_init(&o);
    o.progress = cancel_at_once, o.progress_user = &calls;
    cm_result *r = NULL;
    const double *geoms[2] = {a, b};
    CHECK(cm_triangulate_polygons(geoms, (size_t[]){N, N}, 2, &o, &r) == CM_ERR_CANCELLED);
    cm_result_free(r);
    free(a), free(b);
}

/* The memo gives what computing gives: the same polygons recalled (also
 * with their triangulations given, the ones computing would make), other
 * polygons or another triangulation computed afresh. */
static int same_bound(const cm_bound *a, const cm_bound *b)
{
    return a->corner_fan_deg == b->corner_fan_deg && a->correspondence_deg == b->correspondence_deg &&
           a->distortion == b->distortion && !memcmp(a->quad, b->quad, sizeof a->quad);
}

static void memo_recalls_what_computing_gives(void)
{
    enum { N = 20 };
    double a[2 * N], b[2 * N], c[2 * N];
    CHECK(rp_star(a, N, 5) == 0 && rp_star(b, N, 6) == 0 && rp_star(c, N, 7) == 0);
    const double *ab[2] = {a, b}, *ac[2] = {a, c};
    int32_t ta[3 * (N - 2)], tb[3 * (N - 2)], fan[3 * (N - 2)];
    int32_t idx[N];
    for (int i = 0; i < N; i++) idx[i] = i;
    CHECK(cm_polygon_triangulate(a, idx, N, ta, NULL) == 0 && cm_polygon_triangulate(b, idx, N, tb, NULL) == 0);
    for (int t = 0; t < N - 2; t++) fan[3 * t] = 0, fan[3 * t + 1] = t + 1, fan[3 * t + 2] = t + 2;
    const int32_t *cdt[2] = {ta, tb}, *other[2] = {ta, fan};
    cm_bound fresh_ab, fresh_ac, fresh_other, got;
    cm_error err;
    cm_error_init(&err);
    cm_bound_memo *memo = cm_bound_memo_new();
    CHECK(memo != NULL);
    CHECK(cm_bound_compute(ab, NULL, 2, N, NULL, &fresh_ab, &err) == CM_OK);
    CHECK(cm_bound_compute(ac, NULL, 2, N, NULL, &fresh_ac, &err) == CM_OK);
    CHECK(cm_bound_compute(ab, other, 2, N, NULL, &fresh_other, &err) == CM_OK);
    CHECK(!same_bound(&fresh_ab, &fresh_ac) && !same_bound(&fresh_ab, &fresh_other));
    for (int round = 0; round < 2; round++) { /* computed, then recalled */
        CHECK(cm_bound_compute_memo(memo, ab, NULL, 2, N, NULL, &got, &err) == CM_OK && same_bound(&got, &fresh_ab));
        CHECK(cm_bound_compute_memo(memo, ab, cdt, 2, N, NULL, &got, &err) == CM_OK && same_bound(&got, &fresh_ab));
        CHECK(cm_bound_compute_memo(memo, ac, NULL, 2, N, NULL, &got, &err) == CM_OK && same_bound(&got, &fresh_ac));
        CHECK(cm_bound_compute_memo(memo, ab, other, 2, N, NULL, &got, &err) == CM_OK &&
              same_bound(&got, &fresh_other));
    }
    cm_bound_memo_free(memo);
}

int main(void)
{
    rectangle_modulus(3, 1);
    rectangle_modulus(1, 5);
    rectangle_against_square();
    dilatation_formula();
    dilatation_is_the_largest_between_triangles();
    for (uint64_t seed = 1; seed <= 3; seed++) affine_image(seed);
    never_below_reached();
    cancels();
    memo_recalls_what_computing_gives();
    return check_summary("test_ceiling");
}
