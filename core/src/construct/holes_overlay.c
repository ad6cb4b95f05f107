/* The guaranteed construction for polygons with holes: one bridge per
 * hole, the same tree of bridges in every geometry, routed in each through
 * its own triangulation; the bridges cut the polygon open into one disc D
 * whose boundary cycle is the same in every geometry, and the
 * Aronov-Seidel-Souvaine overlay (construct/overlay.c) triangulates the
 * discs compatibly.
 *
 * Why it always ends, with a valid result or CM_ERR_PRECISION:
 *  - The tree: hole after hole (nearest first, distances summed over the
 *    geometries) gets a bridge from one of its vertices to an unused vertex
 *    of the outer loop or of a hole joined before it. j joined loops (each
 *    of at least 3 vertices) have used 2 (j - 1) vertices, so at least
 *    j + 2 are free: there always is one.
 *  - Routing, in each geometry on its own: the material minus the bridges
 *    drawn so far is connected (each bridge joins a loop not yet reached to
 *    the reached ones, and cutting along an arc between two boundary
 *    components never disconnects a surface), so the triangles adjacent
 *    across edges that are not bridges form a connected graph and a
 *    breadth-first search from the triangles at p reaches those at q. On a
 *    shortest walk T0 .. Tk, only T0 has p and only Tk has q, so the path
 *    p, m1, .., mk, q (mi on the edge between T(i-1) and Ti) has exactly
 *    one segment inside each triangle: it is simple and touches no loop and
 *    no earlier bridge. Splitting the crossed edges at the mi makes its
 *    segments edges of the triangulation. Fewer bends: from each bend kept,
 *    the furthest later mi a straight segment reaches inside the walk's
 *    triangles (exact tests) is the next; such a segment is made an edge by
 *    re-triangulating the triangles it crosses (geom/looptri.h), and where
 *    that fails every mi is kept as above.
 *    Lawson flips then make the triangulation constrained Delaunay (loops
 *    and bridges fixed): valid triangles stay valid.
 *  - The bridges of every geometry get the same number of bends by
 *    splitting their segments (where the four new triangles are roundest:
 *    a midpoint can land next to another bridge's bend).
 *  - Every loop vertex ends at most one bridge and every bend is on one,
 *    so walking the material's boundary, a bridge taken where it starts,
 *    visits the same cycle (loop vertices, bridge ends and bends twice) in
 *    every geometry: D. Each geometry's triangulation, its corners read
 *    as positions of that cycle, triangulates D without interior vertices
 *    (|D| - 2 triangles), which is what the overlay takes; the overlay adds
 *    no vertex on D's boundary, so mapping positions back to vertices
 *    glues the two sides of every bridge.
 *  - Rounding: a bend is a rounded point on an edge. Where a triangle
 *    around it comes out not strictly positive (only beside slivers
 *    thinner than the spacing of doubles) the crossed edge is barred and
 *    the search runs again; when no path is left, or the overlay cannot
 *    place a vertex, the result is CM_ERR_PRECISION, never an invalid
 *    mesh, and the caller's exact check sees every result. Straightened
 *    segments keep clear of the walk's vertices (CLEARANCE), so that no
 *    sliver the overlay cannot round is made on purpose. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "construct/holes_overlay.h"
#include "base/buf.h"
#include "construct/overlay.h"
#include "geom/looptri.h"
#include "geom/polytri.h"
#include "geom/predicates.h"

/* A simplified bridge segment passes its walk's vertices no closer than
 * this share of its length. */
#define CLEARANCE 1e-6

/* One geometry's triangulation, cut along the bridges as they are routed. */
typedef struct cut {
    double *xy;
    size_t nv, cap_v;
    int32_t *tri, *nbr;     /* nbr[3t + i]: across the edge opposite corner i */
    unsigned char *wall;    /* per corner: the edge opposite it is a bridge segment */
    size_t nt, cap_t;
    cm_ibuf *path;          /* per bridge: its vertices from the hole to the other end */
} cut;

/* What cut_restore puts back: the vertices are only ever appended. */
typedef struct saved {
    size_t nv, nt;
    int32_t *tri, *nbr;
    unsigned char *wall;
} saved;

static int reserve(cut *c, size_t nt, size_t nv)
{
    if (nt > c->cap_t) {
        size_t cap = 2 * nt;
        int32_t *tri = realloc(c->tri, 3 * cap * sizeof *tri);
        if (!tri) return CM_NO_MEMORY;
        c->tri = tri;
        int32_t *nbr = realloc(c->nbr, 3 * cap * sizeof *nbr);
        if (!nbr) return CM_NO_MEMORY;
        c->nbr = nbr;
        unsigned char *wall = realloc(c->wall, 3 * cap);
        if (!wall) return CM_NO_MEMORY;
        c->wall = wall;
        c->cap_t = cap;
    }
    if (nv > c->cap_v) {
        double *xy = realloc(c->xy, 4 * nv * sizeof *xy);
        if (!xy) return CM_NO_MEMORY;
        c->xy = xy, c->cap_v = 2 * nv;
    }
    return 0;
}

