/* Angle statistics of a result (geom/angle.c computes the angles). */
#include <math.h>

#include "api/quality.h"
#include "geom/angle.h"

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
        q->max_angle_deg = fmax(q->max_angle_deg, cm_triangle_max_angle(a, b, c) * deg);
        below[0] += lo < 10.0, below[1] += lo < 15.0, below[2] += lo < 20.0;
    }
    double scale = mesh->nt ? 100.0 / (double)mesh->nt : 0.0;
    q->pct_below_10deg = (double)below[0] * scale;
    q->pct_below_15deg = (double)below[1] * scale;
    q->pct_below_20deg = (double)below[2] * scale;
}
