/* The Shamos-Hoey sweep against hand-made cases and against an O(n^2)
 * brute force over all edge pairs, on random polygons built to be
 * degenerate: small integer grids (collinear edges, vertical edges, equal
 * x everywhere), star-shaped polygons, and 2-opt untangled ones that are
 * simple or just barely not. */
#include "check.h"
#include "geom/polygon_check.h"
#include "geom/predicates.h"
#include "random_polygons.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define MAX_N 64
#define MAX_SIDE 8
#define PI 3.14159265358979323846

/* ---- brute force ------------------------------------------------------- */

static const double *vertex(const double *xy, long n, long v)
{
    return xy + 2 * (v % n);
}

/* Edges u-v and v-w share v; anything more means one of the far endpoints
 * lies on the other edge. */
static int consecutive_edges_offend(const double *u, const double *v,
                                    const double *w)
{
    return cm_segments_intersect(w, w, u, v) != 0 ||
           cm_segments_intersect(u, u, v, w) != 0;
}

static int brute_pair_offends(const double *xy, long n, long i, long j)
{
    if (i == j) return 0;
    if ((i + 1) % n == j)
        return consecutive_edges_offend(vertex(xy, n, i), vertex(xy, n, j),
                                        vertex(xy, n, j + 1));
    if ((j + 1) % n == i)
        return consecutive_edges_offend(vertex(xy, n, j), vertex(xy, n, i),
                                        vertex(xy, n, i + 1));
    return cm_segments_intersect(vertex(xy, n, i), vertex(xy, n, i + 1),
                                 vertex(xy, n, j), vertex(xy, n, j + 1)) != 0;
}

/* Returns 1 and the first offending pair, or 0 if simple. */
static int brute_find(const double *xy, long n, long *a, long *b)
{
    for (long i = 0; i < n; i++)
        for (long j = i + 1; j < n; j++)
            if (brute_pair_offends(xy, n, i, j)) {
                *a = i, *b = j;
                return 1;
            }
    return 0;
}

/* Runs the sweep (sorting its events, and on events sorted beforehand)
 * and the brute force; counts a failure if they disagree or the reported
 * pair is not ordered and offending. Returns the verdict. */
static int cross_check(const double *xy, long n, int *disagreements)
{
    long a = -2, b = -2, ba = -1, bb = -1, sa = -2, sb = -2;
    int sweep = cm_polygon_find_intersection(xy, n, &a, &b);
    int brute = brute_find(xy, n, &ba, &bb);
    cm_vertex_event *events = malloc((size_t)n * sizeof *events);
    for (long v = 0; events && v < n; v++) events[v] = (cm_vertex_event){xy[2 * v], xy[2 * v + 1], v};
    int given = events && cm_vertex_events_sort(events, n) == 0
                    ? cm_polygon_find_intersection_sorted(xy, n, events, &sa, &sb) : -1;
    free(events);
    int ok = sweep == brute && given == sweep && sa == a && sb == b;
    if (ok && sweep == 1)
        ok = 0 <= a && a < b && b < n && brute_pair_offends(xy, n, a, b);
    if (ok && sweep == 0) ok = a == -1 && b == -1;
    if (!ok) {
        if (*disagreements < 5) {
            fprintf(stderr, "disagreement: sweep %d (%ld, %ld), brute %d "
                            "(%ld, %ld), n = %ld:",
                    sweep, a, b, brute, ba, bb, n);
            for (long k = 0; k < n; k++)
                fprintf(stderr, " %.17g,%.17g", xy[2 * k], xy[2 * k + 1]);
            fputc('\n', stderr);
        }
        (*disagreements)++;
    }
    return brute;
}

/* ---- hand-made cases ------------------------------------------------------ */

/* Expects a verdict and, for a non-simple polygon, one of the listed pairs
 * (pairs[2k], pairs[2k+1]); an empty list accepts any offending pair. */
