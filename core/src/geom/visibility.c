/* Visibility by cone propagation through a triangulation; see visibility.h. */
#include "geom/visibility.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/cycle.h"
#include "geom/pointgrid.h"
#include "geom/polytri.h"
#include "geom/predicates.h"

/* ---- the visibility table (double coordinates) --------------------------- */

/* A pending crossing: enter the triangle of slot tz through its edge from r
 * (right, as seen from the source) to l, with the cone strictly between
 * rays to b and a (b clockwise of a). tz = 3t + corner of z, the vertex of
 * t opposite the edge; t runs counter-clockwise r, z, l (the slot's view
 * holds them, and the slots beyond its other two edges). */
typedef struct { int32_t tz, b, a; } crossing;

/* What a crossing into slot 3t + i (z = corner i of t) reads: z, r and l,
 * and the slots across r -> z and z -> l (-1 on the boundary). */
typedef struct { int32_t z, r, l, across_rz, across_zl; } slot_view;

typedef struct {
    const double *xy;
    long m;
    const int32_t *tri, *opp, *first; /* opp[3t + i]: the slot 3u + j of the
                                         corner of the triangle u across the
                                         edge opposite corner i of t, -1 on
                                         the boundary; first[v]: 3t + corner
                                         of v, the triangle holding edge
                                         v -> v+1 */
    const slot_view *view; /* per slot, read by the crossings */
    crossing *stack;
    int tame; /* every coordinate tame (cm_coords_tame) */
    const int32_t *want; /* NULL, or want[j] = wanted vertices among 0..j-1 */
    long lo;             /* without want: the vertices lo..m-1 wanted */
} vis_ctx;

#define XY(c, v) ((c)->xy + 2 * (size_t)(v))

static int adjacent(long m, long s, long v)
{
    return v == cm_cycle_next(s, m) || s == cm_cycle_next(v, m);
}

/* Is a wanted vertex strictly between r and l on the chain r, r+1, ..., l
 * (cyclic)? That chain is the pocket beyond the edge from r to l: the only
 * vertices a cone crossing that edge can reach. r and l end a diagonal
 * (the walk crosses no polygon edge): the chain holds a vertex. */
static inline int pocket_wanted(const vis_ctx *c, int32_t r, int32_t l)
{
    if (!c->want) { /* a wanted vertex: one of lo..m-1; r < l: l >= r + 2 */
        if (r < l) return l > c->lo;
        return (r < c->m - 1 && c->lo < c->m) || l > c->lo; /* r + 1..m - 1, then 0..l - 1 */
    }
    if (r < l) return c->want[l] > c->want[r + 1];
    return c->want[c->m] > c->want[r + 1] || c->want[l] > 0;
}

static const int next3[3] = {1, 2, 0}, prev3[3] = {2, 0, 1};

static void propagate(const vis_ctx *ctx, long s, unsigned char *row, long top)
{
    /* a copy: the marks written to row (bytes) could otherwise be the
     * context's fields for the compiler, read again after each */
    const vis_ctx cv = *ctx, *c = &cv;
    while (top > 0) {
        crossing x = c->stack[--top];
        const slot_view *sv = &c->view[x.tz];
        int32_t z = sv->z, r = sv->r, l = sv->l;
        /* z on or right of ray b: the cone goes on across z -> l alone,
         * whatever ray a says (not asked) */
        int oa = 0, ob;
        if (c->tame) {
            ob = cm_orient2d_tame(XY(c, s), XY(c, x.b), XY(c, z));
            if (ob > 0) oa = cm_orient2d_tame(XY(c, s), XY(c, x.a), XY(c, z));
        } else {
            ob = cm_orient2d(XY(c, s), XY(c, x.b), XY(c, z));
            if (ob > 0) oa = cm_orient2d(XY(c, s), XY(c, x.a), XY(c, z));
        }
        int32_t across_rz = sv->across_rz, across_zl = sv->across_zl;
        if (ob > 0 && oa < 0) {
            row[z] = 1;
            if (across_rz >= 0 && pocket_wanted(c, r, z)) c->stack[top++] = (crossing){across_rz, x.b, z};
            if (across_zl >= 0 && pocket_wanted(c, z, l)) c->stack[top++] = (crossing){across_zl, z, x.a};
        } else if (ob <= 0) {
            if (across_zl >= 0 && pocket_wanted(c, z, l)) c->stack[top++] = (crossing){across_zl, x.b, x.a};
        } else if (across_rz >= 0 && pocket_wanted(c, r, z)) {
            c->stack[top++] = (crossing){across_rz, x.b, x.a};
        }
    }
}

