/* The joint max-min polish (maxmin.h).
 *
 * The greedy remesher moves one vertex at a time, so it stops where the
 * smallest angles hold each other: a chain of slim triangles whose worst
 * angle only rises when several vertices move together. Here the Steiner
 * vertices near the smallest angles of one geometry move at once, along
 * the gradient of a smooth smallest angle,
 *
 *   softmin = m - tau log sum_i exp(-(a_i - m) / tau),   m = min_i a_i,
 *
 * which lies within tau log(#angles) of the smallest angle, maximised by
 * L-BFGS (libLBFGS) for a few values of tau, largest first. A step that
 * turns a triangle clockwise (in doubles) is refused by the line search;
 * the positions kept are the best smallest angle met, checked with the
 * exact predicates before they replace the geometry. The geometries
 * share no positions, so each is polished on its own and the
 * connectivity, hence compatibility, never changes. The result's smallest
 * angle is the least over the geometries, so where the caller asks (the
 * index correspondence) the one lowest at the start goes first and the
 * others stop once they are CM_MAXMIN_AHEAD above the least reached.
 *
 * Where the correspondence is the tool's to choose, a boundary point the
 * correspondence put on an input edge of this geometry (the other
 * polygon's vertex, or a split) may slide along that edge: its variable
 * is its arc length along the edge. Sliding changes which points
 * correspond, never the polygon; a slide past a neighbour turns the
 * boundary triangle between them, so the same orientation test keeps the
 * boundary in order. */
#include "remesh/maxmin.h"

#include <lbfgs.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/deadline.h"
#include "geom/angle.h"
#include "geom/predicates.h"

/* Vertices of triangles whose smallest angle is within this of the
 * geometry's (radians) move; the rest stay. */
#define CM_MAXMIN_WARM (5.0 * CM_PI / 180.0)
/* A geometry polished after others (lowest_first) stops when its
 * smallest angle is this much above the least they reached, relatively:
 * more would not raise the result's (index quick set: the same angles,
 * 0.95 of the CPU time). Auto polishes every geometry fully: its
 * polish-scored moves use that room (88 glyph pairs: 21 lower, 9 higher
 * when it stopped early; bench/REMESH.md, "A shorter first run below the
 * restart's gate"). */
#define CM_MAXMIN_AHEAD 0.01
/* The schedule: tau (radians) and its share of the iterations. */
static const double cm_maxmin_tau[] = {0.1 * CM_PI / 180.0,
                                       0.03 * CM_PI / 180.0};
static const double cm_maxmin_share[] = {0.4, 0.6};

typedef struct soft {
    const double *xy;  /* the geometry: positions of the vertices that stay */
    size_t g;          /* its index */
    const cm_maxmin_slide *slide;
    const int32_t *next, *prev; /* boundary neighbours (with slide->max_piece) */
    const int32_t *tri;
    int32_t *moved;    /* triangles touching a moving vertex (indices into tri) */
    size_t nmoved;
    int32_t *slot;     /* per vertex: its variable pair, or -1 */
    int32_t *var;      /* per variable: its vertex */
    size_t nvar;
    int32_t *off;      /* per variable: its first value in x (two inside, one on an edge) */
    int32_t *edge;     /* per variable: the input edge it slides on, or -1 */
    double *along;     /* per variable: the edge's length and unit direction */
    double *pos;       /* per variable: its position at the x last set */
    double *gpos;      /* per variable: the gradient by its position */
    size_t nx;
    size_t slid;       /* boundary points moved so far */
    double rest;       /* the smallest angle of the triangles that do not move */
    double tau;
    double *tmin;      /* nmoved: sin^2 of each moving triangle's smallest angle */
    int32_t *hot;      /* the moving triangles near the smallest angle */
    double *weight;    /* 3 per hot triangle: exp(-(a - m) / tau) of its corners below the cut, else 0 */
    double best;       /* the best smallest angle met, at best_x */
    double enough;     /* the descent stops when best reaches it */
    lbfgsfloatval_t *best_x;
    cm_progress *progress;
} soft;