static int cut_save(const cut *c, saved *s)
{
    s->nv = c->nv, s->nt = c->nt;
    s->tri = malloc(3 * c->nt * sizeof *s->tri), s->nbr = malloc(3 * c->nt * sizeof *s->nbr);
    s->wall = malloc(3 * c->nt);
    if (!s->tri || !s->nbr || !s->wall) return CM_NO_MEMORY;
    memcpy(s->tri, c->tri, 3 * c->nt * sizeof *s->tri), memcpy(s->nbr, c->nbr, 3 * c->nt * sizeof *s->nbr);
    memcpy(s->wall, c->wall, 3 * c->nt);
    return 0;
}

static void cut_restore(cut *c, const saved *s)
{
    c->nv = s->nv, c->nt = s->nt;
    memcpy(c->tri, s->tri, 3 * c->nt * sizeof *s->tri), memcpy(c->nbr, s->nbr, 3 * c->nt * sizeof *s->nbr);
    memcpy(c->wall, s->wall, 3 * c->nt);
}

static void saved_free(saved *s)
{
    free(s->tri), free(s->nbr), free(s->wall);
    memset(s, 0, sizeof *s);
}

static const double *at(const cut *c, int32_t v) { return c->xy + 2 * (size_t)v; }

static int corner_of(const cut *c, long t, int32_t v)
{
    for (int i = 0; i < 3; i++)
        if (c->tri[3 * t + i] == v) return i;
    return -1;
}

/* The corner slot facing edge a -> b (a, b consecutive counter-clockwise
 * in its triangle), or -1. */
static long facing(const cut *c, int32_t a, int32_t b)
{
    for (size_t s = 0; s < 3 * c->nt; s++)
        if (c->tri[s] == a && c->tri[s - s % 3 + (s + 1) % 3] == b) return (long)(s - s % 3 + (s + 2) % 3);
    return -1;
}

static void set_tri(cut *c, long t, const int32_t v[3], const int32_t nb[3], const unsigned char w[3])
{
    for (int i = 0; i < 3; i++) c->tri[3 * t + i] = v[i], c->nbr[3 * t + i] = nb[i], c->wall[3 * t + i] = w[i];
}

static void repoint(cut *c, long t, long from, long to)
{
    if (t < 0) return;
    for (int i = 0; i < 3; i++)
        if (c->nbr[3 * t + i] == from) c->nbr[3 * t + i] = (int32_t)to;
}

/* Splits the interior edge facing slot s at new vertex m: its two
 * triangles become four; the halves keep the edge's wall flag. Room for
 * two more triangles must be reserved. */
static void split_edge(cut *c, long s, int32_t m)
{
    long t = s / 3, u = c->nbr[s];
    int i = (int)(s % 3), i1 = (i + 1) % 3, i2 = (i + 2) % 3;
    int32_t x = c->tri[s], y = c->tri[3 * t + i1], z = c->tri[3 * t + i2];
    int32_t ny = c->nbr[3 * t + i1], nz = c->nbr[3 * t + i2];
    unsigned char wx = c->wall[s], wy = c->wall[3 * t + i1], wz = c->wall[3 * t + i2];
    int j = (corner_of(c, u, z) + 2) % 3; /* u = (w, z, y) from corner j */
    int32_t w = c->tri[3 * u + j], my = c->nbr[3 * u + (j + 2) % 3], mz = c->nbr[3 * u + (j + 1) % 3];
    unsigned char wuy = c->wall[3 * u + (j + 2) % 3], wuz = c->wall[3 * u + (j + 1) % 3];
    long t2 = (long)c->nt, u2 = t2 + 1;
    c->nt += 2;
    set_tri(c, t, (int32_t[3]){x, y, m}, (int32_t[3]){(int32_t)u2, (int32_t)t2, nz}, (unsigned char[3]){wx, 0, wz});
    set_tri(c, t2, (int32_t[3]){x, m, z}, (int32_t[3]){(int32_t)u, ny, (int32_t)t}, (unsigned char[3]){wx, wy, 0});
    set_tri(c, u, (int32_t[3]){w, z, m}, (int32_t[3]){(int32_t)t2, (int32_t)u2, my}, (unsigned char[3]){wx, 0, wuy});
    set_tri(c, u2, (int32_t[3]){w, m, y}, (int32_t[3]){(int32_t)t, mz, (int32_t)u}, (unsigned char[3]){wx, wuz, 0});
    repoint(c, ny, t, t2);
    repoint(c, mz, u, u2);
}

