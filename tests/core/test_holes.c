/* Polygons with holes through cm_triangulate_loops: every bad-input class
 * with its message and location, and fixtures that state what they expect
 * (valid, hole count, Euler characteristic 1 - h, a Steiner bound), each
 * result checked exactly by result_check.h (areas in rationals). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/mesh.h"
#include "check.h"
#include "compatmesh/compatmesh.h"
#include "hole_fixtures.h"
#include "random_polygons.h"
#include "result_check.h"
#include "sweep_boundary_check.h"

static cm_loops loops_of(const shape *s)
{
    return (cm_loops){s->xy, s->sizes, s->loops};
}

static double loop_area(const double *xy, size_t m)
{
    double a = 0;
    for (size_t i = 0; i < m; i++) {
        const double *p = xy + 2 * i, *q = xy + 2 * ((i + 1) % m);
        a += p[0] * q[1] - q[0] * p[1];
    }
    return 0.5 * fabs(a);
}

/* The morph and sweep of a result with holes: sections at t = 0.1 .. 0.9
 * valid (the morph counts inverted triangles exactly) and covering the
 * outer loop's area minus the holes' (the holes stay empty); the sweep
 * into tetrahedra succeeds (every prism and tetrahedron checked exactly). */
static void expect_morph(const char *name, const cm_result *r, const shape *a)
{
    cm_morph *m = NULL;
    cm_status s = cm_morph_create(r, NULL, &m);
    CHECK_MSG(s == CM_OK, "%s: morph: %s", name, cm_morph_message(m));
    size_t nv = cm_result_num_vertices(r), nt = cm_result_num_triangles(r);
    const int32_t *tri = cm_result_triangles(r);
    double *xy = malloc(2 * nv * sizeof *xy);
    for (int step = 1; s == CM_OK && xy && step < 10; step++) {
        size_t inverted = 1;
        s = cm_morph_section(m, step / 10.0, xy, &inverted, NULL);
        CHECK_MSG(s == CM_OK && inverted == 0, "%s: section at t = %.1f: %s", name, step / 10.0, cm_morph_message(m));
        double covered = 0, expected = loop_area(xy, a->sizes[0]);
        for (size_t l = 1, at = a->sizes[0]; l < a->loops; at += a->sizes[l++]) expected -= loop_area(xy + 2 * at, a->sizes[l]);
        for (size_t t = 0; t < nt; t++) {
            const double *p = xy + 2 * tri[3 * t], *q = xy + 2 * tri[3 * t + 1], *u = xy + 2 * tri[3 * t + 2];
            covered += 0.5 * ((q[0] - p[0]) * (u[1] - p[1]) - (q[1] - p[1]) * (u[0] - p[0]));
        }
        CHECK_MSG(fabs(covered - expected) <= 1e-9 * expected, "%s: t = %.1f covers %.17g, expected %.17g", name,
                  step / 10.0, covered, expected);
    }
    free(xy);
    if (s == CM_OK) {
        cm_sweep_options so;
        cm_sweep_options_init(&so);
        so.tets = 1;
        cm_sweep *w = NULL;
        CHECK_MSG(cm_sweep_create(m, &so, &w) == CM_OK, "%s: sweep: %s", name, cm_sweep_message(w));
        check_sweep_boundary(name, w, r, 0);
        check_sweep_boundary(name, w, r, 1);
        cm_sweep_free(w);
    }
    cm_morph_free(m);
}

/* The result's geometries rebuilt by cm_result_from_meshes_loops (what a
 * host program that saved them does): accepted, the same holes, morphed
 * like the original; cm_check_geometry_loops accepts each geometry and
 * refuses one with a hole vertex moved onto the outer loop. */
static void expect_rebuilt(const char *name, const cm_result *r, const shape *a)
{
    size_t nv = cm_result_num_vertices(r), nt = cm_result_num_triangles(r);
    const double *xy[2] = {cm_result_vertices(r, 0), cm_result_vertices(r, 1)};
    cm_result *again = NULL;
    cm_status s = cm_result_from_meshes_loops(xy, 2, a->sizes, a->loops, nv, cm_result_triangles(r), nt, &again);
    CHECK_MSG(s == CM_OK, "%s: rebuilt: %s", name, cm_result_message(again));
    if (s == CM_OK) {
        CHECK_MSG(cm_result_stats(again)->holes == a->loops - 1, "%s: rebuilt with %zu holes", name,
                  cm_result_stats(again)->holes);
        CHECK_MSG(cm_result_num_halfedges(again) == cm_result_num_halfedges(r), "%s: rebuilt half-edges", name);
        expect_morph(name, again, a);
    }
    cm_result_free(again);
    /* The loops given as one boundary: not the mesh's boundary edges. */
    size_t n = a->n;
    again = NULL;
    s = cm_result_from_meshes_loops(xy, 2, &n, 1, nv, cm_result_triangles(r), nt, &again);
    CHECK_MSG(s != CM_OK && cm_result_num_vertices(again) == 0, "%s: the loops as one boundary: %s", name,
              cm_status_string(s));
    cm_result_free(again);
    for (size_t g = 0; g < 2; g++)
        CHECK_MSG(cm_check_geometry_loops(xy[g], a->sizes, a->loops, nv, cm_result_triangles(r), nt, NULL, NULL) ==
                      CM_OK, "%s: geometry %zu refused", name, g);
    /* The first hole's first vertex moved onto the outer loop's first. */
    double *moved = malloc(2 * nv * sizeof *moved);
    if (moved) {
        memcpy(moved, xy[0], 2 * nv * sizeof *moved);
        moved[2 * a->sizes[0]] = moved[0], moved[2 * a->sizes[0] + 1] = moved[1];
        CHECK_MSG(cm_check_geometry_loops(moved, a->sizes, a->loops, nv, cm_result_triangles(r), nt, NULL, NULL) !=
                      CM_OK, "%s: a hole touching the outer loop passed", name);
    }
    free(moved);
}

/* The remesher's automatic Steiner budget with the default restart
 * (cm_options.max_steiner): 2 n + 100, as much again for the restart. */
#define REMESH_BUDGET(n) (2 * (2 * (n) + 100))

/* How a fixture is to be built: by the bridges' pieces (two paths per
 * hole), or by the construction that always succeeds (one per hole), taken
 * over when the pieces fail or asked for with the overlay method. */
enum { PIECES, FALLBACK, OVERLAY };