static void expect(const char *name, const double *xy, long n, int verdict,
                   const long *pairs, int pair_count)
{
    long a, b;
    int r = cm_polygon_find_intersection(xy, n, &a, &b);
    CHECK_MSG(r == verdict, "%s: got %d", name, r);
    if (r != 1 || verdict != 1) return;
    int listed = pair_count == 0 && a < b && brute_pair_offends(xy, n, a, b);
    for (int k = 0; k < pair_count; k++)
        listed |= a == pairs[2 * k] && b == pairs[2 * k + 1];
    CHECK_MSG(listed, "%s: pair (%ld, %ld)", name, a, b);
}

static void test_hand_made(void)
{
    double square[] = {0, 0, 1, 0, 1, 1, 0, 1};
    expect("square", square, 4, 0, NULL, 0);
    double triangle[] = {0, 0, 1, 0, 0, 1};
    expect("triangle", triangle, 3, 0, NULL, 0);
    double bowtie[] = {0, 0, 2, 2, 2, 0, 0, 2};
    expect("bow-tie", bowtie, 4, 1, (long[]){0, 2}, 1);
    double touch[] = {0, 0, 4, 0, 4, 4, 2, 0, 0, 4};
    expect("vertex on edge", touch, 5, 1, (long[]){0, 2, 0, 3}, 2);
    /* vertex 5 = (4, 2) touches the vertical edge 1 from the left: both of
     * its edges end there in sweep order */
    double side_touch[] = {0, 0, 4, 0, 4, 4, 0, 4, 0, 3, 4, 2, 0, 1};
    expect("vertex on vertical edge", side_touch, 7, 1, (long[]){1, 4, 1, 5},
           2);
    double overlap[] = {0, 0, 3, 0, 3, 2, 5, 2, 5, 0, 1, 0};
    expect("collinear overlap", overlap, 6, 1, (long[]){0, 4, 0, 5, 1, 4}, 3);
    double spike[] = {0, 0, 4, 0, 4, 4, 1, 1, 2, 2, 0, 4};
    expect("spike doubling back", spike, 6, 1, (long[]){2, 3, 2, 4}, 2);
    double vertical_spike[] = {0, 0, 4, 0, 4, 4, 4, 2};
    expect("vertical spike", vertical_spike, 4, 1, (long[]){1, 2, 1, 3}, 2);
    double flat[] = {0, 0, 1, 0, 2, 0};
    expect("collinear triangle", flat, 3, 1, NULL, 0);
    double straight[] = {0, 0, 1, 0, 2, 0, 2, 1, 2, 2, 1, 2, 0, 2, 0, 1};
    expect("180-degree vertices", straight, 8, 0, NULL, 0);
    double comb[] = {0, 0, 10, 0, 10, 1, 1, 1, 1, 2, 10, 2, 10, 3, 1, 3,
                     1, 4, 10, 4, 10, 5, 0, 5};
    expect("comb, equal x", comb, 12, 0, NULL, 0);
    double comb_touch[] = {0, 0, 10, 0, 10, 1, 1, 1, 1, 2, 10, 2, 10, 3, 0, 3,
                           0, 4, 10, 4, 10, 5, 0, 5};
    expect("comb touching its spine", comb_touch, 12, 1, NULL, 0);
    double stairs[] = {0, 0, 3, 0, 3, 3, 2, 3, 2, 2, 1, 2, 1, 1, 0, 1};
    expect("staircase", stairs, 8, 0, NULL, 0);
    /* vertex (18, 18) exactly on the diagonal edge, then one ulp off it */
    double on_diagonal[] = {12, 12, 24, 24, 24, 30, 18, 18, 0, 30};
    expect("vertex exactly on diagonal", on_diagonal, 5, 1, NULL, 0);
    double off_diagonal[] = {12, 12, 24, 24, 24, 30, 18, 18 + 0x1p-48, 0, 30};
    expect("vertex one ulp off diagonal", off_diagonal, 5, 0, NULL, 0);
    double huge[] = {-1e300, -1e300, 1e300, -1e300, 1e300, 1e300, 0, -1e300};
    expect("huge, vertex on edge", huge, 4, 1, NULL, 0);
    double tiny[] = {0, 0, 4e-320, 0, 4e-320, 4e-320, 0, 4e-320};
    expect("subnormal square", tiny, 4, 0, NULL, 0);

    /* excluded by the caller, but must not crash */
    double repeated[] = {0, 0, 2, 0, 1, 1, 2, 2, 0, 2, 1, 1};
    expect("repeated vertex", repeated, 6, 1, (long[]){2, 5}, 1);
    double doubled[] = {0, 0, 1, 0, 1, 0, 0, 1};
    expect("adjacent repeated vertex", doubled, 4, 1, (long[]){1, 2}, 1);
    expect("two vertices", square, 2, 1, (long[]){0, 1}, 1);
    expect("one vertex", square, 1, 0, NULL, 0);
    expect("no vertex", square, 0, 0, NULL, 0);
}

