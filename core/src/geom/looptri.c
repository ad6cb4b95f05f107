/* Triangulation of one polygon with holes: the outer loop by ear clipping,
 * the hole vertices inserted into it one by one (each splits the triangle
 * it lies in, or the two beside the edge it lies on), each hole edge that
 * is missing made an edge by removing the triangles it crosses and ear
 * clipping the two polygons on either side of it, Lawson flips to the
 * constrained Delaunay triangulation, and the triangles inside the holes
 * dropped. Every decision is an exact predicate; the work is quadratic in
 * the worst case (point location and edge lookup scan the triangles), which
 * suits its one use, the guaranteed construction for holes. */
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "base/mesh.h"
#include "geom/looptri.h"
#include "geom/polytri.h"
#include "geom/predicates.h"

#define P(v) (xy + 2 * (size_t)(v))

typedef struct {
    const size_t *start;
    size_t n;
} loop_set;

static int32_t next_on_loop(const loop_set *s, int32_t v)
{
    return (int32_t)cm_loops_next(s->start, s->n, (size_t)v);
}

static int is_loop_edge(const void *user, int32_t a, int32_t b)
{
    const loop_set *s = user;
    return next_on_loop(s, a) == b || next_on_loop(s, b) == a;
}

static void put(int32_t *tri, long t, int32_t a, int32_t b, int32_t c)
{
    tri[3 * t] = a, tri[3 * t + 1] = b, tri[3 * t + 2] = c;
}

/* Inserts vertex v, strictly inside the triangulated region and on no
 * vertex. Returns the new triangle count, or -1 when v is not inside. */
static long insert_point(const double *xy, int32_t *tri, long nt, int32_t v)
{
    for (long t = 0; t < nt; t++) {
        int32_t c3[3] = {tri[3 * t], tri[3 * t + 1], tri[3 * t + 2]};
        int o[3], zeros = 0, zero = -1;
        for (int i = 0; i < 3; i++) {
            o[i] = cm_orient2d(P(c3[(i + 1) % 3]), P(c3[(i + 2) % 3]), P(v));
            if (o[i] == 0) zeros++, zero = i;
        }
        if (o[0] < 0 || o[1] < 0 || o[2] < 0) continue;
        if (zeros > 1) return -1;
        if (zeros == 0) {
            put(tri, t, c3[0], c3[1], v), put(tri, nt, c3[1], c3[2], v), put(tri, nt + 1, c3[2], c3[0], v);
            return nt + 2;
        }
        int32_t x = c3[zero], y = c3[(zero + 1) % 3], z = c3[(zero + 2) % 3];
        for (long u = 0; u < nt; u++) /* the triangle on the far side of y-z */
            for (int j = 0; j < 3; j++)
                if (tri[3 * u + j] == z && tri[3 * u + (j + 1) % 3] == y) {
                    int32_t w = tri[3 * u + (j + 2) % 3];
                    put(tri, t, x, y, v), put(tri, nt, x, v, z);
                    put(tri, u, w, z, v), put(tri, nt + 1, w, v, y);
                    return nt + 2;
                }
        return -1; /* on the boundary */
    }
    return -1;
}

static int has_edge(const int32_t *tri, long nt, int32_t a, int32_t b)
{
    for (long s = 0; s < 3 * nt; s++) {
        int32_t u = tri[s], w = tri[s - s % 3 + (s + 1) % 3];
        if ((u == a && w == b) || (u == b && w == a)) return 1;
    }
    return 0;
}

