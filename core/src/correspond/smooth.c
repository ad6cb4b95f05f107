#include <math.h>
#include <stdlib.h>

#include "correspond/smooth.h"
#include "correspond/split.h"

/* ln of the length of edge j -> j + 1 of the common boundary, per polygon. */
typedef struct smooth_state {
    const cm_boundary_map *map;
    double **ln; /* k arrays of n */
    double tau;  /* jumps up to this are free */
} smooth_state;

static double penalty(const smooth_state *st, double d)
{
    d = fabs(d) - st->tau;
    return d > 0 ? d * d : 0;
}

static double ln_length(const cm_boundary_map *map, size_t g, size_t j)
{
    const double *a = map->xy[g] + 2 * j, *b = map->xy[g] + 2 * ((j + 1) % map->n);
    return log(hypot(b[0] - a[0], b[1] - a[1]));
}

/* The sum of squared jumps of ln stretch at vertices j - 1, j, j + 1 when
 * polygon g's edges j - 1 and j have ln lengths a and b (the rest as they
 * are). */
static double jumps(const smooth_state *st, size_t g, size_t j, double a, double b)
{
    const cm_boundary_map *map = st->map;
    const size_t n = map->n, jm = (j + n - 1) % n, jmm = (j + n - 2) % n, jp = (j + 1) % n;
    double sum = 0;
    for (size_t h = 1; h < map->k; h++) {
        const double *L = st->ln[h], *L0 = st->ln[0];
        double before = L[jmm] - L0[jmm], after = L[jp] - L0[jp], ul, ur;
        if (g == 0)
            ul = L[jm] - a, ur = L[j] - b;
        else if (g == h)
            ul = a - L0[jm], ur = b - L0[j];
        else
            ul = L[jm] - L0[jm], ur = L[j] - L0[j];
        sum += penalty(st, ul - before) + penalty(st, ur - ul) + penalty(st, after - ur);
    }
    return sum;
}

/* ln lengths of the two pieces of a segment of ln length d split at logit z. */
static void split_at(double d, double z, double *a, double *b)
{
    /* ln(1 / (1 + e^-z)) = -softplus(-z), stable for large |z|. */
    *a = d - (z < 0 ? -z + log1p(exp(z)) : log1p(exp(-z)));
    *b = d - (z > 0 ? z + log1p(exp(-z)) : log1p(exp(z)));
}

/* Places polygon g's vertex j (on an input edge, not its own) at its best
 * between its neighbours; 1 if it moved. */
