/* Connectivity changes scored by the polish (polish_moves.h).
 *
 * After the joint max-min polish (maxmin.c) the worst triangles sit in
 * sets that hold each other: no motion of the vertices with the
 * connectivity fixed frees them, and the greedy forced moves (a move,
 * then one-vertex flips and smoothing) judge a move by a repair too weak
 * to show what it allows. Here a move near one of the worst triangles (a
 * flip, an edge split, a Steiner vertex collapsed onto a neighbour, a
 * vertex inserted at the centroid, or no move at all) is followed by the
 * polish itself on the Steiner vertices within CM_PMOVE_RINGS rings of
 * it, in every geometry, and kept only when the smallest slack of the
 * triangles around it rose (by CM_PMOVE_GAIN) and no triangle of the
 * whole mesh fell below its smallest angle before the move. Everything
 * runs as a kmesh transaction: a move undone leaves the mesh exactly as it
 * was. The moves are checked with the exact predicates (flip.c,
 * collapse.c, refine.c, maprefine.c) and the polish keeps only exactly
 * valid positions, so every kept state is valid in every geometry, and
 * the connectivity is one for all.
 *
 * With a slide (the correspondence the tool's to choose), the polish
 * also slides the ring's boundary points that lie inside an input edge
 * of a geometry along that edge (their labels' parameters change, in the
 * transaction), and boundary edges split too: on the auto glyph pairs
 * short of their floor the worst triangles often have such a point, or
 * a long boundary edge, as a corner.
 *
 * The gains come from the connectivity changes (bench/REMESH.md, "Moves
 * scored by the polish"): the polish alone near the worst triangle, tried
 * alone, left the smallest angle where the joint polish had put it;
 * flips and splits followed by it raised auto's near misses by up to
 * 25 %. */
#include "remesh/polish_moves.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/deadline.h"
#include "remesh/collapse.h"
#include "remesh/flip.h"
#include "remesh/maprefine.h"
#include "remesh/maxmin.h"
#include "remesh/refine.h"

/* Rings of vertices around a move that the polish moves; the nearest
 * of them move while their stars' triangles, counted once per star,
 * number at most CM_PMOVE_TRIS_MAX (a two-ring region of a mesh of
 * degree 6 counts about 250): beside vertices of high degree (fans in a star
 * polygon) each try's polish otherwise cost more than the joint polish
 * (star_n1000: the run took 6 times its CPU). */
#define CM_PMOVE_RINGS 2
#define CM_PMOVE_TRIS_MAX 600
/* The worst triangles (by slack) a round looks at. */
#define CM_PMOVE_WORST 8
/* The rise of the smallest slack around a move that keeps it (radians);
 * the polish alone must gain more, about 0.06 degrees: it is kept often
 * for less, and each kept move lets every undone one run again, so its
 * small gains took the tries the connectivity changes gain with (tries
 * were used up on every pair measured). */
#define CM_PMOVE_GAIN 1e-5
#define CM_PMOVE_POLISH_GAIN 1e-3
/* How long the stage works (cm_pmove_limits), by whether boundary points
 * may be added (arc length, auto: km->between).
 *
 * The share of its aim the worst triangle must have reached for the
 * stage to run: further below, what holds it is the correspondence (index
 * mode's hard pairs end near 0.4 of it), and 200 tries there cost 60 %
 * more CPU for about 1 % of angle. Where boundary points may be added,
 * the boundary can give way, and on the auto glyph pairs the stage raised
 * pairs ending at 0.35-0.5 of their aim too (bench/REMESH.md, "Boundary
 * points in the polish-scored moves").
 *
 * Tries in a row without a kept move that end the stage: later gains are
 * rare (the same angles on the pairs that gain, bench/REMESH.md), and a
 * pair where nothing gains otherwise pays for every try of the budget.
 *
 * Where boundary points may be added, three times the tries and the idle
 * stop and twice each local polish's L-BFGS iterations (per geometry): a
 * polish that tells a move's worth better, and the auto glyph pairs at
 * min(20, c/2) rose from 71 to 81 of 88 for 1.6 times the CPU, geometric
 * mean (bench/REMESH.md, "A longer polish-scored stage in auto"); auto
 * has no time target to keep. */
static const cm_pmove_limits cm_pmove_fixed = {.share = 0.5, .tries = 200, .idle = 40, .iterations = 100};
static const cm_pmove_limits cm_pmove_between = {.share = 0.25, .tries = 600, .idle = 120, .iterations = 200};

