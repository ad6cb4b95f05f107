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
 * connectivity, hence compatibility, never changes. */
#include "remesh/maxmin.h"

#include <lbfgs.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "geom/angle.h"
#include "geom/predicates.h"

/* Vertices of triangles whose smallest angle is within this of the
 * geometry's (radians) move; the rest stay. */
#define CM_MAXMIN_WARM (5.0 * CM_PI / 180.0)
/* The schedule: tau (radians) and its share of the iterations. */
static const double cm_maxmin_tau[] = {0.1 * CM_PI / 180.0,
                                       0.03 * CM_PI / 180.0};
static const double cm_maxmin_share[] = {0.4, 0.6};

typedef struct soft {
    const double *xy;  /* the geometry: positions of the vertices that stay */
    const int32_t *tri;
    int32_t *moved;    /* triangles touching a moving vertex (indices into tri) */
    size_t nmoved;
    int32_t *slot;     /* per vertex: its variable pair, or -1 */
    int32_t *var;      /* per variable pair: its vertex */
    size_t nvar;
    double rest;       /* the smallest angle of the triangles that do not move */
    double tau;
    double *tmin;      /* nmoved: each moving triangle's smallest angle */
    int32_t *hot;      /* the moving triangles near the smallest angle */
    double *angle;     /* 3 per hot triangle */
    double best;       /* the best smallest angle met, at best_x */
    lbfgsfloatval_t *best_x;
    cm_progress *progress;
} soft;

static const double *position(const soft *s, const lbfgsfloatval_t *x, int32_t v)
{
    return s->slot[v] < 0 ? s->xy + 2 * v : x + 2 * s->slot[v];
}

static void corner_angles(const double *p[3], double out[3])
{
    for (int c = 0; c < 3; c++) out[c] = cm_angle_at(p[c], p[(c + 1) % 3], p[(c + 2) % 3]);
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
    double m = s->rest;
    for (size_t i = 0; i < s->nmoved; i++) {
        const int32_t *v = s->tri + 3 * s->moved[i];
        const double *p[3] = {position(s, x, v[0]), position(s, x, v[1]), position(s, x, v[2])};
        if (!(twice_area(p) > 0)) return HUGE_VAL;
        m = fmin(m, s->tmin[i] = cm_triangle_min_angle(p[0], p[1], p[2]));
    }
    if (m > s->best) s->best = m, memcpy(s->best_x, x, (size_t)n * sizeof *x);
    double cut = m + CM_MAXMIN_CUT * s->tau, sum = s->rest < cut ? exp(-(s->rest - m) / s->tau) : 0;
    size_t hot = 0;
    for (size_t i = 0; i < s->nmoved; i++) {
        if (s->tmin[i] >= cut) continue;
        const int32_t *v = s->tri + 3 * s->moved[i];
        const double *p[3] = {position(s, x, v[0]), position(s, x, v[1]), position(s, x, v[2])};
        double *a = s->angle + 3 * hot;
        corner_angles(p, a);
        for (int c = 0; c < 3; c++) sum += a[c] < cut ? exp(-(a[c] - m) / s->tau) : 0;
        s->hot[hot++] = s->moved[i];
    }
    memset(g, 0, (size_t)n * sizeof *g);
    for (size_t i = 0; i < hot; i++) {
        const int32_t *v = s->tri + 3 * s->hot[i];
        for (int c = 0; c < 3; c++) {
            if (s->angle[3 * i + c] >= cut) continue;
            double w = exp(-(s->angle[3 * i + c] - m) / s->tau) / sum;
            int32_t at[3] = {v[c], v[(c + 1) % 3], v[(c + 2) % 3]};
            const double *a = position(s, x, at[0]), *b = position(s, x, at[1]), *d = position(s, x, at[2]);
            double ux = b[0] - a[0], uy = b[1] - a[1], vx = d[0] - a[0], vy = d[1] - a[1];
            double uu = ux * ux + uy * uy, vv = vx * vx + vy * vy;
            /* the angle is arg(d - a) - arg(b - a) */
            double gd[2] = {-vy / vv, vx / vv}, gb[2] = {uy / uu, -ux / uu};
            double grad[3][2] = {{-gb[0] - gd[0], -gb[1] - gd[1]}, {gb[0], gb[1]}, {gd[0], gd[1]}};
            for (int e = 0; e < 3; e++) {
                int32_t j = s->slot[at[e]];
                if (j < 0) continue;
                g[2 * j] -= w * grad[e][0], g[2 * j + 1] -= w * grad[e][1];
            }
        }
    }
    return -(m - s->tau * log(sum));
}

static int progress(void *instance, const lbfgsfloatval_t *x, const lbfgsfloatval_t *g, const lbfgsfloatval_t fx,
                    const lbfgsfloatval_t xnorm, const lbfgsfloatval_t gnorm, const lbfgsfloatval_t step, int n,
                    int k, int ls)
{
    (void)x, (void)g, (void)fx, (void)xnorm, (void)gnorm, (void)step, (void)n, (void)k, (void)ls;
    return cm_progress_check(((soft *)instance)->progress);
}

