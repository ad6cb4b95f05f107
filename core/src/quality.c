/* Angle statistics. Angles via atan2(|cross|, dot): accurate for slivers. */
#include <math.h>
#include <time.h>

#include "internal.h"

static double angle_at(const double p[2], const double q[2], const double r[2])
{
    double ux = q[0] - p[0], uy = q[1] - p[1], vx = r[0] - p[0], vy = r[1] - p[1];
    return atan2(fabs(ux * vy - uy * vx), ux * vx + uy * vy);
}

double cm_triangle_min_angle(const double a[2], const double b[2], const double c[2])
{
    return fmin(angle_at(a, b, c), fmin(angle_at(b, c, a), angle_at(c, a, b)));
}

static double triangle_max_angle(const double a[2], const double b[2], const double c[2])
{
    return fmax(angle_at(a, b, c), fmax(angle_at(b, c, a), angle_at(c, a, b)));
}

void cm_mesh_quality(const cm_mesh *mesh, size_t g, cm_quality *q)
{
    const double deg = 180.0 / CM_PI;
    const double *xy = mesh->xy[g];
    size_t below[3] = {0, 0, 0};
    q->min_angle_deg = 180.0;
    q->max_angle_deg = 0.0;
    for (size_t t = 0; t < mesh->nt; t++) {
        const double *a = xy + 2 * (size_t)mesh->tri[3 * t], *b = xy + 2 * (size_t)mesh->tri[3 * t + 1],
                     *c = xy + 2 * (size_t)mesh->tri[3 * t + 2];
        double lo = cm_triangle_min_angle(a, b, c) * deg;
        q->min_angle_deg = fmin(q->min_angle_deg, lo);
        q->max_angle_deg = fmax(q->max_angle_deg, triangle_max_angle(a, b, c) * deg);
        below[0] += lo < 10.0, below[1] += lo < 15.0, below[2] += lo < 20.0;
    }
    double scale = mesh->nt ? 100.0 / (double)mesh->nt : 0.0;
    q->pct_below_10deg = (double)below[0] * scale;
    q->pct_below_15deg = (double)below[1] * scale;
    q->pct_below_20deg = (double)below[2] * scale;
}

double cm_seconds_now(void)
{
    struct timespec ts;
    timespec_get(&ts, TIME_UTC);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}
