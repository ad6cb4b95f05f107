/* The Steiner-free dynamic program against brute force: on small polygon
 * pairs every triangulation along common diagonals is enumerated; the
 * program must report cost 0 exactly when one exists, reach the best
 * smallest angle among them, and otherwise leave only stuck faces (no
 * common diagonal inside). With a fan point, star pairs cost at most 1. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "geom/polytri.h"
#include "geom/angle.h"
#include "geom/predicates.h"
#include "random_polygons.h"
#include "construct/steinerfree.h"
#include "geom/visibility.h"

#define MAXN 11

/* common[i][j]: a diagonal of both polygons, by the brute-force test. */
static void common_diagonals(const double *a, const double *b, int n, unsigned char *common)
{
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++)
            common[i * n + j] = i != j && cm_segment_inside(a, n, i, a + 2 * i, j, a + 2 * j) &&
                                cm_segment_inside(b, n, i, b + 2 * i, j, b + 2 * j);
}

/* The program on a byte matrix of common diagonals. */
static int plan_matrix(int n, const unsigned char *common, const double *const *xy, const double *fans,
                       size_t nfans, cm_sf_plan *plan)
{
    cm_diagset set;
    if (cm_diagset_from_matrix(&set, n, common) != 0) return -1;
    cm_diagview view = {&set, NULL};
    int r = cm_steinerfree_plan(n, &view, xy, 2, fans, nfans, plan);
    cm_diagset_clear(&set);
    return r;
}

static double min_angle(const double *p, const double *q, const double *r)
{
    return cm_triangle_min_angle(p, q, r) * 180.0 / CM_PI;
}

/* Enumerates the triangulations of 0..n-1 along links (common diagonals
 * and edges): counts them and records the best smallest angle. */
typedef struct {
    int n;
    const unsigned char *common;
    const double *xy[2];
    long count;
    double best;
} enumeration;

static int is_link(const enumeration *e, int a, int b)
{
    return b == a + 1 || (!(a == 0 && b == e->n - 1) && e->common[a * e->n + b]);
}

/* open[0..nopen-1]: the sub-polygons (a, b) still to triangulate; each
 * branch works on its own copy. */
static void enumerate(enumeration *e, const int (*open)[2], int nopen, double worst)
{
    if (nopen == 0) {
        e->count++;
        if (worst > e->best) e->best = worst;
        return;
    }
    int a = open[nopen - 1][0], b = open[nopen - 1][1], next[2 * MAXN][2];
    memcpy(next, open, sizeof(int[2]) * (size_t)(nopen - 1));
    if (b - a < 2) {
        enumerate(e, (const int(*)[2])next, nopen - 1, worst);
        return;
    }
    for (int c = a + 1; c < b; c++) {
        if (!is_link(e, a, c) || !is_link(e, c, b)) continue;
        double w = worst;
        for (int g = 0; g < 2; g++)
            w = fmin(w, min_angle(e->xy[g] + 2 * a, e->xy[g] + 2 * c, e->xy[g] + 2 * b));
        next[nopen - 1][0] = a, next[nopen - 1][1] = c;
        next[nopen][0] = c, next[nopen][1] = b;
        enumerate(e, (const int(*)[2])next, nopen + 1, w);
    }
}