/* Which vertices move and which triangles they touch; the smallest angle
 * of the others. 0, or -1 out of memory. */
static int choose_moving(soft *s, const double *xy, size_t nt, size_t nb)
{
    double least = HUGE_VAL;
    double *tmin = malloc(nt * sizeof *tmin);
    if (!tmin) return -1;
    for (size_t t = 0; t < nt; t++) {
        const int32_t *v = s->tri + 3 * t;
        const double *p[3] = {xy + 2 * v[0], xy + 2 * v[1], xy + 2 * v[2]};
        least = fmin(least, tmin[t] = cm_triangle_min_angle(p[0], p[1], p[2]));
    }
    s->nvar = s->nmoved = 0;
    for (size_t t = 0; t < nt; t++) {
        if (tmin[t] >= least + CM_MAXMIN_WARM) continue;
        for (int c = 0; c < 3; c++) {
            int32_t v = s->tri[3 * t + c];
            if ((size_t)v >= nb && s->slot[v] < 0) s->var[s->nvar] = v, s->slot[v] = (int32_t)s->nvar++;
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

/* 1 if every moving triangle is counter-clockwise at x, exactly. */
static int exactly_valid(const soft *s, const lbfgsfloatval_t *x)
{
    for (size_t i = 0; i < s->nmoved; i++) {
        const int32_t *v = s->tri + 3 * s->moved[i];
        if (cm_orient2d(position(s, x, v[0]), position(s, x, v[1]), position(s, x, v[2])) <= 0) return 0;
    }
    return 1;
}

static cm_status polish_geometry(soft *s, double *xy, size_t nt, size_t nb, int max_iterations)
{
    s->xy = xy;
    if (choose_moving(s, xy, nt, nb)) return CM_ERR_NO_MEMORY;
    cm_status status = CM_OK;
    lbfgsfloatval_t *x = s->nvar ? lbfgs_malloc((int)(2 * s->nvar)) : NULL;
    s->best_x = s->nvar ? lbfgs_malloc((int)(2 * s->nvar)) : NULL;
    if (s->nvar && (!x || !s->best_x)) status = CM_ERR_NO_MEMORY;
    if (status == CM_OK && s->nvar) {
        for (size_t j = 0; j < s->nvar; j++) x[2 * j] = xy[2 * s->var[j]], x[2 * j + 1] = xy[2 * s->var[j] + 1];
        memcpy(s->best_x, x, 2 * s->nvar * sizeof *x);
        s->best = -HUGE_VAL;
        for (size_t round = 0; round < sizeof cm_maxmin_tau / sizeof *cm_maxmin_tau; round++) {
            lbfgs_parameter_t param;
            lbfgs_parameter_init(&param);
            param.max_iterations = (int)ceil(cm_maxmin_share[round] * max_iterations);
            param.linesearch = LBFGS_LINESEARCH_BACKTRACKING;
            param.epsilon = 1e-9;
            s->tau = cm_maxmin_tau[round];
            /* any end is fine: the best point met is what counts */
            lbfgs((int)(2 * s->nvar), x, NULL, evaluate, progress, s, &param);
            if (cm_progress_check(s->progress)) {
                status = CM_ERR_CANCELLED;
                break;
            }
            memcpy(x, s->best_x, 2 * s->nvar * sizeof *x);
        }
        if (status == CM_OK && exactly_valid(s, s->best_x))
            for (size_t j = 0; j < s->nvar; j++)
                xy[2 * s->var[j]] = s->best_x[2 * j], xy[2 * s->var[j] + 1] = s->best_x[2 * j + 1];
    }
    for (size_t j = 0; j < s->nvar; j++) s->slot[s->var[j]] = -1;
    lbfgs_free(x), lbfgs_free(s->best_x);
    s->best_x = NULL;
    return status;
}

cm_status cm_maxmin_polish(cm_mesh *mesh, size_t nb, int max_iterations, cm_progress *progress)
{
    size_t nv = mesh->nv, nt = mesh->nt;
    if (nt == 0 || max_iterations <= 0) return CM_OK;
    soft s = {.tri = mesh->tri, .progress = progress};
    s.slot = malloc(nv * sizeof *s.slot);
    s.var = malloc(nv * sizeof *s.var);
    s.moved = malloc(nt * sizeof *s.moved);
    s.angle = malloc(3 * nt * sizeof *s.angle);
    s.tmin = malloc(nt * sizeof *s.tmin);
    s.hot = malloc(nt * sizeof *s.hot);
    cm_status status = s.slot && s.var && s.moved && s.angle && s.tmin && s.hot ? CM_OK : CM_ERR_NO_MEMORY;
    for (size_t v = 0; status == CM_OK && v < nv; v++) s.slot[v] = -1;
    for (size_t g = 0; status == CM_OK && g < mesh->k; g++)
        status = polish_geometry(&s, mesh->xy[g], nt, nb, max_iterations);
    free(s.slot), free(s.var), free(s.moved), free(s.angle), free(s.tmin), free(s.hot);
    return status;
}
