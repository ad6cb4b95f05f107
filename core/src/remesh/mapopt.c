/* Map-distortion descent (mapopt.h). The per-triangle term is MIPS,
 * f(A, B) = |B adj(A)|^2 / (det A det B) for the edge matrices A, B of two
 * geometries (columns: the edges from the first vertex), which is the
 * conformal distortion sigma1/sigma2 + sigma2/sigma1 of the affine map
 * A -> B, symmetric in A and B and blind to scale: 2 exactly when the
 * triangle has the same shape in both. Its gradients:
 *   df/dA = (2 A adj(B) adj(B)^T - f det(B) adj(A)^T) / (det A det B)
 * and symmetrically for B. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <cholmod.h>

#include "remesh/mapopt.h"
#include "geom/predicates.h"

/* Armijo's sufficient decrease; the share of the largest flip-free step
 * tried first; halvings before a step is given up. */
#define CM_MAPOPT_ARMIJO 1e-4
#define CM_MAPOPT_SHARE 0.9
#define CM_MAPOPT_HALVINGS 40
/* Stop when a step lowers the energy by less than this share of it. */
#define CM_MAPOPT_TOL 1e-6
/* Geometries handled (the per-triangle scratch); more: no steps. */
#define CM_MAPOPT_MAX_K 16

typedef struct { double a, b, c, d; } m2; /* [[a b] [c d]] */

static m2 adj(m2 m) { return (m2){m.d, -m.b, -m.c, m.a}; }
static double det(m2 m) { return m.a * m.d - m.b * m.c; }
static m2 mul(m2 x, m2 y)
{
    return (m2){x.a * y.a + x.b * y.c, x.a * y.b + x.b * y.d, x.c * y.a + x.d * y.c, x.c * y.b + x.d * y.d};
}
static m2 mul_t(m2 x, m2 y) /* x y^T */
{
    return (m2){x.a * y.a + x.b * y.b, x.a * y.c + x.b * y.d, x.c * y.a + x.d * y.b, x.c * y.c + x.d * y.d};
}
static double norm2(m2 m) { return m.a * m.a + m.b * m.b + m.c * m.c + m.d * m.d; }

/* A triangle whose area is not positive in doubles (the construction
 * leaves slivers that only the exact predicates find valid) has no
 * energy: one flat at the start of a run is left out of the energy and
 * of the step bound (kept valid by the exact check); any other may not
 * become flat. */
static int flat(m2 m) { return !(det(m) > 0); }

/* f(A, B); the gradients added (times s) to ga, gb when not NULL. */
static double mips(m2 A, m2 B, double s, m2 *ga, m2 *gb)
{
    if (flat(A) || flat(B)) return INFINITY;
    double da = det(A), db = det(B);
    m2 aa = adj(A), ab = adj(B);
    double p = da * db, f = norm2(mul(B, aa)) / p;
    if (ga) {
        m2 t = mul_t(mul(A, ab), ab);
        ga->a += s * (2 * t.a - f * db * aa.a) / p, ga->b += s * (2 * t.b - f * db * aa.c) / p;
        ga->c += s * (2 * t.c - f * db * aa.b) / p, ga->d += s * (2 * t.d - f * db * aa.d) / p;
    }
    if (gb) {
        m2 t = mul_t(mul(B, aa), aa);
        gb->a += s * (2 * t.a - f * da * ab.a) / p, gb->b += s * (2 * t.b - f * da * ab.c) / p;
        gb->c += s * (2 * t.c - f * da * ab.b) / p, gb->d += s * (2 * t.d - f * da * ab.d) / p;
    }
    return f;
}

/* f(A, B)^p, gradients likewise (times s). */
static double mips_power(m2 A, m2 B, double p, double s, m2 *ga, m2 *gb)
{
    if (p == 1.0) return mips(A, B, s, ga, gb);
    double f = mips(A, B, 0, NULL, NULL);
    if (!isfinite(f)) return INFINITY;
    if (ga || gb) mips(A, B, s * p * pow(f, p - 1), ga, gb);
    return pow(f, p);
}

