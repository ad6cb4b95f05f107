/* Vertex smoothing, each geometry on its own (paper section 3.1):
 * Laplacian, angle-based (Zhou and Shimada), weighted angle-based (eq. 2),
 * plain or "smart", and the combined scheme. */
#include <math.h>

#include "geom/predicates.h"
#include "remesh/smooth.h"
#include "remesh/criteria.h"

/* Halvings of a rejected smart step toward the proposed position. */
#define CM_SMART_TRIES 3
/* A smart move must gain this much (radians, about 0.06 degrees): smaller
 * gains only ripple through the neighbours and change nothing that
 * matters. */
#define CM_SMOOTH_GAIN 1e-3
/* Below this smallest angle (radians, about 6e-5 degrees; the bench's
 * sharpest input corner is 2e-3) a move need only double it: a fan of
 * slivers onto a run of boundary vertices crowded to 1e-8 of the
 * polygon's size rises in steps no absolute gain allows. */
#define CM_SMOOTH_SLIVER 1e-6
/* Vertices of higher degree are left where they are. */
#define CM_SMOOTH_MAX_DEGREE 128

/* The smallest angle a smart move or the search must reach from `before`. */
static double smooth_aim(double before)
{
    return before < CM_SMOOTH_SLIVER ? 2 * before : before + CM_SMOOTH_GAIN;
}

/* v's link polygon in geometry g, counter-clockwise; p[m] repeats p[0]. */
typedef struct ring {
    const double *c;                      /* v itself */
    double p[CM_SMOOTH_MAX_DEGREE + 1][2]; /* copied: the scans read them in order */
    double link2[CM_SMOOTH_MAX_DEGREE];   /* |p[i+1] - p[i]|^2: the same for every trial point */
    long m;
    long worst;                           /* triangle (p[i], p[i+1]) last found smallest */
    double den_lo;                        /* > 0: ring_sin2's den is at least this, above
                                             CM_ANGLE_SAFE_LO, wherever the trial point */
} ring;

static int ring_of(const cm_kmesh *km, size_t g, int32_t v, const cm_ibuf *star, ring *r)
{
    r->m = (long)star->n;
    if (r->m < 3 || r->m > CM_SMOOTH_MAX_DEGREE) return -1;
    r->c = cm_kmesh_pos(km, g, v);
    for (long i = 0; i <= r->m; i++) {
        const double *q = cm_kmesh_pos(km, g, km->tri[cm_next(star->a[i < r->m ? i : 0])]);
        r->p[i][0] = q[0], r->p[i][1] = q[1];
    }
    double link_lo = HUGE_VAL;
    for (long i = 0; i < r->m; i++) {
        double dx = r->p[i + 1][0] - r->p[i][0], dy = r->p[i + 1][1] - r->p[i][1];
        r->link2[i] = dx * dx + dy * dy;
        if (r->link2[i] < link_lo) link_lo = r->link2[i];
    }
    /* ring_sin2's den multiplies the two longest squared sides: one is at
     * least the link edge's, the other at least a quarter of it (triangle
     * inequality), so den >= link2^2 / 4 but for rounding. */
    r->den_lo = link_lo > 0x1p-498 ? 0.24 * link_lo * link_lo : 0;
    r->worst = 0;
    return 0;
}

static void laplacian_target(const ring *r, double out[2])
{
    double x = 0, y = 0;
    for (long i = 0; i < r->m; i++) x += r->p[i][0], y += r->p[i][1];
    out[0] = x / (double)r->m, out[1] = y / (double)r->m;
}

/* Neighbour p (ring neighbours pn next, pp previous) rotates the edge
 * p -> v (v at c) onto the bisector of the link polygon's angle alpha at
 * p: the rotated point t, and alpha when power is not 0. Where v's
 * triangles at p are counter-clockwise (a valid star) both parts of alpha
 * lie in (0, pi), and with u, w the unit vectors from p to pn and pp the
 * bisector is rot90(u - w) / |u - w| and tan(alpha / 2) = |u - w|^2 /
 * (2 u x w): no trigonometry but one atan2. 0, or -1 where the star is
 * not valid there or the vectors are too short or long for that. */
