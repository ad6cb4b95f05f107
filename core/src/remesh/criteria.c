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
#include "geom/boxtree.h"

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

/* ---- the indexed search ----------------------------------------------------- */

typedef struct search {
    const cm_mesh *mesh;
    const double *xy;
    size_t n, i, j;
    frame f;
    double h, pad;
} search;

/* The box around T(h), padded: a segment outside it lies a distance
 * `pad` outside T(h), so its entry height, rounding included, is not below
 * h and the minimum cannot change. */
static void region_box(const search *s, double q[4])
{
    const double *a = s->xy + 2 * s->i, *b = s->xy + 2 * s->j;
    double tx = s->f.mx - s->h * s->f.uy, ty = s->f.my + s->h * s->f.ux; /* the apex */
    q[0] = fmin(fmin(a[0], b[0]), tx) - s->pad, q[1] = fmin(fmin(a[1], b[1]), ty) - s->pad;
    q[2] = fmax(fmax(a[0], b[0]), tx) + s->pad, q[3] = fmax(fmax(a[1], b[1]), ty) + s->pad;
}

static int visit_segment(void *ctx, int32_t e, double q[4])
{
    search *s = ctx;
    if ((size_t)e == s->i) return 0;
    double h = entry_of(s->mesh, s->xy, s->n, &s->f, s->i, s->j, (size_t)e);
    if (h < s->h) s->h = h, region_box(s, q);
    return 0;
}

/* cm_edge_cap_scan through the segments' tree: the same minimum of the
 * same entries (a minimum does not depend on their order), only the
 * segments near T(h) examined, h shrinking as they are. */
static double edge_cap(const cm_mesh *mesh, const cm_boxtree *tree, const double *xy, size_t n,
                       size_t i)
{
    size_t j = cm_loops_next(mesh->loop_start, n, i);
    search s = {mesh, xy, n, i, j, frame_of(xy + 2 * i, xy + 2 * j), 0, 0};
    s.h = s.f.half * sqrt(3.0);
    s.pad = 1e-9 * (2 * s.f.half + fabs(s.f.mx) + fabs(s.f.my));
    size_t p = cm_loops_prev(mesh->loop_start, n, i); /* the neighbours first: h drops fast */
    s.h = fmin(s.h, fmin(entry_of(mesh, xy, n, &s.f, i, j, p), entry_of(mesh, xy, n, &s.f, i, j, j)));
    double q[4];
    region_box(&s, q);
    cm_boxtree_query(tree, q, visit_segment, &s);
    return cap_of(&s.f, s.h);
}

/* The tree of the loops' segments of one geometry. */
static int segment_tree(const cm_mesh *mesh, const double *xy, size_t n, cm_boxtree *tree)
{
    double *box = malloc(4 * n * sizeof *box);
    if (!box) return CM_NO_MEMORY;
    for (size_t e = 0; e < n; e++) {
        const double *p = xy + 2 * e, *q = xy + 2 * cm_loops_next(mesh->loop_start, n, e);
        box[4 * e] = fmin(p[0], q[0]), box[4 * e + 1] = fmin(p[1], q[1]);
        box[4 * e + 2] = fmax(p[0], q[0]), box[4 * e + 3] = fmax(p[1], q[1]);
    }
    int s = cm_boxtree_build(tree, box, n) ? CM_NO_MEMORY : 0;
    free(box);
    return s;
}

int cm_boundary_caps(const cm_mesh *mesh, size_t n, cm_progress *progress, double *bcap,
                     double *vcap)
{
    for (size_t i = 0; i < n; i++) bcap[i] = vcap[i] = CM_PI;
    for (size_t g = 0; g < mesh->k; g++) {
        const double *xy = mesh->xy[g];
        cm_boxtree tree;
        if (segment_tree(mesh, xy, n, &tree)) return CM_NO_MEMORY;
        for (size_t i = 0; i < n; i++) {
            if (cm_progress_check(progress)) {
                cm_boxtree_free(&tree);
                return CM_CANCELLED;
            }
            bcap[i] = fmin(bcap[i], edge_cap(mesh, &tree, xy, n, i));
            double c = corner_angle(xy + 2 * cm_loops_prev(mesh->loop_start, n, i), xy + 2 * i,
                                    xy + 2 * cm_loops_next(mesh->loop_start, n, i));
            vcap[i] = fmin(vcap[i], 0.5 * c);
        }
        cm_boxtree_free(&tree);
    }
    return 0;
}