/* The equilateral triangle's edge matrix. */
static const m2 equilateral = {1.0, 0.5, 0.0, 0.86602540378443864676};

typedef struct optimiser {
    cm_kmesh *km;
    cm_mapopt_weights w;
    int32_t m;        /* free vertices */
    int32_t *index;   /* vertex -> free index, -1 fixed */
    double *q;        /* k * 2m current normalised positions (geometry-major) */
    double *trial;    /* k * 2m */
    double *grad;     /* 2k columns of m: geometry g's x then y */
    double *dir;      /* the same layout */
    unsigned char *frozen; /* triangle: flat at the start */
} optimiser;

/* Normalised position of vertex v in geometry g, from the state `pos`
 * for free vertices. */
static void point(const optimiser *o, const double *pos, size_t g, int32_t v, double out[2])
{
    int32_t i = o->index[v];
    if (i >= 0) {
        out[0] = pos[2 * (g * (size_t)o->m + (size_t)i)], out[1] = pos[2 * (g * (size_t)o->m + (size_t)i) + 1];
        return;
    }
    const double *p = cm_kmesh_pos(o->km, g, v);
    out[0] = p[0] / o->km->scale[g], out[1] = p[1] / o->km->scale[g];
}

static m2 edges(const optimiser *o, const double *pos, size_t g, const int32_t *v)
{
    double p0[2], p1[2], p2[2];
    point(o, pos, g, v[0], p0), point(o, pos, g, v[1], p1), point(o, pos, g, v[2], p2);
    return (m2){p1[0] - p0[0], p2[0] - p0[0], p1[1] - p0[1], p2[1] - p0[1]};
}

/* Adds the gradient of a triangle's edge matrix to its free vertices. */
static void scatter(const optimiser *o, size_t g, const int32_t *v, m2 ge)
{
    const double gx[3] = {-(ge.a + ge.b), ge.a, ge.b}, gy[3] = {-(ge.c + ge.d), ge.c, ge.d};
    for (int j = 0; j < 3; j++) {
        int32_t i = o->index[v[j]];
        if (i < 0) continue;
        o->grad[(2 * g) * (size_t)o->m + (size_t)i] += gx[j];
        o->grad[(2 * g + 1) * (size_t)o->m + (size_t)i] += gy[j];
    }
}

/* The energy at `pos`; with_grad: its gradient into o->grad. */
static double energy(optimiser *o, const double *pos, int with_grad)
{
    const cm_kmesh *km = o->km;
    size_t k = km->k;
    m2 e[CM_MAPOPT_MAX_K], g[CM_MAPOPT_MAX_K];
    if (with_grad) memset(o->grad, 0, 2 * k * (size_t)o->m * sizeof *o->grad);
    double total = 0, pw = o->w.power > 0 ? o->w.power : 1.0;
    for (int32_t t = 0; t < km->nt; t++) {
        if (!cm_kmesh_tri_live(km, t) || (o->frozen && o->frozen[t])) continue;
        const int32_t *v = km->tri + 3 * (size_t)t;
        for (size_t a = 0; a < k; a++) e[a] = edges(o, pos, a, v), g[a] = (m2){0, 0, 0, 0};
        for (size_t a = 0; a < k; a++) {
            if (o->w.shape > 0)
                total += o->w.shape * mips_power(equilateral, e[a], pw, o->w.shape, NULL, with_grad ? &g[a] : NULL);
            if (o->w.map > 0)
                for (size_t b = a + 1; b < k; b++)
                    total += o->w.map * mips_power(e[a], e[b], pw, o->w.map, with_grad ? &g[a] : NULL,
                                                   with_grad ? &g[b] : NULL);
            if (!isfinite(total)) return INFINITY;
        }
        if (with_grad)
            for (size_t a = 0; a < k; a++) scatter(o, a, v, g[a]);
    }
    return total;
}