/* Walks the fan of s counter-clockwise from the triangle holding s -> s+1. */
static void visible_from(const vis_ctx *ctx, long s, unsigned char *row)
{
    const vis_ctx cv = *ctx, *c = &cv; /* as in propagate */
    long top = 0;
    long slot = c->first[s];
    while (slot >= 0) {
        long base = slot - slot % 3, cs = slot - base;
        int32_t x = c->tri[base + next3[cs]], y = c->tri[base + prev3[cs]];
        if (!adjacent(c->m, s, x)) row[x] = 1;
        if (!adjacent(c->m, s, y)) row[y] = 1;
        int32_t across = c->opp[slot];
        if (across >= 0 && pocket_wanted(c, x, y)) c->stack[top++] = (crossing){across, x, y};
        /* across y -> s the next triangle runs s, y, w: s follows w */
        int32_t next = c->opp[base + next3[cs]];
        slot = next >= 0 ? next - next % 3 + next3[next % 3] : -1;
    }
    propagate(c, s, row, top);
}

struct cm_visrows {
    vis_ctx c;
    int32_t *opp, *first;
    slot_view *view;
};

void cm_visrows_free(cm_visrows *v)
{
    if (!v) return;
    free(v->opp), free(v->first), free(v->view), free(v->c.stack);
    free(v);
}

cm_visrows *cm_visrows_create(const double *xy, long m, const int32_t *tri)
{
    long nt = m - 2;
    cm_visrows *v = calloc(1, sizeof *v);
    if (!v) return NULL;
    v->opp = malloc((size_t)(3 * nt) * sizeof *v->opp);
    v->first = malloc((size_t)m * sizeof *v->first);
    v->view = malloc((size_t)(3 * nt) * sizeof *v->view);
    crossing *stack = malloc((size_t)(nt + 1) * sizeof *stack);
    int32_t *nbr = malloc((size_t)(3 * nt) * sizeof *nbr);
    v->c = (vis_ctx){xy, m, tri, v->opp, v->first, v->view, stack, cm_coords_tame(xy, 2 * m), NULL, 0};
    if (!v->opp || !v->first || !v->view || !stack || !nbr || cm_tri_adjacency(tri, nt, nbr) != 0) {
        free(nbr);
        cm_visrows_free(v);
        return NULL;
    }
    /* the slot of the neighbour's corner that faces back across the edge */
    for (long i = 0; i < 3 * nt; i++) {
        int32_t u = nbr[i];
        int j = 0;
        if (u >= 0)
            while (nbr[3 * u + j] != i / 3) j++;
        v->opp[i] = u >= 0 ? 3 * u + j : -1;
    }
    free(nbr);
    /* the edge r -> z lies opposite l, z -> l opposite r */
    for (long t = 0; t < nt; t++)
        for (int i = 0; i < 3; i++)
            v->view[3 * t + i] = (slot_view){tri[3 * t + i], tri[3 * t + prev3[i]], tri[3 * t + next3[i]],
                                             v->opp[3 * t + next3[i]], v->opp[3 * t + prev3[i]]};
    for (long i = 0; i < m; i++) v->first[i] = -1;
    for (long t = 0; t < nt; t++)
        for (int i = 0; i < 3; i++)
            if (tri[3 * t + (i + 1) % 3] == (tri[3 * t + i] + 1) % m) v->first[tri[3 * t + i]] = (int32_t)(3 * t + i);
    return v;
}

void cm_visrows_row(cm_visrows *v, long s, unsigned char *row)
{
    memset(row, 0, (size_t)v->c.m);
    visible_from(&v->c, s, row);
}

void cm_visrows_row_wanted(cm_visrows *v, long s, const int32_t *want, unsigned char *row)
{
    memset(row, 0, (size_t)v->c.m);
    v->c.want = want;
    visible_from(&v->c, s, row);
    v->c.want = NULL;
}

void cm_visrows_row_from(cm_visrows *v, long s, long lo, unsigned char *row)
{
    memset(row, 0, (size_t)v->c.m);
    v->c.lo = lo;
    visible_from(&v->c, s, row);
    v->c.lo = 0;
}

int cm_visibility_table(const double *xy, long m, const int32_t *tri, unsigned char *vis)
{
    cm_visrows *v = cm_visrows_create(xy, m, tri);
    if (!v) return -1;
    for (long s = 0; s < m; s++) cm_visrows_row(v, s, vis + (size_t)s * (size_t)m);
    cm_visrows_free(v);
    return 0;
}

/* ---- the exact segment test ---------------------------------------------- */

/* The sign of the turn at vertex i (the orientation of its corner). */
static int vertex_turn(const double *xy, long m, long i, int tame)
{
    return cm_orient2d_either(tame, xy + 2 * cm_cycle_prev(i, m), xy + 2 * i, xy + 2 * cm_cycle_next(i, m));
}

