/* Linear finite elements on a polygon (fe.h). */
#include "correspond/fe.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/keymap.h"
#include "geom/looptri.h"
#include "geom/polytri.h"


void cm_fe_free(cm_fe_mesh *m)
{
    free(m->xy), free(m->tri), free(m->bnode), free(m->loop_first);
    if (m->started) {
        cholmod_free_sparse(&m->a, &m->cc);
        cholmod_free_factor(&m->factor, &m->cc);
        cholmod_finish(&m->cc);
    }
    free(m->kx), free(m->fixed), free(m->u), free(m->rhs);
    memset(m, 0, sizeof *m);
}

/* The node at the middle of edge ab, made (after the nv nodes so far)
 * the first time the edge is met. -1 out of memory. */
static int32_t midpoint_node(cm_keymap *mid, const double *from, double *xy, long *nv, int32_t a, int32_t b)
{
    int added;
    int64_t *node = cm_keymap_put(mid, cm_pair_key(a, b), &added);
    if (!node) return -1;
    if (added) {
        *node = *nv;
        xy[2 * *nv] = 0.5 * (from[2 * a] + from[2 * b]), xy[2 * *nv + 1] = 0.5 * (from[2 * a + 1] + from[2 * b + 1]);
        ++*nv;
    }
    return (int32_t)*node;
}

/* Every triangle split into four at its edge midpoints (one new node per
 * edge). */
static int split(cm_fe_mesh *m)
{
    cm_keymap mid = {0};
    long edges_max = 3 * m->nt; /* at most, before sharing */
    double *xy = malloc(2 * (size_t)(m->nv + edges_max) * sizeof *xy);
    int32_t *tri = malloc(12 * (size_t)m->nt * sizeof *tri);
    int32_t *bnode = malloc(2 * (size_t)m->nb * sizeof *bnode);
    int ok = xy && tri && bnode && cm_keymap_reserve(&mid, (size_t)edges_max) == 0;
    long nv = m->nv;
    if (ok) memcpy(xy, m->xy, 2 * (size_t)m->nv * sizeof *xy);
    for (long t = 0; ok && t < m->nt; t++) {
        int32_t a = m->tri[3 * t], b = m->tri[3 * t + 1], c = m->tri[3 * t + 2];
        int32_t ab = midpoint_node(&mid, m->xy, xy, &nv, a, b), bc = midpoint_node(&mid, m->xy, xy, &nv, b, c);
        int32_t ca = midpoint_node(&mid, m->xy, xy, &nv, c, a);
        int32_t *o = tri + 12 * t;
        o[0] = a, o[1] = ab, o[2] = ca;
        o[3] = ab, o[4] = b, o[5] = bc;
        o[6] = ca, o[7] = bc, o[8] = c;
        o[9] = ab, o[10] = bc, o[11] = ca;
        ok = ab >= 0 && bc >= 0 && ca >= 0;
    }
    for (long j = 0; ok && j < m->nb; j++) {
        int32_t a = m->bnode[j], b = m->bnode[cm_fe_next_boundary(m, j)];
        int32_t ab = midpoint_node(&mid, m->xy, xy, &nv, a, b);
        bnode[2 * j] = a, bnode[2 * j + 1] = ab;
        ok = ab >= 0;
    }
    cm_keymap_free(&mid);
    if (!ok) {
        free(xy), free(tri), free(bnode);
        return CM_NO_MEMORY;
    }
    free(m->xy), free(m->tri), free(m->bnode);
    m->xy = xy, m->tri = tri, m->bnode = bnode;
    m->nv = nv, m->nt *= 4, m->nb *= 2, m->levels++;
    for (size_t l = 0; l <= m->num_loops; l++) m->loop_first[l] *= 2;
    return 0;
}

long cm_fe_next_boundary(const cm_fe_mesh *m, long j)
{
    size_t l = 0;
    while (j >= m->loop_first[l + 1]) l++;
    return j + 1 < m->loop_first[l + 1] ? j + 1 : m->loop_first[l];
}

