/* Algorithm 1 (compatible remeshing), preceded by a cleanup that removes
 * the construction's surplus Steiner vertices and followed by a coarsening
 * that removes those the result does not need:
 *
 *   collapse Steiner vertices wherever valid; flips + smoothing
 *   while a triangle falls short of its target and the budget lasts:
 *       split up to k_split edges (eq. 5), each followed by flips +
 *       smoothing around it
 *       every area_every rounds: area equalisation; flips + smoothing
 *   flips + smoothing everywhere
 *   while a move gains: forced moves around the worst triangles
 *   collapse Steiner vertices where no angle drops below the target
 *   flips + smoothing everywhere
 *
 * "flips + smoothing" alternates compatible flips with smart smoothing of
 * each geometry until nothing improves, driven by work lists, so a split
 * costs work near it only. Where the smoothing formulas are stuck beside a
 * triangle short of its target, a small search for the best position
 * takes over (cm_smooth_optimize).
 *
 * Each split (with its repair) and each area equalisation is a
 * transaction: it is undone when the smallest angle of the triangles it
 * changed went down, so refinement never makes the mesh worse; an edge
 * whose split was undone twice is not tried again. Refinement stops at the
 * target, the Steiner budget, the round cap, or when the smallest angle
 * has stopped rising and the triangles short of their aim have stopped
 * falling in number. The greedy operations then sit in a local optimum;
 * forced moves step back from it (a flip the angle rule refuses, the
 * removal of a Steiner vertex, a split, each followed by the repair) and
 * are kept only when the triangles they changed end up better. What is
 * left after that is beyond local repair (typically a correspondence that
 * forces a strong distortion: bench/correspondence_bound.py measures it).
 *
 * The map-aware remesher (CM_REMESHER_MAP) runs a start before the
 * refinement: the Steiner vertices of every geometry move to lower the
 * conformal distortion of the maps between the geometries (mapopt), and
 * vertices go where a triangle is poor in the metric halfway between them
 * (maprefine), each insertion kept only where no angle dropped; its forced
 * moves also try an insertion at the middle circumcentre of a short
 * triangle. When the greedy remesher ends below CM_RESCUE_SHARE of its
 * aim, the map-aware one runs on the same construction and the better
 * result is kept; when that is short of it too, its forced moves run
 * again around the CM_STEP_OUT_WIDE worst triangles instead of the
 * CM_STEP_OUT_WORST.
 *
 * The result written, the joint max-min polish moves its vertices
 * (maxmin.c); where the worst triangle has reached a share of its aim
 * (cm_pmove_limits: lower where boundary edges may be split), moves
 * scored by that polish (polish_moves.c) then change the connectivity
 * the polish cannot, and the mesh is written again. Where the
 * correspondence is the tool's to choose, a second round of those moves
 * follows in which boundary edges split too and the polish slides
 * boundary points along their input edges, as the joint polish does:
 * after the first round, so that it starts from what that round reached
 * (run alone, its different path ended lower on 7 of 88 glyph pairs).
 *
 * Where the result ends below CM_RESTART_BELOW of its aim, up to
 * o->restarts restarts follow: the CM_RESTART_SHARE of the triangles
 * whose affine maps between the geometries are most distorted are split
 * (restart.h), and the whole run (without the cleanup, which would undo
 * the split) starts again from there; its result is kept when its
 * smallest angle is higher by CM_RESTART_GAIN. What holds the greedy run
 * is its connectivity's map, not where its vertices are, and from a
 * denser start in the distorted part it reaches a less distorted one
 * (bench/REMESH.md). */
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "remesh/remesh.h"
#include "remesh/areaeq.h"
#include "remesh/collapse.h"
#include "remesh/criteria.h"
#include "remesh/flip.h"
#include "remesh/mapopt.h"
#include "remesh/maxmin.h"
#include "remesh/maprefine.h"
#include "remesh/polish_moves.h"
#include "remesh/refine.h"
#include "remesh/restart.h"
#include "remesh/smooth.h"
#include "base/clock.h"
#include "base/deadline.h"
#include "base/keymap.h"
#include "geom/angle.h"
#ifdef CM_REMESH_TRACE
#include <stdio.h>
#include <time.h>
#endif

/* Sweeps of flips + smoothing after one split; the polish sweeps over the
 * whole mesh at the end. */
#define CM_IMPROVE_SWEEPS 4
#define CM_POLISH_SWEEPS 16
/* Undone splits of one edge before it is given up. */
#define CM_SPLIT_TRIES 2
/* Refinement stops when the smallest angle has not risen by CM_PROGRESS
 * (radians, about 0.06 degrees; below 2 degrees, by 3 % of itself: slivers
 * of a fraction of a degree rise in small steps) over stall_limit()
 * splits. */
#define CM_PROGRESS 1e-3
#define CM_PROGRESS_SHARE 0.03
/* Rounds of at least CM_IDLE_ROUND_MIN splits also stop it after
 * CM_IDLE_ROUNDS of them in a row that neither raised the smallest angle
 * nor left fewer triangles short of their aim than ever before: where what
 * falls short cannot be helped (a sliver at a corner the ceiling binds),
 * the splits kept as harmless only add vertices, and at 1 % of a large
 * mesh's triangles per round the stall limit (about n / 4 splits) would
 * let that go on for rounds of thousands. Smaller rounds (meshes under
 * 10,000 triangles) leave it to the stall limit: their short triangles
 * can stay put for 16 rounds and still rise later (a spiral against a
 * disc at n = 1,000 stopped at 3.0 degrees with rounds of 16, 3.5 without). */
#define CM_IDLE_ROUNDS 16
#define CM_IDLE_ROUND_MIN 100
/* A greedy result whose smallest angle ends below this share of its aim
 * is also remeshed by the map-aware remesher. */
#define CM_RESCUE_SHARE 0.3
/* The share of the triangles, the most distorted, a restart splits
 * (bench/REMESH.md, "Restarts from the result split where its map is
 * most distorted"). */
#define CM_RESTART_SHARE 0.1
/* Restarts run where a triangle ends below this share of its own aim
 * (cm_kmesh_min_share): stars held by their sharp corners sit at it and
 * gain nothing for the time; glyph pairs at 0.7 to 0.85 of it gain 8 to
 * 20 % (bench/REMESH.md, "Restarts up to 0.85 of the aim"). */
#define CM_RESTART_BELOW 0.85
/* The stall limit of a first run below the restart's gate, as a share of
 * the limit: the restart starts from its result split where its map is
 * most distorted and refines again, so the splits a first run adds late,
 * for gains the restart makes anyway, are mostly paid twice (bench/REMESH.md,
 * "A shorter first run below the restart's gate"). */
#define CM_STALL_BEFORE_RESTART 0.6
/* A run whose polished result is below this share of the result it
 * competes with (beat_deg) skips the polish-scored moves: over the 279
 * runs of auto's 166 glyph pairs they raised a result at most 2.01
 * times, and 1.5 to 1.7 times on the few others that gained most
 * (bench/REMESH.md, "Pairings that cannot win"). */
#define CM_REMESH_BEHIND 0.45
/* A restart's result is kept when its smallest angle is this much
 * higher, relatively: it often doubles the vertices, which a gain of 1 or
 * 2 % does not pay for (the paper's U and S: 20.06 -> 20.41 degrees for
 * 23 -> 72 Steiner vertices). */
#define CM_RESTART_GAIN 0.02
/* The short triangles a round of forced moves looks at; the wider
 * window where both remeshers ended below CM_RESCUE_SHARE of the aim
 * (a distortion the correspondence forces spreads the worst triangles
 * over a region: the first 8 are often all at one equilibrium, and a move
 * that gains sits beside them). */
