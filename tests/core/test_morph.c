/* The convex-combination morph: every frame of the twisted, spiral,
 * glyph-like and three-geometry fixtures is valid (re-checked here with the
 * exact predicates), the ends are the inputs bit for bit, the enclosed mesh
 * is a valid compatible triangulation with a common convex boundary, the
 * linear mode reports the inversions of a twisted pair, and bad arguments
 * give messages. Each fixture states the smallest angle it expects in
 * every frame, a measured floor (convex-combination morphs do not
 * optimise angles). */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "morph/enclosure.h"
#include "morph_fixtures.h"
#include "geom/predicates.h"

#define N 60
#define FRAMES 11

typedef struct expectation {
    fixture_kind kind;
    cm_morph_method method;
    double floor_deg; /* every frame's smallest angle at least this */
} expectation;

/* Measured at N = 60, smallest angle over the frames, ends included
 * (twisted 7.73 and 4.96, spiral 9.19 and 9.44, glyph 7.39 and 7.85, three
 * 11.39 and 6.41): weights interpolated: twisted 4.96, spiral 0.91, glyph
 * 3.18, three 1.01; intrinsic: twisted 4.96, spiral 3.80, glyph 2.99,
 * three 3.42. The floors sit 0.1 to 0.3 degrees below, and below what the
 * ends' remeshing gave before it stepped out of local optima (twisted
 * 4.02 interpolated). The frames' angles depend on the ends' meshes only
 * loosely: a better end does not make a better spiral frame. */
static const expectation fixtures[] = {
    {FIX_TWISTED, CM_MORPH_CONVEX, 3.8},    {FIX_SPIRAL, CM_MORPH_CONVEX, 0.85},
    {FIX_GLYPH, CM_MORPH_CONVEX, 3.0},      {FIX_THREE, CM_MORPH_CONVEX, 0.9},
    {FIX_TWISTED, CM_MORPH_INTRINSIC, 4.7}, {FIX_SPIRAL, CM_MORPH_INTRINSIC, 3.5},
    {FIX_GLYPH, CM_MORPH_INTRINSIC, 2.8},   {FIX_THREE, CM_MORPH_INTRINSIC, 3.2},
};

static size_t exact_inverted(const cm_result *r, const double *xy)
{
    const int32_t *tri = cm_result_triangles(r);
    size_t bad = 0;
    for (size_t t = 0; t < cm_result_num_triangles(r); t++)
        bad += cm_orient2d(xy + 2 * (size_t)tri[3 * t], xy + 2 * (size_t)tri[3 * t + 1],
                           xy + 2 * (size_t)tri[3 * t + 2]) <= 0;
    return bad;
}

static void test_frames(const expectation *x)
{
    const char *name = fixture_name(x->kind);
    cm_result *r = fixture_result(x->kind, N);
    CHECK_MSG(r != NULL, "%s: triangulation", name);
    if (!r) return;
    size_t k = cm_result_num_geometries(r), nv = cm_result_num_vertices(r);
    double bound = x->floor_deg;
    cm_morph *m = NULL;
    cm_morph_options o;
    cm_morph_options_init(&o);
    o.method = x->method;
    cm_status s = cm_morph_create(r, &o, &m);
    CHECK_MSG(s == CM_OK, "%s: %s", name, cm_morph_message(m));
    double *xy = malloc(2 * nv * sizeof *xy);
    size_t valid = 0;
    printf("%s, %s weights (k = %zu, %zu vertices): min angle per frame", name,
           x->method == CM_MORPH_INTRINSIC ? "intrinsic" : "interpolated", k, nv);
    for (int f = 0; f < FRAMES && s == CM_OK; f++) {
        double t = (double)f / (FRAMES - 1), angle = -1;
        size_t inverted = 99;
        cm_status st = cm_morph_section(m, t, xy, &inverted, &angle);
        CHECK_MSG(st == CM_OK && inverted == 0, "%s t=%g: %s", name, t, cm_morph_message(m));
        size_t recount = exact_inverted(r, xy);
        CHECK_MSG(recount == 0, "%s t=%g: %zu triangles invert", name, t, recount);
        CHECK_MSG(angle >= bound, "%s t=%g: min angle %.2f below %.2f", name, t, angle, bound);
        valid += st == CM_OK && recount == 0;
        printf(" %.2f", angle);
    }
    printf("; %zu/%d frames valid\n", valid, FRAMES);
    CHECK(valid == FRAMES);

    /* The ends, and for k = 3 the middle geometry, bit-identical. */
    for (size_t g = 0; g < k && s == CM_OK; g++) {
        double t = (double)g / (double)(k - 1);
        CHECK(cm_morph_section(m, t, xy, NULL, NULL) == CM_OK);
        CHECK_MSG(memcmp(xy, cm_result_vertices(r, g), 2 * nv * sizeof *xy) == 0, "%s: t=%g is not geometry %zu",
                  name, t, g);
    }
    /* Just after t = 0 the solve reproduces geometry 0 (mean value
     * coordinates reproduce the positions they were computed from). */
    if (s == CM_OK && cm_morph_section(m, 1e-12, xy, NULL, NULL) == CM_OK) {
        const double *g0 = cm_result_vertices(r, 0);
        double worst = 0;
        for (size_t j = 0; j < 2 * nv; j++) worst = fmax(worst, fabs(xy[j] - g0[j]));
        CHECK_MSG(worst < 1e-9, "%s: t = 1e-12 is %g away from geometry 0", name, worst);
    }
    free(xy);
    cm_morph_free(m);
    cm_result_free(r);
}

