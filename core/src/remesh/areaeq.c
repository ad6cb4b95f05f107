/* Area equalisation (paper section 3.2, eq. 4). With v at (x, y) the area
 * of triangle (p_i, p_i+1, v) is linear in (x, y); the position minimising
 * the squared deviations from the mean area solves a 2x2 system. */
#include <math.h>

#include "geom/predicates.h"
#include "remesh/areaeq.h"

/* Least-squares position, in coordinates relative to v (for accuracy).
 * Returns 0, or -1 when the system is singular. */
static int area_target(const cm_kmesh *km, size_t g, int32_t v, const cm_ibuf *star, double out[2])
{
    const double *c = cm_kmesh_pos(km, g, v);
    long m = (long)star->n;
    double saa = 0, sab = 0, sbb = 0, sa = 0, sb = 0, sc = 0, sac = 0, sbc = 0;
    for (long i = 0; i < m; i++) {
        const double *p = cm_kmesh_pos(km, g, km->tri[cm_next(star->a[i])]);
        const double *q = cm_kmesh_pos(km, g, km->tri[cm_prev(star->a[i])]);
        double xi = p[0] - c[0], yi = p[1] - c[1], xj = q[0] - c[0], yj = q[1] - c[1];
        /* S_i(x, y) = a x + b y + s with s = S_i(0, 0) */
        double a = 0.5 * (yi - yj), b = 0.5 * (xj - xi), s = 0.5 * (xi * yj - xj * yi);
        saa += a * a, sab += a * b, sbb += b * b;
        sa += a, sb += b, sc += s, sac += a * s, sbc += b * s;
    }
    double mean = sc / (double)m; /* S / k: the star's area shared equally */
    double ra = mean * sa - sac, rb = mean * sb - sbc;
    double det = saa * sbb - sab * sab;
    if (!(fabs(det) > 1e-300) || !(det > 1e-14 * saa * sbb)) return -1;
    out[0] = c[0] + (ra * sbb - rb * sab) / det;
    out[1] = c[1] + (rb * saa - ra * sab) / det;
    return isfinite(out[0]) && isfinite(out[1]) ? 0 : -1;
}

int cm_areaeq_vertex(cm_kmesh *km, size_t g, int32_t v, cm_ibuf *star)
{
    if (cm_kmesh_is_boundary(km, v) || km->vc[v] < 0) return 0;
    long m = cm_kmesh_star(km, v, star);
    if (m < 0) return m == -1 ? -1 : 0;
    double q[2];
    if (area_target(km, g, v, star, q)) return 0;
    const double *c = cm_kmesh_pos(km, g, v);
    if (q[0] == c[0] && q[1] == c[1]) return 0;
    for (long i = 0; i < m; i++) {
        const double *p = cm_kmesh_pos(km, g, km->tri[cm_next(star->a[i])]);
        const double *pn = cm_kmesh_pos(km, g, km->tri[cm_prev(star->a[i])]);
        if (cm_orient2d(q, p, pn) <= 0) return 0;
    }
    cm_kmesh_move(km, g, v, q, star);
    return 1;
}

long cm_areaeq_pass(cm_kmesh *km, cm_work *touched)
{
    cm_ibuf star = {0};
    long moves = 0;
    for (int32_t v = km->n; v < km->nv; v++) {
        int moved = 0;
        for (size_t g = 0; g < km->k && km->vc[v] >= 0; g++) {
            int s = cm_areaeq_vertex(km, g, v, &star);
            if (s < 0) goto oom;
            moved |= s;
        }
        moves += moved;
        if (moved && touched && cm_work_push(touched, v)) goto oom;
    }
    cm_ibuf_free(&star);
    return moves;
oom:
    cm_ibuf_free(&star);
    return -1;
}
