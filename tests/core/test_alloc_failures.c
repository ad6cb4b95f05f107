/* Every allocation of the core fails once: the call returns a clean status
 * (CM_ERR_NO_MEMORY with its message, or CM_OK with a valid result where
 * the failure was absorbed), never a crash, an abort or a wrong answer
 * reported as success. The test binary is linked with
 * -Wl,--wrap=malloc,--wrap=calloc,--wrap=realloc, which sends the core's
 * own calls (the static library's objects) through the counters below;
 * GMP's allocations go through the core's functions (base/gmp_memory.h)
 * and are counted too; UMFPACK's are its own and are not. Run for every
 * allocation of a triangulation with remeshing, a convex morph and a
 * sweep, the same with the map-aware remesher, of the overlay construction
 * (exact rational arithmetic in GMP throughout), and of the constructions
 * for polygons with holes (bridges that need Steiner bends; one bridge per
 * hole and the overlay; auto with the cap split on a hole loop, and with
 * the remesher's splits on one), and of the partition's steps for inputs above its
 * table limit (lowered: the fan, sampled splits). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <math.h>

#include <gmp.h>

void *__gmp_default_allocate(size_t); /* exported by libgmp, not declared */

#include "api/halfedge.h"
#include "api/result.h"
#include "base/gmp_memory.h"
#include "construct/partition.h"
#include "geom/polytri.h"
#include "check.h"
#include "hole_fixtures.h"
#include "random_polygons.h"
#include "result_check.h"

void *__real_malloc(size_t size);
void *__real_calloc(size_t count, size_t size);
void *__real_realloc(void *p, size_t size);

static long calls, fail_at = -1; /* the call that fails, 1-based; -1: none */
static int paused;               /* the test's own checks allocate too */

static int should_fail(void) { return !paused && ++calls == fail_at; }
void *__wrap_malloc(size_t size) { return should_fail() ? NULL : __real_malloc(size); }
void *__wrap_calloc(size_t count, size_t size) { return should_fail() ? NULL : __real_calloc(count, size); }
void *__wrap_realloc(void *p, size_t size) { return should_fail() ? NULL : __real_realloc(p, size); }

#define N 12
static cm_remesher remesher = CM_REMESHER_GREEDY; /* of run() */

/* One run: triangulate, morph, sweep. Returns the first failing status
 * (CM_OK when everything succeeded); checks every intermediate claim. */
static cm_status run(const double *const *polygons, char *where, size_t size)
{
    cm_result *r = NULL;
    size_t counts[2] = {N, N};
    cm_options o;
    cm_options_init(&o);
    o.remesher = remesher;
    cm_status s = cm_triangulate_polygons(polygons, counts, 2, &o, &r);
    /* No handle at all: the one failure that cannot carry a message. */
    snprintf(where, size, "triangulate: %s", r ? cm_result_message(r) : "out of memory (no handle)");
    char why[256] = "";
    paused = 1;
    int valid = s != CM_OK || rc_check(r, polygons, 2, N, why, sizeof why);
    paused = 0;
    if (!valid) {
        snprintf(where, size, "triangulate: success, but invalid: %s", why);
        s = CM_ERR_INTERNAL;
    }
    cm_morph *m = NULL;
    cm_sweep *w = NULL;
    if (s == CM_OK) {
        s = cm_morph_create(r, NULL, &m);
        snprintf(where, size, "morph: %s", m ? cm_morph_message(m) : "out of memory (no handle)");
    }
    if (s == CM_OK) {
        s = cm_sweep_create(m, NULL, &w);
        snprintf(where, size, "sweep: %s", w ? cm_sweep_message(w) : "out of memory (no handle)");
    }
    cm_sweep_free(w);
    cm_morph_free(m);
    cm_result_free(r);
    return s;
}

/* Two 12-vertex stars: run() on them. */
static double star_a[2 * N], star_b[2 * N];
static const double *const stars[2] = {star_a, star_b};

static cm_status run_stars(char *where, size_t size) { return run(stars, where, size); }

/* Annuli, the hole turned half a turn in the second (bent bridges). */
static shape annulus[2];
static int bent; /* the last successful run had Steiner vertices (bends) */
static cm_method holes_method; /* partition: the bridges' pieces; overlay: the construction that always succeeds */