cm_pmove_limits cm_pmove_limits_of(const cm_kmesh *km) { return km->between ? cm_pmove_between : cm_pmove_fixed; }

/* Where the correspondence is the tool's to choose (auto, similarity:
 * boundary points added and slid) and the stage ends with the worst
 * triangle still below CM_PMOVE_LONGER_SHARE of its aim, it runs again at
 * these limits, with the boundary points' turn, up to
 * CM_PMOVE_LONGER_ROUNDS times while a run keeps a move: on the auto
 * glyph pairs short of min(15, c/3) a run stopped by its idle or try limit
 * gains again from where it stopped (hold_Z003_G_Z_n160 10.29 -> 13.90
 * degrees), and pairs above the share pay nothing. Not for arc length
 * (no slide): its results end far below the share (0.2 on those pairs)
 * and gained 0.1 degrees for 3 to 4 times the CPU. */
#define CM_PMOVE_LONGER_SHARE 0.6
static const cm_pmove_limits cm_pmove_longer = {.share = 0.25, .tries = 1500, .idle = 300, .iterations = 200};

cm_pmove_limits cm_pmove_longer_limits(void) { return cm_pmove_longer; }
int cm_pmove_longer_wanted(const cm_kmesh *km) { return km->between && cm_kmesh_min_share(km) < CM_PMOVE_LONGER_SHARE; }

enum pmove { PM_POLISH, PM_FLIP, PM_SPLIT, PM_COLLAPSE, PM_INSERT, PM_KINDS };

/* Rings around the vertices a kept move's try polished (its ring) within
 * which a try undone before may now end otherwise. A try reads the mesh
 * within CM_PMOVE_RINGS + 1 rings of its own vertices (the stars of its
 * ring); a kept move changes positions and edges only among its ring's
 * vertices (every edge it removes or adds has both ends there), so a
 * path from a try's vertices to the first vertex it changed is a path
 * of the mesh after it too. */
#define CM_PMOVE_REACH (CM_PMOVE_RINGS + 1)

/* A move undone: its key (move_key), its own vertices (-1: none), and
 * the memo's round (moves kept, and calls begun) when it was last tried
 * or counted. An undone move is not tried again before the next kept
 * move (as before), and after it only where the kept move changed the
 * mesh within its reach: every input of the try is then as it was, and
 * the mesh's smallest angle, which a kept try may not go below, only
 * rose, so it would be undone again. Such a move counts as a try all the
 * same, so that the stage ends where it did. */
struct cm_pmove_failed {
    uint64_t key;
    int32_t own[4];
    long round;
};

void cm_pmove_memo_free(cm_pmove_memo *memo)
{
    free(memo->failed);
    *memo = (cm_pmove_memo){0};
}

typedef struct mover {
    cm_kmesh *km;
    cm_progress *progress;
    cm_ibuf star, ring, var, tris, gvar;
    double *pts, *pts_t;
    size_t pts_cap, pts_t_cap;
    /* boundary points slide (NULL: they stay): the labels of the polished
     * region's vertices in the form cm_maxmin_local reads, per vertex */
    cm_maxmin_slide *slide;
    cm_maxmin_slide labels;
    int32_t **edge_rows, *next, *prev;
    double **t_rows;
    size_t rows_cap;
    size_t slides; /* boundary points slid by the try under way */
    /* what the try under way must reach to be kept: the ring's smallest
     * slack above `need`, no triangle's key below `least` */
    double need, least;
    cm_pmove_memo *memo; /* the moves undone (cm_pmove_failed) */
    const cm_pmove_limits *limits;
} mover;

/* Adds to x->ring, marked with stamp, the vertices within `rounds` rings
 * of its live vertices (those already in it are marked). 0 or -1 out of
 * memory. */
static int grow_rings(mover *x, int rounds, uint32_t stamp)
{
    cm_kmesh *km = x->km;
    size_t from = 0;
    for (int r = 0; r < rounds; r++) {
        size_t to = x->ring.n;
        for (size_t i = from; i < to; i++) {
            if (km->vc[x->ring.a[i]] < 0) continue;
            long m = cm_kmesh_star(km, x->ring.a[i], &x->star);
            if (m < 0) return -1;
            for (long j = 0; j < m; j++) {
                int32_t c = x->star.a[j];
                for (int e = 0; e < 2; e++) {
                    int32_t w = km->tri[e ? cm_prev(c) : cm_next(c)];
                    if (km->mark[w] == stamp) continue;
                    km->mark[w] = stamp;
                    if (cm_ibuf_push(&x->ring, w)) return -1;
                }
            }
        }
        from = to;
    }
    return 0;
}

