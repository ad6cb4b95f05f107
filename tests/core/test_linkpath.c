/* Visibility, window partition, link distance and minimum-link paths.
 *
 * Every fixture states what it expects: a distance derived by hand for the
 * corridor shapes, and for random polygons the relations every exact
 * answer satisfies: distance 1 exactly for the diagonals (checked against a
 * brute-force segment test), symmetry, a returned path with exactly that
 * many links lying strictly inside, and no overestimate (a breadth-first
 * search through sampled interior points can only find longer paths). */
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "geom/polytri.h"
#include "geom/linkpath.h"
#include "geom/predicates.h"
#include "random_polygons.h"
#include "geom/visibility.h"
#include "geom/xpoint.h"

/* ---- helpers -------------------------------------------------------------- */

static int adjacent(int n, int a, int b) { return b == (a + 1) % n || a == (b + 1) % n; }

/* All-pairs link distances, d[u * n + v]. */
static int *all_distances(cm_linkpart *lp, int n)
{
    int *d = malloc(sizeof(int) * (size_t)n * (size_t)n);
    for (int u = 0; d && u < n; u++) cm_link_distances(lp, u, d + u * n);
    return d;
}

/* Independent check of a path: every link strictly inside, by the exact
 * segment test, and the links pairwise disjoint except neighbours. */
static int path_ok(const double *xy, int n, int u, int v, const double *b, long nb)
{
    const double *pt[64];
    if (nb + 2 > 64) return 0;
    pt[0] = xy + 2 * u, pt[nb + 1] = xy + 2 * v;
    for (long i = 0; i < nb; i++) pt[i + 1] = b + 2 * i;
    for (long i = 0; i <= nb; i++)
        if (!cm_segment_inside(xy, n, i == 0 ? u : -1, pt[i], i == nb ? v : -1, pt[i + 1])) return 0;
    for (long i = 0; i <= nb; i++)
        for (long j = i + 2; j <= nb; j++)
            if (cm_segments_intersect(pt[i], pt[i + 1], pt[j], pt[j + 1]) != 0) return 0;
    return 1;
}

/* Upper bounds on the link distance from u: breadth-first search over the
 * vertices and sampled interior points, joined when one sees the other;
 * polygon vertices other than u end paths. ub[v] = -1 if none found. */
static void sampled_bounds(const double *xy, int n, int u, const double *s, int ns, int *ub)
{
    int total = n + ns, *d = malloc(sizeof(int) * (size_t)total), *queue = malloc(sizeof(int) * (size_t)total);
    for (int i = 0; i < total; i++) d[i] = -1;
    int head = 0, tail = 0;
    d[u] = 0, queue[tail++] = u;
    while (head < tail) {
        int a = queue[head++];
        if (a < n && a != u) continue;
        const double *pa = a < n ? xy + 2 * a : s + 2 * (a - n);
        for (int b = 0; b < total; b++) {
            if (d[b] >= 0) continue;
            const double *pb = b < n ? xy + 2 * b : s + 2 * (b - n);
            if (cm_segment_inside(xy, n, a < n ? a : -1, pa, b < n ? b : -1, pb))
                d[b] = d[a] + 1, queue[tail++] = b;
        }
    }
    memcpy(ub, d, sizeof(int) * (size_t)n);
    free(d), free(queue);
}

/* Random points inside the triangles of the polygon's triangulation. */
static int sample_points(const double *xy, int n, int per_triangle, uint64_t seed, double *s)
{
    int32_t *tri = malloc(sizeof(int32_t) * 3 * (size_t)n), *idx = malloc(sizeof(int32_t) * (size_t)n);
    for (int i = 0; i < n; i++) idx[i] = i;
    cm_polygon_triangulate(xy, idx, n, tri, NULL);
    rp_rng rng = {seed};
    int count = 0;
    for (int t = 0; t < n - 2; t++)
        for (int j = 0; j < per_triangle; j++) {
            double a = rp_uniform(&rng), b = rp_uniform(&rng);
            if (a + b > 1) a = 1 - a, b = 1 - b;
            const double *p = xy + 2 * tri[3 * t], *q = xy + 2 * tri[3 * t + 1], *r = xy + 2 * tri[3 * t + 2];
            s[2 * count] = (1 - a - b) * p[0] + a * q[0] + b * r[0];
            s[2 * count + 1] = (1 - a - b) * p[1] + a * q[1] + b * r[1];
            count++;
        }
    free(tri), free(idx);
    return count;
}

/* ---- exact constructed points --------------------------------------------- */