/* New vertex at the rounded midpoint of a and b. */
static int32_t midpoint_vertex(cut *c, int32_t a, int32_t b)
{
    const double *p = at(c, a), *q = at(c, b);
    int32_t m = (int32_t)c->nv++;
    c->xy[2 * (size_t)m] = 0.5 * (p[0] + q[0]), c->xy[2 * (size_t)m + 1] = 0.5 * (p[1] + q[1]);
    return m;
}

/* A triangle with a corner at vertex first or later that is not strictly
 * counter-clockwise: that corner's vertex, or -1 when there is none. */
static int32_t bad_new_corner(const cut *c, int32_t first)
{
    for (size_t t = 0; t < c->nt; t++) {
        const int32_t *v = c->tri + 3 * t;
        if ((v[0] >= first || v[1] >= first || v[2] >= first) && cm_orient2d(at(c, v[0]), at(c, v[1]), at(c, v[2])) <= 0)
            return v[0] >= first ? v[0] : v[1] >= first ? v[1] : v[2];
    }
    return -1;
}

/* Marks edge a-b a bridge segment on both sides. 0, or 1 when missing. */
static int set_wall(cut *c, int32_t a, int32_t b)
{
    long s = facing(c, a, b), r = facing(c, b, a);
    if (s < 0 || r < 0) return 1;
    c->wall[s] = c->wall[r] = 1;
    return 0;
}

/* Breadth-first over triangles across edges that are neither loops,
 * bridges nor barred, from those at p to the first at q. Writes the slots
 * crossed (each in the triangle before the crossing) to cross; returns how
 * many, or -1 when q is not reached. */
static long search(const cut *c, int32_t p, int32_t q, const unsigned char *barred, int32_t *from, int32_t *queue,
                   int32_t *cross)
{
    size_t head = 0, tail = 0;
    long target = -1;
    for (size_t t = 0; t < c->nt; t++) {
        from[t] = -1;
        if (corner_of(c, (long)t, p) >= 0) from[t] = -2, queue[tail++] = (int32_t)t;
    }
    while (head < tail && target < 0) {
        long t = queue[head++];
        if (corner_of(c, t, q) >= 0) target = t;
        for (int i = 0; i < 3 && target < 0; i++) {
            long s = 3 * t + i, u = c->nbr[s];
            if (u < 0 || c->wall[s] || barred[s] || from[u] != -1) continue;
            from[u] = (int32_t)s, queue[tail++] = (int32_t)u;
        }
    }
    if (target < 0) return -1;
    long k = 0;
    for (long t = target; from[t] >= 0; t = from[t] / 3) cross[k++] = from[t];
    for (long a = 0, b = k - 1; a < b; a++, b--) {
        int32_t tmp = cross[a];
        cross[a] = cross[b], cross[b] = tmp;
    }
    return k;
}

/* The walk of a search from p to q: its crossed edges (ends: 2 per
 * crossing), its triangles (sleeve: k + 1) and the points a path may bend
 * at (pts: p, the crossed edges' rounded midpoints, q). */
typedef struct walk {
    long k;
    int32_t p, q;
    int32_t *ends, *sleeve;
    double *pts;
} walk;

static int same_edge(const int32_t *e, int32_t u, int32_t x)
{
    return (e[0] == u && e[1] == x) || (e[0] == x && e[1] == u);
}

/* Does the segment from point a to point b > a + 1 of the walk stay inside
 * its triangles a .. b - 1: crossing each edge between properly and
 * touching no other edge of them? At p the first triangle's edges meet it
 * at p alone, as it crosses the edge opposite p (at q the same). */
static int reaches(const cut *c, const walk *w, long a, long b)
{
    const double *A = w->pts + 2 * a, *B = w->pts + 2 * b;
    double len = hypot(B[0] - A[0], B[1] - A[1]);
    for (long i = a + 1; i < b; i++) {
        const double *y = at(c, w->ends[2 * (i - 1)]), *z = at(c, w->ends[2 * (i - 1) + 1]);
        if (cm_segments_intersect(A, B, y, z) != 1) return 0;
        /* and clear of their ends: a segment grazing a vertex makes slivers
         * the overlay cannot round (a heuristic; validity is exact) */
        for (int e = 0; e < 2; e++) {
            const double *v = e ? z : y;
            if (fabs((B[0] - A[0]) * (v[1] - A[1]) - (B[1] - A[1]) * (v[0] - A[0])) < CLEARANCE * len * len) return 0;
        }
    }
    for (long i = a; i < b; i++) {
        const int32_t *v = c->tri + 3 * (size_t)w->sleeve[i];
        for (int e = 0; e < 3; e++) {
            int32_t u = v[(e + 1) % 3], x = v[(e + 2) % 3];
            if ((i > 0 && same_edge(w->ends + 2 * (i - 1), u, x)) || (i < w->k && same_edge(w->ends + 2 * i, u, x)))
                continue;
            if ((i == 0 && (u == w->p || x == w->p)) || (i == w->k && (u == w->q || x == w->q))) continue;
            if (cm_segments_intersect(A, B, at(c, u), at(c, x)) != 0) return 0;
        }
    }
    return 1;
}

