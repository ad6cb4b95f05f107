/* One connectivity, k geometries: the mesh the remesher edits in place.
 *
 * A corner table (Rossignac): corner c = 3t + i is vertex tri[c] of triangle
 * t; opp[c] is the corner across the edge opposite c in the neighbouring
 * triangle, -1 on the boundary. Triangles are counter-clockwise in every
 * geometry. Vertices 0..n-1 are the polygon, counter-clockwise in order
 * (or its loops, cm_mesh.loop_start, the holes clockwise), and never move;
 * with boundary splits (cm_kmesh_allow_boundary_splits) vertices added on
 * a boundary edge join them (bnext[v] >= 0 marks a boundary vertex), and
 * never move either (but along their input edges in the polish-scored
 * moves at the end: cm_kmesh_slide); every other vertex is an interior
 * Steiner vertex.
 * Removed
 * triangles and vertices leave dead slots (tri[3t] = -1, vc[v] = -1) that
 * later insertions reuse; cm_kmesh_write compacts.
 *
 * The mesh also keeps, for every live triangle, its quality key tkey: the
 * smallest angle in radians over all k geometries; its slack, tkey minus
 * the angle the triangle should reach (the target, lowered where the
 * boundary allows less: see cm_kmesh_set_caps), in a min-heap, so the
 * worst triangle is always at hand; and a max-heap of the refinement
 * candidates, the interior edges beside a triangle of negative slack, by
 * the split score of eq. (5). Every operation below keeps them current;
 * the candidates' scores are worked out when the heap is next read (a
 * repair moves the same vertices many times between two reads).
 *
 * Operations do not check validity: the callers (flip.c, smooth.c, ...)
 * test each candidate exactly with cm_kmesh_tri_ok first. */
#ifndef CM_KMESH_H
#define CM_KMESH_H

#include "base/buf.h"
#include "base/error.h"
#include "base/heap.h"
#include "base/mesh.h"
#include "geom/angle.h"

/* Where a point between two consecutive boundary vertices goes in
 * geometry g: a and b carry labels (edge, t) (the caller's: where they
 * lie on an input edge); writes the label and the coordinates of the
 * point at the middle parameter between them, for step > 0 nudged by
 * about step ulps of the parameter towards a when step is odd, towards b
 * when even (a rounded point off the edge's line on the outside). 0 when
 * there is no such point strictly between them, else 1. */
typedef int (*cm_kmesh_between)(void *ctx, size_t g, int32_t ea, double ta, int32_t eb, double tb, int step,
                                int32_t *e, double *t, double xy[2]);

typedef struct cm_kmesh {
    size_t k;
    int32_t n;             /* boundary vertices */
    int32_t nv, nt;        /* vertex / triangle slots in use, dead included */
    int32_t cap_v, cap_t;
    int32_t live_v, live_t;
    double **xy;           /* k arrays of 2 * cap_v */
    int32_t *tri, *opp;    /* 3 * cap_t */
    int32_t *vc;           /* vertex -> one of its corners; -1 dead */
    cm_ibuf free_v, free_t;
    double *scale;         /* per geometry: sqrt(polygon area), for lengths */
    double *tkey;          /* triangle: smallest angle over geometries */
    double *tang;          /* k per triangle: its smallest angle in each
                              geometry; the first NaN when not known */
    double *slack;         /* triangle: tkey minus its target */
    cm_heap tq;            /* live triangles by slack */
    cm_heap eq;            /* candidate edges (smaller corner) by -score;
                              read it through cm_kmesh_candidates */
    int eq_dropped;        /* eq emptied and no longer kept */
    uint8_t *eq_stale;     /* 3 per triangle: the corner's edge changed
                              since eq last filed it */
    int32_t *eq_pending;   /* the stale corners, each once */
    int32_t eq_npending;
    double target;         /* radians; 0 until cm_kmesh_set_caps */
    double *bcap;          /* per boundary vertex i: cap of edge i -> bnext[i] */
    int32_t *bnext;        /* per vertex: the next along its boundary loop,
                              -1 for an interior vertex */
    int32_t nb;            /* live boundary vertices */
    cm_kmesh_between between; /* NULL: boundary edges are never split */
    void *between_ctx;
    int32_t *bedge;        /* k per vertex: a boundary vertex's labels */
    double *bt;
    double *vcap;          /* per vertex: half the corner angle (boundary), pi */
    uint16_t *vdirty;      /* vertex: what changed around it since the
                              smoothing last found nothing to do (CM_DIRTY_*) */
    uint32_t *mark;        /* scratch vertex stamps */
    uint32_t stamp;
    struct cm_kmesh_log *log; /* undo log, NULL until the first transaction */
} cm_kmesh;

