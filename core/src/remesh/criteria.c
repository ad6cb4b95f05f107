/* What the boundary lets the remesher promise. Boundary edges are never
 * split and corners keep their angle, so some triangles cannot reach the
 * target however much the interior is refined; refining them anyway only
 * piles up Steiner vertices. These caps tell the refinement when to stop.
 *
 * For boundary edge e = ab of length L, the isosceles triangle on e of
 * height h is T(h) = {0 < d < h (1 - 2|s| / L)} in coordinates s along e
 * from its midpoint and d inward. The T(h) grow with h, so the tallest that
 * fits is found from the first boundary point entering: a point at (s, d)
 * enters at h = d / (1 - 2|s| / L), a ratio of linear functions along each
 * polygon edge, so only the ends of its clipped pieces matter. */
#include <math.h>
#include <stdlib.h>

#include "remesh/criteria.h"
#include "remesh/kmesh.h"
#include "base/error.h"
#include "base/buf.h"
#include "geom/angle.h"
#include "geom/polytri.h"

typedef struct frame { double mx, my, ux, uy, half; } frame; /* e's midpoint, direction, L/2 */

static double entry_height(const frame *f, double px, double py)
{
    double rx = px - f->mx, ry = py - f->my;
    double s = rx * f->ux + ry * f->uy, d = -rx * f->uy + ry * f->ux;
    double room = 1 - fabs(s) / f->half;
    return d > 0 && room > 0 ? d / room : HUGE_VAL;
}

/* Clips parameter interval [*t0, *t1] to {alpha + beta t > 0}. */
static void clip_interval(double alpha, double beta, double *t0, double *t1)
{
    if (beta == 0) {
        if (!(alpha > 0)) *t0 = 1, *t1 = 0;
    } else if (beta > 0) {
        *t0 = fmax(*t0, -alpha / beta);
    } else {
        *t1 = fmin(*t1, -alpha / beta);
    }
}

/* The lowest h at which segment pq enters T(h); ends shared with e are
 * approached, not taken (the ratio is 0/0 there). */
static double segment_entry(const frame *f, const double *p, const double *q, int p_shared,
                            int q_shared)
{
    double t0 = p_shared ? 1e-7 : 0, t1 = q_shared ? 1 - 1e-7 : 1;
    double rx = p[0] - f->mx, ry = p[1] - f->my, dx = q[0] - p[0], dy = q[1] - p[1];
    double s0 = rx * f->ux + ry * f->uy, sd = dx * f->ux + dy * f->uy;
    double d0 = -rx * f->uy + ry * f->ux, dd = -dx * f->uy + dy * f->ux;
    clip_interval(d0, dd, &t0, &t1);
    clip_interval(f->half - s0, -sd, &t0, &t1);
    clip_interval(f->half + s0, sd, &t0, &t1);
    if (!(t0 <= t1)) return HUGE_VAL;
    double h = fmin(entry_height(f, p[0] + t0 * dx, p[1] + t0 * dy),
                    entry_height(f, p[0] + t1 * dx, p[1] + t1 * dy));
    if (sd != 0) { /* the kink of |s| */
        double ts = -s0 / sd;
        if (ts > t0 && ts < t1) h = fmin(h, entry_height(f, p[0] + ts * dx, p[1] + ts * dy));
    }
    return h;
}

static frame frame_of(const double *a, const double *b)
{
    double L = hypot(b[0] - a[0], b[1] - a[1]);
    return (frame){0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), (b[0] - a[0]) / L, (b[1] - a[1]) / L, 0.5 * L};
}

/* Segment e (from vertex e) against edge i -> j's frame. */
static double entry_of(const cm_mesh *mesh, const double *xy, size_t n, const frame *f, size_t i,
                       size_t j, size_t e)
{
    size_t e1 = cm_loops_next(mesh->loop_start, n, e);
    return segment_entry(f, xy + 2 * e, xy + 2 * e1, e == i || e == j, e1 == i || e1 == j);
}

static double cap_of(const frame *f, double h) { return atan2(2 * h, 2 * f->half); }

double cm_edge_cap_scan(const cm_mesh *mesh, const double *xy, size_t n, size_t i)
{
    size_t j = cm_loops_next(mesh->loop_start, n, i);
    frame f = frame_of(xy + 2 * i, xy + 2 * j);
    double h = f.half * sqrt(3.0); /* equilateral: no need to look higher */
    for (size_t e = 0; e < n; e++)
        if (e != i) h = fmin(h, entry_of(mesh, xy, n, &f, i, j, e));
    return cap_of(&f, h);
}

