/* The window partition from a vertex, link distances and minimum-link
 * paths; see linkpath.h.
 *
 * A pocket is a sub-polygon (pool ids, counter-clockwise) with its source:
 * the root pocket is the polygon with the source vertex, every other pocket
 * is cut off by a window, its closing edge ids[k-1] -> ids[0]. One end of a
 * window is its pivot (a reflex vertex lit one level earlier), the other a
 * constructed point on an edge or a vertex the window runs into. */
#include "geom/linkpath.h"

#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/cycle.h"
#include "geom/angle.h"
#include "geom/predicates.h"
#include "geom/visibility.h"
#include "geom/xpoint.h"

/* How a vertex is reached: lit through its pocket's window (the previous
 * bend lies beyond that window, in the parent pocket), or from a lit point
 * right next to it in pocket `via` (it lies on the boundary of that lit
 * region without being visible). */
enum { HOW_NONE, HOW_CONE, HOW_NEAR };

typedef struct pocket {
    long *ids, k;
    int level;
    long parent;
    long source; /* local index of the point source (root), -1 for a window */
    int built, shared; /* shared: vs is the linkpart's root triangulation */
    cm_vsource vs;
    /* Where the window runs in the parent (its local indices): ids are the
     * parent's from `first` on (cyclic), with the constructed end point
     * first (hpos 0), last (hpos 1) or none (-1); the window runs from the
     * pivot to the vertex `end`, or to the point on the edge from `end`. */
    long first, pivot, end;
    int hpos;
} pocket;

struct cm_linkpart {
    long m;
    double *xy;
    cm_xpool *pool;           /* ids 0..m-1: the polygon's vertices */
    long *support, nsupport;  /* per constructed point (id - m): the polygon
                                 edge (its start vertex) holding it */
    pocket *pk;
    long npk, cap_pk;
    int *dist;
    long *via, *cone_a, *cone_b;
    unsigned char *how, *covered;
    long source; /* of the partition built last, -1 none */
    int max_level; /* pockets beyond this level were not processed */
    int limit;     /* of the run under way: deeper pockets are not made */
    int truncated; /* some were: vertices in them are undetermined */
    long *all;   /* 0..m-1: the root pocket's ids */
    cm_vsource root; /* the polygon's triangulation, re-rooted per source */
    int root_state;  /* 0 not built, 1 built, -1 failed */
    cm_visrows *rows;   /* visibility from a vertex over that triangulation */
    unsigned char *row; /* from the current source */
    int *seen;          /* per vertex: in how many pockets of one level */
    cm_xinputs in;      /* the polygon's vertices (pool ids 0..m-1): xy */
    int derive;         /* derive pockets' triangulations from their parents' */
    long derived, clipped; /* pocket vertices triangulated either way */
    /* scratch of a derivation, per parent triangle */
    unsigned *stamp, gen;
    int32_t *queue, *cut_r, *cut_l;
    long cap_scratch;
};

/* cm_xorient, the polygon's vertices read from lp->xy */
static int orient(const cm_linkpart *lp, long a, long b, long c)
{
    return cm_xorient_in(&lp->in, lp->pool, a, b, c);
}

/* ---- set-up ------------------------------------------------------------- */

cm_linkpart *cm_linkpart_create(const double *xy, long m)
{
    cm_linkpart *lp = calloc(1, sizeof *lp);
    if (!lp) return NULL;
    lp->m = m, lp->source = -1, lp->derive = 1;
    size_t n = (size_t)m;
    lp->xy = malloc(2 * n * sizeof *lp->xy);
    lp->pool = cm_xpool_create();
    lp->dist = malloc(n * sizeof *lp->dist);
    lp->via = malloc(n * sizeof *lp->via);
    lp->cone_a = malloc(n * sizeof *lp->cone_a);
    lp->cone_b = malloc(n * sizeof *lp->cone_b);
    lp->how = malloc(n);
    lp->covered = malloc(n + 1);
    lp->all = malloc(n * sizeof *lp->all);
    lp->row = malloc(n);
    lp->seen = malloc(n * sizeof *lp->seen);
    int ok = lp->row && lp->seen && lp->xy && lp->pool && lp->dist && lp->via && lp->cone_a && lp->cone_b && lp->how &&
             lp->covered && lp->all;
    for (long i = 0; ok && i < m; i++) {
        lp->xy[2 * i] = xy[2 * i], lp->xy[2 * i + 1] = xy[2 * i + 1];
        ok = cm_xpool_add(lp->pool, xy[2 * i], xy[2 * i + 1]) == i;
        lp->all[i] = i;
    }
    if (!ok) {
        cm_linkpart_free(lp);
        return NULL;
    }
    lp->in = (cm_xinputs){lp->xy, m, cm_coords_tame(lp->xy, 2 * m)};
    return lp;
}

void cm_linkpart_set_derive(cm_linkpart *lp, int on) { lp->derive = on != 0; }

void cm_linkpart_counts(const cm_linkpart *lp, long *derived, long *clipped)
{
    *derived = lp->derived, *clipped = lp->clipped;
}

static void drop_pockets(cm_linkpart *lp)
{
    for (long i = 0; i < lp->npk; i++) {
        if (!lp->pk[i].shared) cm_vsource_clear(&lp->pk[i].vs);
        if (lp->pk[i].ids != lp->all) free(lp->pk[i].ids);
    }
    lp->npk = 0;
    lp->nsupport = 0;
    if (lp->pool) cm_xpool_truncate(lp->pool, lp->m);
    lp->source = -1;
}

void cm_linkpart_free(cm_linkpart *lp)
{
    if (!lp) return;
    drop_pockets(lp);
    free(lp->pk), free(lp->support), free(lp->xy), free(lp->dist), free(lp->via);
    free(lp->cone_a), free(lp->cone_b), free(lp->how), free(lp->covered), free(lp->all);
    cm_vsource_clear(&lp->root);
    cm_visrows_free(lp->rows);
    free(lp->row), free(lp->seen);
    free(lp->stamp), free(lp->queue), free(lp->cut_r), free(lp->cut_l);
    cm_xpool_free(lp->pool);
    free(lp);
}