static void test_xpoint(void)
{
    cm_xpool *pool = cm_xpool_create();
    /* Lines through awkward points: their intersection must lie exactly on
     * both, though its coordinates are not doubles. */
    long a = cm_xpool_add(pool, 0.1, 0.3), b = cm_xpool_add(pool, 1.7, 0.9);
    long c = cm_xpool_add(pool, 0.2, 1.1), d = cm_xpool_add(pool, 1.3, -0.7);
    long x = cm_xpool_intersect(pool, a, b, c, d);
    CHECK(x >= 0 && !cm_xpool_is_input(pool, x));
    CHECK(cm_xorient(pool, a, b, x) == 0);
    CHECK(cm_xorient(pool, c, d, x) == 0);
    CHECK(cm_xorient(pool, x, a, b) == 0);
    long e = cm_xpool_add(pool, 0.5, 0.5);
    CHECK(cm_xorient(pool, a, b, e) == -cm_xorient(pool, b, a, e));
    /* A point built from a constructed one stays exact. */
    long f = cm_xpool_add(pool, -1.0, 2.0), g = cm_xpool_add(pool, 3.0, 0.25);
    long y = cm_xpool_intersect(pool, x, f, g, c);
    CHECK(y >= 0 && cm_xorient(pool, x, f, y) == 0 && cm_xorient(pool, g, c, y) == 0);
    CHECK(cm_xpool_intersect(pool, a, b, a, b) == -2); /* the same line */
    CHECK(cm_xcompare(pool, x, x, 0) == 0 && cm_xcompare(pool, a, b, 0) < 0);
    cm_xpool_free(pool);
}

/* cm_segment_inside_edges agrees with the full test wherever its premise
 * holds: every edge outside the given range misses the open segment and
 * touches it at most at its ends (checked here by brute force). Random
 * grid polygons have collinear vertices, so the touching cases occur. */
static int touches_only_at(const double *a, const double *b, const double *w)
{
    if (cm_orient2d(a, b, w) != 0) return 1;
    int axis = a[0] != b[0] ? 0 : 1;
    return !((w[axis] > a[axis]) == (b[axis] > a[axis]) && w[axis] != a[axis]);
}

/* cm_segment_inside between two vertices by its definition, every edge
 * tested: not an edge, leaving inward at both ends (inside the corner:
 * within a convex one, not within the outside of a reflex one), and no
 * edge meeting the open segment (those at an end touching it only
 * there). */
static int inward(const double *xy, int n, int v, const double *q)
{
    const double *p = xy + 2 * ((v + n - 1) % n), *c = xy + 2 * v, *s = xy + 2 * ((v + 1) % n);
    int turn = cm_orient2d(p, c, s), in = cm_orient2d(p, c, q) > 0, out = cm_orient2d(c, s, q) > 0;
    return turn > 0 ? in && out : turn < 0 ? in || out : in;
}

static int segment_inside_by_definition(const double *xy, int n, int i, int j)
{
    const double *a = xy + 2 * i, *b = xy + 2 * j;
    if ((i + 1) % n == j || (j + 1) % n == i || !inward(xy, n, i, b) || !inward(xy, n, j, a)) return 0;
    for (int e = 0; e < n; e++) {
        int f = (e + 1) % n;
        const double *e0 = xy + 2 * e, *e1 = xy + 2 * f;
        if (e == i || f == i) {
            if (!touches_only_at(a, b, e == i ? e1 : e0)) return 0;
        } else if (e == j || f == j) {
            if (!touches_only_at(b, a, e == j ? e1 : e0)) return 0;
        } else if (cm_segments_intersect(a, b, e0, e1) != 0) {
            return 0;
        }
    }
    return 1;
}

static void test_segment_inside_edges(void)
{
    long held = 0, inside = 0, outside = 0, bad = 0, definition_bad = 0;
    for (int seed = 1; seed <= 6; seed++) {
        int n = 20 + 8 * seed;
        double *xy = malloc(sizeof(double) * 2 * (size_t)n);
        CHECK(xy && rp_random_simple(xy, n, 900 + (uint64_t)seed) == 0);
        signed char turn[80]; /* the cached turns, on every other pair */
        int tame = xy ? cm_vertex_turns(xy, n, turn) : 0;
        CHECK(!xy || tame); /* random points: tame, the tame orientations are tested */
        rp_rng rng = {77 + (uint64_t)seed};
        for (int i = 0; xy && i < n; i++)
            for (int j = i + 2; j < n; j++) {
                if (i == 0 && j == n - 1) continue;
                definition_bad += cm_segment_inside(xy, n, i, xy + 2 * i, j, xy + 2 * j) !=
                                  segment_inside_by_definition(xy, n, i, j);
                definition_bad += cm_segment_inside_tame(xy, n, i, xy + 2 * i, j, xy + 2 * j) !=
                                  segment_inside_by_definition(xy, n, i, j);
                long first = (long)rp_below(&rng, (uint64_t)n), count = 1 + (long)rp_below(&rng, (uint64_t)n);
                const double *a = xy + 2 * i, *b = xy + 2 * j;
                int premise = 1;
                for (long e = 0; premise && e < n - count; e++) {
                    long s = (first + count + e) % n, t = (s + 1) % n;
                    const double *e0 = xy + 2 * s, *e1 = xy + 2 * t;
                    if (s == i || t == i) premise = touches_only_at(a, b, s == i ? e1 : e0);
                    else if (s == j || t == j) premise = touches_only_at(b, a, s == j ? e1 : e0);
                    else premise = cm_segments_intersect(a, b, e0, e1) == 0;
                }
                if (!premise) continue;
                held++;
                int full = cm_segment_inside(xy, n, i, a, j, b);
                inside += full, outside += !full;
                bad += cm_segment_inside_edges(xy, n, (i + j) % 2 ? turn : NULL, (i + j) % 3 ? tame : 0, i, j, first,
                                               count) != full;
            }
        free(xy);
    }
    CHECK_MSG(bad == 0, "%ld of %ld restricted segment tests disagree", bad, held);
    CHECK_MSG(definition_bad == 0, "%ld segment tests disagree with the definition", definition_bad);
    CHECK_MSG(inside > 50 && outside > 50, "premise held for %ld inside, %ld outside", inside, outside);
}