static inline int32_t cm_next(int32_t c) { return (int32_t)cm_corner_next((size_t)c); }
static inline int32_t cm_prev(int32_t c) { return c % 3 == 0 ? c + 2 : c - 1; }
static inline const double *cm_kmesh_pos(const cm_kmesh *km, size_t g, int32_t v)
{
    return km->xy[g] + 2 * (size_t)v;
}
static inline int cm_kmesh_is_boundary(const cm_kmesh *km, int32_t v) { return km->bnext[v] >= 0; }
static inline int cm_kmesh_tri_live(const cm_kmesh *km, int32_t t) { return km->tri[3 * t] >= 0; }
/* vdirty bits. cm_dirty_smooth(g): a triangle around the vertex changed
 * in geometry g since the smoothing formulas last left it in place there
 * (geometries from the 8th on share one bit, which stays set).
 * CM_DIRTY_OPTIMIZE: a triangle around it changed in any geometry, or a
 * transaction changing one was undone, since cm_smooth_optimize last
 * found it optimal. cm_dirty_search(g): a triangle around it changed in
 * geometry g since cm_smooth_optimize last found no gain there (from the
 * 7th geometry on one shared bit, which stays set): the search depends on
 * the star in g alone, so while the bit is clear it would find none
 * again. */
#define CM_DIRTY_OPTIMIZE 0x100u
#define CM_DIRTY_ALL 0xffffu
static inline unsigned cm_dirty_smooth(size_t g) { return 1u << (g < 7 ? g : 7); }
static inline int cm_dirty_smooth_shared(size_t g) { return g >= 7; }
static inline unsigned cm_dirty_search(size_t g) { return 1u << (9 + (g < 6 ? g : 6)); }
static inline int cm_dirty_search_shared(size_t g) { return g >= 6; }

/* Builds from a compatible triangulation whose vertices 0..n-1 are the
 * counter-clockwise boundary. CM_OK, CM_ERR_NO_MEMORY, or CM_ERR_INTERNAL
 * when the triangle list is not a manifold disk with that boundary. */
cm_status cm_kmesh_build(cm_kmesh *km, const cm_mesh *m, size_t n);
/* Lets boundary edges be split (cm_kmesh_split_boundary) and be
 * refinement candidates: labels edge[g][i], t[g][i] for boundary vertex i
 * < n, between() for the points. 0, or -1 out of memory. */
int cm_kmesh_allow_boundary_splits(cm_kmesh *km, cm_kmesh_between between, void *ctx, const int32_t *const *edge,
                                   const double *const *t);
/* Replaces m's arrays with the compacted mesh: the boundary vertices
 * first, with bit-identical coordinates, each loop in its order (a
 * vertex added on an edge after the edge's start; without such vertices
 * each keeps its index), the Steiner vertices after them in slot order.
 * CM_OK or CM_ERR_NO_MEMORY (m unchanged). */
cm_status cm_kmesh_write(const cm_kmesh *km, cm_mesh *m);
/* Where the loops that start at input vertices loop_start[0 ..
 * num_loops - 1] begin as cm_kmesh_write numbers the boundary (the points
 * added on their edges counted), and out[num_loops] = km->nb. */
