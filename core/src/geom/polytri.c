/* Triangulation of one simple polygon: ear clipping, then Lawson flips to
 * the constrained Delaunay triangulation (which maximises the minimum angle
 * over all triangulations of the polygon). Every decision is exact. */
#include <limits.h>
#include <math.h>
#include <stdlib.h>

#include "base/error.h"
#include "geom/pointgrid.h"
#include "geom/polytri.h"
#include "base/progress.h"
#include "geom/predicates.h"
#include "base/cycle.h"

#define P(v) (xy + 2 * (size_t)(v))

/* The ring's vertices that are not strictly convex, in a grid: only they
 * can block an ear (if the triangle contains a vertex it contains a
 * reflex one), and only those in the ear's bounding box. */
typedef struct {
    const double *xy;
    const int32_t *idx;
    long *prev, *next;
    signed char *convex, *ear;
    long *cells;    /* per ear: the grid cells under its bounding box */
    long remaining; /* vertices left on the ring */
    int tame;       /* every coordinate tame (cm_coords_tame) */
    cm_pointgrid grid;
} ring;

static double min3(double a, double b, double c)
{
    double m = a < b ? a : b;
    return m < c ? m : c;
}

static double max3(double a, double b, double c)
{
    double m = a > b ? a : b;
    return m > c ? m : c;
}

/* The bounding box of triangle abc: box = {x0, y0, x1, y1}. */
static void ear_box(const ring *r, long a, long b, long c, double box[4])
{
    const double *xy = r->xy, *pa = P(r->idx[a]), *pb = P(r->idx[b]), *pc = P(r->idx[c]);
    box[0] = min3(pa[0], pb[0], pc[0]), box[1] = min3(pa[1], pb[1], pc[1]);
    box[2] = max3(pa[0], pb[0], pc[0]), box[3] = max3(pa[1], pb[1], pc[1]);
}

/* Is p inside or on the closed triangle abc (counter-clockwise, box its
 * bounding box)? Outside the box it is outside the triangle: compared
 * first, exactly. */
static inline int in_ear(const double *pa, const double *pb, const double *pc, const double box[4], const double *p,
                  int tame)
{
    if (p[0] < box[0] || p[0] > box[2] || p[1] < box[1] || p[1] > box[3]) return 0;
    if (tame)
        return cm_orient2d_tame(pa, pb, p) >= 0 && cm_orient2d_tame(pb, pc, p) >= 0 &&
               cm_orient2d_tame(pc, pa, p) >= 0;
    return cm_orient2d(pa, pb, p) >= 0 && cm_orient2d(pb, pc, p) >= 0 && cm_orient2d(pc, pa, p) >= 0;
}

/* Is any vertex of the ring (other than a, b, c) inside or on the closed
 * triangle abc (strictly convex)? Sets r->cells[b]. */
static int ear_blocked(ring *r, long a, long b, long c)
{
    const double *xy = r->xy, *pa = P(r->idx[a]), *pb = P(r->idx[b]), *pc = P(r->idx[c]);
    long cells[4];
    double box[4];
    ear_box(r, a, b, c, box);
    long ncells = r->cells[b] = cm_pointgrid_range(&r->grid, box[0], box[1], box[2], box[3], cells);
    /* a box of many more cells than reflex vertices: walk the ring instead
     * when it is the shorter walk (not for a near-convex ring, whose long
     * ears would each walk it whole) */
    if (ncells > 4 * r->grid.count + 16 && ncells > r->remaining) {
        for (long v = r->next[c]; v != a; v = r->next[v]) {
            if (r->convex[v] > 0) continue;
            if (in_ear(pa, pb, pc, box, P(r->idx[v]), r->tame)) return 1;
        }
        return 0;
    }
    for (long cy = cells[2]; cy <= cells[3]; cy++)
        for (long cx = cells[0]; cx <= cells[1]; cx++)
            for (long v = r->grid.head[cy * r->grid.nx + cx]; v >= 0; v = r->grid.next[v]) {
                if (v == a || v == b || v == c) continue;
                if (in_ear(pa, pb, pc, box, P(r->idx[v]), r->tame)) return 1;
            }
    return 0;
}