/* ---- visibility ---------------------------------------------------------- */

/* The cone-propagation table equals the brute-force segment test. */
static void check_table(const double *xy, int n, const char *what)
{
    int32_t *tri = malloc(sizeof(int32_t) * 3 * (size_t)n), *idx = malloc(sizeof(int32_t) * (size_t)n);
    unsigned char *vis = malloc((size_t)n * (size_t)n);
    for (int i = 0; i < n; i++) idx[i] = i;
    CHECK(cm_polygon_triangulate(xy, idx, n, tri, NULL) == 0);
    CHECK(cm_visibility_table(xy, n, tri, vis) == 0);
    int bad = 0;
    for (int u = 0; u < n; u++)
        for (int v = 0; v < n; v++) {
            int brute = u != v && cm_segment_inside(xy, n, u, xy + 2 * u, v, xy + 2 * v);
            bad += brute != vis[u * n + v];
        }
    CHECK_MSG(bad == 0, "%s: %d visibility mismatches", what, bad);
    /* one row at a time, in reverse order, gives the same rows */
    cm_visrows *rows = cm_visrows_create(xy, n, tri);
    unsigned char *row = malloc((size_t)n);
    CHECK(rows && row);
    for (int u = n - 1; rows && row && u >= 0; u--) {
        cm_visrows_row(rows, u, row);
        CHECK_MSG(memcmp(row, vis + (size_t)u * (size_t)n, (size_t)n) == 0, "%s: row %d differs", what, u);
        /* from vertex lo on: the same entries there */
        for (int lo = 1; lo <= n; lo += 1 + lo / 3) {
            cm_visrows_row_from(rows, u, lo, row);
            CHECK_MSG(memcmp(row + lo, vis + (size_t)u * (size_t)n + lo, (size_t)(n - lo)) == 0,
                      "%s: row %d from %d differs", what, u, lo);
        }
    }
    cm_visrows_free(rows);
    free(row);
    free(tri), free(idx), free(vis);
}

/* ---- triangulation by ear clipping ---------------------------------------- */

/* tri (local indices, m - 2 triangles) triangulates the polygon ids[0..m-1]
 * of the pool: every triangle counter-clockwise, every polygon edge in one
 * triangle and every other edge in two, the areas adding up to the
 * polygon's; with input points only, the other edges are diagonals by the
 * brute-force segment test and pairwise do not cross. */
static int triangulates(cm_xpool *pool, const long *ids, int m, const int32_t *tri, const double *xy)
{
    int ok = 1;
    double area = 0.0, sum = 0.0;
    for (int i = 0; i < m; i++) {
        const double *p = cm_xpool_xy(pool, ids[i]), *q = cm_xpool_xy(pool, ids[(i + 1) % m]);
        area += p[0] * q[1] - q[0] * p[1];
    }
    int *uses = calloc((size_t)m * (size_t)m, sizeof *uses);
    for (int t = 0; ok && t < m - 2; t++) {
        const int32_t *c = tri + 3 * t;
        ok = cm_xorient(pool, ids[c[0]], ids[c[1]], ids[c[2]]) > 0;
        for (int e = 0; e < 3; e++) {
            int a = c[e], b = c[(e + 1) % 3];
            uses[(a < b ? a : b) * m + (a < b ? b : a)]++;
            const double *p = cm_xpool_xy(pool, ids[a]), *q = cm_xpool_xy(pool, ids[b]);
            sum += p[0] * q[1] - q[0] * p[1];
        }
    }
    for (int a = 0; ok && a < m; a++)
        for (int b = a + 1; ok && b < m; b++) {
            int u = uses[a * m + b], edge = b == a + 1 || (a == 0 && b == m - 1);
            ok = edge ? u == 1 : u == 0 || u == 2;
            if (ok && !edge && u == 2 && xy) ok = cm_segment_inside(xy, m, a, xy + 2 * a, b, xy + 2 * b);
            for (int c = 0; ok && xy && !edge && u == 2 && c < m; c++)
                for (int d = c + 1; ok && d < m; d++)
                    if (uses[c * m + d] == 2 && c != a && c != b && d != a && d != b)
                        ok = cm_segments_intersect(xy + 2 * a, xy + 2 * b, xy + 2 * c, xy + 2 * d) == 0;
        }
    free(uses);
    return ok && fabs(sum - area) <= 1e-9 * fabs(area);
}