/* Routes bridge j from p to q (see the top): the walk's midpoints, fewest
 * kept where a straight segment between kept ones stays inside the walk's
 * triangles (simplify), each such segment then made an edge. CM_OK,
 * CM_ERR_NO_MEMORY, or CM_ERR_PRECISION when every path left has a bend
 * that rounds badly. */
static cm_status route(cut *c, size_t j, int32_t p, int32_t q)
{
    size_t nt0 = c->nt;
    int32_t *from = malloc(nt0 * sizeof *from), *queue = malloc(nt0 * sizeof *queue);
    int32_t *cross = malloc(nt0 * sizeof *cross), *kept = malloc((nt0 + 2) * sizeof *kept);
    walk w = {0, p, q, malloc(2 * nt0 * sizeof *w.ends), malloc((nt0 + 1) * sizeof *w.sleeve),
              malloc(2 * (nt0 + 2) * sizeof *w.pts)};
    unsigned char *barred = calloc(3 * nt0, 1);
    saved before = {0};
    cm_status s = CM_ERR_NO_MEMORY;
    int simplify = 1;
    if (!from || !queue || !cross || !kept || !w.ends || !w.sleeve || !w.pts || !barred || cut_save(c, &before) != 0)
        goto done;
    for (;;) {
        long k = search(c, p, q, barred, from, queue, cross);
        if (k < 0) {
            s = CM_ERR_PRECISION;
            goto done;
        }
        if (reserve(c, c->nt + 2 * (size_t)k, c->nv + (size_t)k) != 0) goto done;
        w.k = k;
        memcpy(w.pts, at(c, p), 2 * sizeof(double)), memcpy(w.pts + 2 * (k + 1), at(c, q), 2 * sizeof(double));
        for (long i = 0; i < k; i++) { /* the crossed edges, before any split renumbers them */
            long t = cross[i] / 3, ci = cross[i] % 3;
            int32_t y = c->tri[3 * t + (ci + 1) % 3], z = c->tri[3 * t + (ci + 2) % 3];
            w.ends[2 * i] = y, w.ends[2 * i + 1] = z, w.sleeve[i] = (int32_t)t;
            w.pts[2 * (i + 1)] = 0.5 * (at(c, y)[0] + at(c, z)[0]), w.pts[2 * (i + 1) + 1] = 0.5 * (at(c, y)[1] + at(c, z)[1]);
        }
        if (k > 0) w.sleeve[k] = c->nbr[cross[k - 1]];
        long nk = 0;
        for (long a = 0; a < k + 1;) {
            long b = a + 1;
            while (simplify && b < k + 1 && reaches(c, &w, a, b + 1)) b++;
            if (b < k + 1) kept[nk++] = (int32_t)b;
            a = b;
        }
        int32_t first = (int32_t)c->nv;
        c->path[j].n = 0;
        if (cm_ibuf_push(&c->path[j], p) != 0) goto done;
        for (long i = 0; i < nk; i++) {
            const int32_t *e = w.ends + 2 * (kept[i] - 1);
            int32_t m = midpoint_vertex(c, e[0], e[1]);
            split_edge(c, facing(c, e[0], e[1]), m);
            if (cm_ibuf_push(&c->path[j], m) != 0) goto done;
        }
        if (cm_ibuf_push(&c->path[j], q) != 0) goto done;
        int32_t bad = bad_new_corner(c, first);
        if (bad >= 0) { /* bar that crossing and search again */
            long slot = cross[kept[bad - first] - 1], u = before.nbr[slot];
            barred[slot] = 1;
            for (int e = 0; e < 3; e++)
                if (u >= 0 && before.nbr[3 * u + e] == slot / 3) barred[3 * u + e] = 1;
            cut_restore(c, &before);
            continue;
        }
        int made = 0;
        for (size_t i = 0; i + 1 < c->path[j].n && made == 0; i++)
            made = cm_tri_insert_edge(c->xy, c->tri, (long)c->nt, c->path[j].a[i], c->path[j].a[i + 1]);
        if (made == CM_NO_MEMORY || (made == 0 && cm_tri_adjacency(c->tri, (long)c->nt, c->nbr) != 0)) goto done;
        if (made != 0) { /* not inside after all: every midpoint kept */
            cut_restore(c, &before);
            simplify = 0;
            continue;
        }
        memset(c->wall, 0, 3 * c->nt);
        for (size_t b = 0; b <= j; b++)
            for (size_t i = 0; i + 1 < c->path[b].n; i++)
                if (set_wall(c, c->path[b].a[i], c->path[b].a[i + 1])) {
                    s = CM_ERR_INTERNAL;
                    goto done;
                }
        break;
    }
    s = CM_OK;
done:
    free(from), free(queue), free(cross), free(kept), free(w.ends), free(w.sleeve), free(w.pts), free(barred);
    saved_free(&before);
    return s;
}