#define CM_STEP_OUT_WORST 8
#define CM_STEP_OUT_WIDE 64
/* The forced moves the wider window may try: on the hard family its
 * gains come within about 9,000 tries, but a distortion spread over a
 * large region kept it trying for 30,000 (16 s on a 160-vertex pair) for
 * the last half degree. */
#define CM_STEP_OUT_WIDE_TRIES 12000
/* A forced move whose repair ends this close below its start (radians,
 * about 0.1 degrees) gets a second repair before the decision: an
 * undone move is not tried again till the mesh near it changes
 * (step_out), and such a move was often kept on a later try before. */
#define CM_FORCED_CLOSE 0.002
/* A forced move's repair is given up after its first sweep when the
 * triangles it changed are below this share of their smallest angle
 * before: on the tuning pairs 1 in 500 of those repairs ended in a gain
 * (against 1 in 60 of all), and a repair is most of a try's cost. */
#define CM_FORCED_GIVE_UP 0.6
/* Times a forced move may be undone in one step_out: on the tuning
 * pairs a move undone three times or more was kept on 0.6 % of its later
 * tries (a fresh one on 3 %), and those were 40 % of all tries, most in
 * the wide window; at twice an auto glyph pair lost 7 % of its angle. */
#define CM_FORCED_UNDONE 3
/* L-BFGS iterations per geometry of the joint polish (maxmin.c). It
 * ends at this cap still rising: 800 instead of 400 raised 65 of the 147
 * index pairs (1 fell) and the auto glyph pairs at c/2 from 43 to 50 for
 * 8-9 % more CPU; 1,600 gave 0.7 % (index) and 1.3 % (auto) more angle
 * for 14-16 % more CPU. */
#define CM_MAXMIN_ITERATIONS 800

/* Forced moves undone in step_out, with where they acted: the vertices
 * of the triangles their transaction changed and of the move's own
 * triangles. Such a move runs again only once a kept move has moved or
 * reconnected a vertex within a ring of those vertices (till then it
 * meets what it met before), and not after CM_FORCED_UNDONE undos. */
typedef struct failed_moves {
    cm_keymap at;     /* move key -> its entry + 1 */
    cm_ibuf entries;  /* 4 per entry: epoch when last undone, offset and length in region, times undone */
    cm_ibuf region;
    uint32_t *changed; /* vertex -> epoch of the last kept move within a ring of it */
    size_t cap;
    uint32_t epoch;
} failed_moves;

typedef struct remesher {
    cm_kmesh km;
    cm_work verts, edges;
    cm_ibuf star, batch;
    cm_keymap tabu;   /* vertex pairs -> splits tried there */
    failed_moves failed;
    cm_ibuf around;
    const cm_options *o;
    cm_progress *progress;
    double target; /* radians */
    long flips;
    long spent;    /* Steiner vertices added before refine() */
    /* A restart's run (cm_remesh): no cleanup coarsening, which would
     * collapse the split start, and a late one that keeps the smallest
     * angle reached instead of the target. */
    int restarting;
} remesher;

/* ---- progress trace (cmake -DCM_REMESH_TRACE=ON; never in a release) ------ */

#ifdef CM_REMESH_TRACE
/* One line per step to stderr, for bench/remesh_curve.py: the remesher
 * (0 greedy, 1 map-aware), the step, the process's CPU seconds less what
 * the trace itself spent, the smallest angle (degrees), the Steiner
 * vertices and the forced moves tried so far. */
static double trace_spent;
static long trace_forced;

static double trace_cpu(void) { return (double)clock() / CLOCKS_PER_SEC; }

static void trace_line(const remesher *x, const char *step, double (*angle)(const void *), const void *of,
                       long steiner)
{
    double t0 = trace_cpu();
    fprintf(stderr, "cm_trace %d %s %.6f %.9g %ld %ld\n", (int)x->o->remesher, step, t0 - trace_spent,
            angle(of) * 180.0 / CM_PI, steiner, trace_forced);
    trace_spent += trace_cpu() - t0;
}

static double kmesh_angle(const void *km) { return cm_kmesh_min_angle(km); }

/* A step of the remesher's working mesh. */
static void trace(const remesher *x, const char *step)
{
    trace_line(x, step, kmesh_angle, &x->km, (long)(x->km.live_v - x->km.n));
}
#define TRACE_FORCED() (trace_forced++)
#else
#define trace(x, step) ((void)0)
#define TRACE_FORCED() ((void)0)
#endif

/* ---- edges not to split again --------------------------------------------- */

/* key's count in t (0: not there). */
static uint32_t tabu_count_key(const cm_keymap *t, uint64_t key)
{
    const int64_t *v = cm_keymap_find(t, key);
    return v ? (uint32_t)*v : 0;
}

static int tabu_count(const cm_keymap *t, int32_t a, int32_t b)
{
    return tabu_count_key(t, cm_pair_key(a, b));
}

/* Sets key's count to count(old) (a new key: old = 0). */
static int tabu_set_key(cm_keymap *t, uint64_t key, uint32_t (*count)(uint32_t, uint32_t), uint32_t arg)
{
    int added;
    int64_t *v = cm_keymap_put(t, key, &added);
    if (!v) return -1;
    *v = count((uint32_t)*v, arg);
    return 0;
}

static uint32_t count_up(uint32_t old, uint32_t times) { return old + times > 200 ? 200 : old + times; }
static uint32_t count_is(uint32_t old, uint32_t value) { return (void)old, value; }

static int tabu_add(cm_keymap *t, int32_t a, int32_t b, int times)
{
    return tabu_set_key(t, cm_pair_key(a, b), count_up, (uint32_t)times);
}

/* ---- flips and smoothing -------------------------------------------------- */

/* Queues v's neighbours for smoothing and the edges around v for flips. */
static int queue_around(remesher *x, int32_t v)
{
    cm_kmesh *km = &x->km;
    long m = cm_kmesh_star(km, v, &x->star);
    if (m < 0) return -1;
    for (long i = 0; i < m; i++) {
        int32_t c = x->star.a[i];
        if (cm_work_push(&x->verts, km->tri[cm_next(c)]) || cm_work_push(&x->edges, c) ||
            cm_work_push(&x->edges, cm_next(c)) || cm_work_push(&x->edges, cm_prev(c)))
            return -1;
    }
    return cm_kmesh_is_boundary(km, v) ? 0 : cm_work_push(&x->verts, v);
}

/* Is a triangle around v (its star in x->star) among the furthest from
 * its target, short of it by at least half the worst shortfall? The
 * position search is worth its cost there. */
static int near_short(remesher *x)
{
    double gate = fmin(0.0, 0.5 * cm_kmesh_min_slack(&x->km));
    for (size_t i = 0; i < x->star.n; i++)
        if (x->km.slack[x->star.a[i] / 3] < gate) return 1;
    return 0;
}

/* Smooths interior live v in every geometry. Returns 1 if it moved, -1
 * out of memory. Where the smoothing formulas left v in place and nothing
 * around it has changed in that geometry since, they would leave it
 * again: skipped. Moves keep v's star, so it is found once. */
static int smooth_one(remesher *x, int32_t v)
{
    cm_kmesh *km = &x->km;
    long m = cm_kmesh_star(km, v, &x->star);
    if (m < 0) return m == -1 ? -1 : 0;
    int moved = 0;
    int search = near_short(x); /* the same after a move left undone */
    for (size_t g = 0; g < km->k; g++) {
        int s = cm_smooth_then_search(km, g, v, x->o->smoothing, &x->star, search);
        if (s) search = near_short(x);
        moved |= s;
    }
    return moved;
}

/* Smooths every queued vertex once; a vertex that moved queues its
 * surroundings for the next sweep. Returns moves or -1 (stop). */