/* ---- the walk through the triangles ------------------------------------------- */

/* The construction's triangles, shared by the geometries: who is across
 * each edge, which triangle holds each boundary edge, and the stamps of
 * one walk. */
typedef struct walk_mesh {
    const int32_t *tri;
    int32_t *nbr;        /* 3 nt: the triangle across the edge opposite each corner, -1 boundary */
    int32_t *edge_tri;   /* n: the triangle on boundary edge i -> next(i) */
    uint32_t *seen;      /* nt: the last walk that queued it */
    uint32_t walk;
    cm_ibuf stack;
} walk_mesh;

static void walk_free(walk_mesh *w)
{
    free(w->nbr), free(w->edge_tri), free(w->seen);
    cm_ibuf_free(&w->stack);
}

/* 0, CM_NO_MEMORY, or CM_CAPS_NOT_TRIANGULATED (a boundary edge on no
 * triangle); *w is freed unless 0. */
static int walk_build(walk_mesh *w, const cm_mesh *mesh, size_t n)
{
    *w = (walk_mesh){mesh->tri, NULL, NULL, NULL, 0, {0}};
    size_t nt = mesh->nt;
    w->nbr = malloc((3 * nt + 1) * sizeof *w->nbr);
    w->edge_tri = malloc(n * sizeof *w->edge_tri);
    w->seen = calloc(nt + 1, sizeof *w->seen);
    if (!w->nbr || !w->edge_tri || !w->seen || cm_tri_adjacency(mesh->tri, (long)nt, w->nbr)) {
        walk_free(w);
        return CM_NO_MEMORY;
    }
    for (size_t i = 0; i < n; i++) w->edge_tri[i] = -1;
    for (size_t c = 0; c < 3 * nt; c++) {
        int32_t a = mesh->tri[c - c % 3 + (c + 1) % 3]; /* the edge opposite c starts here */
        if (w->nbr[c] < 0 && a >= 0 && (size_t)a < n) w->edge_tri[a] = (int32_t)(c / 3);
    }
    for (size_t i = 0; i < n; i++)
        if (w->edge_tri[i] < 0) {
            walk_free(w);
            return CM_CAPS_NOT_TRIANGULATED;
        }
    return 0;
}

/* A new walk from triangle t: every earlier stamp forgotten, t queued.
 * 0, or -1 (out of memory). */
static int walk_begin(walk_mesh *w, int32_t t, size_t nt)
{
    if (++w->walk == 0) { /* wrapped: forget every stamp */
        for (size_t u = 0; u < nt; u++) w->seen[u] = 0;
        w->walk = 1;
    }
    w->stack.n = 0;
    if (cm_ibuf_push(&w->stack, t)) return -1;
    w->seen[t] = w->walk;
    return 0;
}

typedef struct search {
    const cm_mesh *mesh;
    const double *xy;
    size_t n, i, j;
    frame f;
    double h, pad;
    double q[4];        /* the box around T(h), padded */
    double side[3][3];  /* beyond T(h)'s base and sides: c0 x + c1 y > c2, padded */
} search;

/* T(h) for the current h, grown by `pad` (a margin far above rounding):
 * what lies outside lies that far from T(h). */
static void set_region(search *s)
{
    const frame *f = &s->f;
    const double *a = s->xy + 2 * s->i, *b = s->xy + 2 * s->j;
    double tx = f->mx - s->h * f->uy, ty = f->my + s->h * f->ux; /* the apex */
    s->q[0] = fmin(fmin(a[0], b[0]), tx) - s->pad, s->q[1] = fmin(fmin(a[1], b[1]), ty) - s->pad;
    s->q[2] = fmax(fmax(a[0], b[0]), tx) + s->pad, s->q[3] = fmax(fmax(a[1], b[1]), ty) + s->pad;
    double um = f->ux * f->mx + f->uy * f->my, vm = -f->uy * f->mx + f->ux * f->my;
    /* d = v.(p - m) with v = (-uy, ux): below the base where -d > pad */
    s->side[0][0] = f->uy, s->side[0][1] = -f->ux, s->side[0][2] = s->pad - vm;
    double k = s->h / f->half, limit = s->h + s->pad * sqrt(k * k + 1);
    for (int side = 1; side <= 2; side++) { /* beyond a slope where +-k s + d > h */
        double sg = side == 1 ? 1.0 : -1.0;
        s->side[side][0] = sg * k * f->ux - f->uy, s->side[side][1] = sg * k * f->uy + f->ux;
        s->side[side][2] = limit + sg * k * um + vm;
    }
}