/* ---- random polygons ------------------------------------------------------ */

static uint64_t next_random(uint64_t *state)
{
    *state ^= *state >> 12;
    *state ^= *state << 25;
    *state ^= *state >> 27;
    return *state * 0x2545f4914f6cdd1dULL;
}

static long random_below(uint64_t *state, long bound)
{
    return (long)(next_random(state) % (uint64_t)bound);
}

static double random_unit(uint64_t *state)
{
    return (double)(next_random(state) >> 11) * 0x1p-53;
}

/* n distinct points of the side x side integer grid, in random order. */
static void random_grid_points(uint64_t *state, double *xy, long n, long side)
{
    long cells[MAX_SIDE * MAX_SIDE];
    for (long c = 0; c < side * side; c++) cells[c] = c;
    for (long k = 0; k < n; k++) { /* partial Fisher-Yates */
        long pick = k + random_below(state, side * side - k);
        long t = cells[k];
        cells[k] = cells[pick], cells[pick] = t;
        xy[2 * k] = (double)(cells[k] % side);
        xy[2 * k + 1] = (double)(cells[k] / side);
    }
}

/* p before q around centre: by half-plane, then by exact orientation, then
 * nearer first. */
static int angle_before(const double *c, const double *p, const double *q)
{
    int hp = p[1] < c[1] || (p[1] == c[1] && p[0] < c[0]);
    int hq = q[1] < c[1] || (q[1] == c[1] && q[0] < c[0]);
    if (hp != hq) return hp < hq;
    int o = cm_orient2d(c, p, q);
    if (o != 0) return o > 0;
    return fabs(p[0] - c[0]) + fabs(p[1] - c[1]) <
           fabs(q[0] - c[0]) + fabs(q[1] - c[1]);
}

static void sort_around(const double *centre, double *xy, long n)
{
    for (long i = 1; i < n; i++) { /* insertion sort: n is small */
        double p[2] = {xy[2 * i], xy[2 * i + 1]};
        long j = i;
        while (j > 0 && angle_before(centre, p, xy + 2 * (j - 1))) {
            xy[2 * j] = xy[2 * (j - 1)];
            xy[2 * j + 1] = xy[2 * (j - 1) + 1];
            j--;
        }
        xy[2 * j] = p[0], xy[2 * j + 1] = p[1];
    }
}

static void reverse_vertices(double *xy, long from, long to)
{
    for (; from < to; from++, to--) {
        for (int k = 0; k < 2; k++) {
            double t = xy[2 * from + k];
            xy[2 * from + k] = xy[2 * to + k];
            xy[2 * to + k] = t;
        }
    }
}

/* 2-opt: while two edges i < j offend, reverse the vertices between them.
 * Removes every proper crossing eventually; degenerate contacts may stay. */
static void untangle(double *xy, long n, int max_moves)
{
    long a, b;
    for (int move = 0; move < max_moves && brute_find(xy, n, &a, &b); move++)
        reverse_vertices(xy, a + 1, b);
}