/* The largest s in (0, cap] such that no triangle's area reaches zero in
 * any geometry along pos + s dir (det(E + s D) = det E + s c1 + s^2 c2). */
static double flip_free_step(optimiser *o, double cap)
{
    const cm_kmesh *km = o->km;
    double s = cap;
    for (int32_t t = 0; t < km->nt; t++) {
        if (!cm_kmesh_tri_live(km, t) || o->frozen[t]) continue;
        const int32_t *v = km->tri + 3 * (size_t)t;
        for (size_t g = 0; g < km->k; g++) {
            double dx[3], dy[3];
            for (int j = 0; j < 3; j++) {
                int32_t i = o->index[v[j]];
                dx[j] = i < 0 ? 0 : o->dir[(2 * g) * (size_t)o->m + (size_t)i];
                dy[j] = i < 0 ? 0 : o->dir[(2 * g + 1) * (size_t)o->m + (size_t)i];
            }
            m2 e = edges(o, o->q, g, v);
            m2 d = {dx[1] - dx[0], dx[2] - dx[0], dy[1] - dy[0], dy[2] - dy[0]};
            double c0 = det(e), c2 = det(d), c1 = e.a * d.d + d.a * e.d - e.b * d.c - d.b * e.c;
            /* smallest positive root of c0 + c1 s + c2 s^2 */
            double root = INFINITY;
            if (fabs(c2) < 1e-300) {
                if (c1 < 0) root = -c0 / c1;
            } else {
                double disc = c1 * c1 - 4 * c0 * c2;
                if (disc >= 0) {
                    double sq = sqrt(disc), q = -0.5 * (c1 + copysign(sq, c1));
                    double r1 = q / c2, r2 = q != 0 ? c0 / q : INFINITY;
                    if (r1 > 0) root = fmin(root, r1);
                    if (r2 > 0) root = fmin(root, r2);
                }
            }
            if (root < s) s = root;
        }
    }
    return s;
}

/* Is every triangle counter-clockwise in every geometry at `pos`, in the
 * coordinates the mesh would store (exact)? */
static int valid_at(optimiser *o, const double *pos, double *scratch)
{
    const cm_kmesh *km = o->km;
    for (int32_t t = 0; t < km->nt; t++) {
        if (!cm_kmesh_tri_live(km, t)) continue;
        const int32_t *v = km->tri + 3 * (size_t)t;
        for (size_t g = 0; g < km->k; g++) {
            for (int j = 0; j < 3; j++) {
                int32_t i = o->index[v[j]];
                const double *p = cm_kmesh_pos(km, g, v[j]);
                scratch[2 * j] = i < 0 ? p[0] : pos[2 * (g * (size_t)o->m + (size_t)i)] * km->scale[g];
                scratch[2 * j + 1] = i < 0 ? p[1] : pos[2 * (g * (size_t)o->m + (size_t)i) + 1] * km->scale[g];
            }
            if (cm_orient2d(scratch, scratch + 2, scratch + 4) <= 0) return 0;
        }
    }
    return 1;
}

/* The preconditioner: a graph Laplacian on the free vertices, edge
 * weights 1 / (mean squared normalised length), so a step of about one
 * is a move of about one edge length. */
