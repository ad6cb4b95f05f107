/* Compatible remeshing: every local operation keeps every geometry valid
 * (a property test over random meshes), the smoothing variants on fixed
 * meshes, transactions restore exactly, and Algorithm 1 reaches stated
 * angle and Steiner bounds on fixtures. Every fixture states what it
 * expects, so a quality regression fails here. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "compatmesh/compatmesh.h"
#include "api/quality.h"
#include "remesh/kmesh.h"
#include "geom/angle.h"
#include "geom/looptri.h"
#include "geom/predicates.h"
#include "random_mesh.h"
#include "random_polygons.h"
#include "result_check.h"
#include "remesh/areaeq.h"
#include "remesh/collapse.h"
#include "remesh/criteria.h"
#include "remesh/flip.h"
#include "remesh/mapopt.h"
#include "remesh/polish_moves.h"
#include "remesh/maprefine.h"
#include "remesh/maxmin.h"
#include "remesh/refine.h"
#include "remesh/remesh.h"
#include "remesh/restart.h"
#include "remesh/smooth.h"

#define DEG (180.0 / CM_PI)
/* Degrees an affine image may cost against the polygon alone. */
#define CM_TEST_AFFINE_MARGIN 4.0

/* ---- helpers ------------------------------------------------------------ */

static double *polygon(size_t n) { return calloc(2 * n, sizeof(double)); }

/* The result's mesh as a cm_mesh (counter-clockwise input: same order). */
static int mesh_from_result(const cm_result *r, cm_mesh *m)
{
    size_t k = cm_result_num_geometries(r), nv = cm_result_num_vertices(r);
    size_t nt = cm_result_num_triangles(r);
    m->k = k, m->nv = nv, m->nt = nt;
    m->xy = calloc(k, sizeof *m->xy);
    m->tri = malloc(3 * nt * sizeof *m->tri);
    if (!m->xy || !m->tri) return -1;
    memcpy(m->tri, cm_result_triangles(r), 3 * nt * sizeof *m->tri);
    for (size_t g = 0; g < k; g++) {
        if (!(m->xy[g] = malloc(2 * nv * sizeof *m->xy[g]))) return -1;
        memcpy(m->xy[g], cm_result_vertices(r, g), 2 * nv * sizeof *m->xy[g]);
    }
    return 0;
}

/* The construction alone, as a cm_mesh. */
static int construct(const double *const *in, size_t k, size_t n, cm_mesh *m)
{
    cm_options o;
    cm_options_init(&o);
    o.remesh = 0;
    cm_result *r = NULL;
    size_t counts[3] = {n, n, n};
    int ok = cm_triangulate_polygons(in, counts, k, &o, &r) == CM_OK && mesh_from_result(r, m) == 0;
    cm_result_free(r);
    return ok ? 0 : -1;
}

/* The cached keys and candidate heaps agree with the geometry (the
 * candidates as read by the refinement). */
static int keys_fresh(cm_kmesh *km)
{
    const cm_heap *eq = cm_kmesh_candidates(km);
    for (int32_t t = 0; t < km->nt; t++) {
        if (!cm_kmesh_tri_live(km, t)) {
            if (cm_heap_contains(&km->tq, t)) return 0;
            continue;
        }
        double key = CM_PI;
        const double *tang = km->tang + (size_t)t * km->k; /* the per-geometry angles, where known */
        for (size_t g = 0; g < km->k; g++) {
            key = fmin(key, cm_kmesh_tri_angle(km, g, t));
            if (!isnan(tang[0]) && tang[g] != cm_kmesh_tri_angle(km, g, t)) return 0;
        }
        if (key != km->tkey[t] || !cm_heap_contains(&km->tq, t)) return 0;
        for (int32_t c = 3 * t; c < 3 * t + 3; c++) {
            int32_t o = km->opp[c];
            if (o < 0 || o < c) continue;
            int want = km->slack[t] < 0 || km->slack[o / 3] < 0;
            if (want != cm_heap_contains(eq, c) || cm_heap_contains(eq, o)) return 0;
        }
    }
    return 1;
}

static int boundary_intact(const cm_kmesh *km, const double *const *in)
{
    for (size_t g = 0; g < km->k; g++)
        if (memcmp(km->xy[g], in[g], 2 * (size_t)km->n * sizeof(double)) != 0) return 0;
    return 1;
}

static int same_mesh(const cm_mesh *a, const cm_mesh *b)
{
    if (a->nv != b->nv || a->nt != b->nt || memcmp(a->tri, b->tri, 3 * a->nt * sizeof *a->tri)) return 0;
    for (size_t g = 0; g < a->k; g++)
        if (memcmp(a->xy[g], b->xy[g], 2 * a->nv * sizeof(double))) return 0;
    return 1;
}

static void random_pair(int seed, int n, double *a, double *b)
{
    switch (seed % 4) {
    case 0: rp_star(a, n, (uint64_t)seed), rp_star(b, n, (uint64_t)seed + 1000); break;
    case 1: rp_random_simple(a, n, (uint64_t)seed), rp_disc(b, n); break;
    case 2: rp_star(a, n, (uint64_t)seed), memcpy(b, a, 2 * (size_t)n * sizeof *b), rp_twist(b, n, n / 3); break;
    default: rp_random_simple(a, n, (uint64_t)seed), rp_random_simple(b, n, (uint64_t)seed + 77); break;
    }
}

/* ---- the property test ------------------------------------------------------ */

/* Map-aware energies: the map term alone, the shape term alone, both. */
static cm_mapopt_weights map_weights(rp_rng *rng)
{
    switch (rp_below(rng, 3)) {
    case 0: return (cm_mapopt_weights){1.0, 0.0, 1.0};
    case 1: return (cm_mapopt_weights){0.0, 1.0, 4.0};
    default: return (cm_mapopt_weights){1.0, 0.1, 1.0};
    }
}

/* One random operation; returns 0, -1 out of memory. */
static int random_operation(cm_kmesh *km, rp_rng *rng, cm_ibuf *star, cm_work *work)
{
    int32_t c = (int32_t)rp_below(rng, 3 * (uint64_t)km->nt);
    int32_t v = (int32_t)rp_below(rng, (uint64_t)km->nv);
    size_t g = (size_t)rp_below(rng, km->k);
    if (km->tri[c] < 0) return 0;
    switch (rp_below(rng, 14)) {
    case 0: cm_flip_try(km, c); return 0;
    case 1: cm_flip_if_valid(km, c); return 0;
    case 2: return cm_smooth_vertex(km, g, v, (cm_smoothing)rp_below(rng, 4), (int)rp_below(rng, 2), star) < 0 ? -1 : 0;
    case 3: return cm_smooth_optimize(km, g, v, star) < 0 ? -1 : 0;
    case 4: return cm_areaeq_vertex(km, g, v, star) < 0 ? -1 : 0;
    case 5: return cm_refine_step(km, 1 + (long)rp_below(rng, 4), work) < 0 ? -1 : 0;
    case 6: return cm_collapse_try(km, c, star) < 0 ? -1 : 0;
    case 7: return cm_collapse_pass(km, rp_below(rng, 2) ? 0.0 : CM_PI, 2, work) < 0 ? -1 : 0;
    case 8: return cm_mapopt_local(km, map_weights(rng), 1) < 0 ? -1 : 0;
    case 9: return km->vc[v] >= 0 && cm_mapopt_vertex(km, map_weights(rng), v, 2, star) < 0 ? -1 : 0;
    case 10: return cm_flip_queue_all(km, work) || cm_mid_flip_queue(km, work) < 0 ? -1 : 0;
    case 11: return cm_mid_insert(km, c / 3) == -1 ? -1 : 0;
    case 12: return km->opp[c] < 0 && cm_refine_split(km, c) == CM_NO_MEMORY ? -1 : 0; /* a boundary edge */
    default: return cm_kmesh_star(km, km->vc[v] >= 0 ? v : 0, star) == -1 ? -1 : 0;
    }
}

/* After begin, random operations, rollback: the mesh must be as before,
 * and so must the smoothing's dirty bits (all but CM_DIRTY_OPTIMIZE). */
static int rollback_restores(cm_kmesh *km, rp_rng *rng, cm_ibuf *star, cm_work *work)
{
    cm_mesh before = {km->k, 0, 0, calloc(km->k, sizeof(double *)), NULL, NULL, 0};
    cm_mesh after = {km->k, 0, 0, calloc(km->k, sizeof(double *)), NULL, NULL, 0};
    int32_t nv = km->nv;
    uint16_t *dirty = malloc((size_t)nv * sizeof *dirty);
    int ok = dirty && before.xy && after.xy && cm_kmesh_write(km, &before) == CM_OK && cm_kmesh_tx_begin(km) == 0;
    if (dirty) memcpy(dirty, km->vdirty, (size_t)nv * sizeof *dirty);
    for (int i = 0; ok && i < 8; i++) ok = random_operation(km, rng, star, work) == 0;
    ok = ok && cm_kmesh_tx_rollback(km) == 0 && cm_kmesh_write(km, &after) == CM_OK;
    ok = ok && same_mesh(&before, &after) && keys_fresh(km) && km->nv == nv;
    for (int32_t v = 0; ok && v < nv; v++) ok = ((dirty[v] ^ km->vdirty[v]) & ~CM_DIRTY_OPTIMIZE) == 0;
    cm_mesh_clear(&before), cm_mesh_clear(&after);
    free(dirty);
    return ok;
}

/* Clears the smoothing bit of every vertex and geometry where the
 * smoothing formulas leave the vertex in place, as the remesher does.
 * Returns -1 out of memory. */
static int settle_smoothing(cm_kmesh *km, cm_ibuf *star)
{
    for (int32_t v = km->n; v < km->nv; v++)
        for (size_t g = 0; g < km->k && km->vc[v] >= 0; g++) {
            int s = cm_smooth_vertex(km, g, v, CM_SMOOTH_COMBINED, 1, star);
            if (s < 0) return -1;
            if (s == 0) km->vdirty[v] &= (uint16_t)~cm_dirty_smooth(g);
        }
    return 0;
}

/* Where a vertex's smoothing bit is clear, the smoothing formulas must
 * still leave it in place: every change that matters set the bit. Counts
 * the vertices they would move. */
static int stale_smoothing_bits(cm_kmesh *km, cm_ibuf *star)
{
    int stale = 0;
    for (int32_t v = km->n; v < km->nv; v++)
        for (size_t g = 0; g < km->k && km->vc[v] >= 0; g++)
            if (!(km->vdirty[v] & cm_dirty_smooth(g)))
                stale += cm_smooth_vertex(km, g, v, CM_SMOOTH_COMBINED, 1, star) == 1;
    return stale;
}

/* Random pair number seed (8 to 37 vertices), its construction and the
 * kmesh on it with a 25 degree cap; 0 on success, else nothing is left
 * allocated. */
static int random_kmesh(int seed, double **a, double **b, cm_mesh *m, cm_kmesh *km)
{
    int n = 8 + seed % 30;
    *a = polygon((size_t)n), *b = polygon((size_t)n);
    random_pair(seed, n, *a, *b);
    const double *in[2] = {*a, *b};
    *m = (cm_mesh){0};
    if (construct(in, 2, (size_t)n, m) || cm_kmesh_build(km, m, (size_t)n) != CM_OK) {
        cm_mesh_clear(m), free(*a), free(*b);
        return -1;
    }
    cm_kmesh_set_caps(km, 25 / DEG, NULL, NULL);
    return 0;
}

/* Boundary splits on a kmesh whose geometries are the input polygons
 * themselves (ctx: the k polygons, counter-clockwise, km->n vertices;
 * labels: vertex i is (i, 0)): the point at the middle parameter of the
 * input edge, nudged by ulps, as the pipeline's labels give it. */