static long smooth_queued(remesher *x)
{
    cm_kmesh *km = &x->km;
    x->batch.n = 0;
    for (int32_t v; (v = cm_work_pop(&x->verts)) >= 0;)
        if (!cm_kmesh_is_boundary(km, v) && km->vc[v] >= 0 && cm_ibuf_push(&x->batch, v)) return -1;
    long moves = 0;
    for (size_t i = 0; i < x->batch.n; i++) {
        if (cm_progress_check(x->progress)) return -1;
        int32_t v = x->batch.a[i];
        int moved = smooth_one(x, v);
        if (moved < 0 || (moved && queue_around(x, v))) return -1;
        moves += moved;
    }
    return moves;
}

/* Why a step returned -1. */
static cm_status stop_status_of(const cm_progress *progress)
{
    return progress && progress->cancelled ? CM_ERR_CANCELLED : CM_ERR_NO_MEMORY;
}

static cm_status stop_status(const remesher *x) { return stop_status_of(x->progress); }

/* Flips and smoothing, alternated until neither changes anything or the
 * sweeps run out: both only ever raise local smallest angles. With
 * give_up > 0, given up after the first sweep when the open transaction's
 * triangles fell below give_up of their smallest angle before. Returns 0,
 * 1 given up, or -1 to stop: out of memory, or cancelled (x->progress
 * says which; so for every -1 of the remesher's steps). */
static int repair(remesher *x, int sweeps, double give_up)
{
    int gave_up = 0;
    for (int sweep = 0; sweep < sweeps; sweep++) {
        if (cm_progress_check(x->progress)) return -1;
        long f = cm_flip_queue(&x->km, &x->edges, &x->verts);
        if (f < 0) return -1;
        x->flips += f;
        long moves = smooth_queued(x);
        if (moves < 0) return -1;
        if (give_up > 0 && sweep == 0 && sweeps > 1) {
            double before, after;
            if (cm_kmesh_tx_region(&x->km, &before, &after)) return -1;
            if (after < give_up * before) {
                gave_up = 1;
                break;
            }
        }
        if (moves == 0 && x->edges.items.n == 0) break;
    }
    while (cm_work_pop(&x->verts) >= 0) {} /* past the last sweep: drop the rest */
    while (cm_work_pop(&x->edges) >= 0) {}
    return gave_up;
}

/* repair() never given up: 0, or -1 to stop. */
static int improve(remesher *x, int sweeps) { return repair(x, sweeps, 0); }

static int improve_everywhere(remesher *x)
{
    if (cm_flip_queue_all(&x->km, &x->edges)) return -1;
    for (int32_t v = x->km.n; v < x->km.nv; v++)
        if (x->km.vc[v] >= 0 && !cm_kmesh_is_boundary(&x->km, v) && cm_work_push(&x->verts, v)) return -1;
    return improve(x, CM_POLISH_SWEEPS);
}

/* Moves the touched vertices' surroundings into the work lists. */
static int queue_touched(remesher *x, cm_work *touched)
{
    for (int32_t v; (v = cm_work_pop(touched)) >= 0;)
        if (x->km.vc[v] >= 0 && queue_around(x, v)) return -1;
    return 0;
}

/* ---- transactions ----------------------------------------------------------- */

/* A gain of `gain` radians, or of CM_PROGRESS_SHARE of the angle
 * `before` when that is less: a sliver of a fraction of a degree rises
 * in small steps (as in refine's progress rule). */
static double progress_needed(double gain, double before)
{
    return fmin(gain, CM_PROGRESS_SHARE * before);
}

/* Keeps the open transaction if the smallest angle of the triangles it
 * changed rose by at least progress_needed(gain, ...) (radians; gain 0:
 * did not drop; else it must rise), else undoes it. Returns 1 kept,
 * 0 undone, -1 out of memory. */
static int settle_by(remesher *x, double gain)
{
    double before, after;
    if (cm_kmesh_tx_region(&x->km, &before, &after)) {
        cm_kmesh_tx_commit(&x->km);
        return -1;
    }
    if (after >= before + progress_needed(gain, before) && (gain == 0 || after > before)) {
        cm_kmesh_tx_commit(&x->km);
        return 1;
    }
    return cm_kmesh_tx_rollback(&x->km) ? -1 : 0;
}

static int settle(remesher *x) { return settle_by(x, 0.0); }

/* Splits the edge opposite c and repairs around the new vertex, as one
 * transaction. Returns 1 kept, 0 undone or impossible, -1 out of memory. */
static int try_split(remesher *x, int32_t c)
{
    cm_kmesh *km = &x->km;
    int32_t a = km->tri[cm_next(c)], b = km->tri[cm_prev(c)];
    if (cm_kmesh_tx_begin(km)) return -1;
    int32_t m = cm_refine_split(km, c);
    if (m == CM_NO_MEMORY) return cm_kmesh_tx_commit(km), -1;
    if (m == CM_SPLIT_NO_FIT) {
        cm_kmesh_tx_commit(km);
        cm_kmesh_forget_candidate(km, c);
        return tabu_add(&x->tabu, a, b, CM_SPLIT_TRIES) ? -1 : 0;
    }
    if (queue_around(x, m) || improve(x, CM_IMPROVE_SWEEPS)) return cm_kmesh_tx_commit(km), -1;
    int kept = settle(x);
    if (kept != 0) return kept;
    cm_kmesh_forget_candidate(km, c); /* restored: c is that edge again */
    return tabu_add(&x->tabu, a, b, 1) ? -1 : 0;
}

/* One area equalisation sweep and its repair, as a transaction. */
static int try_area_equalisation(remesher *x)
{
    cm_work touched = {0};
    int s = cm_kmesh_tx_begin(&x->km) ? -1 : 0;
    if (s == 0 && (cm_areaeq_pass(&x->km, &touched) < 0 || queue_touched(x, &touched) ||
                   improve(x, CM_IMPROVE_SWEEPS)))
        s = -1;
    cm_work_free(&touched);
    if (s < 0) {
        cm_kmesh_tx_commit(&x->km);
        return -1;
    }
    return settle(x) < 0 ? -1 : 0;
}

/* ---- the refinement loop ---------------------------------------------------- */

/* Is the edge opposite c still a candidate worth a try? */
static int worth_trying(remesher *x, int32_t c)
{
    cm_kmesh *km = &x->km;
    if (km->tri[c] < 0 || (km->opp[c] < 0 && !km->between)) return 0;
    int32_t rep = km->opp[c] < 0 || c < km->opp[c] ? c : km->opp[c];
    if (!cm_heap_contains(cm_kmesh_candidates(km), rep)) return 0;
    if (tabu_count(&x->tabu, km->tri[cm_next(c)], km->tri[cm_prev(c)]) < CM_SPLIT_TRIES) return 1;
    cm_kmesh_forget_candidate(km, c);
    return 0;
}

static long budget_of(const cm_options *o, size_t n)
{
    return o->max_steiner >= 0 ? o->max_steiner : 2 * (long)n + 100;
}

/* Is this a first run with its boundary fixed (index correspondence)
 * whose worst triangle is below CM_RESTART_BELOW of its aim, the
 * restart's gate? Not whether restarts were asked for: a first run is the
 * same with and without them. Where boundary points may be added, the
 * late splits also refine the loops the restart starts from: left as
 * they were. */
static int restart_ahead(const remesher *x)
{
    return !x->restarting && !x->km.between && cm_kmesh_min_share(&x->km) < CM_RESTART_BELOW;
}

/* Splits without progress before refinement stops, and rounds of forced
 * moves; CM_STALL_BEFORE_RESTART of it where a restart will follow. */
static long stall_limit(const remesher *x)
{
    long limit = 30 + x->km.n / 4;
    return restart_ahead(x) ? (long)(CM_STALL_BEFORE_RESTART * (double)limit) : limit;
}