static cholmod_sparse *laplacian(optimiser *o, cholmod_common *cc)
{
    const cm_kmesh *km = o->km;
    size_t nz = (size_t)o->m + 9 * (size_t)km->live_t; /* three entries per corner */
    cholmod_triplet *tr = cholmod_allocate_triplet((size_t)o->m, (size_t)o->m, nz, 1, CHOLMOD_REAL, cc);
    if (!tr) return NULL;
    int *ti = tr->i, *tj = tr->j;
    double *tx = tr->x;
    size_t e = 0;
    for (int32_t i = 0; i < o->m; i++) ti[e] = tj[e] = i, tx[e++] = 1e-9;
    for (int32_t c = 0; c < 3 * km->nt; c++) {
        if (km->tri[c] < 0) continue;
        int32_t a = km->tri[cm_next(c)], b = km->tri[cm_prev(c)];
        int32_t ia = o->index[a], ib = o->index[b];
        if (ia < 0 && ib < 0) continue;
        double len = 0;
        for (size_t g = 0; g < km->k; g++) {
            double r = cm_kmesh_rel_length(km, g, a, b);
            len += r * r;
        }
        double w = 0.5 * (double)km->k / fmax(len, 1e-300); /* each interior edge is seen twice */
        if (ia >= 0) ti[e] = tj[e] = ia, tx[e++] = w;
        if (ib >= 0) ti[e] = tj[e] = ib, tx[e++] = w;
        if (ia >= 0 && ib >= 0) ti[e] = ia < ib ? ia : ib, tj[e] = ia < ib ? ib : ia, tx[e++] = -w;
    }
    tr->nnz = e;
    cholmod_sparse *a = cholmod_triplet_to_sparse(tr, 0, cc);
    cholmod_free_triplet(&tr, cc);
    return a;
}

static void mark_flat(optimiser *o, const double *pos)
{
    for (int32_t t = 0; t < o->km->nt; t++) {
        if (!cm_kmesh_tri_live(o->km, t)) continue;
        for (size_t g = 0; g < o->km->k; g++)
            if (flat(edges(o, pos, g, o->km->tri + 3 * (size_t)t))) o->frozen[t] = 1;
    }
}

double cm_mapopt_energy(const cm_kmesh *km, cm_mapopt_weights w)
{
    int32_t none = -1;
    optimiser o = {(cm_kmesh *)km, w, 0, NULL, NULL, NULL, NULL, NULL, NULL};
    int32_t *index = malloc((size_t)(km->nv > 0 ? km->nv : 1) * sizeof *index);
    if (!index) return INFINITY;
    for (int32_t v = 0; v < km->nv; v++) index[v] = none;
    o.index = index;
    o.frozen = calloc((size_t)(km->nt > 0 ? km->nt : 1), 1);
    if (!o.frozen) {
        free(index);
        return INFINITY;
    }
    mark_flat(&o, NULL);
    double e = energy(&o, NULL, 0);
    free(index), free(o.frozen);
    return e;
}

