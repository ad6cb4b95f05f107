/* Shamos-Hoey scan-line for polygon simplicity.
 *
 * The scan line visits vertices in (x, then y) order, as a line tilted
 * infinitesimally from vertical would meet them: vertical edges and equal x
 * need no special case. Each edge runs from its left (smaller in that
 * order) endpoint to its right one. The scan-line status holds the edges that
 * cross the scan line, bottom to top, in a treap; each node also links its
 * in-order neighbours so that removal needs no comparison.
 *
 * Every pair of edges that becomes adjacent in the status is tested
 * exactly, and the scan stops at the first offending pair. If the polygon
 * is not simple, let q be the smallest point of any offending contact: up
 * to q the status order is consistent, and the edges through q (or ending
 * there) form a contiguous block in it, so some offending pair is adjacent
 * before the scan line passes q, or the insertion at q meets it in a
 * comparison that returns "on the line". */
#include "geom/polygon_check.h"

#include "base/cycle.h"
#include "geom/predicates.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

typedef struct status_node {
    long left, right, parent; /* treap links, -1 for none */
    long below, above;        /* in-order neighbours, -1 for none */
    uint64_t priority;
} status_node;

typedef struct scanline {
    const double *xy;
    long n;
    const long *succ, *pred; /* loops: the vertex after / before; NULL: one cycle */
    status_node *node; /* indexed by edge */
    long root;
    long hit_a, hit_b; /* the offending pair, once found */
    int tame;          /* every coordinate tame (cm_coords_tame) */
} scanline;

typedef cm_vertex_event vertex_event;

/* ---- geometry -------------------------------------------------------- */

/* Vertices and edges are numbered 0..n-1 (no integer division: these are
 * read at every step of the sweep). */
static const double *vertex_at(const scanline *sw, long v)
{
    return sw->xy + 2 * v;
}

static long succ_of(const scanline *sw, long v)
{
    return sw->succ ? sw->succ[v] : cm_cycle_next(v, sw->n);
}

static long pred_of(const scanline *sw, long v)
{
    return sw->pred ? sw->pred[v] : cm_cycle_prev(v, sw->n);
}

static const double *edge_start(const scanline *sw, long e)
{
    return vertex_at(sw, e);
}

static const double *edge_end(const scanline *sw, long e)
{
    return vertex_at(sw, succ_of(sw, e));
}

static int same_point(const double a[2], const double b[2])
{
    return a[0] == b[0] && a[1] == b[1];
}

static const double *edge_left(const scanline *sw, long e)
{
    const double *s = edge_start(sw, e), *t = edge_end(sw, e);
    return cm_point_less(t, s) ? t : s;
}

static const double *edge_right(const scanline *sw, long e)
{
    const double *s = edge_start(sw, e), *t = edge_end(sw, e);
    return cm_point_less(t, s) ? s : t;
}

/* The orientation of a, b, c (tame points: the filter need not check its
 * differences). */
static int orient(const scanline *sw, const double a[2], const double b[2], const double c[2])
{
    return cm_orient2d_either(sw->tame, a, b, c);
}

/* Edge `first` (u to v) is followed by edge `second` (v to w): they
 * overlap beyond v only when collinear with u and w on the same side. */
static int consecutive_overlap(const scanline *sw, long first, long second)
{
    const double *u = edge_start(sw, first), *v = edge_end(sw, first);
    const double *w = edge_end(sw, second);
    return orient(sw, u, v, w) == 0 && cm_point_less(u, v) == cm_point_less(w, v);
}

static int edges_offend(const scanline *sw, long i, long j)
{
    if (succ_of(sw, i) == j) return consecutive_overlap(sw, i, j);
    if (succ_of(sw, j) == i) return consecutive_overlap(sw, j, i);
    return cm_segments_intersect(edge_start(sw, i), edge_end(sw, i),
                                 edge_start(sw, j), edge_end(sw, j)) != 0;
}

static void record_hit(scanline *sw, long i, long j)
{
    sw->hit_a = i < j ? i : j;
    sw->hit_b = i < j ? j : i;
}

/* Records and returns 1 if i and j (either may be -1) offend. */
static int check_pair(scanline *sw, long i, long j)
{
    if (i < 0 || j < 0 || !edges_offend(sw, i, j)) return 0;
    record_hit(sw, i, j);
    return 1;
}

/* Where edge s, starting at p, goes relative to status edge t: +1 above,
 * -1 below, 0 if they touch (p inside t, or both leave p along one ray). */
