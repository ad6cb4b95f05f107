/* The partition method through the public API: Steiner-free pairs get no
 * Steiner vertex, the fixtures state their Steiner bounds, and a property
 * test over more than a thousand random pairs must return only valid
 * results (cm_triangulate checks exactly; the test checks again from the
 * public arrays) without needing the overlay fallback. */
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "compatmesh/compatmesh.h"
#include "api/halfedge.h"
#include "api/result.h"
#include "geom/polytri.h"
#include "construct/partition.h"
#include "geom/predicates.h"
#include "random_polygons.h"
#include "result_check.h"
#include "geom/visibility.h"

/* Runs the default method without remeshing; returns the Steiner count,
 * or -1 if the result is not valid. */
static long run(const double *const *xy, size_t k, size_t n, size_t *fallbacks)
{
    cm_options o;
    cm_options_init(&o);
    o.remesh = 0;
    size_t counts[3] = {n, n, n};
    cm_result *r = NULL;
    cm_status s = cm_triangulate_polygons(xy, counts, k, &o, &r);
    long steiner = -1;
    if (s == CM_OK && rc_valid(r, xy, k, n)) steiner = (long)cm_result_stats(r)->steiner;
    if (fallbacks) *fallbacks = s == CM_OK ? cm_result_stats(r)->fallback_count : 0;
    if (s != CM_OK) fprintf(stderr, "cm_triangulate: %s\n", cm_result_message(r));
    cm_result_free(r);
    return steiner;
}

static void test_default_method(void)
{
    cm_options o;
    cm_options_init(&o);
    CHECK(o.method == CM_METHOD_PARTITION);
}

/* ---- Steiner-free pairs ---------------------------------------------------- */

/* An exact affine image (dyadic coefficients, positive determinant) keeps
 * every diagonal: no Steiner vertex. */
static void test_affine_pairs(void)
{
    double a[2 * 300], b[2 * 300];
    for (uint64_t seed = 1; seed <= 12; seed++) {
        int n = 25 * (int)seed;
        CHECK(rp_random_simple(a, n, seed) == 0);
        for (int i = 0; i < n; i++) {
            b[2 * i] = 0.5 * a[2 * i] - a[2 * i + 1] + 1;
            b[2 * i + 1] = 0.75 * a[2 * i] + 0.5 * a[2 * i + 1];
        }
        const double *xy[2] = {a, b};
        CHECK_MSG(run(xy, 2, (size_t)n, NULL) == 0, "affine pair n=%d", n);
    }
}

/* A convex polygon against anything: every diagonal of the other is one
 * of the convex polygon. */
static void test_convex_pairs(void)
{
    double a[2 * 400], b[2 * 400];
    for (uint64_t seed = 1; seed <= 8; seed++) {
        int n = 50 * (int)seed;
        CHECK(rp_disc(a, n) == 0);
        int ok = seed % 3 == 0 ? rp_spiral(b, n, 1 + (double)seed / 3) : seed % 3 == 1 ? rp_random_simple(b, n, seed) : rp_comb(b, n, n / 10);
        if (ok != 0) continue;
        const double *xy[2] = {b, a};
        CHECK_MSG(run(xy, 2, (size_t)n, NULL) == 0, "convex pair n=%d", n);
    }
}

/* Small random pairs where some triangulation of one is a triangulation of
 * the other (checked by brute force over all triangulations): 0 Steiner. */
static int is_diagonal(const double *xy, int n, int a, int b)
{
    return cm_segment_inside(xy, n, a, xy + 2 * a, b, xy + 2 * b);
}

static int common_triangulation(const double *a, const double *b, int n, int lo, int hi)
{
    if (hi - lo < 2) return 1;
    for (int c = lo + 1; c < hi; c++) {
        int l1 = c == lo + 1 || (is_diagonal(a, n, lo, c) && is_diagonal(b, n, lo, c));
        int l2 = c == hi - 1 || (is_diagonal(a, n, c, hi) && is_diagonal(b, n, c, hi));
        if (l1 && l2 && common_triangulation(a, b, n, lo, c) && common_triangulation(a, b, n, c, hi)) return 1;
    }
    return 0;
}