static const double *position(const soft *s, int32_t v)
{
    return s->slot[v] < 0 ? s->xy + 2 * v : s->pos + 2 * s->slot[v];
}

/* The variables' positions at x. */
static void set_positions(soft *s, const lbfgsfloatval_t *x)
{
    for (size_t j = 0; j < s->nvar; j++) {
        const lbfgsfloatval_t *u = x + s->off[j];
        if (s->edge[j] < 0)
            s->pos[2 * j] = u[0], s->pos[2 * j + 1] = u[1];
        else
            s->slide->place(s->slide->ctx, s->g, s->edge[j], u[0] / s->along[3 * j], s->pos + 2 * j);
    }
}

/* 1 if every slid point's boundary edges are at most max_piece long. */
static int pieces_short(const soft *s)
{
    double limit = s->slide ? s->slide->max_piece : 0;
    if (!(limit > 0)) return 1;
    for (size_t j = 0; j < s->nvar; j++) {
        if (s->edge[j] < 0) continue;
        const double *p = s->pos + 2 * j;
        for (int side = 0; side < 2; side++) {
            const double *q = position(s, (side ? s->next : s->prev)[s->var[j]]);
            if (hypot(q[0] - p[0], q[1] - p[1]) > limit) return 0;
        }
    }
    return 1;
}

/* The triangle's corner angles where they are below cut (tan_cut =
 * tan(cut)); the others, which weigh nothing, as HUGE_VAL. */
static void corner_angles(const double *p[3], double cut, double tan_cut, double out[3])
{
    for (int c = 0; c < 3; c++) out[c] = cm_angle_at_below(p[c], p[(c + 1) % 3], p[(c + 2) % 3], cut, tan_cut);
}

/* Angles further than this many tau above the smallest weigh less than
 * e^-36 (below a double's resolution of the sum): skipped. */
#define CM_MAXMIN_CUT 36.0

static double twice_area(const double *p[3])
{
    return (p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[1][1] - p[0][1]) * (p[2][0] - p[0][0]);
}

/* Minus the soft smallest angle of the moving triangles and its gradient;
 * a huge value where a triangle is not counter-clockwise. */