/* Splits per round: the option, or about 1 % of the triangles. */
static long round_size(const remesher *x)
{
    return x->o->k_split > 0 ? x->o->k_split : (long)fmax(1, x->km.live_t / 100);
}

/* One round: up to ks splits among the best candidates, no two sharing a
 * vertex. Returns the splits kept, CM_NO_MEMORY, or CM_NO_CANDIDATES.
 * *tried counts the attempts. */
#define CM_NO_CANDIDATES (-2)
static long split_round(remesher *x, long ks, int32_t *cand, long want, long *tried)
{
    cm_kmesh *km = &x->km;
    long nc = cm_refine_candidates(km, want, cand), kept = 0;
    uint32_t stamp = cm_kmesh_new_stamp(km);
    for (long i = 0; i < nc && kept < ks; i++) {
        int32_t c = cand[i];
        if (!worth_trying(x, c) || !cm_refine_take_quad(km, c, stamp)) continue;
        int s = try_split(x, c);
        if (s < 0) return -1;
        kept += s, ++*tried;
    }
    return nc == 0 ? CM_NO_CANDIDATES : kept;
}

/* Live triangles short of their aim. */
static long short_count(const cm_kmesh *km)
{
    long count = 0;
    for (int32_t t = 0; t < km->nt; t++) count += cm_kmesh_tri_live(km, t) && km->slack[t] < 0;
    return count;
}

/* CM_OK, CM_ERR_NO_MEMORY or CM_ERR_CANCELLED. */
static cm_status refine(remesher *x, size_t n, cm_remesh_report *rep)
{
    cm_kmesh *km = &x->km;
    long budget = budget_of(x->o, n) - x->spent, added = 0, attempts = 0, since_best = 0;
    long fewest = short_count(km), idle = 0;
    double best = cm_kmesh_min_angle(km);
    int32_t *cand = NULL;
    while (cm_kmesh_min_slack(km) < 0 && added < budget && since_best < stall_limit(x) &&
           idle < CM_IDLE_ROUNDS && attempts < 4 * budget + 100 &&
           (x->o->max_iterations <= 0 || rep->iterations < (size_t)x->o->max_iterations) && !cm_deadline_passed()) {
        long ks = round_size(x), want = 4 * ks + 8;
        if (ks > budget - added) ks = budget - added;
        int32_t *more = realloc(cand, (size_t)want * 3 * sizeof *cand);
        if (!more) goto oom;
        cand = more;
        long kept = split_round(x, ks, cand, want, &attempts);
        if (kept == CM_NO_MEMORY) goto oom;
        if (kept == CM_NO_CANDIDATES) break;
        added += kept, rep->splits += kept, rep->iterations++;
        double now = cm_kmesh_min_angle(km);
        long shorts = short_count(km);
        int rose = now > best + fmin(CM_PROGRESS, CM_PROGRESS_SHARE * best);
        if (rose) best = now, since_best = 0;
        else since_best += kept > 0 ? kept : 1;
        idle = rose || shorts < fewest || round_size(x) < CM_IDLE_ROUND_MIN ? 0 : idle + 1;
        fewest = shorts < fewest ? shorts : fewest;
        if (x->o->area_every > 0 && rep->iterations % (size_t)x->o->area_every == 0 &&
            try_area_equalisation(x))
            goto oom;
        trace(x, "refine");
        double done = fmin(1.0, fmax(1 + cm_kmesh_min_slack(km) / x->target, (double)added / budget));
        if (cm_progress_poll(x->progress, CM_STAGE_REMESH, done)) {
            free(cand);
            return CM_ERR_CANCELLED;
        }
    }
    rep->split_attempts = attempts;
    free(cand);
    return CM_OK;
oom:
    free(cand);
    return stop_status(x);
}

/* ---- stepping out of local optima ------------------------------------------ */

enum forced_move { FORCED_FLIP, FORCED_COLLAPSE, FORCED_SPLIT, FORCED_INSERT, FORCED_MOVES };
enum forced_result { FORCED_OUT_OF_MEMORY = -1, FORCED_UNDONE, FORCED_KEPT, FORCED_IMPOSSIBLE };

/* A move the greedy rules refuse, on the edge opposite c (flip, split),
 * on its corner vertex (collapse onto the next) or in its triangle (the
 * map-aware remesher: an insertion at the middle circumcentre), then the
 * repair (twice when the first ends close to a gain, given up when its
 * first sweep ends far below: CM_FORCED_GIVE_UP), as one transaction
 * kept only if the smallest angle of the triangles it changed rose.
 * around: the move's own vertices (-1: none), the new one last. */
static enum forced_result try_forced(remesher *x, enum forced_move kind, int32_t c, int32_t around[5])
{
    cm_kmesh *km = &x->km;
    around[0] = around[1] = around[2] = around[3] = around[4] = -1;
    if (km->tri[c] < 0 || (kind == FORCED_FLIP && km->opp[c] < 0) || (kind == FORCED_SPLIT && km->opp[c] < 0 && !km->between))
        return FORCED_IMPOSSIBLE;
    if (kind == FORCED_INSERT && c % 3) return FORCED_IMPOSSIBLE; /* once per triangle */
    if (kind == FORCED_COLLAPSE && cm_kmesh_is_boundary(km, km->tri[c])) return FORCED_IMPOSSIBLE;
    around[0] = km->tri[c], around[1] = km->tri[cm_next(c)], around[2] = km->tri[cm_prev(c)];
    around[3] = km->opp[c] >= 0 ? km->tri[km->opp[c]] : -1;
    if (cm_kmesh_tx_begin(km)) return FORCED_OUT_OF_MEMORY;
    int done = 0;
    if (kind == FORCED_FLIP) {
        done = cm_flip_if_valid(km, c);
    } else if (kind == FORCED_COLLAPSE) {
        done = cm_collapse_try(km, c, &x->star);
    } else {
        int32_t m = kind == FORCED_SPLIT ? cm_refine_split(km, c) : cm_mid_insert(km, c / 3);
        done = m >= 0 ? 1 : m == CM_SPLIT_NO_FIT ? 0 : -1;
        around[4] = m;
    }
    if (done <= 0) {
        cm_kmesh_tx_commit(km); /* nothing changed */
        return done < 0 ? FORCED_OUT_OF_MEMORY : FORCED_IMPOSSIBLE;
    }
    for (int pass = 0; pass < 2; pass++) { /* the second: close to a gain (CM_FORCED_CLOSE) */
        for (int i = 0; i < 5; i++)
            if (around[i] >= 0 && km->vc[around[i]] >= 0 && queue_around(x, around[i]))
                return cm_kmesh_tx_commit(km), FORCED_OUT_OF_MEMORY;
        int r = repair(x, CM_IMPROVE_SWEEPS, CM_FORCED_GIVE_UP);
        if (r < 0) return cm_kmesh_tx_commit(km), FORCED_OUT_OF_MEMORY;
        if (r > 0) return cm_kmesh_tx_rollback(km) ? FORCED_OUT_OF_MEMORY : FORCED_UNDONE;
        double before, after;
        if (cm_kmesh_tx_region(km, &before, &after)) return cm_kmesh_tx_commit(km), FORCED_OUT_OF_MEMORY;
        if (after >= before + progress_needed(CM_PROGRESS, before) || after < before - CM_FORCED_CLOSE) break;
    }
    int kept = settle_by(x, CM_PROGRESS);
    return kept < 0 ? FORCED_OUT_OF_MEMORY : kept ? FORCED_KEPT : FORCED_UNDONE;
}

/* What a forced move changes, as a key: the edge for a flip or a split
 * (either of its corners names it), the directed edge for a collapse (the
 * vertex removed, the one it moves onto), the triangle (its first corner's
 * directed edge) for an insertion. */