int cm_vertex_turns(const double *xy, long m, signed char *turn)
{
    int tame = cm_coords_tame(xy, 2 * m);
    for (long i = 0; i < m; i++) turn[i] = (signed char)vertex_turn(xy, m, i, tame);
    return tame;
}

/* Does the direction from vertex i, whose turn is `turn`, toward point q
 * leave into the interior? */
static int leaves_inward(const double *xy, long m, long i, int turn, const double q[2], int tame)
{
    const double *p = xy + 2 * cm_cycle_prev(i, m), *v = xy + 2 * i, *n = xy + 2 * cm_cycle_next(i, m);
    int left_of_in = cm_orient2d_either(tame, p, v, q) > 0;
    /* the second side only where it can change the answer */
    if (turn > 0) return left_of_in && cm_orient2d_either(tame, v, n, q) > 0;
    if (turn < 0) return left_of_in || cm_orient2d_either(tame, v, n, q) > 0;
    return left_of_in;
}

/* w collinear with a, b: is it on the same side of a as b? */
static int same_direction(const double a[2], const double b[2], const double w[2])
{
    int axis = a[0] != b[0] ? 0 : 1;
    return (w[axis] > a[axis]) == (b[axis] > a[axis]) && w[axis] != a[axis];
}

/* The polygon edge from a (a vertex, an end of segment ab) to w may meet
 * ab only at a. */
static int edge_touches_only_at_end(const double a[2], const double b[2], const double w[2], int tame)
{
    return cm_orient2d_either(tame, a, b, w) != 0 || !same_direction(a, b, w);
}

/* The constant-time conditions of cm_segment_inside: distinct ends, not a
 * polygon edge, leaving inward at the ends that are vertices (their turns
 * read from turn when given). convex: bit 0 (1) set when a (b) is a
 * strictly convex vertex; the segment leaving inward there has both
 * neighbours strictly to one side, so neither edge at that end can
 * overlap it. */
static int ends_inward(const double *xy, long m, const signed char *turn, long ia, const double a[2], long ib,
                       const double b[2], int *convex, int tame)
{
    *convex = 0;
    if (a[0] == b[0] && a[1] == b[1]) return 0;
    if (ia >= 0 && ib >= 0 && adjacent(m, ia, ib)) return 0;
    if (ia >= 0) {
        int t = turn ? turn[ia] : vertex_turn(xy, m, ia, tame);
        if (!leaves_inward(xy, m, ia, t, b, tame)) return 0;
        *convex |= t > 0;
    }
    if (ib >= 0) {
        int t = turn ? turn[ib] : vertex_turn(xy, m, ib, tame);
        if (!leaves_inward(xy, m, ib, t, a, tame)) return 0;
        *convex |= (t > 0) << 1;
    }
    return 1;
}

/* Does the open segment ab miss the edges first .. first + count - 1
 * (cyclic; edge i runs from vertex i to i + 1), an edge at vertex ia or ib
 * touching it only there? convex as from ends_inward: those ends' edges
 * need no test. */
static int edges_clear(const double *xy, long m, long ia, const double a[2], long ib, const double b[2],
                       long first, long count, int convex, int tame)
{
    /* ab's box: edges entirely to one side of it cannot meet ab (exact
     * comparisons, the test cm_segments_intersect starts with, here
     * without the call; skipped for NaN coordinates) */
    const double lo[2] = {a[0] < b[0] ? a[0] : b[0], a[1] < b[1] ? a[1] : b[1]};
    const double hi[2] = {a[0] < b[0] ? b[0] : a[0], a[1] < b[1] ? b[1] : a[1]};
    int boxed = a[0] == a[0] && a[1] == a[1] && b[0] == b[0] && b[1] == b[1];
    for (long c = 0, i = first; c < count; c++, i = cm_cycle_next(i, m)) {
        long j = cm_cycle_next(i, m);
        const double *e0 = xy + 2 * i, *e1 = xy + 2 * j;
        if (ia == i || ia == j) {
            if (!(convex & 1) && !edge_touches_only_at_end(a, b, ia == i ? e1 : e0, tame)) return 0;
            continue;
        }
        if (ib == i || ib == j) {
            if (!(convex & 2) && !edge_touches_only_at_end(b, a, ib == i ? e1 : e0, tame)) return 0;
            continue;
        }
        if (boxed && ((e0[0] < lo[0] && e1[0] < lo[0]) || (e0[0] > hi[0] && e1[0] > hi[0]) ||
                      (e0[1] < lo[1] && e1[1] < lo[1]) || (e0[1] > hi[1] && e1[1] > hi[1])))
            continue;
        if ((tame ? cm_segments_intersect_tame(a, b, e0, e1) : cm_segments_intersect(a, b, e0, e1)) != 0) return 0;
    }
    return 1;
}

