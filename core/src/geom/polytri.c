/* Triangulation of one simple polygon: ear clipping, then Lawson flips to
 * the constrained Delaunay triangulation (which maximises the minimum angle
 * over all triangulations of the polygon). Every decision is exact. */
#include <stdlib.h>

#include "base/error.h"
#include "geom/polytri.h"
#include "base/progress.h"
#include "geom/predicates.h"

#define P(v) (xy + 2 * (size_t)(v))

/* Is any vertex of the ring (other than a, b, c) inside or on the closed
 * triangle abc? Only vertices that are not strictly convex can be: if the
 * triangle contains a vertex it contains a reflex one. */
static int ear_blocked(const double *xy, const int32_t *idx, const long *prev,
                       const long *next, const signed char *convex, long a, long b,
                       long c)
{
    for (long v = next[c]; v != a; v = next[v]) {
        if (convex[v] > 0) continue;
        const double *p = P(idx[v]);
        if (cm_orient2d(P(idx[a]), P(idx[b]), p) >= 0 &&
            cm_orient2d(P(idx[b]), P(idx[c]), p) >= 0 &&
            cm_orient2d(P(idx[c]), P(idx[a]), p) >= 0)
            return 1;
    }
    (void)prev;
    return 0;
}

static void update_vertex(const double *xy, const int32_t *idx, const long *prev,
                          const long *next, signed char *convex, signed char *ear,
                          long v)
{
    convex[v] = (signed char)cm_orient2d(P(idx[prev[v]]), P(idx[v]), P(idx[next[v]]));
    ear[v] = convex[v] > 0 &&
             !ear_blocked(xy, idx, prev, next, convex, prev[v], v, next[v]);
}

static int clip_ears(const double *xy, const int32_t *idx, long m, int32_t *tri, cm_progress *progress)
{
    long *prev = malloc((size_t)m * sizeof *prev), *next = malloc((size_t)m * sizeof *next);
    signed char *convex = malloc((size_t)m), *ear = malloc((size_t)m);
    int status = -1;
    if (!prev || !next || !convex || !ear) goto done;
    for (long i = 0; i < m; i++) {
        prev[i] = (i + m - 1) % m;
        next[i] = (i + 1) % m;
    }
    for (long i = 0; i < m; i++)
        convex[i] = (signed char)cm_orient2d(P(idx[prev[i]]), P(idx[i]), P(idx[next[i]]));
    for (long i = 0; i < m; i++) {
        ear[i] = convex[i] > 0 && !ear_blocked(xy, idx, prev, next, convex, prev[i], i, next[i]);
        if (cm_progress_check(progress)) {
            status = CM_CANCELLED;
            goto done;
        }
    }

    long remaining = m, v = 0, since_last_clip = 0, t = 0;
    status = 1;
    while (remaining > 3) {
        if (ear[v]) {
            long a = prev[v], c = next[v];
            tri[3 * t] = idx[a], tri[3 * t + 1] = idx[v], tri[3 * t + 2] = idx[c];
            t++;
            next[a] = c, prev[c] = a;
            remaining--;
            update_vertex(xy, idx, prev, next, convex, ear, a);
            update_vertex(xy, idx, prev, next, convex, ear, c);
            since_last_clip = 0;
            v = c;
            if (cm_progress_check(progress)) {
                status = CM_CANCELLED;
                goto done;
            }
        } else {
            if (++since_last_clip > remaining) goto done; /* no ear: not simple */
            v = next[v];
        }
    }
    if (cm_orient2d(P(idx[prev[v]]), P(idx[v]), P(idx[next[v]])) <= 0) goto done;
    tri[3 * t] = idx[prev[v]], tri[3 * t + 1] = idx[v], tri[3 * t + 2] = idx[next[v]];
    status = 0;
done:
    free(prev), free(next), free(convex), free(ear);
    return status;
}

/* Triangle adjacency: nbr[3t + i] is the triangle across the edge opposite
 * corner i (from corner i+1 to corner i+2), -1 on the boundary. */
/* ---- triangle adjacency ------------------------------------------------- */

typedef struct { int32_t lo, hi; long slot; } edge_slot;

static int compare_edge_slots(const void *pa, const void *pb)
{
    const edge_slot *x = pa, *y = pb;
    if (x->lo != y->lo) return x->lo < y->lo ? -1 : 1;
    return (x->hi > y->hi) - (x->hi < y->hi);
}