static uint64_t forced_key(const cm_kmesh *km, enum forced_move kind, int32_t c)
{
    uint64_t a = (uint32_t)km->tri[c], b = (uint32_t)km->tri[cm_next(c)];
    if (kind == FORCED_FLIP || kind == FORCED_SPLIT) {
        uint64_t p = (uint32_t)km->tri[cm_next(c)], q = (uint32_t)km->tri[cm_prev(c)];
        a = p < q ? p : q, b = p < q ? q : p;
    }
    return ((uint64_t)kind << 62 | a << 31 | b) + 1;
}

static int grow_changed(failed_moves *f, size_t need)
{
    size_t old = f->cap;
    void *a = f->changed;
    if (cm_grow(&a, &f->cap, need, sizeof *f->changed)) return -1;
    f->changed = a;
    memset(f->changed + old, 0, (f->cap - old) * sizeof *f->changed);
    return 0;
}

/* Was the move `key` undone CM_FORCED_UNDONE times, or undone (or
 * impossible) with no kept move near where it acted since? */
static int still_failed(const failed_moves *f, uint64_t key)
{
    uint32_t e = tabu_count_key(&f->at, key);
    if (!e) return 0;
    const int32_t *entry = f->entries.a + 4 * (e - 1), *v = f->region.a + entry[1];
    if (entry[3] >= CM_FORCED_UNDONE) return 1;
    for (int32_t i = 0; i < entry[2]; i++)
        if ((size_t)v[i] < f->cap && f->changed[v[i]] > (uint32_t)entry[0]) return 0;
    return 1;
}

/* Records the move on corner c just undone (or, !undone, impossible):
 * where it acted, as the mesh is again. 0 or -1 out of memory. */
static int remember_failed(remesher *x, uint64_t key, int32_t c, int undone)
{
    failed_moves *f = &x->failed;
    cm_kmesh *km = &x->km;
    uint32_t old = tabu_count_key(&f->at, key);
    int32_t times = (old ? f->entries.a[4 * (old - 1) + 3] : 0) + (undone != 0);
    size_t off = f->region.n;
    if (cm_kmesh_tx_vertices(km, &f->region)) return -1;
    for (int i = 0; i < 3; i++)
        if (cm_ibuf_push(&f->region, km->tri[3 * (c / 3) + i])) return -1;
    if (km->opp[c] >= 0 && cm_ibuf_push(&f->region, km->tri[km->opp[c]])) return -1;
    size_t e = f->entries.n / 4;
    if (cm_ibuf_push(&f->entries, (int32_t)f->epoch) || cm_ibuf_push(&f->entries, (int32_t)off) ||
        cm_ibuf_push(&f->entries, (int32_t)(f->region.n - off)) || cm_ibuf_push(&f->entries, times))
        return -1;
    return tabu_set_key(&f->at, key, count_is, (uint32_t)e + 1);
}

/* After a kept move: its own vertices (`moved`, as try_forced gave
 * them) and their neighbours get a new epoch. Not every vertex its
 * repair moved: a repair spreads over a wide region, and the undone
 * moves there it woke again were kept half as often as moves tried
 * the first time (the same results on the quick bench set with a
 * sixth fewer tries). 0 or -1 out of memory. */
static int mark_changed(remesher *x, const int32_t moved[5])
{
    failed_moves *f = &x->failed;
    cm_kmesh *km = &x->km;
    x->around.n = 0;
    for (int i = 0; i < 5; i++)
        if (moved[i] >= 0 && km->vc[moved[i]] >= 0 && cm_ibuf_push(&x->around, moved[i])) return -1;
    if (grow_changed(f, (size_t)km->nv)) return -1;
    f->epoch++;
    for (size_t i = 0; i < x->around.n; i++) {
        int32_t v = x->around.a[i];
        long m = cm_kmesh_star(km, v, &x->star);
        if (m < 0) return -1;
        f->changed[v] = f->epoch;
        for (long j = 0; j < m; j++) {
            int32_t c = x->star.a[j];
            f->changed[km->tri[cm_next(c)]] = f->changed[km->tri[cm_prev(c)]] = f->epoch;
        }
    }
    return 0;
}

/* Forced moves around the `window` worst short triangles (at most
 * CM_STEP_OUT_WIDE), the first that gains
 * kept, until none gains, stall_limit() rounds have run, max_tries moves
 * have been tried or (splits) the budget is spent. CM_OK,
 * CM_ERR_NO_MEMORY or CM_ERR_CANCELLED. */
static cm_status step_out(remesher *x, size_t n, int32_t window, long max_tries)
{
    cm_kmesh *km = &x->km;
    int32_t worst[CM_STEP_OUT_WIDE], work[2 * CM_STEP_OUT_WIDE], near[12];
    long budget = budget_of(x->o, n);
    failed_moves *f = &x->failed;
    cm_keymap_clear(&f->at);
    f->entries.n = f->region.n = 0;
    long tries = 0;
    for (long round = 0;
         round < stall_limit(x) && cm_kmesh_min_slack(km) < 0 && tries < max_tries && !cm_deadline_passed(); round++) {
        if (cm_progress_poll(x->progress, CM_STAGE_REMESH, 1.0)) return CM_ERR_CANCELLED;
        int32_t nw = cm_heap_smallest(&km->tq, window, 0.0, worst, work);
        int gained = 0;
        /* An undone move leaves the mesh as it was (but for the position
         * search's flags), so each distinct move runs once till a kept
         * move changes the mesh near it: neighbouring worst triangles,
         * and the two corners of one edge, name the same move again. */
        for (int32_t i = 0; i < nw && !gained && tries < max_tries; i++) {
            if (!cm_kmesh_tri_live(km, worst[i])) continue;
            int m = cm_kmesh_corners_near(km, worst[i], near);
            for (int kind = 0; kind < FORCED_MOVES && !gained; kind++) {
                if ((kind == FORCED_SPLIT || kind == FORCED_INSERT) && km->live_v - km->n >= budget) continue;
                if (kind == FORCED_INSERT && x->o->remesher != CM_REMESHER_MAP) continue;
                for (int j = 0; j < m && !gained; j++) {
                    if (km->tri[near[j]] < 0) continue;
                    uint64_t key = forced_key(km, (enum forced_move)kind, near[j]);
                    if (still_failed(f, key)) continue;
                    int32_t moved[5];
                    enum forced_result s = try_forced(x, (enum forced_move)kind, near[j], moved);
                    tries++;
                    TRACE_FORCED();
                    if (s == FORCED_OUT_OF_MEMORY ||
                        (s != FORCED_KEPT && remember_failed(x, key, near[j], s == FORCED_UNDONE)) ||
                        (s == FORCED_KEPT && mark_changed(x, moved)))
                        return stop_status(x);
                    gained = s == FORCED_KEPT;
                }
            }
        }
        trace(x, gained ? "step" : "step_none");
        if (!gained) break;
    }
    return CM_OK;
}

/* ---- map-aware start ----------------------------------------------------------- */

/* The map-aware remesher's energy (mapopt.h): the shape term keeps each
 * geometry's triangles from degenerating while the map term leads (before
 * refinement), then both count alike; the terms as they are (power 1).
 * Global steps, then one-vertex sweeps. */
#define CM_MAP_SHAPE_FIRST 0.1
#define CM_MAP_SHAPE_AFTER 1.0
#define CM_MAP_POWER 1.0
#define CM_MAP_ITERATIONS 200
#define CM_MAP_SWEEPS 20
/* Middle-metric refinement aims at this share of each triangle's target;
 * it runs in CM_MAP_CYCLES cycles, each ending with the descent on the
 * finer mesh, with an equal share of the budget. */
#define CM_MAP_SHARE 1.0
#define CM_MAP_CYCLES 3
/* The share of the Steiner budget the middle-metric refinement may
 * spend; Algorithm 1 has the rest. */