/* Takes ownership of ids (freed here on failure). Returns the index or -1. */
static long add_pocket(cm_linkpart *lp, long *ids, long k, int level, long parent, long source)
{
    if (lp->npk == lp->cap_pk) {
        long cap = lp->cap_pk ? 2 * lp->cap_pk : 16;
        pocket *p = realloc(lp->pk, (size_t)cap * sizeof *p);
        if (!p) {
            if (ids != lp->all) free(ids);
            return -1;
        }
        lp->pk = p, lp->cap_pk = cap;
    }
    pocket *p = &lp->pk[lp->npk];
    memset(p, 0, sizeof *p);
    p->ids = ids, p->k = k, p->level = level, p->parent = parent, p->source = source;
    return lp->npk++;
}

/* The constructed point on polygon edge e -> e+1 where line(a, b) meets it. */
static long add_hit_point(cm_linkpart *lp, long a, long b, long e)
{
    long id = cm_xpool_intersect(lp->pool, a, b, e, cm_cycle_next(e, lp->m));
    if (id < 0) return id;
    long slot = id - lp->m;
    if (slot >= lp->nsupport) {
        long *s = realloc(lp->support, (size_t)(slot + 64) * sizeof *s);
        if (!s) return -1;
        lp->support = s;
        lp->nsupport = slot + 64;
    }
    lp->support[slot] = e;
    return id;
}

/* The polygon edge (its start vertex) holding the pocket edge ids[r] -> ids[l]. */
static long polygon_edge(const cm_linkpart *lp, long r_id, long l_id)
{
    if (r_id >= lp->m) return lp->support[r_id - lp->m];
    if (l_id >= lp->m) return lp->support[l_id - lp->m];
    return r_id;
}

/* ---- tracing a window ---------------------------------------------------- */

typedef struct tracer {
    cm_linkpart *lp;
    long P;          /* pocket index */
    int side;        /* +1: shadow left of the ray, -1: right */
    long start;      /* local index where the current window starts */
    long la, lb;     /* pool ids on the ray's line, forward beyond lb */
    long cur;        /* local vertex the ray leaves from */
} tracer;

static pocket *tr_pocket(const tracer *tr) { return &tr->lp->pk[tr->P]; }

/* x (on line(a, b)) lies strictly past `from` (a point of that line) in
 * the direction from a to b. */
static int past(cm_xpool *pool, long a, long b, long from, long x)
{
    const double *pa = cm_xpool_xy(pool, a), *pb = cm_xpool_xy(pool, b);
    int axis = fabs(pb[0] - pa[0]) >= fabs(pb[1] - pa[1]) ? 0 : 1;
    int dir = cm_xcompare(pool, b, a, axis);
    if (dir == 0) axis = 1 - axis, dir = cm_xcompare(pool, b, a, axis);
    return dir != 0 && cm_xcompare(pool, x, from, axis) == dir;
}

/* x (on the line) lies beyond lb, in the ray's direction. */
static int beyond(cm_xpool *pool, long la, long lb, long x) { return past(pool, la, lb, lb, x); }

/* Appends local indices from..to (cyclic, inclusive) to list; 0 if the walk
 * would cross the pocket's window or its source. */
static int append_chain(const pocket *p, long from, long to, long *list, long *count)
{
    for (long i = from;; i = cm_cycle_next(i, p->k)) {
        if (p->source >= 0 && i == p->source) return 0;
        list[(*count)++] = i;
        if (i == to) return 1;
        if (p->source < 0 && i == p->k - 1) return 0;
        if (*count > p->k) return 0;
    }
}

/* Cuts off the pocket on the shadow side of the window from local vertex
 * tr->start to `end`: a local vertex (h < 0) or the point h on the pocket
 * edge from local `end` to end + 1. Beyond the run's last level only its
 * vertices are marked covered and the run truncated: such a pocket would
 * never be processed. Returns 0, -1 out of memory. */
static int emit_window(tracer *tr, long end, long h)
{
    cm_linkpart *lp = tr->lp;
    pocket *p = tr_pocket(tr);
    long *local = malloc((size_t)(p->k + 2) * sizeof *local), count = 0;
    if (!local) return -1;
    int ok;
    if (tr->side > 0)
        ok = append_chain(p, h >= 0 ? (end + 1) % p->k : end, tr->start, local, &count);
    else
        ok = append_chain(p, tr->start, end, local, &count);
    long k = count + (h >= 0);
    int level = p->level + 1;
    if (ok && k >= 3 && level > lp->limit) {
        for (long i = 0; i < count; i++)
            if (local[i] != tr->start) lp->covered[local[i]] = 1;
        free(local);
        lp->truncated = 1;
        return 0;
    }
    long *ids = ok && k >= 3 ? malloc((size_t)k * sizeof *ids) : NULL;
    if (ids) {
        long o = 0;
        if (h >= 0 && tr->side > 0) ids[o++] = h;
        for (long i = 0; i < count; i++) ids[o++] = p->ids[local[i]];
        if (h >= 0 && tr->side < 0) ids[o++] = h;
        for (long i = 0; i < count; i++)
            if (local[i] != tr->start) lp->covered[local[i]] = 1;
    }
    long first = count > 0 ? local[0] : 0;
    free(local);
    if (!ids) return ok && k >= 3 ? -1 : 0;
    long c = add_pocket(lp, ids, k, level, tr->P, -1);
    if (c < 0) return -1;
    pocket *child = &lp->pk[c];
    child->first = first, child->pivot = tr->start, child->end = end;
    child->hpos = h < 0 ? -1 : tr->side > 0 ? 0 : 1;
    return 0;
}

/* The fan triangle of tr->cur holding the ray: sets *t and the exit edge
 * (*r right, *l left, local indices), or *hit to a local vertex on the
 * ray. Returns 0 if found, 1 if no triangle holds the ray. */
static int leave_vertex(tracer *tr, long *t, long *r, long *l, long *hit)
{
    pocket *p = tr_pocket(tr);
    const cm_vsource *vs = &p->vs;
    cm_xpool *pool = tr->lp->pool;
    *hit = -1;
    for (long f = vs->fan_start[tr->cur]; f < vs->fan_start[tr->cur + 1]; f++) {
        long tt = vs->fan[f];
        int c = 0;
        while (vs->tri[3 * tt + c] != tr->cur) c++;
        long x = vs->tri[3 * tt + (c + 1) % 3], y = vs->tri[3 * tt + (c + 2) % 3];
        int ox = orient(tr->lp, tr->la, tr->lb, p->ids[x]);
        int oy = orient(tr->lp, tr->la, tr->lb, p->ids[y]);
        if (ox < 0 && oy > 0) {
            *t = tt, *r = x, *l = y;
            return 0;
        }
        if (ox == 0 && beyond(pool, tr->la, tr->lb, p->ids[x])) *hit = x;
        if (oy == 0 && beyond(pool, tr->la, tr->lb, p->ids[y])) *hit = y;
        if (*hit >= 0) return 0;
    }
    return 1;
}