/* The enclosed mesh itself: the result first and unchanged, the enclosure
 * the same strictly convex polygon in every geometry, every triangle
 * counter-clockwise in every geometry. */
static void test_enclosure(fixture_kind kind)
{
    cm_result *r = fixture_result(kind, N);
    if (!r) {
        CHECK(0);
        return;
    }
    cm_mesh full;
    unsigned char *boundary = NULL;
    cm_error err;
    cm_error_init(&err);
    cm_status s = cm_enclosure_build(r, NULL, &full, &boundary, &err);
    CHECK_MSG(s == CM_OK, "%s: %s", fixture_name(kind), err.message);
    if (s == CM_OK) {
        size_t nv = cm_result_num_vertices(r), bad = 0, ne = 0;
        for (size_t g = 0; g < full.k; g++) {
            CHECK(memcmp(full.xy[g], cm_result_vertices(r, g), 2 * nv * sizeof(double)) == 0);
            for (size_t t = 0; t < full.nt; t++)
                bad += cm_orient2d(full.xy[g] + 2 * (size_t)full.tri[3 * t], full.xy[g] + 2 * (size_t)full.tri[3 * t + 1],
                                   full.xy[g] + 2 * (size_t)full.tri[3 * t + 2]) <= 0;
        }
        CHECK_MSG(bad == 0, "%s: %zu inverted triangles in the enclosed mesh", fixture_name(kind), bad);
        for (size_t v = 0; v < full.nv; v++) {
            if (!boundary[v]) continue;
            ne++;
            CHECK(v >= nv);
            for (size_t g = 1; g < full.k; g++)
                CHECK(memcmp(full.xy[g] + 2 * v, full.xy[0] + 2 * v, 2 * sizeof(double)) == 0);
        }
        /* Enclosure vertices are consecutive, counter-clockwise. */
        for (size_t i = 0; i < ne; i++)
            CHECK(cm_orient2d(full.xy[0] + 2 * (nv + i), full.xy[0] + 2 * (nv + (i + 1) % ne),
                              full.xy[0] + 2 * (nv + (i + 2) % ne)) > 0);
        CHECK(full.nt == 2 * full.nv - ne - 2);
        printf("%s: enclosed mesh %zu vertices (%zu enclosure), %zu triangles\n", fixture_name(kind), full.nv, ne,
               full.nt);
    }
    cm_mesh_clear(&full);
    free(boundary);
    cm_result_free(r);
}