#define CM_MAP_BUDGET 0.5

/* The map-aware start: the descent on the maps' distortion, then cycles
 * of middle-metric refinement, each followed by the descent on the finer
 * mesh. CM_OK, CM_ERR_NO_MEMORY or CM_ERR_CANCELLED. */
static cm_status map_start(remesher *x, size_t n, cm_remesh_report *rep)
{
    cm_mapopt_weights first = {1.0, CM_MAP_SHAPE_FIRST, CM_MAP_POWER}, after = {1.0, CM_MAP_SHAPE_AFTER, CM_MAP_POWER};
    long budget = (long)(CM_MAP_BUDGET * (double)budget_of(x->o, n)), start = x->km.live_v - x->km.n;
    if (cm_mapopt_run(&x->km, first, CM_MAP_ITERATIONS) < 0 || cm_mapopt_local(&x->km, first, CM_MAP_SWEEPS) < 0)
        return stop_status(x);
    for (int cycle = 1; cycle <= CM_MAP_CYCLES; cycle++) {
        if (cm_progress_poll(x->progress, CM_STAGE_REMESH, 0.5 * cycle / CM_MAP_CYCLES)) return CM_ERR_CANCELLED;
        long added = cm_mid_refine(&x->km, CM_MAP_SHARE, start + budget * cycle / CM_MAP_CYCLES, after);
        if (added < 0 || cm_mapopt_run(&x->km, after, CM_MAP_ITERATIONS) < 0 ||
            cm_mapopt_local(&x->km, after, CM_MAP_SWEEPS) < 0)
            return stop_status(x);
        rep->splits += added, x->spent += added;
        if (added == 0) break;
    }
    return CM_OK;
}

/* ---- cleanup and coarsening ------------------------------------------------- */

/* Removes Steiner vertices with collapses that pass `threshold`, then
 * repairs around them. Returns collapses or -1. */
static long coarsen(remesher *x, double threshold)
{
    cm_work touched = {0};
    long total = 0;
    for (int pass = 0; pass < 4; pass++) {
        long c = cm_collapse_pass(&x->km, threshold, -1, &touched);
        if (c < 0 || queue_touched(x, &touched) || improve(x, CM_IMPROVE_SWEEPS)) {
            cm_work_free(&touched);
            return -1;
        }
        total += c;
        if (c == 0) break;
    }
    cm_work_free(&touched);
    return total;
}

/* The boundary's caps (criteria.h), edge caps with their margin: bcap[0 .. n),
 * vcap = bcap + n, in *out; with `whole` (no boundary edge is ever split)
 * also what the vertices near each edge allow. Computed once, for every
 * run. */
static cm_status boundary_caps(const cm_mesh *mesh, size_t n, int whole, cm_progress *progress, double **out)
{
    double *bcap = *out = malloc(2 * n * sizeof *bcap);
    if (!bcap) return CM_ERR_NO_MEMORY;
    int s = cm_boundary_caps(mesh, n, progress, bcap, bcap + n);
    if (!s && whole) s = cm_near_vertex_caps(mesh, n, progress, bcap);
    if (s) {
        free(bcap), *out = NULL;
        return s == CM_CAPS_NOT_TRIANGULATED ? CM_ERR_INTERNAL : s == CM_CANCELLED ? CM_ERR_CANCELLED : CM_ERR_NO_MEMORY;
    }
    for (size_t i = 0; i < n; i++) bcap[i] *= CM_EDGE_CAP_MARGIN;
    return CM_OK;
}

static void set_caps(remesher *x, const double *bcap, size_t n, cm_remesh_report *rep)
{
    const double *vcap = bcap + n;
    double lo = x->target;
    for (size_t i = 0; i < n; i++) lo = fmin(lo, fmin(bcap[i], vcap[i]));
    cm_kmesh_set_caps(&x->km, x->target, bcap, vcap);
    rep->target_deg = lo * 180.0 / CM_PI;
}

static void remesher_free(remesher *x)
{
    cm_kmesh_free(&x->km);
    cm_work_free(&x->verts), cm_work_free(&x->edges);
    cm_ibuf_free(&x->star), cm_ibuf_free(&x->batch);
    cm_keymap_free(&x->tabu);
    cm_keymap_free(&x->failed.at), free(x->failed.changed);
    cm_ibuf_free(&x->failed.entries), cm_ibuf_free(&x->failed.region), cm_ibuf_free(&x->around);
}

static cm_status finish(remesher *x, cm_remesh_report *rep);

/* One run of the remesher chosen by o on a copy of mesh, with the
 * boundary's caps bcap (boundary_caps), the result left in x->km. CM_OK,
 * CM_ERR_NO_MEMORY, CM_ERR_CANCELLED or CM_ERR_INTERNAL (the construction
 * is not a triangulated disk). */
static cm_status remesh_run(remesher *x, const cm_mesh *mesh, size_t n, const double *bcap, const cm_options *o,
                            double ceiling_deg, const cm_remesh_boundary *splits, cm_progress *progress,
                            cm_remesh_report *rep)
{
    x->o = o;
    x->progress = progress;
    x->target = fmin(o->min_angle_deg, ceiling_deg) * CM_PI / 180.0;
    cm_status s = cm_kmesh_build(&x->km, mesh, n);
    if (s != CM_OK) return s;
    set_caps(x, bcap, n, rep);
    if (splits && cm_kmesh_allow_boundary_splits(&x->km, splits->between, splits->ctx,
                                                 (const int32_t *const *)splits->edge, (const double *const *)splits->t))
        return CM_ERR_NO_MEMORY;
    trace(x, x->restarting ? "restart" : "start");
    long removed = x->restarting ? 0 : coarsen(x, 0.0);
    if (removed < 0 || improve_everywhere(x)) return stop_status(x);
    rep->collapses += removed;
    trace(x, "cleanup");
    if (cm_progress_report(progress, CM_STAGE_REMESH, 0.0)) return CM_ERR_CANCELLED;
    if (o->remesher == CM_REMESHER_MAP) {
        if ((s = map_start(x, n, rep)) != CM_OK) return s;
        if (improve_everywhere(x)) return stop_status(x);
        trace(x, "map");
    }
    if ((s = refine(x, n, rep)) != CM_OK) return s;
    cm_kmesh_drop_candidates(&x->km); /* no split after this one picks from them */
    if (improve_everywhere(x)) return stop_status(x);
    trace(x, "polish");
    if ((s = step_out(x, n, CM_STEP_OUT_WORST, LONG_MAX)) != CM_OK) return s;
    return finish(x, rep);
}

/* The late coarsening and polish that end a run, and its report.
 * CM_OK, CM_ERR_NO_MEMORY or CM_ERR_CANCELLED. */
static cm_status finish(remesher *x, cm_remesh_report *rep)
{
    double keep = x->o->min_angle_deg * CM_PI / 180.0;
    long late = coarsen(x, x->restarting ? fmin(keep, cm_kmesh_min_angle(&x->km)) : keep);
    if (late < 0 || improve_everywhere(x)) return stop_status(x);
    trace(x, "end");
    rep->collapses += late;
    rep->flips = x->flips;
    rep->min_angle_deg = cm_kmesh_min_angle(&x->km) * 180.0 / CM_PI;
    return CM_OK;
}

/* The joint max-min polish of the written result (the report keeps the
 * smallest angle the stages above reached; the caller measures the
 * result); lowest_first with the index correspondence (`whole`). */
static cm_status polish_jointly(cm_mesh *mesh, size_t nb, cm_remesh_boundary *splits, int whole,
                                cm_progress *progress)
{
    cm_maxmin_slide slide = {0};
    if (splits && splits->place)
        slide = (cm_maxmin_slide){splits->edge, splits->t, splits->place, splits->ctx, splits->max_piece, 0, NULL, NULL};
    cm_status s = cm_maxmin_polish(mesh, nb, slide.place ? &slide : NULL, whole, CM_MAXMIN_ITERATIONS, progress);
    if (s == CM_OK && splits) splits->slid = slide.slid;
    return s;
}