static int bisector_point(const double *c, const double *p, const double *pn, const double *pp, double power,
                          double *alpha, double t[2])
{
    double dx = c[0] - p[0], dy = c[1] - p[1];
    double nx = pn[0] - p[0], ny = pn[1] - p[1], qx = pp[0] - p[0], qy = pp[1] - p[1];
    double nn = nx * nx + ny * ny, qq = qx * qx + qy * qy, dd = dx * dx + dy * dy;
    if (!(nx * dy - ny * dx > 0 && dx * qy - dy * qx > 0 && nn > CM_ANGLE_SAFE_LO && nn < CM_ANGLE_SAFE_HI &&
          qq > CM_ANGLE_SAFE_LO && qq < CM_ANGLE_SAFE_HI && dd < CM_ANGLE_SAFE_HI))
        return -1;
    double rn = 1 / sqrt(nn), rq = 1 / sqrt(qq);
    double ux = nx * rn, uy = ny * rn, wx = qx * rq, wy = qy * rq;
    double ex = ux - wx, ey = uy - wy, ee = ex * ex + ey * ey;
    if (!(ee > 0x1p-60)) return -1;
    double scale = sqrt(dd / ee);
    t[0] = p[0] - ey * scale, t[1] = p[1] + ex * scale;
    *alpha = power == 0 ? 0 : 2 * atan2(0.5 * ee, ux * wy - uy * wx);
    return 0;
}

/* The average of the neighbours' rotated points, weighted by
 * 1 / alpha_i^power (eq. 1: power 0; eq. 2: power 2); the angles measured
 * as they are where bisector_point cannot (a star being untangled). */
static int angle_target(const ring *r, double power, double out[2])
{
    const double *c = r->c;
    double x = 0, y = 0, wsum = 0;
    for (long i = 0; i < r->m; i++) {
        const double *p = r->p[i], *pn = r->p[i + 1], *pp = r->p[i ? i - 1 : r->m - 1];
        double alpha, t[2];
        if (bisector_point(c, p, pn, pp, power, &alpha, t)) {
            double dx = c[0] - p[0], dy = c[1] - p[1];
            double nx = pn[0] - p[0], ny = pn[1] - p[1], qx = pp[0] - p[0], qy = pp[1] - p[1];
            double a1 = atan2(nx * dy - ny * dx, nx * dx + ny * dy); /* from p_{i+1} to v */
            double a2 = atan2(dx * qy - dy * qx, dx * qx + dy * qy); /* from v to p_{i-1} */
            double beta = 0.5 * (a2 - a1), cb = cos(beta), sb = sin(beta);
            alpha = a1 + a2;
            t[0] = p[0] + cb * dx - sb * dy, t[1] = p[1] + sb * dx + cb * dy;
        }
        double w = power == 0   ? 1.0
                   : power == 2 ? 1.0 / fmax(alpha * alpha, 1e-12)
                                : 1.0 / fmax(pow(fabs(alpha), power), 1e-12);
        x += w * t[0];
        y += w * t[1];
        wsum += w;
    }
    if (!(wsum > 0) || !isfinite(x) || !isfinite(y)) return -1;
    out[0] = x / wsum, out[1] = y / wsum;
    return 0;
}

/* The power of an angle-based method's weights: eq. 1's 0, eq. 2's 2. */
static double power_of(cm_smoothing method) { return method == CM_SMOOTH_ANGLE ? 0 : 2; }

/* The target of method, an angle-based one with weights 1 / alpha_i^power. */
static int target_of(const ring *r, cm_smoothing method, double power, double out[2])
{
    switch (method) {
    case CM_SMOOTH_LAPLACIAN: laplacian_target(r, out); return 0;
    case CM_SMOOTH_ANGLE:
    case CM_SMOOTH_WEIGHTED:
    case CM_SMOOTH_COMBINED: return angle_target(r, power, out);
    }
    return -1;
}

