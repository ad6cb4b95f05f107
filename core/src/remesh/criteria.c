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
#include "geom/polytri.h"

static double corner_angle(const double *a, const double *b, const double *c)
{
    double ux = c[0] - b[0], uy = c[1] - b[1], vx = a[0] - b[0], vy = a[1] - b[1];
    double t = atan2(ux * vy - uy * vx, ux * vx + uy * vy);
    return t < 0 ? t + 2 * CM_PI : t;
}

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
    if (++w->walk == 0) { /* wrapped: forget every stamp */
        for (size_t t = 0; t < mesh->nt; t++) w->seen[t] = 0;
        w->walk = 1;
    }
    w->stack.n = 0;
    if (cm_ibuf_push(&w->stack, w->edge_tri[i])) return -1;
    w->seen[w->edge_tri[i]] = w->walk;
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

int cm_boundary_caps(const cm_mesh *mesh, size_t n, cm_progress *progress, double *bcap,
                     double *vcap)
{
    for (size_t i = 0; i < n; i++) bcap[i] = vcap[i] = CM_PI;
    walk_mesh w;
    if (walk_build(&w, mesh, n)) return CM_NO_MEMORY;
    for (size_t i = 0; i < n; i++)
        if (w.edge_tri[i] < 0) {
            walk_free(&w);
            return CM_CAPS_NOT_TRIANGULATED;
        }
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
            double c = corner_angle(xy + 2 * cm_loops_prev(mesh->loop_start, n, i), xy + 2 * i,
                                    xy + 2 * cm_loops_next(mesh->loop_start, n, i));
            vcap[i] = fmin(vcap[i], 0.5 * c);
        }
    }
    walk_free(&w);
    return 0;
}