static int segment_inside(const double *xy, long m, long ia, const double a[2], long ib, const double b[2],
                          int tame)
{
    /* the constant-time conditions first: a segment leaving outward needs
     * no scan */
    int convex;
    if (!ends_inward(xy, m, NULL, ia, a, ib, b, &convex, tame) ||
        !edges_clear(xy, m, ia, a, ib, b, 0, m, convex, tame))
        return 0;
    if (ia < 0 && ib < 0) {
        /* No contact with the boundary: inside iff a is inside. */
        long crossings = 0;
        for (long i = 0; i < m; i++) {
            const double *e0 = xy + 2 * i, *e1 = xy + 2 * cm_cycle_next(i, m);
            int up = e0[1] <= a[1] && e1[1] > a[1], down = e1[1] <= a[1] && e0[1] > a[1];
            if (up && cm_orient2d_either(tame, e0, e1, a) > 0) crossings++;
            if (down && cm_orient2d_either(tame, e0, e1, a) < 0) crossings++;
        }
        return (int)(crossings & 1);
    }
    return 1;
}

int cm_segment_inside(const double *xy, long m, long ia, const double a[2], long ib, const double b[2])
{
    return segment_inside(xy, m, ia, a, ib, b, 0);
}

int cm_segment_inside_tame(const double *xy, long m, long ia, const double a[2], long ib, const double b[2])
{
    return segment_inside(xy, m, ia, a, ib, b, 1);
}

int cm_segment_inside_edges(const double *xy, long m, const signed char *turn, int tame, long ia, long ib,
                            long first, long count)
{
    const double *a = xy + 2 * ia, *b = xy + 2 * ib;
    int convex;
    return ends_inward(xy, m, turn, ia, a, ib, b, &convex, tame) &&
           edges_clear(xy, m, ia, a, ib, b, first, count, convex, tame);
}

/* ---- the kernel ----------------------------------------------------------- */

/* Clips the convex polygon in[0..n-1] to the closed left side of a -> b. */
static long clip_half_plane(const double *in, long n, const double *a, const double *b, double *out)
{
    long count = 0;
    if (n <= 0) return 0;
    /* each point's side once: the next edge's start is this one's end (the
     * same operands, the same double) */
    double s0 = (b[0] - a[0]) * (in[1] - a[1]) - (b[1] - a[1]) * (in[0] - a[0]), sq = s0;
    for (long i = 0; i < n; i++) {
        const double *p = in + 2 * i, *q = in + 2 * cm_cycle_next(i, n);
        double sp = sq;
        sq = i + 1 < n ? (b[0] - a[0]) * (q[1] - a[1]) - (b[1] - a[1]) * (q[0] - a[0]) : s0;
        if (sp >= 0) out[2 * count] = p[0], out[2 * count + 1] = p[1], count++;
        if ((sp >= 0) != (sq >= 0)) {
            double t = sp / (sp - sq);
            out[2 * count] = p[0] + t * (q[0] - p[0]), out[2 * count + 1] = p[1] + t * (q[1] - p[1]);
            count++;
        }
    }
    return count;
}

int cm_kernel_point(const double *xy, long m, double out[2])
{
    double lo[2] = {xy[0], xy[1]}, hi[2] = {xy[0], xy[1]};
    for (long i = 1; i < m; i++)
        for (int c = 0; c < 2; c++) lo[c] = fmin(lo[c], xy[2 * i + c]), hi[c] = fmax(hi[c], xy[2 * i + c]);
    /* the clipped polygon and the next one, in one block */
    double *block = malloc(4 * (size_t)(m + 8) * sizeof *block);
    if (!block) return -1;
    double *a = block, *b = block + 2 * (m + 8);
    double pad = (hi[0] - lo[0]) + (hi[1] - lo[1]); /* any box around it */
    double box[8] = {lo[0] - pad, lo[1] - pad, hi[0] + pad, lo[1] - pad,
                     hi[0] + pad, hi[1] + pad, lo[0] - pad, hi[1] + pad};
    memcpy(a, box, sizeof box);
    long n = 4;
    for (long i = 0; i < m && n >= 3; i++) {
        n = clip_half_plane(a, n, xy + 2 * i, xy + 2 * cm_cycle_next(i, m), b);
        double *t = a;
        a = b, b = t;
    }
    int found = 0;
    if (n >= 3) {
        /* area centroid: inside the kernel even when it is thin */
        double area = 0, cx = 0, cy = 0;
        for (long i = 0; i < n; i++) {
            const double *p = a + 2 * i, *q = a + 2 * cm_cycle_next(i, n);
            double w = p[0] * q[1] - q[0] * p[1];
            area += w, cx += (p[0] + q[0]) * w, cy += (p[1] + q[1]) * w;
        }
        if (area > 0) {
            out[0] = cx / (3 * area), out[1] = cy / (3 * area);
            found = 1;
            for (long i = 0; i < m && found; i++)
                found = cm_orient2d(xy + 2 * i, xy + 2 * cm_cycle_next(i, m), out) > 0;
        }
    }
    free(block);
    return found;
}

