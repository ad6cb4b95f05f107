/* The dynamic program of steinerfree.h.
 *
 * Vertices 0..m-1 in order; a "link" (a, b), a < b, is a common diagonal or
 * a polygon edge b = a + 1. G(i, j) is the best decomposition of the
 * sub-polygon i, i+1, ..., j closed by the link (i, j); its face on that
 * link is a chain of links i = f0 < f1 < ... < ft = j (t >= 2): a triangle
 * (t = 2, cost 0), a stuck face (cost t - 2), or a fan face from the fan
 * point (t >= 3, cost 1), plus G of every chain link. Chains from i are
 * built left to right, per row i: plain chains (one link, or two or more)
 * and fan chains (links that admit the fan). The root is the whole
 * polygon, closed by the edge (m - 1, 0). Values compare by cost, then by
 * the smallest angle (larger is better), kept as sin^2 of that angle. */
#include "construct/steinerfree.h"

#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/buf.h"
#include "base/cycle.h"
#include "geom/predicates.h"

typedef struct { long cost; double q; } val;

static const val none = {LONG_MAX, 0.0};
/* Beyond every cost, with room to add two of them. */
#define FAR (LONG_MAX / 4)
#define NO_TRIANGLE 2.0 /* quality of a value without triangles */

/* fmin without the library call, for a that is not NaN: one minsd. Only
 * quality() can give NaN (inf / inf, squared lengths beyond the doubles),
 * and only as b: every value's quality is a qmin starting from
 * NO_TRIANGLE, so never NaN, and squared lengths are not either.
 * Qualities are never -0 (equal values: either is the same). */
static inline double qmin(double a, double b)
{
    return b < a ? b : a;
}

static int better(val a, val b)
{
    return a.cost < b.cost || (a.cost == b.cost && a.q > b.q);
}

static int exists(val a) { return a.cost != LONG_MAX; }

static val best_of(val a, val b) { return better(b, a) ? b : a; }

enum { BY_TRIANGLE, BY_FACE, BY_FAN };

/* Chains from the row's vertex i to l: one link or more, plain or fan. */
typedef struct chains {
    val one, more;   /* exactly one link; two or more */
    val best;        /* best_of(one, more), once l is done */
    int32_t arg;     /* for `more`: the vertex before l */
    /* flags as int, not char: a char store could be any object for the
     * compiler, the hot loops' arrays and bounds would be read again */
    int from_more; /* `more` extends a chain of two or more */
    int best_more; /* a chain extending this one extends `more` */
} chains;

/* The arrays a run without fan points takes from a workspace. */
enum { W_START, W_REACH, W_LEFT, W_OUT_START, W_OUT_LINK, W_G, W_G_COST, W_ARG, W_BY, W_FAN_OF, W_TRI, W_FACE,
       W_FACE_START, W_FACE_FAN, W_STACK, W_SLOTS };

struct cm_sf_work {
    void *buf[W_SLOTS];
    size_t bytes[W_SLOTS];
};

typedef struct dp {
    cm_sf_work *work; /* NULL: every array its own allocation */
    long m;
    const cm_diagview *common;
    const double *const *xy;
    const double *fans; /* nfans candidates of k points (2 doubles each) */
    size_t k, nfans;
    int tame; /* every coordinate and fan point tame (cm_coords_tame) */
    double *fan_diff; /* tame: per fan point and geometry, each vertex
                         minus the fan point (m pairs), else NULL */
    long *start;      /* links ending at l: left[start[l] .. start[l+1]) */
    int32_t *left;    /* ascending */
    long *out_start;  /* links leaving a: out_link[out_start[a] ..
                         out_start[a+1]), their right ends in out_to,
                         ascending */
    int32_t *out_link, *out_to;
    long row_last;    /* the farthest l the current row's fan chains reach */
    long fan_bound;   /* the current row: a fan chain costing this or more
                         serves no fan face that can win (see closers) */
    val *g;           /* per link */
    long *g_cost;     /* per link: g[].cost again, all the chains' hot loop
                         reads (one index with left[], no 16-byte stride) */
    int32_t *arg;     /* per link: the chain's last vertex before l */
    unsigned char *by;
    int16_t *fan_of;  /* per link: the fan point of a BY_FAN face */
    /* A fan face from x lies outside the sub-polygon closed by each link
     * of its chain and inside the one closed by its closing link, and x
     * lies strictly inside the face: so each link serves x on one side
     * only, the side geometry 0 puts x on (fan_sides). */
    uint64_t *fwd_ok, *rev_ok; /* per link a < b: the fan points whose
                                  triangle on a -> b (b -> a) is valid in
                                  every geometry, on the side x can use */
    double *fan_q;    /* per fan point and link (nfans rows of links): the
                         quality of that triangle */
    uint64_t *row_fans; /* per row i: the fan points inside the sub-polygon
                           of its farthest link, all for the root's row:
                           the only ones its faces can be fans from */
    uint64_t fans_now;  /* row_fans of the row being solved */
    uint64_t *facing;   /* per vertex v: the fan points strictly inside its
                           corner, in every geometry, where v is convex
                           (all where it is not): the only ones a segment
                           from v into the polygon's interior can reach,
                           so the only ones a fan face through v can be
                           from */
    long *reach;        /* per row i: the farthest l it needs, its farthest
                           diagonal (the root's row: all) */
    val root;
    int32_t root_arg;
    unsigned char root_by;
    int16_t root_fan_of;
    uint64_t root_ok;  /* the fan points valid on the closing edge m-1 -> 0 */
    double *root_fan;  /* per fan point: that triangle's quality */
    long nlinks;
    chains *plain, *fanned; /* the current row; fanned: nfans rows of m */
    long *step_from;    /* per l, the current row: plain[l].best.cost + 1,
                           FAR when there is none (the chains' hot loop
                           reads these alone) */
    uint64_t *fan_in;   /* per l, the current row: see start_fans */
    uint64_t *fan_best, *fan_more; /* per l, the current row: the fan points
                                      whose chains to l exist (best), of two
                                      or more links (more) */
} dp;