/* Does the line from pool id `behind` through local vertex w go on
 * strictly into the pocket's interior past w? */
static int continues_past(const cm_linkpart *lp, long P, long w, long behind)
{
    const pocket *p = &lp->pk[P];
    long wp = p->ids[cm_cycle_prev(w, p->k)], wv = p->ids[w], wn = p->ids[cm_cycle_next(w, p->k)];
    int turn = orient(lp, wp, wv, wn);
    int in_left = orient(lp, wp, wv, behind) < 0, out_left = orient(lp, wv, wn, behind) < 0;
    if (turn > 0) return in_left && out_left;
    if (turn < 0) return in_left || out_left;
    return in_left;
}

/* The ray reached local vertex w: end the window there, or go on past it
 * (splitting the window when w's edges lie on the shadow side). Returns 1
 * to go on, 0 when done, -1 out of memory. */
static int pass_vertex(tracer *tr, long w)
{
    pocket *p = tr_pocket(tr);
    if (!continues_past(tr->lp, tr->P, w, tr->lb)) return emit_window(tr, w, -1);
    long wp = p->ids[cm_cycle_prev(w, p->k)];
    if (orient(tr->lp, tr->lb, p->ids[w], wp) == tr->side) {
        if (emit_window(tr, w, -1) < 0) return -1;
        tr->start = w;
    }
    p = tr_pocket(tr);
    tr->la = tr->lb, tr->lb = p->ids[w], tr->cur = w;
    return 1;
}

/* Traces the window from local vertex i along the line from pool id back
 * through i, shadow on `side`. Returns 0, -1 out of memory. */
static int trace(cm_linkpart *lp, long P, long i, long back, int side)
{
    tracer tr = {lp, P, side, i, back, lp->pk[P].ids[i], i};
    for (;;) {
        long t, r, l, hit;
        if (leave_vertex(&tr, &t, &r, &l, &hit) != 0) return 0;
        if (hit >= 0) {
            int s = pass_vertex(&tr, hit);
            if (s <= 0) return s;
            continue;
        }
        for (;;) {
            pocket *p = tr_pocket(&tr);
            const cm_vsource *vs = &p->vs;
            int c = 0;
            while (vs->tri[3 * t + c] == r || vs->tri[3 * t + c] == l) c++;
            long n = vs->nbr[3 * t + c];
            if (n < 0) {
                if (p->source < 0 && r == p->k - 1 && l == 0) return 0; /* the window: impossible */
                long h = add_hit_point(lp, tr.la, tr.lb, polygon_edge(lp, p->ids[r], p->ids[l]));
                if (h == -1) return -1;
                return h < 0 ? 0 : emit_window(&tr, r, h);
            }
            int z = 0;
            while (vs->tri[3 * n + z] == r || vs->tri[3 * n + z] == l) z++;
            long zv = vs->tri[3 * n + z];
            int o = orient(lp, tr.la, tr.lb, p->ids[zv]);
            if (o == 0) {
                hit = zv;
                break;
            }
            if (o > 0) l = zv; else r = zv;
            t = n;
        }
        int s = pass_vertex(&tr, hit);
        if (s <= 0) return s;
    }
}

/* ---- the partition ------------------------------------------------------- */

/* The shadow side (+1 left, -1 right) of a window along the line from
 * pool id `back` through local vertex i, or 0 if there is none: every
 * neighbour of i lies strictly on that side or on the line behind i, at
 * least one off the line, and the line goes on into the interior past i.
 * want: the side asked for, or 0 for either. */
static int window_side(const cm_linkpart *lp, long P, long i, long back, int want)
{
    const pocket *p = &lp->pk[P];
    long u = p->ids[i], nb[2] = {p->ids[cm_cycle_prev(i, p->k)], p->ids[cm_cycle_next(i, p->k)]};
    int side = 0;
    for (int j = 0; j < 2; j++) {
        int o = orient(lp, back, u, nb[j]);
        if (o == 0) {
            if (beyond(lp->pool, back, u, nb[j])) return 0;
        } else if (side == 0) {
            side = o;
        } else if (side != o) {
            return 0;
        }
    }
    if (side == 0 || (want != 0 && side != want)) return 0;
    return continues_past(lp, P, i, back) ? side : 0;
}

/* Windows at a lit vertex with cone (a, b): where the extreme sight line
 * through it grazes it, the region behind it is shadow. */
static int open_windows(cm_linkpart *lp, long P, long i, long a, long b)
{
    if (a == b) {
        int side = window_side(lp, P, i, a, 0);
        return side ? trace(lp, P, i, a, side) : 0;
    }
    if (window_side(lp, P, i, a, 1) && trace(lp, P, i, a, 1) < 0) return -1;
    if (window_side(lp, P, i, b, -1) && trace(lp, P, i, b, -1) < 0) return -1;
    return 0;
}

/* n lies on the segment from e up to (not including) w, all collinear. */
static int behind_on_segment(const cm_linkpart *lp, long e, long w, long n)
{
    cm_xpool *pool = lp->pool;
    return n == e || (orient(lp, e, w, n) == 0 && !beyond(pool, e, w, n) && !beyond(pool, w, e, n));
}

/* A vertex that is not visible but whose sight line from an end of the
 * source runs along the boundary into it (a neighbour lies on that line
 * before it): the line may go on past it as a window. */
static int open_grazing_windows(cm_linkpart *lp, long P, long i)
{
    const pocket *p = &lp->pk[P];
    long ends[2], nends = 0;
    if (p->source >= 0) ends[nends++] = p->ids[p->source];
    else ends[nends++] = p->ids[0], ends[nends++] = p->ids[p->k - 1];
    long u = p->ids[i], nb[2] = {p->ids[cm_cycle_prev(i, p->k)], p->ids[cm_cycle_next(i, p->k)]};
    for (long e = 0; e < nends; e++) {
        if (ends[e] == u) continue;
        if (!behind_on_segment(lp, ends[e], u, nb[0]) && !behind_on_segment(lp, ends[e], u, nb[1]))
            continue;
        int side = window_side(lp, P, i, ends[e], 0);
        if (side && trace(lp, P, i, ends[e], side) < 0) return -1;
        if (side) return 0;
    }
    return 0;
}