static void test_linear(void)
{
    cm_result *r = fixture_result(FIX_TWISTED, N);
    if (!r) {
        CHECK(0);
        return;
    }
    cm_morph_options o;
    cm_morph_options_init(&o);
    o.method = CM_MORPH_LINEAR;
    cm_morph *m = NULL;
    CHECK(cm_morph_create(r, &o, &m) == CM_OK);
    size_t nv = cm_result_num_vertices(r), inverted = 0;
    double *xy = malloc(2 * nv * sizeof *xy);
    CHECK(cm_morph_section(m, 0.5, xy, &inverted, NULL) == CM_OK);
    CHECK_MSG(inverted > 0 && inverted == exact_inverted(r, xy), "linear: %zu inverted", inverted);
    printf("linear morph of the twisted pair: %zu of %zu triangles inverted at t = 0.5\n", inverted,
           cm_result_num_triangles(r));
    CHECK(cm_morph_section(m, 0.0, xy, &inverted, NULL) == CM_OK && inverted == 0);
    free(xy);
    cm_morph_free(m);
    cm_result_free(r);
}

/* Property test: random pairs (random simple polygons, twisted stars,
 * a spiral against a star, a comb against a random polygon), with and
 * without remeshing, weights interpolated and intrinsic in turn: the morph
 * builds, interior frames are valid, and the blend-only sweep succeeds. Trial 42 (spiral against star, no remeshing)
 * has an annulus angle within rounding of pi, where the textbook
 * tan(a / 2) = sin a / (1 + cos a) cancels to a negative weight. */
static int random_pair(int trial, double **xy, int *n)
{
    int kind = trial % 4;
    *n = kind == 2 ? rp_spiral_min_n(2.5) + trial : 20 + (trial * 37) % 180;
    if (!(*xy = calloc(4 * (size_t)*n, sizeof **xy))) return -1;
    double *a = *xy, *b = *xy + 2 * *n;
    switch (kind) {
    case 0: return rp_random_simple(a, *n, (uint64_t)trial) || rp_random_simple(b, *n, (uint64_t)trial + 100) ? -1 : 0;
    case 1:
        if (rp_star(a, *n, (uint64_t)trial)) return -1;
        memcpy(b, a, 2 * (size_t)*n * sizeof *a);
        rp_twist(b, *n, *n / 2);
        return 0;
    case 2: return rp_spiral(a, *n, 2.5) || rp_star(b, *n, (uint64_t)trial) ? -1 : 0;
    default: return rp_comb(a, *n, *n / 10) || rp_random_simple(b, *n, (uint64_t)trial) ? -1 : 0;
    }
}

static void test_random_pairs(void)
{
    static const int trials[] = {0, 1, 2, 3, 5, 6, 8, 11, 13, 18, 22, 27, 40, 42, 50, 54};
    size_t built = 0, count = sizeof trials / sizeof *trials;
    for (size_t i = 0; i < count; i++) {
        int trial = trials[i], n = 0;
        double *xy = NULL;
        if (random_pair(trial, &xy, &n)) {
            CHECK_MSG(0, "trial %d: no polygons", trial);
            free(xy);
            continue;
        }
        cm_options o;
        cm_options_init(&o);
        o.remesh = trial % 2;
        cm_result *r = NULL;
        cm_morph *m = NULL;
        cm_sweep *w = NULL;
        CHECK_MSG(cm_triangulate(xy, 2, (size_t)n, &o, &r) == CM_OK, "trial %d: %s", trial, cm_result_message(r));
        cm_morph_options mo;
        cm_morph_options_init(&mo);
        mo.method = i % 2 ? CM_MORPH_INTRINSIC : CM_MORPH_CONVEX;
        cm_status s = cm_morph_create(r, &mo, &m);
        CHECK_MSG(s == CM_OK, "trial %d (n = %d): %s", trial, n, cm_morph_message(m));
        if (s == CM_OK) {
            size_t nv = cm_result_num_vertices(r), good = 0;
            double *p = malloc(2 * nv * sizeof *p);
            for (int f = 1; f < 10; f++) {
                size_t inverted = 1;
                good += cm_morph_section(m, f / 10.0, p, &inverted, NULL) == CM_OK && inverted == 0 &&
                        exact_inverted(r, p) == 0;
            }
            CHECK_MSG(good == 9, "trial %d: %zu of 9 frames valid", trial, good);
            CHECK_MSG(cm_sweep_create(m, NULL, &w) == CM_OK, "trial %d: %s", trial, cm_sweep_message(w));
            built += good == 9;
            free(p);
        }
        cm_sweep_free(w);
        cm_morph_free(m);
        cm_result_free(r);
        free(xy);
    }
    printf("random pairs: %zu of %zu morphs valid in every frame\n", built, count);
}