enum generator {
    RANDOM_POINTS,
    GRID_POINTS,
    STAR,
    GRID_STAR,
    GRID_UNTANGLED,
    GRID_UNTANGLED_MOVED,
    GENERATOR_COUNT
};

static const char *const generator_name[] = {
    "random points", "grid points", "star", "grid star", "grid untangled",
    "grid untangled, one vertex moved",
};

static long make_polygon(uint64_t *state, enum generator g, double *xy)
{
    long side = 2 + random_below(state, MAX_SIDE - 2); /* 2..7 */
    long most = side * side - 2 < 20 ? side * side - 2 : 20;
    long n = 3 + random_below(state, most); /* 3..side^2 */
    switch (g) {
    case RANDOM_POINTS:
        for (long k = 0; k < 2 * n; k++) xy[k] = random_unit(state);
        break;
    case GRID_POINTS:
        random_grid_points(state, xy, n, side);
        break;
    case STAR: {
        n = 3 + random_below(state, 40);
        double angle[MAX_N];
        for (long k = 0; k < n; k++) angle[k] = 2 * PI * random_unit(state);
        for (long i = 1; i < n; i++) /* insertion sort */
            for (long j = i; j > 0 && angle[j] < angle[j - 1]; j--) {
                double t = angle[j];
                angle[j] = angle[j - 1], angle[j - 1] = t;
            }
        for (long k = 0; k < n; k++) {
            double r = 0.5 + random_unit(state);
            xy[2 * k] = 3 + r * cos(angle[k]);
            xy[2 * k + 1] = -2 + r * sin(angle[k]);
        }
        break;
    }
    case GRID_STAR: {
        double centre[2] = {(double)(side - 1) / 2 + 0.25,
                            (double)(side - 1) / 2 + 0.125};
        if (random_below(state, 2)) /* a grid point: ties in angle */
            centre[0] = (double)(side / 2), centre[1] = (double)(side / 2);
        random_grid_points(state, xy, n, side);
        sort_around(centre, xy, n);
        break;
    }
    case GRID_UNTANGLED:
    case GRID_UNTANGLED_MOVED:
        random_grid_points(state, xy, n, side);
        untangle(xy, n, 200);
        if (g == GRID_UNTANGLED_MOVED && n < side * side) {
            double spare[2 * MAX_SIDE * MAX_SIDE]; /* move a vertex to a free cell */
            random_grid_points(state, spare, side * side, side);
            for (long c = 0; c < side * side; c++) {
                int used = 0;
                for (long k = 0; k < n; k++)
                    used |= xy[2 * k] == spare[2 * c] &&
                            xy[2 * k + 1] == spare[2 * c + 1];
                if (!used) {
                    long v = random_below(state, n);
                    xy[2 * v] = spare[2 * c], xy[2 * v + 1] = spare[2 * c + 1];
                    break;
                }
            }
        }
        break;
    default:
        break;
    }
    /* random scale and shift by powers of two keep every degeneracy */
    double scale = ldexp(1, (int)random_below(state, 41) - 20);
    double shift = (double)(random_below(state, 9) - 4) * 0.5;
    for (long k = 0; k < 2 * n; k++) xy[k] = (xy[k] + shift) * scale;
    return n;
}

static void test_random_against_brute_force(void)
{
    uint64_t state = 0x5eed;
    int disagreements = 0, total = 0;
    for (int g = 0; g < GENERATOR_COUNT; g++) {
        int simple = 0, not_simple = 0;
        for (int trial = 0; trial < 600; trial++) {
            double xy[2 * MAX_N];
            long n = make_polygon(&state, (enum generator)g, xy);
            if (cross_check(xy, n, &disagreements))
                not_simple++;
            else
                simple++;
            total++;
        }
        printf("  %-34s %4d simple, %4d not simple\n", generator_name[g],
               simple, not_simple);
        /* each generator must exercise what it was built for */
        int star = g == STAR || g == GRID_STAR;
        CHECK_MSG(simple >= 30 && (star || not_simple >= 30),
                  "%s: %d simple, %d not", generator_name[g], simple,
                  not_simple);
    }
    CHECK_MSG(disagreements == 0, "%d of %d polygons", disagreements, total);
    CHECK(total >= 2000);
}

