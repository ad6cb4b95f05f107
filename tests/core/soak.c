/* Soak: random valid polygon pairs (and triples) of 5 to 16 vertices
 * through cm_triangulate
 * with the default options (partition + remeshing), every result checked
 * by result_check.h. Any failed call or invalid result is a failure: the
 * inputs are simple polygons, so each must give a valid triangulation.
 *
 *   soak PAIRS [FIRST_SEED]   prints one line per failure and a summary
 *                             (progress every 5000 cases on stderr);
 *                             exit status 1 if anything failed.
 *
 * `make test` runs a few hundred pairs, `make soak` 100,000. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "random_polygons.h"
#include "result_check.h"

enum { MAX_N = 40 };

/* Polygon number `which` of a case: the shape family comes from the seed. */
static int make_polygon(int family, int n, uint64_t seed, int which, const double *first, double *xy)
{
    uint64_t s = seed * 3 + (uint64_t)which * 7777;
    switch (family) {
    case 0: return rp_star(xy, n, s);
    case 1: return rp_random_simple(xy, n, s);
    case 2: return which ? rp_star(xy, n, s) : rp_random_simple(xy, n, s);
    case 3: /* the same star, correspondence rotated */
        if (!which) return rp_star(xy, n, s);
        memcpy(xy, first, sizeof(double) * 2 * (size_t)n);
        rp_twist(xy, n, 1 + (int)(seed % (uint64_t)(n - 1)));
        return 0;
    case 4: return which ? rp_random_simple(xy, n, s) : rp_spiral(xy, n, 1 + (double)(seed % 2));
    default: return which ? rp_random_simple(xy, n, s) : rp_comb(xy, n, 2 + (int)(seed % 2));
    }
}

/* Exact transforms (the coordinates are multiples of 2^-24 in [-1, 1]):
 * scale by a power of two, shift by an integer, or reverse the order. */
static void transform(double *xy, int n, uint64_t seed, int which)
{
    rp_rng rng = {seed * 31 + (uint64_t)which};
    int kind = (int)rp_below(&rng, 8);
    if (kind == 0) {
        double scale = ldexp(1.0, (int)rp_below(&rng, 200) - 100);
        for (int i = 0; i < 2 * n; i++) xy[i] *= scale;
    } else if (kind == 1) {
        double shift = (double)rp_below(&rng, 1u << 20);
        for (int i = 0; i < 2 * n; i++) xy[i] += shift;
    }
}

int main(int argc, char **argv)
{
    long pairs = argc > 1 ? atol(argv[1]) : 300;
    uint64_t seed = argc > 2 ? strtoull(argv[2], NULL, 10) : 1;
    long done = 0, invalid = 0, failed = 0, triples = 0, steiner = 0;
    double a[3][2 * MAX_N];
    clock_t start = clock();
    for (; done < pairs; seed++) {
        int family = (int)(seed % 6);
        int n = 5 + (int)((seed / 6) % 12);
        size_t k = seed % 10 == 9 ? 3 : 2;
        int clockwise = seed % 7 == 3;
        int bad = 0;
        for (size_t g = 0; g < k && !bad; g++) {
            bad = make_polygon(family, n, seed + g / 2, (int)(g % 2), a[0], a[g]) != 0;
            if (!bad && g == 2) transform(a[g], n, seed, 2);
        }
        if (bad) continue;
        transform(a[0], n, seed, 0);
        transform(a[1], n, seed, 1);
        if (clockwise)
            for (size_t g = 0; g < k; g++) rp_reverse(a[g], 0, n - 1);
        const double *xy[3] = {a[0], a[1], a[2]};
        size_t counts[3] = {(size_t)n, (size_t)n, (size_t)n};
        cm_result *r = NULL;
        cm_status s = cm_triangulate_polygons(xy, counts, k, NULL, &r);
        char why[256];
        if (s != CM_OK) {
            failed++;
            printf("seed %llu (family %d, n %d, k %zu): %s: %s\n", (unsigned long long)seed, family, n,
                   k, cm_status_string(s), r ? cm_result_message(r) : "(no handle)");
        } else if (!rc_check(r, xy, k, (size_t)n, why, sizeof why)) {
            invalid++;
            printf("seed %llu (family %d, n %d, k %zu): invalid result reported as success: %s\n",
                   (unsigned long long)seed, family, n, k, why);
        } else {
            steiner += (long)cm_result_stats(r)->steiner;
        }
        cm_result_free(r);
        triples += k == 3;
        if (++done % 5000 == 0)
            fprintf(stderr, "soak: %ld cases, %ld invalid, %ld failed, %.0f s CPU\n", done, invalid,
                    failed, (double)(clock() - start) / CLOCKS_PER_SEC);
    }
    double seconds = (double)(clock() - start) / CLOCKS_PER_SEC;
    printf("soak: %ld cases (%ld with 3 polygons), %ld invalid, %ld failed, %ld Steiner vertices, "
           "%.1f s CPU\n", done, triples, invalid, failed, steiner, seconds);
    return invalid || failed;
}