double cm_fe_tri(const cm_fe_mesh *m, long t, double d[3][2])
{
    const int32_t *v = m->tri + 3 * t;
    const double *a = m->xy + 2 * v[0], *b = m->xy + 2 * v[1], *c = m->xy + 2 * v[2];
    /* the edge opposite corner i, from corner i + 1 to i + 2 */
    d[0][0] = c[0] - b[0], d[0][1] = c[1] - b[1];
    d[1][0] = a[0] - c[0], d[1][1] = a[1] - c[1];
    d[2][0] = b[0] - a[0], d[2][1] = b[1] - a[1];
    return d[0][0] * d[1][1] - d[0][1] * d[1][0];
}

static cm_status chol_status(cm_fe_mesh *m, cm_error *err)
{
    if (m->cc.status == CHOLMOD_OUT_OF_MEMORY) return cm_fail_status(err, CM_ERR_NO_MEMORY);
    return cm_fail(err, CM_ERR_INTERNAL, "finite elements: CHOLMOD failed (status %d)", m->cc.status);
}

/* a's values: the stiffness, with fixed rows and columns the identity. */
static void fill(cm_fe_mesh *m)
{
    const int *ap = m->a->p, *ai = m->a->i;
    double *ax = m->a->x;
    for (int j = 0; j < (int)m->nv; j++)
        for (int p = ap[j]; p < ap[j + 1]; p++) {
            int i = ai[p];
            ax[p] = m->fixed[i] || m->fixed[j] ? (i == j) : m->kx[p];
        }
}

/* Compressed columns of the upper triangle of the stiffness matrix from
 * the triangles (duplicates summed). 0 or CM_NO_MEMORY. */
static int assemble(cm_fe_mesh *m, int *usable)
{
    /* column counts over the pairs i <= j of every triangle, then fill */
    int *count = calloc((size_t)m->nv + 1, sizeof *count), *next = NULL;
    int *ti = NULL;
    double *tx = NULL;
    size_t nz = 6 * (size_t)m->nt;
    if (!count) return CM_NO_MEMORY;
    ti = malloc(nz * sizeof *ti), tx = malloc(nz * sizeof *tx), next = malloc(((size_t)m->nv + 1) * sizeof *next);
    int *tcol = malloc(nz * sizeof *tcol);
    int status = ti && tx && next && tcol ? 0 : CM_NO_MEMORY;
    size_t e = 0;
    for (long t = 0; t < m->nt && !status; t++) {
        double d[3][2], a2 = cm_fe_tri(m, t, d);
        if (!(a2 > 0) || !isfinite(a2)) {
            *usable = 0;
            break;
        }
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) {
                int r = m->tri[3 * t + i], c = m->tri[3 * t + j];
                if (r > c) continue;
                ti[e] = r, tcol[e] = c;
                tx[e++] = (d[i][0] * d[j][0] + d[i][1] * d[j][1]) / (2 * a2);
                count[c + 1]++;
            }
    }
    if (!status && *usable) {
        for (long c = 0; c < m->nv; c++) count[c + 1] += count[c];
        /* bucket by column, then merge duplicate rows in each column */
        int *ri = malloc(e * sizeof *ri);
        double *rx = malloc(e * sizeof *rx);
        int *mark = malloc((size_t)m->nv * sizeof *mark);
        if (!ri || !rx || !mark) status = CM_NO_MEMORY;
        if (!status) {
            memcpy(next, count, ((size_t)m->nv + 1) * sizeof *next);
            for (size_t x = 0; x < e; x++) {
                int p = next[tcol[x]]++;
                ri[p] = ti[x], rx[p] = tx[x];
            }
            size_t unique = 0;
            for (long i = 0; i < m->nv; i++) mark[i] = -1;
            /* first pass: unique entries per column */
            for (long c = 0; c < m->nv; c++)
                for (int p = count[c]; p < count[c + 1]; p++)
                    if (mark[ri[p]] != (int)c) mark[ri[p]] = (int)c, unique++;
            m->a = cholmod_allocate_sparse((size_t)m->nv, (size_t)m->nv, unique, 0, 1, 1, CHOLMOD_REAL, &m->cc);
            m->kx = malloc(unique * sizeof *m->kx);
            if (!m->a || !m->kx) status = CM_NO_MEMORY;
        }
        if (!status) {
            int *ap = m->a->p, *ai = m->a->i, q = 0;
            for (long i = 0; i < m->nv; i++) mark[i] = -1;
            for (long c = 0; c < m->nv; c++) {
                ap[c] = q;
                for (int p = count[c]; p < count[c + 1]; p++) {
                    if (mark[ri[p]] < ap[c]) {
                        mark[ri[p]] = q;
                        ai[q] = ri[p], m->kx[q++] = rx[p];
                    } else {
                        m->kx[mark[ri[p]]] += rx[p];
                    }
                }
            }
            ap[m->nv] = q;
        }
        free(ri), free(rx), free(mark);
    }
    free(count), free(next), free(ti), free(tx), free(tcol);
    return status;
}