long cm_mapopt_run(cm_kmesh *km, cm_mapopt_weights w, int iterations)
{
    if (km->k > CM_MAPOPT_MAX_K) return 0;
    optimiser o = {km, w, 0, NULL, NULL, NULL, NULL, NULL, NULL};
    size_t k = km->k;
    o.index = malloc((size_t)km->nv * sizeof *o.index);
    if (!o.index) return -1;
    for (int32_t v = 0; v < km->nv; v++)
        o.index[v] = !cm_kmesh_is_boundary(km, v) && km->vc[v] >= 0 ? o.m++ : -1;
    if (o.m == 0) {
        free(o.index);
        return 0;
    }
    size_t len = 2 * k * (size_t)o.m;
    o.q = malloc(len * sizeof *o.q), o.trial = malloc(len * sizeof *o.trial);
    o.grad = malloc(len * sizeof *o.grad), o.dir = malloc(len * sizeof *o.dir);
    o.frozen = calloc((size_t)(km->nt > 0 ? km->nt : 1), 1);
    cholmod_common cc;
    cholmod_start(&cc);
    cc.print = 0, cc.error_handler = NULL;
    cholmod_sparse *lap = NULL;
    cholmod_factor *factor = NULL;
    long steps = -1;
    if (!o.q || !o.trial || !o.grad || !o.dir || !o.frozen) goto done;
    for (int32_t v = 0; v < km->nv; v++) {
        int32_t i = o.index[v];
        if (i < 0) continue;
        for (size_t g = 0; g < k; g++) {
            const double *p = cm_kmesh_pos(km, g, v);
            o.q[2 * (g * (size_t)o.m + (size_t)i)] = p[0] / km->scale[g];
            o.q[2 * (g * (size_t)o.m + (size_t)i) + 1] = p[1] / km->scale[g];
        }
    }
    mark_flat(&o, o.q);
    lap = laplacian(&o, &cc);
    if (lap) factor = cholmod_analyze(lap, &cc);
    if (!factor || !cholmod_factorize(lap, factor, &cc) || cc.status != CHOLMOD_OK) {
        /* no preconditioner (not positive definite in doubles): no steps */
        steps = !lap || !factor || cc.status == CHOLMOD_OUT_OF_MEMORY ? -1 : 0;
        goto done;
    }
    double tri_scratch[6];
    double e0 = energy(&o, o.q, 1);
    steps = 0;
    for (int it = 0; it < iterations && isfinite(e0); it++) {
        cholmod_dense b = {(size_t)o.m, 2 * k, 2 * k * (size_t)o.m, (size_t)o.m, o.grad, NULL, CHOLMOD_REAL,
                           CHOLMOD_DOUBLE};
        cholmod_dense *x = cholmod_solve(CHOLMOD_A, factor, &b, &cc);
        if (!x) {
            steps = cc.status == CHOLMOD_OUT_OF_MEMORY ? -1 : steps;
            break;
        }
        double slope = 0;
        const double *sol = x->x;
        for (size_t j = 0; j < len; j++) {
            o.dir[j] = isfinite(sol[j]) ? -sol[j] : 0.0;
            slope += o.dir[j] * o.grad[j];
        }
        cholmod_free_dense(&x, &cc);
        if (!(slope < 0)) break;
        double s = CM_MAPOPT_SHARE * flip_free_step(&o, 1.0 / CM_MAPOPT_SHARE);
        double e1 = INFINITY;
        int found = 0;
        for (int h = 0; h < CM_MAPOPT_HALVINGS && !found; h++, s *= 0.5) {
            /* dir is per column (geometry, axis); q is per vertex (x, y) */
            for (size_t g = 0; g < k; g++)
                for (int32_t i = 0; i < o.m; i++)
                    for (int axis = 0; axis < 2; axis++) {
                        size_t at = 2 * (g * (size_t)o.m + (size_t)i) + (size_t)axis;
                        o.trial[at] = o.q[at] + s * o.dir[(2 * g + (size_t)axis) * (size_t)o.m + (size_t)i];
                    }
            e1 = energy(&o, o.trial, 0);
            found = e1 <= e0 + CM_MAPOPT_ARMIJO * s * slope && valid_at(&o, o.trial, tri_scratch);
        }
        if (!found) break;
        memcpy(o.q, o.trial, len * sizeof *o.q);
        steps++;
        int converged = e0 - e1 < CM_MAPOPT_TOL * e0;
        e0 = energy(&o, o.q, 1);
        if (converged) break;
    }
    /* write back the last accepted state, checked exactly as stored */
    for (int32_t v = 0; v < km->nv && steps > 0; v++) {
        int32_t i = o.index[v];
        if (i < 0) continue;
        for (size_t g = 0; g < k; g++) {
            km->xy[g][2 * (size_t)v] = o.q[2 * (g * (size_t)o.m + (size_t)i)] * km->scale[g];
            km->xy[g][2 * (size_t)v + 1] = o.q[2 * (g * (size_t)o.m + (size_t)i) + 1] * km->scale[g];
        }
    }
    for (int32_t t = 0; t < km->nt && steps > 0; t++)
        if (cm_kmesh_tri_live(km, t)) cm_kmesh_touch(km, t);
done:
    cholmod_free_factor(&factor, &cc);
    cholmod_free_sparse(&lap, &cc);
    cholmod_finish(&cc);
    free(o.index), free(o.q), free(o.trial), free(o.grad), free(o.dir), free(o.frozen);
    return steps;
}

/* ---- one vertex at a time -------------------------------------------------- */

/* The energy of the triangles around v (star: its corners) with v at p
 * in geometry g, the gradient in p (normalised coordinates) into grad
 * when not NULL; flat triangles at the current position (skip[i]) left
 * out. */
