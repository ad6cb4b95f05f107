/* cm_result_from_meshes: a triangulation rebuilt from cm_triangulate's own
 * arrays is the same result (half-edges, stats, quality) and morphs to the
 * same sections; clockwise input is accepted consistently; bad inputs fail
 * with a status and a message naming the geometry, triangle or vertex. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "morph_fixtures.h"

#define N 40
#define FRAMES 7

static int same_ints(const int32_t *a, const int32_t *b, size_t count)
{
    return a && b && memcmp(a, b, count * sizeof *a) == 0;
}

static void test_round_trip(void)
{
    cm_result *r = fixture_result(FIX_TWISTED, N);
    CHECK(r != NULL);
    if (!r) return;
    size_t k = cm_result_num_geometries(r), nv = cm_result_num_vertices(r), nt = cm_result_num_triangles(r);
    const double *xy[2] = {cm_result_vertices(r, 0), cm_result_vertices(r, 1)};
    cm_result *back = NULL;
    cm_status s = cm_result_from_meshes(xy, k, N, nv, cm_result_triangles(r), nt, &back);
    CHECK_MSG(s == CM_OK, "round trip: %s", cm_result_message(back));
    CHECK(cm_result_num_vertices(back) == nv && cm_result_num_triangles(back) == nt);
    CHECK(cm_result_num_halfedges(back) == cm_result_num_halfedges(r));
    size_t nh = cm_result_num_halfedges(r);
    CHECK(same_ints(cm_result_halfedge_next(back), cm_result_halfedge_next(r), nh));
    CHECK(same_ints(cm_result_halfedge_to_vertex(back), cm_result_halfedge_to_vertex(r), nh));
    CHECK(same_ints(cm_result_halfedge_face(back), cm_result_halfedge_face(r), nh));
    CHECK(same_ints(cm_result_vertex_halfedge(back), cm_result_vertex_halfedge(r), nv));
    CHECK(same_ints(cm_result_face_halfedge(back), cm_result_face_halfedge(r), nt));
    const cm_stats *a = cm_result_stats(r), *b = cm_result_stats(back);
    CHECK(b->n == N && b->k == k && b->vertices == a->vertices && b->steiner == a->steiner &&
          b->triangles == a->triangles && !b->reversed_input);
    for (size_t g = 0; g < k; g++) {
        cm_quality qa, qb, qbb;
        cm_result_quality(r, g, &qa);
        CHECK(cm_result_quality(back, g, &qb) == CM_OK);
        CHECK(cm_result_quality_before(back, g, &qbb) == CM_OK);
        CHECK(qa.min_angle_deg == qb.min_angle_deg && qb.min_angle_deg == qbb.min_angle_deg);
    }
    /* The rebuilt result morphs exactly like the original. */
    cm_morph *m0 = NULL, *m1 = NULL;
    CHECK(cm_morph_create(r, NULL, &m0) == CM_OK);
    CHECK_MSG(cm_morph_create(back, NULL, &m1) == CM_OK, "%s", cm_morph_message(m1));
    double *x0 = malloc(2 * nv * sizeof *x0), *x1 = malloc(2 * nv * sizeof *x1);
    double lowest = 90;
    for (int f = 0; f < FRAMES; f++) {
        double t = (double)f / (FRAMES - 1), angle = 0;
        size_t bad0 = 1, bad1 = 1;
        CHECK(cm_morph_section(m0, t, x0, &bad0, NULL) == CM_OK);
        CHECK(cm_morph_section(m1, t, x1, &bad1, &angle) == CM_OK);
        CHECK(bad0 == 0 && bad1 == 0);
        CHECK_MSG(memcmp(x0, x1, 2 * nv * sizeof *x0) == 0, "frame %d differs", f);
        lowest = fmin(lowest, angle);
    }
    CHECK_MSG(lowest > 1.0, "smallest section angle %g", lowest);
    printf("round trip: %zu vertices, %zu triangles, smallest section angle %.2f deg\n", nv, nt, lowest);
    free(x0), free(x1);
    cm_morph_free(m0), cm_morph_free(m1);

    /* The mirror image (x negated): boundary and triangles clockwise in
     * every geometry. Accepted, stored counter-clockwise (two corners
     * swapped), vertex numbering unchanged. */
    double *mirror[2];
    for (size_t g = 0; g < 2; g++) {
        mirror[g] = malloc(2 * nv * sizeof *mirror[g]);
        for (size_t v = 0; v < nv; v++) mirror[g][2 * v] = -xy[g][2 * v], mirror[g][2 * v + 1] = xy[g][2 * v + 1];
    }
    const int32_t *tri = cm_result_triangles(r);
    cm_result *rev = NULL;
    s = cm_result_from_meshes((const double *const *)mirror, k, N, nv, tri, nt, &rev);
    CHECK_MSG(s == CM_OK, "clockwise input: %s", cm_result_message(rev));
    CHECK(cm_result_stats(rev)->reversed_input == 1);
    const int32_t *stored = cm_result_triangles(rev);
    int swapped = stored != NULL;
    for (size_t t = 0; swapped && t < nt; t++)
        swapped = stored[3 * t] == tri[3 * t] && stored[3 * t + 1] == tri[3 * t + 2] &&
                  stored[3 * t + 2] == tri[3 * t + 1];
    CHECK(swapped);
    CHECK(cm_result_num_halfedges(rev) == nh);
    /* A clockwise mesh whose second geometry is counter-clockwise: mixed. */
    const double *mixed[2] = {mirror[0], xy[1]};
    cm_result *bad = NULL;
    CHECK(cm_result_from_meshes(mixed, k, N, nv, tri, nt, &bad) == CM_ERR_ZERO_AREA);
    CHECK_MSG(strstr(cm_result_message(bad), "geometry 1: triangle 0 ") != NULL &&
              strstr(cm_result_message(bad), "flat or counter-clockwise") != NULL, "%s", cm_result_message(bad));
    cm_result_free(bad);
    free(mirror[0]), free(mirror[1]);
    cm_result_free(rev), cm_result_free(back), cm_result_free(r);
}