/* Area over squared longest edge: 0 for a sliver, 0.43 equilateral. */
static double roundness(const double *a, const double *b, const double *c)
{
    double area = fabs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])) / 2;
    double l = fmax(hypot(b[0] - a[0], b[1] - a[1]), fmax(hypot(c[0] - b[0], c[1] - b[1]), hypot(a[0] - c[0], a[1] - c[1])));
    return l > 0 ? area / (l * l) : 0;
}

typedef struct { double score, t; size_t segment; } split_choice;

static int by_score(const void *a, const void *b)
{
    const split_choice *x = a, *y = b;
    return (x->score < y->score) - (x->score > y->score);
}

/* Gives bridge j `want` bends by splitting its segments: each new bend at
 * the point (of a few along each segment) whose four triangles are
 * roundest, so that it keeps away from the vertices around (a midpoint
 * can land next to another bridge's bend). CM_OK, CM_ERR_NO_MEMORY or
 * CM_ERR_PRECISION. */
static const double split_at[5] = {0.5, 0.375, 0.625, 0.25, 0.75};

static cm_status pad(cut *c, size_t j, size_t want)
{
    cm_ibuf *path = &c->path[j];
    while (path->n - 2 < want) {
        size_t m = path->n - 1, count = 0;
        split_choice *choice = malloc(5 * m * sizeof *choice);
        saved before = {0};
        if (!choice || reserve(c, c->nt + 2, c->nv + 1) != 0 || cut_save(c, &before) != 0) {
            free(choice), saved_free(&before);
            return CM_ERR_NO_MEMORY;
        }
        for (size_t i = 0; i < m; i++) {
            int32_t a = path->a[i], b = path->a[i + 1];
            long s = facing(c, a, b);
            if (s < 0 || c->nbr[s] < 0) continue;
            long u = c->nbr[s];
            int32_t x = c->tri[s], y = c->tri[3 * u + (corner_of(c, u, a) + 1) % 3];
            for (int e = 0; e < 5; e++) {
                double t = split_at[e], q[2] = {at(c, a)[0] + t * (at(c, b)[0] - at(c, a)[0]),
                                                at(c, a)[1] + t * (at(c, b)[1] - at(c, a)[1])};
                double r = fmin(fmin(roundness(at(c, x), at(c, a), q), roundness(at(c, x), q, at(c, b))),
                                fmin(roundness(at(c, y), at(c, b), q), roundness(at(c, y), q, at(c, a))));
                choice[count++] = (split_choice){r, t, i};
            }
        }
        qsort(choice, count, sizeof *choice, by_score);
        int found = 0;
        for (size_t ci = 0; ci < count && !found; ci++) {
            size_t i = choice[ci].segment;
            int32_t a = path->a[i], b = path->a[i + 1], mid = (int32_t)c->nv++;
            double t = choice[ci].t;
            c->xy[2 * (size_t)mid] = at(c, a)[0] + t * (at(c, b)[0] - at(c, a)[0]);
            c->xy[2 * (size_t)mid + 1] = at(c, a)[1] + t * (at(c, b)[1] - at(c, a)[1]);
            split_edge(c, facing(c, a, b), mid);
            if (bad_new_corner(c, mid) >= 0) {
                cut_restore(c, &before);
                continue;
            }
            found = 1;
            if (cm_ibuf_push(path, 0) != 0) {
                free(choice), saved_free(&before);
                return CM_ERR_NO_MEMORY;
            }
            memmove(path->a + i + 2, path->a + i + 1, (path->n - i - 2) * sizeof *path->a);
            path->a[i + 1] = mid;
        }
        free(choice), saved_free(&before);
        if (!found) return CM_ERR_PRECISION;
    }
    return CM_OK;
}

/* Triangulates geometry g with its loops and makes the adjacency. */
static cm_status cut_init(cut *c, const double *xy, const size_t *loop_start, size_t num_loops, size_t bridges)
{
    size_t n = loop_start[num_loops], nt = n + 2 * (num_loops - 1) - 2;
    c->path = calloc(bridges + 1, sizeof *c->path);
    if (!c->path || reserve(c, nt, n) != 0) return CM_ERR_NO_MEMORY;
    memcpy(c->xy, xy, 2 * n * sizeof *xy);
    c->nv = n, c->nt = nt;
    int s = cm_loops_triangulate(xy, loop_start, num_loops, c->tri);
    if (s == CM_NO_MEMORY || (s == 0 && cm_tri_adjacency(c->tri, (long)nt, c->nbr) != 0)) return CM_ERR_NO_MEMORY;
    if (s != 0) return CM_ERR_INTERNAL;
    memset(c->wall, 0, 3 * nt);
    return CM_OK;
}