static cm_status run_holes(char *where, size_t size)
{
    cm_loops in[2] = {{annulus[0].xy, annulus[0].sizes, 2}, {annulus[1].xy, annulus[1].sizes, 2}};
    cm_options o; /* the remesher's allocations are the first run's */
    cm_options_init(&o);
    o.remesh = 0;
    o.method = holes_method;
    cm_result *r = NULL;
    cm_status s = cm_triangulate_loops(in, 2, &o, &r);
    snprintf(where, size, "holes: %s", r ? cm_result_message(r) : "out of memory (no handle)");
    char why[256] = "";
    paused = 1;
    int valid = s != CM_OK || rc_check_loops(r, in, 2, why, sizeof why);
    paused = 0;
    if (!valid) {
        snprintf(where, size, "holes: success, but invalid: %s", why);
        s = CM_ERR_INTERNAL;
    }
    if (s == CM_OK) bent = cm_result_stats(r)->steiner > 0;
    cm_result_free(r);
    return s;
}

static void test_holes(void)
{
    hf_turned_hole_small(&annulus[0], &annulus[1]);
    for (int method = 0; method < 2; method++) {
        holes_method = method ? CM_METHOD_OVERLAY : CM_METHOD_PARTITION;
        const char *name = method ? "holes, overlay" : "holes";
        char where[512];
        calls = 0, fail_at = -1;
        CHECK_MSG(run_holes(where, sizeof where) == CM_OK, "%s: the run without failures: %s", name, where);
        CHECK_MSG(strstr(where, "holes: ") && bent, "the turned annulus's bridges bend");
        long total = calls, reported = 0;
        /* Every one of the first 1000 (validation, bridges, the first pieces),
         * then a sample: the pieces' partitions allocate tens of thousands of
         * times, and their allocations are the hole-free run's above. */
        for (long i = 1; i <= total; i += i < 1000 ? 1 : 211) {
            calls = 0, fail_at = i;
            cm_status s = run_holes(where, sizeof where);
            if (s == CM_OK) continue;
            reported++;
            CHECK_MSG(s == CM_ERR_NO_MEMORY && strstr(where, "out of memory"),
                      "%s: allocation %ld of %ld failed: status %s, %s", name, i, total, cm_status_string(s), where);
        }
        printf("%s: %ld allocations, the first 1000 and every 211th failed once: %ld reported out of memory\n",
               name, total, reported);
        CHECK(total > 50 && reported > 0);
    }
}

/* Two polygons with holes, auto with remeshing (slot_pair's or
 * crowd_pair's run); success must keep the expected boundary size
 * (*boundary; 0: not known yet, and then the run's). */
static cm_status run_auto_loops(const shape *pair, size_t *boundary, const char *name, char *where, size_t size)
{
    cm_loops in[2] = {{pair[0].xy, pair[0].sizes, pair[0].loops}, {pair[1].xy, pair[1].sizes, pair[1].loops}};
    cm_options o;
    cm_options_init(&o);
    o.correspondence = CM_CORRESPOND_AUTO;
    o.remesh = pair[0].loops <= 2; /* many holes: the construction's allocations, not the remesher's */
    cm_result *r = NULL;
    cm_status s = cm_triangulate_loops(in, 2, &o, &r);
    snprintf(where, size, "%s: %s", name, r ? cm_result_message(r) : "out of memory (no handle)");
    if (s == CM_OK && !*boundary) *boundary = cm_result_stats(r)->n;
    if (s == CM_OK && cm_result_stats(r)->n != *boundary) {
        snprintf(where, size, "%s: success with %zu boundary vertices, not %zu", name, cm_result_stats(r)->n, *boundary);
        s = CM_ERR_INTERNAL;
    }
    cm_result_free(r);
    return s;
}

/* Runs `runner` once without failures, then once with each of its
 * allocations failing: every failure must end in a clean out of memory. */