/* Clockwise input: the result keeps the input's vertex order, the
 * enclosure walks the boundary the other way round. */
static void test_clockwise(void)
{
    double xy[6 * N];
    size_t k;
    cm_result *r = NULL;
    cm_morph *m = NULL;
    CHECK(fixture_polygons(FIX_GLYPH, N, xy, &k) == 0);
    for (size_t g = 0; g < k; g++) rp_reverse(xy + 2 * N * g, 1, N - 1);
    CHECK(cm_triangulate(xy, k, N, NULL, &r) == CM_OK && cm_result_stats(r)->reversed_input == 1);
    CHECK_MSG(cm_morph_create(r, NULL, &m) == CM_OK, "clockwise: %s", cm_morph_message(m));
    size_t nv = cm_result_num_vertices(r), inverted = 1;
    double *p = malloc(2 * nv * sizeof *p);
    CHECK(cm_morph_section(m, 0.5, p, &inverted, NULL) == CM_OK && inverted == 0 && exact_inverted(r, p) == 0);
    CHECK(cm_morph_section(m, 0.0, p, NULL, NULL) == CM_OK && memcmp(p, xy, 2 * N * sizeof *p) == 0);
    free(p);
    cm_morph_free(m);
    cm_result_free(r);
}

/* The same compatible pair with its second geometry moved far away
 * (about 1,000 times its size): the morph runs about each geometry's
 * centre, so every section is the unmoved pair's section moved by t times
 * the offset, to within rounding, whatever the method. */
static void test_translation(void)
{
    cm_result *r = fixture_result(FIX_GLYPH, N), *far = NULL;
    CHECK(r != NULL);
    if (!r) return;
    size_t nv = cm_result_num_vertices(r);
    double *moved = malloc(2 * nv * sizeof *moved), *p = malloc(2 * nv * sizeof *p), *q = malloc(2 * nv * sizeof *q);
    for (size_t i = 0; moved && i < nv; i++)
        moved[2 * i] = cm_result_vertices(r, 1)[2 * i] + 4000.0, moved[2 * i + 1] = cm_result_vertices(r, 1)[2 * i + 1] - 3000.0;
    const double *geoms[2] = {cm_result_vertices(r, 0), moved};
    CHECK(moved && p && q &&
          cm_result_from_meshes(geoms, 2, N, nv, cm_result_triangles(r), cm_result_num_triangles(r), &far) == CM_OK);
    for (int method = CM_MORPH_CONVEX; method <= CM_MORPH_INTRINSIC && p && q && moved; method++) {
        cm_morph_options mo;
        cm_morph_options_init(&mo);
        mo.method = (cm_morph_method)method;
        cm_morph *m = NULL, *mf = NULL;
        CHECK(cm_morph_create(r, &mo, &m) == CM_OK && cm_morph_create(far, &mo, &mf) == CM_OK);
        for (int j = 1; j < 10; j++) {
            double t = j / 10.0, worst = 0;
            CHECK(cm_morph_section(m, t, p, NULL, NULL) == CM_OK && cm_morph_section(mf, t, q, NULL, NULL) == CM_OK);
            for (size_t v = 0; v < nv; v++)
                worst = fmax(worst, hypot(q[2 * v] - p[2 * v] - 4000.0 * t, q[2 * v + 1] - p[2 * v + 1] + 3000.0 * t));
            CHECK_MSG(worst < 1e-9, "translation, method %d, t = %g: a vertex is %g off", method, t, worst);
        }
        cm_morph_free(m), cm_morph_free(mf);
    }
    free(moved), free(p), free(q);
    cm_result_free(r), cm_result_free(far);
}

/* Progress: fractions rise within [0, 1]; cancelling half-way leaves a
 * handle that refuses sections. */
typedef struct progress_log {
    double last;
    int calls, backwards, cancel_above_half;
} progress_log;

