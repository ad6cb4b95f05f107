/* The guaranteed construction on the classic hard pairs and a seeded
 * property test. Every fixture states what it expects: a valid result
 * (cm_triangulate checks itself exactly; the test checks again here, from
 * the public arrays), the output order contract, and a Steiner bound. */
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "compatmesh/compatmesh.h"
#include "geom/predicates.h"
#include "random_polygons.h"
#include "result_check.h"

typedef struct {
    const char *name;
    size_t k, n;
    double *xy[3];
    size_t max_steiner; /* what the fixture promises */
} fixture;

/* This file tests the overlay construction as built: no longer the default
 * method, and not remeshed (the remesher has its own tests). */
static cm_options overlay_options(void)
{
    cm_options o;
    cm_options_init(&o);
    o.method = CM_METHOD_OVERLAY;
    o.remesh = 0;
    return o;
}

static void run_fixture(const fixture *f)
{
    cm_result *r = NULL;
    cm_options o = overlay_options();
    cm_status s = cm_triangulate_polygons((const double *const *)f->xy,
                                          (size_t[]){f->n, f->n, f->n}, f->k, &o, &r);
    CHECK_MSG(s == CM_OK, "%s: %s", f->name, cm_result_message(r));
    CHECK_MSG(rc_valid(r, (const double *const *)f->xy, f->k, f->n), "%s: invalid", f->name);
    const cm_stats *st = cm_result_stats(r);
    CHECK_MSG(st->steiner <= f->max_steiner, "%s: %zu Steiner vertices > %zu", f->name,
              st->steiner, f->max_steiner);
    printf("%-28s k=%zu n=%-5zu steiner=%-6zu triangles=%zu\n", f->name, f->k, f->n,
           st->steiner, st->triangles);
    cm_result_free(r);
}

static double *polygon(size_t n)
{
    return calloc(2 * n, sizeof(double));
}

static void test_classic_pairs(void)
{
    size_t n = 60;
    fixture f = {"convex vs convex", 2, n, {polygon(n), polygon(n), NULL}, 0};
    rp_disc(f.xy[0], (int)n);
    for (size_t i = 0; i < n; i++) f.xy[1][2 * i] = 2 * f.xy[0][2 * i] + 1, f.xy[1][2 * i + 1] = 0.5 * f.xy[0][2 * i + 1];
    /* Both ear clippings give the same Delaunay fan of an affine image?
     * Not necessarily: promise only the O(n^2) bound of the construction. */
    f.max_steiner = n * n;
    run_fixture(&f);

    f.name = "star vs star";
    rp_star(f.xy[0], (int)n, 1), rp_star(f.xy[1], (int)n, 2);
    run_fixture(&f);

    f.name = "spiral vs disc";
    rp_spiral(f.xy[0], (int)n, 2.0), rp_disc(f.xy[1], (int)n);
    run_fixture(&f);

    f.name = "comb vs disc";
    rp_comb(f.xy[0], (int)n, 6), rp_disc(f.xy[1], (int)n);
    run_fixture(&f);

    f.name = "twisted star";
    rp_star(f.xy[0], (int)n, 3);
    memcpy(f.xy[1], f.xy[0], 2 * n * sizeof(double));
    rp_twist(f.xy[1], (int)n, (int)n / 3);
    run_fixture(&f);

    f.name = "k=3 star, spiral, comb";
    f.k = 3;
    f.xy[2] = polygon(n);
    rp_star(f.xy[0], (int)n, 4), rp_spiral(f.xy[1], (int)n, 1.5), rp_comb(f.xy[2], (int)n, 5);
    f.max_steiner = n * n * n;
    run_fixture(&f);
    for (int g = 0; g < 3; g++) free(f.xy[g]);

    /* The identical polygon twice: one triangulation, no Steiner vertex. */
    n = 40;
    fixture same = {"same polygon twice", 2, n, {polygon(n), polygon(n), NULL}, 0};
    rp_random_simple(same.xy[0], (int)n, 7);
    memcpy(same.xy[1], same.xy[0], 2 * n * sizeof(double));
    run_fixture(&same);
    free(same.xy[0]), free(same.xy[1]);

    /* A triangle: nothing to do. */
    double t0[] = {0, 0, 1, 0, 0, 1}, t1[] = {5, 5, 7, 5, 5, 9};
    fixture tri = {"triangle", 2, 3, {t0, t1, NULL}, 0};
    run_fixture(&tri);

    /* Collinear runs (180-degree corners) are legal. */
    double sq0[] = {0, 0, 1, 0, 2, 0, 2, 1, 2, 2, 1, 2, 0, 2, 0, 1};
    double sq1[] = {0, 0, 1, 0.5, 2, 0, 2, 1, 3, 3, 1, 2, -1, 3, 0, 1};
    fixture col = {"collinear runs", 2, 8, {sq0, sq1, NULL}, 64};
    run_fixture(&col);
}