static void test_brute_force_pairs(void)
{
    double a[2 * 10], b[2 * 10];
    int tried = 0, free_pairs = 0;
    for (uint64_t seed = 1; seed <= 200; seed++) {
        int n = 6 + (int)(seed % 4);
        if (rp_random_simple(a, n, seed) != 0 || rp_star(b, n, seed + 500) != 0) continue;
        const double *xy[2] = {a, b};
        long steiner = run(xy, 2, (size_t)n, NULL);
        int exists = common_triangulation(a, b, n, 0, n - 1);
        CHECK(steiner >= 0);
        CHECK_MSG(exists ? steiner == 0 : steiner > 0, "seed %d: exists %d, steiner %ld", (int)seed, exists, steiner);
        tried++;
        free_pairs += exists;
    }
    CHECK(tried > 150 && free_pairs > 20);
}

/* ---- fixtures with stated bounds ----------------------------------------- */

/* A quadrilateral pair whose only diagonals differ: the dart with its
 * reflex vertex at 2 has only (0,2), the same dart numbered from another
 * corner has its reflex vertex at 1 and only (1,3). No Steiner-free
 * triangulation; one Steiner vertex suffices. */
static void test_stuck_quad(void)
{
    const double p[] = {0, 0, 4, 0, 1, 1, 0, 4}, r[] = {4, 0, 1, 1, 0, 4, 0, 0};
    const double *xy[2] = {p, r};
    CHECK(rp_is_simple(p, 4) && rp_is_simple(r, 4));
    CHECK(is_diagonal(p, 4, 0, 2) && !is_diagonal(p, 4, 1, 3));
    CHECK(is_diagonal(r, 4, 1, 3) && !is_diagonal(r, 4, 0, 2));
    CHECK(run(xy, 2, 4, NULL) == 1);
}

/* Star pairs and twisted stars: star-shaped in both geometries, so at most
 * one Steiner vertex whatever n; three geometries too. */
static void test_stars(void)
{
    double a[2 * 1000], b[2 * 1000], c[2 * 1000];
    for (uint64_t seed = 1; seed <= 6; seed++) {
        int n = (int)(seed * seed) * 25;
        CHECK(rp_star(a, n, seed) == 0 && rp_star(b, n, seed + 100) == 0);
        const double *xy[3] = {a, b, c};
        long s = run(xy, 2, (size_t)n, NULL);
        CHECK_MSG(s >= 0 && s <= 1, "star pair n=%d: %ld", n, s);
        memcpy(c, a, sizeof(double) * 2 * (size_t)n);
        rp_twist(c, n, n / 3);
        xy[1] = c;
        s = run(xy, 2, (size_t)n, NULL);
        CHECK_MSG(s >= 0 && s <= 1, "twisted star n=%d: %ld", n, s);
        xy[1] = b, xy[2] = c;
        s = run(xy, 3, (size_t)n, NULL);
        CHECK_MSG(s >= 0 && s <= 1, "star triple n=%d: %ld", n, s);
    }
}

/* A 10,000-vertex star pair: too large for the Steiner-free program, the
 * partition (not the whole-input overlay) still finds the one fan. */
static void test_large_star_pair(void)
{
    enum { N = 10000 };
    double *a = malloc(sizeof(double) * 2 * N), *b = malloc(sizeof(double) * 2 * N);
    CHECK(a && b && rp_star(a, N, 77) == 0 && rp_star(b, N, 78) == 0);
    const double *xy[2] = {a, b};
    size_t fallbacks = 1;
    long s = run(xy, 2, N, &fallbacks);
    CHECK_MSG(s >= 0 && s <= 1 && fallbacks == 0, "star pair n=%d: %ld Steiner, %zu fallbacks", N, s, fallbacks);
    free(a), free(b);
}

/* Clockwise input is processed reversed and keeps the contract. */
static void test_clockwise(void)
{
    double a[2 * 60], b[2 * 60];
    CHECK(rp_random_simple(a, 60, 3) == 0 && rp_random_simple(b, 60, 4) == 0);
    rp_reverse(a, 1, 59), rp_reverse(b, 1, 59);
    const double *xy[2] = {a, b};
    CHECK(run(xy, 2, 60, NULL) >= 0);
}

/* Pairs that need minimum-link cuts (random polygons are not
 * star-shaped): through the internal entry, the link splits happen and
 * the result is valid. */
