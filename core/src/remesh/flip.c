/* Compatible edge flips: the new diagonal must exist in every geometry (the
 * quad strictly convex everywhere) and raise the worst angle of the pair. */
#include <math.h>

#include "remesh/flip.h"
#include "remesh/criteria.h"

int cm_flip_try(cm_kmesh *km, int32_t c)
{
    int32_t o = km->opp[c];
    if (o < 0 || km->tri[c] < 0) return 0;
    int32_t v0 = km->tri[c], v1 = km->tri[cm_next(c)], v2 = km->tri[cm_prev(c)], v3 = km->tri[o];
    /* Every new triangle's smallest angle must beat the pair's by eps
     * (their keys are smallest angles over the geometries). */
    double bound = fmin(km->tkey[c / 3], km->tkey[o / 3]) + CM_ANGLE_EPS, tan_bound = tan(bound);
    for (size_t g = 0; g < km->k; g++) {
        const double *p0 = cm_kmesh_pos(km, g, v0), *p1 = cm_kmesh_pos(km, g, v1),
                     *p2 = cm_kmesh_pos(km, g, v2), *p3 = cm_kmesh_pos(km, g, v3);
        if (!cm_triangle_min_angle_above(p0, p1, p3, bound, tan_bound) ||
            !cm_triangle_min_angle_above(p3, p2, p0, bound, tan_bound))
            return 0;
    }
    /* Exact: both new triangles counter-clockwise = quad strictly convex. */
    for (size_t g = 0; g < km->k; g++)
        if (!cm_kmesh_tri_ok(km, g, v0, v1, v3) || !cm_kmesh_tri_ok(km, g, v3, v2, v0)) return 0;
    cm_kmesh_flip(km, c);
    return 1;
}

int cm_flip_if_valid(cm_kmesh *km, int32_t c)
{
    int32_t o = km->opp[c];
    if (o < 0 || km->tri[c] < 0) return 0;
    int32_t v0 = km->tri[c], v1 = km->tri[cm_next(c)], v2 = km->tri[cm_prev(c)], v3 = km->tri[o];
    for (size_t g = 0; g < km->k; g++)
        if (!cm_kmesh_tri_ok(km, g, v0, v1, v3) || !cm_kmesh_tri_ok(km, g, v3, v2, v0)) return 0;
    cm_kmesh_flip(km, c);
    return 1;
}

int cm_flip_queue_all(const cm_kmesh *km, cm_work *edges)
{
    for (int32_t c = 0; c < 3 * km->nt; c++)
        if (km->tri[c] >= 0 && km->opp[c] > c && cm_work_push(edges, c)) return -1;
    return 0;
}

int cm_flip_queue_around(const cm_kmesh *km, int32_t v, cm_work *edges, cm_ibuf *star)
{
    long m = cm_kmesh_star(km, v, star);
    if (m < 0) return -1;
    for (long i = 0; i < m; i++) {
        int32_t c = star->a[i];
        if (cm_work_push(edges, c) || cm_work_push(edges, cm_next(c)) ||
            cm_work_push(edges, cm_prev(c)))
            return -1;
    }
    return 0;
}

long cm_flip_queue(cm_kmesh *km, cm_work *edges, cm_work *touched)
{
    long flips = 0;
    for (int32_t c; (c = cm_work_pop(edges)) >= 0;) {
        if (km->tri[c] < 0 || !cm_flip_try(km, c)) continue;
        flips++;
        /* After the flip c sits at v0 in (v0 v1 v3) and the new diagonal
         * v0-v3 is opposite next(c); its partner's triangle is (v3 v2 v0)
         * with corner o at v3. Requeue the quad's four outer edges. */
        int32_t o = cm_prev(km->opp[cm_next(c)]);
        int32_t around[4] = {c, cm_prev(c), o, cm_prev(o)};
        for (int i = 0; i < 4; i++)
            if (cm_work_push(edges, around[i])) return -1;
        if (touched)
            for (int i = 0; i < 3; i++)
                if (cm_work_push(touched, km->tri[3 * (c / 3) + i]) ||
                    cm_work_push(touched, km->tri[3 * (o / 3) + i]))
                    return -1;
    }
    return flips;
}