typedef struct split_inputs {
    const double *const *in;
    size_t n;
} split_inputs;

static int test_between(void *ctx, size_t g, int32_t ea, double ta, int32_t eb, double tb, int step, int32_t *e,
                        double *t, double xy[2])
{
    const split_inputs *s = ctx;
    double t0 = ta, t1 = eb == ea ? tb : 1.0, mid = 0.5 * (t0 + t1);
    for (int i = 0; i < (step + 1) / 2; i++) mid = nextafter(mid, step % 2 ? t0 : t1);
    if (!(t0 < mid && mid < t1)) return 0;
    const double *p = s->in[g] + 2 * ea, *q = s->in[g] + 2 * (((size_t)ea + 1) % s->n);
    *e = ea, *t = mid;
    xy[0] = p[0] + mid * (q[0] - p[0]), xy[1] = p[1] + mid * (q[1] - p[1]);
    return 1;
}

/* Boundary labels on the input polygons (split_inputs): vertex i is (i, 0) in both. 0, or -1 out of memory. */
static int input_labels(size_t n, int32_t *edge[2], double *t[2])
{
    for (int g = 0; g < 2; g++) edge[g] = malloc(n * sizeof **edge), t[g] = calloc(n, sizeof **t);
    int ok = edge[0] && edge[1] && t[0] && t[1];
    for (size_t i = 0; ok && i < n; i++) edge[0][i] = edge[1][i] = (int32_t)i;
    return ok ? 0 : -1;
}

static int allow_splits(cm_kmesh *km, const split_inputs *s)
{
    int32_t *edge[2];
    double *t[2];
    int ok = input_labels(s->n, edge, t) == 0 &&
             cm_kmesh_allow_boundary_splits(km, test_between, (void *)s, (const int32_t *const *)edge,
                                            (const double *const *)t) == 0;
    free(edge[0]), free(edge[1]), free(t[0]), free(t[1]);
    return ok;
}

/* Every boundary vertex added by a split: live, at the point its labels
 * give, bit for bit, in every geometry. Returns how many are not. */
static int misplaced_splits(const cm_kmesh *km, const split_inputs *s)
{
    int bad = 0;
    for (int32_t v = km->n; v < km->nv; v++) {
        if (km->vc[v] < 0 || !cm_kmesh_is_boundary(km, v)) continue;
        for (size_t g = 0; g < km->k; g++) {
            int32_t e = km->bedge[km->k * (size_t)v + g];
            double t = km->bt[km->k * (size_t)v + g];
            const double *p = s->in[g] + 2 * e, *q = s->in[g] + 2 * (((size_t)e + 1) % s->n), *x = cm_kmesh_pos(km, g, v);
            bad += !(0 < t && t < 1) || x[0] != p[0] + t * (q[0] - p[0]) || x[1] != p[1] + t * (q[1] - p[1]);
        }
    }
    return bad;
}

static void test_property_operations(int pairs, int operations)
{
    int invalid = 0, stale = 0, moved = 0, restore = 0, built = 0, unflagged = 0, misplaced = 0, split = 0;
    for (int seed = 0; seed < pairs; seed++) {
        double *a, *b;
        cm_mesh m;
        cm_kmesh km;
        if (random_kmesh(seed, &a, &b, &m, &km)) continue;
        const double *in[2] = {a, b};
        split_inputs inputs = {in, (size_t)km.n};
        built++;
        if (seed % 2) CHECK(allow_splits(&km, &inputs)); /* odd seeds: boundary splits too */
        rp_rng rng = {(uint64_t)seed * 7919};
        cm_ibuf star = {0};
        cm_work work = {0};
        for (int i = 0; i < operations; i++) {
            if (random_operation(&km, &rng, &star, &work)) break;
            while (cm_work_pop(&work) >= 0) {}
            invalid += !cm_kmesh_check(&km);
            moved += !boundary_intact(&km, in);
            if (i % 16 == 0) stale += !keys_fresh(&km);
            if (i % 64 == 0) restore += !rollback_restores(&km, &rng, &star, &work);
            if (i % 32 == 0 && settle_smoothing(&km, &star)) break;
            if (i % 32 == 31) unflagged += stale_smoothing_bits(&km, &star);
            if (seed % 2 && i % 16 == 0) misplaced += misplaced_splits(&km, &inputs);
        }
        split += km.nb > km.n;
        cm_ibuf_free(&star), cm_work_free(&work);
        cm_kmesh_free(&km), cm_mesh_clear(&m);
        free(a), free(b);
    }
    CHECK_MSG(built == pairs, "%d of %d constructions", built, pairs);
    CHECK_MSG(invalid == 0, "%d operations left an invalid mesh", invalid);
    CHECK_MSG(moved == 0, "%d operations moved a boundary vertex", moved);
    CHECK_MSG(stale == 0, "%d stale key checks", stale);
    CHECK_MSG(restore == 0, "%d rollbacks did not restore", restore);
    CHECK_MSG(unflagged == 0, "%d vertices moved by the smoothing though their bit said nothing changed", unflagged);
    CHECK_MSG(misplaced == 0, "%d boundary split points off their labels", misplaced);
    CHECK_MSG(split >= pairs / 4, "boundary splits in %d of %d meshes that allow them", split, pairs / 2);
    printf("property: %d random meshes x %d operations (%d with boundary splits)\n", pairs, operations, split);
}

/* The global map descent and the middle-metric refinement (not inside a
 * transaction, so outside the random operations): on random pairs
 * refined a little, every accepted state is valid in every geometry, the
 * boundary stays bit-identical, the keys stay fresh, the energy does not
 * rise and the refinement never lowers the smallest angle. */
static void test_map_descent(int pairs)
{
    int invalid = 0, moved = 0, stale = 0, rose = 0, stepped = 0, built = 0, dropped = 0;
    for (int seed = 0; seed < pairs; seed++) {
        double *a, *b;
        cm_mesh m;
        cm_kmesh km;
        if (random_kmesh(seed, &a, &b, &m, &km)) continue;
        const double *in[2] = {a, b};
        built++;
        cm_work work = {0};
        for (int i = 0; i < 3; i++) CHECK(cm_refine_step(&km, 4, &work) >= 0);
        cm_work_free(&work);
        cm_mapopt_weights w = {1.0, seed % 2 ? 0.1 : 1.0, seed % 3 ? 1.0 : 4.0};
        double before = cm_mapopt_energy(&km, w);
        long steps = cm_mapopt_run(&km, w, 30);
        CHECK(steps >= 0);
        stepped += steps > 0;
        rose += cm_mapopt_energy(&km, w) > before * (1 + 1e-12);
        invalid += !cm_kmesh_check(&km);
        moved += !boundary_intact(&km, in);
        stale += !keys_fresh(&km);
        /* the middle-metric refinement: its own transactions */
        double lo = cm_kmesh_min_angle(&km);
        CHECK(cm_mid_refine(&km, 1.0, km.live_v - km.n + 20, w) >= 0);
        invalid += !cm_kmesh_check(&km);
        moved += !boundary_intact(&km, in);
        stale += !keys_fresh(&km);
        dropped += cm_kmesh_min_angle(&km) < lo;
        cm_kmesh_free(&km), cm_mesh_clear(&m);
        free(a), free(b);
    }
    CHECK_MSG(built == pairs, "%d of %d constructions", built, pairs);
    CHECK_MSG(invalid == 0 && moved == 0 && stale == 0, "map descent: %d invalid, %d moved boundaries, %d stale",
              invalid, moved, stale);
    CHECK_MSG(rose == 0, "map descent: the energy rose on %d meshes", rose);
    CHECK_MSG(dropped == 0, "middle refinement: the smallest angle dropped on %d meshes", dropped);
    CHECK_MSG(stepped * 2 >= pairs, "map descent: steps on only %d of %d meshes", stepped, pairs);
    printf("map descent: %d random meshes, %d took steps\n", pairs, stepped);
}

/* ---- smoothing and area equalisation ----------------------------------------- */

/* A polygon with random interior vertices, as in the paper's Fig. 7(e). */
static int fixture_mesh(int convex, cm_kmesh *km)
{
    size_t n = 40;
    double *poly = polygon(n);
    int s = convex ? rp_disc(poly, (int)n) : rp_star(poly, (int)n, 5);
    cm_mesh m = {0};
    s = s || rm_build(poly, n, 150, 42, 2, &m) || cm_kmesh_build(km, &m, n) != CM_OK;
    cm_mesh_clear(&m);
    free(poly);
    return s ? -1 : 0;
}

static const char *method_name[] = {"Laplacian", "angle-based", "weighted angle-based", "combined"};

static void test_smoothing_variants(void)
{
    for (int convex = 1; convex >= 0; convex--)
        for (int method = 0; method < 4; method++)
            for (int smart = 0; smart <= 1; smart++) {
                cm_kmesh km;
                if (fixture_mesh(convex, &km)) {
                    CHECK_MSG(0, "fixture mesh");
                    continue;
                }
                double start = cm_kmesh_min_angle(&km), last = start;
                int monotone = 1, valid = 1;
                for (int sweep = 0; sweep < 20; sweep++) {
                    CHECK(cm_smooth_pass(&km, (cm_smoothing)method, smart) >= 0);
                    double now = cm_kmesh_min_angle(&km);
                    monotone &= now >= last;
                    valid &= cm_kmesh_check(&km);
                    last = now;
                }
                CHECK_MSG(valid, "%s %s: invalid", smart ? "smart" : "plain", method_name[method]);
                /* Smart variants never decrease the smallest angle; on the
                 * convex fixture every variant improves it. */
                if (smart) CHECK_MSG(monotone, "smart %s decreased the smallest angle", method_name[method]);
                if (convex || smart)
                    CHECK_MSG(last >= start, "%s %s: %.2f -> %.2f", smart ? "smart" : "plain",
                              method_name[method], start * DEG, last * DEG);
                printf("%-10s %-6s %-21s min angle %5.2f -> %5.2f\n", convex ? "disc" : "star",
                       smart ? "smart" : "plain", method_name[method], start * DEG, last * DEG);
                cm_kmesh_free(&km);
            }
}

static double geometry_min_angle(const cm_mesh *m, size_t g)
{
    double least = HUGE_VAL;
    for (size_t t = 0; t < m->nt; t++) {
        const int32_t *v = m->tri + 3 * t;
        least = fmin(least, cm_triangle_min_angle(m->xy[g] + 2 * v[0], m->xy[g] + 2 * v[1], m->xy[g] + 2 * v[2]));
    }
    return least;
}

/* Fig. 7(e)'s mesh of a disc (convex) or a random star with n boundary
 * vertices and 60 random interior ones, in two geometries made different
 * by a shear of the second. 0, or -1 (m cleared). */
static int sheared_fixture(int convex, uint64_t seed, size_t n, cm_mesh *m)
{
    double *poly = polygon(n);
    int bad = !poly || (convex ? rp_disc(poly, (int)n) : rp_star(poly, (int)n, (int)seed));
    bad = bad || rm_build(poly, n, 60, seed, 2, m);
    free(poly);
    if (bad) {
        cm_mesh_clear(m);
        return -1;
    }
    for (size_t v = 0; v < m->nv; v++) m->xy[1][2 * v] += 0.5 * m->xy[1][2 * v + 1];
    return 0;
}

/* The joint polish on random interior vertices (Fig. 7(e)'s mesh, two
 * geometries made different by a shear): every geometry stays exactly
 * counter-clockwise, the boundary and the connectivity are untouched, no
 * smallest angle falls, and from random positions the least over the
 * geometries at least doubles (the one lowest at the start goes first,
 * the other stops once it is above what the first reached). */