static void fail_each_allocation(const char *name, cm_status (*runner)(char *, size_t))
{
    char where[512];
    calls = 0, fail_at = -1;
    CHECK_MSG(runner(where, sizeof where) == CM_OK, "%s: the run without failures: %s", name, where);
    long total = calls, reported = 0;
    for (long i = 1; i <= total; i++) {
        calls = 0, fail_at = i;
        cm_status s = runner(where, sizeof where);
        if (s == CM_OK) continue;
        reported++;
        CHECK_MSG(s == CM_ERR_NO_MEMORY && strstr(where, "out of memory"),
                  "%s: allocation %ld of %ld failed: status %s, %s", name, i, total, cm_status_string(s), where);
    }
    printf("%s: %ld allocations, each failed once: %ld reported out of memory\n", name, total, reported);
    CHECK(total > 50 && reported > 0);
}

/* A 10 x 3 rectangle with a thin 8 x 1 hole against a scaled copy: the
 * hole loop's long edges bind their cap, so the cap split acts on the hole
 * loop, and the bridges' pieces take the partition's rule on input edges. */
static shape slot[2];

static cm_status run_slot(char *where, size_t size)
{
    static size_t boundary = 36; /* measured */
    return run_auto_loops(slot, &boundary, "slot", where, size);
}

static void test_holes_cap_split(void)
{
    begin_loop(&slot[0]);
    for (int i = 0; i < 10; i++) add_point(&slot[0], i, 0);
    for (int i = 0; i < 3; i++) add_point(&slot[0], 10, i);
    for (int i = 10; i > 0; i--) add_point(&slot[0], i, 3);
    for (int i = 3; i > 0; i--) add_point(&slot[0], 0, i);
    begin_loop(&slot[0]);
    add_point(&slot[0], 1, 1), add_point(&slot[0], 1, 2), add_point(&slot[0], 9, 2), add_point(&slot[0], 9, 1);
    slot[1] = slot[0];
    for (size_t i = 0; i < slot[1].n; i++) slot[1].xy[2 * i] *= 2, slot[1].xy[2 * i + 1] *= 2;
    fail_each_allocation("holes, cap split", run_slot);
}

/* The crowded hole against the hexagon (hole_fixtures.h): the remesher
 * splits edges of the loops (45 boundary vertices before it), so the
 * loops' new starts and the boundary's labels and coordinates are taken
 * over. How many it adds rounds differently with gcc and clang (48 and
 * 47): the run without failures sets the count. */
static shape crowd[2];
static size_t crowd_boundary; /* 0 till the run without failures */

static cm_status run_crowd(char *where, size_t size)
{
    return run_auto_loops(crowd, &crowd_boundary, "crowded hole", where, size);
}

static void test_holes_remesher_splits(void)
{
    hf_crowded_hole(&crowd[0], &crowd[1], -1);
    fail_each_allocation("holes, remesher's boundary splits", run_crowd);
    CHECK_MSG(crowd_boundary > 45, "crowded hole: %zu boundary vertices, 45 before remeshing", crowd_boundary);
}

/* Rectangular plates with three bolt holes (hole_fixtures.h): auto lets
 * the holes choose the outline's turn and pairs them by position. */
static shape plates[2];

static cm_status run_plates(char *where, size_t size)
{
    static size_t boundary = 68; /* measured */
    return run_auto_loops(plates, &boundary, "rectangular plates", where, size);
}

static void test_holes_matched(void)
{
    hf_rectangle_plates_near(&plates[0], &plates[1]);
    fail_each_allocation("holes matched by position", run_plates);
}

/* The overlay of two stars: its intersection points are GMP rationals, so
 * failures land inside GMP. Each must end the call with CM_ERR_NO_MEMORY
 * (the reserve carried GMP through) or a valid result, never an abort. */