/* The polish-scored moves at limits whose polish also slides the boundary
 * points along their input edges (splits->place), memo the moves the
 * calls before undid: the moves kept (their slides counted in
 * splits->slid), or -1. */
static long sliding_moves(remesher *x, const cm_pmove_limits *limits, size_t n, cm_remesh_boundary *splits,
                          cm_pmove_memo *memo)
{
    cm_kmesh *km = &x->km;
    cm_maxmin_slide slide = {NULL, NULL, splits->place, splits->ctx, splits->max_piece, 0, NULL, NULL};
    long kept = cm_polish_moves(km, limits, budget_of(x->o, n) - (km->live_v - km->n), &slide, memo, x->progress);
    if (kept >= 0) splits->slid += slide.slid;
    return kept;
}

/* Moves scored by the polish on the polished result (polish_moves.c):
 * the kmesh takes the polished positions back, and the mesh is written
 * again when a move was kept. */
static cm_status polish_moves(remesher *x, cm_mesh *mesh, size_t n, cm_remesh_boundary *splits)
{
    cm_kmesh *km = &x->km;
    const int32_t *const *edge = splits ? (const int32_t *const *)splits->edge : NULL;
    const double *const *t = splits ? (const double *const *)splits->t : NULL;
    if (cm_kmesh_read_back(km, mesh, edge, t)) return CM_ERR_NO_MEMORY;
    cm_pmove_limits limits = cm_pmove_limits_of(km);
    if (cm_kmesh_min_slack(km) < -(1 - limits.share) * x->target) return CM_OK;
    long kept = cm_polish_moves(km, &limits, budget_of(x->o, n) - (km->live_v - km->n), NULL, NULL, x->progress);
    if (kept < 0) return stop_status(x);
    cm_pmove_memo memo = {0}; /* the sliding runs' undone moves, from one run to the next */
    if (splits && splits->place) { /* the boundary points' turn */
        long more = sliding_moves(x, &limits, n, splits, &memo);
        kept = more < 0 ? -1 : kept + more;
    }
    /* Still far below the aim where the correspondence is the tool's to
     * choose: longer runs with the boundary points' turn while they keep
     * moves (polish_moves.c says why). */
    cm_pmove_limits longer = cm_pmove_longer_limits();
    for (int r = 0; kept >= 0 && splits && splits->place && r < CM_PMOVE_LONGER_ROUNDS && cm_pmove_longer_wanted(km);
         r++) {
        long more = sliding_moves(x, &longer, n, splits, &memo);
        kept = more < 0 ? -1 : kept + more;
        if (more == 0) break;
    }
    cm_pmove_memo_free(&memo);
    if (kept < 0) return stop_status(x);
    if (kept == 0) return CM_OK;
    cm_status s = splits ? cm_kmesh_write_labels(km, splits->edge, splits->t) : CM_OK;
    return s == CM_OK ? cm_kmesh_write(km, mesh) : s;
}

/* The smallest angle of every geometry of mesh (radians). */
static double mesh_min_angle(const cm_mesh *m)
{
    double least = HUGE_VAL;
    for (size_t g = 0; g < m->k; g++) least = fmin(least, cm_triangles_min_angle(m->tri, m->nt, m->xy[g]));
    return least;
}

#ifdef CM_REMESH_TRACE
static double written_angle(const void *m) { return mesh_min_angle(m); }

/* A step of the written result (the joint polish, the polish-scored
 * moves), whose first nb vertices are its boundary. */
static void trace_written(const remesher *x, const char *step, const cm_mesh *m, size_t nb)
{
    trace_line(x, step, written_angle, m, (long)(m->nv - nb));
}
#else
#define trace_written(x, step, m, nb) ((void)0)
#endif

/* One restart of the finished (written, polished) mesh, whose first nb
 * vertices are its boundary (whole: no boundary edge is ever split, as
 * for boundary_caps): the CM_RESTART_SHARE most distorted triangles
 * split (restart.h), the remesher run again from there with its polish
 * and polish-scored moves, boundary fixed, and its result kept in mesh
 * when its smallest angle is higher than *least (mesh's, radians) by
 * CM_RESTART_GAIN, *least then the new one. 1 kept, 0 not, or -status. */
static int restart(cm_mesh *mesh, double *least, size_t nb, int whole, const cm_options *o, double ceiling_deg,
                   cm_progress *progress, cm_remesh_report *rep)
{
    cm_mesh start;
    double *bcap = NULL;
    remesher z = {0};
    cm_remesh_report again = {0};
    cm_status s = cm_restart_refine(mesh, CM_RESTART_SHARE, &start);
    /* The budget (budget_of): the automatic one is the first run's again
     * for each restart, the split's points counted in it; one the caller
     * set is shared, the restart's split and refinement adding no more
     * than the Steiner vertices so far leave of it. It runs only if some
     * is left. */
    z.spent = (long)(start.nv - (o->max_steiner < 0 ? mesh->nv : nb));
    if (s == CM_OK && z.spent >= budget_of(o, nb)) {
        cm_mesh_clear(&start);
        return 0;
    }
    if (s == CM_OK) s = boundary_caps(&start, nb, whole, progress, &bcap);
    z.restarting = 1;
    if (s == CM_OK) s = remesh_run(&z, &start, nb, bcap, o, ceiling_deg, NULL, progress, &again);
    if (s == CM_OK) s = cm_kmesh_write(&z.km, &start);
    if (s == CM_OK) s = polish_jointly(&start, nb, NULL, whole, progress);
    if (s == CM_OK) trace_written(&z, "joint", &start, nb);
    if (s == CM_OK) s = polish_moves(&z, &start, nb, NULL);
    if (s == CM_OK) trace_written(&z, "moves", &start, nb);
    double reached = s == CM_OK ? mesh_min_angle(&start) : 0;
    int kept = s == CM_OK && reached > (1 + CM_RESTART_GAIN) * *least;
    if (s == CM_ERR_INTERNAL) s = CM_OK; /* a start the remesher cannot read: the result stands */
    if (kept) {
        cm_mesh_clear(mesh);
        *mesh = start;
        start = (cm_mesh){0};
        *least = reached;
        rep->iterations += again.iterations, rep->splits += again.splits;
        rep->split_attempts += again.split_attempts, rep->collapses += again.collapses, rep->flips += again.flips;
        /* rep->min_angle_deg stays the first run's: the callers' choices
         * that read it (auto's rescues) are those they made without */
    }
    cm_mesh_clear(&start);
    free(bcap);
    remesher_free(&z);
    return s == CM_OK ? kept : -(int)s;
}

/* The runs up to where the restarts start (cm_remesh_resume): the greedy
 * run and where it stalls the map-aware one, written into mesh, the
 * joint polish and the polish-scored moves; *least the result's smallest
 * angle (radians). x holds the run kept. */