/* Checks the plan against the enumeration and against its own promises. */
static void check_pair(const double *a, const double *b, int n, int *free_pairs)
{
    unsigned char common[MAXN * MAXN];
    common_diagonals(a, b, n, common);
    const double *xy[2] = {a, b};
    cm_sf_plan plan;
    CHECK(plan_matrix(n, common, xy, NULL, 0, &plan) == 0);
    enumeration e = {n, common, {a, b}, 0, -1.0};
    const int open[1][2] = {{0, n - 1}};
    enumerate(&e, open, 1, 180.0);
    CHECK_MSG((plan.cost == 0) == (e.count > 0), "n=%d cost %ld, %ld triangulations", n, plan.cost, e.count);
    if (e.count > 0) {
        (*free_pairs)++;
        CHECK_MSG(fabs(plan.min_angle_deg - e.best) < 1e-9, "angle %.12f, best %.12f", plan.min_angle_deg, e.best);
    }
    /* the triangles are counter-clockwise in both polygons */
    long corners = 0;
    for (long t = 0; t < plan.nt; t++)
        for (int g = 0; g < 2; g++)
            CHECK(cm_orient2d(xy[g] + 2 * plan.tri[3 * t], xy[g] + 2 * plan.tri[3 * t + 1],
                              xy[g] + 2 * plan.tri[3 * t + 2]) > 0);
    /* faces: stuck (no common diagonal inside), and the cost adds up */
    long cost = 0;
    for (long f = 0; f < plan.nf; f++) {
        const int32_t *v = plan.face + plan.face_start[f];
        long m = plan.face_start[f + 1] - plan.face_start[f];
        CHECK(m >= 4);
        cost += m - 3;
        corners += m - 2;
        for (long i = 0; i < m; i++)
            for (long j = i + 2; j < m; j++)
                if (!(i == 0 && j == m - 1)) CHECK(!common[v[i] * n + v[j]]);
    }
    CHECK(cost == plan.cost);
    CHECK(plan.nt + corners == n - 2); /* faces and triangles tile the polygon */
    cm_sf_plan_clear(&plan);
}

static void test_against_enumeration(void)
{
    double a[2 * MAXN], b[2 * MAXN];
    int pairs = 0, free_pairs = 0;
    for (uint64_t seed = 1; seed <= 300; seed++) {
        int n = 5 + (int)(seed % 6);
        int ok = seed % 3 == 0   ? rp_random_simple(a, n, seed) | rp_random_simple(b, n, seed + 1000)
                 : seed % 3 == 1 ? rp_star(a, n, seed) | rp_random_simple(b, n, seed + 2000)
                                 : rp_star(a, n, seed) | rp_star(b, n, seed + 3000);
        if (ok != 0) continue;
        check_pair(a, b, n, &free_pairs);
        pairs++;
    }
    CHECK(pairs > 250);
    CHECK(free_pairs > 20 && free_pairs < pairs); /* both outcomes exercised */
    printf("enumeration: %d pairs, %d Steiner-free\n", pairs, free_pairs);
}

/* A polygon and an exact affine image of it (dyadic coefficients keep the
 * image exact, a positive determinant keeps every orientation): every
 * triangulation of one is one of the other. */
static void test_affine_image(void)
{
    double a[2 * 200], b[2 * 200];
    for (uint64_t seed = 1; seed <= 10; seed++) {
        int n = 20 * (int)seed;
        CHECK(rp_random_simple(a, n, seed) == 0);
        for (int i = 0; i < n; i++) {
            b[2 * i] = 2 * a[2 * i] + 0.5 * a[2 * i + 1] + 3;
            b[2 * i + 1] = 0.25 * a[2 * i] + a[2 * i + 1] - 1;
        }
        unsigned char *common = malloc((size_t)n * (size_t)n);
        int32_t *tri = malloc(sizeof(int32_t) * 3 * (size_t)n), *idx = malloc(sizeof(int32_t) * (size_t)n);
        for (int i = 0; i < n; i++) idx[i] = i;
        CHECK(cm_polygon_triangulate(a, idx, n, tri, NULL) == 0);
        unsigned char *vb = malloc((size_t)n * (size_t)n);
        cm_visibility_table(a, n, tri, common);
        CHECK(cm_polygon_triangulate(b, idx, n, tri, NULL) == 0);
        cm_visibility_table(b, n, tri, vb);
        for (int i = 0; i < n * n; i++) CHECK(common[i] == vb[i]);
        const double *xy[2] = {a, b};
        cm_sf_plan plan;
        CHECK(plan_matrix(n, common, xy, NULL, 0, &plan) == 0);
        CHECK(plan.cost == 0 && plan.nt == n - 2 && plan.nf == 0);
        cm_sf_plan_clear(&plan);
        free(common), free(vb), free(tri), free(idx);
    }
}