static int place(smooth_state *st, const double *polygon, size_t count, int reversed, size_t g, size_t j)
{
    const cm_boundary_map *map = st->map;
    const size_t n = map->n, jm = (j + n - 1) % n, jp = (j + 1) % n;
    int32_t e, e2;
    double ta, tj, tj2, tb;
    cm_boundary_piece(map->edge[g][jm], map->t[g][jm], map->edge[g][j], map->t[g][j], count, reversed, &e, &ta,
                      &tj);
    cm_boundary_piece(map->edge[g][j], map->t[g][j], map->edge[g][jp], map->t[g][jp], count, reversed, &e2, &tj2,
                      &tb);
    if (e != map->edge[g][j] || e2 != e || !(tb != ta)) return 0;
    const double *pa = map->xy[g] + 2 * jm, *pb = map->xy[g] + 2 * jp;
    double d = log(hypot(pb[0] - pa[0], pb[1] - pa[1]));
    double lambda0 = (tj - ta) / (tb - ta);
    if (!(lambda0 > 0 && lambda0 < 1) || !isfinite(d)) return 0;
    /* Pieces no shorter than about 1e-3 of the segment unless already so. */
    double z0 = log(lambda0 / (1 - lambda0)), lo = fmin(z0, -7.0), hi = fmax(z0, 7.0);
    double best_z = z0, a, b, best;
    split_at(d, z0, &a, &b);
    best = jumps(st, g, j, a, b);
    const int grid = 48;
    for (int i = 0; i <= grid; i++) {
        double z = lo + (hi - lo) * i / grid;
        split_at(d, z, &a, &b);
        double f = jumps(st, g, j, a, b);
        if (f < best) best = f, best_z = z;
    }
    /* Golden section around the best grid point. */
    double step = (hi - lo) / grid, x0 = fmax(lo, best_z - step), x3 = fmin(hi, best_z + step);
    const double r = 0.6180339887498949;
    double x1 = x3 - r * (x3 - x0), x2 = x0 + r * (x3 - x0), f1, f2;
    split_at(d, x1, &a, &b), f1 = jumps(st, g, j, a, b);
    split_at(d, x2, &a, &b), f2 = jumps(st, g, j, a, b);
    for (int i = 0; i < 40; i++) {
        if (f1 < f2)
            x3 = x2, x2 = x1, f2 = f1, x1 = x3 - r * (x3 - x0), split_at(d, x1, &a, &b), f1 = jumps(st, g, j, a, b);
        else
            x0 = x1, x1 = x2, f1 = f2, x2 = x0 + r * (x3 - x0), split_at(d, x2, &a, &b), f2 = jumps(st, g, j, a, b);
    }
    double zc = f1 < f2 ? x1 : x2, fc = fmin(f1, f2);
    if (fc < best) best = fc, best_z = zc;
    if (best_z == z0) return 0;
    double lambda = 1 / (1 + exp(-best_z)), t = ta + lambda * (tb - ta), xy[2];
    /* Strictly inside the edge and between the neighbours, at a point of
     * its own. */
    if (!(t > 0 && t < 1) || !((t - ta) * (tb - t) > 0)) return 0;
    cm_edge_point(polygon, count, e, t, xy);
    if ((xy[0] == pa[0] && xy[1] == pa[1]) || (xy[0] == pb[0] && xy[1] == pb[1])) return 0;
    double old_t = map->t[g][j], old[2] = {map->xy[g][2 * j], map->xy[g][2 * j + 1]};
    map->t[g][j] = t, map->xy[g][2 * j] = xy[0], map->xy[g][2 * j + 1] = xy[1];
    double ljm = ln_length(map, g, jm), lj = ln_length(map, g, j);
    if (!isfinite(ljm) || !isfinite(lj) || jumps(st, g, j, ljm, lj) > jumps(st, g, j, st->ln[g][jm], st->ln[g][j])) {
        map->t[g][j] = old_t, map->xy[g][2 * j] = old[0], map->xy[g][2 * j + 1] = old[1];
        return 0;
    }
    st->ln[g][jm] = ljm, st->ln[g][j] = lj;
    return 1;
}

cm_status cm_boundary_map_smooth(cm_boundary_map *map, const double *const *polygons, const size_t *counts,
                                 const int *orientation, int sweeps, cm_error *err)
{
    const size_t k = map->k, n = map->n;
    if (k < 2 || n < 4 || sweeps <= 0) return CM_OK;
    const char *env = getenv("CM_SMOOTH_TAU");
    smooth_state st = {map, calloc(k, sizeof(double *)), env ? atof(env) : 0};
    cm_status s = st.ln ? CM_OK : cm_fail_status(err, CM_ERR_NO_MEMORY);
    for (size_t g = 0; s == CM_OK && g < k; g++) {
        st.ln[g] = malloc(n * sizeof **st.ln);
        if (!st.ln[g]) {
            s = cm_fail_status(err, CM_ERR_NO_MEMORY);
            break;
        }
        for (size_t j = 0; j < n; j++) st.ln[g][j] = ln_length(map, g, j);
    }
    for (int sweep = 0; s == CM_OK && sweep < sweeps; sweep++) {
        size_t moved = 0;
        for (size_t j = 0; j < n; j++)
            for (size_t g = 0; g < k; g++)
                if (map->t[g][j] != 0) moved += (size_t)place(&st, polygons[g], counts[g], orientation[g] < 0, g, j);
        if (!moved) break;
    }
    for (size_t g = 0; st.ln && g < k; g++) free(st.ln[g]);
    free(st.ln);
    return s;
}