/* The vertices within CM_PMOVE_RINGS rings of seeds[0 .. ns) (live
 * ones) into x->ring, nearest first. 0 or -1 out of memory. */
static int rings(mover *x, const int32_t *seeds, int ns)
{
    cm_kmesh *km = x->km;
    uint32_t stamp = cm_kmesh_new_stamp(km);
    x->ring.n = 0;
    for (int i = 0; i < ns; i++)
        if (seeds[i] >= 0 && km->vc[seeds[i]] >= 0 && km->mark[seeds[i]] != stamp) {
            km->mark[seeds[i]] = stamp;
            if (cm_ibuf_push(&x->ring, seeds[i])) return -1;
        }
    return grow_rings(x, CM_PMOVE_RINGS, stamp);
}

/* The smallest slack and smallest key of the triangles around the ring's
 * live vertices (g = k); or (g < k) the most they can become while
 * geometry g stays as it is: a triangle's key is its smallest angle over
 * the geometries, so at most its angle in g. 0 or -1 out of memory. */
static int ring_quality(mover *x, size_t g, double *slack, double *key)
{
    cm_kmesh *km = x->km;
    *slack = *key = HUGE_VAL;
    for (size_t i = 0; i < x->ring.n; i++) {
        int32_t v = x->ring.a[i];
        if (km->vc[v] < 0) continue;
        long m = cm_kmesh_star(km, v, &x->star);
        if (m < 0) return -1;
        for (long j = 0; j < m; j++) {
            int32_t t = x->star.a[j] / 3;
            double a = g < km->k ? km->tang[(size_t)t * km->k + g] : km->tkey[t];
            *slack = fmin(*slack, a - km->tkey[t] + km->slack[t]), *key = fmin(*key, a);
        }
    }
    return 0;
}

/* Can the try under way no longer be kept, geometry g polished? The
 * slack's bound is rounded: a margin far below any gain asked. */
static int try_lost(mover *x, size_t g, int *hopeless)
{
    double slack, key;
    if (ring_quality(x, g, &slack, &key)) return -1;
    *hopeless = !(slack > x->need - 1e-12) || key < x->least;
    return 0;
}

static int by_id(const void *a, const void *b)
{
    int32_t x = *(const int32_t *)a, y = *(const int32_t *)b;
    return (x > y) - (x < y);
}

/* Room for the labels of km->nv vertices. 0, or -1 out of memory. */
static int grow_rows(mover *x)
{
    cm_kmesh *km = x->km;
    size_t need = (size_t)km->nv, cap = x->rows_cap;
    if (need <= cap) return 0;
    for (size_t g = 0; g < km->k; g++) {
        size_t c = cap;
        void *p = x->edge_rows[g];
        if (cm_grow(&p, &c, need, sizeof **x->edge_rows)) return -1;
        x->edge_rows[g] = p, c = cap, p = x->t_rows[g];
        if (cm_grow(&p, &c, need, sizeof **x->t_rows)) return -1;
        x->t_rows[g] = p;
    }
    size_t c = cap;
    void *p = x->next;
    if (cm_grow(&p, &c, need, sizeof *x->next)) return -1;
    x->next = p, c = cap, p = x->prev;
    if (cm_grow(&p, &c, need, sizeof *x->prev)) return -1;
    x->prev = p, x->rows_cap = c;
    x->labels.edge = x->edge_rows, x->labels.t = x->t_rows, x->labels.next = x->next, x->labels.prev = x->prev;
    return 0;
}

/* The labels of boundary vertex v (its star in x->star) for the polish:
 * where it lies inside an input edge of a geometry it slides there,
 * elsewhere (an input vertex of it) it stays. */
static void label_boundary(mover *x, int32_t v, long m)
{
    cm_kmesh *km = x->km;
    for (size_t g = 0; g < km->k; g++) {
        size_t a = km->k * (size_t)v + g;
        x->edge_rows[g][v] = km->bt[a] > 0 ? km->bedge[a] : -1, x->t_rows[g][v] = km->bt[a];
    }
    x->next[v] = km->bnext[v], x->prev[v] = km->tri[cm_prev(x->star.a[m - 1])];
}