static int same_plan(const cm_sf_plan *p, const cm_sf_plan *q)
{
    if (p->cost != q->cost || p->min_angle_deg != q->min_angle_deg || p->nt != q->nt || p->nf != q->nf) return 0;
    if (memcmp(p->tri, q->tri, sizeof(int32_t) * 3 * (size_t)p->nt) != 0) return 0;
    if (memcmp(p->face_start, q->face_start, sizeof(long) * (size_t)(p->nf + 1)) != 0) return 0;
    if (p->nf && memcmp(p->face_fan, q->face_fan, sizeof(int32_t) * (size_t)p->nf) != 0) return 0;
    return memcmp(p->face, q->face, sizeof(int32_t) * (size_t)p->face_start[p->nf]) == 0;
}

/* The fan points the partition tries: kernel points of the stuck faces of
 * plan (each inside some sub-polygons only, so rows keep the memo's
 * values), then of the whole polygon; up to max, 2 per geometry each. */
static size_t stuck_face_fans(int n, const double *const *xy, const cm_sf_plan *plan, double *fans, size_t max)
{
    double *face = malloc(2 * sizeof(double) * (size_t)n);
    CHECK(face != NULL);
    size_t nf = 0;
    for (long f = 0; face && f <= plan->nf && nf < max; f++) {
        const int32_t *v = f < plan->nf ? plan->face + plan->face_start[f] : NULL;
        long m = f < plan->nf ? plan->face_start[f + 1] - plan->face_start[f] : n;
        int star = 1;
        for (int g = 0; g < 2 && star; g++) {
            for (long i = 0; i < m; i++)
                face[2 * i] = xy[g][2 * (v ? v[i] : i)], face[2 * i + 1] = xy[g][2 * (v ? v[i] : i) + 1];
            star = cm_kernel_point(face, m, fans + 2 * (2 * nf + (size_t)g)) == 1;
        }
        nf += star;
    }
    free(face);
    return nf;
}

/* The run with fan points after a memo of the run without gives the plan
 * the run with them alone gives, with the fan points the partition
 * tries. */
static int check_memo(int n, const unsigned char *common, const double *const *xy)
{
    enum { NF = 8 };
    double fans[2 * 2 * NF];
    cm_diagset set;
    CHECK(cm_diagset_from_matrix(&set, n, common) == 0);
    cm_diagview view = {&set, NULL};
    cm_sf_plan plain, again, alone, after;
    cm_sf_memo *memo = NULL;
    CHECK(cm_steinerfree_plan(n, &view, xy, 2, NULL, 0, &plain) == 0);
    CHECK(cm_steinerfree_plan_memo(n, &view, xy, 2, &again, &memo) == 0);
    CHECK(same_plan(&plain, &again));
    size_t nf = stuck_face_fans(n, xy, &plain, fans, NF);
    for (size_t c = 1; c <= nf; c++) {
        CHECK(cm_steinerfree_plan(n, &view, xy, 2, fans, c, &alone) == 0);
        CHECK(cm_steinerfree_plan_fans(memo, fans, c, &after) == 0);
        CHECK_MSG(same_plan(&alone, &after), "n %d, %zu fan points: the memo's plan differs", n, c);
        cm_sf_plan_clear(&alone), cm_sf_plan_clear(&after);
    }
    cm_sf_memo_free(memo);
    cm_sf_plan_clear(&plain), cm_sf_plan_clear(&again);
    cm_diagset_clear(&set);
    return (int)nf;
}

static void test_memo(void)
{
    enum { N = 40 };
    double a[2 * N], b[2 * N];
    int32_t tri[3 * N], idx[N];
    unsigned char common[N * N], vb[N * N];
    int runs = 0;
    for (uint64_t seed = 1; seed <= 60; seed++) {
        int n = 16 + (int)(seed % 25);
        int ok = seed % 2 ? rp_random_simple(a, n, seed) | rp_random_simple(b, n, seed + 500)
                          : rp_star(a, n, seed) | rp_random_simple(b, n, seed + 900);
        if (ok != 0) continue;
        for (int i = 0; i < n; i++) idx[i] = i;
        cm_polygon_triangulate(a, idx, n, tri, NULL), cm_visibility_table(a, n, tri, common);
        cm_polygon_triangulate(b, idx, n, tri, NULL), cm_visibility_table(b, n, tri, vb);
        for (int i = 0; i < n * n; i++) common[i] &= vb[i];
        const double *xy[2] = {a, b};
        runs += check_memo(n, common, xy) > 1;
    }
    CHECK(runs > 10);
}