static void test_joint_polish(void)
{
    for (int convex = 1; convex >= 0; convex--)
        for (uint64_t seed = 1; seed <= 4; seed++) {
            size_t n = 40;
            cm_mesh m = {0};
            if (sheared_fixture(convex, seed, n, &m)) {
                CHECK_MSG(0, "fixture mesh");
                continue;
            }
            cm_mesh before = m;
            double *keep[2], start[2];
            int32_t *tri = malloc(3 * m.nt * sizeof *tri);
            for (size_t g = 0; g < 2; g++) {
                keep[g] = malloc(2 * m.nv * sizeof(double));
                memcpy(keep[g], m.xy[g], 2 * m.nv * sizeof(double));
                start[g] = geometry_min_angle(&m, g);
            }
            memcpy(tri, m.tri, 3 * m.nt * sizeof *tri);
            CHECK(cm_maxmin_polish(&m, n, NULL, 1, 400, NULL) == CM_OK);
            CHECK(m.nv == before.nv && m.nt == before.nt && !memcmp(tri, m.tri, 3 * m.nt * sizeof *tri));
            size_t first = start[1] < start[0];
            double least_start = fmin(start[0], start[1]), first_now = geometry_min_angle(&m, first);
            CHECK_MSG(fmin(first_now, geometry_min_angle(&m, 1 - first)) >= 2 * least_start,
                      "%s seed %d: the least smallest angle %.3f -> %.3f degrees", convex ? "disc" : "star", (int)seed,
                      least_start * DEG, fmin(first_now, geometry_min_angle(&m, 1 - first)) * DEG);
            for (size_t g = 0; g < 2; g++) {
                CHECK_MSG(!memcmp(keep[g], m.xy[g], 2 * n * sizeof(double)), "boundary moved");
                int ccw = 1;
                for (size_t t = 0; t < m.nt; t++) {
                    const int32_t *v = m.tri + 3 * t;
                    ccw &= cm_orient2d(m.xy[g] + 2 * v[0], m.xy[g] + 2 * v[1], m.xy[g] + 2 * v[2]) > 0;
                }
                double now = geometry_min_angle(&m, g);
                CHECK_MSG(ccw, "joint polish: a triangle turned");
                printf("joint polish, %s seed %d geometry %zu: %.3f -> %.3f degrees\n", convex ? "disc" : "star", (int)seed, g,
                       start[g] * DEG, now * DEG);
                CHECK_MSG(now >= start[g], "%s seed %d geometry %zu: %.3f -> %.3f degrees",
                          convex ? "disc" : "star", (int)seed, g, start[g] * DEG, now * DEG);
                free(keep[g]);
            }
            free(tri);
            cm_mesh_clear(&m);
        }
}

/* The joint polish leaves a geometry far above the other as it is: the
 * sheared disc polished, then its first geometry's interior put back at
 * its random start and polished a few iterations only (so it stays far
 * below the second): the second is bit-identical, the first rose. */
static void test_joint_polish_lowest_first(void)
{
    size_t n = 40;
    cm_mesh m = {0}, fresh = {0};
    if (sheared_fixture(1, 1, n, &m) || sheared_fixture(1, 1, n, &fresh)) {
        CHECK_MSG(0, "fixture mesh");
        cm_mesh_clear(&m), cm_mesh_clear(&fresh);
        return;
    }
    CHECK(cm_maxmin_polish(&m, n, NULL, 1, 2000, NULL) == CM_OK);
    memcpy(m.xy[0], fresh.xy[0], 2 * m.nv * sizeof(double));
    double *second = malloc(2 * m.nv * sizeof *second);
    memcpy(second, m.xy[1], 2 * m.nv * sizeof *second);
    double low = geometry_min_angle(&m, 0), high = geometry_min_angle(&m, 1);
    CHECK(cm_maxmin_polish(&m, n, NULL, 1, 5, NULL) == CM_OK);
    double now = geometry_min_angle(&m, 0);
    printf("joint polish, lowest first: %.3f -> %.3f degrees, the other at %.3f\n", low * DEG, now * DEG, high * DEG);
    CHECK_MSG(now > low && now < high, "the first geometry %.3f -> %.3f degrees, the other at %.3f", low * DEG,
              now * DEG, high * DEG);
    CHECK_MSG(!memcmp(second, m.xy[1], 2 * m.nv * sizeof *second), "the geometry above moved");
    free(second);
    cm_mesh_clear(&m), cm_mesh_clear(&fresh);
}

/* The polish-scored moves on random meshes with random interior
 * vertices (two geometries, the second sheared, aim 30 degrees): every
 * kept state is a valid compatible mesh in every geometry (the full
 * exact check), the smallest angle over both geometries never falls, and
 * from such a start it rises on every mesh. */
static void test_polish_moves(void)
{
    for (int convex = 1; convex >= 0; convex--)
        for (uint64_t seed = 1; seed <= 3; seed++) {
            size_t n = 40;
            cm_mesh m = {0};
            cm_kmesh km = {0};
            int bad = sheared_fixture(convex, seed, n, &m);
            bad = bad || cm_kmesh_build(&km, &m, n) != CM_OK;
            cm_mesh_clear(&m);
            if (bad) {
                CHECK_MSG(0, "fixture mesh");
                continue;
            }
            cm_kmesh_set_caps(&km, 30.0 / DEG, NULL, NULL);
            double start = cm_kmesh_min_angle(&km), now = start;
            long kept = 0, total = 0;
            cm_pmove_limits limits = cm_pmove_limits_of(&km);
            limits.tries = 25;
            for (int batch = 0; batch < 4 && kept >= 0; batch++) { /* a check between batches */
                kept = cm_polish_moves(&km, &limits, 10, NULL, NULL, NULL);
                double after = cm_kmesh_min_angle(&km);
                CHECK_MSG(kept >= 0, "polish moves failed");
                CHECK_MSG(cm_kmesh_check(&km), "polish moves: %s seed %d left an invalid mesh", convex ? "disc" : "star",
                          (int)seed);
                CHECK_MSG(after >= now, "polish moves: the smallest angle fell, %.4f -> %.4f degrees", now * DEG,
                          after * DEG);
                now = after, total += kept > 0 ? kept : 0;
            }
            printf("polish moves, %s seed %d: %.3f -> %.3f degrees, %ld moves kept\n", convex ? "disc" : "star",
                   (int)seed, start * DEG, now * DEG, total);
            CHECK_MSG(now > start, "polish moves: %s seed %d gained nothing (%.3f degrees)", convex ? "disc" : "star",
                      (int)seed, start * DEG);
            cm_kmesh_free(&km);
        }
}

/* cm_maxmin_slide's place on split_inputs: the formula misplaced_splits
 * checks the points against. */
static void test_place(void *ctx, size_t g, int32_t e, double t, double xy[2])
{
    const split_inputs *s = ctx;
    const double *p = s->in[g] + 2 * e, *q = s->in[g] + 2 * (((size_t)e + 1) % s->n);
    xy[0] = p[0] + t * (q[0] - p[0]), xy[1] = p[1] + t * (q[1] - p[1]);
}

/* A random pair's kmesh whose boundary edges are split first, on the
 * input polygons themselves (in: room for the two polygons that inputs
 * points to), caps at 30 degrees. 0, or -1 (nothing to free). */
static int sliding_kmesh(int seed, const double *in[2], split_inputs *inputs, double **a, double **b, cm_mesh *m,
                         cm_kmesh *km)
{
    if (random_kmesh(seed, a, b, m, km)) return -1;
    in[0] = *a, in[1] = *b;
    *inputs = (split_inputs){in, (size_t)km->n};
    if (!allow_splits(km, inputs)) {
        cm_kmesh_free(km), cm_mesh_clear(m), free(*a), free(*b);
        return -1;
    }
    for (int32_t c = 0, splits = 0; c < 3 * km->nt && splits < km->n; c++)
        if (km->tri[c] >= 0 && km->opp[c] < 0) splits += cm_refine_split(km, c) >= 0;
    cm_kmesh_set_caps(km, 30.0 / DEG, NULL, NULL);
    return 0;
}

/* The polish-scored moves with boundary points that slide (random pairs,
 * boundary edges split first): every kept state is exactly valid, every
 * boundary point lies where its labels say in every geometry (so an undone
 * move restored the parameters it slid, and a slid point is on its input
 * edge), the smallest angle never falls, and points do slide. */
static void test_polish_moves_slide(void)
{
    size_t slid = 0;
    int meshes = 0;
    for (int seed = 1; seed <= 24; seed++) {
        double *a, *b;
        const double *in[2];
        split_inputs inputs;
        cm_mesh m;
        cm_kmesh km;
        if (sliding_kmesh(seed, in, &inputs, &a, &b, &m, &km)) {
            CHECK_MSG(0, "seed %d: no kmesh with its boundary edges split", seed);
            continue;
        }
        cm_maxmin_slide slide = {NULL, NULL, test_place, &inputs, 0, 0, NULL, NULL};
        double now = cm_kmesh_min_angle(&km);
        cm_pmove_limits limits = cm_pmove_limits_of(&km);
        limits.tries = 20;
        for (int batch = 0; batch < 3; batch++) {
            long kept = cm_polish_moves(&km, &limits, 10, &slide, NULL, NULL);
            double after = cm_kmesh_min_angle(&km);
            CHECK_MSG(kept >= 0, "polish moves failed");
            CHECK_MSG(cm_kmesh_check(&km), "polish moves with slides: seed %d left an invalid mesh", seed);
            CHECK_MSG(misplaced_splits(&km, &inputs) == 0, "seed %d: boundary points off their labels", seed);
            CHECK_MSG(after >= now, "polish moves with slides: the smallest angle fell, %.4f -> %.4f degrees",
                      now * DEG, after * DEG);
            now = after;
        }
        slid += slide.slid, meshes++;
        cm_kmesh_free(&km), cm_mesh_clear(&m);
        free(a), free(b);
    }
    printf("polish moves with slides: %d meshes, %zu boundary points slid\n", meshes, slid);
    CHECK_MSG(meshes == 24, "%d of 24 meshes", meshes);
    CHECK_MSG(slid > 0, "no boundary point slid");
}

/* Runs of the polish-scored moves that share a memo (cm_pmove_memo: the
 * moves undone before, counted without being run again) end exactly as
 * runs that try every move again: the same moves kept, the same
 * positions bit for bit, in every geometry. A move the memo skipped that
 * would have been kept shows as a difference. */
static void test_polish_moves_memo(void)
{
    int meshes = 0, carried = 0;
    for (int seed = 1; seed <= 16; seed++) {
        const double *in[2][2];
        split_inputs inputs[2];
        double *a[2], *b[2];
        cm_mesh m[2];
        cm_kmesh km[2];
        if (sliding_kmesh(seed, in[0], &inputs[0], &a[0], &b[0], &m[0], &km[0])) continue;
        if (sliding_kmesh(seed, in[1], &inputs[1], &a[1], &b[1], &m[1], &km[1])) {
            cm_kmesh_free(&km[0]), cm_mesh_clear(&m[0]), free(a[0]), free(b[0]);
            continue;
        }
        cm_pmove_memo memo = {0};
        cm_pmove_limits limits = cm_pmove_limits_of(&km[0]);
        limits.tries = 15;
        int same = 1;
        for (int batch = 0; batch < 4 && same; batch++) {
            long kept[2];
            for (int i = 0; i < 2; i++) {
                cm_maxmin_slide slide = {NULL, NULL, test_place, &inputs[i], 0, 0, NULL, NULL};
                kept[i] = cm_polish_moves(&km[i], &limits, 10, &slide, i ? NULL : &memo, NULL);
            }
            carried += batch > 0 && memo.n > 0;
            same = kept[0] == kept[1] && km[0].nv == km[1].nv && km[0].nt == km[1].nt;
            for (int32_t v = 0; same && v < km[0].nv; v++)
                for (size_t g = 0; g < 2; g++)
                    same &= km[0].vc[v] == km[1].vc[v] &&
                            (km[0].vc[v] < 0 ||
                             memcmp(cm_kmesh_pos(&km[0], g, v), cm_kmesh_pos(&km[1], g, v), 2 * sizeof(double)) == 0);
            CHECK_MSG(same, "seed %d batch %d: with the memo %ld moves kept, without %ld, or other positions", seed,
                      batch, kept[0], kept[1]);
        }
        cm_pmove_memo_free(&memo);
        for (int i = 0; i < 2; i++) cm_kmesh_free(&km[i]), cm_mesh_clear(&m[i]), free(a[i]), free(b[i]);
        meshes++;
    }
    printf("polish moves with a memo: %d meshes, %d later runs began with moves undone before\n", meshes, carried);
    CHECK_MSG(meshes == 16, "%d of 16 meshes", meshes);
    CHECK_MSG(carried > 0, "no run began with a move undone before: the memo was not exercised");
}