/* Is a-b a bridge segment? (bridge_nbr: the two neighbours along its
 * bridge of every vertex, -1 where none) */
static int is_segment(const void *user, int32_t a, int32_t b)
{
    const int32_t *nbr = user;
    return nbr[2 * (size_t)a] == b || nbr[2 * (size_t)a + 1] == b;
}

/* Lawson flips to the triangulation that is constrained Delaunay for the
 * loops and the bridges (the cavities' ear clipping leaves slivers a flip
 * removes, and the overlay rounds better without them), then the
 * adjacency and walls again. 0, CM_NO_MEMORY, or 1 (a bridge segment lost). */
static int cut_delaunay(cut *c, size_t bridges)
{
    int32_t *along = malloc(2 * c->nv * sizeof *along);
    if (!along) return CM_NO_MEMORY;
    for (size_t v = 0; v < 2 * c->nv; v++) along[v] = -1;
    for (size_t j = 0; j < bridges; j++)
        for (size_t i = 0; i + 1 < c->path[j].n; i++) {
            int32_t a = c->path[j].a[i], b = c->path[j].a[i + 1];
            along[2 * (size_t)a + (along[2 * (size_t)a] >= 0)] = b;
            along[2 * (size_t)b + (along[2 * (size_t)b] >= 0)] = a;
        }
    int s = cm_tri_make_delaunay(c->xy, c->tri, (long)c->nt, is_segment, along);
    free(along);
    if (s == 0) s = cm_tri_adjacency(c->tri, (long)c->nt, c->nbr);
    if (s != 0) return s;
    memset(c->wall, 0, 3 * c->nt);
    for (size_t j = 0; j < bridges; j++)
        for (size_t i = 0; i + 1 < c->path[j].n; i++)
            if (set_wall(c, c->path[j].a[i], c->path[j].a[i + 1])) return 1;
    return 0;
}

static void cut_free(cut *c, size_t bridges)
{
    free(c->xy), free(c->tri), free(c->nbr), free(c->wall);
    for (size_t j = 0; c->path && j < bridges; j++) cm_ibuf_free(&c->path[j]);
    free(c->path);
}

typedef struct { double len; int32_t p, q; } link;

static double span(const double *const *geoms, size_t k, int32_t a, int32_t b)
{
    double len = 0;
    for (size_t g = 0; g < k; g++) {
        const double *p = geoms[g] + 2 * (size_t)a, *q = geoms[g] + 2 * (size_t)b;
        len += hypot(p[0] - q[0], p[1] - q[1]);
    }
    return len;
}

/* The shortest link from hole h to a free vertex of loop l, into *best. */
static void improve(const double *const *geoms, size_t k, const size_t *start, size_t h, size_t l,
                    const unsigned char *used, link *best)
{
    for (size_t p = start[h]; p < start[h + 1]; p++)
        for (size_t q = start[l]; q < start[l + 1]; q++) {
            if (used[q]) continue;
            double len = span(geoms, k, (int32_t)p, (int32_t)q);
            if (best->p < 0 || len < best->len) *best = (link){len, (int32_t)p, (int32_t)q};
        }
}

/* The tree of bridges (see the top): bridge j from bp[j] on a hole to
 * bq[j], in an order where each joins a hole to the loops before it. */
static int choose_tree(const double *const *geoms, size_t k, const size_t *start, size_t num_loops, int32_t *bp,
                       int32_t *bq)
{
    size_t n = start[num_loops];
    unsigned char *used = calloc(n, 1), *joined = calloc(num_loops, 1);
    link *best = malloc(num_loops * sizeof *best);
    if (!used || !joined || !best) {
        free(used), free(joined), free(best);
        return CM_NO_MEMORY;
    }
    joined[0] = 1;
    for (size_t h = 1; h < num_loops; h++) best[h] = (link){0, -1, -1}, improve(geoms, k, start, h, 0, used, &best[h]);
    for (size_t j = 0; j + 1 < num_loops; j++) {
        size_t pick = 0;
        for (size_t h = 1; h < num_loops; h++)
            if (!joined[h] && (pick == 0 || best[h].len < best[pick].len)) pick = h;
        bp[j] = best[pick].p, bq[j] = best[pick].q;
        used[bp[j]] = used[bq[j]] = 1, joined[pick] = 1;
        for (size_t h = 1; h < num_loops; h++) {
            if (joined[h]) continue;
            if (best[h].q == bq[j]) { /* its nearest is taken: all joined loops again */
                best[h] = (link){0, -1, -1};
                for (size_t l = 0; l < num_loops; l++)
                    if (joined[l]) improve(geoms, k, start, h, l, used, &best[h]);
            } else {
                improve(geoms, k, start, h, pick, used, &best[h]);
            }
        }
    }
    free(used), free(joined), free(best);
    return 0;
}