static void test_clockwise_input(void)
{
    size_t n = 30;
    double *a = polygon(n), *b = polygon(n);
    rp_star(a, (int)n, 11), rp_star(b, (int)n, 12);
    /* Reverse both: clockwise, same correspondence. */
    for (size_t i = 0; i < n / 2; i++)
        for (int c = 0; c < 2; c++) {
            double t = a[2 * i + c]; a[2 * i + c] = a[2 * (n - 1 - i) + c]; a[2 * (n - 1 - i) + c] = t;
            t = b[2 * i + c]; b[2 * i + c] = b[2 * (n - 1 - i) + c]; b[2 * (n - 1 - i) + c] = t;
        }
    const double *in[2] = {a, b};
    cm_result *r = NULL;
    cm_options o = overlay_options();
    CHECK(cm_triangulate_polygons(in, (size_t[]){n, n}, 2, &o, &r) == CM_OK);
    CHECK(cm_result_stats(r)->reversed_input == 1);
    CHECK(rc_valid(r, in, 2, n));
    /* Boundary half-edges run along the input's (clockwise) order. */
    const int32_t *vh = cm_result_vertex_halfedge(r), *to = cm_result_halfedge_to_vertex(r),
                  *face = cm_result_halfedge_face(r);
    int boundary_ok = 1;
    for (size_t v = 0; v < n; v++)
        boundary_ok &= face[vh[v]] < 0 && (size_t)to[vh[v]] == (v + 1) % n;
    CHECK_MSG(boundary_ok, "boundary half-edges follow the clockwise input");
    cm_result_free(r);
    free(a), free(b);
}

static void test_property_random_pairs(int count)
{
    int invalid = 0, failed = 0;
    size_t steiner_total = 0;
    for (int seed = 0; seed < count; seed++) {
        int n = 8 + seed % 40;
        double *a = polygon((size_t)n), *b = polygon((size_t)n);
        if (seed % 3 == 0) rp_random_simple(a, n, (uint64_t)seed), rp_random_simple(b, n, (uint64_t)seed + 100000);
        else if (seed % 3 == 1) rp_star(a, n, (uint64_t)seed), rp_random_simple(b, n, (uint64_t)seed);
        else rp_star(a, n, (uint64_t)seed), rp_star(b, n, (uint64_t)seed + 7), rp_twist(b, n, seed % n);
        const double *in[2] = {a, b};
        cm_result *r = NULL;
        cm_options o = overlay_options();
        cm_status s = cm_triangulate_polygons(in, (size_t[]){(size_t)n, (size_t)n}, 2, &o, &r);
        if (s != CM_OK) {
            failed++;
            fprintf(stderr, "seed %d: %s\n", seed, cm_result_message(r));
        } else if (!rc_valid(r, in, 2, (size_t)n)) {
            invalid++;
        } else {
            steiner_total += cm_result_stats(r)->steiner;
        }
        cm_result_free(r);
        free(a), free(b);
    }
    CHECK_MSG(failed == 0, "%d of %d random pairs failed", failed, count);
    CHECK_MSG(invalid == 0, "%d of %d random pairs invalid", invalid, count);
    printf("property: %d random pairs, mean Steiner %.1f\n", count, (double)steiner_total / count);
}

int main(void)
{
    test_classic_pairs();
    test_clockwise_input();
    test_property_random_pairs(1000);
    return check_summary("test_overlay");
}
