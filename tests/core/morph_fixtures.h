/* Polygon pairs for the morph and sweep tests: each fixture is k polygons
 * of n vertices, compatibly triangulated with the library's defaults. */
#ifndef CM_TEST_MORPH_FIXTURES_H
#define CM_TEST_MORPH_FIXTURES_H

#include <stdlib.h>

#include "compatmesh/compatmesh.h"
#include "random_polygons.h"

typedef enum fixture_kind {
    FIX_TWISTED, /* a star and the same star with its correspondence turned
                    by a third: straight-line paths pass through the middle */
    FIX_SPIRAL,  /* a two-turn spiral band to a disc */
    FIX_GLYPH,   /* a comb (glyph-like: thin teeth) to a star */
    FIX_THREE    /* disc, star, comb: a piecewise morph through k = 3 */
} fixture_kind;

static const char *fixture_name(fixture_kind kind)
{
    static const char *names[] = {"twisted", "spiral", "glyph", "three"};
    return names[kind];
}

/* Fills k (2 or 3) polygons of n vertices into xy (3 * 2n doubles). */
static int fixture_polygons(fixture_kind kind, int n, double *xy, size_t *k)
{
    double *a = xy, *b = xy + 2 * n, *c = xy + 4 * n;
    *k = 2;
    switch (kind) {
    case FIX_TWISTED:
        if (rp_star(a, n, 7)) return -1;
        memcpy(b, a, 2 * (size_t)n * sizeof *a);
        rp_twist(b, n, n / 3);
        return 0;
    case FIX_SPIRAL:
        return rp_spiral(a, n, 2.0) || rp_disc(b, n) ? -1 : 0;
    case FIX_GLYPH:
        return rp_comb(a, n, n / 10) || rp_star(b, n, 11) ? -1 : 0;
    case FIX_THREE:
        *k = 3;
        return rp_disc(a, n) || rp_star(b, n, 5) || rp_comb(c, n, n / 10) ? -1 : 0;
    }
    return -1;
}

/* The compatible triangulation (library defaults: partition + remesh),
 * the remesher aiming at the full target (no ceiling): these fixtures
 * measure the morph, and their floors were set on those end meshes. */
static cm_result *fixture_result(fixture_kind kind, int n)
{
    double *xy = calloc(6 * (size_t)n, sizeof *xy);
    size_t k;
    cm_result *r = NULL;
    cm_options o;
    cm_options_init(&o);
    o.ceiling = 0;
    if (xy && fixture_polygons(kind, n, xy, &k) == 0) cm_triangulate(xy, k, (size_t)n, &o, &r);
    free(xy);
    if (r && cm_result_status(r) != CM_OK) {
        fprintf(stderr, "fixture %s: %s\n", fixture_name(kind), cm_result_message(r));
        cm_result_free(r);
        r = NULL;
    }
    return r;
}

#endif