int cm_smooth_target(const cm_kmesh *km, size_t g, int32_t v, cm_smoothing method,
                     const cm_ibuf *star, double out[2])
{
    ring r;
    return ring_of(km, g, v, star, &r) ? -1 : target_of(&r, method, power_of(method), out);
}

/* cm_triangle_min_angle_sin2(q, p[i], p[i+1]), the same arithmetic with
 * the link edge's squared length taken from the ring; or, when that is
 * certainly below `floor` (> 0), floor itself without the division.
 * `bounded`: den is known to be at least r->den_lo and floor * den, when
 * positive, above 2^-900, so only overflow needs a test. */
static inline double ring_sin2(const ring *r, const double q[2], long i, double floor, int bounded)
{
    const double *b = r->p[i], *c = r->p[i + 1];
    double abx = b[0] - q[0], aby = b[1] - q[1], cax = q[0] - c[0], cay = q[1] - c[1];
    double lab = abx * abx + aby * aby, lbc = r->link2[i], lca = cax * cax + cay * cay;
    double cross = abx * cay - aby * cax, den = cm_sin2_den(lab, lbc, lca);
    if (bounded) {
        if (!(den < CM_ANGLE_SAFE_HI)) return cm_triangle_min_angle_sin2_wide(q, b, c);
        if (cross * cross < floor * den * (1 - 0x1p-40)) return floor;
        return cross * cross / den;
    }
    if (!(den > CM_ANGLE_SAFE_LO && den < CM_ANGLE_SAFE_HI) && den != 0) return cm_triangle_min_angle_sin2_wide(q, b, c);
    double bar = floor * den;
    if (bar > 0x1p-900 && cross * cross < bar * (1 - 0x1p-40)) return floor; /* the rounded quotient is below floor */
    return den > 0 ? cross * cross / den : 0.0;
}

/* Smallest angle of v's triangles with v at q, as sin^2 (monotone below
 * 90 degrees, no atan2: this runs for every candidate position). Only
 * values above `floor` matter to the callers: the scan stops at the first
 * triangle at or below it and returns a value at or below floor. */
static inline double star_scan(const ring *r, const double q[2], double floor, int bounded, long *worst)
{
    double lo = 1.0;
    long m = r->m, w = *worst, lo_at = w;
    for (long i = w; i < m; i++) { /* from the last worst: it fails first */
        double s = ring_sin2(r, q, i, floor, bounded);
        if (s < lo) lo = s, lo_at = i;
        if (!(lo > floor)) goto done;
    }
    for (long i = 0; i < w; i++) {
        double s = ring_sin2(r, q, i, floor, bounded);
        if (s < lo) lo = s, lo_at = i;
        if (!(lo > floor)) break;
    }
done:
    *worst = lo_at;
    return lo;
}

/* May the scans with this floor take ring_sin2's bounded path? */
static int scan_bounded(const ring *r, double floor)
{
    return r->den_lo > 0 && (floor <= 0 || floor * r->den_lo > 0x1p-900);
}

/* bounded: scan_bounded(r, floor), found once for many trial points;
 * *worst: where the scan starts, then the triangle it found smallest. */
static inline double star_sin2_above(const ring *r, const double q[2], double floor, int bounded, long *worst)
{
    return bounded ? star_scan(r, q, floor, 1, worst) : star_scan(r, q, floor, 0, worst);
}

static double star_sin2(ring *r, const double q[2])
{
    return star_sin2_above(r, q, -1.0, scan_bounded(r, -1.0), &r->worst);
}

double cm_smooth_star_sin2(const cm_kmesh *km, size_t g, int32_t v, const cm_ibuf *star, const double q[2],
                           double floor, long start)
{
    ring r;
    if (ring_of(km, g, v, star, &r)) return NAN;
    long worst = start % r.m;
    return star_sin2_above(&r, q, floor, scan_bounded(&r, floor), &worst);
}