int cm_tri_adjacency(const int32_t *tri, long nt, int32_t *nbr)
{
    edge_slot *e = malloc((size_t)(3 * nt + 1) * sizeof *e);
    if (!e) return -1;
    for (long s = 0; s < 3 * nt; s++) {
        int32_t a = tri[s - s % 3 + (s + 1) % 3], b = tri[s - s % 3 + (s + 2) % 3];
        e[s] = (edge_slot){a < b ? a : b, a < b ? b : a, s};
        nbr[s] = -1;
    }
    qsort(e, (size_t)(3 * nt), sizeof *e, compare_edge_slots);
    for (long s = 0; s + 1 < 3 * nt; s++) {
        if (compare_edge_slots(&e[s], &e[s + 1]) != 0) continue;
        nbr[e[s].slot] = (int32_t)(e[s + 1].slot / 3);
        nbr[e[s + 1].slot] = (int32_t)(e[s].slot / 3);
        s++;
    }
    free(e);
    return 0;
}

static long corner_facing(const int32_t *nbr, long t, long other)
{
    for (int i = 0; i < 3; i++)
        if (nbr[3 * t + i] == other) return i;
    return -1;
}

/* Flips the edge opposite corner i of triangle t if it is not locally
 * Delaunay. Returns 1 if flipped. Triangles (a,b,c) with edge b-c shared by
 * u = (c,b,d): become (a,b,d) and (a,d,c). */
static int flip_if_illegal(const double *xy, int32_t *tri, int32_t *nbr, long t, long i)
{
    long u = nbr[3 * t + i];
    if (u < 0) return 0;
    long j = corner_facing(nbr, u, t);
    int32_t a = tri[3 * t + i], b = tri[3 * t + (i + 1) % 3], c = tri[3 * t + (i + 2) % 3];
    int32_t d = tri[3 * u + j];
    if (cm_incircle(P(a), P(b), P(c), P(d)) <= 0) return 0;
    if (cm_orient2d(P(a), P(b), P(d)) <= 0 || cm_orient2d(P(a), P(d), P(c)) <= 0) return 0;
    long t_ab = nbr[3 * t + (i + 2) % 3], t_ca = nbr[3 * t + (i + 1) % 3];
    long u_bd = nbr[3 * u + (j + 1) % 3], u_dc = nbr[3 * u + (j + 2) % 3];
    /* u's corners: d at j, c at j+1, b at j+2 (u = (c, b, d) rotated). */
    tri[3 * t] = a, tri[3 * t + 1] = b, tri[3 * t + 2] = d;
    nbr[3 * t] = u_bd, nbr[3 * t + 1] = u, nbr[3 * t + 2] = t_ab;
    tri[3 * u] = a, tri[3 * u + 1] = d, tri[3 * u + 2] = c;
    nbr[3 * u] = u_dc, nbr[3 * u + 1] = t_ca, nbr[3 * u + 2] = t;
    if (u_bd >= 0) nbr[3 * u_bd + corner_facing(nbr, u_bd, u)] = t;
    if (t_ca >= 0) nbr[3 * t_ca + corner_facing(nbr, t_ca, t)] = u;
    return 1;
}

static int make_delaunay(const double *xy, int32_t *tri, long nt, cm_progress *progress)
{
    int32_t *nbr = malloc((size_t)(3 * nt) * sizeof *nbr);
    long *stack = malloc((size_t)(3 * nt) * sizeof *stack);
    char *queued = calloc((size_t)nt, 1);
    int status = -1;
    if (!nbr || !stack || !queued || cm_tri_adjacency(tri, nt, nbr) != 0) goto done;
    /* A stack of triangles to re-examine; a flip re-queues both triangles. */
    long top = 0;
    for (long t = 0; t < nt; t++) stack[top++] = t, queued[t] = 1;
    while (top > 0) {
        if (cm_progress_check(progress)) {
            status = CM_CANCELLED;
            goto done;
        }
        long t = stack[--top];
        queued[t] = 0;
        for (long i = 0; i < 3; i++) {
            long u = nbr[3 * t + i];
            if (u >= 0 && flip_if_illegal(xy, tri, nbr, t, i)) {
                if (!queued[u]) stack[top++] = u, queued[u] = 1;
                if (!queued[t]) stack[top++] = t, queued[t] = 1;
                break;
            }
        }
    }
    status = 0;
done:
    free(nbr), free(stack), free(queued);
    return status;
}

int cm_polygon_triangulate(const double *xy, const int32_t *idx, long m, int32_t *tri_out,
                           cm_progress *progress)
{
    int s = clip_ears(xy, idx, m, tri_out, progress);
    if (s != 0) return s;
    return make_delaunay(xy, tri_out, m - 2, progress);
}