static int log_progress(void *user, double fraction, const char *stage)
{
    progress_log *log = user;
    log->backwards += fraction < log->last || fraction > 1.0 || !stage;
    log->last = fraction;
    log->calls++;
    return log->cancel_above_half && fraction > 0.5;
}

static void test_progress(void)
{
    cm_result *r = fixture_result(FIX_TWISTED, N);
    cm_morph_options o;
    cm_morph_options_init(&o);
    progress_log log = {0};
    o.progress = log_progress, o.progress_user = &log;
    cm_morph *m = NULL;
    CHECK(cm_morph_create(r, &o, &m) == CM_OK);
    CHECK_MSG(log.calls >= 3 && log.backwards == 0 && log.last == 1.0, "%d calls, %d out of order", log.calls,
              log.backwards);
    cm_morph_free(m);
    progress_log stop = {.cancel_above_half = 1};
    o.progress_user = &stop;
    CHECK(cm_morph_create(r, &o, &m) == CM_ERR_CANCELLED);
    double *p = malloc(2 * cm_result_num_vertices(r) * sizeof *p);
    CHECK(cm_morph_section(m, 0.5, p, NULL, NULL) == CM_ERR_ARGUMENT);
    free(p);
    cm_morph_free(m);
    cm_result_free(r);
}

static int cancel_now(void *user, double fraction, const char *stage)
{
    (void)user, (void)fraction, (void)stage;
    return 1;
}

static void test_bad_arguments(void)
{
    cm_morph *m = NULL;
    CHECK(cm_morph_create(NULL, NULL, &m) == CM_ERR_ARGUMENT && strstr(cm_morph_message(m), "result"));
    cm_morph_free(m);
    CHECK(cm_morph_create(NULL, NULL, NULL) == CM_ERR_ARGUMENT);

    double tiny[8] = {0, 0, 1, 0, 0, 0, 1, 0};
    cm_result *bad = NULL;
    cm_triangulate(tiny, 2, 2, NULL, &bad); /* fails: 2 vertices */
    CHECK(cm_morph_create(bad, NULL, &m) == CM_ERR_ARGUMENT && strstr(cm_morph_message(m), "failed"));
    double xy[8];
    CHECK(cm_morph_section(m, 0.5, xy, NULL, NULL) == CM_ERR_ARGUMENT);
    cm_morph_free(m);
    cm_result_free(bad);

    cm_result *r = fixture_result(FIX_GLYPH, N);
    cm_morph_options o;
    cm_morph_options_init(&o);
    o.method = (cm_morph_method)7;
    CHECK(cm_morph_create(r, &o, &m) == CM_ERR_ARGUMENT && strstr(cm_morph_message(m), "method"));
    cm_morph_free(m);
    cm_morph_options_init(&o);
    o.progress = cancel_now;
    CHECK(cm_morph_create(r, &o, &m) == CM_ERR_CANCELLED);
    cm_morph_free(m);

    CHECK(cm_morph_create(r, NULL, &m) == CM_OK);
    double *out = malloc(2 * cm_result_num_vertices(r) * sizeof *out);
    CHECK(cm_morph_section(m, 1.5, out, NULL, NULL) == CM_ERR_ARGUMENT && strstr(cm_morph_message(m), "outside"));
    CHECK(cm_morph_section(m, NAN, out, NULL, NULL) == CM_ERR_ARGUMENT);
    CHECK(cm_morph_section(m, 0.5, NULL, NULL, NULL) == CM_ERR_ARGUMENT && strstr(cm_morph_message(m), "xy"));
    CHECK(cm_morph_section(m, 0.5, out, NULL, NULL) == CM_OK && cm_morph_message(m)[0] == '\0');
    free(out);
    cm_morph_free(m);
    cm_result_free(r);
    cm_morph_free(NULL);
    CHECK(cm_morph_message(NULL) != NULL);
}

int main(void)
{
    for (size_t i = 0; i < sizeof fixtures / sizeof *fixtures; i++) test_frames(&fixtures[i]);
    test_enclosure(FIX_TWISTED);
    test_enclosure(FIX_SPIRAL);
    test_enclosure(FIX_THREE);
    test_linear();
    test_random_pairs();
    test_clockwise();
    test_translation();
    test_progress();
    test_bad_arguments();
    return check_summary("test_morph");
}