static void reach_vertex(cm_linkpart *lp, long v, int level, long via, int how, long a, long b)
{
    lp->dist[v] = level, lp->via[v] = via, lp->how[v] = (unsigned char)how;
    lp->cone_a[v] = a, lp->cone_b[v] = b;
}

static int candidate(const pocket *p, long i)
{
    return p->source >= 0 ? i != p->source : i > 0 && i < p->k - 1;
}

/* The root pocket takes the cached triangulation of the polygon and the
 * vertices its source sees from one pass of cone propagation over it
 * (O(triangles seen), where a walk from every vertex to the source would
 * cost O(m) each). Nothing walks up its dual tree (its cones are the
 * visibility row, its points' cones the sight test of lit_in), so the
 * tree keeps the rooting it was built with. */
static int build_root(cm_linkpart *lp, pocket *p)
{
    if (lp->root_state == 0) {
        int s = cm_vsource_build(&lp->root, lp->pool, lp->all, lp->m, p->source);
        lp->root_state = s == 0 ? 1 : -1;
        if (s < 0) return -1;
        if (s == 0) {
            lp->rows = cm_visrows_create(lp->xy, lp->m, lp->root.tri);
            if (!lp->rows) {
                cm_vsource_clear(&lp->root);
                lp->root_state = 0;
                return -1;
            }
        }
    }
    if (lp->root_state < 0) return 1;
    lp->root.in = lp->in;
    cm_visrows_row(lp->rows, p->source, lp->row);
    p->vs = lp->root, p->shared = 1;
    return 0;
}

/* ---- a pocket's triangulation from its parent's ----------------------------
 *
 * The window cuts the parent's triangulation along one segment: the
 * triangles it does not cross lie wholly on one side, and those on the
 * pocket's side are the pocket's, renumbered. The pocket-side pieces of the
 * crossed triangles form a sleeve: the window, and the crossed edges' ends
 * on the pocket's side in the order the window crosses them. Only the
 * sleeve is ear-clipped. So a pocket costs O(its triangles + the crossed
 * ones), not a triangulation from scratch. */

/* x (on line(a, b)) lies strictly ahead of a, toward b. */
static int ahead(cm_xpool *pool, long a, long b, long x) { return past(pool, a, b, a, x); }

static int grow_scratch(cm_linkpart *lp, long nt)
{
    if (nt + 2 <= lp->cap_scratch) return 0;
    long cap = 2 * (nt + 2);
    unsigned *stamp = realloc(lp->stamp, (size_t)cap * sizeof *stamp);
    if (stamp) lp->stamp = stamp;
    int32_t *q = realloc(lp->queue, (size_t)cap * sizeof *q);
    if (q) lp->queue = q;
    int32_t *r = realloc(lp->cut_r, (size_t)cap * sizeof *r);
    if (r) lp->cut_r = r;
    int32_t *l = realloc(lp->cut_l, (size_t)cap * sizeof *l);
    if (l) lp->cut_l = l;
    if (!stamp || !q || !r || !l) return -1;
    memset(stamp, 0, (size_t)cap * sizeof *stamp);
    lp->cap_scratch = cap, lp->gen = 0;
    return 0;
}

/* Pocket p's local index of its parent's local vertex i, -1 if none. */
static long child_local(const pocket *p, long parent_k, long i)
{
    long d = i - p->first; /* both in [0, parent_k) */
    if (d < 0) d += parent_k;
    return d < p->k - (p->hpos >= 0) ? d + (p->hpos == 0) : -1;
}

/* Pocket P's triangles (local indices, 3 (k - 2)) into tri, from its
 * parent's triangulation. Returns 0, 1 where this does not apply (the
 * window runs through a vertex of the parent, or anything unexpected:
 * the caller ear-clips), -1 out of memory. */