/* ---- ear clipping over exact points -------------------------------------- */

/* The ring of remaining vertices, their turn (sign of the orientation at
 * the vertex) and cached ear flags. Only vertices that are not strictly
 * convex can block an ear, and a vertex never turns from convex back to
 * reflex while ears are cut: the input points among them sit in a grid
 * (only those in an ear's bounding box are tested), the few constructed
 * points (approximate coordinates) in a list tested every time. */
typedef struct {
    cm_xpool *pool;
    const long *ids;
    long *prev, *next, *blockers, nblockers;
    signed char *turn, *ear, *gone;
    const double **input; /* per vertex: its coordinates if an input point, else NULL */
    cm_pointgrid grid;
} ear_ctx;

/* cm_xorient, with input points tested here directly (what it does for them) */
static int xo(const ear_ctx *e, long a, long b, long c)
{
    const double *pa = e->input[a], *pb = e->input[b], *pc = e->input[c];
    if (pa && pb && pc && e->ids[a] != e->ids[b] && e->ids[b] != e->ids[c] && e->ids[a] != e->ids[c])
        return cm_orient2d(pa, pb, pc);
    return cm_xorient(e->pool, e->ids[a], e->ids[b], e->ids[c]);
}

static int xinside(const ear_ctx *e, long a, long b, long c, long v)
{
    return v != a && v != b && v != c && xo(e, a, b, v) >= 0 && xo(e, b, c, v) >= 0 && xo(e, c, a, v) >= 0;
}

static int xear_blocked(ear_ctx *e, long a, long b, long c)
{
    long kept = 0;
    int blocked = 0;
    for (long i = 0; i < e->nblockers; i++) { /* constructed points */
        long v = e->blockers[i];
        if (e->gone[v] || e->turn[v] > 0) continue; /* drop it for good */
        e->blockers[kept++] = v;
        if (!blocked) blocked = xinside(e, a, b, c, v);
    }
    e->nblockers = kept;
    if (blocked || e->grid.count == 0) return blocked;
    /* the triangle's bounding box, widened to hold its exact corners */
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    const long corners[3] = {a, b, c};
    for (int i = 0; i < 3; i++) {
        const double *q = cm_xpool_xy(e->pool, e->ids[corners[i]]);
        int exact = cm_xpool_is_input(e->pool, e->ids[corners[i]]);
        for (int d = 0; d < 2; d++) {
            double slack = exact ? 0.0 : 1e-10 * (fabs(q[0]) + fabs(q[1])) + 1e-300;
            lo[d] = fmin(lo[d], q[d] - slack), hi[d] = fmax(hi[d], q[d] + slack);
        }
    }
    long cells[4];
    cm_pointgrid_range(&e->grid, lo[0], lo[1], hi[0], hi[1], cells);
    for (long cy = cells[2]; cy <= cells[3] && !blocked; cy++)
        for (long cx = cells[0]; cx <= cells[1] && !blocked; cx++)
            for (long v = e->grid.head[cy * e->grid.nx + cx]; v >= 0 && !blocked; v = e->grid.next[v])
                blocked = xinside(e, a, b, c, v);
    return blocked;
}

static void xupdate_vertex(ear_ctx *e, long v)
{
    e->turn[v] = (signed char)xo(e, e->prev[v], v, e->next[v]);
    if (e->turn[v] > 0) cm_pointgrid_remove(&e->grid, v);
    e->ear[v] = e->turn[v] > 0 && !xear_blocked(e, e->prev[v], v, e->next[v]);
}