/* Is v at q strictly inside its link polygon's kernel (every triangle
 * counter-clockwise)? Exact: a triangle whose determinant clears its
 * rounding by a wide margin (products far from overflow and underflow;
 * 1e-12 relative, thousands of times orient2d's own error bound, fused
 * multiply-add or not) needs no exact predicate. */
static int star_valid(const ring *r, const double q[2])
{
    for (long i = 0; i < r->m; i++) {
        const double *b = r->p[i], *c = r->p[i + 1];
        double left = (b[0] - q[0]) * (c[1] - q[1]), right = (b[1] - q[1]) * (c[0] - q[0]);
        double size = fabs(left) + fabs(right);
        if (size > 0x1p-900 && size < 0x1p900 && left - right > 1e-12 * size) continue;
        if (cm_orient2d(q, b, c) <= 0) return 0;
    }
    return 1;
}

static double sin2_to_angle(double s) { return asin(sqrt(fmin(1.0, fmax(0.0, s)))); }

/* Is a smallest angle of `want` radians out of v's reach? Wherever v
 * goes in its kernel, its two triangles at link vertex p_i split the link
 * polygon's angle there, so the smallest angle stays below half the
 * smallest link angle: a move that must reach more is not looked for.
 * Only link angles clearly below 2 want count (cosines compared squared,
 * with a margin for the rounding). */
static int out_of_reach(const ring *r, double want)
{
    double a2 = 2 * want - 1e-9;
    if (!(a2 > 0 && a2 < 0.5 * CM_PI)) return 0;
    double c = cos(a2), c2 = c * c * (1 + 1e-12);
    for (long i = 0; i < r->m; i++) {
        const double *p = r->p[i], *pn = r->p[i + 1], *pp = r->p[i ? i - 1 : r->m - 1];
        double ux = pn[0] - p[0], uy = pn[1] - p[1], wx = pp[0] - p[0], wy = pp[1] - p[1];
        double cross = ux * wy - uy * wx, dot = ux * wx + uy * wy;
        if (cross > 0 && dot > 0 && dot * dot > c2 * (ux * ux + uy * uy) * (wx * wx + wy * wy))
            return 1;
    }
    return 0;
}

/* Tries q (and, if smart, points between v and q): moves v to the first
 * acceptable one. Returns 1 if moved. */
static int try_move(cm_kmesh *km, size_t g, int32_t v, const cm_ibuf *star, ring *r,
                    const double q[2], int smart, double before)
{
    const double *c = r->c;
    double p[2] = {q[0], q[1]};
    /* Just below sin^2 of the angle a smart move must beat: positions at
     * or under it fail the test without the full scan or the asin. */
    double s = smart ? sin(fmin(smooth_aim(before), 0.5 * CM_PI)) : 0, floor = s * s * (1 - 1e-9);
    int bounded = scan_bounded(r, floor);
    for (int attempt = 0; attempt < (smart ? CM_SMART_TRIES : 1); attempt++) {
        if (p[0] == c[0] && p[1] == c[1]) return 0;
        double sp = smart ? star_sin2_above(r, p, floor, bounded, &r->worst) : 0;
        if ((!smart || (sp > floor && sin2_to_angle(sp) > smooth_aim(before))) && star_valid(r, p)) {
            cm_kmesh_move(km, g, v, p, star);
            return 1;
        }
        p[0] = 0.5 * (p[0] + c[0]), p[1] = 0.5 * (p[1] + c[1]);
    }
    return 0;
}

/* The star of v at its place: sin^2 of its smallest angle, the triangle
 * holding it, the angle itself, and whether a gain is in reach at all
 * (out_of_reach): what the smoothing and the search both start from. */
typedef struct star_start {
    double sin2, angle;
    long worst;
    int reachable;
} star_start;