/* The plan of two geometries, with one fan point (NULL: none). */
static void plan_two(int n, const unsigned char *common, const double *p, const double *q, const double *fan,
                     cm_sf_plan *plan)
{
    const double *xy[2] = {p, q};
    CHECK(plan_matrix(n, common, xy, fan, fan ? 1 : 0, plan) == 0);
}

/* Beyond the doubles' squares a triangle's quality is NaN (inf / inf):
 * the program takes the worst of the other geometries' then. A polygon
 * and its exact image scaled by 2^300 (every squared length product
 * overflows; tame coordinates) or by 2^420 (not tame: the fan tests'
 * filter makes its own differences) plan as the polygon with itself, fan
 * point or not. Two stars plan the same in either order. */
static void test_scale_and_order(void)
{
    enum { N = 40 };
    double a[2 * N], b[2 * N], c[2 * N], fa[2], fb[2];
    int32_t tri[3 * N], idx[N];
    unsigned char common[N * N], vb[N * N];
    int runs = 0, swapped = 0;
    for (uint64_t seed = 1; seed <= 20; seed++) {
        int n = 12 + (int)seed;
        if ((seed % 2 ? rp_random_simple(a, n, seed) : rp_star(a, n, seed)) != 0) continue;
        for (int i = 0; i < n; i++) idx[i] = i;
        CHECK(cm_polygon_triangulate(a, idx, n, tri, NULL) == 0);
        cm_visibility_table(a, n, tri, common);
        int star = cm_kernel_point(a, n, fa) == 1;
        for (int shift = 300; shift <= 420; shift += 120) {
            for (int i = 0; i < 2 * n; i++) b[i] = ldexp(a[i], shift);
            double same[4] = {fa[0], fa[1], fa[0], fa[1]}, scaled[4] = {fa[0], fa[1], ldexp(fa[0], shift), ldexp(fa[1], shift)};
            for (int with_fan = 0; with_fan <= star; with_fan++) {
                cm_sf_plan p, q;
                plan_two(n, common, a, a, with_fan ? same : NULL, &p);
                plan_two(n, common, a, b, with_fan ? scaled : NULL, &q);
                CHECK_MSG(same_plan(&p, &q) && p.nt > 0 && q.min_angle_deg == q.min_angle_deg,
                          "seed %d, scale 2^%d, fan %d: the image plans differently", (int)seed, shift, with_fan);
                runs += with_fan;
                cm_sf_plan_clear(&p), cm_sf_plan_clear(&q);
            }
        }
        if (seed % 2 || rp_star(c, n, seed + 40) != 0 || cm_kernel_point(c, n, fb) != 1 || !star) continue;
        CHECK(cm_polygon_triangulate(c, idx, n, tri, NULL) == 0);
        cm_visibility_table(c, n, tri, vb);
        for (int i = 0; i < n * n; i++) vb[i] &= common[i];
        double ab[4] = {fa[0], fa[1], fb[0], fb[1]}, ba[4] = {fb[0], fb[1], fa[0], fa[1]};
        cm_sf_plan p, q;
        plan_two(n, vb, a, c, ab, &p);
        plan_two(n, vb, c, a, ba, &q);
        CHECK_MSG(same_plan(&p, &q), "seed %d: two stars plan differently in the other order", (int)seed);
        swapped += p.nf > 0;
        cm_sf_plan_clear(&p), cm_sf_plan_clear(&q);
    }
    CHECK(runs > 6 && swapped > 2);
}