static cm_status run_to_restarts(remesher *x, remesher *y, cm_mesh *mesh, size_t n, const cm_options *o,
                                 double ceiling_deg, double beat_deg, cm_remesh_boundary *splits,
                                 cm_progress *progress, cm_remesh_report *rep, double *least)
{
    cm_options map = *o; /* the rescue's options: x keeps pointing at them when it wins */
    map.remesher = CM_REMESHER_MAP;
    double *bcap;
    cm_status s = boundary_caps(mesh, n, !splits, progress, &bcap);
    if (s == CM_OK) s = remesh_run(x, mesh, n, bcap, o, ceiling_deg, splits, progress, rep);
    /* The greedy remesher can stall far below its aim, typically on a
     * sliver its local moves cannot reach (a slivered result also makes
     * the sweep's tetrahedra fail); the map-aware remesher starts the
     * same construction differently. The better result is kept. */
    if (s == CM_OK && o->remesher == CM_REMESHER_GREEDY && rep->min_angle_deg < CM_RESCUE_SHARE * rep->target_deg &&
        !cm_deadline_passed()) {
        cm_remesh_report again = {0};
        s = remesh_run(y, mesh, n, bcap, &map, ceiling_deg, splits, progress, &again);
        if (s == CM_OK && again.min_angle_deg > rep->min_angle_deg) {
            remesher t = *x;
            *x = *y, *y = t;
            again.iterations += rep->iterations, again.splits += rep->splits;
            again.split_attempts += rep->split_attempts;
            *rep = again;
        }
        /* Both ended short: the better one's forced moves look wider. */
        if (s == CM_OK && rep->min_angle_deg < CM_RESCUE_SHARE * rep->target_deg) {
            s = step_out(x, n, CM_STEP_OUT_WIDE, CM_STEP_OUT_WIDE_TRIES);
            if (s == CM_OK) s = finish(x, rep);
        }
    }
    free(bcap);
    if (s == CM_OK && splits) s = cm_kmesh_write_labels(&x->km, splits->edge, splits->t);
    if (s == CM_OK) s = cm_kmesh_write(&x->km, mesh);
    if (s == CM_OK) s = polish_jointly(mesh, (size_t)x->km.nb, splits, !splits, progress);
    if (s == CM_OK) trace_written(x, "joint", mesh, (size_t)x->km.nb);
    int behind = s == CM_OK && beat_deg > 0 && mesh_min_angle(mesh) * 180.0 / CM_PI < CM_REMESH_BEHIND * beat_deg;
    if (s == CM_OK && !behind) s = polish_moves(x, mesh, n, splits);
    if (s == CM_OK && !behind) trace_written(x, "moves", mesh, (size_t)x->km.nb);
    *least = s == CM_OK ? mesh_min_angle(mesh) : 0;
    rep->polished_deg = *least * 180.0 / CM_PI;
    rep->restart_wanted = s == CM_OK && cm_kmesh_min_share(&x->km) < CM_RESTART_BELOW;
    return s;
}

void cm_remesh_resume_clear(cm_remesh_resume *resume)
{
    size_t k = resume->mesh.k;
    cm_mesh_clear(&resume->mesh);
    free(resume->written);
    for (size_t g = 0; resume->edge && g < k; g++) free(resume->edge[g]);
    for (size_t g = 0; resume->t && g < k; g++) free(resume->t[g]);
    free(resume->edge), free(resume->t);
    *resume = (cm_remesh_resume){0};
}

/* Keeps in resume where the restarts start from (cm_remesh_resume): mesh,
 * its nb boundary vertices, its loops' offsets `written` (or NULL), the
 * labels and slides in splits (or NULL), the report. Without memory for
 * it nothing is kept: a later call then runs from the start. */
static void keep_resume(cm_remesh_resume *resume, const cm_mesh *mesh, size_t nb, const size_t *written,
                        const cm_remesh_boundary *splits, const cm_remesh_report *rep)
{
    size_t k = mesh->k;
    int ok = cm_mesh_copy(&resume->mesh, mesh) == 0;
    resume->mesh.loop_start = NULL; /* the caller's, not the copy's */
    resume->nb = nb, resume->report = *rep, resume->slid = splits ? splits->slid : 0;
    if (ok && written) {
        size_t bytes = (mesh->num_loops + 1) * sizeof *written;
        ok = (resume->written = malloc(bytes)) != NULL;
        if (ok) memcpy(resume->written, written, bytes);
    }
    if (ok && splits) {
        ok = (resume->edge = calloc(k, sizeof *resume->edge)) && (resume->t = calloc(k, sizeof *resume->t));
        for (size_t g = 0; ok && g < k; g++) {
            ok = (resume->edge[g] = malloc((nb + 1) * sizeof **resume->edge)) &&
                 (resume->t[g] = malloc((nb + 1) * sizeof **resume->t));
            if (ok) {
                memcpy(resume->edge[g], splits->edge[g], nb * sizeof **resume->edge);
                memcpy(resume->t[g], splits->t[g], nb * sizeof **resume->t);
            }
        }
    }
    if (!ok) cm_remesh_resume_clear(resume);
}

/* Takes what resume kept into mesh (its loops staying its own), splits and
 * the report; resume is emptied. Its boundary vertices, and its loops'
 * offsets (or NULL), are returned. */
static size_t take_resume(cm_remesh_resume *resume, cm_mesh *mesh, cm_remesh_boundary *splits,
                          cm_remesh_report *rep, size_t **written)
{
    const size_t *loops = mesh->loop_start;
    size_t num_loops = mesh->num_loops, nb = resume->nb;
    cm_mesh_clear(mesh);
    *mesh = resume->mesh;
    mesh->loop_start = loops, mesh->num_loops = num_loops;
    *rep = resume->report;
    *written = resume->written;
    for (size_t g = 0; splits && g < mesh->k; g++) {
        free(splits->edge[g]), free(splits->t[g]);
        splits->edge[g] = resume->edge[g], splits->t[g] = resume->t[g];
        resume->edge[g] = NULL, resume->t[g] = NULL;
    }
    if (splits) splits->slid = resume->slid;
    resume->mesh = (cm_mesh){0}, resume->written = NULL;
    cm_remesh_resume_clear(resume);
    return nb;
}

cm_status cm_remesh(cm_mesh *mesh, size_t n, const cm_options *o, double ceiling_deg, double beat_deg,
                    cm_remesh_boundary *splits, cm_remesh_resume *resume, cm_progress *progress,
                    cm_remesh_report *rep, cm_error *err)
{
    remesher x = {0}, y = {0};
    const size_t *given = mesh->loop_start;
    size_t *written = NULL, nb;
    double least;
    cm_status s = CM_OK;
    if (resume && resume->mesh.nv) {
        nb = take_resume(resume, mesh, splits, rep, &written);
        least = mesh_min_angle(mesh);
    } else {
        s = run_to_restarts(&x, &y, mesh, n, o, ceiling_deg, beat_deg, splits, progress, rep, &least);
        nb = (size_t)x.km.nb;
        /* Where points were added to the loops of a polygon with holes,
         * the restarts start from the written loops' offsets; the caller
         * gets the input's back, as without restarts. */
        if (s == CM_OK && rep->restart_wanted && (o->restarts > 0 || resume) && given && nb != n) {
            written = malloc((mesh->num_loops + 1) * sizeof *written);
            if (!written) s = CM_ERR_NO_MEMORY;
            else cm_kmesh_written_loops(&x.km, given, mesh->num_loops, written);
        }
        if (s == CM_OK && resume && rep->restart_wanted) keep_resume(resume, mesh, nb, written, splits, rep);
    }
    /* Far below the aim, restarts from the result split where its map is
     * most distorted (the boundary, and with it the labels just written,
     * stays as it is). */
    if (written) mesh->loop_start = written;
    for (int i = 0; s == CM_OK && rep->restart_wanted && i < o->restarts && !cm_deadline_passed(); i++) {
        int r = restart(mesh, &least, nb, !splits, o, ceiling_deg, progress, rep);
        if (r < 0) s = (cm_status)-r;
        if (r <= 0) break;
    }
    mesh->loop_start = given;
    free(written);
    if (s == CM_OK && splits) splits->n = nb;
    remesher_free(&x), remesher_free(&y);
    if (s == CM_ERR_INTERNAL) return cm_fail(err, s, "remesh: the construction is not a triangulated disk");
    return s == CM_OK ? CM_OK : cm_fail_status(err, s);
}