/* A square (0..3) with a centre vertex 4 and four triangles. */
static double square0[] = {0, 0, 2, 0, 2, 2, 0, 2, 1, 1};
static double square1[] = {0, 0, 4, 0, 4, 2, 0, 2, 3, 1};
static const int32_t fan[] = {0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4};

static void expect_failure(const char *what, const double *g1, const int32_t *tri, size_t nt,
                           size_t n, cm_status want, const char *in_message)
{
    const double *xy[2] = {square0, g1};
    cm_result *r = NULL;
    cm_status s = cm_result_from_meshes(xy, 2, n, 5, tri, nt, &r);
    const char *msg = cm_result_message(r);
    CHECK_MSG(s == want && cm_result_status(r) == want, "%s: status %s, want %s (%s)", what,
              cm_status_string(s), cm_status_string(want), msg);
    CHECK_MSG(strstr(msg, in_message) != NULL, "%s: message '%s' lacks '%s'", what, msg, in_message);
    CHECK(cm_result_num_vertices(r) == 0 && cm_result_triangles(r) == NULL);
    cm_result_free(r);
}

static void test_bad_input(void)
{
    const double *xy[2] = {square0, square1};
    cm_result *r = NULL;
    CHECK(cm_result_from_meshes(xy, 2, 4, 5, fan, 4, &r) == CM_OK);
    cm_result_free(r);

    /* Centre moved past the right edge in geometry 1: triangle 1 clockwise. */
    double outside[] = {0, 0, 4, 0, 4, 2, 0, 2, 5, 1};
    expect_failure("clockwise in one geometry", outside, fan, 4, 4, CM_ERR_ZERO_AREA,
                   "geometry 1: triangle 1 (1 2 4) is flat or clockwise");
    /* Triangle 0 given twice: three triangles on edge 0-4 (and 0-1). */
    int32_t twice[15];
    memcpy(twice, fan, sizeof fan);
    memcpy(twice + 12, fan, 3 * sizeof *fan);
    expect_failure("non-manifold", square1, twice, 5, 4, CM_ERR_ARGUMENT,
                   "not a compatible triangulation: at edge 0-1");
    /* Boundary declared as the triangle 0 1 2: vertex 3 is on the boundary. */
    expect_failure("boundary not the polygon", square1, fan, 4, 3, CM_ERR_ARGUMENT,
                   "not a compatible triangulation");
    /* Index 5 with 5 vertices. */
    int32_t out[12];
    memcpy(out, fan, sizeof fan);
    out[7] = 5;
    expect_failure("index out of range", square1, out, 4, 4, CM_ERR_ARGUMENT,
                   "triangle 2: vertex index 5 out of range");
    /* Fewer than two geometries, NULL triangles. */
    CHECK(cm_result_from_meshes(xy, 1, 4, 5, fan, 4, &r) == CM_ERR_ARGUMENT);
    CHECK(strstr(cm_result_message(r), "at least 2 geometries") != NULL);
    cm_result_free(r);
    CHECK(cm_result_from_meshes(xy, 2, 4, 5, NULL, 4, &r) == CM_ERR_ARGUMENT);
    cm_result_free(r);
    CHECK(cm_result_from_meshes(xy, 2, 4, 5, fan, 4, NULL) == CM_ERR_ARGUMENT);
}