static double star_energy(const cm_kmesh *km, cm_mapopt_weights w, const cm_ibuf *star,
                          const unsigned char *skip, size_t g, const double p[2], double grad[2])
{
    m2 e[CM_MAPOPT_MAX_K], ge[CM_MAPOPT_MAX_K];
    double total = 0, pw = w.power > 0 ? w.power : 1.0;
    if (grad) grad[0] = grad[1] = 0;
    for (size_t i = 0; i < star->n; i++) {
        if (skip[i]) continue;
        int32_t c = star->a[i], j = c % 3;
        const int32_t *v = km->tri + 3 * (c / 3);
        for (size_t a = 0; a < km->k; a++) {
            double q[3][2];
            for (int r = 0; r < 3; r++) {
                const double *x = a == g && r == j ? p : cm_kmesh_pos(km, a, v[r]);
                q[r][0] = x[0] / km->scale[a], q[r][1] = x[1] / km->scale[a];
            }
            e[a] = (m2){q[1][0] - q[0][0], q[2][0] - q[0][0], q[1][1] - q[0][1], q[2][1] - q[0][1]};
            ge[a] = (m2){0, 0, 0, 0};
        }
        for (size_t a = 0; a < km->k; a++) {
            if (w.shape > 0) total += w.shape * mips_power(equilateral, e[a], pw, w.shape, NULL, a == g ? &ge[a] : NULL);
            if (w.map > 0)
                for (size_t b = a + 1; b < km->k; b++)
                    total += w.map * mips_power(e[a], e[b], pw, w.map, a == g ? &ge[a] : NULL, b == g ? &ge[b] : NULL);
        }
        if (!isfinite(total)) return INFINITY;
        if (grad) { /* d/dp of the corner j of the edge matrix, back to unnormalised */
            m2 d = ge[g];
            double gx = j == 0 ? -(d.a + d.b) : j == 1 ? d.a : d.b;
            double gy = j == 0 ? -(d.c + d.d) : j == 1 ? d.c : d.d;
            grad[0] += gx / km->scale[g], grad[1] += gy / km->scale[g];
        }
    }
    return total;
}

/* Is every triangle around v counter-clockwise in geometry g with v at p
 * (exact)? */
static int star_valid(const cm_kmesh *km, const cm_ibuf *star, size_t g, const double p[2])
{
    for (size_t i = 0; i < star->n; i++) {
        int32_t c = star->a[i];
        if (cm_orient2d(p, cm_kmesh_pos(km, g, km->tri[cm_next(c)]), cm_kmesh_pos(km, g, km->tri[cm_prev(c)])) <= 0)
            return 0;
    }
    return 1;
}

/* One Newton step (Hessian by central differences of the gradient,
 * gradient descent where it is not positive definite) on v's position in
 * geometry g, backtracking until the energy drops and every triangle
 * around v stays valid. Returns 1 moved, 0 not. */
