/* cm_table1: the paper's Table 1 (Surazhsky & Gotsman, section 3): a
 * non-convex polygon with randomly placed interior vertices (Fig. 7(e)),
 * smoothed by each method; smallest angle and the share of triangles whose
 * smallest angle is under 10, 15 and 20 degrees, as a markdown table.
 *
 *   cm_table1 [OUT.md]
 *
 * Every method moves interior vertices only and never makes a triangle
 * invalid (plain: any valid move; smart: only moves that raise the
 * smallest angle around the vertex). The connectivity stays fixed, as in
 * the paper's comparison. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "api/quality.h"
#include "random_mesh.h"
#include "remesh/areaeq.h"
#include "remesh/smooth.h"

#define SWEEPS 100

typedef struct shape {
    const char *name;
    size_t n, interior;
    int (*make)(double *xy, int n);
} shape;

static int make_star(double *xy, int n) { return rp_star(xy, n, 2002); }
static int make_comb(double *xy, int n) { return rp_comb(xy, n, 5); }

typedef struct method {
    const char *name;
    int kind; /* a cm_smoothing, or -1 none, -2 area equalisation */
    int smart;
} method;

static const method methods[] = {
    {"Original (random interior vertices)", -1, 0},
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

static int table(FILE *f, const shape *s)
{
    double *poly = calloc(2 * s->n, sizeof *poly);
    cm_mesh fixture = {0};
    if (!poly || s->make(poly, (int)s->n) || rm_build(poly, s->n, s->interior, 7, 1, &fixture)) {
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
    fprintf(f, "\n%s: %zu boundary vertices (smallest corner %.1f°), %zu random interior "
               "vertices, %zu triangles; each method run to convergence or %d sweeps.\n\n",
            s->name, s->n, corner, s->interior, fixture.nt, SWEEPS);
    fprintf(f, "| Method | Min angle | Triangles < 10° | Triangles < 15° | Triangles < 20° |\n");
    fprintf(f, "| :--- | ---: | ---: | ---: | ---: |\n");
    int status = 0;
    for (size_t i = 0; i < sizeof methods / sizeof *methods && status == 0; i++) {
        cm_quality q;
        status = measure(&fixture, s->n, &methods[i], &q);
        if (status == 0)
            fprintf(f, "| %s | %.2f° | %.2f %% | %.2f %% | %.2f %% |\n", methods[i].name,
                    q.min_angle_deg, q.pct_below_10deg, q.pct_below_15deg, q.pct_below_20deg);
    }
    free(poly), cm_mesh_clear(&fixture);
    return status;
}

int main(int argc, char **argv)
{
    static const shape shapes[] = {
        {"Star-shaped polygon", 48, 300, make_star},
        {"Comb (5 teeth)", 60, 300, make_comb},
    };
    FILE *out = argc > 1 ? fopen(argv[1], "w") : NULL;
    if (argc > 1 && !out) {
        fprintf(stderr, "cm_table1: cannot write %s\n", argv[1]);
        return 1;
    }
    for (int pass = 0; pass < (out ? 2 : 1); pass++) {
        FILE *f = pass == 0 ? stdout : out;
        fprintf(f, "## Table 1: smoothing methods on random interior vertices\n");
        for (size_t i = 0; i < sizeof shapes / sizeof *shapes; i++)
            if (table(f, &shapes[i])) {
                fprintf(stderr, "cm_table1: %s failed\n", shapes[i].name);
                return 1;
            }
    }
    if (out) fclose(out);
    return 0;
}