/* The statistics do not depend on the scale: the same meshes scaled by
 * 1e300 and by 1e-300 report the same angles (they used to read 180 and 0
 * degrees, squared lengths overflowing and underflowing). */
static void test_statistics_are_scale_free(void)
{
    cm_result *r = fixture_result(FIX_TWISTED, N);
    CHECK(r != NULL);
    if (!r) return;
    size_t k = cm_result_num_geometries(r), nv = cm_result_num_vertices(r), nt = cm_result_num_triangles(r);
    const double scales[] = {1e300, 1e-300};
    for (size_t i = 0; i < sizeof scales / sizeof scales[0]; i++) {
        double *xy[2] = {malloc(2 * nv * sizeof(double)), malloc(2 * nv * sizeof(double))};
        for (size_t g = 0; g < k; g++)
            for (size_t j = 0; j < 2 * nv; j++) xy[g][j] = cm_result_vertices(r, g)[j] * scales[i];
        cm_result *scaled = NULL;
        cm_status s = cm_result_from_meshes((const double *const *)xy, k, N, nv, cm_result_triangles(r), nt, &scaled);
        CHECK_MSG(s == CM_OK, "scale %g: %s", scales[i], cm_result_message(scaled));
        for (size_t g = 0; s == CM_OK && g < k; g++) {
            cm_quality want, got;
            CHECK(cm_result_quality(r, g, &want) == CM_OK && cm_result_quality(scaled, g, &got) == CM_OK);
            CHECK_MSG(fabs(want.min_angle_deg - got.min_angle_deg) < 1e-9 &&
                          fabs(want.max_angle_deg - got.max_angle_deg) < 1e-9 &&
                          want.pct_below_20deg == got.pct_below_20deg,
                      "scale %g, geometry %zu: smallest angle %.12g (at scale 1: %.12g), largest %.12g (%.12g)",
                      scales[i], g, got.min_angle_deg, want.min_angle_deg, got.max_angle_deg, want.max_angle_deg);
        }
        cm_result_free(scaled);
        free(xy[0]), free(xy[1]);
    }
    cm_result_free(r);
}

int main(void)
{
    test_round_trip();
    test_statistics_are_scale_free();
    test_bad_input();
    return check_summary("test_from_meshes");
}