/* Runs a fixture and checks everything it states. */
static void expect_built_morphed(const char *name, const shape *a, const shape *b, int remesh, size_t max_steiner,
                                 int how, int morph)
{
    cm_loops in[2] = {loops_of(a), loops_of(b)};
    cm_options o;
    cm_options_init(&o);
    o.remesh = remesh;
    if (how == OVERLAY) o.method = CM_METHOD_OVERLAY;
    cm_result *r = NULL;
    cm_status s = cm_triangulate_loops(in, 2, &o, &r);
    CHECK_MSG(s == CM_OK, "%s: %s (%s)", name, cm_status_string(s), cm_result_message(r));
    if (s == CM_OK) {
        char why[256] = "";
        const cm_stats *st = cm_result_stats(r);
        CHECK_MSG(rc_check_loops(r, in, 2, why, sizeof why), "%s: %s", name, why);
        CHECK_MSG(rc_check_halfedges_holes(r, a->n, a->loops - 1, why, sizeof why), "%s: %s", name, why);
        CHECK_MSG(st->holes == a->loops - 1, "%s: %zu holes", name, st->holes);
        CHECK_MSG(st->bridges == (how == PIECES ? 2 : 1) * (a->loops - 1) && st->fallback_count == (how != PIECES),
                  "%s: %zu bridges, fallback %zu", name, st->bridges, st->fallback_count);
        CHECK_MSG(st->n == a->n && st->vertices == cm_result_num_vertices(r), "%s: counts", name);
        CHECK_MSG(st->steiner <= max_steiner, "%s: %zu Steiner vertices, at most %zu expected", name,
                  st->steiner, max_steiner);
        /* Euler: V - E + F = 1 - h with E = (3F + n) / 2. */
        size_t v = cm_result_num_vertices(r), f = cm_result_num_triangles(r);
        CHECK_MSG(2 * (long)v - (3 * (long)f + (long)a->n) + 2 * (long)f == 2 * (2 - (long)a->loops),
                  "%s: Euler characteristic", name);
        cm_quality q0, q1;
        cm_result_quality(r, 0, &q0), cm_result_quality(r, 1, &q1);
        printf("%-28s holes %zu  Steiner %zu (construction %zu)  smallest angles %.1f %.1f\n", name,
               st->holes, st->steiner, st->steiner_before_remesh, q0.min_angle_deg, q1.min_angle_deg);
        if (morph) {
            expect_morph(name, r, a);
            expect_rebuilt(name, r, a);
        }
    }
    cm_result_free(r);
}

static void expect_built(const char *name, const shape *a, const shape *b, int remesh, size_t max_steiner,
                         int how)
{
    expect_built_morphed(name, a, b, remesh, max_steiner, how, 1);
}

static void expect_valid(const char *name, const shape *a, const shape *b, int remesh, size_t max_steiner)
{
    expect_built(name, a, b, remesh, max_steiner, PIECES);
}

/* A square with a square hole against a disc with an off-centre round
 * hole: valid, 1 hole, Euler characteristic 0; the construction needs few
 * Steiner vertices (at most 40), remeshing at most 2 n + 100. */
static void test_square_and_disc(void)
{
    shape a = {0}, b = {0};
    hf_square_disc(&a, &b);
    expect_valid("square/disc", &a, &b, 0, 40);
    expect_valid("square/disc remeshed", &a, &b, 1, 2 * a.n + 100);
    /* Holes given counter-clockwise, outer clockwise: normalised. */
    shape c = {0}, d = {0};
    hf_square_disc_reversed(&c, &d);
    expect_valid("square/disc reversed loops", &c, &d, 0, 40);
}

/* A plate with 3 bolt holes against a rotated, sheared copy with the holes
 * moved: valid, 3 holes, Euler characteristic -2. */
static void test_plate(void)
{
    shape a = {0}, b = {0};
    hf_plate(&a, &b);
    expect_valid("plate", &a, &b, 0, 60);
    expect_valid("plate remeshed", &a, &b, 1, 2 * a.n + 100);
}

/* A thin annulus whose hole is turned half a turn in the second polygon
 * (hole vertex i sits opposite where it was): no straight chord from the
 * hole to the outer loop is inside the material in both, so the bridges
 * need Steiner bends. Valid, 1 hole, Euler characteristic 0; the
 * construction has Steiner vertices (the bends), at most 2 x 32 of them
 * plus what the pieces need (80 in all). */
static void test_turned_hole(void)
{
    shape a = {0}, b = {0};
    hf_turned_hole(&a, &b);
    cm_loops in[2] = {loops_of(&a), loops_of(&b)};
    cm_options o;
    cm_options_init(&o);
    o.remesh = 0;
    cm_result *r = NULL;
    CHECK(cm_triangulate_loops(in, 2, &o, &r) == CM_OK);
    CHECK_MSG(cm_result_stats(r)->steiner > 0, "the turned hole's bridges bend");
    cm_result_free(r);
    expect_valid("turned hole", &a, &b, 0, 80);
    expect_valid("turned hole remeshed", &a, &b, 1, REMESH_BUDGET(a.n));
    /* two holes, both turned */
    shape c = {0}, d = {0};
    hf_two_turned_holes(&c, &d);
    expect_valid("two turned holes", &c, &d, 0, 200);
    expect_valid("two turned holes remeshed", &c, &d, 1, REMESH_BUDGET(c.n));
}

/* Inputs where the bridges' pieces cannot be built, so the construction
 * that always succeeds (one bridge per hole routed in each polygon's own
 * triangulation, the overlay of the cut-open discs) takes over. Expected:
 * valid, one bridge per hole, Euler characteristic 1 - h, morphed and swept,
 * the Steiner counts of the construction within the stated bounds (the
 * overlay's, quadratic in the cut's size, measured with a margin). */
static void test_fallback(void)
{
    /* Five triangle holes (hole_fixtures.h): 20 path ends among 19 vertices. */
    shape a = {0}, b = {0};
    hf_five_triangles(&a, &b);
    expect_built("five triangle holes", &a, &b, 0, 120, FALLBACK);
    expect_built("five triangle holes remeshed", &a, &b, 1, REMESH_BUDGET(a.n), FALLBACK);
    /* A small hole on swapped sides of a central one: no path from it is
     * inside the material in both. */
    shape c = {0}, d = {0};
    hf_swapped_sides(&c, &d);
    expect_built("holes on swapped sides", &c, &d, 0, 180, FALLBACK);
    expect_built("holes on swapped sides remeshed", &c, &d, 1, REMESH_BUDGET(c.n), FALLBACK);
    /* Seven round holes, their places permuted, through the overlay method. */
    shape e = {0}, f = {0};
    hf_seven_permuted(&e, &f);
    /* the raw overlay of two unrelated cuts is thousands of slivers: not
     * morphed here (slow), its remeshed result is */
    expect_built_morphed("seven holes permuted", &e, &f, 0, 3000, OVERLAY, 0);
    expect_built("seven holes permuted remeshed", &e, &f, 1, 450 + 2 * e.n + 100, OVERLAY); /* measured; a restart's budget */
    /* The overlay method takes it for any input: the fixtures above. */
    shape g = {0}, h = {0};
    hf_square_disc(&g, &h);
    expect_built("square/disc, overlay", &g, &h, 0, 200, OVERLAY);
    expect_built("square/disc, overlay remeshed", &g, &h, 1, REMESH_BUDGET(g.n), OVERLAY);
}

/* Bad input: status, a message naming polygon, loop and vertex, the
 * location (vertex: index in the polygon's whole array). */
static void expect_bad(const char *name, const shape *a, const shape *b, cm_status want,
                       const char *fragment, long polygon, long vertex)
{
    cm_loops in[2] = {loops_of(a), loops_of(b)};
    cm_result *r = NULL;
    cm_status s = cm_triangulate_loops(in, 2, NULL, &r);
    CHECK_MSG(s == want, "%s: got %s (%s), want %s", name, cm_status_string(s), cm_result_message(r),
              cm_status_string(want));
    CHECK_MSG(strstr(cm_result_message(r), fragment), "%s: message '%s' lacks '%s'", name,
              cm_result_message(r), fragment);
    long p = -2, v = -2;
    cm_result_error_location(r, &p, &v, NULL);
    CHECK_MSG(p == polygon && v == vertex, "%s: location (%ld, %ld), want (%ld, %ld)", name, p, v,
              polygon, vertex);
    CHECK_MSG(cm_result_num_triangles(r) == 0 && cm_result_vertices(r, 0) == NULL,
              "%s: no geometry", name);
    cm_result_free(r);
}

