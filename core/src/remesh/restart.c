/* The restart's start (restart.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "remesh/restart.h"

/* The dilatation (largest over smallest singular value) of the affine map
 * taking triangle t of geometry 0 onto geometry g's: K with K + 1/K =
 * |J|^2 / det J; the largest over the geometries. */
static double dilatation(const cm_mesh *m, size_t t)
{
    const int32_t *v = m->tri + 3 * t;
    const double *a0 = m->xy[0] + 2 * v[0], *a1 = m->xy[0] + 2 * v[1], *a2 = m->xy[0] + 2 * v[2];
    double e00 = a1[0] - a0[0], e01 = a2[0] - a0[0], e10 = a1[1] - a0[1], e11 = a2[1] - a0[1];
    double worst = 1.0;
    for (size_t g = 1; g < m->k; g++) {
        const double *b0 = m->xy[g] + 2 * v[0], *b1 = m->xy[g] + 2 * v[1], *b2 = m->xy[g] + 2 * v[2];
        double f00 = b1[0] - b0[0], f01 = b2[0] - b0[0], f10 = b1[1] - b0[1], f11 = b2[1] - b0[1];
        /* J = F E^-1 times det E, which leaves K as it is */
        double j00 = f00 * e11 - f01 * e10, j01 = f01 * e00 - f00 * e01;
        double j10 = f10 * e11 - f11 * e10, j11 = f11 * e00 - f10 * e01;
        double q = (j00 * j00 + j01 * j01 + j10 * j10 + j11 * j11) / fabs(j00 * j11 - j01 * j10);
        double K = 0.5 * (q + sqrt(fmax(0.0, q * q - 4.0)));
        worst = K > worst ? K : K == K ? worst : HUGE_VAL; /* NaN: a triangle of no area, the worst */
    }
    return worst;
}

static int descending(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? 1 : x > y ? -1 : 0;
}

static int32_t edge_end(const cm_mesh *m, size_t c) { return m->tri[cm_corner_next(c)]; }

/* Per corner c (edge from tri[c] to the next vertex): its twin corner in
 * the neighbouring triangle, -1 on the boundary. */
static int32_t *twins(const cm_mesh *m)
{
    size_t ne = 3 * m->nt;
    cm_edge_key *e = cm_mesh_edge_keys(m->tri, m->nt);
    int32_t *twin = malloc((ne + 1) * sizeof *twin);
    if (!e || !twin) {
        free(e), free(twin);
        return NULL;
    }
    for (size_t c = 0; c < ne; c++) twin[c] = -1;
    for (size_t i = 0; i + 1 < ne; i++)
        if (e[i].lo == e[i + 1].lo && e[i].hi == e[i + 1].hi)
            twin[e[i].corner] = e[i + 1].corner, twin[e[i + 1].corner] = e[i].corner;
    free(e);
    return twin;
}

/* Which edges to split: per corner, the new vertex on its edge or -1. */
static cm_status choose_splits(const cm_mesh *m, double share, const int32_t *twin, int32_t *mid, size_t *nv)
{
    size_t nt = m->nt;
    double *K = malloc(nt * sizeof *K), *sorted = malloc(nt * sizeof *sorted);
    if (!K || !sorted) {
        free(K), free(sorted);
        return CM_ERR_NO_MEMORY;
    }
    for (size_t t = 0; t < nt; t++) sorted[t] = K[t] = dilatation(m, t);
    qsort(sorted, nt, sizeof *sorted, descending);
    size_t take = (size_t)(share * (double)nt);
    double least = sorted[take < nt ? take : nt - 1];
    for (size_t c = 0; c < 3 * nt; c++) mid[c] = -1;
    for (size_t t = 0; t < nt; t++)
        for (size_t c = 3 * t; K[t] >= least && c < 3 * t + 3; c++)
            if (twin[c] >= 0 && mid[c] < 0) mid[c] = mid[twin[c]] = (int32_t)(*nv)++;
    free(K), free(sorted);
    return CM_OK;
}

/* Triangle t (vertices a b c from corner r on, its edges' new vertices
 * mab mbc mca or -1) cut by the pattern of its split edges; the pieces
 * written at out, their count returned (0: the pattern does not start at
 * corner r). */
static size_t cut(int32_t a, int32_t b, int32_t c, int32_t mab, int32_t mbc, int32_t mca, int32_t *out)
{
    int32_t pieces[4][3];
    size_t n = 0;
    if (mab >= 0 && mbc >= 0 && mca >= 0) {
        int32_t p[4][3] = {{a, mab, mca}, {mab, b, mbc}, {mca, mbc, c}, {mab, mbc, mca}};
        memcpy(pieces, p, sizeof p), n = 4;
    } else if (mab < 0 && mbc >= 0 && mca >= 0) {
        int32_t p[3][3] = {{a, b, mbc}, {a, mbc, mca}, {mca, mbc, c}};
        memcpy(pieces, p, sizeof p), n = 3;
    } else if (mab < 0 && mbc >= 0 && mca < 0) {
        int32_t p[2][3] = {{a, b, mbc}, {a, mbc, c}};
        memcpy(pieces, p, sizeof p), n = 2;
    } else if (mab < 0 && mbc < 0 && mca < 0) {
        int32_t p[1][3] = {{a, b, c}};
        memcpy(pieces, p, sizeof p), n = 1;
    }
    memcpy(out, pieces, n * sizeof *pieces);
    return n;
}

cm_status cm_restart_refine(const cm_mesh *in, double share, cm_mesh *out)
{
    size_t ne = 3 * in->nt, nv = in->nv;
    int32_t *twin = twins(in), *mid = malloc(ne * sizeof *mid);
    cm_status s = twin && mid ? choose_splits(in, share, twin, mid, &nv) : CM_ERR_NO_MEMORY;
    *out = (cm_mesh){.k = in->k, .loop_start = in->loop_start, .num_loops = in->num_loops};
    if (s == CM_OK) {
        out->xy = calloc(in->k, sizeof *out->xy);
        out->tri = malloc(4 * ne * sizeof *out->tri);
        if (!out->xy || !out->tri) s = CM_ERR_NO_MEMORY;
    }
    for (size_t g = 0; s == CM_OK && g < in->k; g++) {
        double *xy = out->xy[g] = malloc(2 * nv * sizeof *xy);
        if (!xy) {
            s = CM_ERR_NO_MEMORY;
            break;
        }
        memcpy(xy, in->xy[g], 2 * in->nv * sizeof *xy);
        for (size_t c = 0; c < ne; c++)
            if (mid[c] >= 0) {
                const double *p = in->xy[g] + 2 * in->tri[c], *q = in->xy[g] + 2 * edge_end(in, c);
                xy[2 * mid[c]] = 0.5 * (p[0] + q[0]), xy[2 * mid[c] + 1] = 0.5 * (p[1] + q[1]);
            }
    }
    for (size_t t = 0; s == CM_OK && t < in->nt; t++) {
        const int32_t *v = in->tri + 3 * t, *e = mid + 3 * t;
        size_t pieces = 0;
        for (int r = 0; r < 3 && !pieces; r++)
            pieces = cut(v[r], v[(r + 1) % 3], v[(r + 2) % 3], e[r], e[(r + 1) % 3], e[(r + 2) % 3],
                         out->tri + 3 * out->nt);
        out->nt += pieces;
    }
    out->nv = nv;
    free(twin), free(mid);
    if (s != CM_OK) cm_mesh_clear(out);
    return s;
}