/* n elements of size bytes (zeroed if asked): the workspace's slot, kept
 * for its next run, or a fresh allocation without one. */
static void *take(cm_sf_work *w, int slot, size_t n, size_t size, int zero)
{
    size_t bytes = n * size;
    if (!w) return zero ? calloc(n, size) : malloc(bytes);
    if (w->bytes[slot] < bytes) {
        size_t want = bytes > 2 * w->bytes[slot] ? bytes : 2 * w->bytes[slot];
        void *b = malloc(want);
        if (!b) return NULL;
        free(w->buf[slot]);
        w->buf[slot] = b, w->bytes[slot] = want;
    }
    if (zero) memset(w->buf[slot], 0, bytes);
    return w->buf[slot];
}

/* cm_grow for the links' left ends, in the workspace's slot if any. */
static int grow_left(dp *d, size_t *cap, size_t need)
{
    if (need <= *cap) return 0; /* the usual case, without the call */
    int r = cm_grow((void **)&d->left, cap, need, sizeof *d->left);
    if (d->work) d->work->buf[W_LEFT] = d->left, d->work->bytes[W_LEFT] = *cap * sizeof *d->left;
    return r;
}

static int is_link(const dp *d, long a, long b)
{
    if (b == a + 1) return 1;
    if (a == 0 && b == d->m - 1) return 0; /* the closing edge: the root */
    return cm_diagview_has(d->common, a, b);
}

/* sin^2 of the smallest angle of the triangle pa, pb, pc. */
static inline double quality(const double *pa, const double *pb, const double *pc)
{
    double ux = pb[0] - pa[0], uy = pb[1] - pa[1], vx = pc[0] - pa[0], vy = pc[1] - pa[1];
    double wx = pc[0] - pb[0], wy = pc[1] - pb[1];
    double ab = ux * ux + uy * uy, ac = vx * vx + vy * vy, bc = wx * wx + wy * wy;
    double cross = ux * vy - uy * vx, shortest = qmin(ab, qmin(ac, bc));
    return shortest > 0 ? cross * cross * shortest / (ab * ac * bc) : 0.0;
}

/* Worst geometry's quality of triangle (a, b, c). */
static inline double triangle_quality(const dp *d, long a, long b, long c)
{
    double q = NO_TRIANGLE;
    for (size_t g = 0; g < d->k; g++)
        q = qmin(q, quality(d->xy[g] + 2 * a, d->xy[g] + 2 * b, d->xy[g] + 2 * c));
    return q;
}

/* The orientation of a, b, c, fan points or vertices: where all are tame
 * the filter need not check its differences. */
static inline int orient(const dp *d, const double *a, const double *b, const double *c)
{
    return cm_orient2d_either(d->tame, a, b, c);
}

/* Is the triangle from fan point x on the directed edge a -> b valid in
 * every geometry? With tame points the filter reads the differences from
 * the fan point made once (fan_diff), the same doubles it would make. */
static int fan_valid(const dp *d, size_t x, long a, long b)
{
    for (size_t g = 0, xg = x * d->k; g < d->k; g++, xg++) {
        int o = 2;
        if (d->fan_diff) {
            const double *diff = d->fan_diff + 2 * xg * (size_t)d->m;
            o = cm_orient2d_bound_a(diff[2 * a], diff[2 * b], diff[2 * a + 1], diff[2 * b + 1]);
        }
        if (o == 2) o = orient(d, d->xy[g] + 2 * a, d->xy[g] + 2 * b, d->fans + 2 * xg);
        if (o <= 0) return 0;
    }
    return 1;
}

/* Worst geometry's quality of the triangle from fan point x on a -> b. */
static double fan_quality(const dp *d, size_t x, long a, long b)
{
    double q = NO_TRIANGLE;
    for (size_t g = 0; g < d->k; g++)
        q = qmin(q, quality(d->xy[g] + 2 * a, d->xy[g] + 2 * b, d->fans + 2 * (x * d->k + g)));
    return q;
}

/* The triangle from fan point x on the directed edge a -> b, or -1 if
 * invalid in some geometry. */
static double fan_min_angle(const dp *d, size_t x, long a, long b)
{
    return fan_valid(d, x, a, b) ? fan_quality(d, x, a, b) : -1.0;
}

#define Q_UNKNOWN -2.0 /* a valid fan triangle's quality not computed yet */

/* The quality of the valid triangle from fan point x on link s, directed
 * a -> b as it was found valid (the same operands: the same double),
 * computed when first read: most are never read. */
static double fan_q(const dp *d, size_t x, long s, long a, long b)
{
    double *q = &d->fan_q[x * (size_t)d->nlinks + (size_t)s];
    if (*q == Q_UNKNOWN) *q = fan_quality(d, x, a, b);
    return *q;
}
static int has_fan(uint64_t set, size_t x) { return (int)(set >> x) & 1; }
static chains *fanned(const dp *d, size_t x, long l) { return &d->fanned[x * (size_t)d->m + (size_t)l]; }

static long find_link(const dp *d, long a, long b)
{
    long lo = d->start[b], hi = d->start[b + 1] - 1;
    while (lo <= hi) {
        long mid = (lo + hi) / 2;
        if (d->left[mid] == a) return mid;
        if (d->left[mid] < a) lo = mid + 1; else hi = mid - 1;
    }
    return -1;
}

/* First link into l whose left end is > i. */
static long first_after(const dp *d, long l, long i)
{
    long lo = d->start[l], hi = d->start[l + 1];
    while (lo < hi) {
        long mid = (lo + hi) / 2;
        if (d->left[mid] <= i) lo = mid + 1; else hi = mid;
    }
    return lo;
}

/* The best decomposition so far for one link (or the root). */
typedef struct {
    val *value;
    long *cost; /* the link's g_cost, NULL for the root */
    int32_t *arg;
    unsigned char *by;
    int16_t *fan_of;
} slot;

/* The best decomposition found so far, kept apart from the table while a
 * link is solved (the table holds the links it is built from). */