static void test_bad_input(void)
{
    shape a = {0}, b = {0};
    add_square(&a, 0, 0, 1, 8, 1);
    add_square(&a, 0, 0, 0.4, 4, -1);
    b = a;
    shape c = a;
    c.loops = 1, c.n = 8;
    expect_bad("hole count", &a, &c, CM_ERR_COUNT_MISMATCH, "polygon 1 has 0 holes but polygon 0 has 1", 1, -1);
    shape d = {0};
    add_square(&d, 0, 0, 1, 8, 1);
    add_circle(&d, 0, 0, 0.4, 5, -1);
    expect_bad("loop size", &a, &d, CM_ERR_COUNT_MISMATCH,
               "polygon 1: hole 1 (loop 1) has 5 vertices but in polygon 0 it has 4", 1, -1);
    shape e = a;
    e.sizes[1] = 2, e.n = 10;
    expect_bad("tiny hole", &e, &e, CM_ERR_TOO_FEW_VERTICES, "hole 1 (loop 1) has 2 vertices", 0, -1);
    b.xy[2 * 9 + 1] = NAN;
    expect_bad("not finite", &a, &b, CM_ERR_NOT_FINITE, "polygon 1: hole 1 (loop 1): vertex 1", 1, 9);
    b = a;
    b.xy[2 * 10] = b.xy[2 * 2], b.xy[2 * 10 + 1] = b.xy[2 * 2 + 1];
    expect_bad("repeated", &a, &b, CM_ERR_REPEATED_VERTEX,
               "polygon 1: hole 1 (loop 1): vertex 2 repeats vertex 2 of the outer loop", 1, 10);
    b = a; /* the hole's last vertex closing it as a ring */
    b.xy[2 * 11] = b.xy[2 * 8], b.xy[2 * 11 + 1] = b.xy[2 * 8 + 1];
    expect_bad("closed ring", &a, &b, CM_ERR_REPEATED_VERTEX,
               "polygon 1: hole 1 (loop 1): vertex 3 repeats vertex 0 of hole 1 (loop 1) (-0.40000000000000002, "
               "-0.40000000000000002) (a closed ring",
               1, 11);
    b = a; /* hole vertex 2 pushed through the outer loop's right side */
    b.xy[2 * 10] = 1.5;
    expect_bad("hole crosses outer", &a, &b, CM_ERR_SELF_INTERSECTION,
               "polygon 1: edge 3-4 of the outer loop (loop 0) and edge", 1, 3);
    b = a; /* hole bow-tie: vertices 1 and 2 swapped */
    b.xy[2 * 9] = a.xy[2 * 10], b.xy[2 * 9 + 1] = a.xy[2 * 10 + 1];
    b.xy[2 * 10] = a.xy[2 * 9], b.xy[2 * 10 + 1] = a.xy[2 * 9 + 1];
    expect_bad("hole not simple", &a, &b, CM_ERR_SELF_INTERSECTION,
               "polygon 1: hole 1 (loop 1): edges", 1, 8);
    b = a; /* the hole moved outside */
    for (size_t i = 8; i < 12; i++) b.xy[2 * i] += 5;
    expect_bad("hole outside", &a, &b, CM_ERR_SELF_INTERSECTION, "polygon 1: hole 1 (loop 1) lies outside the outer loop", 1, 8);
    shape f = {0}, g = {0};
    add_square(&f, 0, 0, 1, 8, 1);
    add_square(&f, 0, 0, 0.6, 4, -1);
    add_square(&f, 0, 0, 0.2, 4, -1);
    add_square(&g, 0, 0, 1, 8, 1);
    add_square(&g, -0.5, 0, 0.2, 4, -1);
    add_square(&g, 0.5, 0, 0.2, 4, -1);
    expect_bad("nested holes", &g, &f, CM_ERR_SELF_INTERSECTION,
               "polygon 1: hole 2 (loop 2) lies inside hole 1 (loop 1)", 1, 12);
    shape t = g; /* hole 2 touching hole 1 at a vertex */
    t.xy[2 * 12] = -0.3, t.xy[2 * 12 + 1] = 0.1;
    t.xy[2 * 14] = -0.2, t.xy[2 * 14 + 1] = 0.4;
    t.xy[2 * 13] = t.xy[2 * 9 + 0], t.xy[2 * 13 + 1] = t.xy[2 * 9 + 1] - 0.0;
    expect_bad("holes touch", &g, &t, CM_ERR_REPEATED_VERTEX, "hole 2 (loop 2): vertex 1 repeats vertex 1 of hole 1", 1, 13);
    shape u = g; /* hole 2 mirrored: clockwise in polygon 0, counter-clockwise here */
    for (size_t i = 0; i < 4; i++) {
        u.xy[2 * (12 + i)] = g.xy[2 * (15 - i)], u.xy[2 * (12 + i) + 1] = g.xy[2 * (15 - i) + 1];
    }
    expect_bad("orientation", &g, &u, CM_ERR_ORIENTATION_MISMATCH,
               "polygon 1: hole 2 (loop 2) is counter-clockwise but in polygon 0 it is clockwise", 1, 12);
    cm_options o;
    cm_options_init(&o);
    o.correspondence = CM_CORRESPOND_ARCLENGTH;
    size_t pins[2] = {0, 0};
    o.pins = pins, o.num_pins = 1;
    cm_loops in[2] = {loops_of(&a), loops_of(&a)};
    cm_result *r = NULL;
    CHECK(cm_triangulate_loops(in, 2, &o, &r) == CM_ERR_ARGUMENT);
    CHECK(strstr(cm_result_message(r), "pins are not taken for polygons with holes"));
    cm_result_free(r);
}

/* The input loop of polygon g that input vertex v (whole-array index)
 * belongs to, and its start and size. */
static size_t input_loop(const shape *s, long v, size_t *start, size_t *size)
{
    size_t l = 0, at = 0;
    while (l + 1 < s->loops && (size_t)v >= at + s->sizes[l]) at += s->sizes[l++];
    *start = at, *size = s->sizes[l];
    return l;
}

/* The boundary contract of an arc-length result with holes, polygon by
 * polygon: every boundary vertex is P[e] + t (P[e + 1] - P[e]) bit for bit
 * (e + 1 within e's loop; an input vertex at t = 0 is the input's own
 * coordinates), the loops one after another in input order (the second
 * polygon's in the order `second`, its input loop at each place, where
 * not NULL), each input vertex once and in its loop's cyclic order either
 * way round, every loop of the same size in every polygon, the outer loop
 * counter-clockwise and the holes clockwise. sizes: the output loops'
 * sizes; hole_added: points not input vertices on the loops after the
 * first. 1 when it holds. */