/* cm_remesh of a copy of start into out, with boundary splits on inputs
 * when `splits` (the final labels then in edge and t, *nb of them),
 * restarts as given, resume as given. */
static cm_status remesh_copy(const cm_mesh *start, size_t n, int restarts, int splits, split_inputs *inputs,
                             int32_t *edge[2], double *t[2], cm_remesh_resume *resume, cm_mesh *out,
                             cm_remesh_report *rep, size_t *nb)
{
    cm_options o;
    cm_options_init(&o);
    o.restarts = restarts;
    cm_error err = {0};
    *rep = (cm_remesh_report){0};
    if (cm_mesh_copy(out, start) || (splits && input_labels(n, edge, t))) return CM_ERR_NO_MEMORY;
    cm_remesh_boundary b = {test_between, inputs, edge, t, n, test_place, 0, 0};
    cm_status s = cm_remesh(out, n, &o, 60.0, 0, splits ? &b : NULL, resume, NULL, rep, &err);
    *nb = b.n;
    return s;
}

/* A run without restarts that keeps where they start (cm_remesh_resume),
 * then the same mesh remeshed with a restart from there, ends exactly as
 * one whole run with the restart: the same mesh bit for bit, the same
 * report, the same boundary labels where boundary edges split. */
static void test_remesh_resume(void)
{
    int runs = 0, resumed = 0;
    for (int seed = 1; seed <= 12; seed++)
        for (int splits = 0; splits <= 1; splits++) {
            int n = 12 + seed % 20;
            double *a = polygon((size_t)n), *b = polygon((size_t)n);
            random_pair(seed, n, a, b);
            const double *in[2] = {a, b};
            split_inputs inputs = {in, (size_t)n};
            cm_mesh start = {0}, whole = {0}, once = {0}, again = {0};
            int32_t *edge[3][2] = {{0}};
            double *t[3][2] = {{0}};
            size_t nb[3];
            cm_remesh_resume resume = {0};
            cm_remesh_report rw, ro, ra;
            int ok = construct(in, 2, (size_t)n, &start) == 0;
            ok = ok &&
                 remesh_copy(&start, (size_t)n, 1, splits, &inputs, edge[0], t[0], NULL, &whole, &rw, &nb[0]) == CM_OK;
            ok = ok && remesh_copy(&start, (size_t)n, 0, splits, &inputs, edge[1], t[1], &resume, &once, &ro,
                                   &nb[1]) == CM_OK;
            CHECK_MSG(ok, "seed %d: a run failed", seed);
            CHECK_MSG(!ok || (resume.mesh.nv > 0) == ro.restart_wanted,
                      "seed %d: kept where the restarts start %s a restart was wanted", seed,
                      ro.restart_wanted ? "though no" : "where no");
            if (ok && resume.mesh.nv > 0) {
                ok = remesh_copy(&start, (size_t)n, 1, splits, &inputs, edge[2], t[2], &resume, &again, &ra, &nb[2]) ==
                     CM_OK;
                int same = ok && same_mesh(&whole, &again) && memcmp(&rw, &ra, sizeof rw) == 0 && nb[0] == nb[2] &&
                           resume.mesh.nv == 0;
                for (int g = 0; same && splits && g < 2; g++)
                    same = memcmp(edge[0][g], edge[2][g], nb[0] * sizeof **edge[0]) == 0 &&
                           memcmp(t[0][g], t[2][g], nb[0] * sizeof **t[0]) == 0;
                CHECK_MSG(same, "seed %d%s: resumed from where the restarts start, not the whole run's result", seed,
                          splits ? " (boundary splits)" : "");
                resumed++;
            }
            runs += ok;
            cm_remesh_resume_clear(&resume);
            cm_mesh_clear(&start), cm_mesh_clear(&whole), cm_mesh_clear(&once), cm_mesh_clear(&again);
            for (int i = 0; i < 3; i++)
                for (int g = 0; g < 2; g++) free(edge[i][g]), free(t[i][g]);
            free(a), free(b);
        }
    printf("remesh resumed: %d runs, %d resumed from where the restarts start\n", runs, resumed);
    CHECK_MSG(resumed > 0, "no run wanted a restart: the resume was not exercised");
}

static double area_spread(const cm_kmesh *km, size_t g)
{
    double sum = 0, sum2 = 0;
    long count = 0;
    for (int32_t t = 0; t < km->nt; t++) {
        if (!cm_kmesh_tri_live(km, t)) continue;
        const int32_t *v = km->tri + 3 * t;
        double a = rm_area2(cm_kmesh_pos(km, g, v[0]), cm_kmesh_pos(km, g, v[1]), cm_kmesh_pos(km, g, v[2]));
        sum += a, sum2 += a * a, count++;
    }
    double mean = sum / (double)count;
    return sqrt(fmax(0, sum2 / (double)count - mean * mean)) / mean;
}

static void test_area_equalisation(void)
{
    cm_kmesh km;
    if (fixture_mesh(0, &km)) {
        CHECK_MSG(0, "fixture mesh");
        return;
    }
    double before = area_spread(&km, 0);
    int valid = 1;
    for (int i = 0; i < 10; i++) {
        CHECK(cm_areaeq_pass(&km, NULL) >= 0);
        valid &= cm_kmesh_check(&km);
    }
    double after = area_spread(&km, 0);
    CHECK_MSG(valid, "area equalisation left an invalid mesh");
    CHECK_MSG(after < 0.8 * before, "area spread %.3f -> %.3f", before, after);
    printf("area equalisation: relative spread of triangle areas %.3f -> %.3f\n", before, after);
    cm_kmesh_free(&km);
}

static void test_refine_keeps_boundary(void)
{
    size_t n = 30;
    double *a = polygon(n), *b = polygon(n);
    rp_star(a, (int)n, 3), rp_star(b, (int)n, 4);
    const double *in[2] = {a, b};
    cm_mesh m = {0};
    cm_kmesh km;
    if (construct(in, 2, n, &m) || cm_kmesh_build(&km, &m, n) != CM_OK) {
        CHECK_MSG(0, "construction");
        cm_mesh_clear(&m), free(a), free(b);
        return;
    }
    cm_kmesh_set_caps(&km, 59 / DEG, NULL, NULL); /* everything is a candidate */
    cm_work touched = {0};
    long total = 0;
    for (int round = 0; round < 20; round++) {
        long s = cm_refine_step(&km, 5, &touched);
        CHECK(s >= 0);
        total += s;
    }
    /* cm_kmesh_check also checks the boundary edges are exactly i -> i+1 */
    CHECK(cm_kmesh_check(&km) && boundary_intact(&km, in) && keys_fresh(&km));
    CHECK_MSG(total > 50 && km.live_v == (int32_t)m.nv + total, "%ld splits", total);
    cm_work_free(&touched), cm_kmesh_free(&km), cm_mesh_clear(&m);
    free(a), free(b);
}

/* ---- the boundary caps ------------------------------------------------------- */

/* cm_boundary_caps on mesh equals, bit for bit, the smallest over the
 * geometries of the scan of every segment. Returns the mismatches. */
static int caps_mismatches(const cm_mesh *m, size_t n, const char *what)
{
    double *bcap = malloc(2 * n * sizeof *bcap);
    int bad = 0;
    if (!bcap || cm_boundary_caps(m, n, NULL, bcap, bcap + n) != 0) {
        CHECK_MSG(0, "%s: cm_boundary_caps failed", what);
        free(bcap);
        return 1;
    }
    for (size_t i = 0; i < n; i++) {
        double scan = CM_PI;
        for (size_t g = 0; g < m->k; g++) scan = fmin(scan, cm_edge_cap_scan(m, m->xy[g], n, i));
        if (scan != bcap[i] && bad++ < 3)
            fprintf(stderr, "%s: edge %zu: cap %.17g, scan %.17g\n", what, i, bcap[i], scan);
    }
    CHECK_MSG(bad == 0, "%s: %d edge caps differ from the scan", what, bad);
    free(bcap);
    return bad;
}

/* The constrained Delaunay triangulation of one polygon's loops as a
 * one-geometry mesh over xy. 0, or -1. */
static int loops_mesh(double *xy, size_t n, const size_t *starts, size_t loops, double **geom, cm_mesh *m)
{
    *m = (cm_mesh){.k = 1, .nv = n, .nt = n + 2 * (loops - 1) - 2, .xy = geom, .loop_start = starts,
                   .num_loops = loops};
    geom[0] = xy;
    m->tri = malloc(3 * m->nt * sizeof *m->tri);
    if (m->tri && cm_loops_triangulate(xy, starts, loops, m->tri) == 0) return 0;
    free(m->tri), m->tri = NULL;
    return -1;
}