typedef struct {
    val value;
    int32_t arg;
    unsigned char by;
    int16_t fan_of;
} pick;

static inline void offer(val c, unsigned char how, int32_t a, int16_t fan, pick *out)
{
    if (better(c, out->value)) out->value = c, out->arg = a, out->by = how, out->fan_of = fan;
}

/* Could a value of this cost whose quality is at most qmin(q, anything)
 * beat cur? The triangle's quality is worth computing only then. (q is
 * never NaN: see qmin.) */
static int could_win(long cost, double q, val cur)
{
    return cost < cur.cost || (cost == cur.cost && q > cur.q);
}

/* G for the link (i, l) (or the root) when a triangle on it costs 0: a
 * face of three or more links, or a fan face, costs at least 1, so only
 * the triangles of cost 0 can win, in the order close_face offers them,
 * and the row's chains are not needed (one[] is). 1 done, 0 not. */
static int close_triangle(const dp *d, long i, long l, long first, slot out)
{
    pick p = {none, -1, BY_TRIANGLE, -1};
    for (long s = first; s < d->start[l + 1]; s++) {
        long a = d->left[s];
        val gl = d->g[s], one = d->plain[a].one;
        if (gl.cost == 0 && one.cost == 1 && could_win(0, qmin(one.q, gl.q), p.value))
            offer((val){0, qmin(qmin(one.q, gl.q), triangle_quality(d, i, a, l))}, BY_TRIANGLE, (int32_t)a, -1, &p);
    }
    if (p.value.cost != 0) return 0;
    *out.value = p.value, *out.arg = p.arg, *out.by = p.by, *out.fan_of = p.fan_of;
    if (out.cost) *out.cost = p.value.cost;
    return 1;
}

/* G for the link (i, l) (or the root): the face on it closes a chain of
 * two links (a triangle), of three or more (a stuck face), or a fan chain
 * of three or more from a fan point whose triangle on the closing edge
 * l -> i is valid too (x in rev_ok of the link, root_ok for the root). */
static void close_face(const dp *d, long i, long l, long first, long chord, slot out)
{
    pick p = {none, -1, BY_TRIANGLE, -1};
    uint64_t closing = d->fans_now ? (chord >= 0 ? d->rev_ok[chord] : d->root_ok) & d->fans_now : 0;
    for (long s = first; s < d->start[l + 1]; s++) {
        long a = d->left[s];
        val gl = d->g[s];
        const chains *pc = &d->plain[a];
        if (exists(pc->one) && could_win(pc->one.cost + gl.cost - 1, qmin(pc->one.q, gl.q), p.value))
            offer((val){pc->one.cost + gl.cost - 1, qmin(qmin(pc->one.q, gl.q), triangle_quality(d, i, a, l))},
                  BY_TRIANGLE, (int32_t)a, -1, &p);
        if (exists(pc->more))
            offer((val){pc->more.cost + gl.cost - 1, qmin(pc->more.q, gl.q)}, BY_FACE, (int32_t)a, -1, &p);
        for (uint64_t b = closing ? closing & d->fwd_ok[s] & d->fan_more[a] : 0; b; b &= b - 1) {
            size_t x = (size_t)cm_lowest_bit(b);
            const chains *fc = fanned(d, x, a);
            long cost = fc->more.cost + gl.cost + 1;
            double q = qmin(fc->more.q, gl.q); /* the fan triangles' qualities only lower it */
            if (!could_win(cost, q, p.value)) continue;
            double closing_q = chord >= 0 ? fan_q(d, x, chord, l, i) : d->root_fan[x]; /* on l -> i */
            offer((val){cost, qmin(q, qmin(fan_q(d, x, s, a, l), closing_q))}, BY_FAN, (int32_t)a, (int16_t)x, &p);
        }
    }
    *out.value = p.value, *out.arg = p.arg, *out.by = p.by, *out.fan_of = p.fan_of;
    if (out.cost) *out.cost = p.value.cost;
}

/* The chains into l are done: what extending them starts from. */
static inline void finish(chains *c)
{
    c->best = best_of(c->one, c->more);
    c->best_more = !better(c->one, c->more);
}

/* A fan chain of row i serves only a fan face closed by a link (i, j)
 * (the root for row 0) whose closing triangle from its fan point is valid,
 * and only up to the vertex before j: the row's fan points are cut to those
 * of its closing links, and its fan chains end before the last of them.
 * A link whose G costs 0 closes none (its triangulation stays). G of a
 * link held now (the memo's while the row is solved) bounds the cost of
 * the face that wins on it (the values only get better with fan points),
 * and a fan face costs one more than its chain: a chain costing the most
 * of those G or more is not read, nor extended (costs only grow). The
 * chains read stay the same. Returns that last vertex. */
static long closers(dp *d, long i)
{
    uint64_t fans = d->fans_now, used = 0;
    long last = i, bound = 0;
    for (long o = d->out_start[i]; fans && o < d->out_start[i + 1]; o++) {
        long t = d->out_link[o];
        uint64_t c = d->g[t].cost ? d->rev_ok[t] & fans : 0;
        if (c) used |= c, last = d->out_to[o], bound = d->g[t].cost > bound ? d->g[t].cost : bound;
    }
    if (i == 0 && (d->root_ok & fans)) used |= d->root_ok & fans, last = d->m - 1, bound = FAR;
    d->fans_now = used, d->fan_bound = bound;
    return last - 1;
}

/* A row's fan chains start empty; each vertex's, once done, extends those
 * of the vertices after it within the row's reach over its links: into
 * each l they arrive by ascending vertex, the order the plain ones are
 * read in. fan_in[l]: the fan points whose chains of two or more links
 * into l have had a candidate (the others' entries are stale). */
static void start_fans(dp *d, long i, long last)
{
    long reach = closers(d, i);
    d->row_last = last < reach ? last : reach;
    for (long l = i + 1; l <= d->row_last; l++) d->fan_in[l] = 0;
}