static int holes_boundary_contract_in(const cm_result *r, const shape *const *in, const size_t *second,
                                      size_t *sizes, size_t *hole_added)
{
    size_t n = cm_result_stats(r)->n, loops = in[0]->loops;
    int ok = 1;
    *hole_added = 0;
    for (size_t g = 0; g < 2 && ok; g++) {
        const shape *s = in[g];
        const double *xy = cm_result_vertices(r, g);
        size_t count[HF_MAX_LOOPS] = {0}, seen[HF_MAX_LOOPS] = {0}, at = 0;
        long last = -1, step = 0;
        for (size_t i = 0; i < n && ok; i++) {
            double t;
            long e = cm_result_boundary_source(r, g, i, &t);
            if (e < 0 || (size_t)e >= s->n || !(t >= 0 && t < 1)) return 0;
            size_t start, size, l = input_loop(s, e, &start, &size), place = l;
            for (size_t j = 0; g == 1 && second && j < loops; j++)
                if (second[j] == l) place = j;
            if (place < at || place >= loops) return 0;
            if (place > at) at = place, last = -1, step = 0;
            count[place]++;
            const double *p = s->xy + 2 * e, *q = s->xy + 2 * (start + ((size_t)e - start + 1) % size);
            ok &= xy[2 * i] == p[0] + t * (q[0] - p[0]) && xy[2 * i + 1] == p[1] + t * (q[1] - p[1]);
            if (t != 0) {
                *hole_added += g == 0 && l > 0;
                continue;
            }
            seen[place]++;
            long local = e - (long)start, m = (long)size;
            if (last >= 0) { /* the next input vertex of the loop, one way throughout */
                long d = ((local - last) % m + m) % m;
                if (!step) step = d == 1 ? 1 : d == m - 1 ? -1 : 0;
                ok &= step != 0 && d == (step > 0 ? 1 : m - 1);
            }
            last = local;
        }
        for (size_t l = 0, first = 0; l < loops && ok; first += count[l++]) {
            ok &= seen[l] == s->sizes[g == 1 && second ? second[l] : l] && (g == 0 || count[l] == sizes[l]);
            if (g == 0) sizes[l] = count[l];
            double area = 0;
            for (size_t i = 0; i < count[l]; i++) {
                const double *u = xy + 2 * (first + i), *w = xy + 2 * (first + (i + 1) % count[l]);
                area += u[0] * w[1] - w[0] * u[1];
            }
            ok &= l == 0 ? area > 0 : area < 0;
        }
    }
    return ok;
}

static int holes_boundary_contract(const cm_result *r, const shape *const *in, size_t *sizes, size_t *hole_added)
{
    return holes_boundary_contract_in(r, in, NULL, sizes, hole_added);
}

/* Arc-length and auto correspondences with holes: loops of different
 * sizes pair loop by loop. Expected: valid (checked exactly against the
 * refined loops the result reports), every input vertex of every loop a
 * boundary vertex, bit-identical, once and in order; every other boundary
 * vertex on the input edge it names, of its own loop; 1 hole, Euler
 * characteristic 0. The index correspondence with max_edge (loops of equal
 * sizes) splits the edges the same way, loop by loop. */
static void test_arclength_loops(void)
{
    shape a = {0}, b = {0}, c = {0}, unused = {0};
    hf_sizes_differ(&a, &b); /* b the other way round: normalised */
    hf_square_disc(&unused, &c);
    cm_correspondence modes[3] = {CM_CORRESPOND_ARCLENGTH, CM_CORRESPOND_AUTO, CM_CORRESPOND_INDEX};
    for (int mode = 0; mode < 3; mode++)
        for (int remesh = 0; remesh < 2; remesh++) {
            const shape *in_shape[2] = {&a, mode == 2 ? &c : &b};
            cm_options o;
            cm_options_init(&o);
            o.correspondence = modes[mode], o.remesh = remesh;
            if (mode == 2) o.max_edge = 0.2;
            cm_loops in[2] = {loops_of(in_shape[0]), loops_of(in_shape[1])};
            cm_result *r = NULL;
            cm_status st = cm_triangulate_loops(in, 2, &o, &r);
            CHECK_MSG(st == CM_OK, "mode %d: %s", mode, cm_result_message(r));
            if (st != CM_OK) {
                cm_result_free(r);
                continue;
            }
            size_t n = cm_result_stats(r)->n, sizes[HF_MAX_LOOPS], added;
            int contract = holes_boundary_contract(r, in_shape, sizes, &added);
            CHECK_MSG(contract, "mode %d remesh %d: the boundary contract", mode, remesh);
            if (contract) {
                cm_loops refined[2] = {{cm_result_vertices(r, 0), sizes, 2}, {cm_result_vertices(r, 1), sizes, 2}};
                char why[256] = "";
                CHECK_MSG(rc_check_loops(r, refined, 2, why, sizeof why), "mode %d remesh %d: %s", mode, remesh, why);
                CHECK_MSG(rc_check_halfedges_holes(r, n, 1, why, sizeof why), "mode %d remesh %d: %s", mode, remesh, why);
                CHECK(cm_result_stats(r)->holes == 1 && n >= (mode == 2 ? 24 + 10 : 23 + 11));
                cm_quality q0, q1;
                cm_result_quality(r, 0, &q0), cm_result_quality(r, 1, &q1);
                printf("square/disc, loops of different sizes, %s%s: %zu boundary vertices, Steiner %zu, "
                       "smallest angles %.1f %.1f\n", mode == 2 ? "index, max_edge 0.2" : mode ? "auto" : "arclength",
                       remesh ? ", remeshed" : "", n,
                       cm_result_stats(r)->steiner, q0.min_angle_deg, q1.min_angle_deg);
            }
            cm_result_free(r);
        }
}

/* Auto chooses a hole's start jointly with the outer loop. An egg with a
 * regular 12-gon hole, and its image under a similarity (scale 2, turned
 * 100 degrees, moved) renumbered from outer vertex 3, whose hole is the
 * image of the 24-gon through the 12-gon's vertices, numbered so that
 * vertex 19 is the image of the 12-gon's vertex 0. Aligned on its own, a
 * regular hole fits every start alike; under the outer loops' similarity
 * only vertex 19 lies on it. Expected: valid, and the boundary vertex that
 * is the first polygon's hole vertex 0 (input vertex 20) is input vertex
 * 39 of the second, with or without remeshing. */
static void test_auto_hole_starts(void)
{
    shape a = {0}, b = {0};
    hf_egg(&a, &b);
    for (int remesh = 0; remesh < 2; remesh++) {
        cm_options o;
        cm_options_init(&o);
        o.correspondence = CM_CORRESPOND_AUTO, o.remesh = remesh;
        cm_loops in[2] = {loops_of(&a), loops_of(&b)};
        cm_result *r = NULL;
        cm_status st = cm_triangulate_loops(in, 2, &o, &r);
        CHECK_MSG(st == CM_OK, "auto hole starts: %s", cm_result_message(r));
        long paired = -2;
        for (size_t i = 0; st == CM_OK && i < cm_result_stats(r)->n; i++) {
            double t0, t1;
            if (cm_result_boundary_source(r, 0, i, &t0) == 20 && t0 == 0) {
                paired = cm_result_boundary_source(r, 1, i, &t1);
                if (t1 != 0) paired = -1;
            }
        }
        CHECK_MSG(paired == 39, "remesh %d: hole vertex 0 of the first polygon paired with %ld of the second, "
                                "not 39", remesh, paired);
        cm_result_free(r);
    }
}

/* One auto run of a pair with holes (remeshed with the given restarts,
 * or restarts < 0: not remeshed): valid, within the boundary contract (the
 * loops as the result wrote them checked exactly); *n: the boundary
 * vertices, *least: the smallest angle. 0 where the run or the contract
 * failed. */