static void test_link_splits(void)
{
    double a[2 * 40], b[2 * 40];
    size_t splits = 0;
    for (uint64_t seed = 1; seed <= 20; seed++) {
        if (rp_random_simple(a, 40, seed) != 0 || rp_random_simple(b, 40, seed + 99) != 0) continue;
        const double *xy[2] = {a, b};
        int32_t *tris[2];
        int32_t idx[40];
        for (int i = 0; i < 40; i++) idx[i] = i;
        for (int g = 0; g < 2; g++) {
            tris[g] = malloc(sizeof(int32_t) * 3 * 38);
            CHECK(cm_polygon_triangulate(xy[g], idx, 40, tris[g], NULL) == 0);
        }
        cm_result *r = calloc(1, sizeof *r);
        cm_partition_stats st;
        CHECK(cm_partition(xy, (const int32_t *const *)tris, 2, 40, NULL, &r->mesh, &st, &r->error) == CM_OK);
        int32_t boundary[40];
        for (int i = 0; i < 40; i++) boundary[i] = i;
        r->n = 40;
        CHECK(cm_halfedge_build_and_check(r, boundary, NULL, 1) == CM_OK);
        CHECK(st.fallback_count == 0);
        splits += st.link_splits;
        cm_result_free(r);
        free(tris[0]), free(tris[1]);
    }
    CHECK(splits > 10);
}

/* Partitions through the internal entry with the given table limit; 1 if
 * the result is valid (checked from its arrays). */
static int partition_limited(const double *const *xy, int n, long limit, cm_partition_stats *st)
{
    int32_t *tris[2] = {malloc(sizeof(int32_t) * 3 * (size_t)(n - 2)), malloc(sizeof(int32_t) * 3 * (size_t)(n - 2))};
    int32_t *idx = malloc(sizeof(int32_t) * (size_t)n);
    cm_result *r = calloc(1, sizeof *r);
    CHECK(tris[0] && tris[1] && idx && r);
    for (int i = 0; i < n; i++) idx[i] = i;
    for (int g = 0; g < 2; g++) CHECK(cm_polygon_triangulate(xy[g], idx, n, tris[g], NULL) == 0);
    CHECK(cm_partition_limited(xy, (const int32_t *const *)tris, 2, (size_t)n, limit, NULL, &r->mesh, st,
                               &r->error) == CM_OK);
    r->n = (size_t)n;
    int ok = cm_halfedge_build_and_check(r, idx, NULL, 1) == CM_OK;
    cm_result_free(r);
    free(tris[0]), free(tris[1]), free(idx);
    return ok;
}

/* Inputs above the table limit (lowered here). A star pair is fanned from
 * one Steiner vertex without a table. An exact affine pair (every
 * diagonal common) is split in halves by sampled splits until the pieces
 * get tables, and stays Steiner-free. Random pairs are split along common
 * diagonals seen from spread vertices and stay valid without the
 * overlay. */
static void test_above_table_limit(void)
{
    enum { N = 1200 };
    double *a = malloc(sizeof(double) * 2 * N), *b = malloc(sizeof(double) * 2 * N);
    CHECK(a && b && rp_star(a, N, 31) == 0 && rp_star(b, N, 32) == 0);
    const double *xy[2] = {a, b};
    cm_partition_stats st;
    CHECK(partition_limited(xy, N, 300, &st));
    CHECK_MSG(st.steiner == 1 && st.fans == 1 && st.sampled_splits == 0 && st.fallback_count == 0,
              "star pair above the limit: %zu Steiner, %zu fans", st.steiner, st.fans);
    CHECK(rp_random_simple(a, N, 5) == 0);
    for (int i = 0; i < N; i++) b[2 * i] = 0.5 * a[2 * i] - a[2 * i + 1] + 1, b[2 * i + 1] = 0.75 * a[2 * i] + 0.5 * a[2 * i + 1];
    CHECK(partition_limited(xy, N, 250, &st));
    CHECK_MSG(st.steiner == 0 && st.sampled_splits >= 3 && st.fallback_count == 0,
              "affine pair above the limit: %zu Steiner, %zu sampled splits", st.steiner, st.sampled_splits);
    for (uint64_t seed = 1; seed <= 3; seed += 2) {
        CHECK(rp_random_simple(a, N, seed) == 0 && rp_random_simple(b, N, seed + 40) == 0);
        CHECK_MSG(partition_limited(xy, N, 600, &st), "random pair %llu above the limit", (unsigned long long)seed);
        CHECK_MSG(st.sampled_splits > 0 && st.fallback_count == 0 && st.steiner < N,
                  "random pair %llu: %zu sampled splits, %zu Steiner, %zu fallbacks", (unsigned long long)seed,
                  st.sampled_splits, st.steiner, st.fallback_count);
    }
    free(a), free(b);
}