typedef struct { int64_t key; long slot; } directed;

static int by_key(const void *a, const void *b)
{
    const directed *x = a, *y = b;
    return (x->key > y->key) - (x->key < y->key);
}

/* Geometry c's triangles with their corners read as positions of the
 * cycle D (local[i]: the vertex of position i in c): the fan of triangles
 * at position i runs counter-clockwise from the edge to the next position
 * to the edge to the previous one. 0, CM_NO_MEMORY, or 1 when a fan does
 * not close as it must. */
static int cycle_triangles(const cut *c, const int32_t *local, size_t np, int32_t *out)
{
    directed *e = malloc(3 * c->nt * sizeof *e);
    if (!e) return CM_NO_MEMORY;
    int64_t nv = (int64_t)c->nv;
    for (size_t s = 0; s < 3 * c->nt; s++) {
        e[s] = (directed){(int64_t)c->tri[s] * nv + c->tri[s - s % 3 + (s + 1) % 3], (long)s};
        out[s] = -1;
    }
    qsort(e, 3 * c->nt, sizeof *e, by_key);
    int status = 0;
    for (size_t i = 0; i < np && status == 0; i++) {
        int32_t v = local[i], w = local[(i + 1) % np], u = local[(i + np - 1) % np];
        directed key = {(int64_t)v * nv + w, 0}, *hit = bsearch(&key, e, 3 * c->nt, sizeof *e, by_key);
        if (!hit) {
            status = 1;
            break;
        }
        long t = hit->slot / 3;
        int cv = (int)(hit->slot % 3);
        for (size_t steps = 0;; steps++) {
            if (out[3 * t + cv] >= 0 || steps > c->nt) {
                status = 1;
                break;
            }
            out[3 * t + cv] = (int32_t)i;
            if (c->tri[3 * t + (cv + 2) % 3] == u) break;
            long sx = 3 * t + (cv + 1) % 3;
            if (c->wall[sx] || c->nbr[sx] < 0) {
                status = 1;
                break;
            }
            t = c->nbr[sx], cv = corner_of(c, t, v);
            if (cv < 0) {
                status = 1;
                break;
            }
        }
    }
    for (size_t s = 0; s < 3 * c->nt && status == 0; s++)
        if (out[s] < 0) status = 1;
    free(e);
    return status;
}