static lbfgsfloatval_t evaluate(void *instance, const lbfgsfloatval_t *x, lbfgsfloatval_t *g, const int n,
                                const lbfgsfloatval_t step)
{
    (void)step;
    soft *s = instance;
    set_positions(s, x);
    /* sin^2 orders the triangles' smallest angles (each at most 60
     * degrees) as the angles do, without an atan2 each: the angle itself
     * only for the least */
    double least2 = HUGE_VAL;
    size_t lowest = 0;
    for (size_t i = 0; i < s->nmoved; i++) {
        const int32_t *v = s->tri + 3 * s->moved[i];
        const double *p[3] = {position(s, v[0]), position(s, v[1]), position(s, v[2])};
        if (!(twice_area(p) > 0)) return HUGE_VAL;
        s->tmin[i] = cm_triangle_min_angle_sin2(p[0], p[1], p[2]);
        if (s->tmin[i] < least2) least2 = s->tmin[i], lowest = i;
    }
    if (!pieces_short(s)) return HUGE_VAL;
    double m = s->rest;
    if (s->nmoved) {
        const int32_t *v = s->tri + 3 * s->moved[lowest];
        m = fmin(m, cm_triangle_min_angle(position(s, v[0]), position(s, v[1]), position(s, v[2])));
    }
    if (m > s->best) s->best = m, memcpy(s->best_x, x, (size_t)n * sizeof *x);
    double cut = m + CM_MAXMIN_CUT * s->tau, sum = s->rest < cut ? exp(-(s->rest - m) / s->tau) : 0;
    double cut2 = sin(fmin(cut, CM_PI / 2)), hot_above = cut2 * cut2, tan_cut = tan(fmin(cut, CM_PI / 2));
    size_t hot = 0;
    for (size_t i = 0; i < s->nmoved; i++) {
        if (s->tmin[i] >= hot_above) continue;
        const int32_t *v = s->tri + 3 * s->moved[i];
        const double *p[3] = {position(s, v[0]), position(s, v[1]), position(s, v[2])};
        double a[3], *e = s->weight + 3 * hot;
        corner_angles(p, cut, tan_cut, a);
        for (int c = 0; c < 3; c++) sum += e[c] = a[c] < cut ? exp(-(a[c] - m) / s->tau) : 0;
        s->hot[hot++] = s->moved[i];
    }
    memset(s->gpos, 0, 2 * s->nvar * sizeof *s->gpos);
    for (size_t i = 0; i < hot; i++) {
        const int32_t *v = s->tri + 3 * s->hot[i];
        for (int c = 0; c < 3; c++) {
            if (!(s->weight[3 * i + c] > 0)) continue; /* at or above the cut */
            double w = s->weight[3 * i + c] / sum;
            int32_t at[3] = {v[c], v[(c + 1) % 3], v[(c + 2) % 3]};
            const double *a = position(s, at[0]), *b = position(s, at[1]), *d = position(s, at[2]);
            double ux = b[0] - a[0], uy = b[1] - a[1], vx = d[0] - a[0], vy = d[1] - a[1];
            double uu = ux * ux + uy * uy, vv = vx * vx + vy * vy;
            /* the angle is arg(d - a) - arg(b - a) */
            double gd[2] = {-vy / vv, vx / vv}, gb[2] = {uy / uu, -ux / uu};
            double grad[3][2] = {{-gb[0] - gd[0], -gb[1] - gd[1]}, {gb[0], gb[1]}, {gd[0], gd[1]}};
            for (int e = 0; e < 3; e++) {
                int32_t j = s->slot[at[e]];
                if (j < 0) continue;
                s->gpos[2 * j] -= w * grad[e][0], s->gpos[2 * j + 1] -= w * grad[e][1];
            }
        }
    }
    for (size_t j = 0; j < s->nvar; j++) {
        lbfgsfloatval_t *gj = g + s->off[j];
        const double *d = s->gpos + 2 * j;
        if (s->edge[j] < 0)
            gj[0] = d[0], gj[1] = d[1];
        else
            gj[0] = d[0] * s->along[3 * j + 1] + d[1] * s->along[3 * j + 2];
    }
    return -(m - s->tau * log(sum));
}

static int progress(void *instance, const lbfgsfloatval_t *x, const lbfgsfloatval_t *g, const lbfgsfloatval_t fx,
                    const lbfgsfloatval_t xnorm, const lbfgsfloatval_t gnorm, const lbfgsfloatval_t step, int n,
                    int k, int ls)
{
    (void)x, (void)g, (void)fx, (void)xnorm, (void)gnorm, (void)step, (void)n, (void)k, (void)ls;
    const soft *s = instance;
    return s->best >= s->enough || cm_progress_check(s->progress) || cm_deadline_passed();
}

/* v as a variable of s: two values for a Steiner vertex, one (its arc
 * length along its input edge) for a boundary point that slides. */
static void add_variable(soft *s, int32_t v, int on_edge)
{
    size_t j = s->nvar++;
    s->var[j] = v, s->slot[v] = (int32_t)j, s->off[j] = (int32_t)s->nx, s->edge[j] = -1;
    if (!on_edge) {
        s->nx += 2;
        return;
    }
    const cm_maxmin_slide *sl = s->slide;
    double a[2], b[2];
    int32_t e = sl->edge[s->g][v];
    sl->place(sl->ctx, s->g, e, 0.0, a), sl->place(sl->ctx, s->g, e, 1.0, b);
    double len = hypot(b[0] - a[0], b[1] - a[1]);
    s->edge[j] = e;
    s->along[3 * j] = len, s->along[3 * j + 1] = (b[0] - a[0]) / len, s->along[3 * j + 2] = (b[1] - a[1]) / len;
    s->nx += 1;
}

/* 1 if boundary vertex v of this geometry may slide. */
static int slides(const soft *s, int32_t v)
{
    return s->slide && s->slide->t[s->g][v] > 0;
}