static int derive_triangles(cm_linkpart *lp, long P, int32_t *tri)
{
    const pocket *p = &lp->pk[P], *q = &lp->pk[p->parent];
    const cm_vsource *vs = &q->vs;
    cm_xpool *pool = lp->pool;
    long qk = q->k, k = p->k, want = k - 2, out = 0;
    if (grow_scratch(lp, vs->nt) < 0) return -1;
    if (++lp->gen == 0) memset(lp->stamp, 0, (size_t)lp->cap_scratch * sizeof *lp->stamp), lp->gen = 1;
    unsigned gen = lp->gen, *stamp = lp->stamp;
    long a = p->pivot, A = q->ids[a];
    long b_local = A == p->ids[0] ? k - 1 : 0, B = p->ids[b_local], a_local = k - 1 - b_local;
    long bv = p->hpos >= 0 ? -1 : p->end; /* B as the parent's vertex */
    int cs = b_local == 0 ? 1 : -1; /* the pocket lies left of A -> B (+1) or right */
    if (A != p->ids[a_local] || child_local(p, qk, a) != a_local) return 1;
    if (bv >= 0 && child_local(p, qk, bv) != b_local) return 1;
    /* the first triangle: the fan triangle of A the window enters */
    long t = -1, r = -1, l = -1, seed = -1, ncut = 0, nq = 0;
    for (long f = vs->fan_start[a]; f < vs->fan_start[a + 1] && t < 0 && seed < 0; f++) {
        long tt = vs->fan[f];
        int c = 0;
        while (vs->tri[3 * tt + c] != a) c++;
        long x = vs->tri[3 * tt + (c + 1) % 3], y = vs->tri[3 * tt + (c + 2) % 3];
        int ox = orient(lp, A, B, q->ids[x]), oy = orient(lp, A, B, q->ids[y]);
        if (ox < 0 && oy > 0) {
            t = tt, r = x, l = y;
            continue;
        }
        long on = ox == 0 && ahead(pool, A, B, q->ids[x]) ? x : oy == 0 && ahead(pool, A, B, q->ids[y]) ? y : -1;
        if (on < 0) continue;
        if (on != bv) return 1; /* through a vertex */
        /* the window is an edge of the triangulation: nothing is cut */
        long third = on == x ? y : x, across = vs->nbr[3 * tt + (on == x ? (c + 2) % 3 : (c + 1) % 3)];
        int o = on == x ? oy : ox;
        seed = o == cs ? tt : across;
        long other = o == cs ? across : tt;
        (void)third;
        if (seed < 0) return 1;
        if (other >= 0) stamp[other] = gen;
    }
    if (t >= 0) { /* walk the window through the triangles it crosses */
        for (;;) {
            if (ncut > vs->nt) return 1;
            stamp[t] = gen;
            lp->queue[nq++] = (int32_t)t; /* crossed triangles first, for their sides */
            lp->cut_r[ncut] = (int32_t)r, lp->cut_l[ncut] = (int32_t)l, ncut++;
            int c = 0;
            while (vs->tri[3 * t + c] == r || vs->tri[3 * t + c] == l) c++;
            long n = vs->nbr[3 * t + c];
            if (n < 0) { /* the boundary: must be the edge holding B */
                long e1 = (p->end + 1) % qk;
                if (bv >= 0 || !((r == p->end && l == e1) || (l == p->end && r == e1))) return 1;
                break;
            }
            int z = 0;
            while (vs->tri[3 * n + z] == r || vs->tri[3 * n + z] == l) z++;
            long zv = vs->tri[3 * n + z];
            int o = orient(lp, A, B, q->ids[zv]);
            if (o == 0) {
                if (zv != bv) return 1; /* through a vertex */
                stamp[n] = gen;
                lp->queue[nq++] = (int32_t)n;
                break;
            }
            if (o > 0) l = zv; else r = zv;
            t = n;
        }
    } else if (seed < 0) {
        return 1;
    }
    /* the sleeve: A, B and the crossed edges' pocket-side ends, ccw */
    long ncross = nq, ns = 0;
    if (ncut > 0) {
        long *sl = malloc((size_t)(ncut + 2) * sizeof *sl), *sid = malloc((size_t)(ncut + 2) * sizeof *sid);
        int32_t *st = malloc(3 * (size_t)ncut * sizeof *st);
        if (!sl || !sid || !st) {
            free(sl), free(sid), free(st);
            return -1;
        }
        int ok = 1;
        sl[ns++] = cs > 0 ? a_local : b_local;
        sl[ns++] = cs > 0 ? b_local : a_local;
        for (long i = 0; ok && i < ncut; i++) {
            long e = cs > 0 ? ncut - 1 - i : i, v = cs > 0 ? lp->cut_l[e] : lp->cut_r[e];
            long cl = child_local(p, qk, v);
            if (cl < 0) ok = 0;
            else if (cl != sl[ns - 1]) sl[ns++] = cl;
        }
        if (ns - 2 > want) ok = 0;
        for (long i = 0; ok && i < ns; i++) sid[i] = p->ids[sl[i]];
        int s = ok ? cm_xtriangulate(pool, sid, ns, st) : 1;
        if (s == 0) {
            for (long i = 0; i < 3 * (ns - 2); i++) tri[3 * (want - (ns - 2)) + i] = (int32_t)sl[st[i]];
        }
        free(sl), free(sid), free(st);
        if (s != 0) return s;
        /* the triangles beyond the crossed ones' pocket-side edges */
        for (long i = 0; i < ncross; i++) {
            long tt = lp->queue[i];
            for (int c = 0; c < 3; c++) {
                long n = vs->nbr[3 * tt + c];
                if (n < 0 || stamp[n] == gen) continue;
                int inside = 1;
                for (int j = 1; j < 3 && inside; j++) {
                    long v = vs->tri[3 * tt + (c + j) % 3];
                    inside = v == a || v == bv || orient(lp, A, B, q->ids[v]) == cs;
                }
                if (inside) stamp[n] = gen, lp->queue[nq++] = (int32_t)n;
            }
        }
    } else {
        stamp[seed] = gen, lp->queue[nq++] = (int32_t)seed;
    }
    /* flood the pocket's side, copying */
    long copy_max = want - (ns >= 3 ? ns - 2 : 0);
    for (long h = ncross; h < nq; h++) {
        long tt = lp->queue[h];
        if (out >= copy_max) return 1;
        for (int c = 0; c < 3; c++) {
            long cl = child_local(p, qk, vs->tri[3 * tt + c]);
            if (cl < 0) return 1;
            tri[3 * out + c] = (int32_t)cl;
            long n = vs->nbr[3 * tt + c];
            if (n >= 0 && stamp[n] != gen) {
                if (nq >= lp->cap_scratch) return 1;
                stamp[n] = gen, lp->queue[nq++] = (int32_t)n;
            }
        }
        out++;
    }
    return out == copy_max ? 0 : 1;
}

/* A window pocket's triangulation, derived or (where that does not apply)
 * by ear clipping. Returns 0, -1 out of memory, 1 not triangulated. */
static int build_pocket(cm_linkpart *lp, long P)
{
    pocket *p = &lp->pk[P];
    const pocket *q = &lp->pk[p->parent];
    if (lp->derive && q->built) {
        int32_t *tri = malloc(3 * (size_t)(p->k - 2) * sizeof *tri);
        if (!tri) return -1;
        int s = derive_triangles(lp, P, tri);
        if (s < 0) {
            free(tri);
            return -1;
        }
        if (s == 0) {
            s = cm_vsource_build_tri(&p->vs, lp->pool, p->ids, p->k, p->source, tri);
            if (s == 0) lp->derived += p->k;
            if (s <= 0) return s;
            cm_vsource_clear(&p->vs);
        } else {
            free(tri);
        }
    }
    lp->clipped += p->k;
    return cm_vsource_build(&p->vs, lp->pool, p->ids, p->k, p->source);
}

/* Local vertex i of pocket P sees its source: the cone of sight lines. */
static int vertex_cone(cm_linkpart *lp, pocket *p, long i, long *a, long *b)
{
    if (p->source < 0) return cm_vsource_vertex_cone(&p->vs, i, a, b);
    if (!lp->row[i]) return 0; /* the root: local i is vertex i */
    *a = *b = p->source;
    return 1;
}