static int auto_run_on_loops(const shape *a, const shape *b, int restarts, const char *name, size_t *n,
                             double *least, cm_correspondence_choice *choice)
{
    cm_options o;
    cm_options_init(&o);
    o.correspondence = CM_CORRESPOND_AUTO, o.restarts = restarts < 0 ? 0 : restarts, o.remesh = restarts >= 0;
    cm_loops in[2] = {loops_of(a), loops_of(b)};
    cm_result *r = NULL;
    cm_status st = cm_triangulate_loops(in, 2, &o, &r);
    CHECK_MSG(st == CM_OK, "%s, restarts %d: %s", name, restarts, cm_result_message(r));
    int ok = 0;
    if (st == CM_OK) {
        const shape *in_shape[2] = {a, b};
        size_t sizes[HF_MAX_LOOPS], hole_added;
        int contract = holes_boundary_contract(r, in_shape, sizes, &hole_added);
        CHECK_MSG(contract, "%s, restarts %d: the boundary contract", name, restarts);
        if (contract) {
            cm_loops refined[2] = {{cm_result_vertices(r, 0), sizes, b->loops},
                                   {cm_result_vertices(r, 1), sizes, b->loops}};
            char why[256] = "";
            CHECK_MSG(rc_check_loops(r, refined, 2, why, sizeof why), "%s: %s", name, why);
            CHECK_MSG(rc_check_halfedges_holes(r, cm_result_stats(r)->n, b->loops - 1, why, sizeof why), "%s: %s",
                      name, why);
            ok = 1;
        }
        *n = cm_result_stats(r)->n, *least = rc_least_angle(r, 2), *choice = cm_result_stats(r)->correspondence_choice;
        printf("%s, auto, restarts %d: %zu boundary vertices, Steiner %zu, smallest angle %.1f\n", name, restarts, *n,
               cm_result_stats(r)->steiner, *least);
    }
    cm_result_free(r);
    return ok;
}

/* Auto on a square ring against the same ring with a stem (hole_fixtures.h,
 * loops of different sizes), remeshed. Arc length from the similarity's
 * start reached 13.3 degrees (smaller of the two meshes); the conformal
 * correspondence of the filled outer loops, auto's first pairing, 19.5 to
 * 20.8, below 0.8 of the aim of 25, so the rescues run; the first of them
 * for one hole, the annulus pairing of both loops at once, 28.9. Expected,
 * with and without restarts: valid, the annulus pairing kept, the
 * smallest angle of both meshes at least 25 degrees. */
static void test_auto_ring_and_stem(void)
{
    shape a = {0}, b = {0};
    hf_ring_and_stem(&a, &b);
    CHECK(a.n == 32 + 12 && b.n == 64 + 12);
    for (int restarts = 0; restarts < 2; restarts++) {
        size_t n = 0;
        double least = 0;
        cm_correspondence_choice choice = CM_CHOICE_INDEX;
        if (!auto_run_on_loops(&a, &b, restarts, "ring and stem", &n, &least, &choice)) continue;
        CHECK(choice == CM_CHOICE_ANNULUS);
        CHECK_MSG(least >= 25.0, "ring and stem: smallest angle %.2f, below 25 degrees", least);
    }
}

/* The remesher's restart starts from the loops as the first run refined
 * them: five triangle holes (hole_fixtures.h) paired by auto, where the
 * remesher adds points to the loops and ends below 0.85 of its aim (10
 * degrees; 19 boundary vertices before remeshing, 22 after). Expected,
 * with and without the restart: valid, within the boundary contract, more
 * boundary vertices than before remeshing; the restart higher. */
static void test_auto_restart_from_refined_loops(void)
{
    shape a = {0}, b = {0};
    hf_five_triangles(&a, &b);
    double least[2] = {0, 0}, unused;
    size_t before = 0;
    cm_correspondence_choice choice;
    auto_run_on_loops(&a, &b, -1, "five triangle holes, not remeshed", &before, &unused, &choice);
    for (int restarts = 0; restarts < 2; restarts++) {
        size_t n = 0;
        if (!auto_run_on_loops(&a, &b, restarts, "five triangle holes", &n, &least[restarts], &choice)) continue;
        CHECK_MSG(before > 0 && n > before, "five triangle holes, restarts %d: %zu boundary vertices, %zu before remeshing",
                  restarts, n, before);
    }
    CHECK_MSG(least[1] > least[0], "five triangle holes: the restart %.2f, without %.2f degrees", least[1],
              least[0]);
}

/* Auto takes the least turn where turns fit alike: two sections of a
 * pipe (circles of other sizes from other angles, hole_fixtures.h), and
 * a flange against itself turned by 15 degrees (six bolt holes; the
 * outline fixes no turn, the holes fix it up to 60 degrees); the
 * similarity choice too, on that flange (every start of its outline fits
 * alike: the holes break the tie, within half a start's step of 9
 * degrees) and on a hexagonal flange turned by 15 degrees (six starts fit
 * exactly, their residuals rounding noise either side of 0). Expected:
 * valid, within the boundary contract; the pipe paired with a turn of the
 * plane under 2 degrees (built before on a turn of -159 degrees), the
 * flanges with one within 2 degrees of 15 (the similarity choice on the
 * round one within 4.5, half its step; before -161, 67 and 135, six holes
 * paired with others in each) and every hole with the one at its place
 * (holes_moved 0), all at least 15 degrees (min(15, c / 3)). */
static void test_auto_least_turn(void)
{
    static const struct {
        const char *name;
        void (*build)(shape *, shape *);
        double turn, within;
        cm_correspondence mode;
    } cases[] = {{"pipe", hf_pipe, 0, 2, CM_CORRESPOND_AUTO},
                 {"flange", hf_flange_turned, 15, 2, CM_CORRESPOND_AUTO},
                 {"flange, similarity", hf_flange_turned, 15, 4.5, CM_CORRESPOND_SIMILARITY},
                 {"hexagonal flange, similarity", hf_hex_flange_turned, 15, 2, CM_CORRESPOND_SIMILARITY}};
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        shape a = {0}, b = {0};
        cases[c].build(&a, &b);
        cm_options o;
        cm_options_init(&o);
        o.correspondence = cases[c].mode;
        cm_loops in[2] = {loops_of(&a), loops_of(&b)};
        cm_result *r = NULL;
        cm_status st = cm_triangulate_loops(in, 2, &o, &r);
        CHECK_MSG(st == CM_OK, "%s: %s", cases[c].name, cm_result_message(r));
        if (st == CM_OK) {
            const shape *in_shape[2] = {&a, &b};
            size_t sizes[HF_MAX_LOOPS], hole_added;
            CHECK_MSG(holes_boundary_contract(r, in_shape, sizes, &hole_added), "%s: the boundary contract",
                      cases[c].name);
            double turn = rc_plane_turn_deg(r, 1, sizes[0]), least = rc_least_angle(r, 2);
            CHECK_MSG(fabs(turn - cases[c].turn) < cases[c].within, "%s: turned by %.2f degrees, not %.0f", cases[c].name,
                      turn, cases[c].turn);
            CHECK_MSG(cm_result_stats(r)->holes_moved == 0, "%s: %zu holes moved", cases[c].name,
                      cm_result_stats(r)->holes_moved);
            CHECK_MSG(least >= 15, "%s: smallest angle %.2f", cases[c].name, least);
            printf("%s: turned by %.2f degrees, Steiner %zu, smallest angle %.1f\n", cases[c].name, turn,
                   cm_result_stats(r)->steiner, least);
        }
        cm_result_free(r);
    }
}

/* Three sections of a part that twists as it goes: the hexagonal flange
 * (hole_fixtures.h) at 0, 25 and 50 degrees, 10, 8 and 9 points a side
 * (auto: conformal; similarity), and with 10 a side each (auto: affine).
 * Turns 60 degrees apart fit alike, so the third alone could pair at -10
 * degrees; each is taken nearest the one before. Expected: valid; the
 * second and third paired turned by 25 and 50 degrees, within 2 (before:
 * -130 and 170 among others), no hole moved; at least 15 degrees. */