/* The turn at v between its ring neighbours (tame points: the filter
 * need not check its differences). */
static int turn(const ring *r, long u, long v, long w)
{
    const double *xy = r->xy;
    return cm_orient2d_either(r->tame, P(r->idx[u]), P(r->idx[v]), P(r->idx[w]));
}

static void set_turn(ring *r, long v)
{
    const double *xy = r->xy;
    r->convex[v] = (signed char)turn(r, r->prev[v], v, r->next[v]);
    if (r->convex[v] > 0) cm_pointgrid_remove(&r->grid, v);
    else if (r->grid.cell[v] < 0) cm_pointgrid_insert(&r->grid, v, P(r->idx[v])[0], P(r->idx[v])[1]);
}

static void update_vertex(ring *r, long v)
{
    set_turn(r, v);
    r->ear[v] = r->convex[v] > 0 && !ear_blocked(r, r->prev[v], v, r->next[v]);
}

/* Rings above this many vertices clip small ears first when the result
 * is flipped to the constrained Delaunay triangulation (always when only
 * walked). */
#define SMALL_EARS_FROM 2048

/* small_first: clip the ears under at most `limit` grid cells first,
 * raising the limit after a round without one. Clipping next to the last
 * ear instead fans long chains from one vertex (a polygon's arc closed
 * by a chord: O(m) grid points under each ear); small ears first halve
 * such chains round by round. */
static int clip_ears(const double *xy, const int32_t *idx, long m, int32_t *tri, cm_progress *progress,
                     int small_first)
{
    ring r = {xy, idx, malloc((size_t)m * sizeof(long)), malloc((size_t)m * sizeof(long)), malloc((size_t)m),
              malloc((size_t)m), malloc((size_t)m * sizeof(long)), .grid = {.head = NULL}};
    int status = -1;
    double lo[2] = {P(idx[0])[0], P(idx[0])[1]}, hi[2] = {lo[0], lo[1]};
    long reflex = 0;
    if (!r.prev || !r.next || !r.convex || !r.ear || !r.cells) goto done;
    for (long i = 0; i < m; i++) {
        r.prev[i] = cm_cycle_prev(i, m);
        r.next[i] = cm_cycle_next(i, m);
        for (int c = 0; c < 2; c++) lo[c] = fmin(lo[c], P(idx[i])[c]), hi[c] = fmax(hi[c], P(idx[i])[c]);
    }
    r.tame = 1;
    for (long i = 0; i < m && r.tame; i++) r.tame = cm_coords_tame(P(idx[i]), 2);
    for (long i = 0; i < m; i++) {
        r.convex[i] = (signed char)turn(&r, r.prev[i], i, r.next[i]);
        reflex += r.convex[i] <= 0;
    }
    r.remaining = m;
    if (cm_pointgrid_init(&r.grid, m, lo, hi, reflex) != 0) goto done;
    for (long i = 0; i < m; i++)
        if (r.convex[i] <= 0) cm_pointgrid_insert(&r.grid, i, P(idx[i])[0], P(idx[i])[1]);
    for (long i = 0; i < m; i++) {
        r.ear[i] = r.convex[i] > 0 && !ear_blocked(&r, r.prev[i], i, r.next[i]);
        if (cm_progress_check(progress)) {
            status = CM_CANCELLED;
            goto done;
        }
    }

    long remaining = m, v = 0, since_last_clip = 0, t = 0, limit = small_first ? 4 : LONG_MAX;
    long all_cells = r.grid.nx * r.grid.ny;
    status = 1;
    while (remaining > 3) {
        if (r.ear[v] && r.cells[v] <= limit) { /* an ear's cells: set with its flag */
            long a = r.prev[v], c = r.next[v];
            tri[3 * t] = idx[a], tri[3 * t + 1] = idx[v], tri[3 * t + 2] = idx[c];
            t++;
            r.next[a] = c, r.prev[c] = a;
            r.remaining = --remaining;
            update_vertex(&r, a);
            update_vertex(&r, c);
            since_last_clip = 0;
            v = c;
            if (cm_progress_check(progress)) {
                status = CM_CANCELLED;
                goto done;
            }
        } else {
            if (++since_last_clip > remaining) {
                if (limit == LONG_MAX) goto done; /* no ear: not simple */
                limit = limit >= all_cells ? LONG_MAX : 2 * limit;
                since_last_clip = 0;
            }
            v = r.next[v];
        }
    }
    if (turn(&r, r.prev[v], v, r.next[v]) <= 0) goto done;
    tri[3 * t] = idx[r.prev[v]], tri[3 * t + 1] = idx[v], tri[3 * t + 2] = idx[r.next[v]];
    status = 0;
done:
    free(r.prev), free(r.next), free(r.convex), free(r.ear), free(r.cells);
    cm_pointgrid_clear(&r.grid);
    return status;
}