/* Can segment pq meet the padded T(h)? (no when both ends are beyond one
 * of its sides or outside its box) */
static int may_meet(const search *s, const double *p, const double *q)
{
    if (fmax(p[0], q[0]) < s->q[0] || fmin(p[0], q[0]) > s->q[2] || fmax(p[1], q[1]) < s->q[1] ||
        fmin(p[1], q[1]) > s->q[3])
        return 0;
    for (int k = 0; k < 3; k++) {
        const double *c = s->side[k];
        if (c[0] * p[0] + c[1] * p[1] > c[2] && c[0] * q[0] + c[1] * q[1] > c[2]) return 0;
    }
    return 1;
}

/* cm_edge_cap_scan through the triangles. Below the smallest entry height
 * h* the open T(h*) holds no boundary, so it lies in the polygon and the
 * triangles meeting it are reached from edge i's triangle across edges
 * that meet it; the segment that enters at h* is an edge of one of them.
 * The walk crosses every edge that may meet the padded T(h) of the h found
 * so far (T(h*) and the segments within rounding of it included), so it
 * takes the same minimum of the same entries as the scan, over the
 * segments near T(h*) only. */
static double edge_cap(const cm_mesh *mesh, walk_mesh *w, const double *xy, size_t n, size_t i)
{
    size_t j = cm_loops_next(mesh->loop_start, n, i);
    search s = {mesh, xy, n, i, j, frame_of(xy + 2 * i, xy + 2 * j), 0, 0, {0}, {{0}}};
    s.h = s.f.half * sqrt(3.0);
    s.pad = 1e-9 * (2 * s.f.half + fabs(s.f.mx) + fabs(s.f.my));
    size_t p = cm_loops_prev(mesh->loop_start, n, i); /* the neighbours first: h drops fast */
    s.h = fmin(s.h, fmin(entry_of(mesh, xy, n, &s.f, i, j, p), entry_of(mesh, xy, n, &s.f, i, j, j)));
    set_region(&s);
    if (walk_begin(w, w->edge_tri[i], mesh->nt)) return -1;
    while (w->stack.n > 0) {
        int32_t t = w->stack.a[--w->stack.n];
        for (int c = 0; c < 3; c++) {
            int32_t a = w->tri[3 * t + (c + 1) % 3], b = w->tri[3 * t + (c + 2) % 3], u = w->nbr[3 * t + c];
            if (u < 0) { /* a boundary edge, a -> next(a) */
                double h = (size_t)a == i ? HUGE_VAL : entry_of(mesh, xy, n, &s.f, i, j, (size_t)a);
                if (h < s.h) s.h = h, set_region(&s);
            } else if (w->seen[u] != w->walk && may_meet(&s, xy + 2 * a, xy + 2 * b)) {
                w->seen[u] = w->walk;
                if (cm_ibuf_push(&w->stack, u)) return -1;
            }
        }
    }
    return cap_of(&s.f, s.h);
}

/* ---- one triangle further: a vertex near the edge ----------------------------- */

/* Where no boundary edge is split (index mode), the triangle abc on edge
 * i = ab keeps every boundary vertex p out of it, and out of the triangle
 * across its side bc (or ac) too. With p at height h over ab (L long, the
 * inside on its left), seen at angle phi_a from a and phi_b from b, a
 * smallest angle alpha needs one of
 *   min(phi_b, max(phi_b / 2, atan(2 h / L))), the same with phi_a,
 *   the smallest angle of abp, or
 *   that of ab and a's or b's other boundary neighbour (that triangle
 *   left of ab, with no boundary vertex inside)
 * at alpha or above. Proof (bench/CEILING.md, "Index mode: the near-vertex
 * cap"): p not inside abc means beta <= phi_b or gamma <= phi_a (its
 * angles at b, a); say beta. Then c = p, or bc is b's other boundary edge,
 * or the triangle across bc holds the isosceles triangle of base angle
 * alpha on bc, which p must stay out of: phi_b - beta >= alpha (so alpha
 * <= phi_b / 2), or |bc| = L sin(gamma) / sin(beta + gamma) <= |bp|
 * sin(alpha + phi_b - beta) / sin(alpha), which at its least (gamma =
 * alpha) and best (beta = alpha) is tan(alpha) <= 2 h / L. */