static int compare_at(const scanline *sw, long s, const double p[2], long t)
{
    const double *t_left = edge_left(sw, t), *t_right = edge_right(sw, t);
    if (same_point(t_left, p))
        return orient(sw, p, t_right, edge_right(sw, s));
    return orient(sw, t_left, t_right, p);
}

/* ---- treap ----------------------------------------------------------- */

/* Fixed pseudo-random priorities: a hash of the edge index (splitmix64). */
static uint64_t priority_of(long e)
{
    uint64_t z = (uint64_t)e + 0x9e3779b97f4a7c15u;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return z ^ (z >> 31);
}

static void replace_child(scanline *sw, long parent, long old, long new_child)
{
    if (parent < 0)
        sw->root = new_child;
    else if (sw->node[parent].left == old)
        sw->node[parent].left = new_child;
    else
        sw->node[parent].right = new_child;
}

/* Rotates x above its parent, keeping the in-order sequence. */
static void rotate_up(scanline *sw, long x)
{
    status_node *nd = sw->node;
    long p = nd[x].parent, g = nd[p].parent, moved;
    if (nd[p].left == x) {
        moved = nd[x].right;
        nd[p].left = moved;
        nd[x].right = p;
    } else {
        moved = nd[x].left;
        nd[p].right = moved;
        nd[x].left = p;
    }
    if (moved >= 0) nd[moved].parent = p;
    nd[p].parent = x;
    nd[x].parent = g;
    replace_child(sw, g, p, x);
}

/* Inserts edge s, whose left endpoint p is the current event, then tests
 * it against its new neighbours. Returns 1 if an offending pair is found. */
static int status_insert(scanline *sw, long s, const double p[2])
{
    status_node *nd = sw->node;
    long parent = -1, below = -1, above = -1, cur = sw->root;
    int side = 0;
    while (cur >= 0) {
        side = compare_at(sw, s, p, cur);
        if (side == 0) {
            record_hit(sw, s, cur);
            return 1;
        }
        parent = cur;
        if (side > 0) {
            below = cur;
            cur = nd[cur].right;
        } else {
            above = cur;
            cur = nd[cur].left;
        }
    }
    nd[s] = (status_node){-1, -1, parent, below, above, priority_of(s)};
    if (parent < 0)
        sw->root = s;
    else if (side > 0)
        nd[parent].right = s;
    else
        nd[parent].left = s;
    if (below >= 0) nd[below].above = s;
    if (above >= 0) nd[above].below = s;
    while (nd[s].parent >= 0 && nd[s].priority > nd[nd[s].parent].priority)
        rotate_up(sw, s);
    return check_pair(sw, below, s) || check_pair(sw, s, above);
}

/* Removes edge s, then tests the two edges that become neighbours. */
static int status_remove(scanline *sw, long s)
{
    status_node *nd = sw->node;
    for (;;) { /* rotate s down to a leaf */
        long l = nd[s].left, r = nd[s].right;
        if (l < 0 && r < 0) break;
        if (r < 0 || (l >= 0 && nd[l].priority > nd[r].priority))
            rotate_up(sw, l);
        else
            rotate_up(sw, r);
    }
    replace_child(sw, nd[s].parent, s, -1);
    long below = nd[s].below, above = nd[s].above;
    if (below >= 0) nd[below].above = above;
    if (above >= 0) nd[above].below = below;
    return check_pair(sw, below, above);
}

/* ---- scan line ----------------------------------------------------------- */

static int event_before(const vertex_event *a, const vertex_event *b)
{
    if (a->x != b->x) return a->x < b->x;
    if (a->y != b->y) return a->y < b->y;
    return a->vertex < b->vertex;
}

int cm_vertex_events_sort(cm_vertex_event *e, long n)
{
    enum { RUN = 8 };
    for (long lo = 0; lo < n; lo += RUN) /* insertion sort of short runs */
        for (long i = lo + 1; i < n && i < lo + RUN; i++) {
            vertex_event x = e[i];
            long j = i;
            for (; j > lo && event_before(&x, &e[j - 1]); j--) e[j] = e[j - 1];
            e[j] = x;
        }
    if (n <= RUN) return 0;
    vertex_event *tmp = malloc((size_t)n * sizeof *tmp), *from = e, *to = tmp;
    if (!tmp) return -1;
    for (long width = RUN; width < n; width *= 2) {
        for (long lo = 0; lo < n; lo += 2 * width) {
            long mid = lo + width < n ? lo + width : n, hi = lo + 2 * width < n ? lo + 2 * width : n;
            long a = lo, b = mid, k = lo;
            while (a < mid && b < hi) to[k++] = event_before(&from[b], &from[a]) ? from[b++] : from[a++];
            while (a < mid) to[k++] = from[a++];
            while (b < hi) to[k++] = from[b++];
        }
        vertex_event *t = from;
        from = to, to = t;
    }
    if (from != e) memcpy(e, from, (size_t)n * sizeof *e);
    free(tmp);
    return 0;
}