static void test_boundary_caps(void)
{
    /* By hand: a 2 x 1 box with a notch down to (1, 0.5) in its top. On
     * the bottom edge the notch's tip enters the isosceles triangle first,
     * at height 0.5 (above the edge's midpoint): cap atan(2 * 0.5 / 2). A
     * side edge's equilateral triangle fits: 60 degrees. The notch's tip
     * is a reflex corner of 270 degrees: vcap 135. */
    double notch[14] = {0, 0, 2, 0, 2, 1, 1.5, 1, 1, 0.5, 0.5, 1, 0, 1}, *geom[1], bcap[14];
    size_t one[2] = {0, 7};
    cm_mesh m;
    CHECK(loops_mesh(notch, 7, one, 1, geom, &m) == 0);
    CHECK(cm_boundary_caps(&m, 7, NULL, bcap, bcap + 7) == 0);
    CHECK_MSG(fabs(bcap[0] - atan(0.5)) < 1e-15, "bottom edge cap %.17g", bcap[0] * DEG);
    CHECK_MSG(fabs(bcap[1] - CM_PI / 3) < 1e-15, "side edge cap %.17g", bcap[1] * DEG);
    CHECK_MSG(fabs(bcap[7 + 4] - 0.75 * CM_PI) < 1e-15, "notch vcap %.17g", bcap[7 + 4] * DEG);
    caps_mismatches(&m, 7, "notched box");
    /* One triangle further: the tip, seen at 45 degrees from both ends of
     * the bottom edge, leaves its cap; the right side's triangle keeps
     * (1.5, 1) out of it and of the one across its side: 45 degrees, where
     * both neighbours' triangles have 26.6 */
    double whole[14];
    memcpy(whole, bcap, sizeof whole);
    CHECK(cm_near_vertex_caps(&m, 7, NULL, bcap) == 0);
    CHECK_MSG(bcap[0] == whole[0], "notched box: bottom edge %.17g", bcap[0] * DEG);
    CHECK_MSG(fabs(bcap[1] - CM_PI / 4) < 1e-15, "notched box: side edge %.17g", bcap[1] * DEG);
    for (size_t i = 0; i < 7; i++) CHECK(bcap[i] <= whole[i]);
    free(m.tri);
    m.tri = NULL, m.nt = 0; /* no triangles: no walk */
    CHECK(cm_boundary_caps(&m, 7, NULL, bcap, bcap + 7) == CM_CAPS_NOT_TRIANGULATED);

    /* A 4 x 2 box whose notch reaches down to p = (3.2, 0.3), 0.8 short of
     * the bottom edge's end b = (4, 0): seen from b at phi = atan(0.3 /
     * 0.8), p allows the bottom edge's triangle phi / 2 one triangle
     * further; the isosceles cap, where p enters first, allows 2 phi */
    double deep[14] = {0, 0, 4, 0, 4, 2, 3.7, 2, 3.2, 0.3, 2.7, 2, 0, 2}, dcap[14];
    CHECK(loops_mesh(deep, 7, one, 1, geom, &m) == 0);
    CHECK(cm_boundary_caps(&m, 7, NULL, dcap, dcap + 7) == 0);
    CHECK_MSG(fabs(dcap[0] - atan(0.375)) < 1e-12, "deep notch: bottom edge cap %.17g", dcap[0] * DEG);
    double iso[7];
    memcpy(iso, dcap, sizeof iso);
    CHECK(cm_near_vertex_caps(&m, 7, NULL, dcap) == 0);
    CHECK_MSG(fabs(dcap[0] - atan(0.375) / 2) < 1e-12, "deep notch: near-vertex cap %.17g", dcap[0] * DEG);
    for (size_t i = 0; i < 7; i++) CHECK(dcap[i] <= iso[i]);
    free(m.tri);

    /* Random simple polygons, stars and combs: each alone (constrained
     * Delaunay) and two unrelated ones through the construction (long
     * skinny triangles, Steiner vertices). */
    int mismatched = 0;
    for (int shape = 0; shape < 3; shape++) {
        const char *name = shape == 0 ? "random" : shape == 1 ? "star" : "comb";
        size_t n = shape == 0 ? 300 : shape == 1 ? 1500 : 600;
        double *a = polygon(n), *b = polygon(n);
        int made = shape == 0   ? rp_random_simple(a, (int)n, 11) || rp_random_simple(b, (int)n, 12)
                   : shape == 1 ? rp_star(a, (int)n, 13) || rp_star(b, (int)n, 14)
                                : rp_comb(a, (int)n, 25) || rp_comb(b, (int)n, 7);
        CHECK_MSG(made == 0, "%s: not generated", name);
        size_t loop[2] = {0, n};
        if (made == 0 && loops_mesh(a, n, loop, 1, geom, &m) == 0) {
            mismatched += caps_mismatches(&m, n, name);
            free(m.tri);
        }
        const double *in[2] = {a, b};
        cm_mesh two = {0};
        CHECK_MSG(made == 0 && construct(in, 2, n, &two) == 0, "%s: no construction", name);
        if (made == 0 && two.tri) mismatched += caps_mismatches(&two, n, name);
        cm_mesh_clear(&two), free(a), free(b);
    }

    /* Holes: a star with two clockwise star holes near its centre, the
     * loops read through loop_start. */
    size_t outer = 500, hole = 60, n = outer + 2 * hole, starts[4] = {0, outer, outer + hole, n};
    double *xy = polygon(n);
    CHECK(rp_star(xy, (int)outer, 21) == 0);
    for (int h = 0; h < 2; h++) {
        double *p = xy + 2 * (outer + h * hole);
        CHECK(rp_star(p, (int)hole, 22 + (uint64_t)h) == 0);
        for (size_t i = 0; i < hole; i++) p[2 * i] = 0.08 * p[2 * i] + (h ? 0.12 : -0.12), p[2 * i + 1] *= 0.08;
        rp_reverse(p, 0, (int)hole - 1);
    }
    CHECK(loops_mesh(xy, n, starts, 3, geom, &m) == 0);
    if (m.tri) mismatched += caps_mismatches(&m, n, "star with holes");
    free(m.tri), free(xy);
    printf("boundary caps: equal to the scan on %s\n", mismatched ? "NOT all shapes" : "all shapes");
}

/* ---- Algorithm 1 on fixtures ---------------------------------------------------- */

/* DejaVu Sans "U" and "S" outlines resampled to 40 points (bench/gen_pairs),
 * the S re-indexed so the strokes' ends correspond (the paper's Fig. 8). */
static const double glyph_u[80] = {
    0.1481542587, 0.06862878799, 0.2249205112, 0.01191866398, 0.3178288341, -0.01171135902,
    0.4139226079, -0.01176172495, 0.5068225265, 0.01187700033, 0.5834668279, 0.06876212358,
    0.6286566257, 0.1530073285, 0.6443853378, 0.2477124929, 0.6450195312, 0.3439624906,
    0.6450195312, 0.4402228594, 0.6450195312, 0.5364832282, 0.6450195312, 0.6327435374,
    0.6450195312, 0.7290039062, 0.5954589844, 0.7290039062, 0.5458984375, 0.7290039062,
    0.5458984375, 0.638181746, 0.5458984375, 0.5473595858, 0.5458984375, 0.4565374255,
    0.5458984375, 0.3657152653, 0.5457929373, 0.2748937607, 0.5351647139, 0.1848937869,
    0.4928273559, 0.1059654355, 0.4112155437, 0.06927990913, 0.3207430243, 0.06931966543,
    0.2391095161, 0.1059686542, 0.1967688799, 0.1848937869, 0.1861406565, 0.2748937607,
    0.1860351562, 0.3657152653, 0.1860351562, 0.4565374255, 0.1860351562, 0.5473595858,
    0.1860351562, 0.638181746, 0.1860351562, 0.7290039062, 0.1364746094, 0.7290039062,
    0.0869140625, 0.7290039062, 0.0869140625, 0.6327435374, 0.0869140625, 0.5364832282,
    0.0869140625, 0.4402228594, 0.0869140625, 0.3439624906, 0.08754390478, 0.2477123141,
    0.1031703949, 0.1529870033,
};
static const double glyph_s[80] = {
    0.5787082911, 0.2161140442, 0.5546479225, 0.3054177165, 0.4902101159, 0.3715337515,
    0.4045072198, 0.407595098, 0.3133260608, 0.4273289442, 0.2234179378, 0.4516196847,
    0.1667770743, 0.5198052526, 0.1855356693, 0.6086692214, 0.264395237, 0.654974103,
    0.3571612239, 0.6612282395, 0.4485359788, 0.6433608532, 0.53515625, 0.6088867188,
    0.53515625, 0.6569824219, 0.53515625, 0.705078125, 0.4455113411, 0.72926718,
    0.3534716964, 0.7413079739, 0.2607685328, 0.7381004095, 0.1722177863, 0.7114021182,
    0.101424098, 0.6525586843, 0.06803101301, 0.5669199228, 0.07338601351, 0.4747544527,
    0.1223192215, 0.3974818587, 0.2037768364, 0.3538687825, 0.2937985063, 0.3312738538,
    0.3841862679, 0.3101732731, 0.4592226148, 0.258446455, 0.473949492, 0.1687481403,
    0.4231504202, 0.09438425303, 0.3350829482, 0.06753313541, 0.2424556613, 0.07037836313,
    0.1528631449, 0.09433573484, 0.06884765625, 0.1337890625, 0.06884765625, 0.0830078125,
    0.06884765625, 0.0322265625, 0.1579453349, 0.004658639431, 0.2497505546, -0.01157879829,
    0.3429397345, -0.01268815994, 0.4346039295, 0.003600776196, 0.5162452459, 0.04740804434,
    0.5674923658, 0.1240240932,
};

static void fill_us(double *u, double *s)
{
    memcpy(u, glyph_u, sizeof glyph_u);
    memcpy(s, glyph_s, sizeof glyph_s);
}

typedef struct fixture {
    const char *name;
    size_t n;
    double *xy[2];
    double min_angle_deg; /* promised in both geometries */
    size_t max_steiner;
} fixture;

/* Smallest interior corner angle of the two polygons, degrees. */
static double smallest_corner(const double *const *in, size_t n)
{
    double lo = 360;
    for (size_t g = 0; g < 2; g++)
        for (size_t i = 0; i < n; i++) {
            const double *a = in[g] + 2 * ((i + n - 1) % n), *b = in[g] + 2 * i, *c = in[g] + 2 * ((i + 1) % n);
            double t = atan2((c[0] - b[0]) * (a[1] - b[1]) - (c[1] - b[1]) * (a[0] - b[0]),
                             (c[0] - b[0]) * (a[0] - b[0]) + (c[1] - b[1]) * (a[1] - b[1]));
            lo = fmin(lo, (t < 0 ? t + 2 * CM_PI : t) * DEG);
        }
    return lo;
}

static void run_fixture(const fixture *f)
{
    const double *in[2] = {f->xy[0], f->xy[1]};
    cm_result *r = NULL;
    cm_status s = cm_triangulate_polygons(in, (size_t[]){f->n, f->n}, 2, NULL, &r);
    CHECK_MSG(s == CM_OK, "%s: %s", f->name, cm_result_message(r));
    if (s != CM_OK) {
        cm_result_free(r);
        return;
    }
    CHECK_MSG(rc_valid(r, in, 2, f->n), "%s: output contract", f->name);
    cm_quality q[2], q0[2];
    for (size_t g = 0; g < 2; g++) {
        cm_result_quality(r, g, &q[g]);
        CHECK(cm_result_quality_before(r, g, &q0[g]) == CM_OK);
        CHECK_MSG(q[g].min_angle_deg >= f->min_angle_deg, "%s: geometry %zu min angle %.2f < %.2f",
                  f->name, g, q[g].min_angle_deg, f->min_angle_deg);
    }
    const cm_stats *st = cm_result_stats(r);
    CHECK_MSG(st->steiner <= f->max_steiner, "%s: %zu Steiner > %zu", f->name, st->steiner, f->max_steiner);
    printf("%-26s n=%-3zu corner %5.1f  min angle %5.2f %5.2f (before %5.2f %5.2f)  Steiner %zu "
           "(before %zu)\n", f->name, f->n, smallest_corner(in, f->n), q[0].min_angle_deg,
           q[1].min_angle_deg, q0[0].min_angle_deg, q0[1].min_angle_deg, st->steiner,
           st->steiner_before_remesh);
    cm_result_free(r);
}

/* The polygon against an affine image of it. */
static void affine_copy(const double *a, double *b, size_t n)
{
    for (size_t i = 0; i < n; i++)
        b[2 * i] = 1.5 * a[2 * i] + 0.4 * a[2 * i + 1] + 3, b[2 * i + 1] = -0.2 * a[2 * i] + 0.8 * a[2 * i + 1];
}

static void test_algorithm1_fixtures(void)
{
    size_t n = 40;
    fixture f = {"U / S glyphs", n, {polygon(n), polygon(n)}, 0, 0};

    fill_us(f.xy[0], f.xy[1]);
    f.min_angle_deg = 19.0, f.max_steiner = 30; /* the paper: 17.1 and 17.6 with 7 */
    run_fixture(&f);

    f.name = "star vs its affine image";
    rp_star(f.xy[0], (int)n, 9), affine_copy(f.xy[0], f.xy[1], n);
    f.min_angle_deg = 10.5, f.max_steiner = 40; /* corner 11.9: c / 2 = 6 */
    run_fixture(&f);

    f.name = "comb vs its affine image";
    rp_comb(f.xy[0], (int)n, 4), affine_copy(f.xy[0], f.xy[1], n);
    f.min_angle_deg = 10.0, f.max_steiner = 50;
    run_fixture(&f);

    f.name = "spiral vs its affine image";
    rp_spiral(f.xy[0], (int)n, 1.5), affine_copy(f.xy[0], f.xy[1], n);
    f.min_angle_deg = 16.5, f.max_steiner = 20;
    run_fixture(&f);

    n = 16, f.n = n;
    f.name = "star pair n=16";
    rp_star(f.xy[0], (int)n, 32), rp_star(f.xy[1], (int)n, 33);
    f.min_angle_deg = 15.0, f.max_steiner = 60;
    run_fixture(&f);

    f.name = "twisted star n=16";
    rp_star(f.xy[0], (int)n, 1016), memcpy(f.xy[1], f.xy[0], 2 * n * sizeof(double));
    rp_twist(f.xy[1], (int)n, 5);
    f.min_angle_deg = 20.0, f.max_steiner = 45;
    run_fixture(&f);
    free(f.xy[0]), free(f.xy[1]);
}