static int process_window(cm_linkpart *lp, long P)
{
    pocket *p = &lp->pk[P];
    int s = p->source >= 0 ? build_root(lp, p) : build_pocket(lp, P);
    if (s < 0) return -1;
    if (s > 0) {
        if (!p->shared) cm_vsource_clear(&p->vs);
        return 0; /* cannot happen for a simple polygon: leave it undetermined */
    }
    p->built = 1;
    p->vs.in = lp->in;
    long k = p->k;
    memset(lp->covered, 0, (size_t)k);
    for (long i = 0; i < k; i++) {
        p = &lp->pk[P];
        long v = p->ids[i], a, b;
        if (!candidate(p, i) || v >= lp->m || lp->dist[v] >= 0) continue;
        if (!vertex_cone(lp, p, i, &a, &b)) continue;
        reach_vertex(lp, v, p->level, P, HOW_CONE, a, b);
        if (open_windows(lp, P, i, a, b) < 0) return -1;
    }
    for (long i = 0; i < k; i++) {
        p = &lp->pk[P];
        long v = p->ids[i];
        if (candidate(p, i) && v < lp->m && lp->dist[v] < 0 && !lp->covered[i])
            if (open_grazing_windows(lp, P, i) < 0) return -1;
    }
    p = &lp->pk[P];
    for (long e = 0; p->source < 0 && e < k; e += k - 1) {
        long v = p->ids[e];
        if (v < lp->m && lp->dist[v] < 0) reach_vertex(lp, v, p->level, p->parent, HOW_NEAR, -1, -1);
    }
    for (long i = 0; i < k; i++) {
        long v = p->ids[i];
        if (candidate(p, i) && v < lp->m && lp->dist[v] < 0 && !lp->covered[i])
            reach_vertex(lp, v, p->level + 1, P, HOW_NEAR, -1, -1);
    }
    return 0;
}

/* May pocket P go unprocessed? With need given: when none of its vertices
 * is needed and none is in another pocket of its level. What processing a
 * pocket decides is confined to its vertices (and its sub-pockets, all
 * within it); a vertex shared with a sibling could be decided by either,
 * in order, so those are kept. */
static int skippable(const cm_linkpart *lp, long P, const unsigned char *need)
{
    const pocket *p = &lp->pk[P];
    for (long i = 0; i < p->k; i++) {
        long v = p->ids[i];
        if (v < lp->m && (need[v] || lp->seen[v] > 1)) return 0;
    }
    return 1;
}

/* The window partition from s up to max_level; with need (per vertex,
 * NULL for all), pockets holding no needed vertex may be left out: the
 * distances of the needed vertices are those of the whole partition, the
 * others may stay undetermined, and the partition is not kept for paths. */
static int run_levels(cm_linkpart *lp, long s, int max_level, const unsigned char *need)
{
    if (!need && lp->source == s && lp->max_level >= max_level) return 0;
    drop_pockets(lp);
    for (long v = 0; v < lp->m; v++) lp->dist[v] = -1, lp->how[v] = HOW_NONE;
    lp->dist[s] = 0;
    if (add_pocket(lp, lp->all, lp->m, 1, -1, s) < 0) return -1;
    lp->truncated = 0, lp->limit = max_level;
    int counted = 1;
    for (long P = 0; P < lp->npk; P++) {
        if (lp->pk[P].level > max_level) {
            lp->truncated = 1;
            continue;
        }
        if (need && lp->pk[P].level > counted) { /* a new level: all its pockets exist */
            counted = lp->pk[P].level;
            memset(lp->seen, 0, (size_t)lp->m * sizeof *lp->seen);
            for (long Q = P; Q < lp->npk && lp->pk[Q].level == counted; Q++)
                for (long i = 0; i < lp->pk[Q].k; i++)
                    if (lp->pk[Q].ids[i] < lp->m) lp->seen[lp->pk[Q].ids[i]]++;
        }
        if (need && P > 0 && skippable(lp, P, need)) continue;
        if (process_window(lp, P) < 0) {
            drop_pockets(lp);
            return -1;
        }
    }
    lp->source = need ? -1 : s, lp->max_level = max_level;
    return 0;
}

int cm_link_distances_upto(cm_linkpart *lp, long s, int max_level, int *dist)
{
    if (run_levels(lp, s, max_level, NULL) < 0) return -1;
    memcpy(dist, lp->dist, (size_t)lp->m * sizeof *dist);
    return lp->truncated;
}

int cm_link_distances_needed(cm_linkpart *lp, long s, int max_level, const unsigned char *need, int *dist)
{
    if (run_levels(lp, s, max_level, need) < 0) return -1;
    memcpy(dist, lp->dist, (size_t)lp->m * sizeof *dist);
    return lp->truncated;
}

int cm_link_distances(cm_linkpart *lp, long s, int *dist)
{
    return cm_link_distances_upto(lp, s, INT_MAX, dist) < 0 ? -1 : 0;
}

/* ---- minimum-link paths --------------------------------------------------- */

static int sees(const cm_linkpart *lp, long vertex, const double p[2], const double y[2])
{
    return (lp->in.tame && cm_coords_tame(p, 2) && cm_coords_tame(y, 2) ? cm_segment_inside_tame
                                                                      : cm_segment_inside)(lp->xy, lp->m, vertex, p,
                                                                                           -1, y);
}

/* Is the point y lit in pocket Q (visible from its source)? If so, *a, *b
 * get its cone toward Q's source. Returns 1, 0, or -1 out of memory. */
static int lit_in(cm_linkpart *lp, long Q, const double y[2], long *a, long *b)
{
    pocket *q = &lp->pk[Q];
    if (q->source >= 0) {
        *a = *b = lp->source;
        return sees(lp, lp->source, lp->xy + 2 * lp->source, y);
    }
    if (!q->built) return 0;
    long mark = cm_xpool_count(lp->pool);
    long id = cm_xpool_add(lp->pool, y[0], y[1]);
    if (id < 0) return -1;
    int r = cm_vsource_point_cone(&q->vs, id, a, b) == 1;
    cm_xpool_truncate(lp->pool, mark);
    return r;
}

static void unit(double v[2])
{
    double len = hypot(v[0], v[1]);
    if (len > 0) v[0] /= len, v[1] /= len;
}

/* The best bend so far: the widest cone toward its pocket's source, so
 * that the next bend has room (a bend on the edge of a lit region would
 * leave it a sliver). */