/* The fan chains from row i into l = lo..hi, as extend_range says. */
static void extend_fans(dp *d, long i, long lo, long hi, const long *first)
{
    const val *g = d->g;
    const uint64_t *fwd_ok = d->fwd_ok, *facing = d->facing;
    uint64_t *fan_in = d->fan_in;
    for (long l = lo; l <= hi && l <= d->row_last; l++) {
        long f = first[l], s = exists(d->plain[l].one) ? f : -1;
        uint64_t fans = d->fans_now & facing[l];
        uint64_t in = fan_in[l] & fans, ones = s >= 0 ? fwd_ok[s] & fans : 0;
        if (!(in | ones)) { /* no fan chain into l: none goes on from it */
            d->fan_best[l] = d->fan_more[l] = 0;
            continue;
        }
        uint64_t best = 0, more = 0;
        for (uint64_t b = in | ones; b; b &= b - 1) { /* the other fan points have no chain into l */
            size_t x = (size_t)cm_lowest_bit(b);
            chains *fc = fanned(d, x, l);
            fc->one = has_fan(ones, x) ? (val){g[s].cost, qmin(g[s].q, fan_q(d, x, s, i, l))} : none;
            if (!has_fan(in, x)) fc->more = none, fc->arg = -1;
            finish(fc);
            best |= (uint64_t)(fc->best.cost < d->fan_bound) << x;
            more |= (uint64_t)(fc->more.cost < d->fan_bound) << x;
        }
        d->fan_best[l] = best, d->fan_more[l] = more;
        for (long o = d->out_start[l]; best && o < d->out_start[l + 1] && d->out_to[o] <= d->row_last; o++) {
            long t = d->out_link[o], e = d->out_to[o];
            for (uint64_t b = best & fwd_ok[t] & facing[e]; b; b &= b - 1) {
                size_t x = (size_t)cm_lowest_bit(b);
                chains *fc = fanned(d, x, e);
                const chains *from = fanned(d, x, l);
                long cost = from->best.cost + g[t].cost;
                double q = qmin(from->best.q, g[t].q); /* the fan triangle's quality only lowers it */
                if (!has_fan(fan_in[e], x)) {
                    fc->more = none, fc->arg = -1; /* its first candidate */
                    fan_in[e] |= (uint64_t)1 << x;
                } else if (!could_win(cost, q, fc->more)) {
                    continue;
                }
                val v = {cost, qmin(q, fan_q(d, x, t, l, e))};
                if (better(v, fc->more)) fc->more = v, fc->arg = (int32_t)l, fc->from_more = from->best_more;
            }
        }
    }
}

/* The chains from row i into l = lo..hi, once every link into them is
 * solved: first[l] is the link (i, l) if there is one, else the first link
 * into l from beyond i; plain[l].one is set (none where (i, l) is not a
 * link: it tells which). A plain chain counts each link once (it adds a
 * face vertex); a fan chain only collects G, the fan face costs 1 in all.
 * The plain chains go first over the whole range (they read no fan
 * chain), in one call: the arrays stay in registers. */
static void extend_range(dp *d, long i, long lo, long hi, const long *first)
{
    chains *plain = d->plain;
    long *step_from = d->step_from;
    const val *g = d->g;
    const long *g_cost = d->g_cost;
    const int32_t *left = d->left;
    const long *start = d->start;
    for (long l = lo; l <= hi; l++) {
        long f = first[l], end = start[l + 1];
        chains *pc = &plain[l];
        /* every plain link extends the best chain into its left end by
         * one link, the running best kept in locals (the rows below l are
         * not l: nothing they hold changes here) */
        val mv = {FAR - 1, 0.0}; /* none: every candidate costs less, but
                                    those from a missing chain (FAR or more) */
        int32_t arg = -1;
        int from_more = 0;
        for (long t = exists(pc->one) ? f + 1 : f; t < end; t++) {
            int32_t a = left[t];
            long cost = step_from[a] + g_cost[t]; /* G of a solved link exists */
            if (cost > mv.cost) continue;
            const chains *prev = &plain[a];
            val v = {cost, qmin(prev->best.q, g[t].q)};
            if (better(v, mv)) mv = v, arg = a, from_more = prev->best_more;
        }
        pc->more = arg >= 0 ? mv : none, pc->arg = arg;
        if (arg >= 0) pc->from_more = from_more;
        finish(pc);
        step_from[l] = exists(pc->best) ? pc->best.cost + 1 : FAR;
    }
    /* beyond the row's fan chains' reach fan_best and fan_more stay 0, or
     * are not read */
    if (d->nfans) extend_fans(d, i, lo, hi, first);
}

/* Rows from the last up. first[l]: the first link into l from beyond the
 * row (a link from the row into l, if any, just before it). With a memo
 * (a run without fan points over the same links), a row other than the
 * root's whose sub-polygons hold no fan point keeps its values: G of such
 * a link admits no fan face, and every link inside it is such a link.
 * A row's chains are extended only as far as a link of the row needs
 * them: close_triangle is tried first where they are behind, and one[]
 * is kept for every l. */