/* Edges ending at vertex v leave the status before edges starting there
 * enter it. Returns 1 if an offending pair is found. */
static int process_vertex(scanline *sw, long v)
{
    long incoming = pred_of(sw, v), outgoing = v;
    const double *p = vertex_at(sw, v);
    int incoming_ends = cm_point_less(vertex_at(sw, incoming), p);
    int outgoing_ends = cm_point_less(vertex_at(sw, succ_of(sw, v)), p);
    if (incoming_ends && status_remove(sw, incoming)) return 1;
    if (outgoing_ends && status_remove(sw, outgoing)) return 1;
    if (!incoming_ends && status_insert(sw, incoming, p)) return 1;
    if (!outgoing_ends && status_insert(sw, outgoing, p)) return 1;
    return 0;
}

/* A repeated vertex (excluded by the caller, but possible) breaks the
 * scan line's invariants; report the edges leaving its two copies instead. */
static int find_repeated_vertex(scanline *sw, const vertex_event *events)
{
    for (long k = 0; k + 1 < sw->n; k++) {
        if (events[k].x == events[k + 1].x && events[k].y == events[k + 1].y) {
            record_hit(sw, events[k].vertex, events[k + 1].vertex);
            return 1;
        }
    }
    return 0;
}

static int run_scanline(scanline *sw, const vertex_event *events)
{
    if (find_repeated_vertex(sw, events)) return 1;
    for (long k = 0; k < sw->n; k++)
        if (process_vertex(sw, events[k].vertex)) return 1;
    return 0;
}

/* sorted: the vertex events in cm_vertex_events_sort's order, or NULL
 * (made here). */
static int find_intersection(scanline *sw, const vertex_event *sorted, long *edge_a, long *edge_b)
{
    int found;
    long n = sw->n;
    if (n < 2) {
        found = 0;
    } else if (n == 2) { /* the two edges coincide */
        record_hit(sw, 0, 1);
        found = 1;
    } else if ((size_t)n > SIZE_MAX / sizeof(status_node)) {
        found = -1;
    } else {
        vertex_event *events = sorted ? NULL : malloc((size_t)n * sizeof *events);
        for (long v = 0; events && v < n; v++) events[v] = (vertex_event){sw->xy[2 * v], sw->xy[2 * v + 1], v};
        sw->node = malloc((size_t)n * sizeof *sw->node);
        if ((!sorted && (!events || cm_vertex_events_sort(events, n) != 0)) || !sw->node) found = -1;
        else found = run_scanline(sw, sorted ? sorted : events);
        free(events);
        free(sw->node);
    }
    if (edge_a) *edge_a = found == 1 ? sw->hit_a : -1;
    if (edge_b) *edge_b = found == 1 ? sw->hit_b : -1;
    return found;
}

int cm_polygon_find_intersection(const double *xy, long n, long *edge_a,
                                 long *edge_b)
{
    return cm_polygon_find_intersection_sorted(xy, n, NULL, edge_a, edge_b);
}

int cm_polygon_find_intersection_sorted(const double *xy, long n, const cm_vertex_event *sorted, long *edge_a,
                                        long *edge_b)
{
    scanline sw = {xy, n, NULL, NULL, NULL, -1, -1, -1, cm_coords_tame(xy, 2 * n)};
    return find_intersection(&sw, sorted, edge_a, edge_b);
}

int cm_loops_find_intersection(const double *xy, const size_t *loop_sizes, size_t num_loops,
                               long *edge_a, long *edge_b)
{
    long n = 0;
    for (size_t l = 0; l < num_loops; l++) n += (long)loop_sizes[l];
    long *succ = malloc(((size_t)n + 1) * sizeof *succ), *pred = malloc(((size_t)n + 1) * sizeof *pred);
    int found = -1;
    if (succ && pred) {
        long start = 0;
        for (size_t l = 0; l < num_loops; l++) {
            long m = (long)loop_sizes[l];
            for (long j = 0; j < m; j++) {
                succ[start + j] = start + (j + 1) % m;
                pred[start + (j + 1) % m] = start + j;
            }
            start += m;
        }
        scanline sw = {xy, n, succ, pred, NULL, -1, -1, -1, cm_coords_tame(xy, 2 * n)};
        found = find_intersection(&sw, NULL, edge_a, edge_b);
    }
    free(succ), free(pred);
    return found;
}
