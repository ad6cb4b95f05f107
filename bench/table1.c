/* cm_table1: the paper's Table 1 (Surazhsky & Gotsman, section 3), each
 * smoothing method on two kinds of starting mesh of a non-convex polygon:
 *
 *  - as in the paper's Figure 6(a): a valid mesh with the irregular
 *    connectivity meshes have (the library's own mesh of the polygon,
 *    remeshed to 25 degrees), its interior vertices then displaced at
 *    random as far as validity allows. Good positions exist for this
 *    connectivity; the question is which method finds them.
 *  - as in Figure 7(e): randomly placed interior vertices with their
 *    Delaunay connectivity, which no smoothing with fixed connectivity can
 *    make good (the paper uses it for area equalisation, not Table 1).
 *
 * Smallest angle and the share of triangles whose smallest angle is under
 * 10, 15 and 20 degrees, as markdown tables.
 *
 *   cm_table1 [--check] [OUT.md]
 *
 * With --check (a test) it also fails when a smart method ends below the
 * starting mesh's smallest angle (smart moves only ever raise it) or, on
 * the Figure 6(a) comb, the weighted angle-based scheme ends below the
 * plain one (the paper's claim, eq. 2 against eq. 1). On the star the
 * claim does not hold: the plain schemes mostly forget the displacement
 * (nine of ten seeds of it end at the same smallest angles, the tenth's
 * eq. 1 below 1 degree), and those fixed points are 13.75 degrees for
 * eq. 1 and 9.95 for eq. 2 (bench/RESULTS.md).
 *
 * Every method moves interior vertices only and never makes a triangle
 * invalid (plain: any valid move; smart: only moves that raise the
 * smallest angle around the vertex). The connectivity stays fixed, as in
 * the paper's comparison. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "compatmesh/compatmesh.h"
#include "api/quality.h"
#include "geom/predicates.h"
#include "random_mesh.h"
#include "remesh/areaeq.h"
#include "remesh/smooth.h"

#define SWEEPS 100
/* The displaced fixture: the remeshing aim and Steiner budget of the mesh
 * the vertices are displaced in (about 300 interior vertices, as the
 * random fixture). */
#define DISPLACED_AIM 40.0
#define DISPLACED_STEINER 300
#define DISPLACED_SPLIT 4

/* Makes a shape of n / DISPLACED_SPLIT vertices and puts DISPLACED_SPLIT - 1
 * points evenly on each of its edges. */
static int make_split(int (*make)(double *, int), double *xy, int n)
{
    int m = n / DISPLACED_SPLIT;
    double *shape = malloc(2 * (size_t)m * sizeof *shape);
    if (!shape || make(shape, m)) {
        free(shape);
        return -1;
    }
    for (int i = 0; i < m; i++)
        for (int j = 0; j < DISPLACED_SPLIT; j++) {
            const double *a = shape + 2 * i, *b = shape + 2 * ((i + 1) % m);
            double t = (double)j / DISPLACED_SPLIT;
            xy[2 * (i * DISPLACED_SPLIT + j)] = a[0] + t * (b[0] - a[0]);
            xy[2 * (i * DISPLACED_SPLIT + j) + 1] = a[1] + t * (b[1] - a[1]);
        }
    free(shape);
    return 0;
}

typedef struct shape {
    const char *name;
    size_t n, interior; /* interior: random vertices (0: a displaced mesh) */
    int (*make)(double *xy, int n);
    int weighted_wins; /* --check: eq. 2 must end at or above eq. 1 */
} shape;

/* Moves every interior vertex of the single-geometry mesh m, `passes`
 * times, to a random point of the segment towards a random neighbour (up
 * to 90 % of the way), the move kept only if every triangle around the
 * vertex stays counter-clockwise. */
static void displace(cm_mesh *m, size_t n, int passes, rp_rng *rng)
{
    double *xy = m->xy[0];
    for (int pass = 0; pass < passes; pass++)
        for (size_t v = n; v < m->nv; v++) {
            int32_t ring[64];
            size_t count = 0;
            for (size_t t = 0; t < m->nt && count < 64; t++)
                for (int i = 0; i < 3; i++)
                    if (m->tri[3 * t + i] == (int32_t)v) ring[count++] = (int32_t)t;
            if (count == 0) continue;
            const int32_t *pick = m->tri + 3 * ring[rp_below(rng, count)];
            int32_t u = pick[0] != (int32_t)v ? pick[0] : pick[1];
            double f = 0.9 * rp_uniform(rng), old[2] = {xy[2 * v], xy[2 * v + 1]};
            xy[2 * v] = old[0] + f * (xy[2 * u] - old[0]);
            xy[2 * v + 1] = old[1] + f * (xy[2 * u + 1] - old[1]);
            for (size_t j = 0; j < count; j++) {
                const int32_t *t = m->tri + 3 * ring[j];
                if (cm_orient2d(xy + 2 * t[0], xy + 2 * t[1], xy + 2 * t[2]) <= 0) {
                    xy[2 * v] = old[0], xy[2 * v + 1] = old[1];
                    break;
                }
            }
        }
}