/* Which vertices move and which triangles they touch; the smallest angle
 * of the others (and of all, *least). 0, or -1 out of memory. */
static int choose_moving(soft *s, const double *xy, size_t nt, size_t nb, double *least)
{
    *least = HUGE_VAL;
    double *tmin = malloc(nt * sizeof *tmin);
    if (!tmin) return -1;
    for (size_t t = 0; t < nt; t++) {
        const int32_t *v = s->tri + 3 * t;
        const double *p[3] = {xy + 2 * v[0], xy + 2 * v[1], xy + 2 * v[2]};
        *least = fmin(*least, tmin[t] = cm_triangle_min_angle(p[0], p[1], p[2]));
    }
    s->nvar = s->nmoved = s->nx = 0;
    for (size_t t = 0; t < nt; t++) {
        if (tmin[t] >= *least + CM_MAXMIN_WARM) continue;
        for (int c = 0; c < 3; c++) {
            int32_t v = s->tri[3 * t + c];
            if (s->slot[v] < 0 && ((size_t)v >= nb || slides(s, v))) add_variable(s, v, (size_t)v < nb);
        }
    }
    s->rest = HUGE_VAL;
    for (size_t t = 0; t < nt; t++) {
        const int32_t *v = s->tri + 3 * t;
        if (s->slot[v[0]] >= 0 || s->slot[v[1]] >= 0 || s->slot[v[2]] >= 0)
            s->moved[s->nmoved++] = (int32_t)t;
        else
            s->rest = fmin(s->rest, tmin[t]);
    }
    free(tmin);
    return 0;
}

/* 1 if every moving triangle is counter-clockwise at x, exactly, and the
 * slid points' boundary edges short enough. */
static int exactly_valid(soft *s, const lbfgsfloatval_t *x)
{
    set_positions(s, x);
    for (size_t i = 0; i < s->nmoved; i++) {
        const int32_t *v = s->tri + 3 * s->moved[i];
        if (cm_orient2d(position(s, v[0]), position(s, v[1]), position(s, v[2])) <= 0) return 0;
    }
    return pieces_short(s);
}

/* The schedule of L-BFGS runs from the variables' positions (a slid
 * point's from its label), the best point met kept in s->best_x. 1 if
 * it is exactly valid and its smallest angle at least `least` (s->pos
 * then holds its positions), 0 if not, CM_ERR_NO_MEMORY or
 * CM_ERR_CANCELLED as negative statuses. */
static int descend(soft *s, const double *xy, double least, int max_iterations)
{
    if (!s->nx) return 0;
    lbfgsfloatval_t *x = lbfgs_malloc((int)s->nx);
    s->best_x = lbfgs_malloc((int)s->nx);
    int result = x && s->best_x ? 0 : -CM_ERR_NO_MEMORY;
    for (size_t j = 0; !result && j < s->nvar; j++) {
        const double *p = xy + 2 * s->var[j];
        if (s->edge[j] < 0)
            x[s->off[j]] = p[0], x[s->off[j] + 1] = p[1];
        else
            x[s->off[j]] = s->slide->t[s->g][s->var[j]] * s->along[3 * j];
    }
    if (!result) {
        memcpy(s->best_x, x, s->nx * sizeof *x);
        s->best = -HUGE_VAL;
    }
    for (size_t round = 0; !result && round < sizeof cm_maxmin_tau / sizeof *cm_maxmin_tau && s->best < s->enough;
         round++) {
        lbfgs_parameter_t param;
        lbfgs_parameter_init(&param);
        param.max_iterations = (int)ceil(cm_maxmin_share[round] * max_iterations);
        param.linesearch = LBFGS_LINESEARCH_BACKTRACKING;
        param.epsilon = 1e-9;
        s->tau = cm_maxmin_tau[round];
        /* any end is fine: the best point met is what counts */
        lbfgs((int)s->nx, x, NULL, evaluate, progress, s, &param);
        if (cm_progress_check(s->progress)) result = -CM_ERR_CANCELLED;
        memcpy(x, s->best_x, s->nx * sizeof *x);
    }
    /* a slid point's start is its label's parameter times a length,
     * not its exact position: keep nothing worse than the start */
    if (!result) result = s->best >= least && exactly_valid(s, s->best_x);
    lbfgs_free(x);
    return result;
}