static void solve(dp *d, long *first, int memo)
{
    long m = d->m;
    /* one[] holds none but where a row sets it for its links (close_* and
     * the chains' range read it): those are cleared after the row */
    for (long l = 0; l < m; l++) first[l] = d->start[l + 1], d->plain[l].one = none;
    for (long i = m - 2; i >= 0; i--) {
        long last = d->reach[i], done = i;
        if (memo && i > 0 && (!d->nfans || !d->row_fans[i])) { /* kept: only first[] moves, over the row's links */
            for (long o = d->out_start[i]; o < d->out_start[i + 1]; o++) first[d->out_to[o]] = d->out_link[o];
            continue;
        }
        d->fans_now = d->nfans ? d->row_fans[i] & d->facing[i] : 0;
        if (d->nfans) start_fans(d, i, last);
        /* the row's links by right end (first[l] is just past each), then
         * for row 0 the root, closed by the edge (m - 1, 0) */
        for (long o = d->out_start[i]; o <= d->out_start[i + 1]; o++) {
            int root = o == d->out_start[i + 1];
            if (root && i > 0) break;
            long s = root ? -1 : d->out_link[o], l = root ? m - 1 : d->out_to[o], f = first[l];
            if (l > i + 1) {
                slot out = s >= 0 ? (slot){&d->g[s], &d->g_cost[s], &d->arg[s], &d->by[s], &d->fan_of[s]}
                                  : (slot){&d->root, NULL, &d->root_arg, &d->root_by, &d->root_fan_of};
                if (memo && s >= 0 && d->g[s].cost == 0) {
                    /* the memo's G: a decomposition of cost 0 has no fan
                     * face, so both runs find the same of cost 0 */
                } else if ((memo && s >= 0) || done + 1 == l || !close_triangle(d, i, l, f, out)) {
                    /* with a memo, a link here has no triangulation (the
                     * memo would have found it): no triangle of cost 0 */
                    if (done + 1 < l) extend_range(d, i, done + 1, l - 1, first), done = l - 1;
                    close_face(d, i, l, f, s, out);
                }
            }
            if (root) break;
            d->plain[l].one = (val){d->g[s].cost + 1, d->g[s].q};
            first[l] = s;
        }
        for (long o = d->out_start[i]; o < d->out_start[i + 1]; o++) d->plain[d->out_to[o]].one = none;
    }
}

/* Does the ray from x towards +x cross the segment p q? Half-open in y
 * with the exact orientation: the parity of the crossings with a closed
 * polyline is exact for every x off it. */
static int ray_crosses(const dp *d, const double *p, const double *q, const double *x)
{
    if ((p[1] > x[1]) == (q[1] > x[1])) return 0;
    int o = orient(d, p, q, x);
    return q[1] > p[1] ? o > 0 : o < 0;
}

/* The fan points inside the sub-polygon a, a+1, ..., b closed by the link
 * (a, b), in geometry 0, of those in which; parity[v]: the fan points
 * whose rays cross an odd number of the edges before v. Exact for points
 * off its boundary; a point on it is strictly inside none of its faces, nor strictly on one
 * side of a link through it, so either answer serves. */
static uint64_t fans_inside(const dp *d, const uint64_t *parity, long a, long b, uint64_t which)
{
    uint64_t in = parity[a] ^ parity[b];
    const double *pa = d->xy[0] + 2 * a, *pb = d->xy[0] + 2 * b;
    for (uint64_t w = which; w; w &= w - 1) {
        int x = cm_lowest_bit(w);
        in ^= (uint64_t)ray_crosses(d, pb, pa, d->fans + 2 * (size_t)x * d->k) << x;
    }
    return in & which;
}

/* The first set vertex of a view whose vertices are consecutive in its
 * set (map NULL, or map[i] = map[0] + i), else -1: its rows are read by
 * words. */
static long consecutive_base(const cm_diagview *v, long m)
{
    if (!v->map) return 0;
    for (long i = 1; i < m; i++)
        if (v->map[i] != v->map[0] + i) return -1;
    return v->map[0];
}

/* The links, by their right ends, and each row's reach. */
static int build_links(dp *d)
{
    long m = d->m, count = 0, base = consecutive_base(d->common, m);
    size_t cap = 0;
    if (d->work) d->left = d->work->buf[W_LEFT], cap = d->work->bytes[W_LEFT] / sizeof *d->left;
    d->start = take(d->work, W_START, (size_t)m + 2, sizeof *d->start, 1);
    d->reach = take(d->work, W_REACH, (size_t)m, sizeof *d->reach, 0);
    if (!d->start || !d->reach || grow_left(d, &cap, 4 * (size_t)m) != 0) return -1;
    for (long i = 0; i < m; i++) d->reach[i] = i == 0 ? m - 1 : i + 1;
    for (long b = 0; b < m; b++) {
        d->start[b] = count;
        if (base >= 0 && b > 0) {
            /* the diagonals a < b - 1 (not 0 for the closing edge) from the
             * set's row of b, ascending, then the edge b - 1 */
            const cm_diagset *set = d->common->set;
            const uint64_t *row = set->bits + (size_t)(base + b) * set->stride;
            long lo = base + (b == m - 1), hi = base + b - 1;
            for (long w = lo / 64; 64 * w < hi; w++) {
                uint64_t bits = row[w];
                if (64 * w < lo) bits &= ~(uint64_t)0 << (lo - 64 * w);
                if (64 * w + 64 > hi) bits &= ((uint64_t)1 << (hi - 64 * w)) - 1;
                if (grow_left(d, &cap, (size_t)count + 64 + 1) != 0) return -1;
                for (; bits; bits &= bits - 1) {
                    long a = 64 * w + cm_lowest_bit(bits) - base;
                    d->left[count++] = (int32_t)a;
                    if (a > 0) d->reach[a] = b; /* b ascends: the farthest last */
                }
            }
            if (grow_left(d, &cap, (size_t)count + 1) != 0) return -1;
            d->left[count++] = (int32_t)(b - 1);
            continue;
        }
        for (long a = 0; a < b; a++) {
            if (!is_link(d, a, b)) continue;
            if (grow_left(d, &cap, (size_t)count + 1) != 0) return -1;
            d->left[count++] = (int32_t)a;
            if (a > 0 && b > a + 1) d->reach[a] = b; /* b ascends: the farthest last */
        }
    }
    d->start[m] = d->start[m + 1] = count;
    d->nlinks = count;
    d->out_start = take(d->work, W_OUT_START, (size_t)m + 2, sizeof *d->out_start, 1);
    d->out_link = take(d->work, W_OUT_LINK, 2 * ((size_t)count + 1), sizeof *d->out_link, 0);
    if (!d->out_start || !d->out_link) return -1;
    d->out_to = d->out_link + count + 1;
    for (long t = 0; t < count; t++) d->out_start[d->left[t] + 2]++;
    for (long a = 0; a < m; a++) d->out_start[a + 2] += d->out_start[a + 1];
    for (long b = 0; b < m; b++) /* b ascends: each list by right ends */
        for (long t = d->start[b]; t < d->start[b + 1]; t++) {
            long o = d->out_start[d->left[t] + 1]++;
            d->out_link[o] = (int32_t)t, d->out_to[o] = (int32_t)b;
        }
    return 0;
}