/* Two unrelated random polygons of n vertices against a table limit:
 * valid, no piece to the overlay, some link splits, and fewer Steiner
 * vertices than 0.45 n. */
static void check_unrelated_pair(const double *const *xy, int n, long limit, const char *name)
{
    cm_partition_stats st;
    CHECK_MSG(partition_limited(xy, n, limit, &st), "%s: partitioned and valid", name);
    CHECK_MSG(st.fallback_count == 0 && st.steiner < (size_t)(45 * n / 100) && st.link_splits > 0,
              "%s: %zu Steiner, %zu fallbacks, %zu link splits", name, st.steiner, st.fallback_count, st.link_splits);
}

/* Pairs above the table limit (the default one) through the internal
 * entry. A random polygon against a disc: the most balanced diagonals of
 * the random polygon's triangulation are common, so the pieces get
 * tables with no Steiner vertex. Two unrelated random polygons: their
 * common diagonals are all short, so the large pieces are cut along
 * minimum-link paths between far-apart vertices; no piece goes to the
 * overlay, and the Steiner vertices stay below 0.45 n (0.39 n to 0.42 n
 * measured from 1,000 to 30,000 vertices). */
static void test_large_random_pairs(void)
{
    enum { N = 5000 };
    double *a = malloc(sizeof(double) * 2 * N), *b = malloc(sizeof(double) * 2 * N);
    CHECK(a && b && rp_random_simple(a, N, 7) == 0 && rp_disc(b, N) == 0);
    const double *xy[2] = {a, b};
    cm_partition_stats st;
    CHECK(N > CM_PARTITION_MAX_VERTICES && partition_limited(xy, N, CM_PARTITION_MAX_VERTICES, &st));
    CHECK_MSG(st.steiner == 0 && st.fallback_count == 0 && st.sampled_splits >= 2 && st.link_splits == 0,
              "random polygon against a disc: %zu Steiner, %zu fallbacks, %zu sampled splits, %zu link splits",
              st.steiner, st.fallback_count, st.sampled_splits, st.link_splits);
    CHECK(rp_random_simple(b, N, 8) == 0);
    check_unrelated_pair(xy, N, CM_PARTITION_MAX_VERTICES, "unrelated random pair");
    free(a), free(b);
}

/* Two unrelated random polygons far above a lowered table limit (2,048
 * against 3,000 vertices would take one balanced cut; 128 takes them over
 * five levels, as a 100,000-vertex pair does against the real limit):
 * every piece is cut without the overlay, with the Steiner vertices of an
 * input below the limit (about 0.4 n for this family). */
static void test_balanced_cut_levels(void)
{
    enum { N = 3000 };
    double *a = malloc(sizeof(double) * 2 * N), *b = malloc(sizeof(double) * 2 * N);
    CHECK(a && b && rp_random_simple(a, N, 21) == 0 && rp_random_simple(b, N, 22) == 0);
    const double *xy[2] = {a, b};
    check_unrelated_pair(xy, N, 128, "random pair, limit 128");
    free(a), free(b);
}

/* The space-partitioning generator (the scale bench's random polygons up to
 * 100,000 vertices): simple, counter-clockwise, no flat corner, checked by
 * brute force at every n up to 200; two of them at n = 400 partition into
 * a valid result without the overlay. */
static void test_space_partition_polygons(void)
{
    enum { N = 400 };
    double a[2 * N], b[2 * N];
    for (int n = 3; n <= 200; n++)
        for (uint64_t seed = 1; seed <= 3; seed++) {
            int made = rp_random_spa(a, n, seed) == 0;
            CHECK_MSG(made && rp_is_simple(a, n) && rp_signed_area2(a, n) > 0 && !rp_has_flat_corner(a, n),
                      "n = %d, seed %lu", n, (unsigned long)seed);
        }
    CHECK(rp_random_spa(a, N, 11) == 0 && rp_random_spa(b, N, 12) == 0);
    const double *xy[2] = {a, b};
    size_t fallbacks = 1;
    CHECK(run(xy, 2, N, &fallbacks) >= 0 && fallbacks == 0);
}

