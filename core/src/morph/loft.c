/* The loft (loft.h). */
#include "morph/loft.h"

#include <math.h>

#include "geom/predicates.h"

static double dot3(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/* F_g(x, y), as the bindings' PlaneFrame::to_space computes it. */
static void in_plane(const double *f, double x, double y, double p[3])
{
    for (int c = 0; c < 3; c++) p[c] = f[c] + x * f[3 + c] + y * f[6 + c];
}

cm_status cm_loft_levels(const double *frames, const double *centres, size_t k, double *levels, cm_error *err)
{
    for (size_t g = 0; g < k; g++) {
        const double *f = frames + CM_LOFT_FRAME * g, *u = f + 3, *v = f + 6;
        for (int i = 0; i < CM_LOFT_FRAME; i++)
            if (!isfinite(f[i])) return cm_fail(err, CM_ERR_ARGUMENT, "sweep: frames[%zu] is not finite", CM_LOFT_FRAME * g + i);
        if (!(fabs(dot3(u, u) - 1) < 1e-6 && fabs(dot3(v, v) - 1) < 1e-6 && fabs(dot3(u, v)) < 1e-6))
            return cm_fail(err, CM_ERR_ARGUMENT,
                           "sweep: the frame of geometry %zu needs unit vectors u and v at right angles", g);
    }
    levels[0] = 0;
    for (size_t g = 1; g < k; g++) {
        double a[3], b[3];
        in_plane(frames + CM_LOFT_FRAME * (g - 1), centres[2 * g - 2], centres[2 * g - 1], a);
        in_plane(frames + CM_LOFT_FRAME * g, centres[2 * g], centres[2 * g + 1], b);
        levels[g] = levels[g - 1] + hypot(hypot(b[0] - a[0], b[1] - a[1]), b[2] - a[2]);
        if (!(levels[g] > levels[g - 1]) || !isfinite(levels[g]))
            return cm_fail(err, CM_ERR_ARGUMENT,
                           "sweep: geometries %zu and %zu are centred at the same point (a loft needs sections apart)",
                           g - 1, g);
    }
    return CM_OK;
}

/* The plane point (x, y) at fraction s between frames f (segment g) and
 * the next: (1 - s) F_g + s F_g+1, either end exactly at s = 0 or 1. */
static void blend(const double *f, double s, double x, double y, double out[3])
{
    double p[3], q[3];
    in_plane(f, x, y, p);
    in_plane(f + CM_LOFT_FRAME, x, y, q);
    for (int c = 0; c < 3; c++) out[c] = s == 0 ? p[c] : s == 1 ? q[c] : (1 - s) * p[c] + s * q[c];
}

void cm_loft_place(const double *frames, const double *levels, size_t k, double *nodes, size_t count)
{
    size_t g = 0;
    for (size_t i = 0; i < count; i++) {
        double *n = nodes + 3 * i, z = n[2];
        while (g > 0 && z < levels[g]) g--; /* nodes come section by section: g rarely moves */
        while (g + 2 < k && z > levels[g + 1]) g++;
        blend(frames + CM_LOFT_FRAME * g, (z - levels[g]) / (levels[g + 1] - levels[g]), n[0], n[1], n);
    }
}

void cm_loft_section(const double *frames, size_t k, double t, const double *xy, size_t num_vertices, double *xyz)
{
    double at = t * (double)(k - 1);
    size_t g = at >= (double)(k - 1) ? k - 2 : (size_t)at;
    for (size_t v = 0; v < num_vertices; v++)
        blend(frames + CM_LOFT_FRAME * g, at - (double)g, xy[2 * v], xy[2 * v + 1], xyz + 3 * v);
}

static const double *node(const double *nodes, const int32_t *cell, int c) { return nodes + 3 * (size_t)cell[c]; }

long cm_loft_first_inverted(const double *nodes, const int32_t *cells, size_t count, int tets)
{
    for (size_t i = 0; i < count; i++) {
        if (tets) {
            const int32_t *t = cells + 4 * i;
            if (cm_orient3d(node(nodes, t, 0), node(nodes, t, 1), node(nodes, t, 2), node(nodes, t, 3)) <= 0)
                return (long)i;
            continue;
        }
        const int32_t *p = cells + 6 * i;
        for (int c = 0; c < 3; c++) {
            int n1 = (c + 1) % 3, n2 = (c + 2) % 3;
            /* bottom corner c: its edges to the next two bottom corners and up;
             * top corner c': to the top corners the other way round and down */
            if (cm_orient3d(node(nodes, p, c), node(nodes, p, n1), node(nodes, p, n2), node(nodes, p, 3 + c)) <= 0 ||
                cm_orient3d(node(nodes, p, 3 + c), node(nodes, p, 3 + n2), node(nodes, p, 3 + n1), node(nodes, p, c)) <= 0)
                return (long)i;
        }
    }
    return -1;
}

/* The volume of a 6-node wedge, exactly as a finite-element code
 * integrates its Jacobian: with x = (1 - z) B(u, v) + z T(u, v), B and T
 * the bottom and top triangles' affine maps, det J = (e(z) x f(z)) . d(u, v)
 * where e, f (the triangle's edges) are linear in z and d = T - B affine in
 * (u, v); over the reference triangle d integrates to half the centroids'
 * difference, and e x f over z to the Bernstein weights 1/3, 1/6, 1/3. */
static long double wedge_volume(const double *nodes, const int32_t *p)
{
    long double e[2][3], f[2][3], d[3];
    for (int c = 0; c < 3; c++) {
        for (int top = 0; top < 2; top++) {
            const double *a = node(nodes, p, 3 * top), *b = node(nodes, p, 3 * top + 1), *q = node(nodes, p, 3 * top + 2);
            e[top][c] = (long double)b[c] - a[c], f[top][c] = (long double)q[c] - a[c];
        }
        long double below = 0, above = 0;
        for (int j = 0; j < 3; j++) below += node(nodes, p, j)[c], above += node(nodes, p, 3 + j)[c];
        d[c] = (above - below) / 3;
    }
    long double sum = 0;
    static const long double weight[2][2] = {{1.0L / 3, 1.0L / 6}, {1.0L / 6, 1.0L / 3}};
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2; j++) {
            const long double *a = e[i], *b = f[j];
            long double cross[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
            sum += weight[i][j] * (cross[0] * d[0] + cross[1] * d[1] + cross[2] * d[2]);
        }
    return 0.5L * sum;
}

double cm_loft_volume(const double *nodes, const int32_t *prisms, size_t count)
{
    long double sum = 0;
    for (size_t i = 0; i < count; i++) sum += wedge_volume(nodes, prisms + 6 * i);
    return (double)sum;
}
