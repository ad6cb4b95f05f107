/* Every bad-input class: its own status, a message naming the polygon and
 * vertex, the error location, and no geometry on the failed result. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "compatmesh/compatmesh.h"

static void expect(const char *name, const double *const *polys, const size_t *counts,
                   size_t k, cm_status want, const char *fragment, long polygon, long vertex)
{
    cm_result *r = NULL;
    cm_status s = cm_triangulate_polygons(polys, counts, k, NULL, &r);
    CHECK_MSG(s == want, "%s: got %s (%s), want %s", name, cm_status_string(s),
              cm_result_message(r), cm_status_string(want));
    CHECK_MSG(r && cm_result_status(r) == s, "%s: handle carries the status", name);
    CHECK_MSG(r && strstr(cm_result_message(r), fragment), "%s: message '%s' lacks '%s'", name,
              cm_result_message(r), fragment);
    long p = -2, v = -2;
    cm_result_error_location(r, &p, &v, NULL);
    CHECK_MSG(p == polygon && v == vertex, "%s: location (%ld, %ld), want (%ld, %ld)", name, p, v,
              polygon, vertex);
    CHECK_MSG(cm_result_num_triangles(r) == 0 && cm_result_triangles(r) == NULL &&
                  cm_result_vertices(r, 0) == NULL,
              "%s: a failed result exposes no geometry", name);
    cm_result_free(r);
}

static const double square[] = {0, 0, 1, 0, 1, 1, 0, 1};

static void test_counts(void)
{
    const double two[] = {0, 0, 1, 0};
    const double *p2[] = {two, two};
    expect("two vertices", p2, (size_t[]){2, 2}, 2, CM_ERR_TOO_FEW_VERTICES, "at least 3", 0, -1);
    const double *one[] = {square};
    expect("one polygon", one, (size_t[]){4}, 1, CM_ERR_ARGUMENT, "at least 2 polygons", -1, -1);
    const double tri[] = {0, 0, 1, 0, 0, 1};
    const double *mixed[] = {square, tri};
    expect("mismatched counts", mixed, (size_t[]){4, 3}, 2, CM_ERR_COUNT_MISMATCH,
           "polygon 1 has 3 vertices but polygon 0 has 4", 1, -1);
    expect("null polygons", NULL, NULL, 2, CM_ERR_ARGUMENT, "no polygons", -1, -1);
}

static void test_coordinates(void)
{
    double bad[] = {0, 0, 1, 0, 1, NAN, 0, 1};
    const double *p[] = {square, bad};
    expect("NaN", p, (size_t[]){4, 4}, 2, CM_ERR_NOT_FINITE, "polygon 1: vertex 2", 1, 2);
    bad[5] = INFINITY;
    expect("Inf", p, (size_t[]){4, 4}, 2, CM_ERR_NOT_FINITE, "not finite", 1, 2);
    double rep[] = {0, 0, 1, 0, 1, 1, 1, 0};
    const double *q[] = {rep, square};
    expect("repeated vertex", q, (size_t[]){4, 4}, 2, CM_ERR_REPEATED_VERTEX,
           "polygon 0: vertex 3 repeats vertex 1", 0, 3);
    double ring[] = {0, 0, 1, 0, 1, 1, 0, 1, 0, 0}; /* closed as GIS formats write rings */
    const double *rings[] = {ring, ring};
    expect("closed ring", rings, (size_t[]){5, 5}, 2, CM_ERR_REPEATED_VERTEX,
           "polygon 0: vertex 4 repeats vertex 0 (0, 0) (a closed ring: give each vertex once", 0, 4);
}

static void test_shapes(void)
{
    const double bowtie[] = {0, 0, 1, 1, 1, 0, 0, 1};
    const double *p[] = {square, bowtie};
    expect("bow-tie", p, (size_t[]){4, 4}, 2, CM_ERR_SELF_INTERSECTION, "cross or touch", 1, 0);
    /* Vertex 4 touches edge 1-2 from inside: a pinched, not simple, polygon. */
    const double touch[] = {0, 0, 2, 0, 2, 2, 1, 2, 2, 1, 0, 2};
    const double sq6[] = {0, 0, 1, 0, 2, 0, 2, 2, 1, 2, 0, 2};
    const double *t[] = {sq6, touch};
    cm_result *r = NULL;
    CHECK(cm_triangulate_polygons(t, (size_t[]){6, 6}, 2, NULL, &r) == CM_ERR_SELF_INTERSECTION);
    cm_result_free(r);
    const double flat[] = {0, 0, 1, 0, 2, 0, 3, 0};
    const double *f[] = {square, flat};
    expect("zero area", f, (size_t[]){4, 4}, 2, CM_ERR_ZERO_AREA, "polygon 1 has zero area", 1, -1);
    const double cw[] = {0, 0, 0, 1, 1, 1, 1, 0};
    const double *o[] = {square, cw};
    expect("mixed orientation", o, (size_t[]){4, 4}, 2, CM_ERR_ORIENTATION_MISMATCH,
           "polygon 1 is clockwise but polygon 0 is counter-clockwise", 1, -1);
}

static void test_legal_edge_cases(void)
{
    /* 180-degree corners, huge and tiny scales, offsets: all legal. */
    const double run[] = {0, 0, 1, 0, 2, 0, 3, 0, 3, 1, 0, 1};
    const double other[] = {0, 0, 1, -1, 2, -1, 3, 0, 3, 2, 0, 2};
    const double *p[] = {run, other};
    cm_result *r = NULL;
    CHECK(cm_triangulate_polygons(p, (size_t[]){6, 6}, 2, NULL, &r) == CM_OK);
    cm_result_free(r);
    double huge[8], tiny[8], offset[8];
    for (int i = 0; i < 8; i++) {
        huge[i] = square[i] * 1e300;
        tiny[i] = square[i] * 1e-300;
        offset[i] = square[i] * 1e-3 + 1e6;
    }
    const double *q[] = {huge, tiny, offset};
    CHECK(cm_triangulate_polygons(q, (size_t[]){4, 4, 4}, 3, NULL, &r) == CM_OK);
    cm_result_free(r);
}

static int cancel_at_check(void *user, double fraction, const char *stage)
{
    (*(int *)user)++;
    return strcmp(stage, "check") == 0;
}

static void test_cancel(void)
{
    const double *p[] = {square, square};
    cm_options o;
    cm_options_init(&o);
    int calls = 0;
    o.progress = cancel_at_check;
    o.progress_user = &calls;
    cm_result *r = NULL;
    CHECK(cm_triangulate_polygons(p, (size_t[]){4, 4}, 2, &o, &r) == CM_ERR_CANCELLED);
    CHECK(calls >= 2);
    CHECK(cm_result_num_triangles(r) == 0);
    cm_result_free(r);
    cm_result_free(NULL); /* a no-op */
}

int main(void)
{
    test_counts();
    test_coordinates();
    test_shapes();
    test_legal_edge_cases();
    test_cancel();
    return check_summary("test_input");
}