static void start_of(ring *r, star_start *s)
{
    s->sin2 = star_sin2(r, r->c), s->worst = r->worst, s->angle = sin2_to_angle(s->sin2);
    s->reachable = !out_of_reach(r, smooth_aim(s->angle));
}

/* The smoothing move of v in its ring r: to method's target, then (the
 * combined method) the Laplacian one; if smart, only where the smallest
 * angle around v reaches smooth_aim(before). */
static int smooth_in_ring(cm_kmesh *km, size_t g, int32_t v, cm_smoothing method, double power, int smart,
                          const cm_ibuf *star, ring *r, double before)
{
    double q[2];
    if (target_of(r, method, power, q) == 0 && try_move(km, g, v, star, r, q, smart, before)) return 1;
    if (method != CM_SMOOTH_COMBINED) return 0;
    laplacian_target(r, q);
    return try_move(km, g, v, star, r, q, smart, before);
}

/* v in geometry g moved by method from its star, the angle-based weights' power given. */
static int smooth_star(cm_kmesh *km, size_t g, int32_t v, cm_smoothing method, double power, int smart,
                       const cm_ibuf *star)
{
    ring r;
    if (ring_of(km, g, v, star, &r)) return 0;
    if (!smart) return smooth_in_ring(km, g, v, method, power, 0, star, &r, 0);
    star_start s;
    start_of(&r, &s);
    return s.reachable && smooth_in_ring(km, g, v, method, power, 1, star, &r, s.angle);
}

/* cm_smooth_vertex with the angle-based weights' power given. */
static int smooth_vertex(cm_kmesh *km, size_t g, int32_t v, cm_smoothing method, double power, int smart,
                         cm_ibuf *star)
{
    if (cm_kmesh_is_boundary(km, v) || km->vc[v] < 0) return 0;
    long m = cm_kmesh_star(km, v, star);
    if (m < 0) return m == -1 ? -1 : 0;
    return smooth_star(km, g, v, method, power, smart, star);
}

int cm_smooth_vertex(cm_kmesh *km, size_t g, int32_t v, cm_smoothing method, int smart,
                     cm_ibuf *star)
{
    return smooth_vertex(km, g, v, method, power_of(method), smart, star);
}

/* The search found no gain for v in geometry g. Returns 0. */
static int no_gain(cm_kmesh *km, size_t g, int32_t v)
{
    unsigned dirty = km->vdirty[v];
    if (!cm_dirty_search_shared(g)) dirty &= ~cm_dirty_search(g); /* till its star in g changes */
    if (g + 1 == km->k) dirty &= ~CM_DIRTY_OPTIMIZE; /* optimal in every geometry, till a change */
    cm_kmesh_set_dirty(km, v, dirty);
    return 0;
}

/* Steps of the pattern search below. */
#define CM_OPTIMIZE_STEPS 10

/* The pattern search of v in its ring r, from its start s. */
static int search_in_ring(cm_kmesh *km, size_t g, int32_t v, const cm_ibuf *star, ring *r, const star_start *s)
{
    static const double dir[8][2] = {{1, 0}, {0.7071067811865476, 0.7071067811865476}, {0, 1},
                                     {-0.7071067811865476, 0.7071067811865476}, {-1, 0},
                                     {-0.7071067811865476, -0.7071067811865476}, {0, -1},
                                     {0.7071067811865476, -0.7071067811865476}};
    if (!s->reachable) return no_gain(km, g, v);
    r->worst = s->worst; /* as the scan at r->c left it (the smoothing's trials move it) */
    double best[2] = {r->c[0], r->c[1]}, q = s->sin2, near2 = HUGE_VAL, step = HUGE_VAL;
    for (long i = 0; i < r->m; i++) {
        double dx = r->p[i][0] - best[0], dy = r->p[i][1] - best[1];
        near2 = fmin(near2, dx * dx + dy * dy);
    }
    for (long i = 0; i < r->m; i++) { /* the distance to the nearest neighbour: hypot only near the least square */
        double dx = r->p[i][0] - best[0], dy = r->p[i][1] - best[1];
        if (!(dx * dx + dy * dy > near2 * (1 + 1e-9))) step = fmin(step, hypot(dx, dy));
    }
    step *= 0.25;
    long from[8]; /* per direction: the triangle that last stopped its scan, likely again */
    for (int d = 0; d < 8; d++) from[d] = r->worst;
    int bounded = scan_bounded(r, q);
    for (int it = 0; it < CM_OPTIMIZE_STEPS && step > 0; it++) {
        int improved = 0;
        for (int d = 0; d < 8; d++) {
            double p[2] = {best[0] + step * dir[d][0], best[1] + step * dir[d][1]};
            double qp = star_sin2_above(r, p, q, bounded, &from[d]);
            if (qp > q && star_valid(r, p))
                q = qp, best[0] = p[0], best[1] = p[1], improved = 1, bounded = scan_bounded(r, q);
        }
        if (!improved) step *= 0.5;
    }
    if (!(sin2_to_angle(q) > smooth_aim(s->angle))) return no_gain(km, g, v);
    cm_kmesh_move(km, g, v, best, star);
    return 1;
}