/* 1 if v moves in geometry g: an interior vertex, or a boundary point
 * that slides there. */
static int moves_in(const mover *x, size_t g, int32_t v)
{
    return !cm_kmesh_is_boundary(x->km, v) || x->edge_rows[g][v] >= 0;
}

/* The local polish of the ring's live interior vertices in every
 * geometry, and of its boundary points where they slide; the geometries
 * after one that leaves the try out of reach (*hopeless) are skipped.
 * 0, or -1 out of memory or cancelled. */
static int polish_ring(mover *x, int *hopeless)
{
    cm_kmesh *km = x->km;
    x->var.n = x->tris.n = 0;
    *hopeless = 0;
    if (x->slide && grow_rows(x)) return -1;
    for (size_t i = 0; i < x->ring.n; i++) {
        int32_t v = x->ring.a[i];
        int boundary = km->vc[v] >= 0 && cm_kmesh_is_boundary(km, v);
        if (km->vc[v] < 0 || (boundary && !x->slide)) continue;
        long m = cm_kmesh_star(km, v, &x->star);
        if (m < 0) return -1;
        if (x->tris.n + (size_t)m > CM_PMOVE_TRIS_MAX) continue;
        if (boundary) label_boundary(x, v, m);
        for (size_t g = 0; x->slide && !boundary && g < km->k; g++) x->edge_rows[g][v] = -1; /* moves freely */
        if (cm_ibuf_push(&x->var, v)) return -1;
        for (long j = 0; j < m; j++)
            if (cm_ibuf_push(&x->tris, x->star.a[j] / 3)) return -1;
    }
    if (!x->var.n) return 0;
    qsort(x->tris.a, x->tris.n, sizeof *x->tris.a, by_id);
    size_t nt = 0;
    for (size_t i = 0; i < x->tris.n; i++)
        if (!nt || x->tris.a[nt - 1] != x->tris.a[i]) x->tris.a[nt++] = x->tris.a[i];
    x->tris.n = nt;
    void *p = x->pts;
    if (cm_grow(&p, &x->pts_cap, 2 * x->var.n, sizeof *x->pts)) return -1;
    x->pts = p, p = x->pts_t;
    if (cm_grow(&p, &x->pts_t_cap, x->var.n, sizeof *x->pts_t)) return -1;
    x->pts_t = p;
    for (size_t g = 0; g < km->k && !*hopeless; g++) {
        x->gvar.n = 0;
        for (size_t j = 0; j < x->var.n; j++)
            if ((!x->slide || moves_in(x, g, x->var.a[j])) && cm_ibuf_push(&x->gvar, x->var.a[j])) return -1;
        if (!x->gvar.n) continue;
        int r = cm_maxmin_local(km->tri, km->xy[g], (size_t)km->nv, x->gvar.a, x->gvar.n, x->tris.a, x->tris.n,
                                x->slide ? &x->labels : NULL, g, x->limits->iterations, x->progress, x->pts,
                                x->pts_t);
        if (r < 0) return -1;
        for (size_t j = 0; r > 0 && j < x->gvar.n; j++) {
            int32_t v = x->gvar.a[j];
            if (cm_kmesh_star(km, v, &x->star) < 0) return -1;
            if (!cm_kmesh_is_boundary(km, v)) {
                cm_kmesh_move(km, g, v, x->pts + 2 * j, &x->star);
            } else if (x->pts_t[j] != x->t_rows[g][v]) {
                cm_kmesh_slide(km, g, v, x->pts + 2 * j, x->pts_t[j], &x->star);
                x->t_rows[g][v] = x->pts_t[j], x->slides++;
            }
        }
        if (g + 1 < km->k && try_lost(x, g, hopeless)) return -1;
    }
    return 0;
}

/* A move as a key: its kind and the vertices it acts on (the edge for a
 * flip or a split, the directed edge for a collapse, the triangle for
 * the rest). */
static uint64_t move_key(const cm_kmesh *km, enum pmove kind, int32_t c)
{
    uint64_t a = (uint32_t)km->tri[c], b = (uint32_t)km->tri[cm_next(c)], d = (uint32_t)km->tri[cm_prev(c)];
    if (kind == PM_FLIP || kind == PM_SPLIT) a = b < d ? b : d, b = b < d ? d : b;
    else if (kind != PM_COLLAPSE) a = a * 0x9E3779B97F4A7C15ull ^ b * 0xC2B2AE3D27D4EB4Full ^ d, b = 0;
    return (uint64_t)kind << 60 ^ a << 30 ^ b;
}

