/* cm_check_geometry: the exact re-check of a result whose coordinates were
 * rounded or moved. Each case states the status it expects and where. */
#include "check.h"
#include "compatmesh/compatmesh.h"

#include <float.h>
#include <string.h>

/* A unit square split by the diagonal 0-2, plus a centre vertex 4 fanned. */
static const int32_t fan[] = {0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4};

static cm_status check(const double *xy, size_t nv, const int32_t *tri, size_t nt, long *w, long *o)
{
    return cm_check_geometry(xy, 4, nv, tri, nt, w, o);
}

int main(void)
{
    long w, o;
    double square[] = {0, 0, 1, 0, 1, 1, 0, 1, 0.5, 0.5};
    CHECK(check(square, 5, fan, 4, &w, &o) == CM_OK && w == -1 && o == -1);

    /* The centre moved onto edge 1-2: triangle 1 (1, 2, 4) is flat. */
    double flat[10];
    memcpy(flat, square, sizeof flat);
    flat[8] = 1.0;
    CHECK(check(flat, 5, fan, 4, &w, &o) == CM_ERR_ZERO_AREA && w == 1);

    /* The centre moved outside: triangle 1 is clockwise. */
    flat[8] = 1.0 + DBL_EPSILON;
    CHECK(check(flat, 5, fan, 4, &w, &o) == CM_ERR_ZERO_AREA && w == 1);

    /* The smallest possible move inside keeps it valid (exact, not a tolerance). */
    flat[8] = 1.0 - DBL_EPSILON / 2;
    CHECK(check(flat, 5, fan, 4, &w, &o) == CM_OK);

    /* Two boundary vertices rounded onto each other: a triangle between
     * them is flat first, so a triangle list without that triangle shows
     * the repeated-vertex report. */
    double twice[] = {0, 0, 1, 0, 1, 1, 1, 1, 0.5, 0.5};
    const int32_t some[] = {0, 1, 4};
    CHECK(check(twice, 5, some, 1, &w, &o) == CM_ERR_REPEATED_VERTEX && w == 2 && o == 3);

    /* A boundary that crosses itself while the listed triangles stay
     * counter-clockwise: edges 1 and 3 of the bow-tie cross. */
    double bowtie[] = {0, 0, 1, 1, 1, 0, 0, 1, 0.5, -1};
    const int32_t below[] = {0, 4, 2};
    CHECK(check(bowtie, 5, below, 1, &w, &o) == CM_ERR_SELF_INTERSECTION && w == 0 && o == 2);

    /* Bad arguments. */
    const int32_t out_of_range[] = {0, 1, 7};
    CHECK(check(square, 5, out_of_range, 1, &w, &o) == CM_ERR_ARGUMENT && w == 0);
    CHECK(cm_check_geometry(square, 2, 5, fan, 4, NULL, NULL) == CM_ERR_ARGUMENT);
    CHECK(cm_check_geometry(NULL, 4, 5, fan, 4, NULL, NULL) == CM_ERR_ARGUMENT);
    double nan_xy[10];
    memcpy(nan_xy, square, sizeof nan_xy);
    nan_xy[9] = 0.0 / 0.0;
    CHECK(check(nan_xy, 5, fan, 4, &w, &o) == CM_ERR_NOT_FINITE && w == 4);

    /* A real result, every geometry rounded to float, checked again. */
    const double xy[] = {0, 0, 4, 0, 4, 3, 2, 1, 0, 3, /* */ 0, 0, 4, 0, 4, 3, 2, 2.5, 0, 3};
    cm_result *r = NULL;
    CHECK(cm_triangulate(xy, 2, 5, NULL, &r) == CM_OK);
    for (size_t g = 0; g < 2; g++) {
        const double *v = cm_result_vertices(r, g);
        size_t nv = cm_result_num_vertices(r);
        double rounded[2 * 64];
        CHECK(nv <= 64);
        for (size_t i = 0; i < 2 * nv && i < 128; i++) rounded[i] = (float)v[i];
        CHECK(cm_check_geometry(rounded, 5, nv, cm_result_triangles(r), cm_result_num_triangles(r),
                                NULL, NULL) == CM_OK);
    }
    cm_result_free(r);

    /* cm_check_tetrahedra: a positive tetrahedron and an inverted one (and
     * swapped into a positive one), one whose apex is the smallest double
     * above its base's plane (positive, exactly) and then on it (flat), a
     * NaN node, an index out of range. */
    double nodes[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1};
    int32_t tets[] = {0, 1, 2, 3, 2, 1, 3, 4};
    long where = -2;
    CHECK(cm_check_tetrahedra(nodes, 5, tets, 1, &where) == CM_OK && where == -1);
    CHECK(cm_check_tetrahedra(nodes, 5, tets, 2, &where) == CM_ERR_ZERO_AREA && where == 1); /* 2 1 3 4: inverted */
    int32_t swapped[] = {0, 1, 2, 3, 1, 2, 3, 4};
    CHECK(cm_check_tetrahedra(nodes, 5, swapped, 2, &where) == CM_OK);
    double lifted[15];
    memcpy(lifted, nodes, sizeof lifted);
    lifted[11] = 0x1p-1074; /* node 3 just above the plane z = 0: positive, exactly */
    CHECK(cm_check_tetrahedra(lifted, 5, tets, 1, &where) == CM_OK);
    lifted[11] = 0;
    CHECK(cm_check_tetrahedra(lifted, 5, tets, 1, &where) == CM_ERR_ZERO_AREA && where == 0);
    lifted[11] = 0.0 / 0.0;
    CHECK(cm_check_tetrahedra(lifted, 5, tets, 1, &where) == CM_ERR_NOT_FINITE && where == 3);
    int32_t outside[] = {0, 1, 2, 5};
    CHECK(cm_check_tetrahedra(nodes, 5, outside, 1, &where) == CM_ERR_ARGUMENT && where == 0);
    return check_summary("test_check_geometry");
}