/* With tame coordinates the fan tests' filter reads differences made once;
 * otherwise it makes its own. One coordinate 0 made 2^-450 (not tame) in
 * a pair of stars whose other coordinates are far from 0 changes no
 * double the program computes but the filter's path: the plans with the
 * stuck faces' fan points stay the same. */
static void test_fans_tame_or_not(void)
{
    enum { N = 40, NF = 8 };
    double a[2 * N], b[2 * N], fans[2 * 2 * NF];
    int32_t tri[3 * N], idx[N];
    unsigned char common[N * N], vb[N * N];
    int runs = 0;
    for (uint64_t seed = 1; seed <= 30; seed++) {
        int n = 12 + (int)(seed % 25), far = 1;
        CHECK(rp_star(a, n, seed) == 0 && rp_star(b, n, seed + 77) == 0);
        double x0 = b[0];
        for (int i = 0; i < n; i++) b[2 * i] -= x0; /* vertex 0 of b on x = 0 */
        for (int i = 0; i < 2 * n; i++) far &= fabs(a[i]) > 1e-3 && (i == 0 || fabs(b[i]) > 1e-3);
        if (!far || b[0] != 0.0) continue;
        for (int i = 0; i < n; i++) idx[i] = i;
        cm_polygon_triangulate(a, idx, n, tri, NULL), cm_visibility_table(a, n, tri, common);
        cm_polygon_triangulate(b, idx, n, tri, NULL), cm_visibility_table(b, n, tri, vb);
        for (int i = 0; i < n * n; i++) common[i] &= vb[i];
        const double *xy[2] = {a, b};
        cm_sf_plan plain, tame, wild;
        CHECK(plan_matrix(n, common, xy, NULL, 0, &plain) == 0);
        size_t nf = stuck_face_fans(n, xy, &plain, fans, NF);
        for (size_t i = 0; i < 2 * 2 * nf; i++) far &= fabs(fans[i]) > 1e-3;
        for (int mixed = 0; mixed < 2 && nf > 1 && far; mixed++) {
            if (mixed) /* geometry 1 of each fan point from the next face: valid on other edges in each geometry */
                for (size_t x = 0; x < nf; x++) {
                    double *p = fans + 2 * (2 * x + 1), *q = fans + 2 * (2 * ((x + 1) % nf) + 1), t[2] = {p[0], p[1]};
                    if (x + 1 < nf) p[0] = q[0], p[1] = q[1], q[0] = t[0], q[1] = t[1];
                }
            b[0] = 0.0;
            CHECK(plan_matrix(n, common, xy, fans, nf, &tame) == 0);
            b[0] = 0x1p-450;
            CHECK(plan_matrix(n, common, xy, fans, nf, &wild) == 0);
            CHECK_MSG(same_plan(&tame, &wild), "seed %d: the fan plans differ, tame or not", (int)seed);
            runs += tame.nf > 0 && tame.cost < plain.cost;
            cm_sf_plan_clear(&tame), cm_sf_plan_clear(&wild);
        }
        cm_sf_plan_clear(&plain);
    }
    CHECK(runs > 5);
}

/* Two stars: star-shaped in both, so a fan from kernel points merges all
 * stuck faces into one: cost at most 1, and the fan face is valid. */