/* Smallest angle over both geometries of the remeshed pair (a, b), -1
 * on failure; the result checked against the output contract. */
static double pair_min_angle(const double *a, const double *b, size_t n, cm_remesher remesher)
{
    const double *in[2] = {a, b};
    cm_options o;
    cm_options_init(&o);
    o.remesher = remesher;
    o.min_angle_deg = 32; /* above what either reaches: no early stop */
    cm_result *r = NULL;
    double lo = -1;
    if (cm_triangulate_polygons(in, (size_t[]){n, n}, 2, &o, &r) == CM_OK && rc_valid(r, in, 2, n)) {
        cm_quality q[2];
        cm_result_quality(r, 0, &q[0]), cm_result_quality(r, 1, &q[1]);
        lo = fmin(q[0].min_angle_deg, q[1].min_angle_deg);
    }
    cm_result_free(r);
    return lo;
}

/* The map-aware remesher on a polygon against a mild affine image of it
 * (singular values 1.10 and 0.95): the map between them can be that
 * affine map, which stretches an equilateral triangle of the metric
 * halfway between them by sqrt(1.10 / 0.95) = 1.08 each way, turning 60
 * degrees into 56; so the pair should come within a few degrees of the
 * polygon alone (paired with itself). */
static void test_map_affine_fixture(void)
{
    size_t n = 40;
    double *u = polygon(n), *s = polygon(n), *image = polygon(n);
    fill_us(u, s);
    const double *shapes[2] = {u, s};
    const char *names[2] = {"U glyph", "S glyph"};
    for (int i = 0; i < 2; i++) {
        for (size_t j = 0; j < n; j++)
            image[2 * j] = 1.1 * shapes[i][2 * j] + 0.05 * shapes[i][2 * j + 1] - 2,
            image[2 * j + 1] = 0.95 * shapes[i][2 * j + 1] + 1;
        double alone = pair_min_angle(shapes[i], shapes[i], n, CM_REMESHER_MAP);
        double pair = pair_min_angle(shapes[i], image, n, CM_REMESHER_MAP);
        double greedy = pair_min_angle(shapes[i], image, n, CM_REMESHER_GREEDY);
        CHECK_MSG(alone >= 0 && pair >= 0 && greedy >= 0, "%s: remeshing failed", names[i]);
        CHECK_MSG(pair >= alone - CM_TEST_AFFINE_MARGIN, "%s vs its affine image: %.2f, alone %.2f", names[i], pair,
                  alone);
        printf("map remesher, %s: alone %.2f, vs its affine image %.2f (greedy %.2f)\n", names[i], alone, pair,
               greedy);
    }
    free(u), free(s), free(image);
}

/* ---- options and the result ------------------------------------------------------ */