/* The largest of the first three for p, in e's frame; HUGE_VAL where p is
 * not left of e (nothing to keep out). */
static double vertex_bound(const frame *f, const double *p)
{
    double rx = p[0] - f->mx, ry = p[1] - f->my;
    double s = rx * f->ux + ry * f->uy, d = -rx * f->uy + ry * f->ux;
    if (!(d > 0)) return HUGE_VAL;
    double phi_a = atan2(d, f->half + s), phi_b = atan2(d, f->half - s), w = atan(d / f->half);
    double by_b = fmin(phi_b, fmax(0.5 * phi_b, w)), by_a = fmin(phi_a, fmax(0.5 * phi_a, w));
    double by_p = fmin(fmin(phi_a, phi_b), CM_PI - phi_a - phi_b);
    return fmax(fmax(by_a, by_b), by_p);
}

static double cross3(const double *a, const double *b, const double *c)
{
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

static double smallest_angle(const double *a, const double *b, const double *c)
{
    double t = CM_PI;
    const double *v[3] = {a, b, c};
    for (int k = 0; k < 3; k++) {
        const double *o = v[k], *p = v[(k + 1) % 3], *q = v[(k + 2) % 3];
        double ux = p[0] - o[0], uy = p[1] - o[1], wx = q[0] - o[0], wy = q[1] - o[1];
        t = fmin(t, atan2(fabs(ux * wy - uy * wx), ux * wx + uy * wy));
    }
    return t;
}

/* A neighbour's triangle t (a, b and the neighbour, counter-clockwise when
 * it is one): its smallest angle, 0 when it is not left of e. */
static double neighbour_triangle(const double *const t[3])
{
    return cross3(t[0], t[1], t[2]) > 0 ? smallest_angle(t[0], t[1], t[2]) : 0;
}

static int strictly_inside(const double *const t[3], const double *p)
{
    return cross3(t[0], t[1], p) > 0 && cross3(t[1], t[2], p) > 0 && cross3(t[2], t[0], p) > 0;
}

/* Only a vertex with all three below cap lowers it: h below cap's
 * isosceles height and phi_a, phi_b below 2 cap, a convex region R (the
 * isosceles triangle of base angle 2 cap cut at that height). Four
 * half-planes c0 s + c1 d > c2 (frame coordinates) beyond it, padded. */
typedef struct near_region { double side[4][3]; } near_region;

static int segment_may_meet(const near_region *r, const frame *f, const double *p, const double *q)
{
    double s[2], d[2];
    const double *e[2] = {p, q};
    for (int m = 0; m < 2; m++) {
        double rx = e[m][0] - f->mx, ry = e[m][1] - f->my;
        s[m] = rx * f->ux + ry * f->uy, d[m] = -rx * f->uy + ry * f->ux;
    }
    for (int k = 0; k < 4; k++) {
        const double *c = r->side[k];
        if (c[0] * s[0] + c[1] * d[0] > c[2] && c[0] * s[1] + c[1] * d[1] > c[2]) return 0;
    }
    return 1;
}

/* Triangles a near-vertex walk reads at most: on a construction of long
 * slivers (a star's fan) every walk would cross the whole mesh, n^2 in
 * all (100 s for two 100,000-vertex stars); a walk cut short only leaves
 * the cap higher. */
#define CM_NEAR_WALK_LIMIT 4096

/* Edge i's cap lowered by the vertices near it, given its isosceles cap
 * (unscaled). The vertices looked at are the corners of the triangles
 * that meet R, reached from edge i's triangle across edges that meet it:
 * a vertex of R left out only leaves the cap higher. A neighbour's
 * triangle counts unless one of those vertices lies inside it (again on
 * the safe side). Returns the cap, or -1 (out of memory). */
static double near_vertex_cap(const cm_mesh *mesh, walk_mesh *w, const double *xy, size_t n, size_t i,
                              double cap)
{
    if (!(cap > 0) || 2 * cap >= CM_PI) return cap;
    size_t j = cm_loops_next(mesh->loop_start, n, i);
    size_t pa = cm_loops_prev(mesh->loop_start, n, i), nb = cm_loops_next(mesh->loop_start, n, j);
    frame f = frame_of(xy + 2 * i, xy + 2 * j);
    double h = f.half * tan(cap), c2 = cos(2 * cap), s2 = sin(2 * cap);
    double pad = 1e-9 * (2 * f.half + fabs(f.mx) + fabs(f.my));
    /* beyond: d < 0; d > h; seen from a above 2 cap: c2 d - s2 (s + half) > 0; from b likewise */
    near_region r = {{{0, -1, pad}, {0, 1, h + pad}, {-s2, c2, s2 * f.half + pad}, {s2, c2, s2 * f.half + pad}}};
    const double *a = xy + 2 * i, *b = xy + 2 * j;
    const double *ta[3] = {xy + 2 * pa, a, b}, *tb[3] = {a, b, xy + 2 * nb};
    double best = HUGE_VAL;
    int void_a = 0, void_b = 0;
    if (walk_begin(w, w->edge_tri[i], mesh->nt)) return -1;
    for (long read = 0; w->stack.n > 0 && read < CM_NEAR_WALK_LIMIT; read++) {
        int32_t t = w->stack.a[--w->stack.n];
        for (int c = 0; c < 3; c++) {
            int32_t v = w->tri[3 * t + c];
            if (v >= 0 && (size_t)v < n && (size_t)v != i && (size_t)v != j) {
                const double *p = xy + 2 * v;
                best = fmin(best, vertex_bound(&f, p));
                void_a |= (size_t)v != pa && strictly_inside(ta, p);
                void_b |= (size_t)v != nb && strictly_inside(tb, p);
            }
            int32_t e0 = w->tri[3 * t + (c + 1) % 3], e1 = w->tri[3 * t + (c + 2) % 3], u = w->nbr[3 * t + c];
            if (u >= 0 && w->seen[u] != w->walk && segment_may_meet(&r, &f, xy + 2 * e0, xy + 2 * e1)) {
                w->seen[u] = w->walk;
                if (cm_ibuf_push(&w->stack, u)) return -1;
            }
        }
    }
    double escape = fmax(void_a ? 0 : neighbour_triangle(ta), void_b ? 0 : neighbour_triangle(tb));
    return fmin(cap, fmax(best, escape));
}

int cm_near_vertex_caps(const cm_mesh *mesh, size_t n, cm_progress *progress, double *bcap)
{
    walk_mesh w;
    int built = walk_build(&w, mesh, n);
    if (built) return built;
    for (size_t g = 0; g < mesh->k; g++)
        for (size_t i = 0; i < n; i++) {
            if (cm_progress_check(progress)) {
                walk_free(&w);
                return CM_CANCELLED;
            }
            double cap = near_vertex_cap(mesh, &w, mesh->xy[g], n, i, bcap[i]);
            if (cap < 0) {
                walk_free(&w);
                return CM_NO_MEMORY;
            }
            bcap[i] = cap;
        }
    walk_free(&w);
    return 0;
}

int cm_boundary_caps(const cm_mesh *mesh, size_t n, cm_progress *progress, double *bcap,
                     double *vcap)
{
    for (size_t i = 0; i < n; i++) bcap[i] = vcap[i] = CM_PI;
    walk_mesh w;
    int built = walk_build(&w, mesh, n);
    if (built) return built;
    for (size_t g = 0; g < mesh->k; g++) {
        const double *xy = mesh->xy[g];
        for (size_t i = 0; i < n; i++) {
            if (cm_progress_check(progress)) {
                walk_free(&w);
                return CM_CANCELLED;
            }
            double cap = edge_cap(mesh, &w, xy, n, i);
            if (cap < 0) {
                walk_free(&w);
                return CM_NO_MEMORY;
            }
            bcap[i] = fmin(bcap[i], cap);
            double c = cm_corner_angle(xy + 2 * cm_loops_prev(mesh->loop_start, n, i), xy + 2 * i,
                                       xy + 2 * cm_loops_next(mesh->loop_start, n, i));
            vcap[i] = fmin(vcap[i], 0.5 * c);
        }
    }
    walk_free(&w);
    return 0;
}