/* Triangle adjacency: nbr[3t + i] is the triangle across the edge opposite
 * corner i (from corner i+1 to corner i+2), -1 on the boundary. */
/* ---- triangle adjacency ------------------------------------------------- */

typedef struct { int32_t lo, hi; long slot; } edge_slot;

static const int next3[3] = {1, 2, 0}, prev3[3] = {2, 0, 1};

static int compare_edge_slots(const void *pa, const void *pb)
{
    const edge_slot *x = pa, *y = pb;
    if (x->lo != y->lo) return x->lo < y->lo ? -1 : 1;
    return (x->hi > y->hi) - (x->hi < y->hi);
}

/* Pairs the slots by edge in buckets of their lower ends, when the vertex
 * values are small (always, for a polygon's local indices): each bucket's
 * slots in order, mark[hi] holding the slot still waiting for its twin.
 * The pairs are those of the sorted order (equal edges by slot, each pair
 * taken from the first unpaired). 0 done, 1 values too large for it, -1
 * out of memory. */
static int pair_in_buckets(const edge_slot *e, long n, int32_t *nbr)
{
    int32_t lo = 0, hi = 0;
    for (long s = 0; s < n; s++) lo = e[s].lo < lo ? e[s].lo : lo, hi = e[s].hi > hi ? e[s].hi : hi;
    if (lo < 0 || hi > 4 * n + 64) return 1;
    long *start = calloc((size_t)hi + 2, sizeof *start);
    int32_t *order = malloc((size_t)(n + 1) * sizeof *order), *mark = malloc(((size_t)hi + 1) * sizeof *mark);
    int status = start && order && mark ? 0 : -1;
    if (status == 0) {
        for (long s = 0; s < n; s++) start[e[s].lo + 1]++;
        for (long v = 0; v <= hi; v++) start[v + 1] += start[v], mark[v] = -1;
        for (long s = 0; s < n; s++) order[start[e[s].lo]++] = (int32_t)s; /* start[v]: now bucket v's end */
        for (long v = 0, s = 0; v <= hi; v++) {
            long from = s;
            for (; s < start[v]; s++) {
                int32_t x = order[s], *w = &mark[e[x].hi];
                if (*w < 0) {
                    *w = x;
                    continue;
                }
                nbr[*w] = x / 3, nbr[x] = *w / 3;
                *w = -1;
            }
            for (long t = from; t < s; t++) mark[e[order[t]].hi] = -1;
        }
    }
    free(start), free(order), free(mark);
    return status;
}

int cm_tri_adjacency(const int32_t *tri, long nt, int32_t *nbr)
{
    edge_slot *e = malloc((size_t)(3 * nt + 1) * sizeof *e);
    if (!e) return -1;
    for (long t = 0; t < nt; t++)
        for (int i = 0; i < 3; i++) {
            int32_t a = tri[3 * t + next3[i]], b = tri[3 * t + prev3[i]];
            e[3 * t + i] = (edge_slot){a < b ? a : b, a < b ? b : a, 3 * t + i};
            nbr[3 * t + i] = -1;
        }
    int paired = pair_in_buckets(e, 3 * nt, nbr);
    if (paired > 0) {
        qsort(e, (size_t)(3 * nt), sizeof *e, compare_edge_slots);
        for (long s = 0; s + 1 < 3 * nt; s++) {
            if (compare_edge_slots(&e[s], &e[s + 1]) != 0) continue;
            nbr[e[s].slot] = (int32_t)(e[s + 1].slot / 3);
            nbr[e[s + 1].slot] = (int32_t)(e[s].slot / 3);
            s++;
        }
    }
    free(e);
    return paired < 0 ? -1 : 0;
}

