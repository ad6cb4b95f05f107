/* A static tree of axis-aligned boxes (a bounding-volume hierarchy): the
 * items whose box meets a query box, without scanning them all. Unlike
 * cm_pointgrid (points that come and go) the items are extended objects,
 * segments above all, fixed once built; a long segment is one item, not
 * one per cell it crosses.
 *
 * The items are ordered along a Morton curve of their boxes' centres and
 * the tree halves that order down to leaves of a few items, so it is
 * balanced whatever the input. The query box may shrink while the tree is
 * walked (a nearest-style search): subtrees are tested against the box as
 * it is when they are reached. Exact as a filter: boxes are compared, never
 * computed. Build O(n log n), memory O(n). */
#ifndef CM_GEOM_BOXTREE_H
#define CM_GEOM_BOXTREE_H

#include <stddef.h>
#include <stdint.h>

typedef struct cm_boxtree {
    size_t n;          /* items */
    int32_t *item;     /* item ids in leaf order */
    double *item_box;  /* 4 per item in leaf order: x0, y0, x1, y1 */
    double *node_box;  /* 4 per node, node 1 the root, children 2i, 2i + 1 */
    size_t nodes;
} cm_boxtree;

/* Builds the tree over items 0 .. n - 1, item i's box being box[4i ..
 * 4i + 3] = x0, y0, x1, y1 (x0 <= x1, y0 <= y1). Returns 0 or -1 out of
 * memory (the tree is then empty). */
int cm_boxtree_build(cm_boxtree *t, const double *box, size_t n);
void cm_boxtree_free(cm_boxtree *t);

/* Called for an item whose box meets the closed query box q (x0, y0, x1,
 * y1); it may shrink q. Nonzero stops the walk and is returned. */
typedef int (*cm_boxtree_visit)(void *ctx, int32_t item, double q[4]);

/* Calls visit for every item whose box meets q when its leaf is reached,
 * the subtree nearer q's centre first. Returns 0 or visit's nonzero. */
int cm_boxtree_query(const cm_boxtree *t, double q[4], cm_boxtree_visit visit, void *ctx);

#endif
