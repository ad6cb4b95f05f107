/* Connectivity changes scored by the joint polish: moves near the worst
 * triangles, each followed by the max-min polish of a small
 * neighbourhood in every geometry (polish_moves.c says why). */
#ifndef CM_REMESH_POLISH_MOVES_H
#define CM_REMESH_POLISH_MOVES_H

#include "base/progress.h"
#include "remesh/kmesh.h"
#include "remesh/maxmin.h"

/* How long the stage works: it runs where the worst triangle's slack is
 * at least -(1 - share) of the aim; at most `tries` moves, ending after
 * `idle` in a row without a kept one; `iterations` L-BFGS iterations per
 * geometry in each local polish. */
typedef struct cm_pmove_limits {
    double share;
    long tries, idle;
    int iterations;
} cm_pmove_limits;

/* The limits for km: longer where boundary points may be added
 * (km->between; polish_moves.c says why). */
cm_pmove_limits cm_pmove_limits_of(const cm_kmesh *km);

/* Where boundary points slide (the caller's choice) and the worst
 * triangle is still far below its aim after the stage
 * (cm_pmove_longer_wanted; km->between), the stage runs again at
 * cm_pmove_longer_limits, up to CM_PMOVE_LONGER_ROUNDS times while a run
 * keeps a move (polish_moves.c says why). */
#define CM_PMOVE_LONGER_ROUNDS 3
cm_pmove_limits cm_pmove_longer_limits(void);
int cm_pmove_longer_wanted(const cm_kmesh *km);

/* The moves a call of cm_polish_moves undid, for the next call on the
 * same mesh with the same slide and L-BFGS iterations (auto's longer
 * runs): those the kept moves left out of their reach are counted as
 * tries without running them again (polish_moves.c says why). Zeroed
 * before first use; cm_pmove_memo_free after the last. */
typedef struct cm_pmove_memo {
    struct cm_pmove_failed *failed;
    size_t n, cap;
    long round;
    int iterations, slides;
} cm_pmove_memo;

void cm_pmove_memo_free(cm_pmove_memo *memo);

/* Tries moves (a polish alone, a flip, a split, a Steiner vertex's
 * removal, an insertion) around the triangles furthest below their aim,
 * each with the local polish, keeping one only when the smallest slack of
 * the triangles around it rose and the smallest angle of the whole mesh
 * (all geometries) did not fall; every kept state is exactly valid in
 * every geometry and the connectivity stays shared. As long as limits
 * allow; at most steiner_left vertices added. With slide (its place, ctx
 * and max_piece; NULL where the correspondence is not the tool's to
 * choose), the polish after each move also slides the boundary points that
 * lie inside an input edge along it, as the joint polish does, and adds to
 * slide->slid the points the kept moves slid. memo: the moves undone by
 * the caller's earlier calls (cm_pmove_memo), or NULL. Returns the moves
 * kept, or -1 out of memory or cancelled (progress says which). */
long cm_polish_moves(cm_kmesh *km, const cm_pmove_limits *limits, long steiner_left, cm_maxmin_slide *slide,
                     cm_pmove_memo *memo, cm_progress *progress);

#endif