static int clip_xears(ear_ctx *e, long k, int32_t *tri_out)
{
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    long reflex = 0;
    for (long i = 0; i < k; i++) {
        e->prev[i] = (i + k - 1) % k, e->next[i] = (i + 1) % k, e->gone[i] = 0;
        const double *q = cm_xpool_xy(e->pool, e->ids[i]);
        for (int d = 0; d < 2; d++) lo[d] = fmin(lo[d], q[d]), hi[d] = fmax(hi[d], q[d]);
    }
    e->nblockers = 0;
    for (long i = 0; i < k; i++) {
        e->turn[i] = (signed char)xo(e, e->prev[i], i, e->next[i]);
        reflex += e->turn[i] <= 0;
    }
    if (cm_pointgrid_init(&e->grid, k, lo, hi, reflex) != 0) return -1;
    for (long i = 0; i < k; i++) {
        if (e->turn[i] > 0) continue;
        if (cm_xpool_is_input(e->pool, e->ids[i])) {
            const double *q = cm_xpool_xy(e->pool, e->ids[i]);
            cm_pointgrid_insert(&e->grid, i, q[0], q[1]);
        } else {
            e->blockers[e->nblockers++] = i;
        }
    }
    for (long i = 0; i < k; i++) e->ear[i] = e->turn[i] > 0 && !xear_blocked(e, e->prev[i], i, e->next[i]);
    long remaining = k, v = 0, misses = 0, t = 0;
    while (remaining > 3) {
        if (!e->ear[v]) {
            if (++misses > remaining) return 1; /* no ear: not simple */
            v = e->next[v];
            continue;
        }
        long a = e->prev[v], c = e->next[v];
        tri_out[3 * t] = (int32_t)a, tri_out[3 * t + 1] = (int32_t)v, tri_out[3 * t + 2] = (int32_t)c;
        t++;
        e->next[a] = c, e->prev[c] = a, e->gone[v] = 1;
        cm_pointgrid_remove(&e->grid, v);
        remaining--;
        xupdate_vertex(e, a);
        xupdate_vertex(e, c);
        misses = 0;
        v = a;
    }
    if (xo(e, e->prev[v], v, e->next[v]) <= 0) return 1;
    tri_out[3 * t] = (int32_t)e->prev[v], tri_out[3 * t + 1] = (int32_t)v,
    tri_out[3 * t + 2] = (int32_t)e->next[v];
    return 0;
}

int cm_xtriangulate(cm_xpool *pool, const long *ids, long k, int32_t *tri_out)
{
    size_t n = (size_t)k;
    ear_ctx e = {pool, ids, malloc(n * sizeof(long)), malloc(n * sizeof(long)),
                 malloc(n * sizeof(long)), 0, malloc(n), malloc(n), malloc(n), malloc(n * sizeof(double *)),
                 .grid = {.head = NULL}};
    int status = -1;
    for (long i = 0; e.input && i < k; i++)
        e.input[i] = cm_xpool_is_input(pool, ids[i]) ? cm_xpool_xy(pool, ids[i]) : NULL;
    if (e.prev && e.next && e.blockers && e.turn && e.ear && e.gone && e.input) status = clip_xears(&e, k, tri_out);
    free(e.prev), free(e.next), free(e.blockers), free(e.turn), free(e.ear), free(e.gone), free(e.input);
    cm_pointgrid_clear(&e.grid);
    return status;
}

/* ---- visibility from a source: rooted dual tree, backward cones ---------- */

void cm_vsource_clear(cm_vsource *vs)
{
    free(vs->tri), free(vs->nbr); /* nbr starts the block of the others */
    memset(vs, 0, sizeof *vs);
}

/* The arrays besides the triangles, in one block that nbr starts (one
 * allocation per pocket, not seven). fan_start is zeroed. */
static int alloc_arrays(cm_vsource *vs)
{
    size_t k = (size_t)vs->k, nt = (size_t)vs->nt;
    int32_t *b = malloc((11 * nt + 2 * k + 2) * sizeof *b);
    if (!b) return -1;
    vs->nbr = b, b += 3 * nt;
    vs->up = b, b += nt;
    vs->depth = b, b += nt;
    vs->toward = b, b += 3 * nt;
    vs->fan = b, b += 3 * nt + 1;
    vs->low = b, b += k;
    vs->fan_start = b;
    memset(vs->fan_start, 0, (k + 1) * sizeof *b);
    return 0;
}

/* Breadth-first from the roots (the source's fan, or the triangle on the
 * window k-1 -> 0, both found from the fans): depth and the corner facing
 * the parent. The dual graph is a tree, so these do not depend on the
 * order. */
static int root_tree(cm_vsource *vs)
{
    long nt = vs->nt, head = 0, tail = 0;
    int32_t *queue = vs->low; /* k > nt entries, filled only after this */
    for (long t = 0; t < nt; t++) vs->depth[t] = -1, vs->up[t] = -1;
    long v = vs->source >= 0 ? vs->source : 0;
    for (long f = vs->fan_start[v]; f < vs->fan_start[v + 1]; f++) {
        int32_t t = vs->fan[f];
        const int32_t *c = vs->tri + 3 * t;
        if (vs->source < 0 && (c[0] == 0 ? c[2] : c[1] == 0 ? c[0] : c[1]) != vs->k - 1) continue;
        vs->depth[t] = 0, queue[tail++] = t;
    }
    while (head < tail) {
        long t = queue[head++];
        for (int i = 0; i < 3; i++) {
            int32_t n = vs->nbr[3 * t + i];
            if (n < 0 || vs->depth[n] >= 0) continue;
            vs->depth[n] = vs->depth[t] + 1;
            for (int j = 0; j < 3; j++)
                if (vs->nbr[3 * n + j] == t) vs->up[n] = j;
            queue[tail++] = n;
        }
    }
    for (long t = 0; t < nt; t++) {
        int c = vs->up[t];
        int32_t *w = vs->toward + 3 * t;
        w[0] = c < 0 ? -1 : vs->nbr[3 * t + c];
        w[1] = c < 0 ? -1 : (int32_t)vs->ids[vs->tri[3 * t + (c + 2) % 3]];
        w[2] = c < 0 ? -1 : (int32_t)vs->ids[vs->tri[3 * t + (c + 1) % 3]];
    }
    return 0;
}