/* The Figure 6(a) fixture: the library's mesh of the polygon (paired with
 * itself), interior vertices displaced. poly holds n vertices: every
 * DISPLACED_SPLIT-th is a vertex of the shape, the others evenly on its
 * edges (so the mesh is finer, the corners the same). */
static int build_displaced(const double *poly, size_t n, cm_mesh *out)
{
    const double *polygons[2] = {poly, poly};
    size_t counts[2] = {n, n};
    cm_result *r = NULL;
    cm_options o;
    cm_options_init(&o);
    o.min_angle_deg = DISPLACED_AIM; /* an aim above reach: a fine mesh */
    o.max_steiner = DISPLACED_STEINER;
    o.ceiling = 0; /* the aim is a fine mesh, not the best reachable angle */
    if (cm_triangulate_polygons(polygons, counts, 2, &o, &r) != CM_OK) {
        cm_result_free(r);
        return -1;
    }
    size_t nv = cm_result_num_vertices(r), nt = cm_result_num_triangles(r);
    double **xy = calloc(1, sizeof *xy);
    int32_t *tri = malloc(3 * nt * sizeof *tri);
    if (xy) xy[0] = malloc(2 * nv * sizeof **xy);
    if (!xy || !xy[0] || !tri) {
        if (xy) free(xy[0]);
        free(xy), free(tri), cm_result_free(r);
        return -1;
    }
    memcpy(xy[0], cm_result_vertices(r, 0), 2 * nv * sizeof **xy);
    memcpy(tri, cm_result_triangles(r), 3 * nt * sizeof *tri);
    cm_result_free(r);
    *out = (cm_mesh){.k = 1, .nv = nv, .nt = nt, .xy = xy, .tri = tri};
    rp_rng rng = {2002};
    displace(out, n, 3, &rng);
    return 0;
}

static int make_star(double *xy, int n) { return rp_star(xy, n, 2002); }
static int make_comb(double *xy, int n) { return rp_comb(xy, n, 5); }
static int make_star_split(double *xy, int n) { return make_split(make_star, xy, n); }
static int make_comb_split(double *xy, int n) { return make_split(make_comb, xy, n); }

typedef struct method {
    const char *name;
    int kind; /* a cm_smoothing, or -1 none, -2 area equalisation */
    int smart;
} method;

/* Indices into methods[] of the two schemes the paper compares. */
enum { METHOD_ANGLE = 2, METHOD_WEIGHTED = 3 };

static const method methods[] = {
    {"Original (the starting mesh)", -1, 0},
    {"Laplacian", CM_SMOOTH_LAPLACIAN, 0},
    {"Angle-based (Zhou and Shimada)", CM_SMOOTH_ANGLE, 0},
    {"Weighted angle-based (eq. 2)", CM_SMOOTH_WEIGHTED, 0},
    {"Smart Laplacian", CM_SMOOTH_LAPLACIAN, 1},
    {"Smart angle-based", CM_SMOOTH_ANGLE, 1},
    {"Smart weighted angle-based", CM_SMOOTH_WEIGHTED, 1},
    {"Combined (smart weighted, else Laplacian)", CM_SMOOTH_COMBINED, 1},
    {"Area equalisation (eq. 4)", -2, 0},
};

/* Smooths a fresh copy of the fixture and measures it. */
static int measure(const cm_mesh *fixture, size_t n, const method *m, cm_quality *q)
{
    cm_kmesh km;
    if (cm_kmesh_build(&km, fixture, n) != CM_OK) return -1;
    int status = 0;
    for (int sweep = 0; sweep < SWEEPS && m->kind != -1 && status == 0; sweep++) {
        long moves = m->kind == -2 ? cm_areaeq_pass(&km, NULL)
                                   : cm_smooth_pass(&km, (cm_smoothing)m->kind, m->smart);
        if (moves < 0) status = -1;
        if (moves == 0) break;
    }
    cm_mesh out = {1, 0, 0, calloc(1, sizeof(double *)), NULL, NULL, 0};
    if (status == 0 && (!out.xy || !cm_kmesh_check(&km) || cm_kmesh_write(&km, &out) != CM_OK))
        status = -1;
    if (status == 0) cm_mesh_quality(&out, 0, q);
    cm_mesh_clear(&out);
    cm_kmesh_free(&km);
    return status;
}

