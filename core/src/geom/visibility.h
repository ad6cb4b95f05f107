/* Visibility in a simple polygon, exact.
 *
 * "v sees w" always means strict visibility: the open segment vw lies in the
 * open interior of the polygon (it may not touch the boundary, not even at
 * a vertex), and at a polygon vertex the segment leaves into the interior.
 * Two polygon vertices see each other iff they span a diagonal.
 *
 * All visibility here works on a triangulation of the polygon: a sight line
 * from a point crosses the triangles of one path of the dual tree, so the
 * directions it can take form one cone, narrowed at each crossed diagonal
 * by the diagonal's end points (cone propagation). Every decision is an
 * exact orientation test. */
#ifndef CM_VISIBILITY_H
#define CM_VISIBILITY_H

#include <stdint.h>

#include "geom/xpoint.h"

/* Visibility of a vertex: the whole table. xy holds the m vertices of a
 * simple counter-clockwise polygon, tri a triangulation of it (m - 2
 * triangles, vertex indices). Writes vis[s * m + v] = 1 if s sees v, else
 * 0, for all s, v. O(m) per vertex s (each triangle is entered at most once
 * from s). Returns 0, or -1 out of memory. */
int cm_visibility_table(const double *xy, long m, const int32_t *tri, unsigned char *vis);

/* The same one row at a time, in O(m) memory: create (NULL when out of
 * memory), then row s into row[0..m-1] as many times as wanted. */
typedef struct cm_visrows cm_visrows;
cm_visrows *cm_visrows_create(const double *xy, long m, const int32_t *tri);
void cm_visrows_row(cm_visrows *v, long s, unsigned char *row);
/* Row s only where it is wanted: want[j] (j = 0..m) counts the wanted
 * vertices among 0..j-1. row[j] is exact for every wanted j; the cones
 * skip the pockets without one, so other entries may be 0 where s sees j. */
void cm_visrows_row_wanted(cm_visrows *v, long s, const int32_t *want, unsigned char *row);
/* The same with the vertices lo..m-1 wanted (no counts to make). */
void cm_visrows_row_from(cm_visrows *v, long s, long lo, unsigned char *row);
void cm_visrows_free(cm_visrows *v);

/* 1 if the open segment ab lies strictly inside the simple counter-clockwise
 * polygon xy[0..m-1]. ia (ib) is the polygon vertex a (b) is, or -1 when a
 * (b) is a point that must itself lie strictly inside. Exact, O(m). */
int cm_segment_inside(const double *xy, long m, long ia, const double a[2], long ib,
                      const double b[2]);
/* The same when xy, a and b are all tame (cm_coords_tame). */
int cm_segment_inside_tame(const double *xy, long m, long ia, const double a[2], long ib, const double b[2]);
/* The same for the segment between vertices ia and ib when only the edges
 * first .. first + count - 1 (cyclic; edge i from vertex i to i + 1) can
 * meet it, the others known to miss the open segment and to touch it at
 * most at its ends: the end directions and those edges are tested (all m
 * edges from 0: the full test). turn: the vertices' turns from
 * cm_vertex_turns, or NULL to compute the two needed; tame: what
 * cm_vertex_turns returned (or 0). Exact, O(count). */
int cm_segment_inside_edges(const double *xy, long m, const signed char *turn, int tame, long ia, long ib,
                            long first, long count);
/* turn[i]: the sign of the orientation of the corner at vertex i (exact).
 * Returns 1 if every coordinate is tame (cm_coords_tame), else 0. */
int cm_vertex_turns(const double *xy, long m, signed char *turn);

/* A point strictly inside the kernel of the simple counter-clockwise
 * polygon xy[0..m-1] (the points that see the whole polygon), found by
 * half-plane clipping in doubles and checked exactly: every edge has it
 * strictly on its left, so the fan from it triangulates the polygon.
 * Returns 1 and the point in out, 0 if none was found, -1 out of memory. */
int cm_kernel_point(const double *xy, long m, double out[2]);

/* Ear clipping over exact points: triangulates the simple counter-clockwise
 * polygon with vertices ids[0..k-1] (pool ids) into k - 2 triangles of local
 * indices (0..k-1) in tri_out. Returns 0, -1 out of memory, 1 no ear. */
int cm_xtriangulate(cm_xpool *pool, const long *ids, long k, int32_t *tri_out);

/* A triangulated polygon over exact points with a visibility source: one of
 * its vertices (point source) or its closing edge ids[k-1] -> ids[0] (a
 * window: what is visible from the window's open segment is weakly visible
 * from it). The dual tree is rooted at the source's triangles. */
typedef struct cm_vsource {
    cm_xpool *pool;
    const long *ids; /* k pool ids, counter-clockwise; owned by the caller */
    long k, nt;
    long source;     /* local index of a point source, -1 for the window */
    int32_t *tri;    /* 3 nt local indices */
    int32_t *nbr;    /* 3 nt */
    int32_t *up;     /* per triangle: corner opposite the edge toward the
                        root, -1 for root triangles */
    int32_t *depth;  /* per triangle */
    int32_t *toward; /* per triangle: the neighbour toward the root (-1 for
                        root triangles) and the pool ids of the left and
                        right end of the edge to it, as seen from t: one
                        read per step of a walk up the tree */
    int32_t *fan_start, *fan; /* per vertex: incident triangles (CSR) */
    int32_t *low;    /* per vertex: incident triangle of least depth */
    cm_xinputs in;   /* pool ids with coordinates at hand; set by the
                        caller after building, none by default */
} cm_vsource;

/* Triangulates and roots. Returns 0, -1 out of memory, 1 if the polygon
 * could not be triangulated (not simple). */
int cm_vsource_build(cm_vsource *vs, cm_xpool *pool, const long *ids, long k, long source);
/* The same over given triangles: tri (3 (k - 2) local indices of
 * counter-clockwise triangles, malloc'd) is taken over, freed by
 * cm_vsource_clear also on failure. They are checked to triangulate the
 * polygon (around every vertex one fan from its next to its previous
 * vertex, O(k)). Returns 0, -1 out of memory, 1 if they do not. */
int cm_vsource_build_tri(cm_vsource *vs, cm_xpool *pool, const long *ids, long k, long source, int32_t *tri);
/* Roots the same triangulation at another point source (a vertex).
 * Returns 0, -1 out of memory. */
int cm_vsource_reroot(cm_vsource *vs, long source);
void cm_vsource_clear(cm_vsource *vs);

/* Does local vertex i see the source? For a window: does it see some point
 * of the open window (i not an end of the window). Returns 1 and the cone
 * of sight lines: *a, *b are pool ids such that the directions from vertex
 * i that reach the source lie strictly counter-clockwise from b and
 * strictly clockwise from a (for a point source *a = *b = the source);
 * 0 if not visible. */
int cm_vsource_vertex_cone(cm_vsource *vs, long i, long *a, long *b);
/* The same for the point with pool id p: 1 visible (cone in *a, *b), 0 not
 * visible, -1 if p is not strictly inside a triangle of the polygon. */
int cm_vsource_point_cone(cm_vsource *vs, long p, long *a, long *b);

#endif