static cm_status polish_geometry(soft *s, size_t g, double *xy, size_t nt, size_t nb, int max_iterations)
{
    s->xy = xy, s->g = g;
    double least;
    if (choose_moving(s, xy, nt, nb, &least)) return CM_ERR_NO_MEMORY;
    int better = descend(s, xy, least, max_iterations);
    if (better > 0)
        for (size_t j = 0; j < s->nvar; j++) {
            int32_t v = s->var[j];
            xy[2 * v] = s->pos[2 * j], xy[2 * v + 1] = s->pos[2 * j + 1];
            double t = s->edge[j] < 0 ? 0 : s->best_x[s->off[j]] / s->along[3 * j];
            if (s->edge[j] >= 0 && t != s->slide->t[g][v]) s->slide->t[g][v] = t, s->slid++;
        }
    for (size_t j = 0; j < s->nvar; j++) s->slot[s->var[j]] = -1;
    lbfgs_free(s->best_x);
    s->best_x = NULL;
    return better < 0 ? (cm_status)-better : CM_OK;
}

/* The work arrays of a polish: slots for nv vertices (all -1), nvar
 * variables (slid along an edge when `sliding`), ntris moving triangles.
 * 0, or -1 out of memory (what was made is freed by soft_free). */
static int soft_alloc(soft *s, size_t nv, size_t nvar, size_t ntris, int sliding)
{
    s->slot = malloc(nv * sizeof *s->slot);
    s->var = malloc(nvar * sizeof *s->var);
    s->off = malloc(nvar * sizeof *s->off);
    s->edge = malloc(nvar * sizeof *s->edge);
    s->along = sliding ? malloc(3 * nvar * sizeof *s->along) : NULL;
    s->pos = malloc(2 * nvar * sizeof *s->pos);
    s->gpos = malloc(2 * nvar * sizeof *s->gpos);
    s->moved = malloc(ntris * sizeof *s->moved);
    s->weight = malloc(3 * ntris * sizeof *s->weight);
    s->tmin = malloc(ntris * sizeof *s->tmin);
    s->hot = malloc(ntris * sizeof *s->hot);
    if (!s->slot || !s->var || !s->off || !s->edge || (sliding && !s->along) || !s->pos || !s->gpos || !s->moved ||
        !s->weight || !s->tmin || !s->hot)
        return -1;
    for (size_t v = 0; v < nv; v++) s->slot[v] = -1;
    return 0;
}

static void soft_free(soft *s)
{
    free(s->slot), free(s->var), free(s->off), free(s->edge), free(s->along), free(s->pos), free(s->gpos);
    free(s->moved), free(s->weight), free(s->tmin), free(s->hot);
}

int cm_maxmin_local(const int32_t *tri, const double *xy, size_t nv, const int32_t *var, size_t nvar,
                    const int32_t *tris, size_t ntris, const cm_maxmin_slide *slide, size_t g, int max_iterations,
                    cm_progress *progress, double *out, double *out_t)
{
    soft s = {.xy = xy, .g = g, .slide = slide, .tri = tri, .progress = progress, .rest = HUGE_VAL, .enough = HUGE_VAL};
    if (slide) s.next = slide->next, s.prev = slide->prev;
    int result = -CM_ERR_NO_MEMORY;
    if (soft_alloc(&s, nv, nvar, ntris, slide != NULL) == 0) {
        for (size_t j = 0; j < nvar; j++) add_variable(&s, var[j], slide && slide->edge[g][var[j]] >= 0);
        double least = HUGE_VAL;
        for (size_t i = 0; i < ntris; i++) {
            const int32_t *v = tri + 3 * (size_t)tris[i];
            s.moved[s.nmoved++] = tris[i];
            least = fmin(least, cm_triangle_min_angle(xy + 2 * v[0], xy + 2 * v[1], xy + 2 * v[2]));
        }
        result = descend(&s, xy, least, max_iterations);
        if (result > 0) {
            memcpy(out, s.pos, 2 * nvar * sizeof *out);
            for (size_t j = 0; j < nvar; j++)
                if (s.edge[j] >= 0) out_t[j] = s.best_x[s.off[j]] / s.along[3 * j];
        }
        lbfgs_free(s.best_x);
    }
    soft_free(&s);
    return result;
}