static void check_ear_clipping(const double *xy, int m, const char *what)
{
    int32_t *tri = malloc(sizeof(int32_t) * 3 * (size_t)m), *idx = malloc(sizeof(int32_t) * (size_t)m);
    long *ids = malloc(sizeof(long) * (size_t)(m + 1));
    cm_xpool *pool = cm_xpool_create();
    for (int i = 0; i < m; i++) idx[i] = i, ids[i] = cm_xpool_add(pool, xy[2 * i], xy[2 * i + 1]);
    /* the double-coordinate triangulation (ear clipping and flips) */
    CHECK(cm_polygon_triangulate(xy, idx, m, tri, NULL) == 0);
    CHECK_MSG(triangulates(pool, ids, m, tri, xy), "%s: cm_polygon_triangulate", what);
    /* over the pool */
    CHECK(cm_xtriangulate(pool, ids, m, tri) == 0);
    CHECK_MSG(triangulates(pool, ids, m, tri, xy), "%s: cm_xtriangulate", what);
    /* with a constructed point inserted on the edge 0 -> 1 (a flat vertex
     * with approximate coordinates: tested as a blocker every time) */
    const double *p0 = xy, *p1 = xy + 2;
    double mx = 0.5 * (p0[0] + p1[0]), my = 0.5 * (p0[1] + p1[1]), dx = p1[0] - p0[0], dy = p1[1] - p0[1];
    long a = cm_xpool_add(pool, mx - 0.3 * dy + 0.01 * dx, my + 0.3 * dx + 0.01 * dy);
    long b = cm_xpool_add(pool, mx + 0.3 * dy, my - 0.3 * dx);
    long x = cm_xpool_intersect(pool, ids[0], ids[1], a, b);
    CHECK(x >= 0 && !cm_xpool_is_input(pool, x) && cm_xorient(pool, ids[0], ids[1], x) == 0);
    memmove(ids + 2, ids + 1, sizeof(long) * (size_t)(m - 1));
    ids[1] = x;
    int32_t *tri2 = malloc(sizeof(int32_t) * 3 * (size_t)(m + 1));
    CHECK(cm_xtriangulate(pool, ids, m + 1, tri2) == 0);
    CHECK_MSG(triangulates(pool, ids, m + 1, tri2, NULL), "%s: cm_xtriangulate with a constructed point", what);
    cm_xpool_free(pool);
    free(tri), free(tri2), free(idx), free(ids);
}

/* Ear clipping tests an ear only against the reflex vertices in a grid
 * cell its bounding box covers: against the brute-force checks above. */
static void test_ear_clipping(void)
{
    double xy[2 * 200];
    for (uint64_t seed = 1; seed <= 12; seed++) {
        int n = 10 + 15 * (int)seed;
        if (rp_random_simple(xy, n, 300 + seed) == 0) check_ear_clipping(xy, n, "random");
        if (rp_star(xy, n, 400 + seed) == 0) check_ear_clipping(xy, n, "star");
    }
    if (rp_spiral(xy, 160, 4) == 0) check_ear_clipping(xy, 160, "spiral");
    if (rp_comb(xy, 200, 12) == 0) check_ear_clipping(xy, 200, "comb");
    if (rp_disc(xy, 64) == 0) check_ear_clipping(xy, 64, "disc");
}

static void test_visibility_table(void)
{
    double xy[2 * 120];
    for (uint64_t seed = 1; seed <= 20; seed++) {
        if (rp_random_simple(xy, 40, seed) == 0) check_table(xy, 40, "random");
        if (rp_star(xy, 60, seed) == 0) check_table(xy, 60, "star");
    }
    if (rp_spiral(xy, 120, 3) == 0) check_table(xy, 120, "spiral");
    if (rp_comb(xy, 100, 8) == 0) check_table(xy, 100, "comb");
}

static void test_segment_inside(void)
{
    /* square with a notch: (0,0) (4,0) (4,4) (2,1) (0,4) */
    const double xy[] = {0, 0, 4, 0, 4, 4, 2, 1, 0, 4};
    CHECK(cm_segment_inside(xy, 5, 0, xy + 0, 3, xy + 6));  /* a diagonal */
    CHECK(!cm_segment_inside(xy, 5, 0, xy + 0, 1, xy + 2)); /* an edge */
    CHECK(!cm_segment_inside(xy, 5, 2, xy + 4, 4, xy + 8)); /* across the notch */
    const double in[2] = {2, 0.5}, out[2] = {2, 3}, on[2] = {1, 2.5};
    CHECK(cm_segment_inside(xy, 5, 0, xy, -1, in));
    CHECK(!cm_segment_inside(xy, 5, 0, xy, -1, out));
    CHECK(!cm_segment_inside(xy, 5, -1, in, -1, on)); /* ends on an edge */
    CHECK(cm_segment_inside(xy, 5, -1, in, 1, xy + 2));
}

