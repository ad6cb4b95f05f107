/* Angle statistics of a result (geom/angle.c computes the angles). */
#include <math.h>

#include "api/quality.h"
#include "geom/angle.h"

/* The least double x whose degrees (x * deg, rounded) reach d: a
 * smallest angle counts below d degrees exactly when it is below x. */
static double radians_reaching(double d, double deg)
{
    double x = d / deg;
    while (x * deg >= d) x = nextafter(x, 0.0);
    while (x * deg < d) x = nextafter(x, 1.0);
    return x;
}

/* A triangle's smallest angle is needed as a value only where it may be
 * the least so far; the counts need only which bounds it passes, and the
 * largest angle only where it may be the greatest: the rest is decided
 * without atan2, exactly as the comparisons of the values would. */
void cm_mesh_quality(const cm_mesh *mesh, size_t g, cm_quality *q)
{
    const double deg = 180.0 / CM_PI;
    const double degrees[3] = {10.0, 15.0, 20.0};
    const double *xy = mesh->xy[g];
    size_t below[3] = {0, 0, 0};
    /* counted[j]: a smallest angle counts below degrees[j] unless above it */
    double counted[3], tan_counted[3];
    for (int j = 0; j < 3; j++)
        counted[j] = nextafter(radians_reaching(degrees[j], deg), 0.0), tan_counted[j] = tan(counted[j]);
    /* the extremes so far in radians (-1: none yet); bound: the counted
     * bounds with the least angle in its place (at least) while it is
     * below pi/2, where the tangent test holds (a smallest angle is at
     * most pi/3 but in degenerate triangles) */
    double least = -1.0, greatest = -1.0, cos_greatest = 0.0, bound[4], tan_bound[4];
    int at = -1;
    q->min_angle_deg = 180.0;
    q->max_angle_deg = 0.0;
    for (size_t t = 0; t < mesh->nt; t++) {
        const double *a = xy + 2 * (size_t)mesh->tri[3 * t], *b = xy + 2 * (size_t)mesh->tri[3 * t + 1],
                     *c = xy + 2 * (size_t)mesh->tri[3 * t + 2];
        if (!(greatest >= 0.0 && cm_triangle_max_angle_below(a, b, c, greatest, cos_greatest))) {
            double hi = cm_triangle_max_angle(a, b, c);
            if (hi > greatest) greatest = hi, cos_greatest = cos(hi);
            q->max_angle_deg = fmax(q->max_angle_deg, hi * deg);
        }
        if (at >= 0) {
            int passed = cm_triangle_min_angle_rank(a, b, c, bound, tan_bound, 4);
            if (passed > at) { /* above the least: the counts alone */
                for (int j = 0; j < 3; j++) below[j] += passed <= (j < at ? j : j + 1);
                continue;
            }
        }
        double rad = cm_triangle_min_angle(a, b, c), lo = rad * deg;
        if (least < 0.0 || rad < least) {
            least = rad, at = -1;
            if (least < 1.5)
                for (int j = 0, i = 0; i < 4; i++) {
                    int here = at < 0 && (j == 3 || least <= counted[j]);
                    bound[i] = here ? least : counted[j], tan_bound[i] = here ? tan(least) : tan_counted[j];
                    if (here) at = i; else j++;
                }
        }
        q->min_angle_deg = fmin(q->min_angle_deg, lo);
        below[0] += lo < 10.0, below[1] += lo < 15.0, below[2] += lo < 20.0;
    }
    double scale = mesh->nt ? 100.0 / (double)mesh->nt : 0.0;
    q->pct_below_10deg = (double)below[0] * scale;
    q->pct_below_15deg = (double)below[1] * scale;
    q->pct_below_20deg = (double)below[2] * scale;
}
