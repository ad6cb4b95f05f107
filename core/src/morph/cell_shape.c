#include "morph/cell_shape.h"

#include <math.h>

#define DEGREES (180.0 / 3.14159265358979323846)

static void sub(const double a[3], const double b[3], double out[3])
{
    out[0] = a[0] - b[0], out[1] = a[1] - b[1], out[2] = a[2] - b[2];
}

static void cross(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

static double dot(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
static double norm(const double a[3]) { return sqrt(dot(a, a)); }

/* Angle in degrees between the planes (e, u) and (e, v), all from one
 * point: the angle between u and v seen along e. */
static double dihedral(const double e[3], const double u[3], const double v[3])
{
    double n1[3], n2[3], n[3];
    cross(e, u, n1), cross(e, v, n2), cross(n1, n2, n);
    return atan2(norm(n), dot(n1, n2)) * DEGREES;
}

static double triple(const double a[3], const double b[3], const double c[3])
{
    double n[3];
    cross(b, c, n);
    return dot(a, n);
}

static const int tet_edges[6][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2}, {1, 2, 0, 3}, {1, 3, 0, 2}, {2, 3, 0, 1}};

static void tet_dihedrals(const double p[4][3], double *lo, double *hi)
{
    *lo = 180, *hi = 0;
    for (int i = 0; i < 6; i++) {
        const int *c = tet_edges[i];
        double e[3], u[3], v[3];
        sub(p[c[1]], p[c[0]], e), sub(p[c[2]], p[c[0]], u), sub(p[c[3]], p[c[0]], v);
        double angle = dihedral(e, u, v);
        *lo = fmin(*lo, angle), *hi = fmax(*hi, angle);
    }
}

double cm_tet_min_dihedral(const double p[4][3])
{
    double e1[3], e2[3], e3[3], lo, hi;
    sub(p[1], p[0], e1), sub(p[2], p[0], e2), sub(p[3], p[0], e3);
    if (!(triple(e1, e2, e3) > 0)) return -1;
    tet_dihedrals(p, &lo, &hi);
    return lo;
}

void cm_tet_shape(const double p[4][3], cm_cell_shape *shape)
{
    double e1[3], e2[3], e3[3];
    sub(p[1], p[0], e1), sub(p[2], p[0], e2), sub(p[3], p[0], e3);
    double six_volume = triple(e1, e2, e3), longest = 0, area = 0, lengths[4] = {1, 1, 1, 1};
    for (int i = 0; i < 6; i++) {
        double e[3];
        sub(p[tet_edges[i][1]], p[tet_edges[i][0]], e);
        double length = norm(e);
        longest = fmax(longest, length);
        lengths[tet_edges[i][0]] *= length, lengths[tet_edges[i][1]] *= length;
    }
    double most = 0; /* largest product of the three edge lengths at a corner */
    for (int i = 0; i < 4; i++) most = fmax(most, lengths[i]);
    for (int f = 0; f < 4; f++) { /* face opposite corner f */
        const double *a = p[(f + 1) % 4], *b = p[(f + 2) % 4], *c = p[(f + 3) % 4];
        double u[3], v[3], n[3];
        sub(b, a, u), sub(c, a, v), cross(u, v, n);
        area += 0.5 * norm(n);
    }
    tet_dihedrals(p, &shape->min_dihedral_deg, &shape->max_dihedral_deg);
    shape->scaled_jacobian = most > 0 ? sqrt(2.0) * six_volume / most : 0;
    /* inradius = 3 V / area = six_volume / (2 area) */
    shape->aspect_ratio = six_volume > 0 ? longest * area / (sqrt(6.0) * six_volume) : INFINITY;
}

void cm_prism_shape(const double p[6][3], cm_cell_shape *shape)
{
    shape->min_dihedral_deg = 180, shape->max_dihedral_deg = 0, shape->scaled_jacobian = INFINITY;
    double longest = 0, shortest = INFINITY;
    for (int i = 0; i < 6; i++) {
        int top = i >= 3, j = i % 3;
        /* The corner's edges in the order that makes a valid prism's
         * determinant positive: along the triangle, then to the other end. */
        const double *a = p[(top ? 3 + (j + 2) % 3 : (j + 1) % 3)], *b = p[(top ? 3 + (j + 1) % 3 : (j + 2) % 3)];
        const double *c = p[top ? j : j + 3];
        double e1[3], e2[3], e3[3];
        sub(a, p[i], e1), sub(b, p[i], e2), sub(c, p[i], e3);
        double l1 = norm(e1), l2 = norm(e2), l3 = norm(e3);
        longest = fmax(longest, fmax(l1, fmax(l2, l3)));
        shortest = fmin(shortest, fmin(l1, fmin(l2, l3)));
        double product = l1 * l2 * l3;
        double jacobian = product > 0 ? 2.0 / sqrt(3.0) * triple(e1, e2, e3) / product : 0;
        shape->scaled_jacobian = fmin(shape->scaled_jacobian, jacobian);
        const double angles[3] = {dihedral(e1, e2, e3), dihedral(e2, e3, e1), dihedral(e3, e1, e2)};
        for (int k = 0; k < 3; k++)
            shape->min_dihedral_deg = fmin(shape->min_dihedral_deg, angles[k]),
            shape->max_dihedral_deg = fmax(shape->max_dihedral_deg, angles[k]);
    }
    shape->aspect_ratio = shortest > 0 ? longest / shortest : INFINITY;
}
