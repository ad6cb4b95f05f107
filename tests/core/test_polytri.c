/* Triangle adjacency (geom/polytri.h) against its definition, pair by
 * pair: the slots of one edge, in slot order, pair up first with second,
 * third with fourth (an edge of three or more triangles keeps that
 * order); a slot left alone has no neighbour. On polygon triangulations,
 * on random triangle soups with repeated edges, and with vertex numbers
 * too large for the buckets. */
#include <stdlib.h>

#include "check.h"
#include "geom/polytri.h"
#include "random_polygons.h"

static void edge_of(const int32_t *tri, long s, int32_t *lo, int32_t *hi)
{
    int32_t a = tri[s - s % 3 + (s + 1) % 3], b = tri[s - s % 3 + (s + 2) % 3];
    *lo = a < b ? a : b, *hi = a < b ? b : a;
}

/* The definition, in O(n^2). */
static void reference(const int32_t *tri, long nt, int32_t *nbr)
{
    for (long s = 0; s < 3 * nt; s++) {
        int32_t lo, hi, l2, h2;
        edge_of(tri, s, &lo, &hi);
        long rank = 0, partner = -1, count = 0; /* s's rank among its edge's slots */
        for (long u = 0; u < 3 * nt; u++) {
            edge_of(tri, u, &l2, &h2);
            if (l2 != lo || h2 != hi) continue;
            if (u < s) rank++;
            count++;
        }
        long want = rank % 2 == 0 ? rank + 1 : rank - 1, seen = 0;
        for (long u = 0; u < 3 * nt && want < count; u++) {
            edge_of(tri, u, &l2, &h2);
            if (l2 != lo || h2 != hi) continue;
            if (seen++ == want) partner = u;
        }
        nbr[s] = partner >= 0 ? (int32_t)(partner / 3) : -1;
    }
}

static int same_as_reference(const int32_t *tri, long nt)
{
    int32_t *got = malloc((size_t)(3 * nt) * sizeof *got), *want = malloc((size_t)(3 * nt) * sizeof *want);
    int same = got && want && cm_tri_adjacency(tri, nt, got) == 0;
    if (same) reference(tri, nt, want);
    for (long s = 0; same && s < 3 * nt; s++) same = got[s] == want[s];
    free(got), free(want);
    return same;
}

static void test_polygons(void)
{
    enum { N = 120 };
    double xy[2 * N];
    int32_t idx[N], tri[3 * N];
    for (int i = 0; i < N; i++) idx[i] = i;
    for (uint64_t seed = 1; seed <= 20; seed++) {
        int n = 4 + (int)(seed * 5);
        CHECK((seed % 2 ? rp_random_simple(xy, n, seed) : rp_star(xy, n, seed)) == 0);
        CHECK(cm_polygon_ear_clip(xy, idx, n, tri, NULL) == 0);
        CHECK_MSG(same_as_reference(tri, n - 2), "ear clipping, n %d", n);
        CHECK(cm_polygon_triangulate(xy, idx, n, tri, NULL) == 0);
        CHECK_MSG(same_as_reference(tri, n - 2), "Delaunay, n %d", n);
    }
}

/* Triangles over a few vertices: edges of one to five triangles. */
static void test_soups(void)
{
    rp_rng rng = {12345};
    int32_t tri[3 * 60];
    for (int round = 0; round < 300; round++) {
        long nt = 1 + (long)(rp_next(&rng) % 60);
        int32_t vertices = 3 + (int32_t)(rp_next(&rng) % 8), scale = round % 3 == 0 ? 100000 : 1;
        for (long t = 0; t < nt; t++) {
            int32_t a = (int32_t)(rp_next(&rng) % (uint64_t)vertices), b, c;
            do b = (int32_t)(rp_next(&rng) % (uint64_t)vertices); while (b == a);
            do c = (int32_t)(rp_next(&rng) % (uint64_t)vertices); while (c == a || c == b);
            tri[3 * t] = a * scale, tri[3 * t + 1] = b * scale, tri[3 * t + 2] = c * scale;
        }
        CHECK_MSG(scale > 1 || same_as_reference(tri, nt), "soup %d", round);
        if (scale > 1) { /* the sorting path: its order among three or more is not kept, pairs of two are */
            int32_t *got = malloc((size_t)(3 * nt) * sizeof *got), *want = malloc((size_t)(3 * nt) * sizeof *want);
            CHECK(got && want && cm_tri_adjacency(tri, nt, got) == 0);
            reference(tri, nt, want);
            for (long s = 0; s < 3 * nt; s++) {
                int32_t lo, hi, l2, h2;
                long count = 0;
                edge_of(tri, s, &lo, &hi);
                for (long u = 0; u < 3 * nt; u++) edge_of(tri, u, &l2, &h2), count += l2 == lo && h2 == hi;
                if (count <= 2) CHECK(got[s] == want[s]);
            }
            free(got), free(want);
        }
    }
}

int main(void)
{
    test_polygons();
    test_soups();
    return check_summary("test_polytri");
}