typedef struct {
    double y[2], score;
    long a, b;
    int found;
} bend_choice;

/* Considers bend y for pocket Q, to be seen from the previous point p
 * (polygon vertex p_vertex or -1). Its score comes first: a bend that
 * cannot beat the best so far needs no sight test. Returns 0 or -1 (out
 * of memory). */
static int consider(cm_linkpart *lp, long Q, const double y[2], long p_vertex, const double p[2],
                    bend_choice *best)
{
    long a, b;
    if (lp->pk[Q].source >= 0 && best->found) return 0; /* the root's cone is its source: score 0 */
    int r = lit_in(lp, Q, y, &a, &b);
    if (r <= 0) return r;
    double score = 0.0;
    if (a != b) {
        const double *pa = cm_xpool_xy(lp->pool, a), *pb = cm_xpool_xy(lp->pool, b);
        double ux = pa[0] - y[0], uy = pa[1] - y[1], vx = pb[0] - y[0], vy = pb[1] - y[1];
        score = atan2(fabs(ux * vy - uy * vx), ux * vx + uy * vy);
    }
    if (best->found && !(score > best->score)) return 0;
    if (!sees(lp, p_vertex, p, y)) return 0;
    best->y[0] = y[0], best->y[1] = y[1], best->score = score;
    best->a = a, best->b = b, best->found = 1;
    return 0;
}

/* Puts the chosen bend into the pool. 1, 0 (none) or -1. */
static int take(cm_linkpart *lp, const bend_choice *best, double y[2], long *id, long *a, long *b)
{
    if (!best->found) return 0;
    y[0] = best->y[0], y[1] = best->y[1];
    *id = cm_xpool_add(lp->pool, y[0], y[1]);
    if (*id < 0) return -1;
    *a = best->a, *b = best->b;
    return 1;
}

static const double deltas[] = {0.5, 0.25, 0.12, 0.05, 0.02, 5e-3, 1e-3, 1e-4, 1e-5, 1e-7};
#define NDELTAS (sizeof deltas / sizeof deltas[0])
/* Depths into the free stretch of a ray beyond a window, as fractions. */
static const double depths[] = {0.5, 0.3, 0.7, 0.15, 0.85, 0.05, 0.02, 5e-3, 1e-3, 1e-4, 1e-6};
#define NDEPTHS (sizeof depths / sizeof depths[0])

/* Distance along the unit direction dir from p to the polygon boundary,
 * beyond distance `from` (doubles: it only places candidates). */
static double ray_free(const cm_linkpart *lp, const double p[2], const double dir[2], double from)
{
    double best = INFINITY;
    for (long i = 0; i < lp->m; i++) {
        const double *a = lp->xy + 2 * i, *b = lp->xy + 2 * cm_cycle_next(i, lp->m);
        double ex = b[0] - a[0], ey = b[1] - a[1];
        double den = dir[0] * ey - dir[1] * ex;
        if (den == 0) continue;
        double t = ((a[0] - p[0]) * ey - (a[1] - p[1]) * ex) / den;
        double u = ((a[0] - p[0]) * dir[1] - (a[1] - p[1]) * dir[0]) / den;
        if (t > from && u >= 0 && u <= 1 && t < best) best = t;
    }
    return best;
}

/* A bend for point p (pool id, polygon vertex p_vertex or -1) lit in pocket
 * P with cone (a, b): a point beyond P's window, lit in the parent pocket,
 * that p sees. Returns 1 (bend in y, its id and cone in *id, *a, *b), 0,
 * or -1 out of memory. */
static int cone_bend(cm_linkpart *lp, long P, long p_id, long p_vertex, long *a, long *b,
                     double y[2], long *id)
{
    static const double fractions[] = {0.5, 0.3, 0.7, 0.15, 0.85, 0.05, 0.95};
    const pocket *pk = &lp->pk[P];
    double p[2], ua[2], ub[2], w0[2], w1[2];
    const double *q;
    q = cm_xpool_xy(lp->pool, p_id), p[0] = q[0], p[1] = q[1];
    q = cm_xpool_xy(lp->pool, *a), ua[0] = q[0] - p[0], ua[1] = q[1] - p[1];
    q = cm_xpool_xy(lp->pool, *b), ub[0] = q[0] - p[0], ub[1] = q[1] - p[1];
    q = cm_xpool_xy(lp->pool, pk->ids[pk->k - 1]), w0[0] = q[0], w0[1] = q[1];
    q = cm_xpool_xy(lp->pool, pk->ids[0]), w1[0] = q[0], w1[1] = q[1];
    unit(ua), unit(ub);
    double wd[2] = {w1[0] - w0[0], w1[1] - w0[1]};
    long parent = pk->parent;
    bend_choice best = {{0, 0}, 0, -1, -1, 0};
    for (size_t fi = 0; fi < sizeof fractions / sizeof fractions[0]; fi++) {
        double f = fractions[fi], dir[2] = {f * ua[0] + (1 - f) * ub[0], f * ua[1] + (1 - f) * ub[1]};
        unit(dir);
        double den = dir[0] * wd[1] - dir[1] * wd[0];
        double s = ((w0[0] - p[0]) * wd[1] - (w0[1] - p[1]) * wd[0]) / den;
        if (!(s > 0) || !isfinite(s)) continue;
        double room = ray_free(lp, p, dir, s) - s;
        if (!isfinite(room)) room = s;
        for (size_t di = 0; di < NDEPTHS; di++) {
            double step = s + room * depths[di], c[2] = {p[0] + step * dir[0], p[1] + step * dir[1]};
            if (consider(lp, parent, c, p_vertex, p, &best) < 0) return -1;
        }
    }
    return take(lp, &best, y, id, a, b);
}

/* A bend next to polygon vertex w, inside its corner, lit in pocket Q and
 * seeing w. Returns 1 (bend in y, its id and cone in *id, *a, *b), 0, -1. */