/* The mesh's arrays for the n vertices xy in num_loops loops (loop_start:
 * num_loops + 1 first vertices) and nt triangles (left to fill). */
static cm_status start_mesh(cm_fe_mesh *m, const double *xy, size_t n, long nt, const size_t *loop_start,
                            size_t num_loops, cm_error *err)
{
    memset(m, 0, sizeof *m);
    m->nv = (long)n, m->nt = nt, m->nb = (long)n, m->num_loops = num_loops;
    m->xy = malloc(2 * n * sizeof *m->xy);
    m->tri = malloc(3 * (size_t)nt * sizeof *m->tri);
    m->bnode = malloc(n * sizeof *m->bnode);
    m->loop_first = malloc((num_loops + 1) * sizeof *m->loop_first);
    if (!m->xy || !m->tri || !m->bnode || !m->loop_first) return cm_fail_status(err, CM_ERR_NO_MEMORY);
    memcpy(m->xy, xy, 2 * n * sizeof *m->xy);
    for (size_t i = 0; i < n; i++) m->bnode[i] = (int32_t)i;
    for (size_t l = 0; l <= num_loops; l++) m->loop_first[l] = (long)loop_start[l];
    return CM_OK;
}

/* Split until min_triangles, the stiffness matrix, its analysis with the
 * boundary fixed. */
static cm_status finish_mesh(cm_fe_mesh *m, long min_triangles, int *usable, cm_error *err)
{
    while (m->nt < min_triangles)
        if (split(m)) return cm_fail_status(err, CM_ERR_NO_MEMORY);

    m->fixed = malloc((size_t)m->nv);
    m->u = malloc((size_t)m->nv * sizeof *m->u);
    m->rhs = malloc((size_t)m->nv * sizeof *m->rhs);
    if (!m->fixed || !m->u || !m->rhs) return cm_fail_status(err, CM_ERR_NO_MEMORY);
    cholmod_start(&m->cc);
    m->started = 1;
    m->cc.print = 0, m->cc.error_handler = NULL;
    if (assemble(m, usable) || m->cc.status == CHOLMOD_OUT_OF_MEMORY) return cm_fail_status(err, CM_ERR_NO_MEMORY);
    if (!*usable) return CM_OK;
    /* The pattern analysed once (fill-reducing order), on the matrix with
     * the boundary fixed. */
    memset(m->fixed, 0, (size_t)m->nv);
    for (long j = 0; j < m->nb; j++) m->fixed[m->bnode[j]] = 1;
    fill(m);
    m->factor = cholmod_analyze(m->a, &m->cc);
    return m->factor ? CM_OK : chol_status(m, err);
}