/* Fresh values: G of an edge is an empty triangulation, of a diagonal
 * none yet. */
static int init_values(dp *d)
{
    size_t c = (size_t)d->nlinks + 1;
    d->g = take(d->work, W_G, c, sizeof *d->g, 0);
    d->g_cost = take(d->work, W_G_COST, c, sizeof *d->g_cost, 0);
    d->arg = take(d->work, W_ARG, c, sizeof *d->arg, 0);
    d->by = take(d->work, W_BY, c, 1, 0);
    d->fan_of = take(d->work, W_FAN_OF, c, sizeof *d->fan_of, 0);
    if (!d->g || !d->g_cost || !d->arg || !d->by || !d->fan_of) return -1;
    for (long b = 0; b < d->m; b++)
        for (long s = d->start[b]; s < d->start[b + 1]; s++) {
            d->g[s] = b == d->left[s] + 1 ? (val){0, NO_TRIANGLE} : none;
            d->g_cost[s] = d->g[s].cost;
            d->arg[s] = -1, d->by[s] = BY_TRIANGLE, d->fan_of[s] = -1;
        }
    return 0;
}

/* The fan triangles of every link and of the root, and each row's fan
 * points. */
static int build_fans(dp *d)
{
    long m = d->m;
    size_t c = (size_t)d->nlinks + 1, f = d->nfans ? d->nfans : 1;
    /* three blocks (many small programs run): per vertex, per link, the
     * qualities */
    d->row_fans = calloc(6 * (size_t)m, sizeof *d->row_fans);
    d->fwd_ok = malloc(2 * c * sizeof *d->fwd_ok); /* each link's set below */
    d->fan_q = malloc((f * c + f) * sizeof *d->fan_q);
    if (!d->row_fans || !d->fwd_ok || !d->fan_q) return -1;
    d->fan_best = d->row_fans + m, d->fan_more = d->row_fans + 2 * m, d->facing = d->row_fans + 3 * m;
    d->rev_ok = d->fwd_ok + c, d->root_fan = d->fan_q + f * c;
    d->fwd_ok[c - 1] = d->rev_ok[c - 1] = 0; /* past the links */
    uint64_t *parity = d->row_fans + 4 * m;
    d->fan_in = d->row_fans + 5 * m;
    /* the fan tests' differences, while they fit a modest block (else
     * the filter makes its own), where the filter may be inline (see
     * CM_ORIENT2D_INLINE) */
#ifdef CM_ORIENT2D_INLINE
    if (d->tame && d->nfans * d->k * (size_t)m <= ((size_t)1 << 20) &&
        (d->fan_diff = malloc(2 * d->nfans * d->k * (size_t)m * sizeof *d->fan_diff)))
        for (size_t x = 0; x < d->nfans; x++)
            for (size_t g = 0; g < d->k; g++) {
                const double *px = d->fans + 2 * (x * d->k + g);
                double *diff = d->fan_diff + 2 * (x * d->k + g) * (size_t)m;
                for (long v = 0; v < m; v++)
                    diff[2 * v] = d->xy[g][2 * v] - px[0], diff[2 * v + 1] = d->xy[g][2 * v + 1] - px[1];
            }
#endif
    for (size_t x = 0; x < d->nfans; x++) {
        const double *f0 = d->fans + 2 * x * d->k;
        uint64_t odd = 0;
        for (long v = 0; v + 1 < m; v++) {
            odd ^= (uint64_t)ray_crosses(d, d->xy[0] + 2 * v, d->xy[0] + 2 * v + 2, f0);
            parity[v + 1] |= odd << x;
        }
    }
    if (d->nfans) d->row_fans[0] = d->nfans == 64 ? ~(uint64_t)0 : ((uint64_t)1 << d->nfans) - 1;
    for (long v = 0; d->nfans && v < m; v++) {
        d->facing[v] = d->row_fans[0];
        for (size_t g = 0; g < d->k; g++) {
            const double *p = d->xy[g] + 2 * cm_cycle_prev(v, m), *q = d->xy[g] + 2 * v;
            const double *r = d->xy[g] + 2 * cm_cycle_next(v, m);
            if (orient(d, p, q, r) <= 0) continue;
            for (size_t x = 0; x < d->nfans; x++) {
                const double *fx = d->fans + 2 * (x * d->k + g);
                if (orient(d, p, q, fx) <= 0 || orient(d, q, r, fx) <= 0) d->facing[v] &= ~((uint64_t)1 << x);
            }
        }
    }
    for (long i = 1; i < m; i++)
        if (d->nfans && d->reach[i] > i + 1) d->row_fans[i] = fans_inside(d, parity, i, d->reach[i], d->row_fans[0]);
    for (long b = 0; b < m; b++)
        for (long s = d->start[b]; s < d->start[b + 1]; s++) {
            long a = d->left[s];
            uint64_t ends = d->facing[a] & d->facing[b], in = fans_inside(d, parity, a, b, ends);
            d->fwd_ok[s] = d->rev_ok[s] = 0;
            for (uint64_t w = ends; w; w &= w - 1) {
                size_t x = (size_t)cm_lowest_bit(w);
                int inside = has_fan(in, x);
                int ok = inside ? b != a + 1 && fan_valid(d, x, b, a) : fan_valid(d, x, a, b);
                d->fan_q[x * (size_t)d->nlinks + (size_t)s] = Q_UNKNOWN;
                if (ok) *(inside ? &d->rev_ok[s] : &d->fwd_ok[s]) |= (uint64_t)1 << x;
            }
        }
    d->root_ok = 0;
    for (size_t x = 0; x < d->nfans; x++) {
        d->root_fan[x] = fan_min_angle(d, x, m - 1, 0);
        if (d->root_fan[x] >= 0) d->root_ok |= (uint64_t)1 << x;
    }
    return 0;
}