/* May the search run on v in g, or has it found no gain there since
 * nothing changed (then said so in the flags)? */
static int search_wanted(cm_kmesh *km, size_t g, int32_t v)
{
    if (!(km->vdirty[v] & CM_DIRTY_OPTIMIZE)) return 0;
    if (!(km->vdirty[v] & cm_dirty_search(g))) return no_gain(km, g, v); /* its star in g is as it found none */
    return 1;
}

int cm_smooth_optimize(cm_kmesh *km, size_t g, int32_t v, cm_ibuf *star)
{
    if (cm_kmesh_is_boundary(km, v) || km->vc[v] < 0 || !search_wanted(km, g, v)) return 0;
    long m = cm_kmesh_star(km, v, star);
    if (m < 0) return m == -1 ? -1 : 0;
    ring r;
    if (ring_of(km, g, v, star, &r)) return 0;
    star_start s;
    start_of(&r, &s);
    return search_in_ring(km, g, v, star, &r, &s);
}

int cm_smooth_then_search(cm_kmesh *km, size_t g, int32_t v, cm_smoothing method, const cm_ibuf *star, int search)
{
    unsigned bit = cm_dirty_smooth(g);
    ring r;
    star_start s;
    int have_ring = 0;
    if (km->vdirty[v] & bit && ring_of(km, g, v, star, &r) == 0) {
        have_ring = 1;
        start_of(&r, &s);
        if (s.reachable && smooth_in_ring(km, g, v, method, power_of(method), 1, star, &r, s.angle)) return 1;
    }
    if (!cm_dirty_smooth_shared(g)) cm_kmesh_set_dirty(km, v, km->vdirty[v] & ~bit);
    if (!search || !search_wanted(km, g, v)) return 0;
    if (!have_ring) {
        if (ring_of(km, g, v, star, &r)) return 0;
        start_of(&r, &s);
    }
    return search_in_ring(km, g, v, star, &r, &s);
}

/* One sweep of method, an angle-based one with weights 1 / alpha_i^power. */
static long sweep(cm_kmesh *km, cm_smoothing method, double power, int smart)
{
    cm_ibuf star = {0};
    long moves = 0;
    for (int32_t v = km->n; v < km->nv; v++)
        for (size_t g = 0; g < km->k && km->vc[v] >= 0; g++) {
            int s = smooth_vertex(km, g, v, method, power, smart, &star);
            if (s < 0) {
                cm_ibuf_free(&star);
                return -1;
            }
            moves += s;
        }
    cm_ibuf_free(&star);
    return moves;
}

long cm_smooth_pass(cm_kmesh *km, cm_smoothing method, int smart)
{
    return sweep(km, method, power_of(method), smart);
}

long cm_smooth_pass_power(cm_kmesh *km, double power) { return sweep(km, CM_SMOOTH_WEIGHTED, power, 0); }