cm_status cm_holes_overlay(const double *const *geoms, size_t k, const size_t *loop_start, size_t num_loops,
                           cm_mesh *out, size_t *bridges, cm_error *err)
{
    size_t n = loop_start[num_loops], nb = num_loops - 1, np = 0, total = 0, g = 0;
    memset(out, 0, sizeof *out);
    out->k = k;
    *bridges = 0;
    int32_t *bp = malloc((nb + 1) * sizeof *bp), *bq = malloc((nb + 1) * sizeof *bq);
    int32_t *bridge_at = malloc(n * sizeof *bridge_at), *cycle = NULL, *local = NULL;
    size_t *offset = calloc(nb + 1, sizeof *offset);
    cut *cuts = calloc(k, sizeof *cuts);
    int32_t **tris = calloc(k, sizeof *tris);
    double **cxy = calloc(k, sizeof *cxy);
    cm_mesh om = {0};
    cm_status s = CM_ERR_NO_MEMORY;
    if (!bp || !bq || !bridge_at || !offset || !cuts || !tris || !cxy ||
        choose_tree(geoms, k, loop_start, num_loops, bp, bq) != 0)
        goto done;
    s = CM_OK;
    const char *what = "";
    for (g = 0; g < k && s == CM_OK; g++) {
        what = "its loops could not be triangulated";
        s = cut_init(&cuts[g], geoms[g], loop_start, num_loops, nb);
        what = "a bridge could not be cut into its triangulation";
        for (size_t j = 0; j < nb && s == CM_OK; j++) s = route(&cuts[g], j, bp[j], bq[j]);
        if (s == CM_OK) { /* before the padding: its bends are collinear, flips there would make slivers */
            int d = cut_delaunay(&cuts[g], nb);
            s = d == 0 ? CM_OK : d == CM_NO_MEMORY ? CM_ERR_NO_MEMORY : CM_ERR_INTERNAL;
            what = "a bridge segment was lost";
        }
    }
    for (size_t j = 0; j < nb && s == CM_OK; j++) {
        size_t want = 0;
        for (size_t h = 0; h < k; h++) want = cuts[h].path[j].n - 2 > want ? cuts[h].path[j].n - 2 : want;
        for (g = 0; g < k && s == CM_OK; g++) s = pad(&cuts[g], j, want);
        offset[j] = total, total += want;
    }
    if (s != CM_OK) { /* g is one past the polygon that failed */
        if (s == CM_ERR_PRECISION)
            cm_fail(err, s, "holes: polygon %zu: no bridge whose bends round to valid triangles (its vertices are "
                    "too close together for their magnitude)", g - 1);
        else if (s == CM_ERR_INTERNAL)
            cm_fail(err, s, "holes: polygon %zu: %s", g - 1, what);
        else cm_fail_status(err, s);
        goto done;
    }
    /* D: the boundary walk, a bridge taken where the walk reaches its end */
    np = n + 2 * nb + 2 * total;
    s = CM_ERR_NO_MEMORY;
    if (!(cycle = malloc(np * sizeof *cycle)) || !(local = malloc(np * sizeof *local))) goto done;
    for (size_t v = 0; v < n; v++) bridge_at[v] = -1;
    for (size_t j = 0; j < nb; j++) bridge_at[bp[j]] = bridge_at[bq[j]] = (int32_t)j;
    size_t used = 0;
    int32_t v = 0;
    do {
        if (used >= np) break;
        cycle[used++] = v;
        int32_t w = (int32_t)cm_loops_next(loop_start, n, (size_t)v);
        int32_t j = bridge_at[w];
        if (j < 0) {
            v = w;
            continue;
        }
        size_t bends = cuts[0].path[j].n - 2;
        if (used + 1 + bends > np) break;
        cycle[used++] = w;
        for (size_t i = 0; i < bends; i++)
            cycle[used++] = (int32_t)(n + offset[j] + (w == bp[j] ? i : bends - 1 - i));
        v = w == bp[j] ? bq[j] : bp[j];
    } while (v != 0);
    if (used != np || v != 0) {
        s = cm_fail(err, CM_ERR_INTERNAL, "holes: the bridges' cut has %zu boundary vertices, not %zu", used, np);
        goto done;
    }
    for (g = 0; g < k; g++) {
        const cut *c = &cuts[g];
        for (size_t i = 0; i < np; i++) {
            size_t id = (size_t)cycle[i];
            if (id < n) {
                local[i] = (int32_t)id;
                continue;
            }
            size_t j = 0;
            while (j + 1 < nb && offset[j + 1] <= id - n) j++;
            local[i] = c->path[j].a[id - n - offset[j] + 1];
        }
        if (!(tris[g] = malloc(3 * c->nt * sizeof *tris[g])) || !(cxy[g] = malloc(2 * np * sizeof *cxy[g])))
            goto done;
        for (size_t i = 0; i < np; i++) memcpy(cxy[g] + 2 * i, at(c, local[i]), 2 * sizeof(double));
        int cs = c->nt == np - 2 ? cycle_triangles(c, local, np, tris[g]) : 1;
        if (cs == CM_NO_MEMORY) goto done;
        if (cs != 0) {
            s = cm_fail(err, CM_ERR_INTERNAL, "holes: polygon %zu's triangulation does not fit the bridges' cut", g);
            goto done;
        }
    }
    size_t centroids = 0;
    s = cm_overlay((const double *const *)cxy, (const int32_t *const *)tris, k, np, &om, &centroids, err);
    if (s != CM_OK) goto done;
    /* back to vertices: the loops, the bends, then the overlay's own */
    s = CM_ERR_NO_MEMORY;
    size_t nv = n + total + (om.nv - np);
    if (!(out->xy = calloc(k, sizeof *out->xy)) || !(out->tri = malloc(3 * om.nt * sizeof *out->tri))) goto done;
    for (g = 0; g < k; g++) {
        if (!(out->xy[g] = malloc(2 * nv * sizeof *out->xy[g]))) goto done;
        memcpy(out->xy[g], geoms[g], 2 * n * sizeof(double));
        for (size_t j = 0; j < nb; j++)
            for (size_t i = 0; i + 2 < cuts[g].path[j].n; i++)
                memcpy(out->xy[g] + 2 * (n + offset[j] + i), at(&cuts[g], cuts[g].path[j].a[i + 1]), 2 * sizeof(double));
        memcpy(out->xy[g] + 2 * (n + total), om.xy[g] + 2 * np, 2 * (om.nv - np) * sizeof(double));
    }
    for (size_t i = 0; i < 3 * om.nt; i++)
        out->tri[i] = (size_t)om.tri[i] < np ? cycle[om.tri[i]] : (int32_t)(n + total + (size_t)om.tri[i] - np);
    out->nv = nv, out->nt = om.nt;
    *bridges = nb;
    s = CM_OK;
done:
    if (s == CM_ERR_NO_MEMORY) cm_fail_status(err, s);
    if (s != CM_OK) cm_mesh_clear(out);
    cm_mesh_clear(&om);
    for (size_t h = 0; cuts && h < k; h++) cut_free(&cuts[h], nb);
    for (size_t h = 0; h < k; h++) {
        if (tris) free(tris[h]);
        if (cxy) free(cxy[h]);
    }
    free(bp), free(bq), free(bridge_at), free(offset), free(cuts), free(tris), free(cxy), free(cycle), free(local);
    return s;
}