/* ---- reading the plan back ------------------------------------------------ */

typedef struct { long a, b; } link;

/* The stack holds at most the plan's m - 2 diagonals and the closing
 * edge (each pushed once). */
static void push_link(link *stack, long *top, long a, long b)
{
    if (b > a + 1) stack[(*top)++] = (link){a, b};
}

static void plan_add_triangle(cm_sf_plan *p, long a, long b, long c)
{
    p->tri[3 * p->nt] = (int32_t)a, p->tri[3 * p->nt + 1] = (int32_t)b, p->tri[3 * p->nt + 2] = (int32_t)c;
    p->nt++;
}

/* The face on link (i, j) whose chain ends with link (a, j): its vertices
 * go to the plan, its links to the stack. first: m longs of scratch. */
static void add_face(dp *d, cm_sf_plan *p, long i, long a, long j, int fan, link *stack, long *top, long *first)
{
    d->fans_now = d->nfans ? d->row_fans[i] & d->facing[i] : 0;
    if (d->nfans) start_fans(d, i, fan >= 0 ? a : i); /* a fan face reads its fan point's chains alone */
    for (long l = i + 1; l <= a; l++) {
        long s = find_link(d, i, l);
        first[l] = s >= 0 ? s : first_after(d, l, i);
        d->plain[l].one = s >= 0 ? (val){d->g[s].cost + 1, d->g[s].q} : none;
    }
    extend_range(d, i, i + 1, a, first);
    const chains *row = fan >= 0 ? fanned(d, (size_t)fan, 0) : d->plain;
    long count = 0, v = a;
    int32_t *f = p->face + p->face_start[p->nf];
    f[count++] = (int32_t)j;
    f[count++] = (int32_t)a;
    for (int more = 1; more;) {
        long prev = row[v].arg;
        more = row[v].from_more;
        f[count++] = (int32_t)prev;
        v = prev;
    }
    if (f[count - 1] != i) f[count++] = (int32_t)i;
    for (long x = 0, y = count - 1; x < y; x++, y--) {
        int32_t t = f[x];
        f[x] = f[y], f[y] = t;
    }
    p->face_fan[p->nf] = fan;
    p->face_start[p->nf + 1] = p->face_start[p->nf] + count;
    p->nf++;
    for (long x = 0; x + 1 < count; x++) push_link(stack, top, f[x], f[x + 1]);
}

static int read_plan(dp *d, cm_sf_plan *p, long *first)
{
    long m = d->m;
    p->tri = take(d->work, W_TRI, 3 * (size_t)m, sizeof *p->tri, 0);
    p->face = take(d->work, W_FACE, 3 * (size_t)m, sizeof *p->face, 0);
    p->face_start = take(d->work, W_FACE_START, (size_t)m + 1, sizeof *p->face_start, 1);
    p->face_fan = take(d->work, W_FACE_FAN, (size_t)m, sizeof *p->face_fan, 0);
    link *stack = take(d->work, W_STACK, (size_t)m, sizeof *stack, 0);
    long top = 0;
    if (!p->tri || !p->face || !p->face_start || !p->face_fan || !stack) {
        if (!d->work) free(stack);
        return -1;
    }
    push_link(stack, &top, 0, m - 1);
    while (top > 0) {
        link l = stack[--top];
        int32_t a;
        unsigned char by;
        int fan;
        if (l.a == 0 && l.b == m - 1) {
            a = d->root_arg, by = d->root_by, fan = d->root_fan_of;
        } else {
            long s = find_link(d, l.a, l.b);
            a = d->arg[s], by = d->by[s], fan = d->fan_of[s];
        }
        if (by == BY_TRIANGLE) {
            plan_add_triangle(p, l.a, a, l.b);
            push_link(stack, &top, l.a, a), push_link(stack, &top, a, l.b);
        } else {
            add_face(d, p, l.a, a, l.b, by == BY_FAN ? fan : -1, stack, &top, first);
        }
    }
    if (!d->work) free(stack);
    return 0;
}

void cm_sf_plan_clear(cm_sf_plan *plan)
{
    free(plan->tri), free(plan->face), free(plan->face_start), free(plan->face_fan);
    memset(plan, 0, sizeof *plan);
}

long cm_steinerfree_count_to(long m, const cm_diagview *common, long limit)
{
    long count = 0;
    cm_diagrows rows;
    int32_t *row = m >= CM_DIAGROWS_FROM ? malloc((size_t)m * sizeof *row) : NULL;
    if (row && cm_diagrows_open(&rows, common, m) == 0) {
        for (long a = 0; a < m && count < limit; a++) {
            long c = cm_diagrows_row(&rows, a, row);
            for (long t = 0; t < c; t++)
                count += row[t] >= a + 2 && !(a == 0 && row[t] == m - 1);
        }
        cm_diagrows_close(&rows);
        free(row);
        return count < limit ? count : limit;
    }
    free(row); /* out of memory: pair by pair */
    for (long a = 0; a < m && count < limit; a++)
        for (long b = a + 2; b < m; b++)
            if (!(a == 0 && b == m - 1)) count += cm_diagview_has(common, a, b);
    return count < limit ? count : limit;
}

long cm_steinerfree_count(long m, const cm_diagview *common)
{
    return cm_steinerfree_count_to(m, common, LONG_MAX);
}

struct cm_sf_memo {
    dp d; /* the run's links and values */
};

/* Everything but the links (start, left, reach), which a memo may share;
 * the values stay in a workspace. */
static void free_run(dp *d)
{
    free(d->fwd_ok), free(d->fan_q), free(d->plain), free(d->step_from), free(d->fanned), free(d->row_fans);
    free(d->fan_diff);
    if (!d->work) free(d->g), free(d->g_cost), free(d->arg), free(d->by), free(d->fan_of);
}

static void free_links(dp *d)
{
    if (d->work) return; /* the workspace's */
    free(d->start), free(d->left), free(d->reach), free(d->out_start), free(d->out_link);
}