static int near_bend(cm_linkpart *lp, long Q, long w, double y[2], long *id, long *a, long *b)
{
    static const double fractions[] = {0.5,  0.25, 0.75, 0.1,   0.9,  0.4,   0.6,   0.02,
                                       0.98, 0.005, 0.995, 0.001, 0.999, 0.33, 0.67};
    const double *pw = lp->xy + 2 * w, *pp = lp->xy + 2 * ((w + lp->m - 1) % lp->m),
                 *pn = lp->xy + 2 * ((w + 1) % lp->m);
    double a0 = atan2(pn[1] - pw[1], pn[0] - pw[0]), a1 = atan2(pp[1] - pw[1], pp[0] - pw[0]);
    double span = a1 - a0;
    while (span <= 0) span += 2 * CM_PI;
    double scale = fmin(hypot(pn[0] - pw[0], pn[1] - pw[1]), hypot(pp[0] - pw[0], pp[1] - pw[1]));
    bend_choice best = {{0, 0}, 0, -1, -1, 0};
    for (size_t fi = 0; fi < sizeof fractions / sizeof fractions[0]; fi++) {
        double angle = a0 + fractions[fi] * span;
        for (size_t di = 0; di < NDELTAS; di++) {
            double step = 0.6 * deltas[di] * scale;
            double c[2] = {pw[0] + step * cos(angle), pw[1] + step * sin(angle)};
            if (consider(lp, Q, c, w, pw, &best) < 0) return -1;
        }
    }
    return take(lp, &best, y, id, a, b);
}

/* Builds the bends backward from v; pts gets d - 1 bends. 1, 0 or -1. */
static int build_bends(cm_linkpart *lp, long v, int d, double *pts)
{
    long p_id = v, p_vertex = v, P = lp->via[v], a = lp->cone_a[v], b = lp->cone_b[v];
    int how = lp->how[v];
    for (int j = d - 1; j >= 1; j--) {
        long Q = how == HOW_CONE ? lp->pk[P].parent : P, id;
        if (Q < 0 || lp->pk[Q].level != j) return 0;
        double *y = pts + 2 * (j - 1);
        int r = how == HOW_CONE ? cone_bend(lp, P, p_id, p_vertex, &a, &b, y, &id)
                                : near_bend(lp, Q, p_vertex, y, &id, &a, &b);
        if (r <= 0) return r;
        p_id = id, p_vertex = -1, P = Q, how = HOW_CONE;
    }
    return 1;
}

int cm_link_path(cm_linkpart *lp, long u, long v, double **bends, long *nbends)
{
    return cm_link_path_within(lp, u, v, INT_MAX, bends, nbends);
}

int cm_link_path_within(cm_linkpart *lp, long u, long v, int max_level, double **bends, long *nbends)
{
    *bends = NULL, *nbends = 0;
    /* the path reads only v's pocket and its ancestors, all within v's
     * level: the levels beyond change nothing */
    if (run_levels(lp, u, max_level, NULL) < 0) return -1;
    int d = lp->dist[v];
    if (d < 1 || d > max_level) return 0;
    if (d == 1) return cm_path_valid_in(lp->xy, lp->m, lp->in.tame, u, v, NULL, 0);
    double *pts = malloc(2 * (size_t)(d - 1) * sizeof *pts);
    if (!pts) return -1;
    long mark = cm_xpool_count(lp->pool);
    int r = build_bends(lp, v, d, pts);
    cm_xpool_truncate(lp->pool, mark);
    if (r == 1 && !cm_path_valid_in(lp->xy, lp->m, lp->in.tame, u, v, pts, d - 1)) r = 0;
    if (r != 1) {
        free(pts);
        return r;
    }
    *bends = pts, *nbends = d - 1;
    return d;
}

/* Consecutive links meeting at q may not fold back onto each other. */
static int no_fold(const double *p, const double *q, const double *r)
{
    if (cm_orient2d(p, q, r) != 0) return 1;
    int axis = p[0] != q[0] ? 0 : 1;
    return (q[axis] > p[axis]) == (r[axis] > q[axis]);
}

/* Point i of the path u, bends[0..nb-1], v (n = nb + 2 points). */
static const double *path_point(const double *xy, long u, long v, const double *bends, long n, long i)
{
    return i == 0 ? xy + 2 * u : i == n - 1 ? xy + 2 * v : bends + 2 * (i - 1);
}

int cm_path_valid(const double *xy, long m, long u, long v, const double *bends, long nb)
{
    return cm_path_valid_in(xy, m, cm_coords_tame(xy, 2 * m), u, v, bends, nb);
}

int cm_path_valid_in(const double *xy, long m, int tame, long u, long v, const double *bends, long nb)
{
    long n = nb + 2;
#define PT(i) path_point(xy, u, v, bends, n, i)
    int ok = 1;
    /* O(nb) once, against O(m) per link */
    int (*inside)(const double *, long, long, const double *, long, const double *) =
        tame && cm_coords_tame(bends, 2 * nb) ? cm_segment_inside_tame : cm_segment_inside;
    for (long i = 0; ok && i + 1 < n; i++)
        ok = inside(xy, m, i == 0 ? u : -1, PT(i), i + 1 == n - 1 ? v : -1, PT(i + 1));
    for (long i = 0; ok && i + 2 < n; i++) ok = no_fold(PT(i), PT(i + 1), PT(i + 2));
    for (long i = 0; ok && i + 1 < n; i++)
        for (long j = i + 2; ok && j + 1 < n; j++)
            ok = cm_segments_intersect(PT(i), PT(i + 1), PT(j), PT(j + 1)) == 0;
#undef PT
    return ok;
}

int cm_weak_visibility(const double *xy, long m, long a, long b, unsigned char *vis)
{
    long k = (b - a + m) % m + 1;
    cm_xpool *pool = cm_xpool_create();
    long *ids = malloc((size_t)k * sizeof *ids);
    int status = -1;
    cm_vsource vs;
    memset(&vs, 0, sizeof vs);
    memset(vis, 0, (size_t)m);
    if (!pool || !ids) goto done;
    for (long i = 0; i < k; i++) {
        long v = (a + i) % m;
        ids[i] = cm_xpool_add(pool, xy[2 * v], xy[2 * v + 1]);
        if (ids[i] < 0) goto done;
    }
    status = cm_vsource_build(&vs, pool, ids, k, -1);
    for (long i = 1; status == 0 && i + 1 < k; i++) {
        long ca, cb;
        vis[(a + i) % m] = (unsigned char)cm_vsource_vertex_cone(&vs, i, &ca, &cb);
    }
done:
    cm_vsource_clear(&vs);
    free(ids);
    cm_xpool_free(pool);
    return status;
}