static void test_twisting_sections(void)
{
    const double pi = 3.14159265358979323846;
    static const struct {
        const char *name;
        size_t per[3];
        cm_correspondence mode;
    } cases[] = {{"auto", {10, 8, 9}, CM_CORRESPOND_AUTO},
                 {"similarity", {10, 8, 9}, CM_CORRESPOND_SIMILARITY},
                 {"auto, equal counts", {10, 10, 10}, CM_CORRESPOND_AUTO}};
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        shape s[3];
        memset(s, 0, sizeof s);
        for (int g = 0; g < 3; g++) hex_flange(&s[g], g * 25 * pi / 180, cases[c].per[g]);
        cm_options o;
        cm_options_init(&o);
        o.correspondence = cases[c].mode;
        cm_loops in[3] = {loops_of(&s[0]), loops_of(&s[1]), loops_of(&s[2])};
        cm_result *r = NULL;
        cm_status st = cm_triangulate_loops(in, 3, &o, &r);
        CHECK_MSG(st == CM_OK, "twisting sections, %s: %s", cases[c].name, cm_result_message(r));
        if (st == CM_OK) {
            size_t n = cm_result_stats(r)->n, outer = 0;
            for (double t; outer < n && cm_result_boundary_source(r, 0, outer, &t) < (long)s[0].sizes[0];) outer++;
            double turn[2];
            for (int g = 1; g < 3; g++) { /* over the outer loop */
                turn[g - 1] = rc_plane_turn_deg(r, (size_t)g, outer);
                CHECK_MSG(fabs(turn[g - 1] - 25 * g) < 2, "twisting sections, %s: section %d turned by %.2f degrees",
                          cases[c].name, g, turn[g - 1]);
            }
            double least = rc_least_angle(r, 3);
            CHECK_MSG(cm_result_stats(r)->holes_moved == 0, "twisting sections, %s: %zu holes moved", cases[c].name,
                      cm_result_stats(r)->holes_moved);
            CHECK_MSG(least >= 15, "twisting sections, %s: smallest angle %.2f", cases[c].name, least);
            printf("twisting sections, %s: turned by %.2f and %.2f degrees, Steiner %zu, smallest angle %.1f\n",
                   cases[c].name, turn[0], turn[1], cm_result_stats(r)->steiner, least);
        }
        cm_result_free(r);
    }
}

/* Auto pairs the holes by position: seven round holes on a grid in a
 * disc, listed in another order in the second polygon, whose loops have
 * other vertex counts (hole_fixtures.h; with equal counts the index
 * correspondence pairs holes at different places and ends near 4
 * degrees). Expected with auto: every hole of the second polygon pairs
 * with the first's hole at the same place (the boundary contract with the
 * second's loops in that order, stats.holes_moved 7 of 7), valid, and the
 * smallest angle at least 15 degrees (min(15, c / 3)); with arclength the
 * loops pair in input order (holes_moved 0). */
static void test_auto_matches_holes_by_position(void)
{
    shape a = {0}, b = {0};
    hf_seven_permuted_counts(&a, &b);
    size_t second[8] = {0, 4, 7, 5, 2, 6, 1, 3}; /* the second's input loop at each place of the first's */
    for (int mode = 0; mode < 2; mode++) {
        cm_options o;
        cm_options_init(&o);
        o.correspondence = mode ? CM_CORRESPOND_AUTO : CM_CORRESPOND_ARCLENGTH, o.remesh = mode;
        cm_loops in[2] = {loops_of(&a), loops_of(&b)};
        cm_result *r = NULL;
        cm_status st = cm_triangulate_loops(in, 2, &o, &r);
        CHECK_MSG(st == CM_OK, "seven holes permuted, %s: %s", mode ? "auto" : "arclength", cm_result_message(r));
        if (st == CM_OK) {
            const shape *in_shape[2] = {&a, &b};
            size_t sizes[HF_MAX_LOOPS], added;
            int contract = holes_boundary_contract_in(r, in_shape, mode ? second : NULL, sizes, &added);
            CHECK_MSG(contract, "seven holes permuted, %s: the boundary contract", mode ? "auto" : "arclength");
            CHECK(cm_result_stats(r)->holes_moved == (mode ? 7u : 0u));
            if (contract) {
                cm_loops refined[2] = {{cm_result_vertices(r, 0), sizes, 8}, {cm_result_vertices(r, 1), sizes, 8}};
                char why[256] = "";
                CHECK_MSG(rc_check_loops(r, refined, 2, why, sizeof why), "seven holes permuted: %s", why);
                CHECK_MSG(rc_check_halfedges_holes(r, cm_result_stats(r)->n, 7, why, sizeof why),
                          "seven holes permuted: %s", why);
            }
            if (mode) {
                double least = rc_least_angle(r, 2);
                CHECK_MSG(least >= 15.0, "seven holes permuted, auto: smallest angle %.2f, below 15 degrees", least);
                printf("seven holes permuted, auto: %zu holes moved, Steiner %zu, smallest angle %.1f\n",
                       cm_result_stats(r)->holes_moved, cm_result_stats(r)->steiner, least);
            }
        }
        cm_result_free(r);
    }
}

/* Auto lets the holes choose the turn of an outline a half turn takes onto
 * itself: rectangular plates with three bolt holes, the second moved and
 * listed from the opposite corner (hole_fixtures.h), as the same loops (an
 * affine image) and as a plate a little different. Expected: the first
 * plate's corner (-4, -2) pairs with the second's corresponding corner
 * (-3.7, 8) or (-3.8, 8.1): exactly for the affine image, within 0.5
 * otherwise (a conformal pairing of rectangles of other shapes slides the
 * corners; half turned it lies 9 away), no hole moved, valid, and the
 * smallest angle at least 20 degrees (the outline paired half turned
 * against the holes twisted the map: 7 degrees). */
static void test_auto_turn_chosen_by_holes(void)
{
    for (int exact = 0; exact < 2; exact++) {
        shape a = {0}, b = {0};
        hf_rectangle_plates(&a, &b, exact);
        cm_options o;
        cm_options_init(&o);
        o.correspondence = CM_CORRESPOND_AUTO;
        cm_loops in[2] = {loops_of(&a), loops_of(&b)};
        cm_result *r = NULL;
        cm_status st = cm_triangulate_loops(in, 2, &o, &r);
        const char *name = exact ? "rectangular plates, exact" : "rectangular plates, near";
        CHECK_MSG(st == CM_OK, "%s: %s", name, cm_result_message(r));
        if (st == CM_OK) {
            double want[2] = {exact ? -3.7 : -3.8, exact ? 8 : 8.1}, apart = HUGE_VAL;
            for (size_t i = 0; i < cm_result_stats(r)->n; i++) {
                double t;
                if (cm_result_boundary_source(r, 0, i, &t) == 0 && t == 0) {
                    const double *p = cm_result_vertices(r, 1) + 2 * i;
                    apart = hypot(p[0] - want[0], p[1] - want[1]);
                }
            }
            CHECK_MSG(exact ? apart == 0 : apart < 0.5, "%s: the corner pairs %.3g from its own", name, apart);
            CHECK(cm_result_stats(r)->holes_moved == 0);
            CHECK(!exact || cm_result_stats(r)->correspondence_choice == CM_CHOICE_AFFINE);
            double least = rc_least_angle(r, 2);
            CHECK_MSG(least >= 20.0, "%s: smallest angle %.2f, below 20 degrees", name, least);
            printf("%s, auto: %s, Steiner %zu, smallest angle %.1f\n", name,
                   cm_correspondence_choice_name(cm_result_stats(r)->correspondence_choice),
                   cm_result_stats(r)->steiner, least);
        }
        cm_result_free(r);
    }
}