static void build_fans(cm_vsource *vs)
{
    long k = vs->k, nt = vs->nt;
    for (long s = 0; s < 3 * nt; s++) vs->fan_start[vs->tri[s] + 1]++;
    for (long v = 0; v < k; v++) vs->fan_start[v + 1] += vs->fan_start[v];
    for (long s = 0; s < 3 * nt; s++) vs->fan[vs->fan_start[vs->tri[s]]++] = (int32_t)(s / 3);
    for (long v = k; v > 0; v--) vs->fan_start[v] = vs->fan_start[v - 1];
    vs->fan_start[0] = 0;
}

/* Per vertex, the incident triangle of least depth. */
static void find_low(cm_vsource *vs)
{
    for (long v = 0; v < vs->k; v++) {
        vs->low[v] = vs->fan[vs->fan_start[v]];
        for (long f = vs->fan_start[v] + 1; f < vs->fan_start[v + 1]; f++)
            if (vs->depth[vs->fan[f]] < vs->depth[vs->low[v]]) vs->low[v] = vs->fan[f];
    }
}

int cm_vsource_reroot(cm_vsource *vs, long source)
{
    vs->source = source;
    if (root_tree(vs) != 0) return -1;
    for (long t = 0; t < vs->nt; t++)
        if (vs->depth[t] < 0) return 1; /* disconnected: not a triangulation */
    find_low(vs);
    return 0;
}

/* The arrays besides the triangles, and the rooting. */
static int finish_build(cm_vsource *vs, long source)
{
    if (alloc_arrays(vs) != 0 || cm_tri_adjacency(vs->tri, vs->nt, vs->nbr) != 0) return -1;
    build_fans(vs);
    return cm_vsource_reroot(vs, source);
}

int cm_vsource_build(cm_vsource *vs, cm_xpool *pool, const long *ids, long k, long source)
{
    memset(vs, 0, sizeof *vs);
    vs->pool = pool, vs->ids = ids, vs->k = k, vs->nt = k - 2, vs->source = source;
    vs->tri = malloc(3 * (size_t)(k - 2) * sizeof *vs->tri);
    if (!vs->tri) return -1;
    int s = cm_xtriangulate(pool, ids, k, vs->tri);
    if (s != 0) return s;
    return finish_build(vs, source);
}

/* Do the counter-clockwise triangles over the polygon's k vertices
 * triangulate it? They do when around every vertex v they form one fan
 * from the edge to v + 1 to the edge to v - 1: then they form a disk
 * (k - 2 triangles, every vertex on the one boundary cycle, which is the
 * polygon), and counter-clockwise triangles over a disk whose boundary is
 * a simple polygon cover each of its points once (the winding number).
 * The fans give the neighbours too: the triangle (v, x, y) of v's fan
 * meets the one (v, y, z) across its edge v - y, the corner x's slot
 * (none where y is v - 1). Every edge of a triangle is such an edge of
 * one of its corners' fans, so nbr is filled. O(k). Returns 0 yes, 1 no,
 * -1 out of memory. */