static void test_kernel(void)
{
    double xy[2 * 200], k[2];
    for (uint64_t seed = 1; seed <= 20; seed++) {
        CHECK(rp_star(xy, 200, seed) == 0);
        CHECK(cm_kernel_point(xy, 200, k) == 1);
        for (int i = 0; i < 200; i++) CHECK(cm_orient2d(xy + 2 * i, xy + 2 * ((i + 1) % 200), k) > 0);
    }
    CHECK(rp_spiral(xy, 100, 2) == 0);
    CHECK(cm_kernel_point(xy, 100, k) == 0); /* a spiral is not star-shaped */
}

/* Weak visibility from a diagonal: a vertex it reports sees the middle of
 * its cone (checked by sampling the diagonal densely); one it does not
 * report sees no sampled point. */
static void test_weak_visibility(void)
{
    double xy[2 * 30];
    int checked = 0;
    for (uint64_t seed = 1; seed <= 12; seed++) {
        if (rp_random_simple(xy, 30, seed) != 0) continue;
        for (int a = 0; a < 30; a += 3)
            for (int b = 0; b < 30; b++) {
                if (adjacent(30, a, b) || a == b || !cm_segment_inside(xy, 30, a, xy + 2 * a, b, xy + 2 * b))
                    continue;
                unsigned char vis[30];
                CHECK(cm_weak_visibility(xy, 30, a, b, vis) == 0);
                for (int v = (a + 1) % 30; v != b; v = (v + 1) % 30) {
                    int seen = 0;
                    for (int s = 1; s < 200 && !seen; s++) {
                        double t = s / 200.0, p[2] = {xy[2 * a] + t * (xy[2 * b] - xy[2 * a]),
                                                      xy[2 * a + 1] + t * (xy[2 * b + 1] - xy[2 * a + 1])};
                        seen = cm_segment_inside(xy, 30, v, xy + 2 * v, -1, p);
                    }
                    CHECK_MSG(!seen || vis[v], "seed %d: %d sees diagonal %d-%d", (int)seed, v, a, b);
                    checked++;
                }
            }
    }
    CHECK(checked > 500);
}

/* ---- link distance on random polygons ------------------------------------- */

static void check_polygon(const double *xy, int n, int sample, const char *what)
{
    cm_linkpart *lp = cm_linkpart_create(xy, n);
    int *d = all_distances(lp, n);
    int bad_diag = 0, asym = 0, bad_path = 0, over = 0, undetermined = 0;
    double *s = malloc(sizeof(double) * 2 * (size_t)n * 40);
    int ns = sample ? sample_points(xy, n, 10, (uint64_t)n, s) : 0;
    int *ub = malloc(sizeof(int) * (size_t)n);
    for (int u = 0; u < n; u++) {
        if (sample) sampled_bounds(xy, n, u, s, ns, ub);
        for (int v = 0; v < n; v++) {
            if (v == u) continue;
            int duv = d[u * n + v];
            undetermined += duv < 1;
            int diagonal = cm_segment_inside(xy, n, u, xy + 2 * u, v, xy + 2 * v);
            bad_diag += (duv == 1) != diagonal;
            asym += duv != d[v * n + u];
            if (sample && ub[v] > 0 && ub[v] < duv) over++;
            if (adjacent(n, u, v) || (n > 20 && (u + v) % 3 != 0)) continue;
            double *b = NULL;
            long nb = 0;
            int links = cm_link_path(lp, u, v, &b, &nb);
            if (links != duv || nb != links - 1 || !path_ok(xy, n, u, v, b, nb)) bad_path++;
            free(b);
        }
    }
    CHECK_MSG(undetermined == 0, "%s: %d undetermined", what, undetermined);
    CHECK_MSG(bad_diag == 0, "%s: %d pairs where distance 1 is not a diagonal", what, bad_diag);
    CHECK_MSG(asym == 0, "%s: %d asymmetric pairs", what, asym);
    CHECK_MSG(bad_path == 0, "%s: %d paths missing or not matching", what, bad_path);
    CHECK_MSG(over == 0, "%s: %d distances above a sampled path", what, over);
    free(ub), free(s), free(d);
    cm_linkpart_free(lp);
}

/* Distances asked for some vertices only: at those vertices they equal the
 * whole partition's at the same cap; when it reports nothing left beyond
 * the cap, they are final (the uncapped partition's). Masks: the vertices
 * after the source (how the partition asks), a random half, none but one. */