static int check_claims(const shape *s, const cm_quality *q)
{
    int bad = 0;
    for (size_t i = 0; i < sizeof methods / sizeof *methods; i++)
        if (methods[i].smart && q[i].min_angle_deg < q[0].min_angle_deg) {
            fprintf(stderr, "cm_table1: %s: %s ends at %.2f°, below the starting %.2f°\n", s->name,
                    methods[i].name, q[i].min_angle_deg, q[0].min_angle_deg);
            bad = 1;
        }
    if (s->weighted_wins && q[METHOD_WEIGHTED].min_angle_deg < q[METHOD_ANGLE].min_angle_deg) {
        fprintf(stderr, "cm_table1: %s: weighted angle-based (%.2f°) below angle-based (%.2f°)\n",
                s->name, q[METHOD_WEIGHTED].min_angle_deg, q[METHOD_ANGLE].min_angle_deg);
        bad = 1;
    }
    return bad ? -1 : 0;
}

static int table(FILE *f, const shape *s, int check)
{
    double *poly = calloc(2 * s->n, sizeof *poly);
    cm_mesh fixture = {0};
    if (!poly || s->make(poly, (int)s->n) ||
        (s->interior ? rm_build(poly, s->n, s->interior, 7, 1, &fixture) : build_displaced(poly, s->n, &fixture))) {
        free(poly), cm_mesh_clear(&fixture);
        return -1;
    }
    double corner = 180.0;
    for (size_t i = 0; i < s->n; i++) {
        const double *a = poly + 2 * ((i + s->n - 1) % s->n), *b = poly + 2 * i, *c = poly + 2 * ((i + 1) % s->n);
        double t = atan2((c[0] - b[0]) * (a[1] - b[1]) - (c[1] - b[1]) * (a[0] - b[0]),
                         (c[0] - b[0]) * (a[0] - b[0]) + (c[1] - b[1]) * (a[1] - b[1]));
        corner = fmin(corner, (t < 0 ? t + 2 * CM_PI : t) * 180.0 / CM_PI);
    }
    fprintf(f, "\n%s: %zu boundary vertices (smallest corner %.1f°), %zu %s interior "
               "vertices, %zu triangles; each method run to convergence or %d sweeps.\n\n",
            s->name, s->n, corner, fixture.nv - s->n, s->interior ? "random" : "displaced",
            fixture.nt, SWEEPS);
    fprintf(f, "| Method | Min angle | Triangles < 10° | Triangles < 15° | Triangles < 20° |\n");
    fprintf(f, "| :--- | ---: | ---: | ---: | ---: |\n");
    int status = 0;
    cm_quality q[sizeof methods / sizeof *methods];
    for (size_t i = 0; i < sizeof methods / sizeof *methods && status == 0; i++) {
        status = measure(&fixture, s->n, &methods[i], &q[i]);
        if (status == 0)
            fprintf(f, "| %s | %.2f° | %.2f %% | %.2f %% | %.2f %% |\n", methods[i].name,
                    q[i].min_angle_deg, q[i].pct_below_10deg, q[i].pct_below_15deg, q[i].pct_below_20deg);
    }
    if (status == 0 && check) status = check_claims(s, q);
    free(poly), cm_mesh_clear(&fixture);
    return status;
}

int main(int argc, char **argv)
{
    static const shape displaced[] = {
        {"Star-shaped polygon", 48 * DISPLACED_SPLIT, 0, make_star_split, 0},
        {"Comb (5 teeth)", 60 * DISPLACED_SPLIT, 0, make_comb_split, 1},
    };
    static const shape random[] = {
        {"Star-shaped polygon", 48, 300, make_star, 0},
        {"Comb (5 teeth)", 60, 300, make_comb, 0},
    };
    int check = argc > 1 && strcmp(argv[1], "--check") == 0;
    const char *path = argc > 1 + check ? argv[1 + check] : NULL;
    FILE *out = path ? fopen(path, "w") : NULL;
    if (path && !out) {
        fprintf(stderr, "cm_table1: cannot write %s\n", path);
        return 1;
    }
    for (int pass = 0; pass < (out ? 2 : 1); pass++) {
        FILE *f = pass == 0 ? stdout : out;
        fprintf(f, "## Table 1: smoothing methods on a valid mesh with displaced vertices (as Figure 6(a))\n");
        for (size_t i = 0; i < sizeof displaced / sizeof *displaced; i++)
            if (table(f, &displaced[i], check)) {
                fprintf(stderr, "cm_table1: %s failed\n", displaced[i].name);
                return 1;
            }
        fprintf(f, "\n## Smoothing methods on random interior vertices (as Figure 7(e))\n");
        for (size_t i = 0; i < sizeof random / sizeof *random; i++)
            if (table(f, &random[i], check)) {
                fprintf(stderr, "cm_table1: %s failed\n", random[i].name);
                return 1;
            }
    }
    if (out) fclose(out);
    return 0;
}