/* One run over the links of *d (set up, values fresh or the memo's):
 * the plan. 0 or -1. */
static int run(dp *d, int memo, cm_sf_plan *plan)
{
    long m = d->m;
    d->root = none, d->root_arg = -1, d->root_by = BY_TRIANGLE, d->root_fan_of = -1;
    /* the row's arrays fresh from malloc even with a workspace: the
     * compiler then knows they alias nothing (the loops below read the
     * links' arrays while writing these) */
    d->plain = malloc((size_t)m * sizeof *d->plain);
    d->step_from = malloc((size_t)m * sizeof *d->step_from);
    d->fanned = d->nfans ? malloc((size_t)m * d->nfans * sizeof *d->fanned) : NULL;
    long *first = malloc((size_t)m * sizeof *first);
    int status = -1;
    /* without fan points no fan array is read (fans_now stays 0): the
     * many small programs of the link cuts skip them */
    if (d->plain && d->step_from && first && (!d->nfans || (d->fanned && build_fans(d) == 0))) {
        solve(d, first, memo);
        plan->cost = d->root.cost;
        double q = qmin(d->root.q, 1.0);
        plan->min_angle_deg = d->root.q >= NO_TRIANGLE ? 180.0 : asin(sqrt(q)) * 180.0 / 3.14159265358979323846;
        status = read_plan(d, plan, first); /* first[] done with: add_face's scratch */
    }
    free(first);
    if (d->work) {
        if (status != 0) memset(plan, 0, sizeof *plan);
        return status;
    }
    if (status != 0) cm_sf_plan_clear(plan);
    return status;
}

static void setup(dp *d, long m, const cm_diagview *common, const double *const *xy, size_t k)
{
    memset(d, 0, sizeof *d);
    d->m = m, d->common = common, d->xy = xy, d->k = k;
}

/* Sets the fan points and whether every point is tame (read by the fan
 * tests alone: not looked at without fan points). */
static void set_fans(dp *d, const double *fans, size_t nfans)
{
    d->fans = fans, d->nfans = fans ? nfans : 0;
    d->tame = d->nfans && cm_coords_tame(d->fans, 2 * (long)(d->nfans * d->k));
    for (size_t g = 0; g < d->k && d->tame; g++) d->tame = cm_coords_tame(d->xy[g], 2 * d->m);
}

int cm_steinerfree_plan(long m, const cm_diagview *common, const double *const *xy, size_t k,
                        const double *fans, size_t nfans, cm_sf_plan *plan)
{
    memset(plan, 0, sizeof *plan);
    if (fans && nfans > CM_SF_MAX_FANS) return -1;
    dp d;
    setup(&d, m, common, xy, k);
    set_fans(&d, fans, nfans);
    int status = build_links(&d) == 0 && init_values(&d) == 0 ? run(&d, 0, plan) : -1;
    free_run(&d), free_links(&d);
    return status;
}

cm_sf_work *cm_sf_work_new(void)
{
    return calloc(1, sizeof(cm_sf_work));
}

void cm_sf_work_free(cm_sf_work *work)
{
    if (!work) return;
    for (int s = 0; s < W_SLOTS; s++) free(work->buf[s]);
    free(work);
}

int cm_steinerfree_plan_in(cm_sf_work *work, long m, const cm_diagview *common, const double *const *xy, size_t k,
                           cm_sf_plan *plan)
{
    memset(plan, 0, sizeof *plan);
    dp d;
    setup(&d, m, common, xy, k);
    set_fans(&d, NULL, 0);
    d.work = work;
    int status = build_links(&d) == 0 && init_values(&d) == 0 ? run(&d, 0, plan) : -1;
    free_run(&d);
    return status;
}

int cm_steinerfree_plan_memo(long m, const cm_diagview *common, const double *const *xy, size_t k,
                             cm_sf_plan *plan, cm_sf_memo **memo)
{
    memset(plan, 0, sizeof *plan);
    *memo = calloc(1, sizeof **memo);
    if (!*memo) return -1;
    dp *d = &(*memo)->d;
    setup(d, m, common, xy, k);
    int status = build_links(d) == 0 && init_values(d) == 0 ? run(d, 0, plan) : -1;
    if (status != 0) {
        cm_sf_memo_free(*memo);
        *memo = NULL;
    }
    return status;
}

int cm_steinerfree_plan_fans(const cm_sf_memo *memo, const double *fans, size_t nfans, cm_sf_plan *plan)
{
    memset(plan, 0, sizeof *plan);
    if (nfans > CM_SF_MAX_FANS) return -1;
    const dp *first = &memo->d;
    size_t c = (size_t)first->nlinks + 1;
    dp d;
    setup(&d, first->m, first->common, first->xy, first->k);
    set_fans(&d, fans, nfans);
    d.start = first->start, d.left = first->left, d.reach = first->reach, d.nlinks = first->nlinks;
    d.out_start = first->out_start, d.out_link = first->out_link, d.out_to = first->out_to;
    d.g = malloc(c * sizeof *d.g);
    d.g_cost = malloc(c * sizeof *d.g_cost);
    d.arg = malloc(c * sizeof *d.arg);
    d.by = malloc(c);
    d.fan_of = malloc(c * sizeof *d.fan_of);
    int status = -1;
    if (d.g && d.g_cost && d.arg && d.by && d.fan_of) {
        memcpy(d.g, first->g, c * sizeof *d.g);
        memcpy(d.g_cost, first->g_cost, c * sizeof *d.g_cost);
        memcpy(d.arg, first->arg, c * sizeof *d.arg);
        memcpy(d.by, first->by, c);
        memcpy(d.fan_of, first->fan_of, c * sizeof *d.fan_of);
        status = run(&d, 1, plan);
    }
    free_run(&d); /* the links are the memo's */
    return status;
}

void cm_sf_memo_free(cm_sf_memo *memo)
{
    if (!memo) return;
    free_run(&memo->d), free_links(&memo->d);
    free(memo);
}