/* ---- size ---------------------------------------------------------------- */

/* A 100000-gon star: quadratic work would take minutes. One vertex pulled
 * across the centre and out of the polygon must then be found. */
static void test_large_star(void)
{
    long n = 100000;
    double *xy = malloc(2 * (size_t)n * sizeof *xy);
    CHECK(xy != NULL);
    if (!xy) return;
    for (long k = 0; k < n; k++) {
        double angle = 2 * PI * (double)k / (double)n;
        double r = k % 2 ? 1.0 : 0.999;
        xy[2 * k] = r * cos(angle);
        xy[2 * k + 1] = r * sin(angle);
    }
    long a, b;
    CHECK(cm_polygon_find_intersection(xy, n, &a, &b) == 0);
    xy[2 * 5000] *= -2, xy[2 * 5000 + 1] *= -2;
    CHECK(cm_polygon_find_intersection(xy, n, &a, &b) == 1);
    CHECK(a < b && brute_pair_offends(xy, n, a, b));
    free(xy);
}

/* The shared generators' simple shapes, both ways round: a spiral keeps
 * many edges in the sweep status at once, a comb many equal x. */
static void test_shared_generators(void)
{
    enum { N = 3000 }; /* the generators check simplicity in O(n^2) */
    double *xy = malloc(2 * N * sizeof *xy);
    CHECK(xy != NULL);
    if (!xy) return;
    for (int shape = 0; shape < 8; shape++) {
        int n = shape < 2 ? N : shape < 4 ? 2000 : 200;
        int made = shape == 0   ? rp_spiral(xy, n, 25)
                   : shape == 1 ? rp_star(xy, n, 17)
                   : shape == 2 ? rp_comb(xy, n, 200)
                   : shape == 3 ? rp_disc(xy, n)
                                : rp_random_simple(xy, n, (uint64_t)shape);
        CHECK_MSG(made == 0, "shape %d not generated", shape);
        if (made != 0) continue;
        long a, b;
        CHECK_MSG(cm_polygon_find_intersection(xy, n, &a, &b) == 0,
                  "shape %d: edges %ld, %ld", shape, a, b);
        reverse_vertices(xy, 0, n - 1);
        CHECK_MSG(cm_polygon_find_intersection(xy, n, &a, &b) == 0,
                  "shape %d reversed: edges %ld, %ld", shape, a, b);
    }
    free(xy);
}

/* cm_vertex_events_sort against qsort with the same order, on random
 * points with many repeated coordinates, every length up to 300. */
static int event_cmp(const void *pa, const void *pb)
{
    const cm_vertex_event *a = pa, *b = pb;
    if (a->x != b->x) return a->x < b->x ? -1 : 1;
    if (a->y != b->y) return a->y < b->y ? -1 : 1;
    return (a->vertex > b->vertex) - (a->vertex < b->vertex);
}

static void test_event_sort(void)
{
    uint64_t state = 20261128;
    int bad = 0;
    cm_vertex_event e[300], want[300];
    for (long n = 0; n <= 300; n++) {
        for (long i = 0; i < n; i++) {
            e[i] = (cm_vertex_event){(double)(next_random(&state) % 7), (double)(next_random(&state) % 5),
                                     (long)(next_random(&state) % 1000)};
            want[i] = e[i];
        }
        qsort(want, (size_t)n, sizeof *want, event_cmp);
        bad += cm_vertex_events_sort(e, n) != 0 || (n && memcmp(e, want, (size_t)n * sizeof *e) != 0);
    }
    CHECK_MSG(bad == 0, "event sort: %d lengths differ from qsort", bad);
}

int main(void)
{
    test_event_sort();
    test_hand_made();
    test_random_against_brute_force();
    test_large_star();
    test_shared_generators();
    return check_summary("test_polygon_check");
}