/* Do boundary vertices u and w of polygon g (input loops s) lie on one of
 * its input edges? An input vertex lies on the edges before and after it
 * along its loop, a point inside an edge on that edge alone. */
static int on_one_edge(const cm_result *r, const shape *s, size_t g, size_t u, size_t w)
{
    double t[2];
    long e[2] = {cm_result_boundary_source(r, g, u, &t[0]), cm_result_boundary_source(r, g, w, &t[1])}, before[2];
    for (int i = 0; i < 2; i++) {
        size_t start, size;
        input_loop(s, e[i], &start, &size);
        before[i] = (size_t)e[i] == start ? (long)(start + size - 1) : e[i] - 1;
    }
    return e[0] == e[1] || (t[0] == 0 && e[1] == before[0]) || (t[1] == 0 && e[0] == before[1]);
}

/* A slanted quadrilateral with a slanted quadrilateral hole against stars
 * with an off-centre star hole (auto, seeds 1 to 8): every loop of the
 * quadrilateral gets the stars' vertices on its edges, rounded off their
 * lines, so a segment between two on one input edge can pass as a
 * diagonal with a sliver beside it (seeds 2, 7 and 8 join two on one edge
 * of the hole loop when the partition is not told where they lie).
 * Expected: valid; points added on the hole loop's input edges (else the
 * check below is idle); no construction edge but the boundary's joins two
 * boundary vertices on one input edge of either polygon, on any loop. */
static void test_no_edge_along_an_input_edge(void)
{
    enum { N = 40, H = 24 };
    const double quad[8] = {0, 0, 1, 0.3, 0.7, 1.3, -0.3, 1};
    for (int seed = 1; seed <= 8; seed++) {
        shape a = {0}, b = {0};
        begin_loop(&a);
        for (int i = 0; i < 4; i++) add_point(&a, quad[2 * i], quad[2 * i + 1]);
        begin_loop(&a); /* the quadrilateral shrunk to 0.3 about (0.35, 0.65), clockwise */
        for (int i = 3; i >= 0; i--) add_point(&a, 0.35 + 0.3 * (quad[2 * i] - 0.35), 0.65 + 0.3 * (quad[2 * i + 1] - 0.65));
        double star[2 * N], hole[2 * H];
        CHECK(rp_star(star, N, (uint64_t)seed) == 0 && rp_star(hole, H, (uint64_t)seed + 50) == 0);
        begin_loop(&b);
        for (int i = 0; i < N; i++) add_point(&b, star[2 * i], star[2 * i + 1]);
        begin_loop(&b); /* within 0.24 of the centre, inside the star's radius 0.3; clockwise */
        for (int i = H - 1; i >= 0; i--) add_point(&b, 0.12 + 0.12 * hole[2 * i], 0.12 * hole[2 * i + 1]);
        cm_options o;
        cm_options_init(&o);
        o.correspondence = CM_CORRESPOND_AUTO, o.remesh = 0;
        cm_loops in[2] = {loops_of(&a), loops_of(&b)};
        cm_result *r = NULL;
        CHECK_MSG(cm_triangulate_loops(in, 2, &o, &r) == CM_OK, "seed %d: %s", seed, cm_result_message(r));
        if (cm_result_status(r) != CM_OK) {
            cm_result_free(r);
            continue;
        }
        size_t n = cm_result_stats(r)->n, added = 0, along = 0, start[3] = {0, n, n}; /* the output's loops */
        for (size_t i = 0; i < n; i++) {
            double t;
            if (cm_result_boundary_source(r, 0, i, &t) < 4) continue; /* the outer loop's */
            start[1] = i < start[1] ? i : start[1];
            added += t != 0;
        }
        const int32_t *tri = cm_result_triangles(r);
        for (size_t c = 0; c < 3 * cm_result_num_triangles(r); c++) {
            size_t u = (size_t)tri[c], w = (size_t)tri[c - c % 3 + (c + 1) % 3];
            if (u >= n || w >= n || cm_loops_next(start, n, u) == w || cm_loops_next(start, n, w) == u) continue;
            along += on_one_edge(r, &a, 0, u, w) + on_one_edge(r, &b, 1, u, w);
        }
        CHECK_MSG(added >= H / 2, "seed %d: %zu points added on the hole loop", seed, added);
        CHECK_MSG(along == 0, "seed %d: %zu construction edges along an input edge", seed, along);
        cm_result_free(r);
    }
}

/* A 10 x 3 rectangle (unit edges, 26 vertices) with an 8 x 1 rectangular
 * hole 1 from either long side (input vertices 26 to 29, clockwise from
 * (1, 1): edges 27 (1, 2) -> (9, 2) and 29 (9, 1) -> (1, 1) the long ones),
 * against a copy scaled by 2 and moved. A triangle on a long hole edge
 * has its apex at most 1 from it, so its smallest angle is at most
 * atan(1 / 4) = 14.04 degrees: index keeps the boundary and stays below
 * that. Arclength and auto halve the long hole edges in every polygon (cap
 * 25 degrees with the margin 0.9 needs pieces of 2: t = 1/4, 1/2, 3/4),
 * no other edge (the outer ones are short); the output keeps the loops'
 * input vertices first, in order, and passes the bound. Expected: valid,
 * 1 hole, V - E + F = 0, 36 boundary vertices, the hole's boundary sources
 * as listed. */
static void test_capped_hole_edges_split(void)
{
    shape a = {0}, b = {0};
    begin_loop(&a);
    for (int i = 0; i < 10; i++) add_point(&a, i, 0);
    for (int i = 0; i < 3; i++) add_point(&a, 10, i);
    for (int i = 10; i > 0; i--) add_point(&a, i, 3);
    for (int i = 3; i > 0; i--) add_point(&a, 0, i);
    begin_loop(&a);
    add_point(&a, 1, 1), add_point(&a, 1, 2), add_point(&a, 9, 2), add_point(&a, 9, 1);
    b = a;
    for (size_t i = 0; i < b.n; i++) b.xy[2 * i] = 2 * a.xy[2 * i] + 5, b.xy[2 * i + 1] = 2 * a.xy[2 * i + 1] - 1;
    double bound = atan(0.25) * 45.0 / atan(1.0);
    cm_correspondence modes[3] = {CM_CORRESPOND_INDEX, CM_CORRESPOND_ARCLENGTH, CM_CORRESPOND_AUTO};
    for (int m = 0; m < 3; m++) {
        cm_options o;
        cm_options_init(&o);
        o.correspondence = modes[m];
        cm_loops in[2] = {loops_of(&a), loops_of(&b)};
        cm_result *r = NULL;
        CHECK_MSG(cm_triangulate_loops(in, 2, &o, &r) == CM_OK, "mode %d: %s", m, cm_result_message(r));
        if (cm_result_status(r) != CM_OK) {
            cm_result_free(r);
            continue;
        }
        size_t n = cm_result_stats(r)->n;
        double least = rc_least_angle(r, 2);
        if (m == 0) {
            CHECK_MSG(n == 30 && least <= bound, "index: %zu boundary vertices, %g degrees", n, least);
            cm_result_free(r);
            continue;
        }
        CHECK_MSG(n == 36 && least > bound, "mode %d: %zu boundary vertices, %g degrees", m, n, least);
        /* the hole in input order, its long edges' new points between */
        static const long edge[10] = {26, 27, 27, 27, 27, 28, 29, 29, 29, 29};
        static const double at[10] = {0, 0, 0.25, 0.5, 0.75, 0, 0, 0.25, 0.5, 0.75};
        for (size_t g = 0; g < 2 && n == 36; g++) {
            const double *xy = cm_result_vertices(r, g), *in_xy = g ? b.xy : a.xy;
            for (size_t i = 0; i < n; i++) {
                double t;
                long e = cm_result_boundary_source(r, g, i, &t);
                long want = i < 26 ? (long)i : edge[i - 26];
                double want_t = i < 26 ? 0 : at[i - 26];
                CHECK_MSG(e == want && t == want_t, "mode %d, polygon %zu, vertex %zu: edge %ld at %g", m, g, i, e, t);
                if (t == 0 && e >= 0 && e < 30)
                    CHECK_MSG(memcmp(xy + 2 * i, in_xy + 2 * e, 2 * sizeof(double)) == 0,
                              "mode %d, polygon %zu, vertex %zu: not input vertex %ld", m, g, i, e);
            }
        }
        if (n == 36) {
            size_t sizes[2] = {26, 10};
            cm_loops refined[2] = {{cm_result_vertices(r, 0), sizes, 2}, {cm_result_vertices(r, 1), sizes, 2}};
            char why[256] = "";
            CHECK_MSG(rc_check_loops(r, refined, 2, why, sizeof why), "mode %d: %s", m, why);
            CHECK_MSG(rc_check_halfedges_holes(r, n, 1, why, sizeof why), "mode %d: %s", m, why);
        }
        cm_result_free(r);
    }
}