static void check_needed(const double *xy, int n, const char *what)
{
    /* ref keeps its last partition for a run at the same source and a
     * lower cap, so the final distances come from a third one */
    cm_linkpart *lp = cm_linkpart_create(xy, n), *ref = cm_linkpart_create(xy, n), *fin = cm_linkpart_create(xy, n);
    int *d = malloc(sizeof(int) * 3 * (size_t)n), *full = d + n, *final = d + 2 * n;
    unsigned char *need = malloc((size_t)n);
    CHECK(lp && ref && fin && d && need);
    rp_rng rng = {(uint64_t)n};
    long bad = 0, compared = 0;
    static const int caps[] = {2, 4, INT_MAX};
    for (int s = 0; lp && ref && fin && d && need && s < n; s++) {
        cm_link_distances(fin, s, final);
        for (size_t c = 0; c < sizeof caps / sizeof *caps; c++) {
            /* rising caps: ref builds each partition anew */
            CHECK(cm_link_distances_upto(ref, s, caps[c], full) >= 0);
            for (int mask = 0; mask < 3; mask++) {
                for (int v = 0; v < n; v++)
                    need[v] = mask == 0 ? v > s : mask == 1 ? (unsigned char)rp_below(&rng, 2) : v == (s + n / 2) % n;
                int deeper = cm_link_distances_needed(lp, s, caps[c], need, d);
                CHECK(deeper >= 0);
                for (int v = 0; v < n; v++) {
                    if (!need[v]) continue;
                    compared++;
                    bad += d[v] != full[v] || (deeper == 0 && d[v] != final[v]);
                }
            }
        }
    }
    CHECK_MSG(bad == 0 && compared > 0, "%s: %ld of %ld needed distances differ", what, bad, compared);
    /* a path from the same linkpart after a partial run is still exact */
    double *bends = NULL;
    long nb = 0;
    if (lp && n > 4) {
        int links = cm_link_path(lp, 0, n / 2, &bends, &nb);
        cm_link_distances(fin, 0, final);
        CHECK_MSG(links == final[n / 2] || links == 0, "%s: path after a partial run", what);
        free(bends);
    }
    /* a partition built only as far as the distance gives the same path,
     * bit for bit, and none below it */
    long same = 0, paths = 0;
    for (int u = 0; lp && fin && u < n; u += 3) {
        cm_link_distances(fin, u, final);
        for (int v = 0; v < n; v++) {
            if (final[v] < 2) continue;
            double *b1 = NULL, *b2 = NULL, *b3 = NULL;
            long n1 = 0, n2 = 0, n3 = 0;
            int l1 = cm_link_path(ref, u, v, &b1, &n1);
            int l2 = cm_link_path_within(lp, u, v, final[v], &b2, &n2);
            int l3 = cm_link_path_within(lp, u, v, final[v] - 1, &b3, &n3);
            paths++;
            same += l1 == l2 && n1 == n2 && (n1 == 0 || memcmp(b1, b2, sizeof(double) * 2 * (size_t)n1) == 0) &&
                    l3 == 0 && !b3;
            free(b1), free(b2), free(b3);
        }
    }
    CHECK_MSG(same == paths && paths > 0, "%s: %ld of %ld paths within the distance differ", what, paths - same, paths);
    cm_linkpart_free(lp), cm_linkpart_free(ref), cm_linkpart_free(fin);
    free(d), free(need);
}

static void test_needed_distances(void)
{
    double xy[2 * 64];
    for (uint64_t seed = 1; seed <= 4; seed++)
        if (rp_random_simple(xy, 40, 300 + seed) == 0) check_needed(xy, 40, "random 40");
    if (rp_spiral(xy, 48, 2) == 0) check_needed(xy, 48, "spiral 48");
    if (rp_comb(xy, 48, 6) == 0) check_needed(xy, 48, "comb 48");
}

static void test_random_polygons(void)
{
    double xy[2 * 64];
    for (uint64_t seed = 1; seed <= 8; seed++) {
        if (rp_random_simple(xy, 16, seed) == 0) check_polygon(xy, 16, 1, "random 16");
        if (rp_star(xy, 16, seed) == 0) check_polygon(xy, 16, 1, "star 16");
    }
    for (uint64_t seed = 1; seed <= 3; seed++)
        if (rp_random_simple(xy, 36, 100 + seed) == 0) check_polygon(xy, 36, 0, "random 36");
    for (int turns = 1; turns <= 2; turns++)
        if (rp_spiral(xy, 40, turns) == 0) check_polygon(xy, 40, 0, "spiral 40");
    if (rp_comb(xy, 48, 6) == 0) check_polygon(xy, 48, 0, "comb 48");
}

/* cm_path_valid_in with the polygon's tameness given says what
 * cm_path_valid says, and a polygon's exact image scaled by 2^450 (not
 * tame: the full segment tests) what the polygon says (tame tests), on
 * single- and double-bend candidates over random stars and polygons. */
static void test_path_valid_in(void)
{
    enum { N = 24 };
    double xy[2 * N], big[2 * N], y[4], ybig[4];
    rp_rng rng = {2026112901};
    long differ = 0, valid = 0, tried = 0;
    for (uint64_t seed = 1; seed <= 12; seed++) {
        if ((seed % 2 ? rp_star(xy, N, seed) : rp_random_simple(xy, N, seed)) != 0) continue;
        for (int i = 0; i < 2 * N; i++) big[i] = ldexp(xy[i], 450);
        int tame = cm_coords_tame(xy, 2 * N), wild = cm_coords_tame(big, 2 * N);
        CHECK(tame && !wild);
        for (int trial = 0; trial < 200; trial++) {
            long u = (long)(rp_next(&rng) % N), v = (long)(rp_next(&rng) % N), nb = 1 + trial % 2;
            if (u == v) continue;
            for (int i = 0; i < 2 * nb; i++) y[i] = 2.2 * rp_uniform(&rng) - 1.1, ybig[i] = ldexp(y[i], 450);
            int plain = cm_path_valid(xy, N, u, v, y, nb);
            differ += cm_path_valid_in(xy, N, tame, u, v, y, nb) != plain;
            differ += cm_path_valid_in(big, N, wild, u, v, ybig, nb) != plain;
            valid += plain, tried++;
        }
    }
    CHECK_MSG(differ == 0 && valid > 20 && valid < tried, "path_valid_in: %ld differ, %ld of %ld valid", differ,
              valid, tried);
}