/* ---- the property test ----------------------------------------------------- */

/* A square with n/4 points per side (collinear runs), vertex 0 a corner. */
static int collinear_square(double *xy, int n)
{
    int q = n / 4;
    if (4 * q != n) return -1;
    for (int i = 0; i < n; i++) {
        int side = i / q;
        double f = (double)(i % q) / q;
        xy[2 * i] = side == 0 ? -1 + 2 * f : side == 1 ? 1 : side == 2 ? 1 - 2 * f : -1;
        xy[2 * i + 1] = side == 0 ? -1 : side == 1 ? -1 + 2 * f : side == 2 ? 1 : 1 - 2 * f;
    }
    return 0;
}

static int make_pair(int family, int n, uint64_t seed, double *a, double *b)
{
    switch (family) {
    case 0: return rp_star(a, n, seed) | rp_star(b, n, seed + 7777);
    case 1: return rp_random_simple(a, n, seed) | rp_random_simple(b, n, seed + 7777);
    case 2: return rp_random_simple(a, n, seed) | rp_star(b, n, seed + 7777);
    case 3:
        if (rp_star(a, n, seed) != 0) return -1;
        memcpy(b, a, sizeof(double) * 2 * (size_t)n);
        rp_twist(b, n, 1 + (int)(seed % (uint64_t)(n - 1)));
        return 0;
    case 4: return rp_spiral(a, n, 1 + (double)(seed % 3)) | rp_random_simple(b, n, seed);
    case 5: return rp_comb(a, n, 2 + (int)(seed % 3)) | rp_random_simple(b, n, seed);
    default:
        if (collinear_square(a, n) != 0 || rp_comb(b, n, 2) != 0) return -1;
        rp_twist(a, n, (int)(seed % (uint64_t)n));
        return 0;
    }
}

static void test_property(void)
{
    double a[2 * 40], b[2 * 40];
    long pairs = 0, invalid = 0, steiner = 0;
    size_t fallbacks = 0;
    for (uint64_t seed = 1; pairs < 1200; seed++) {
        int family = (int)(seed % 7), n = 6 + (int)(seed % 23);
        if (family == 6) n = 8 * (1 + (int)(seed % 4));
        if (make_pair(family, n, seed, a, b) != 0) continue;
        const double *xy[2] = {a, b};
        size_t fb = 0;
        long s = run(xy, 2, (size_t)n, &fb);
        if (s < 0) {
            invalid++;
            fprintf(stderr, "family %d n %d seed %llu: invalid\n", family, n, (unsigned long long)seed);
        } else {
            steiner += s;
        }
        fallbacks += fb;
        pairs++;
    }
    CHECK(invalid == 0);
    printf("property test: %ld pairs, %ld invalid, %ld Steiner vertices, %zu fallbacks\n", pairs, invalid,
           steiner, fallbacks);
}

/* The overlay construction stays available. */
static void test_overlay_method(void)
{
    double a[2 * 50], b[2 * 50];
    CHECK(rp_random_simple(a, 50, 8) == 0 && rp_star(b, 50, 9) == 0);
    cm_options o;
    cm_options_init(&o);
    o.method = CM_METHOD_OVERLAY, o.remesh = 0;
    const double *xy[2] = {a, b};
    size_t counts[2] = {50, 50};
    cm_result *r = NULL;
    CHECK(cm_triangulate_polygons(xy, counts, 2, &o, &r) == CM_OK);
    CHECK(rc_valid(r, xy, 2, 50));
    cm_result_free(r);
}

int main(void)
{
    test_default_method();
    test_affine_pairs();
    test_convex_pairs();
    test_brute_force_pairs();
    test_stuck_quad();
    test_stars();
    test_large_star_pair();
    test_clockwise();
    test_link_splits();
    test_above_table_limit();
    test_large_random_pairs();
    test_balanced_cut_levels();
    test_space_partition_polygons();
    test_overlay_method();
    test_property();
    return check_summary("test_partition");
}