/* Twice the signed area of triangle t of geometry xy. */
static double twice_area(const double *xy, const int32_t *t)
{
    const double *a = xy + 2 * t[0], *b = xy + 2 * t[1], *c = xy + 2 * t[2];
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

/* The restart's start (restart.h) on a remeshed spiral against a disc:
 * every input vertex kept, each new one the midpoint of an interior edge
 * in both geometries, two triangles more per new vertex, every triangle
 * counter-clockwise by the exact predicate, each geometry's area the
 * same, and the tenth of the triangles with the largest dilatation split.
 * Then the restart itself (cm_options.restarts): there a pair ending
 * below 0.85 of its aim gains (12.1 -> 13.1 degrees when written), valid,
 * within its automatic budget (2 n + 100 more); with max_steiner at the
 * first result's count there is no room, and the result is that one. */
static void test_restarts(void)
{
    size_t n = 50;
    double *a = polygon(n), *b = polygon(n);
    CHECK(rp_spiral(a, (int)n, 1.5) == 0 && rp_disc(b, (int)n) == 0);
    const double *in[2] = {a, b};
    cm_result *r[3] = {NULL, NULL, NULL};
    cm_options o;
    cm_options_init(&o);
    o.restarts = 0;
    CHECK(cm_triangulate_polygons(in, (size_t[]){n, n}, 2, &o, &r[0]) == CM_OK);
    size_t nv = cm_result_num_vertices(r[0]), nt = cm_result_num_triangles(r[0]);
    double *xy[2] = {(double *)cm_result_vertices(r[0], 0), (double *)cm_result_vertices(r[0], 1)};
    cm_mesh mesh = {.k = 2, .nv = nv, .nt = nt, .xy = xy, .tri = (int32_t *)cm_result_triangles(r[0])}, out;
    CHECK(cm_restart_refine(&mesh, 0.1, &out) == CM_OK);
    size_t added = out.nv - nv;
    CHECK_MSG(added > 0 && out.nt == nt + 2 * added, "restart split: %zu points, %zu -> %zu triangles", added, nt,
              out.nt);
    for (size_t g = 0; g < 2; g++) {
        CHECK(memcmp(out.xy[g], xy[g], 2 * nv * sizeof(double)) == 0);
        double before = 0, after = 0;
        for (size_t t = 0; t < nt; t++) before += twice_area(xy[g], mesh.tri + 3 * t);
        for (size_t t = 0; t < out.nt; t++) {
            const int32_t *v = out.tri + 3 * t;
            after += twice_area(out.xy[g], v);
            CHECK(cm_orient2d(out.xy[g] + 2 * v[0], out.xy[g] + 2 * v[1], out.xy[g] + 2 * v[2]) > 0);
        }
        CHECK_MSG(fabs(after - before) <= 1e-12 * before, "geometry %zu: area %.17g -> %.17g", g, before, after);
    }
    for (size_t v = nv; v < out.nv; v++) { /* on an edge of the input shared by two triangles */
        int sides = 0;
        for (size_t t = 0; t < nt; t++)
            for (int i = 0; i < 3; i++) {
                int32_t p = mesh.tri[3 * t + i], q = mesh.tri[3 * t + (i + 1) % 3];
                int mid = 1;
                for (size_t g = 0; g < 2; g++)
                    mid &= out.xy[g][2 * v] == 0.5 * (xy[g][2 * p] + xy[g][2 * q]) &&
                           out.xy[g][2 * v + 1] == 0.5 * (xy[g][2 * p + 1] + xy[g][2 * q + 1]);
                sides += mid;
            }
        CHECK_MSG(sides == 2, "new vertex %zu: the midpoint of %d triangles' edges", v, sides);
    }
    free(out.xy[0]), free(out.xy[1]), free(out.xy), free(out.tri);

    cm_options_init(&o); /* the default: one restart */
    CHECK(cm_triangulate_polygons(in, (size_t[]){n, n}, 2, &o, &r[1]) == CM_OK && rc_valid(r[1], in, 2, n));
    o.max_steiner = (long)cm_result_stats(r[0])->steiner;
    CHECK(cm_triangulate_polygons(in, (size_t[]){n, n}, 2, &o, &r[2]) == CM_OK && rc_valid(r[2], in, 2, n));
    double least[3];
    for (int i = 0; i < 3; i++) {
        cm_quality q0, q1;
        cm_result_quality(r[i], 0, &q0), cm_result_quality(r[i], 1, &q1);
        least[i] = fmin(q0.min_angle_deg, q1.min_angle_deg);
    }
    size_t s0 = cm_result_stats(r[0])->steiner, s1 = cm_result_stats(r[1])->steiner;
    CHECK_MSG(least[1] > least[0] && s1 <= s0 + 2 * n + 100, "restart: %.2f -> %.2f degrees, %zu -> %zu Steiner",
              least[0], least[1], s0, s1);
    CHECK_MSG(least[2] == least[0] && cm_result_stats(r[2])->steiner == s0, "restart without room: %.2f, %zu",
              least[2], cm_result_stats(r[2])->steiner);
    printf("restart: spiral / disc n=%zu %.2f -> %.2f degrees, Steiner %zu -> %zu\n", n, least[0], least[1], s0, s1);
    for (int i = 0; i < 3; i++) cm_result_free(r[i]);
    free(a), free(b);
}

static void test_options(void)
{
    size_t n = 20;
    double *a = polygon(n), *b = polygon(n);
    rp_star(a, (int)n, 1), rp_star(b, (int)n, 2);
    const double *in[2] = {a, b};
    struct { const char *what; void (*set)(cm_options *); } bad[] = {
        {"k_split", NULL}, {"min_angle_deg", NULL}, {"min_angle_deg", NULL}, {"max_steiner", NULL},
        {"area_every", NULL}, {"max_iterations", NULL}, {"smoothing", NULL}, {"restarts", NULL}};
    for (int i = 0; i < 8; i++) {
        cm_options o;
        cm_options_init(&o);
        switch (i) {
        case 0: o.k_split = -1; break;
        case 1: o.min_angle_deg = 0; break;
        case 2: o.min_angle_deg = 60; break;
        case 3: o.max_steiner = -2; break;
        case 4: o.area_every = -3; break;
        case 5: o.max_iterations = -1; break;
        case 6: o.smoothing = (cm_smoothing)9; break;
        default: o.restarts = -1; break;
        }
        cm_result *r = NULL;
        cm_status s = cm_triangulate_polygons(in, (size_t[]){n, n}, 2, &o, &r);
        CHECK_MSG(s == CM_ERR_ARGUMENT && strstr(cm_result_message(r), bad[i].what),
                  "bad %s: status %d, message \"%s\"", bad[i].what, (int)s, cm_result_message(r));
        cm_result_free(r);
    }

    cm_options o;
    cm_options_init(&o);
    CHECK(o.remesh == 1 && o.min_angle_deg == 25 && o.max_steiner == -1 && o.k_split == 0 &&
          o.area_every == 0 && o.smoothing == CM_SMOOTH_COMBINED && o.max_iterations == 0 && o.restarts == 1);

    /* remesh off: the construction itself, quality before == after */
    o.remesh = 0;
    cm_result *r = NULL;
    CHECK(cm_triangulate_polygons(in, (size_t[]){n, n}, 2, &o, &r) == CM_OK);
    const cm_stats *st = cm_result_stats(r);
    cm_quality q, q0;
    CHECK(cm_result_quality(r, 0, &q) == CM_OK && cm_result_quality_before(r, 0, &q0) == CM_OK);
    CHECK(st->steiner == st->steiner_before_remesh && st->remesh_iterations == 0 &&
          q.min_angle_deg == q0.min_angle_deg);
    CHECK(cm_result_quality_before(r, 2, &q0) == CM_ERR_ARGUMENT);
    cm_result_free(r);

    /* every smoothing scheme, area equalisation, fixed k_split, budget 0 */
    for (int i = 0; i < 4; i++) {
        cm_options_init(&o);
        o.smoothing = (cm_smoothing)i, o.area_every = i, o.k_split = 1 + i;
        if (i == 3) o.max_steiner = 0;
        CHECK(cm_triangulate_polygons(in, (size_t[]){n, n}, 2, &o, &r) == CM_OK);
        CHECK(rc_valid(r, in, 2, n));
        CHECK(cm_result_quality(r, 0, &q) == CM_OK && cm_result_quality_before(r, 0, &q0) == CM_OK);
        CHECK_MSG(q.min_angle_deg >= q0.min_angle_deg, "smoothing %d: %.2f < %.2f", i,
                  q.min_angle_deg, q0.min_angle_deg);
        cm_result_free(r);
    }
    free(a), free(b);
}

static int stop_at_remesh(void *user, double fraction, const char *stage)
{
    (void)fraction;
    ++*(int *)user;
    return strcmp(stage, "remesh") == 0;
}

static void test_cancel_and_clockwise(void)
{
    size_t n = 30;
    double *a = polygon(n), *b = polygon(n);
    rp_star(a, (int)n, 21), rp_star(b, (int)n, 22);
    const double *in[2] = {a, b};
    cm_options o;
    cm_options_init(&o);
    int calls = 0;
    o.progress = stop_at_remesh, o.progress_user = &calls;
    cm_result *r = NULL;
    CHECK(cm_triangulate_polygons(in, (size_t[]){n, n}, 2, &o, &r) == CM_ERR_CANCELLED);
    CHECK(calls > 0 && cm_result_num_vertices(r) == 0);
    cm_result_free(r);

    /* clockwise input: remeshed in internal order, returned in input order */
    for (size_t i = 0; i < n / 2; i++)
        for (int c = 0; c < 2; c++) {
            double t = a[2 * i + c]; a[2 * i + c] = a[2 * (n - 1 - i) + c]; a[2 * (n - 1 - i) + c] = t;
            t = b[2 * i + c]; b[2 * i + c] = b[2 * (n - 1 - i) + c]; b[2 * (n - 1 - i) + c] = t;
        }
    CHECK(cm_triangulate_polygons(in, (size_t[]){n, n}, 2, NULL, &r) == CM_OK);
    CHECK(cm_result_stats(r)->reversed_input == 1 && rc_valid(r, in, 2, n));
    cm_result_free(r);
    free(a), free(b);
}

/* Test triangle i: random points at scale 1, 1e-200 or 1e200 (by i % 7),
 * every fifth a sliver (the third point near the first two's line). */
static void random_triangle(rp_rng *rng, int i, double p[3][2])
{
    double scale = i % 7 == 0 ? 1e-200 : i % 7 == 1 ? 1e200 : 1.0;
    for (int j = 0; j < 3; j++)
        for (int d = 0; d < 2; d++) p[j][d] = scale * (rp_uniform(rng) - 0.5);
    if (i % 5 == 0)
        for (int d = 0; d < 2; d++) p[2][d] = 0.3 * p[0][d] + 0.7 * p[1][d] + scale * 1e-9 * rp_uniform(rng);
}

/* Puts the third point of p on the perpendicular bisector of the first
 * two (nearly isosceles triangles), off it by up to 1e-7 of their distance
 * along them when `jitter`. */
static void near_bisector(rp_rng *rng, double p[3][2], int jitter)
{
    double mx = 0.5 * (p[0][0] + p[1][0]), my = 0.5 * (p[0][1] + p[1][1]);
    double dx = p[1][0] - p[0][0], dy = p[1][1] - p[0][1], t = rp_uniform(rng) * 2.0 - 1.0;
    double off = jitter ? 1e-7 * (rp_uniform(rng) - 0.5) : 0.0;
    p[2][0] = mx - t * dy + off * dx, p[2][1] = my + t * dx + off * dy;
}

/* cm_triangle_max_angle_below decides as cm_triangle_max_angle's value
 * compared with the bound, and cm_triangle_min_angle_rank counts the
 * bounds cm_triangle_min_angle's value is above: bounds at the angles
 * themselves and a few ulps either side, random ones, nearly isosceles
 * triangles, slivers and far scales. */
static void test_angle_bounds(int count)
{
    rp_rng rng = {20261129};
    int mismatches = 0;
    for (int i = 0; i < count; i++) {
        double p[3][2];
        random_triangle(&rng, i, p);
        if (i % 6 == 4) near_bisector(&rng, p, 0);
        double hi = cm_triangle_max_angle(p[0], p[1], p[2]), lo = cm_triangle_min_angle(p[0], p[1], p[2]);
        double near[5] = {hi, nextafter(hi, 0.0), nextafter(hi, 4.0), nextafter(nextafter(hi, 4.0), 4.0),
                          CM_PI / 3 + rp_uniform(&rng) * 2.0};
        for (int j = 0; j < 5; j++)
            mismatches += cm_triangle_max_angle_below(p[0], p[1], p[2], near[j], cos(near[j])) != (hi < near[j]);
        double bound[4] = {nextafter(lo, 0.0), lo, nextafter(lo, 2.0), rp_uniform(&rng) * 1.5}, tans[4];
        if (bound[3] < bound[2]) { /* ascending */
            double x = bound[3];
            int at = 3;
            for (; at > 0 && bound[at - 1] > x; at--) bound[at] = bound[at - 1];
            bound[at] = x;
        }
        int want = 0;
        for (int j = 0; j < 4; j++) tans[j] = tan(bound[j]), want += lo > bound[j];
        mismatches += cm_triangle_min_angle_rank(p[0], p[1], p[2], bound, tans, 4) != want;
    }
    CHECK_MSG(mismatches == 0, "angle bounds: %d mismatches in %d triangles", mismatches, count);
}

/* cm_mesh_quality against the plain loop over every triangle's angles,
 * to the bit: random meshes at several scales, with slivers. */
static void test_mesh_quality(void)
{
    rp_rng rng = {20261130};
    enum { NT = 400 };
    double xy[3 * 2 * NT];
    int32_t tri[3 * NT];
    double *geoms[1] = {xy};
    int differ = 0;
    for (int round = 0; round < 200; round++) {
        size_t nt = 1 + (size_t)(rp_next(&rng) % NT);
        for (size_t t = 0; t < nt; t++) {
            double p[3][2];
            random_triangle(&rng, round * 7 + (int)t, p);
            if (round % 2 && t % 3 == 0) /* skinny ones, counted at each bound */
                for (int d = 0; d < 2; d++) p[2][d] = 0.5 * (p[0][d] + p[1][d]) + rp_uniform(&rng) * 0.3 * (p[1][1 - d] - p[0][1 - d]);
            for (int j = 0; j < 3; j++) xy[6 * t + 2 * j] = p[j][0], xy[6 * t + 2 * j + 1] = p[j][1];
            for (int j = 0; j < 3; j++) tri[3 * t + j] = (int32_t)(3 * t + (size_t)j);
        }
        cm_mesh mesh = {0};
        mesh.k = 1, mesh.nv = 3 * nt, mesh.nt = nt, mesh.xy = geoms, mesh.tri = tri;
        cm_quality got, want = {0};
        cm_mesh_quality(&mesh, 0, &got);
        size_t below[3] = {0, 0, 0};
        want.min_angle_deg = 180.0, want.max_angle_deg = 0.0;
        for (size_t t = 0; t < nt; t++) {
            const double *a = xy + 6 * t, *b = a + 2, *c = a + 4;
            double lo = cm_triangle_min_angle(a, b, c) * (180.0 / CM_PI);
            want.min_angle_deg = fmin(want.min_angle_deg, lo);
            want.max_angle_deg = fmax(want.max_angle_deg, cm_triangle_max_angle(a, b, c) * (180.0 / CM_PI));
            below[0] += lo < 10.0, below[1] += lo < 15.0, below[2] += lo < 20.0;
        }
        differ += got.min_angle_deg != want.min_angle_deg || got.max_angle_deg != want.max_angle_deg ||
                  got.pct_below_10deg != (double)below[0] * (100.0 / (double)nt) ||
                  got.pct_below_15deg != (double)below[1] * (100.0 / (double)nt) ||
                  got.pct_below_20deg != (double)below[2] * (100.0 / (double)nt);
    }
    CHECK_MSG(differ == 0, "mesh quality: %d of 200 meshes differ from the plain loop", differ);
}

/* cm_triangle_min_angle_above decides as cm_triangle_min_angle's value
 * compared with the bound: bounds at the angle itself and a few ulps
 * either side, random ones, slivers, and coordinates near 1e-200 and
 * 1e200 (the long double path). */
static void test_min_angle_above(int count)
{
    rp_rng rng = {20261124};
    int mismatches = 0, near = 0;
    for (int i = 0; i < count; i++) {
        double p[3][2];
        random_triangle(&rng, i, p);
        double a = cm_triangle_min_angle(p[0], p[1], p[2]), bound;
        switch (i % 4) {
        case 0: bound = a; break;
        case 1: bound = nextafter(nextafter(a, 0.0), 0.0); break;
        case 2: bound = nextafter(a, 1.0); break;
        default: bound = rp_uniform(&rng) * 1.2; break;
        }
        near += i % 4 != 3;
        mismatches += cm_triangle_min_angle_above(p[0], p[1], p[2], bound, tan(bound)) != (a > bound);
    }
    CHECK(near > 0 && mismatches == 0);
}

/* cm_angle_at_below is cm_angle_at, to the bit, where that is below the
 * bound, and at least the bound elsewhere: bounds at the angle and an ulp
 * either side, random ones below a right angle and one above, on random
 * triangles, slivers, nearly isosceles ones and far scales. */
static void test_angle_at_below(int count)
{
    rp_rng rng = {20261130};
    int mismatches = 0, skipped = 0;
    for (int i = 0; i < count; i++) {
        double p[3][2];
        random_triangle(&rng, i, p);
        if (i % 6 == 4) near_bisector(&rng, p, i % 12 == 4);
        for (int c = 0; c < 3; c++) {
            const double *a = p[c], *b = p[(c + 1) % 3], *d = p[(c + 2) % 3];
            double angle = cm_angle_at(a, b, d);
            double bounds[5] = {angle, nextafter(angle, 0.0), nextafter(angle, 4.0), rp_uniform(&rng) * CM_PI / 2,
                                CM_PI / 2 + rp_uniform(&rng)};
            for (int j = 0; j < 5; j++) {
                double got = cm_angle_at_below(a, b, d, bounds[j], tan(bounds[j]));
                if (angle < bounds[j]) mismatches += memcmp(&got, &angle, sizeof got) != 0;
                else mismatches += !(got >= bounds[j]), skipped += got != angle;
            }
        }
    }
    CHECK_MSG(mismatches == 0 && skipped > 0, "angle below a bound: %d of %d wrong (%d skipped)", mismatches,
              15 * count, skipped);
}

/* cm_triangle_max_angle is the largest of the three cm_angle_at values,
 * to the bit: also for nearly isosceles triangles (two longest edges
 * within the factor it trusts, and just outside it), slivers and far
 * scales. */
static void test_max_angle(int count)
{
    rp_rng rng = {20261128};
    int mismatches = 0;
    for (int i = 0; i < count; i++) {
        double p[3][2];
        random_triangle(&rng, i, p);
        if (i % 5 == 1 || i % 5 == 2) near_bisector(&rng, p, i % 5 == 1);
        double want = fmax(cm_angle_at(p[0], p[1], p[2]), fmax(cm_angle_at(p[1], p[2], p[0]), cm_angle_at(p[2], p[0], p[1])));
        double got = cm_triangle_max_angle(p[0], p[1], p[2]);
        mismatches += memcmp(&want, &got, sizeof got) != 0;
    }
    CHECK_MSG(mismatches == 0, "max angle: %d of %d differ from the three angles' largest", mismatches, count);
}

/* cm_triangle_min_angle_sin2 with den picked by comparisons, as the
 * smallest angle is opposite the shortest side. */
static double min_angle_sin2_reference(const double a[2], const double b[2], const double c[2])
{
    double abx = b[0] - a[0], aby = b[1] - a[1], bcx = c[0] - b[0], bcy = c[1] - b[1];
    double cax = a[0] - c[0], cay = a[1] - c[1];
    double lab = abx * abx + aby * aby, lbc = bcx * bcx + bcy * bcy, lca = cax * cax + cay * cay;
    double cross = abx * cay - aby * cax, den;
    if (lab <= lbc && lab <= lca) den = lbc * lca;
    else if (lbc <= lca) den = lab * lca;
    else den = lab * lbc;
    if (!(den > CM_ANGLE_SAFE_LO && den < CM_ANGLE_SAFE_HI) && den != 0)
        return cm_triangle_min_angle_sin2_wide(a, b, c);
    return den > 0 ? cross * cross / den : 0.0;
}

/* Its smallest value over v's link polygon p in geometry g, (q, p_i,
 * p_i+1): the reference for the position search's scan. */
/* random_kmesh with a vertex inserted at the centroid of every third
 * triangle: interior vertices of degree 3 and more. */
static int random_kmesh_inner(int seed, double **a, double **b, cm_mesh *m, cm_kmesh *km)
{
    if (random_kmesh(seed, a, b, m, km)) return -1;
    for (int32_t t = 0, nt = km->nt; t < nt; t += 3) {
        if (!cm_kmesh_tri_live(km, t)) continue;
        double pts[4];
        for (size_t g = 0; g < 2; g++)
            for (int d = 0; d < 2; d++)
                pts[2 * g + d] = (cm_kmesh_pos(km, g, km->tri[3 * t])[d] + cm_kmesh_pos(km, g, km->tri[3 * t + 1])[d] +
                                  cm_kmesh_pos(km, g, km->tri[3 * t + 2])[d]) / 3;
        CHECK(cm_kmesh_insert(km, t, pts) >= 0);
    }
    return 0;
}

/* What a scaled-star test does at one interior vertex v of degree 3 and
 * more, in geometry g (its star's corners in star). */
typedef void (*star_visit)(void *ctx, const cm_kmesh *km, size_t g, int32_t v, const cm_ibuf *star);

/* visit() at every interior vertex of `pairs` random meshes
 * (random_kmesh_inner), in both geometries, the meshes scaled by 2^shift[i]
 * for each of the nshift shifts in turn. */
static void for_each_scaled_star(int pairs, const int *shift, size_t nshift, star_visit visit, void *ctx)
{
    for (int seed = 0; seed < pairs; seed++) {
        double *a, *b;
        cm_mesh m;
        cm_kmesh km;
        if (random_kmesh_inner(seed, &a, &b, &m, &km)) continue;
        size_t coords = 2 * (size_t)km.nv;
        double *orig[2];
        for (size_t g = 0; g < 2; g++) {
            orig[g] = malloc(coords * sizeof *orig[g]);
            memcpy(orig[g], km.xy[g], coords * sizeof *orig[g]);
        }
        cm_ibuf star = {0};
        for (size_t s = 0; s < nshift; s++) {
            for (size_t g = 0; g < 2; g++)
                for (size_t i = 0; i < coords; i++) km.xy[g][i] = ldexp(orig[g][i], shift[s]);
            for (int32_t v = km.n; v < km.nv; v++) {
                if (km.vc[v] < 0 || cm_kmesh_is_boundary(&km, v) || cm_kmesh_star(&km, v, &star) < 3) continue;
                for (size_t g = 0; g < 2; g++) visit(ctx, &km, g, v, &star);
            }
        }
        for (size_t g = 0; g < 2; g++) free(orig[g]);
        cm_ibuf_free(&star), cm_kmesh_free(&km), cm_mesh_clear(&m);
        free(a), free(b);
    }
}

/* The angle-based smoothing target by its definition (Zhou and Shimada;
 * eq. 2 with power 2): at each ring vertex p_i, the angles from p_{i+1} to
 * v and from v to p_{i-1} measured with atan2, p_i -> v rotated by half
 * their difference onto the bisector, weighted by 1 / alpha_i^power. */
static void angle_target_reference(const cm_kmesh *km, size_t g, int32_t v, const cm_ibuf *star, double power,
                                   double out[2])
{
    const double *c = cm_kmesh_pos(km, g, v);
    double x = 0, y = 0, wsum = 0;
    for (size_t i = 0, m = star->n; i < m; i++) {
        const double *p = cm_kmesh_pos(km, g, km->tri[cm_next(star->a[i])]);
        const double *pn = cm_kmesh_pos(km, g, km->tri[cm_next(star->a[(i + 1) % m])]);
        const double *pp = cm_kmesh_pos(km, g, km->tri[cm_next(star->a[(i + m - 1) % m])]);
        double d[2] = {c[0] - p[0], c[1] - p[1]}, n[2] = {pn[0] - p[0], pn[1] - p[1]}, q[2] = {pp[0] - p[0], pp[1] - p[1]};
        double a1 = atan2(n[0] * d[1] - n[1] * d[0], n[0] * d[0] + n[1] * d[1]);
        double a2 = atan2(d[0] * q[1] - d[1] * q[0], d[0] * q[0] + d[1] * q[1]);
        double beta = 0.5 * (a2 - a1), w = 1.0 / fmax(pow(a1 + a2, power), 1e-12);
        x += w * (p[0] + cos(beta) * d[0] - sin(beta) * d[1]);
        y += w * (p[1] + sin(beta) * d[0] + cos(beta) * d[1]);
        wsum += w;
    }
    out[0] = x / wsum, out[1] = y / wsum;
}

typedef struct target_tally {
    long checked, wrong;
    double worst;
} target_tally;

static void check_angle_targets(void *ctx, const cm_kmesh *km, size_t g, int32_t v, const cm_ibuf *star)
{
    static const cm_smoothing methods[] = {CM_SMOOTH_ANGLE, CM_SMOOTH_WEIGHTED};
    target_tally *t = ctx;
    const double *c = cm_kmesh_pos(km, g, v), *p0 = cm_kmesh_pos(km, g, km->tri[cm_next(star->a[0])]);
    double size = hypot(p0[0] - c[0], p0[1] - c[1]);
    for (size_t k = 0; k < 2; k++) {
        double got[2], want[2];
        angle_target_reference(km, g, v, star, methods[k] == CM_SMOOTH_ANGLE ? 0 : 2, want);
        t->checked++;
        if (cm_smooth_target(km, g, v, methods[k], star, got)) {
            t->wrong++;
            continue;
        }
        double off = hypot(got[0] - want[0], got[1] - want[1]) / size;
        t->worst = fmax(t->worst, off);
        t->wrong += !(off < 1e-10);
    }
}

/* The angle-based targets (eq. 1 and eq. 2) on random valid stars, the
 * meshes scaled by powers of two from 2^-300 to 2^300, agree with their
 * definition to 1e-10 of the ring's size (a wrong bisector is off by
 * about the size itself). */
static void test_angle_target(int pairs)
{
    static const int shift[] = {-300, -40, 0, 40, 300};
    target_tally t = {0};
    for_each_scaled_star(pairs, shift, sizeof shift / sizeof *shift, check_angle_targets, &t);
    CHECK_MSG(t.checked > 1000 && t.wrong == 0, "angle targets: %ld of %ld differ from the definition (worst %.3g)",
              t.wrong, t.checked, t.worst);
    printf("angle targets: %ld, furthest %.3g of the ring's size from the definition\n", t.checked, t.worst);
}

static double star_sin2_reference(const cm_kmesh *km, size_t g, const cm_ibuf *star, const double q[2])
{
    double lo = 1.0;
    for (size_t i = 0; i < star->n; i++) {
        const double *b = cm_kmesh_pos(km, g, km->tri[cm_next(star->a[i])]);
        const double *c = cm_kmesh_pos(km, g, km->tri[cm_next(star->a[(i + 1) % star->n])]);
        lo = fmin(lo, min_angle_sin2_reference(q, b, c));
    }
    return lo;
}

typedef struct scan_tally {
    rp_rng rng;
    long checked, above, wrong;
} scan_tally;

static void check_star_scan(void *ctx, const cm_kmesh *km, size_t g, int32_t v, const cm_ibuf *star)
{
    scan_tally *t = ctx;
    const double *c = cm_kmesh_pos(km, g, v), *p0 = cm_kmesh_pos(km, g, km->tri[cm_next(star->a[0])]);
    const double *p1 = cm_kmesh_pos(km, g, km->tri[cm_next(star->a[1])]);
    double reach = hypot(p0[0] - c[0], p0[1] - c[1]);
    for (int trial = 0; trial < 16; trial++) {
        double q[2] = {c[0], c[1]}, mid[2] = {0.5 * (p0[0] + p1[0]), 0.5 * (p0[1] + p1[1])};
        if (trial == 1) q[0] = p0[0], q[1] = p0[1];
        else if (trial == 2) q[0] = mid[0], q[1] = mid[1];
        else if (trial == 3) q[0] += 1e3 * reach, q[1] -= 1e3 * reach;
        else if (trial < 8) { /* a sliver whose sin^2 underflows: 2^-1000 .. 2^-1090 */
            double off = ldexp(1.0, -500 - 15 * (trial - 4));
            q[0] = mid[0] - off * (p1[1] - p0[1]), q[1] = mid[1] + off * (p1[0] - p0[0]);
        } else q[0] += reach * (rp_uniform(&t->rng) - 0.5), q[1] += reach * (rp_uniform(&t->rng) - 0.5);
        double want = star_sin2_reference(km, g, star, q), floor;
        switch ((int)(rp_uniform(&t->rng) * 7)) {
        case 0: floor = -1.0; break;
        case 1: floor = 0.0; break;
        case 2: floor = 0x1p-1000; break;
        case 3: floor = want; break;
        case 4: floor = nextafter(want, 0.0); break;
        case 5: floor = nextafter(want, 1.0); break;
        default: floor = 0.75 * rp_uniform(&t->rng); break;
        }
        double got = cm_smooth_star_sin2(km, g, v, star, q, floor, (long)(rp_uniform(&t->rng) * 64));
        t->checked++;
        if (want > floor) t->above++, t->wrong += memcmp(&want, &got, sizeof got) != 0;
        else t->wrong += got > floor;
    }
}

/* The position search's star scan and its shortcuts (no range tests
 * where the ring's shortest link edge bounds den from below, den as the
 * largest of three products, cm_sin2_den, a start anywhere) against the
 * reference:
 * the same bits above the floor, at or below it otherwise. Meshes scaled
 * by 2^-560 .. 2^480, around where the range tests fire (squared link
 * lengths near 2^-498, products near 2^+-1000); trial points near v, on
 * a link vertex, mid-edge and far; floors -1, 0, tiny, random, and the
 * value itself and its neighbours. */
static void test_star_scan(int pairs)
{
    static const int shift[] = {0, -200, -240, -247, -248, -249, -250, -251, -252, -256, -300, -500, -560,
                                200, 240, 248, 249, 250, 251, 252, 256, 300, 480};
    scan_tally t = {{104729}, 0, 0, 0};
    for_each_scaled_star(pairs, shift, sizeof shift / sizeof *shift, check_star_scan, &t);
    CHECK_MSG(t.wrong == 0, "star scan: %ld of %ld trials differ from the reference", t.wrong, t.checked);
    CHECK_MSG(t.above > t.checked / 4, "star scan: only %ld of %ld trials above their floor", t.above, t.checked);
    printf("star scan: %ld trials, %ld above their floor\n", t.checked, t.above);
}

int main(void)
{
    test_restarts();
    test_angle_target(40);
    test_star_scan(40);
    test_min_angle_above(40000);
    test_max_angle(200000);
    test_angle_at_below(100000);
    test_angle_bounds(100000);
    test_mesh_quality();
    test_property_operations(60, 400);
    test_map_descent(30);
    test_smoothing_variants();
    test_joint_polish();
    test_joint_polish_lowest_first();
    test_polish_moves();
    test_polish_moves_slide();
    test_polish_moves_memo();
    test_remesh_resume();
    test_area_equalisation();
    test_refine_keeps_boundary();
    test_boundary_caps();
    test_algorithm1_fixtures();
    test_map_affine_fixture();
    test_options();
    test_cancel_and_clockwise();
    return check_summary("test_remesh");
}