static int triangulates(cm_vsource *vs)
{
    static const int after[3] = {1, 2, 0}, before[3] = {2, 0, 1};
    long k = vs->k;
    int32_t *next = malloc(2 * (size_t)k * sizeof *next);
    if (!next) return -1;
    int32_t *from = next + k;
    for (long v = 0; v < k; v++) next[v] = -1;
    int ok = 1;
    for (long v = 0; v < k && ok; v++) {
        long deg = vs->fan_start[v + 1] - vs->fan_start[v], steps = 0;
        long vn = v + 1 == k ? 0 : v + 1, vp = v == 0 ? k - 1 : v - 1;
        for (long f = vs->fan_start[v]; f < vs->fan_start[v + 1]; f++) {
            long t = vs->fan[f];
            const int32_t *c = vs->tri + 3 * t;
            int i = c[0] == v ? 0 : c[1] == v ? 1 : 2;
            int32_t x = c[after[i]];
            if (next[x] >= 0) ok = 0;
            next[x] = c[before[i]], from[x] = (int32_t)t;
        }
        for (long u = vn; ok && u != vp; steps++) {
            if (steps >= deg || next[u] < 0) ok = 0;
            else u = next[u];
        }
        ok = ok && steps == deg;
        for (long f = vs->fan_start[v]; ok && f < vs->fan_start[v + 1]; f++) {
            long t = vs->fan[f];
            const int32_t *c = vs->tri + 3 * t;
            int i = c[0] == v ? 0 : c[1] == v ? 1 : 2;
            int32_t y = c[before[i]];
            vs->nbr[3 * t + after[i]] = y == vp ? -1 : from[y];
        }
        for (long f = vs->fan_start[v]; f < vs->fan_start[v + 1]; f++) {
            const int32_t *c = vs->tri + 3 * vs->fan[f];
            next[c[0]] = next[c[1]] = next[c[2]] = -1;
        }
    }
    free(next);
    return !ok;
}

int cm_vsource_build_tri(cm_vsource *vs, cm_xpool *pool, const long *ids, long k, long source, int32_t *tri)
{
    memset(vs, 0, sizeof *vs);
    vs->pool = pool, vs->ids = ids, vs->k = k, vs->nt = k - 2, vs->source = source;
    vs->tri = tri;
    if (alloc_arrays(vs) != 0) return -1;
    build_fans(vs);
    int s = triangulates(vs);
    if (s != 0) return s;
    return cm_vsource_reroot(vs, source);
}

/* Narrows the cone (b, a) seen from p, not empty, by a crossed diagonal
 * from r (right) to l (left). Returns 0 if the cone became empty; when
 * neither end moved it is the cone it was. */
static int narrow(const cm_vsource *vs, long p, long *a, long *b, long l, long r)
{
    int moved = 0;
    if (cm_xorient_in(&vs->in, vs->pool, p, *a, l) < 0) *a = l, moved = 1;
    if (cm_xorient_in(&vs->in, vs->pool, p, *b, r) > 0) *b = r, moved = 1;
    return !moved || cm_xorient_in(&vs->in, vs->pool, p, *b, *a) > 0;
}

/* From triangle t (not a root) up to the source, the cone starting at t's
 * edge toward the root. */
static int walk_up(const cm_vsource *vs, long p, long t, long *a, long *b)
{
    const long *ids = vs->ids;
    const int32_t *w = vs->toward + 3 * t;
    long la = w[1], lb = w[2];
    for (w = vs->toward + 3 * (size_t)w[0]; w[0] >= 0; w = vs->toward + 3 * (size_t)w[0])
        if (!narrow(vs, p, &la, &lb, w[1], w[2])) return 0;
    if (vs->source < 0) {
        if (!narrow(vs, p, &la, &lb, ids[0], ids[vs->k - 1])) return 0;
    } else {
        long s = ids[vs->source];
        if (cm_xorient_in(&vs->in, vs->pool, p, lb, s) <= 0 || cm_xorient_in(&vs->in, vs->pool, p, s, la) <= 0) return 0;
        la = lb = s;
    }
    *a = la, *b = lb;
    return 1;
}

static int root_cone(const cm_vsource *vs, long *a, long *b)
{
    if (vs->source < 0) {
        *a = vs->ids[0], *b = vs->ids[vs->k - 1];
    } else {
        *a = *b = vs->ids[vs->source];
    }
    return 1;
}

int cm_vsource_vertex_cone(cm_vsource *vs, long i, long *a, long *b)
{
    long t = vs->low[i];
    if (vs->source == i || (vs->source < 0 && (i == 0 || i == vs->k - 1))) return 0;
    if (vs->depth[t] == 0) {
        if (vs->source >= 0 && (i == (vs->source + 1) % vs->k || vs->source == (i + 1) % vs->k))
            return 0; /* a polygon edge, not a diagonal */
        return root_cone(vs, a, b);
    }
    if (vs->tri[3 * t + vs->up[t]] != i) return 0; /* cannot happen: low is lowest */
    return walk_up(vs, vs->ids[i], t, a, b);
}

int cm_vsource_point_cone(cm_vsource *vs, long p, long *a, long *b)
{
    for (long t = 0; t < vs->nt; t++) {
        const int32_t *c = vs->tri + 3 * t;
        int inside = 1;
        for (int i = 0; i < 3 && inside; i++)
            inside = cm_xorient_in(&vs->in, vs->pool, vs->ids[c[i]], vs->ids[c[(i + 1) % 3]], p) > 0;
        if (!inside) continue;
        if (vs->depth[t] == 0) return root_cone(vs, a, b);
        return walk_up(vs, p, t, a, b);
    }
    return -1;
}