static int by_pair(const void *a, const void *b)
{
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return (x > y) - (x < y);
}

/* next[v], prev[v]: boundary vertex v's neighbours along its loop (the
 * edges between boundary vertices whose reverse is no triangle's). 0, or
 * -1 out of memory. */
static int boundary_neighbours(const int32_t *tri, size_t nt, size_t nb, int32_t *next, int32_t *prev)
{
    uint64_t *e = malloc(3 * nt * sizeof *e);
    if (!e) return -1;
    size_t m = 0;
    for (size_t t = 0; t < 3 * nt; t++) {
        uint64_t a = (uint64_t)tri[t], b = (uint64_t)tri[cm_corner_next(t)];
        if (a < nb && b < nb) e[m++] = a << 32 | b;
    }
    qsort(e, m, sizeof *e, by_pair);
    for (size_t i = 0; i < m; i++) {
        uint64_t a = e[i] >> 32, b = e[i] & 0xffffffffu, twin = b << 32 | a;
        if (!bsearch(&twin, e, m, sizeof *e, by_pair)) next[a] = (int32_t)b, prev[b] = (int32_t)a;
    }
    free(e);
    return 0;
}

cm_status cm_maxmin_polish(cm_mesh *mesh, size_t nb, cm_maxmin_slide *slide, int lowest_first, int max_iterations,
                           cm_progress *progress)
{
    size_t nv = mesh->nv, nt = mesh->nt;
    if (nt == 0 || max_iterations <= 0) return CM_OK;
    soft s = {.tri = mesh->tri, .slide = slide, .progress = progress};
    int32_t *links = slide && slide->max_piece > 0 ? malloc(2 * nb * sizeof *links) : NULL;
    cm_status status = soft_alloc(&s, nv, nv, nt, 1) == 0 && (links || !(slide && slide->max_piece > 0))
                           ? CM_OK
                           : CM_ERR_NO_MEMORY;
    if (status == CM_OK && links) {
        s.next = links, s.prev = links + nb;
        if (boundary_neighbours(mesh->tri, nt, nb, links, links + nb)) status = CM_ERR_NO_MEMORY;
    }
    size_t *order = status == CM_OK ? malloc(mesh->k * sizeof *order) : NULL;
    double *start = status == CM_OK ? malloc(mesh->k * sizeof *start) : NULL;
    if (status == CM_OK && (!order || !start)) status = CM_ERR_NO_MEMORY;
    for (size_t g = 0; status == CM_OK && g < mesh->k; g++) { /* lowest_first: by smallest angle, lowest first */
        size_t i = g;
        if (lowest_first) {
            start[g] = cm_triangles_min_angle(mesh->tri, nt, mesh->xy[g]);
            for (; i > 0 && start[order[i - 1]] > start[g]; i--) order[i] = order[i - 1];
        }
        order[i] = g;
    }
    double reached = HUGE_VAL; /* lowest_first: the least smallest angle of the geometries polished so far */
    for (size_t i = 0; status == CM_OK && i < mesh->k; i++) {
        size_t g = order[i];
        s.enough = reached < HUGE_VAL ? (1 + CM_MAXMIN_AHEAD) * reached : HUGE_VAL;
        if (lowest_first && start[g] >= s.enough) continue; /* far enough above already: left as it is */
        status = polish_geometry(&s, g, mesh->xy[g], nt, nb, max_iterations);
        if (status == CM_OK && lowest_first)
            reached = fmin(reached, cm_triangles_min_angle(mesh->tri, nt, mesh->xy[g]));
    }
    free(order), free(start);
    if (slide) slide->slid = s.slid;
    free(links);
    soft_free(&s);
    return status;
}
