/* Link distance and minimum-link paths in a simple polygon (Suri's window
 * partition), exact.
 *
 * The window partition from a vertex s: the region s sees (level 1); each
 * window (a chord bounding it, through a reflex vertex) cuts off a pocket;
 * what is weakly visible in a pocket from its window is level 2; and so on.
 * The link distance from s to a vertex is its level: the least number of
 * links of a polyline from s to it whose links lie strictly inside the
 * polygon (interior bends, each link an open segment in the open interior).
 *
 * Built per pocket: the pocket's triangulation is its parent's cut along
 * the window (the triangles on its side kept, the pieces of those the
 * window crosses ear-clipped, checked; ear clipping of the whole pocket
 * where that does not apply), every vertex's cone of sight lines toward
 * the window is propagated through the triangulation (O(k) per vertex for
 * a pocket of k vertices), windows are traced through the triangles. So
 * O(n^2) per source in the worst case, close to O(n) when the pockets are
 * small. Window end points are exact
 * constructed points (xpoint.h); every decision is an exact predicate.
 *
 * Degenerate configurations (a window through another vertex, collinear
 * boundary vertices) are handled: a window that passes a vertex continues
 * past it, a vertex that lies on the boundary of a lit region without
 * being visible is one link further. */
#ifndef CM_LINKPATH_H
#define CM_LINKPATH_H

typedef struct cm_linkpart cm_linkpart;

/* xy: the m vertices of a simple counter-clockwise polygon (copied).
 * NULL when out of memory. */
cm_linkpart *cm_linkpart_create(const double *xy, long m);
void cm_linkpart_free(cm_linkpart *lp);
/* Derive pockets' triangulations from their parents' (on, the default) or
 * ear-clip each (off): the same distances either way; paths may bend
 * elsewhere. */
void cm_linkpart_set_derive(cm_linkpart *lp, int on);
/* Pocket vertices triangulated so far, by derivation and by ear clipping
 * (window pockets; the root is the polygon's own triangulation). */
void cm_linkpart_counts(const cm_linkpart *lp, long *derived, long *clipped);

/* Link distance from vertex s to every vertex: dist[v] (dist[s] = 0,
 * dist[v] = 1 iff s sees v); -1 where it was not determined (only if a
 * pocket failed to triangulate, which exact arithmetic rules out for
 * simple input). Returns 0, or -1 out of memory. */
int cm_link_distances(cm_linkpart *lp, long s, int *dist);
/* The same, building the partition only up to level max_level: dist[v] =
 * -1 for the vertices farther than that (some at max_level + 1 may still
 * get their distance). Returns 0 when every distance was determined (a
 * larger max_level gives the same), 1 when some pocket lay beyond
 * max_level, -1 out of memory. */
int cm_link_distances_upto(cm_linkpart *lp, long s, int max_level, int *dist);
/* The same where only the vertices v with need[v] must be determined (the
 * others may be left -1): pockets holding none of them are left out. 1
 * when some pocket left to build lay beyond max_level, else as above. */
int cm_link_distances_needed(cm_linkpart *lp, long s, int max_level, const unsigned char *need, int *dist);

/* A minimum-link path from vertex u to vertex v: the bends (interior
 * points, two doubles each, from u's end) in *bends (malloc'd, NULL if
 * none) and their count in *nbends. Built backward from v: each bend sits
 * just across the window of the pocket the previous point lies in, where
 * that point's cone of sight lines reaches, inside the parent pocket's lit
 * region (points on a window itself are only limits of links strictly
 * inside); among such points the one with the widest cone toward the next
 * window is taken. Every link is checked exactly to lie strictly inside,
 * consecutive bends see each other and the path is simple. Returns the
 * number of links (= the link distance), 0 if no such path could be built
 * in doubles (a window passing within rounding distance of a vertex),
 * -1 out of memory. */
int cm_link_path(cm_linkpart *lp, long u, long v, double **bends, long *nbends);
/* The same when the link distance is known to be at most max_level (the
 * partition is built only that far; the same path): 0 also when it is
 * not. */
int cm_link_path_within(cm_linkpart *lp, long u, long v, int max_level, double **bends, long *nbends);

/* 1 if the polyline u, bends[0..nb-1], v is a valid cut: every link lies
 * strictly inside the polygon xy[0..m-1] (u, v vertices, bends interior
 * points) and the polyline is simple. Exact. */
int cm_path_valid(const double *xy, long m, long u, long v, const double *bends, long nb);
/* The same with tame = cm_coords_tame(xy, 2 * m), known to the caller:
 * the many tests of one polygon's candidate paths check it once. */
int cm_path_valid_in(const double *xy, long m, int tame, long u, long v, const double *bends, long nb);

/* Weak visibility from a diagonal: vis[v] = 1 for the vertices v strictly
 * between a and b (counter-clockwise from a) that see some point of the
 * open diagonal ab; 0 for the others. Returns 0, -1 out of memory, 1 if
 * (a, b) is not a diagonal's sub-polygon that can be triangulated. */
int cm_weak_visibility(const double *xy, long m, long a, long b, unsigned char *vis);

#endif