/* The remesher's boundary splits on a hole loop (arclength and auto): the
 * crowded hole against the hexagon, the disc's loops either way round.
 * The cap split adds no point on this pair (no edge's cap binds), so the
 * hole loop's points beyond those of the run without remeshing are the
 * remesher's. Expected: valid (exactly, against the output's loops), 1
 * hole, V - E + F = 0, the boundary contract above, in auto the
 * remesher's points on the hole loop (arclength splits the outer loop
 * and only its own, the greedy path's choice); the morph's sections valid and covering the outer
 * loop's area minus the hole's. Index never splits (test_capped_hole_edges_split). */
static void test_remesher_splits_hole_loops(void)
{
    cm_correspondence modes[2] = {CM_CORRESPOND_ARCLENGTH, CM_CORRESPOND_AUTO};
    for (int dir = -1; dir <= 1; dir += 2)
        for (int mode = 0; mode < 2; mode++) {
            static shape a, b, out;
            memset(&a, 0, sizeof a), memset(&b, 0, sizeof b), memset(&out, 0, sizeof out);
            hf_crowded_hole(&a, &b, dir);
            const shape *in_shape[2] = {&a, &b};
            cm_loops in[2] = {loops_of(&a), loops_of(&b)};
            size_t added[2] = {0, 0}, sizes[2][HF_MAX_LOOPS];
            cm_result *r[2] = {NULL, NULL};
            int contract[2] = {0, 0};
            for (int remesh = 0; remesh < 2; remesh++) {
                cm_options o;
                cm_options_init(&o);
                o.correspondence = modes[mode], o.remesh = remesh;
                CHECK_MSG(cm_triangulate_loops(in, 2, &o, &r[remesh]) == CM_OK, "dir %d mode %d remesh %d: %s", dir,
                          mode, remesh, cm_result_message(r[remesh]));
                if (cm_result_status(r[remesh]) == CM_OK)
                    contract[remesh] = holes_boundary_contract(r[remesh], in_shape, sizes[remesh], &added[remesh]);
                CHECK_MSG(contract[remesh], "dir %d mode %d remesh %d: the boundary contract", dir, mode, remesh);
            }
            if (contract[0] && contract[1]) {
                const cm_result *rr = r[1];
                size_t n = cm_result_stats(rr)->n;
                CHECK_MSG(!mode || added[1] > added[0], "dir %d, auto: %zu points on the hole loop remeshed, %zu without",
                          dir, added[1], added[0]);
                cm_loops refined[2] = {{cm_result_vertices(rr, 0), sizes[1], 2}, {cm_result_vertices(rr, 1), sizes[1], 2}};
                char why[256] = "";
                CHECK_MSG(rc_check_loops(rr, refined, 2, why, sizeof why), "dir %d mode %d: %s", dir, mode, why);
                CHECK_MSG(rc_check_halfedges_holes(rr, n, 1, why, sizeof why), "dir %d mode %d: %s", dir, mode, why);
                CHECK(cm_result_stats(rr)->holes == 1);
                size_t v = cm_result_num_vertices(rr), f = cm_result_num_triangles(rr);
                CHECK_MSG(2 * (long)v - (3 * (long)f + (long)n) + 2 * (long)f == 0, "dir %d mode %d: Euler", dir, mode);
                out.loops = 2, out.n = n, out.sizes[0] = sizes[1][0], out.sizes[1] = sizes[1][1];
                expect_morph("crowded hole", rr, &out);
                printf("crowded hole, disc's loops %s, %s: %zu boundary vertices (%zu without remeshing), %zu "
                       "points on the hole loop (%zu), smallest angle %.1f\n", dir > 0 ? "as usual" : "reversed",
                       mode ? "auto" : "arclength", n, cm_result_stats(r[0])->n, added[1], added[0],
                       rc_least_angle(rr, 2));
            }
            cm_result_free(r[0]), cm_result_free(r[1]);
        }
}

/* Without holes the loops call is cm_triangulate_polygons, bit for bit. */
static void test_hole_free_same(void)
{
    shape a = {0}, b = {0};
    add_square(&a, 0, 0, 1, 12, 1);
    add_circle(&b, 0.2, 0, 1.3, 12, 1);
    cm_loops in[2] = {loops_of(&a), loops_of(&b)};
    const double *p[2] = {a.xy, b.xy};
    size_t counts[2] = {12, 12};
    cm_result *r1 = NULL, *r2 = NULL;
    CHECK(cm_triangulate_loops(in, 2, NULL, &r1) == CM_OK);
    CHECK(cm_triangulate_polygons(p, counts, 2, NULL, &r2) == CM_OK);
    CHECK(cm_result_num_vertices(r1) == cm_result_num_vertices(r2) &&
          cm_result_num_triangles(r1) == cm_result_num_triangles(r2));
    CHECK(memcmp(cm_result_triangles(r1), cm_result_triangles(r2),
                 3 * cm_result_num_triangles(r1) * sizeof(int32_t)) == 0);
    for (size_t g = 0; g < 2; g++)
        CHECK(memcmp(cm_result_vertices(r1, g), cm_result_vertices(r2, g),
                     2 * cm_result_num_vertices(r1) * sizeof(double)) == 0);
    CHECK(cm_result_stats(r1)->holes == 0);
    cm_result_free(r1), cm_result_free(r2);
}

int main(void)
{
    test_bad_input();
    test_hole_free_same();
    test_square_and_disc();
    test_plate();
    test_turned_hole();
    test_fallback();
    test_arclength_loops();
    test_auto_hole_starts();
    test_auto_ring_and_stem();
    test_auto_restart_from_refined_loops();
    test_auto_least_turn();
    test_twisting_sections();
    test_auto_matches_holes_by_position();
    test_auto_turn_chosen_by_holes();
    test_no_edge_along_an_input_edge();
    test_capped_hole_edges_split();
    test_remesher_splits_hole_loops();
    return check_summary("test_holes");
}