/* Pockets triangulated from their parents' give the distances of pockets
 * ear-clipped from scratch, from every source, capped or not, and paths of
 * the same length that are valid; most pocket vertices go the derived way
 * (so a wrong derivation cannot hide behind the ear-clipping fallback). */
static void check_derived(const double *xy, int n, const char *what, long *fallbacks)
{
    cm_linkpart *lp = cm_linkpart_create(xy, n), *ref = cm_linkpart_create(xy, n);
    int *d = malloc(sizeof(int) * 2 * (size_t)n), *e = d + n;
    CHECK(lp && ref && d);
    if (!lp || !ref || !d) return;
    cm_linkpart_set_derive(ref, 0);
    long bad = 0, bad_path = 0, paths = 0;
    for (int s = 0; s < n; s++) {
        CHECK(cm_link_distances(lp, s, d) == 0 && cm_link_distances(ref, s, e) == 0);
        for (int v = 0; v < n; v++) bad += d[v] != e[v] || (v != s && d[v] < 1);
        CHECK(cm_link_distances_upto(lp, s, 2, d) >= 0 && cm_link_distances_upto(ref, s, 2, e) >= 0);
        for (int v = 0; v < n; v++) bad += d[v] != e[v];
        if (s % 7 != 0) continue;
        cm_link_distances(ref, s, e);
        for (int v = 0; v < n; v += 5) {
            if (e[v] < 2) continue;
            double *b = NULL;
            long nb = 0;
            int links = cm_link_path(lp, s, v, &b, &nb);
            paths++;
            bad_path += links != e[v] || nb != links - 1 || !path_ok(xy, n, s, v, b, nb);
            free(b);
        }
    }
    long derived, clipped, ref_derived, ref_clipped;
    cm_linkpart_counts(lp, &derived, &clipped);
    cm_linkpart_counts(ref, &ref_derived, &ref_clipped);
    CHECK_MSG(bad == 0, "%s: %ld distances differ from ear-clipped pockets", what, bad);
    CHECK_MSG(bad_path == 0, "%s: %ld of %ld paths missing or not matching", what, bad_path, paths);
    CHECK_MSG(ref_derived == 0 && ref_clipped > 0, "%s: the reference derived pockets", what);
    CHECK_MSG(derived > 4 * clipped, "%s: %ld pocket vertices derived, %ld ear-clipped", what, derived, clipped);
    *fallbacks += clipped;
    cm_linkpart_free(lp), cm_linkpart_free(ref);
    free(d);
}

/* Random polygons on a coarse grid: windows running through vertices and
 * along edges, where the derivation gives way to ear clipping. */
static int coarse_polygon(double *xy, int n, uint64_t seed)
{
    if (rp_random_simple(xy, n, seed) != 0) return -1;
    for (int i = 0; i < 2 * n; i++) xy[i] = round(xy[i] * 12) / 12;
    for (int i = 0; i < n; i++)
        for (int j = i + 1; j < n; j++)
            if (xy[2 * i] == xy[2 * j] && xy[2 * i + 1] == xy[2 * j + 1]) return -1;
    return rp_is_simple(xy, n) && rp_signed_area2(xy, n) > 0 ? 0 : -1;
}

static void test_derived_pockets(void)
{
    static double xy[2 * 400];
    long fallbacks = 0, coarse = 0;
    for (uint64_t seed = 1; seed <= 6; seed++)
        if (rp_random_simple(xy, 120, 500 + seed) == 0) check_derived(xy, 120, "random 120", &fallbacks);
    for (uint64_t seed = 1; seed <= 2; seed++)
        if (rp_random_spa(xy, 400, 600 + seed) == 0) check_derived(xy, 400, "spa 400", &fallbacks);
    if (rp_random_simple(xy, 400, 700) == 0) check_derived(xy, 400, "random 400", &fallbacks);
    if (rp_spiral(xy, 200, 3) == 0) check_derived(xy, 200, "spiral 200", &fallbacks);
    if (rp_comb(xy, 200, 20) == 0) check_derived(xy, 200, "comb 200", &fallbacks);
    if (rp_star(xy, 100, 9) == 0) check_derived(xy, 100, "star 100", &fallbacks);
    fallbacks = 0;
    for (uint64_t seed = 1; seed <= 200 && coarse < 12; seed++)
        if (coarse_polygon(xy, 30, 800 + seed) == 0) check_derived(xy, 30, "coarse 30", &fallbacks), coarse++;
    CHECK_MSG(coarse == 12 && fallbacks > 0, "coarse: %ld polygons, %ld pocket vertices ear-clipped", coarse,
              fallbacks);
}