static void test_fan(void)
{
    double a[2 * 120], b[2 * 120], ka[2], kb[2];
    int merged = 0;
    for (uint64_t seed = 1; seed <= 20; seed++) {
        int n = 30 + 4 * (int)seed;
        CHECK(rp_star(a, n, seed) == 0 && rp_star(b, n, seed + 77) == 0);
        CHECK(cm_kernel_point(a, n, ka) == 1 && cm_kernel_point(b, n, kb) == 1);
        unsigned char *common = malloc((size_t)n * (size_t)n);
        int32_t *tri = malloc(sizeof(int32_t) * 3 * (size_t)n), *idx = malloc(sizeof(int32_t) * (size_t)n);
        unsigned char *vb = malloc((size_t)n * (size_t)n);
        for (int i = 0; i < n; i++) idx[i] = i;
        cm_polygon_triangulate(a, idx, n, tri, NULL), cm_visibility_table(a, n, tri, common);
        cm_polygon_triangulate(b, idx, n, tri, NULL), cm_visibility_table(b, n, tri, vb);
        for (int i = 0; i < n * n; i++) common[i] &= vb[i];
        const double *xy[2] = {a, b}, fan[4] = {ka[0], ka[1], kb[0], kb[1]};
        cm_sf_plan plain, fanned;
        CHECK(plan_matrix(n, common, xy, NULL, 0, &plain) == 0);
        CHECK(plan_matrix(n, common, xy, fan, 1, &fanned) == 0);
        CHECK(fanned.cost <= 1 && fanned.cost <= plain.cost);
        if (plain.cost >= 2) {
            merged++;
            CHECK(fanned.nf == 1 && fanned.face_fan[0] == 0);
            const int32_t *f = fanned.face;
            long m = fanned.face_start[1];
            for (long i = 0; i < m; i++)
                for (int g = 0; g < 2; g++)
                    CHECK(cm_orient2d(xy[g] + 2 * f[i], xy[g] + 2 * f[(i + 1) % m], fan + 2 * g) > 0);
        }
        cm_sf_plan_clear(&plain), cm_sf_plan_clear(&fanned);
        free(common), free(vb), free(tri), free(idx);
    }
    CHECK(merged > 5);
}

/* A large view read row by row (cm_diagrows, what the count and the
 * greedy split use from CM_DIAGROWS_FROM vertices) gives exactly the pairs
 * cm_diagview_has gives: a random set over n vertices, a view of every
 * vertex but a random few (a sub-polygon's cyclic subsequence), and the
 * identity view. The count agrees with the pair-by-pair count. */
static void check_rows(const cm_diagview *view, long m, const char *what)
{
    cm_diagrows rows;
    int32_t *row = malloc(sizeof(int32_t) * (size_t)m);
    unsigned char *mark = calloc((size_t)m, 1);
    CHECK(row && mark && cm_diagrows_open(&rows, view, m) == 0);
    long bad = 0, pairs = 0, brute = 0;
    for (long a = 0; row && mark && a < m; a++) {
        long c = cm_diagrows_row(&rows, a, row);
        for (long t = 0; t < c; t++) mark[row[t]]++;
        for (long b = 0; b < m; b++) {
            int has = cm_diagview_has(view, a, b);
            bad += mark[b] != has;
            pairs += has;
            brute += has && b >= a + 2 && !(a == 0 && b == m - 1);
            mark[b] = 0;
        }
    }
    cm_diagrows_close(&rows);
    CHECK_MSG(bad == 0 && pairs > 0, "%s: %ld of %ld pairs differ read row by row", what, bad, pairs);
    CHECK_MSG(cm_steinerfree_count(m, view) == brute, "%s: count differs", what);
    free(row), free(mark);
}

static void test_rows(void)
{
    long n = CM_DIAGROWS_FROM + 300;
    cm_diagset set;
    CHECK(cm_diagset_init(&set, n) == 0);
    rp_rng rng = {4242};
    for (long i = 0; i < n; i++)
        for (long j = i + 2; j < n; j++)
            if (rp_below(&rng, 97) == 0) cm_diagset_add(&set, i, j);
    int32_t *map = malloc(sizeof(int32_t) * (size_t)n);
    long m = 0;
    for (long i = 0; map && i < n; i++)
        if (rp_below(&rng, 11) != 0) map[m++] = (int32_t)i;
    CHECK(m >= CM_DIAGROWS_FROM);
    cm_diagview sub = {&set, map}, all = {&set, NULL};
    if (map) check_rows(&sub, m, "sub-polygon view");
    check_rows(&all, n, "identity view");
    free(map);
    cm_diagset_clear(&set);
}

int main(void)
{
    test_against_enumeration();
    test_affine_image();
    test_fan();
    test_memo();
    test_scale_and_order();
    test_fans_tame_or_not();
    test_rows();
    return check_summary("test_steinerfree");
}