static void test_gmp(const double *const *polygons)
{
    cm_options o;
    cm_options_init(&o);
    o.method = CM_METHOD_OVERLAY;
    o.remesh = 0;
    size_t counts[2] = {N, N};
    long total = -1, inside_gmp = 0, reported = 0;
    for (long i = 0; i <= total || total < 0; i++) {
        calls = 0, fail_at = i ? i : -1;
        cm_result *r = NULL;
        cm_status s = cm_triangulate_polygons(polygons, counts, 2, &o, &r);
        int reserve = cm_gmp_memory_exhausted();
        paused = 1;
        char why[256] = "";
        CHECK_MSG(s != CM_OK || rc_check(r, polygons, 2, N, why, sizeof why),
                  "overlay, allocation %ld failed: success, but invalid: %s", i, why);
        CHECK_MSG(s == CM_OK || (s == CM_ERR_NO_MEMORY && (!r || strstr(cm_result_message(r), "out of memory"))),
                  "overlay, allocation %ld failed: status %s, %s", i, cm_status_string(s),
                  r ? cm_result_message(r) : "no handle");
        paused = 0;
        cm_result_free(r);
        if (i == 0) {
            CHECK_MSG(s == CM_OK, "the overlay without failures");
            total = calls;
        }
        inside_gmp += reserve;
        reported += s != CM_OK;
    }
    void *(*a)(size_t);
    mp_get_memory_functions(&a, NULL, NULL);
    printf("overlay: %ld allocations, each failed once: %ld reported out of memory, %ld inside GMP\n", total,
           reported, inside_gmp);
    CHECK_MSG(a != __gmp_default_allocate, "GMP allocates through the core's functions");
    CHECK_MSG(inside_gmp > 0, "some failures hit GMP's allocations");
}

/* The same with the map-aware remesher. */
static void test_map_remesher(void)
{
    remesher = CM_REMESHER_MAP;
    fail_each_allocation("map remesher", run_stars);
    remesher = CM_REMESHER_GREEDY;
}

/* The partition with its table limit lowered to 12 on pairs of 40
 * vertices: a star pair (one fan without a table) and an exact affine pair
 * (sampled splits, then tables); each allocation fails once. */
static void test_above_table_limit(void)
{
    enum { M = 40 };
    double a[2 * M], b[2 * M];
    int32_t idx[M], ta[3 * (M - 2)], tb[3 * (M - 2)], *tris[2] = {ta, tb};
    for (int i = 0; i < M; i++) idx[i] = i;
    for (int pair = 0; pair < 2; pair++) {
        if (pair == 0) {
            CHECK(rp_star(a, M, 5) == 0 && rp_star(b, M, 6) == 0);
        } else {
            CHECK(rp_random_simple(a, M, 7) == 0);
            for (int i = 0; i < M; i++) b[2 * i] = a[2 * i] - 0.5 * a[2 * i + 1], b[2 * i + 1] = 0.5 * a[2 * i] + a[2 * i + 1];
        }
        const double *xy[2] = {a, b};
        CHECK(cm_polygon_triangulate(a, idx, M, ta, NULL) == 0 && cm_polygon_triangulate(b, idx, M, tb, NULL) == 0);
        long total = -1, reported = 0;
        for (long i = 0; i <= total || total < 0; i++) {
            paused = 1;
            cm_result *r = calloc(1, sizeof *r);
            cm_partition_stats st;
            paused = 0;
            calls = 0, fail_at = i ? i : -1;
            cm_status s = cm_partition_limited(xy, (const int32_t *const *)tris, 2, M, 12, NULL, &r->mesh, &st, &r->error);
            paused = 1;
            r->n = M;
            CHECK_MSG(s == CM_OK ? cm_halfedge_build_and_check(r, idx, NULL, 1) == CM_OK
                                 : s == CM_ERR_NO_MEMORY && strstr(r->error.message, "out of memory"),
                      "partition above the limit, pair %d, allocation %ld failed: status %s, %s", pair, i,
                      cm_status_string(s), r->error.message);
            if (i == 0) {
                CHECK_MSG(s == CM_OK && (pair == 0 ? st.fans == 1 && st.sampled_splits == 0 : st.sampled_splits >= 2),
                          "pair %d without failures: %zu fans, %zu sampled splits", pair, st.fans, st.sampled_splits);
                total = calls;
            }
            reported += s != CM_OK;
            cm_result_free(r);
            paused = 0;
        }
        printf("partition above the table limit, pair %d: %ld allocations, each failed once: %ld reported out of memory\n",
               pair, total, reported);
        CHECK(reported > 0);
    }
}

int main(void)
{
    CHECK(rp_star(star_a, N, 3) == 0 && rp_star(star_b, N, 4) == 0);
    fail_each_allocation("triangulate, morph, sweep", run_stars);
    test_gmp(stars);
    test_map_remesher();
    test_holes();
    test_holes_cap_split();
    test_holes_remesher_splits();
    test_holes_matched();
    test_above_table_limit();
    return check_summary("test_alloc_failures");
}