void cm_kmesh_written_loops(const cm_kmesh *km, const size_t *loop_start, size_t num_loops, size_t *out);
/* With boundary splits allowed: replaces edge[g] and t[g] (k arrays the
 * caller allocated with malloc) by the labels of the boundary as
 * cm_kmesh_write numbers it, km->nb of them. CM_OK or CM_ERR_NO_MEMORY
 * (the arrays unchanged). */
cm_status cm_kmesh_write_labels(const cm_kmesh *km, int32_t **edge, double **t);
/* The inverse of cm_kmesh_write for positions: every vertex of km takes
 * its coordinates from m, the mesh cm_kmesh_write wrote from km and
 * whose vertices moved since (the joint polish), and with edge != NULL
 * and boundary splits allowed each boundary vertex its labels (as
 * cm_kmesh_write_labels numbered them). Every key is recomputed. CM_OK
 * or CM_ERR_NO_MEMORY. */
cm_status cm_kmesh_read_back(cm_kmesh *km, const cm_mesh *m, const int32_t *const *edge, const double *const *t);
void cm_kmesh_free(cm_kmesh *km);

/* Corners at v in counter-clockwise order; for a boundary vertex the first
 * corner's triangle holds the edge v -> v + 1 and the last one v - 1 -> v.
 * Returns the count, or -1 out of memory. */
long cm_kmesh_star(const cm_kmesh *km, int32_t v, cm_ibuf *corners);

/* Triangle t's smallest angle in geometry g. */
double cm_kmesh_tri_angle(const cm_kmesh *km, size_t g, int32_t t);
/* 1 if (a, b, c) is strictly counter-clockwise in geometry g (exact). */
int cm_kmesh_tri_ok(const cm_kmesh *km, size_t g, int32_t a, int32_t b, int32_t c);
/* Recomputes t's quality key; its vertices become dirty (CM_DIRTY_ALL). */
void cm_kmesh_touch(cm_kmesh *km, int32_t t);
/* Sets vdirty[v] (logged: a rollback restores it). */
void cm_kmesh_set_dirty(cm_kmesh *km, int32_t v, unsigned dirty);
/* Length of edge ab in geometry g over that geometry's scale. */
double cm_kmesh_rel_length(const cm_kmesh *km, size_t g, int32_t a, int32_t b);

/* Flips the interior edge opposite corner c. Afterwards c and opp[c] hold
 * the two far vertices: the new edge is opposite cm_next(c). */
void cm_kmesh_flip(cm_kmesh *km, int32_t c);
/* Splits the interior edge opposite corner c at the points pts (2k
 * doubles, one point per geometry). Returns the new vertex, -1 out of
 * memory. The new vertex's corners: cm_prev(c) is one of them. */
int32_t cm_kmesh_split(cm_kmesh *km, int32_t c, const double *pts);
/* Splits the boundary edge opposite corner c at the points pts, labels
 * edge[g], t[g]: a new boundary vertex, never moved. Returns it, -1 out
 * of memory. Its corners: cm_prev(c) is one of them. */
int32_t cm_kmesh_split_boundary(cm_kmesh *km, int32_t c, const double *pts, const int32_t *edge, const double *t);
/* Inserts a vertex inside triangle t at the points pts (2k doubles, one
 * per geometry): t becomes three triangles around it. Returns the new
 * vertex, -1 out of memory. */
int32_t cm_kmesh_insert(cm_kmesh *km, int32_t t, const double *pts);
/* 1 if removing interior vertex tri[c] by moving it onto u = tri[next(c)]
 * keeps the mesh a manifold disk (the link condition). */
int cm_kmesh_collapse_ok_topology(cm_kmesh *km, int32_t c, const cm_ibuf *star);
/* Collapses the edge from v = tri[c] (interior) to u = tri[next(c)]; star
 * holds v's corners as from cm_kmesh_star. v's slot and the two triangles
 * on the edge die. */
void cm_kmesh_collapse(cm_kmesh *km, int32_t c, const cm_ibuf *star);
/* Moves interior vertex v in geometry g and refreshes the keys around it;
 * its star's vertices become dirty for the smoothing in g and for
 * cm_smooth_optimize. */