static struct cm_pmove_failed *failed_before(mover *x, uint64_t key)
{
    cm_pmove_memo *memo = x->memo;
    for (size_t i = 0; i < memo->n; i++)
        if (memo->failed[i].key == key) return &memo->failed[i];
    return NULL;
}

/* The vertices a move on corner c acts on (-1: none), its ring's seeds. */
static void own_vertices(const cm_kmesh *km, int32_t c, int32_t own[4])
{
    own[0] = km->tri[c], own[1] = km->tri[cm_next(c)], own[2] = km->tri[cm_prev(c)];
    own[3] = km->opp[c] >= 0 ? km->tri[km->opp[c]] : -1;
}

static int remember_failed(mover *x, uint64_t key, int32_t c)
{
    cm_pmove_memo *memo = x->memo;
    void *p = memo->failed;
    if (cm_grow(&p, &memo->cap, memo->n + 1, sizeof *memo->failed)) return -1;
    memo->failed = p;
    struct cm_pmove_failed *f = &memo->failed[memo->n++];
    f->key = key, f->round = memo->round;
    own_vertices(x->km, c, f->own);
    return 0;
}

/* After a kept move (its ring in x->ring): forgets the undone moves with
 * a vertex within CM_PMOVE_REACH rings of the ring. 0, or -1 out of
 * memory. */
static int forget_near(mover *x)
{
    cm_kmesh *km = x->km;
    uint32_t stamp = cm_kmesh_new_stamp(km);
    for (size_t i = 0; i < x->ring.n; i++) km->mark[x->ring.a[i]] = stamp;
    if (grow_rings(x, CM_PMOVE_REACH, stamp)) return -1;
    cm_pmove_memo *memo = x->memo;
    size_t kept = 0;
    for (size_t i = 0; i < memo->n; i++) {
        const struct cm_pmove_failed *f = &memo->failed[i];
        int near = 0;
        for (int j = 0; j < 4; j++) near |= f->own[j] >= 0 && km->mark[f->own[j]] == stamp;
        if (!near) memo->failed[kept++] = *f;
    }
    memo->n = kept;
    return 0;
}

/* One move on corner c (its edge: flip, split; its vertex onto the next:
 * collapse; its triangle: polish alone, insertion) with the local
 * polish, as a transaction kept when the ring's smallest slack rose and
 * no triangle fell below `least` (the whole mesh's smallest angle).
 * Returns 1 kept, 0 undone or impossible, -1 out of memory or cancelled. */
static int try_move(mover *x, enum pmove kind, int32_t c, double least)
{
    cm_kmesh *km = x->km;
    int32_t t = c / 3, o = km->opp[c];
    /* a boundary edge splits only where the polish slides its points
     * (the variant measured: bench/REMESH.md) */
    if ((kind == PM_FLIP || (kind == PM_SPLIT && !x->slide)) && o < 0) return 0;
    if (kind == PM_COLLAPSE && cm_kmesh_is_boundary(km, km->tri[c])) return 0;
    int32_t seeds[4];
    own_vertices(km, c, seeds);
    x->slides = 0;
    double before, after, key;
    if (rings(x, seeds, 4) || ring_quality(x, km->k, &before, &key) || cm_kmesh_tx_begin(km)) return -1;
    x->need = before + (kind == PM_POLISH ? CM_PMOVE_POLISH_GAIN : CM_PMOVE_GAIN), x->least = least;
    int done = 0;
    if (kind == PM_POLISH) {
        done = 1;
    } else if (kind == PM_FLIP) {
        done = cm_flip_if_valid(km, c);
    } else if (kind == PM_COLLAPSE) {
        done = cm_collapse_try(km, c, &x->star);
    } else {
        static const double centroid[3] = {1.0 / 3, 1.0 / 3, 1.0 / 3};
        int32_t m = kind == PM_SPLIT ? cm_refine_split(km, c) : cm_insert_bary(km, t, centroid);
        done = m >= 0 ? 1 : m == CM_SPLIT_NO_FIT ? 0 : -1;
        if (m >= 0 && cm_ibuf_push(&x->ring, m)) done = -1;
    }
    if (done <= 0) {
        cm_kmesh_tx_commit(km); /* nothing changed */
        return done;
    }
    int hopeless;
    if (polish_ring(x, &hopeless) || (!hopeless && ring_quality(x, km->k, &after, &key)))
        return cm_kmesh_tx_commit(km), -1;
    if (!hopeless && after > x->need && key >= least) {
        cm_kmesh_tx_commit(km);
        if (x->slide) x->slide->slid += x->slides;
        return 1;
    }
    return cm_kmesh_tx_rollback(km) ? -1 : 0;
}