static int vertex_step(cm_kmesh *km, cm_mapopt_weights w, int32_t v, size_t g, const cm_ibuf *star,
                       unsigned char *skip)
{
    const double *now = cm_kmesh_pos(km, g, v);
    double p[2] = {now[0], now[1]}, grad[2], len = 0;
    for (size_t i = 0; i < star->n; i++) {
        const double *q = cm_kmesh_pos(km, g, km->tri[cm_next(star->a[i])]);
        len += hypot(q[0] - p[0], q[1] - p[1]) / (double)star->n;
        int32_t t = star->a[i] / 3;
        skip[i] = 0;
        for (size_t a = 0; a < km->k; a++) {
            const int32_t *tv = km->tri + 3 * t;
            const double *x = cm_kmesh_pos(km, a, tv[0]), *y = cm_kmesh_pos(km, a, tv[1]), *z = cm_kmesh_pos(km, a, tv[2]);
            if (flat((m2){y[0] - x[0], z[0] - x[0], y[1] - x[1], z[1] - x[1]})) skip[i] = 1;
        }
    }
    double e0 = star_energy(km, w, star, skip, g, p, grad);
    if (!isfinite(e0) || !(len > 0)) return 0;
    double h = 1e-4 * len, gp[2], gm[2], hess[4];
    for (int axis = 0; axis < 2; axis++) {
        double q[2] = {p[0], p[1]};
        q[axis] = p[axis] + h;
        double ep = star_energy(km, w, star, skip, g, q, gp);
        q[axis] = p[axis] - h;
        double em = star_energy(km, w, star, skip, g, q, gm);
        if (!isfinite(ep) || !isfinite(em)) return 0;
        hess[2 * axis] = (gp[0] - gm[0]) / (2 * h), hess[2 * axis + 1] = (gp[1] - gm[1]) / (2 * h);
    }
    double hxy = 0.5 * (hess[1] + hess[2]), dh = hess[0] * hess[3] - hxy * hxy, d[2];
    if (hess[0] > 0 && dh > 0) {
        d[0] = -(hess[3] * grad[0] - hxy * grad[1]) / dh;
        d[1] = -(hess[0] * grad[1] - hxy * grad[0]) / dh;
    } else {
        double gn = hypot(grad[0], grad[1]);
        if (!(gn > 0)) return 0;
        d[0] = -grad[0] / gn * 0.1 * len, d[1] = -grad[1] / gn * 0.1 * len;
    }
    double dn = hypot(d[0], d[1]);
    if (!(dn > 0)) return 0;
    double s = dn > 0.5 * len ? 0.5 * len / dn : 1.0;
    for (int halving = 0; halving < 12; halving++, s *= 0.5) {
        double q[2] = {p[0] + s * d[0], p[1] + s * d[1]};
        double e1 = star_energy(km, w, star, skip, g, q, NULL);
        if (e1 < e0 - 1e-12 * e0 && star_valid(km, star, g, q)) {
            cm_kmesh_move(km, g, v, q, star);
            return 1;
        }
    }
    return 0;
}

int cm_mapopt_vertex(cm_kmesh *km, cm_mapopt_weights w, int32_t v, int steps, cm_ibuf *star)
{
    if (km->k > CM_MAPOPT_MAX_K || cm_kmesh_is_boundary(km, v)) return 0;
    long m = cm_kmesh_star(km, v, star);
    if (m < 0) return m == -1 ? -1 : 0;
    unsigned char *skip = malloc((size_t)m);
    if (!skip) return -1;
    int moved = 0;
    for (int i = 0; i < steps; i++) {
        int any = 0;
        for (size_t g = 0; g < km->k; g++) any |= vertex_step(km, w, v, g, star, skip);
        if (!any) break;
        moved = 1;
    }
    free(skip);
    return moved;
}

long cm_mapopt_local(cm_kmesh *km, cm_mapopt_weights w, int sweeps)
{
    if (km->k > CM_MAPOPT_MAX_K) return 0;
    cm_ibuf star = {0};
    unsigned char *skip = NULL;
    size_t skip_cap = 0;
    long moves = 0;
    for (int sweep = 0; sweep < sweeps; sweep++) {
        long before = moves;
        for (int32_t v = km->n; v < km->nv; v++) {
            if (km->vc[v] < 0 || cm_kmesh_is_boundary(km, v)) continue;
            long m = cm_kmesh_star(km, v, &star);
            if (m == -1) goto oom;
            if (m < 0) continue;
            if ((size_t)m > skip_cap) {
                unsigned char *more = realloc(skip, (size_t)m);
                if (!more) goto oom;
                skip = more, skip_cap = (size_t)m;
            }
            for (size_t g = 0; g < km->k; g++) moves += vertex_step(km, w, v, g, &star, skip);
        }
        if (moves == before) break;
    }
    cm_ibuf_free(&star), free(skip);
    return moves;
oom:
    cm_ibuf_free(&star), free(skip);
    return -1;
}