static long corner_facing(const int32_t *nbr, long t, long other)
{
    for (int i = 0; i < 3; i++)
        if (nbr[3 * t + i] == other) return i;
    return -1;
}

/* Flips the edge opposite corner i of triangle t if it is not locally
 * Delaunay. Returns 1 if flipped. Triangles (a,b,c) with edge b-c shared by
 * u = (c,b,d): become (a,b,d) and (a,d,c). kept[s]: the vertex across the
 * edge opposite slot s when that edge was last found to stay, -1 unknown;
 * the decision is the same from either side (the in-circle sign is
 * symmetric, the quad the same), and a triangle's slots are cleared when
 * it changes, so a kept edge is not tested again until one side changes. */
static int flip_if_illegal(const double *xy, int32_t *tri, int32_t *nbr, int32_t *kept, long t, long i)
{
    long u = nbr[3 * t + i];
    if (u < 0) return 0;
    long j = corner_facing(nbr, u, t);
    int32_t a = tri[3 * t + i], b = tri[3 * t + (i + 1) % 3], c = tri[3 * t + (i + 2) % 3];
    int32_t d = tri[3 * u + j];
    if (kept[3 * t + i] == d) return 0;
    if (cm_incircle(P(a), P(b), P(c), P(d)) <= 0 || cm_orient2d(P(a), P(b), P(d)) <= 0 ||
        cm_orient2d(P(a), P(d), P(c)) <= 0) {
        kept[3 * t + i] = d, kept[3 * u + j] = a;
        return 0;
    }
    for (int k = 0; k < 3; k++) kept[3 * t + k] = kept[3 * u + k] = -1;
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

static int make_delaunay(const double *xy, int32_t *tri, long nt, int (*fixed)(const void *, int32_t, int32_t),
                         const void *user, cm_progress *progress)
{
    int32_t *nbr = malloc((size_t)(3 * nt) * sizeof *nbr);
    long *stack = malloc((size_t)(3 * nt) * sizeof *stack);
    int32_t *kept = malloc((size_t)(3 * nt) * sizeof *kept);
    char *queued = calloc((size_t)nt, 1);
    int status = -1;
    if (!nbr || !stack || !kept || !queued || cm_tri_adjacency(tri, nt, nbr) != 0) goto done;
    for (long s = 0; s < 3 * nt; s++) kept[s] = -1;
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
            if (u >= 0 && fixed && fixed(user, tri[3 * t + (i + 1) % 3], tri[3 * t + (i + 2) % 3])) continue;
            if (u >= 0 && flip_if_illegal(xy, tri, nbr, kept, t, i)) {
                if (!queued[u]) stack[top++] = u, queued[u] = 1;
                if (!queued[t]) stack[top++] = t, queued[t] = 1;
                break;
            }
        }
    }
    status = 0;
done:
    free(nbr), free(stack), free(kept), free(queued);
    return status;
}

int cm_polygon_ear_clip(const double *xy, const int32_t *idx, long m, int32_t *tri_out, cm_progress *progress)
{
    return clip_ears(xy, idx, m, tri_out, progress, 1);
}

int cm_polygon_triangulate(const double *xy, const int32_t *idx, long m, int32_t *tri_out,
                           cm_progress *progress)
{
    /* the flips make the result the constrained Delaunay triangulation,
     * but where it is not unique (cocircular vertices) the one reached
     * depends on the ears: rings up to SMALL_EARS_FROM keep their order */
    int s = clip_ears(xy, idx, m, tri_out, progress, m > SMALL_EARS_FROM);
    if (s != 0) return s;
    return make_delaunay(xy, tri_out, m - 2, NULL, NULL, progress);
}

int cm_tri_make_delaunay(const double *xy, int32_t *tri, long nt, int (*fixed)(const void *, int32_t, int32_t),
                         const void *user)
{
    return make_delaunay(xy, tri, nt, fixed, user, NULL);
}