cm_status cm_fe_build(cm_fe_mesh *m, const double *xy, const int32_t *tri, size_t n, long min_triangles, int *usable,
                      cm_error *err)
{
    *usable = 1;
    const size_t one_loop[2] = {0, n};
    cm_status s = start_mesh(m, xy, n, (long)n - 2, one_loop, 1, err);
    if (s != CM_OK) return s;
    if (tri) {
        memcpy(m->tri, tri, 3 * (n - 2) * sizeof *m->tri);
    } else {
        int32_t *idx = malloc(n * sizeof *idx);
        if (!idx) return cm_fail_status(err, CM_ERR_NO_MEMORY);
        for (size_t i = 0; i < n; i++) idx[i] = (int32_t)i;
        int t = cm_polygon_triangulate(xy, idx, (long)n, m->tri, NULL);
        free(idx);
        if (t == CM_NO_MEMORY) return cm_fail_status(err, CM_ERR_NO_MEMORY);
        if (t != 0) return cm_fail(err, CM_ERR_INTERNAL, "finite elements: a polygon has no ear");
    }
    return finish_mesh(m, min_triangles, usable, err);
}

cm_status cm_fe_build_loops(cm_fe_mesh *m, const double *xy, const size_t *loop_start, size_t num_loops,
                            long min_triangles, int *usable, cm_error *err)
{
    *usable = 1;
    size_t n = loop_start[num_loops];
    cm_status s = start_mesh(m, xy, n, (long)(n + 2 * (num_loops - 1)) - 2, loop_start, num_loops, err);
    if (s != CM_OK) return s;
    int t = cm_loops_triangulate(xy, loop_start, num_loops, m->tri);
    if (t == CM_NO_MEMORY) return cm_fail_status(err, CM_ERR_NO_MEMORY);
    if (t != 0) return cm_fail(err, CM_ERR_INTERNAL, "finite elements: the loops do not bound a polygon");
    return finish_mesh(m, min_triangles, usable, err);
}

cm_status cm_fe_solve(cm_fe_mesh *m, long source, int refactor, cm_error *err)
{
    const int *ap = m->a->p, *ai = m->a->i;
    memset(m->rhs, 0, (size_t)m->nv * sizeof *m->rhs);
    /* Fixed values all 0 (a harmonic measure) contribute nothing: the
     * loop below would only subtract zeros from +0. */
    int loaded = 0;
    for (long i = 0; i < m->nv && !loaded; i++) loaded = m->fixed[i] && m->u[i] != 0;
    for (int j = 0; loaded && j < (int)m->nv; j++)
        for (int p = ap[j]; p < ap[j + 1]; p++) { /* upper triangle: both (i, j) and (j, i) */
            int i = ai[p];
            if (i == j) continue;
            if (m->fixed[j] && !m->fixed[i]) m->rhs[i] -= m->kx[p] * m->u[j];
            if (m->fixed[i] && !m->fixed[j]) m->rhs[j] -= m->kx[p] * m->u[i];
        }
    for (long i = 0; i < m->nv; i++)
        if (m->fixed[i]) m->rhs[i] = m->u[i];
    if (source >= 0) m->rhs[source] += 1.0;
    if (refactor) {
        fill(m);
        if (!cholmod_factorize(m->a, m->factor, &m->cc) || m->cc.status == CHOLMOD_OUT_OF_MEMORY)
            return chol_status(m, err);
    }
    /* Not positive definite in doubles (status CHOLMOD_NOT_POSDEF): u
     * below is still admissible, only less good. */
    cholmod_dense b = {(size_t)m->nv, 1, (size_t)m->nv, (size_t)m->nv, m->rhs, NULL, CHOLMOD_REAL, CHOLMOD_DOUBLE};
    cholmod_dense *x = m->cc.status == CHOLMOD_OK ? cholmod_solve(CHOLMOD_A, m->factor, &b, &m->cc) : NULL;
    if (!x && m->cc.status == CHOLMOD_OUT_OF_MEMORY) return chol_status(m, err);
    const double *sol = x ? x->x : NULL;
    for (long i = 0; i < m->nv; i++)
        if (!m->fixed[i]) m->u[i] = sol && isfinite(sol[i]) ? sol[i] : 0.0;
    cholmod_free_dense(&x, &m->cc);
    return CM_OK;
}