void cm_kmesh_move(cm_kmesh *km, size_t g, int32_t v, const double p[2], const cm_ibuf *star);
/* Slides boundary vertex v of geometry g along its input edge: to p,
 * the point at parameter t of that edge (its label's edge stays), with
 * the keys refreshed as by cm_kmesh_move. The joint polish's and its
 * local form's slide, for the stages after which no boundary vertex is
 * assumed fixed. */
void cm_kmesh_slide(cm_kmesh *km, size_t g, int32_t v, const double p[2], double t, const cm_ibuf *star);

/* Transactions: after cm_kmesh_tx_begin every change is logged until
 * commit or rollback; rollback restores the mesh exactly (vdirty too, but
 * for CM_DIRTY_OPTIMIZE, set around the undone change). tx_region gives
 * the smallest tkey over the triangles the transaction changed, before
 * and after. begin returns 0 or -1 out of memory; region and rollback
 * return -1 when the log ran out of memory (the changes then stay). */
int cm_kmesh_tx_begin(cm_kmesh *km);
int cm_kmesh_tx_region(const cm_kmesh *km, double *before, double *after);
void cm_kmesh_tx_commit(cm_kmesh *km);
int cm_kmesh_tx_rollback(cm_kmesh *km);
/* Appends to out the vertices of the live triangles in the slots the last
 * transaction changed (after its commit or rollback: as they are now;
 * repeats possible). Returns 0, or -1 out of memory or when the log ran
 * out of it. */
int cm_kmesh_tx_vertices(const cm_kmesh *km, cm_ibuf *out);

/* Full exact check (tests): adjacency symmetric, every live triangle
 * counter-clockwise in every geometry, boundary edges exactly i -> bnext[i].
 * Returns 1 when valid. */
int cm_kmesh_check(const cm_kmesh *km);

/* A fresh value for km->mark[v] == stamp tests (vertex sets). */
uint32_t cm_kmesh_new_stamp(cm_kmesh *km);

/* Writes the corners of triangle t and of its neighbours (up to 12) to
 * out: where moves around t start. Returns how many. */
int cm_kmesh_corners_near(const cm_kmesh *km, int32_t t, int32_t out[12]);

/* Smallest slack over live triangles (radians), pi when empty. */
double cm_kmesh_min_slack(const cm_kmesh *km);
/* Smallest share of its own target a live triangle's key reaches (the
 * target after the boundary's caps: a triangle at a sharp corner is held
 * to what the corner allows); O(t). */
double cm_kmesh_min_share(const cm_kmesh *km);
/* Smallest angle over all triangles and geometries (radians); O(t). */
double cm_kmesh_min_angle(const cm_kmesh *km);
/* Sets the target angle (radians) and the caps: a triangle on boundary
 * edge i -> i+1 should reach min(target, bcap[i]), one at corner i
 * min(target, vcap[i]) (n entries each, radians; NULL: no cap). */
void cm_kmesh_set_caps(cm_kmesh *km, double target, const double *bcap, const double *vcap);
/* Ends the refinement: the candidate heap is emptied and no longer kept,
 * so cm_refine_candidates finds none (keeping it costs a score, with a
 * square root, per edge of every changed triangle). */
void cm_kmesh_drop_candidates(cm_kmesh *km);
/* The refinement candidates, with every edge changed since the last read
 * filed again (the same heap as if each change had filed it at once). */
const cm_heap *cm_kmesh_candidates(cm_kmesh *km);
/* Takes the edge opposite c out of the candidates until a triangle beside
 * it changes again. */
void cm_kmesh_forget_candidate(cm_kmesh *km, int32_t c);
/* Split score of eq. (5) of the edge opposite c (interior, or boundary
 * with boundary splits): the largest
 * relative length over geometries over alpha_min(e)^2. */
double cm_kmesh_split_score(const cm_kmesh *km, int32_t c);

#endif