int cm_tri_insert_edge(const double *xy, int32_t *tri, long nt, int32_t a, int32_t b)
{
    if (has_edge(tri, nt, a, b)) return 0;
    int32_t *nbr = malloc((size_t)(3 * nt) * sizeof *nbr), *left = malloc((size_t)(nt + 2) * sizeof *left);
    int32_t *right = malloc((size_t)(nt + 2) * sizeof *right), *gone = malloc((size_t)nt * sizeof *gone);
    int32_t *poly = malloc((size_t)(nt + 4) * sizeof *poly), *out = malloc((size_t)(3 * nt) * sizeof *out);
    int status = CM_NO_MEMORY;
    if (!nbr || !left || !right || !gone || !poly || !out || cm_tri_adjacency(tri, nt, nbr) != 0) goto done;
    status = 1;
    long cur = -1, nl = 0, nr = 0, ng = 0;
    for (long s = 0; s < 3 * nt && cur < 0; s++) { /* the triangle at a that a-b leaves through */
        if (tri[s] != a) continue;
        int32_t x = tri[s - s % 3 + (s + 1) % 3], y = tri[s - s % 3 + (s + 2) % 3];
        if (cm_orient2d(P(a), P(x), P(b)) > 0 && cm_orient2d(P(a), P(y), P(b)) < 0)
            cur = s / 3, right[nr++] = x, left[nl++] = y;
    }
    if (cur < 0) goto done;
    gone[ng++] = (int32_t)cur;
    for (;;) {
        int32_t l = left[nl - 1], r = right[nr - 1];
        int i = 0;
        while (i < 3 && (tri[3 * cur + i] == l || tri[3 * cur + i] == r)) i++;
        long u = i < 3 ? nbr[3 * cur + i] : -1;
        if (u < 0 || ng == nt) goto done;
        gone[ng++] = (int32_t)u;
        int32_t w = tri[3 * u] != l && tri[3 * u] != r ? tri[3 * u]
                    : tri[3 * u + 1] != l && tri[3 * u + 1] != r ? tri[3 * u + 1]
                                                                  : tri[3 * u + 2];
        if (w == b) break;
        int o = cm_orient2d(P(a), P(b), P(w));
        if (o == 0) goto done;
        if (o > 0) left[nl++] = w;
        else right[nr++] = w;
        cur = u;
    }
    /* left of a->b: a, b, then the left chain back; right: b, a, the right chain */
    long m = 0, used = 0;
    poly[m++] = a, poly[m++] = b;
    for (long i = nl - 1; i >= 0; i--) poly[m++] = left[i];
    int s = cm_polygon_triangulate(xy, poly, m, out, NULL);
    if (s != 0) { status = s; goto done; }
    used = m - 2, m = 0;
    poly[m++] = b, poly[m++] = a;
    for (long i = 0; i < nr; i++) poly[m++] = right[i];
    s = cm_polygon_triangulate(xy, poly, m, out + 3 * used, NULL);
    if (s != 0) { status = s; goto done; }
    used += m - 2;
    if (used != ng) goto done;
    for (long i = 0; i < ng; i++) memcpy(tri + 3 * gone[i], out + 3 * i, 3 * sizeof *tri);
    status = 0;
done:
    free(nbr), free(left), free(right), free(gone), free(poly), free(out);
    return status;
}

/* Keeps the triangles on the material side of the loops: those left of a
 * loop edge in its direction, and all reached from them without crossing
 * a loop edge. Returns the count kept (compacted to the front), or -1. */
static long keep_material(int32_t *tri, long nt, const loop_set *ls)
{
    int32_t *nbr = malloc((size_t)(3 * nt) * sizeof *nbr), *stack = malloc((size_t)nt * sizeof *stack);
    unsigned char *keep = calloc((size_t)nt, 1);
    long kept = -1, top = 0;
    if (!nbr || !stack || !keep || cm_tri_adjacency(tri, nt, nbr) != 0) goto done;
    for (long s = 0; s < 3 * nt; s++)
        if (next_on_loop(ls, tri[s]) == tri[s - s % 3 + (s + 1) % 3] && !keep[s / 3])
            keep[s / 3] = 1, stack[top++] = (int32_t)(s / 3);
    while (top > 0) {
        long t = stack[--top];
        for (int i = 0; i < 3; i++) {
            long u = nbr[3 * t + i];
            if (u < 0 || keep[u] || is_loop_edge(ls, tri[3 * t + (i + 1) % 3], tri[3 * t + (i + 2) % 3])) continue;
            keep[u] = 1, stack[top++] = (int32_t)u;
        }
    }
    kept = 0;
    for (long t = 0; t < nt; t++)
        if (keep[t]) memmove(tri + 3 * kept++, tri + 3 * t, 3 * sizeof *tri);
done:
    free(nbr), free(stack), free(keep);
    return kept;
}

int cm_loops_triangulate(const double *xy, const size_t *loop_start, size_t num_loops, int32_t *tri_out)
{
    size_t n = loop_start[num_loops], n0 = loop_start[1];
    loop_set ls = {loop_start, n};
    long cap = (long)(n0 - 2 + 2 * (n - n0)), nt = (long)n0 - 2;
    int32_t *tri = malloc((size_t)(3 * cap) * sizeof *tri), *idx = malloc(n0 * sizeof *idx);
    int status = CM_NO_MEMORY;
    if (!tri || !idx) goto done;
    for (size_t i = 0; i < n0; i++) idx[i] = (int32_t)i;
    status = cm_polygon_triangulate(xy, idx, (long)n0, tri, NULL);
    for (size_t v = n0; status == 0 && v < n; v++)
        if ((nt = insert_point(xy, tri, nt, (int32_t)v)) < 0) status = 1;
    for (size_t v = n0; status == 0 && v < n; v++)
        status = cm_tri_insert_edge(xy, tri, nt, (int32_t)v, next_on_loop(&ls, (int32_t)v));
    if (status == 0) status = cm_tri_make_delaunay(xy, tri, nt, is_loop_edge, &ls);
    if (status == 0) {
        long kept = keep_material(tri, nt, &ls);
        if (kept < 0) status = CM_NO_MEMORY;
        else if ((size_t)kept != n + 2 * (num_loops - 1) - 2) status = 1;
        else memcpy(tri_out, tri, (size_t)(3 * kept) * sizeof *tri);
    }
done:
    free(tri), free(idx);
    return status;
}