long cm_fe_sample_interior(cm_fe_mesh *m, long *sample)
{
    memset(m->fixed, 0, (size_t)m->nv);
    memset(m->u, 0, (size_t)m->nv * sizeof *m->u);
    for (long j = 0; j < m->nb; j++) m->fixed[m->bnode[j]] = 1;
    long interior = m->nv - m->nb, stride = interior > CM_FE_SAMPLE ? interior / CM_FE_SAMPLE : 1, seen = 0, ns = 0;
    for (long v = 0; v < m->nv && ns < CM_FE_SAMPLE; v++)
        if (!m->fixed[v] && seen++ % stride == 0) sample[ns++] = v;
    return ns;
}

/* The squared distance from p to the polygon (its first n nodes), or, as
 * soon as some edge is no farther than floor, that edge's: a node no
 * deeper than the deepest so far needs no more edges. The edges are tried
 * from *near on (the least of the distances, whatever their order), and
 * *near becomes the edge that stopped the scan: the next node, most often
 * a neighbour, is likely near it too. */
static double depth2_above(const cm_fe_mesh *m, size_t n, const double *p, double floor, size_t *near)
{
    double dist = INFINITY;
    for (size_t k = 0, i = *near; k < n && dist > floor; k++, i = i + 1 < n ? i + 1 : 0) {
        *near = i;
        const double *a = m->xy + 2 * i, *b = m->xy + 2 * (i + 1 < n ? i + 1 : 0);
        double ex = b[0] - a[0], ey = b[1] - a[1], px = p[0] - a[0], py = p[1] - a[1];
        double t = fmin(1.0, fmax(0.0, (px * ex + py * ey) / (ex * ex + ey * ey)));
        double dx = px - t * ex, dy = py - t * ey;
        if (dx * dx + dy * dy < dist) dist = dx * dx + dy * dy;
    }
    return dist;
}

long cm_fe_deepest(const cm_fe_mesh *m, size_t n, const long *sample, long ns)
{
    double best = -1;
    long deepest = sample[0];
    size_t near = 0;
    for (long j = 0; j < ns; j++) {
        double d = depth2_above(m, n, m->xy + 2 * sample[j], best, &near);
        if (d > best) best = d, deepest = sample[j];
    }
    return deepest;
}

void cm_fe_residual(const cm_fe_mesh *m, double *out)
{
    const int *ap = m->a->p, *ai = m->a->i;
    memset(out, 0, (size_t)m->nv * sizeof *out);
    for (int j = 0; j < (int)m->nv; j++)
        for (int p = ap[j]; p < ap[j + 1]; p++) { /* upper triangle: both (i, j) and (j, i) */
            int i = ai[p];
            out[i] += m->kx[p] * m->u[j];
            if (i != j) out[j] += m->kx[p] * m->u[i];
        }
}

cm_status cm_fe_harmonic_measure(cm_fe_mesh *m, long source, int refactor, double *w, cm_error *err)
{
    memset(m->fixed, 0, (size_t)m->nv);
    memset(m->u, 0, (size_t)m->nv * sizeof *m->u);
    for (long j = 0; j < m->nb; j++) m->fixed[m->bnode[j]] = 1;
    cm_status s = cm_fe_solve(m, source, refactor, err);
    if (s != CM_OK) return s;
    /* flux out of boundary node b: -(K u)_b */
    cm_fe_residual(m, m->rhs);
    double total = 0;
    for (long j = 0; j < m->nb; j++) total += fmax(0.0, -m->rhs[m->bnode[j]]);
    for (long j = 0; j < m->nb; j++) w[j] = total > 0 ? fmax(0.0, -m->rhs[m->bnode[j]]) / total : 1.0 / (double)m->nb;
    return CM_OK;
}