/* ---- hand-derived distances ----------------------------------------------- */

static int distance(const double *xy, int n, int u, int v, int *path_links)
{
    cm_linkpart *lp = cm_linkpart_create(xy, n);
    int *d = malloc(sizeof(int) * (size_t)n);
    cm_link_distances(lp, u, d);
    int duv = d[v];
    double *b = NULL;
    long nb = 0;
    *path_links = cm_link_path(lp, u, v, &b, &nb);
    if (*path_links > 0 && !path_ok(xy, n, u, v, b, nb)) *path_links = -1;
    free(b), free(d);
    cm_linkpart_free(lp);
    return duv;
}

/* A square spiral corridor of width 1 with five legs, walls 1 thick:
 * bottom (y 0..1), right (x 8..9), top (y 8..9), left (x 0..1, down to
 * y = 2), inner bottom (y 2..3, x 0..7). A link can run along one leg and
 * no further (the next-but-one leg lies behind a corner), and from a corner
 * square both of its legs are visible, so the distance from the start of
 * the first leg to the end of the last is the number of legs, 5; the
 * outer corner of legs 2 and 3 is 2 away (one link to the first corner
 * square, one along leg 2). */
static void test_spiral_corridor(void)
{
    const double xy[] = {0, 0, 9, 0, 9, 9, 0, 9, 0, 2, 7, 2, 7, 3, 1, 3, 1, 8, 8, 8, 8, 1, 0, 1};
    int n = 12, links;
    CHECK(rp_is_simple(xy, n) && rp_signed_area2(xy, n) > 0);
    CHECK(distance(xy, n, 0, 6, &links) == 5 && links == 5);
    CHECK(distance(xy, n, 6, 0, &links) == 5 && links == 5);
    CHECK(distance(xy, n, 0, 2, &links) == 2 && links == 2);
    CHECK(distance(xy, n, 0, 3, &links) == 3 && links == 3); /* outer corner of top and left */
    CHECK(distance(xy, n, 0, 5, &links) == 5 && links == 5);
}

/* An orthogonal comb: bar [0,5] x [0,1], three teeth [0,1], [2,3], [4,5]
 * up to y = 10, a flat vertex at (0,1) on the left wall. From a tooth's tip
 * the bar is seen only below that tooth (x within 1.12 of it), so two tips
 * of different teeth see no common point: 3 links. The bottom-left corner
 * sees the whole bar and a point of the bar below a tooth sees its tip: 2.
 * The corner (0,0) and the tip (0,10) of the same wall see each other only
 * along the wall (through the flat vertex): 2. */
static void test_comb(void)
{
    const double xy[] = {0, 0, 5, 0, 5, 10, 4, 10, 4, 1, 3, 1, 3, 10, 2, 10, 2, 1, 1, 1, 1, 10, 0, 10, 0, 1};
    int n = 13, links;
    CHECK(rp_is_simple(xy, n) && rp_signed_area2(xy, n) > 0);
    CHECK(distance(xy, n, 11, 2, &links) == 3 && links == 3); /* tip of tooth 0 to tip of tooth 2 */
    CHECK(distance(xy, n, 11, 7, &links) == 3 && links == 3); /* to the tip of tooth 1 */
    CHECK(distance(xy, n, 10, 6, &links) == 3 && links == 3); /* right tips of teeth 0 and 1 */
    CHECK(distance(xy, n, 0, 2, &links) == 2 && links == 2);
    CHECK(distance(xy, n, 0, 11, &links) == 2 && links == 2);  /* along the wall */
    CHECK(distance(xy, n, 11, 1, &links) == 2 && links == 2);  /* tip to the far bottom corner */
    CHECK(distance(xy, n, 0, 5, &links) == 1 && links == 1);   /* a diagonal */
}

/* A convex polygon: every non-adjacent pair spans a diagonal, neighbours
 * are two links apart. */
static void test_convex(void)
{
    double xy[2 * 32];
    CHECK(rp_disc(xy, 32) == 0);
    cm_linkpart *lp = cm_linkpart_create(xy, 32);
    int d[32], bad = 0;
    for (int u = 0; u < 32; u++) {
        cm_link_distances(lp, u, d);
        for (int v = 0; v < 32; v++) bad += v != u && d[v] != (adjacent(32, u, v) ? 2 : 1);
    }
    CHECK(bad == 0);
    cm_linkpart_free(lp);
}

int main(void)
{
    test_xpoint();
    test_segment_inside();
    test_segment_inside_edges();
    test_visibility_table();
    test_ear_clipping();
    test_kernel();
    test_weak_visibility();
    test_convex();
    test_spiral_corridor();
    test_comb();
    test_random_polygons();
    test_path_valid_in();
    test_needed_distances();
    test_derived_pockets();
    return check_summary("test_linkpath");
}