static int tries_left(const mover *x, long tries, long idle)
{
    return tries < x->limits->tries && idle < x->limits->idle && !cm_deadline_passed();
}

long cm_polish_moves(cm_kmesh *km, const cm_pmove_limits *limits, long steiner_left, cm_maxmin_slide *slide,
                     cm_pmove_memo *memo, cm_progress *progress)
{
    cm_pmove_memo own = {0};
    mover x = {.km = km, .progress = progress, .slide = slide && km->bt ? slide : NULL, .limits = limits,
               .memo = memo ? memo : &own};
    /* a memo of tries made otherwise says nothing of these */
    if (x.memo->n && (x.memo->iterations != limits->iterations || x.memo->slides != (x.slide != NULL)))
        x.memo->n = 0;
    x.memo->iterations = limits->iterations, x.memo->slides = x.slide != NULL;
    x.memo->round++; /* the moves undone in earlier calls are counted once here */
    if (x.slide) {
        x.labels = *slide;
        x.edge_rows = calloc(km->k, sizeof *x.edge_rows), x.t_rows = calloc(km->k, sizeof *x.t_rows);
        if (!x.edge_rows || !x.t_rows) {
            free(x.edge_rows), free(x.t_rows);
            return -1;
        }
    }
    int32_t worst[CM_PMOVE_WORST], work[2 * CM_PMOVE_WORST], near[12];
    long tries = 0, kept = 0, idle = 0;
    double least = cm_kmesh_min_angle(km);
    while (tries_left(&x, tries, idle) && cm_kmesh_min_slack(km) < 0) {
        int32_t nw = cm_heap_smallest(&km->tq, CM_PMOVE_WORST, 0.0, worst, work);
        int gained = 0;
        for (int32_t i = 0; i < nw && !gained && tries_left(&x, tries, idle); i++) {
            if (!cm_kmesh_tri_live(km, worst[i])) continue;
            int m = cm_kmesh_corners_near(km, worst[i], near);
            for (int kind = 0; kind < PM_KINDS && !gained && tries_left(&x, tries, idle); kind++) {
                int adds = kind == PM_SPLIT || kind == PM_INSERT;
                if (adds && steiner_left <= 0) continue;
                /* the polish alone and an insertion: on the worst triangle only */
                int mk = kind == PM_POLISH || kind == PM_INSERT ? 1 : m;
                for (int j = 0; j < mk && !gained && tries_left(&x, tries, idle); j++) {
                    if (km->tri[near[j]] < 0) continue;
                    uint64_t key = move_key(km, (enum pmove)kind, near[j]);
                    struct cm_pmove_failed *f = failed_before(&x, key);
                    if (f && f->round == x.memo->round) continue;
                    if (f) { /* undone again (cm_pmove_failed): counted, not run */
                        f->round = x.memo->round, tries++, idle++;
                        continue;
                    }
                    int s = try_move(&x, (enum pmove)kind, near[j], least);
                    tries++, idle++;
                    if (s < 0 || (s == 0 && remember_failed(&x, key, near[j])) || (s > 0 && forget_near(&x))) {
                        kept = -1;
                        goto done;
                    }
                    if (s > 0) {
                        gained = 1, kept++, steiner_left -= adds, idle = 0;
                        x.memo->round++;
                        least = cm_kmesh_min_angle(km);
                    }
                }
            }
        }
        if (!gained) break;
    }
done:
    cm_ibuf_free(&x.star), cm_ibuf_free(&x.ring), cm_ibuf_free(&x.var), cm_ibuf_free(&x.tris), cm_ibuf_free(&x.gvar);
    free(x.pts), free(x.pts_t), free(x.next), free(x.prev);
    cm_pmove_memo_free(&own);
    for (size_t g = 0; x.slide && g < km->k; g++) free(x.edge_rows[g]), free(x.t_rows[g]);
    free(x.edge_rows), free(x.t_rows);
    return kept;
}
