/* Sets of common diagonals: one bit per vertex pair of a polygon (n^2 / 8
 * bytes, an eighth of a byte table), and views that read a sub-polygon's
 * pairs out of its ancestor's set through a map of vertex indices.
 *
 * A diagonal between two vertices of a sub-polygon cut from a polygon
 * along its diagonals is a diagonal of the sub-polygon iff it is one of
 * the polygon: so every such sub-polygon reads the input's set. */
#ifndef CM_CONSTRUCT_DIAGSET_H
#define CM_CONSTRUCT_DIAGSET_H

#include <stddef.h>
#include <stdint.h>

typedef struct cm_diagset {
    long n;
    size_t stride; /* 64-bit words per row */
    uint64_t *bits;
} cm_diagset;

/* An empty set over n vertices. Returns 0 or -1 out of memory. */
int cm_diagset_init(cm_diagset *s, long n);
void cm_diagset_clear(cm_diagset *s);
/* The set of the pairs (i, j) with matrix[i * n + j] != 0. 0 or -1. */
int cm_diagset_from_matrix(cm_diagset *s, long n, const unsigned char *matrix);

static inline void cm_diagset_add(cm_diagset *s, long i, long j)
{
    s->bits[(size_t)i * s->stride + (size_t)j / 64] |= (uint64_t)1 << (j % 64);
    s->bits[(size_t)j * s->stride + (size_t)i / 64] |= (uint64_t)1 << (i % 64);
}

static inline int cm_diagset_has(const cm_diagset *s, long i, long j)
{
    return (int)(s->bits[(size_t)i * s->stride + (size_t)j / 64] >> (j % 64)) & 1;
}

/* Index of the lowest set bit of a nonzero word. */
static inline int cm_lowest_bit(uint64_t bits)
{
#if defined(__GNUC__) || defined(__clang__)
    return __builtin_ctzll(bits);
#else
    int i = 0;
    while (!(bits & 1)) bits >>= 1, i++;
    return i;
#endif
}

/* Sub-polygon vertex i is vertex map[i] of the set's polygon (map NULL:
 * the identity). */
typedef struct cm_diagview {
    const cm_diagset *set;
    const int32_t *map;
} cm_diagview;

static inline int cm_diagview_has(const cm_diagview *v, long i, long j)
{
    return v->map ? cm_diagset_has(v->set, v->map[i], v->map[j]) : cm_diagset_has(v->set, i, j);
}

/* A view's pairs row by row, by words of the set's rows: O(n / 64 + row)
 * a row for a set over n vertices, where looking up every local pair costs
 * O(m) a row; for sub-polygons from CM_DIAGROWS_FROM vertices. */
#define CM_DIAGROWS_FROM 2048
typedef struct cm_diagrows {
    const cm_diagview *view;
    uint64_t *member;  /* the set's vertices that are the view's */
    int32_t *local_of; /* set vertex -> local vertex (members only) */
} cm_diagrows;

/* For a view of m local vertices. 0 or -1 out of memory. */
int cm_diagrows_open(cm_diagrows *r, const cm_diagview *view, long m);
/* The local vertices b that (a, b) is in the set for, in no set order,
 * into out (room for m). Returns their number. */
long cm_diagrows_row(const cm_diagrows *r, long a, int32_t *out);
void cm_diagrows_close(cm_diagrows *r);

#endif
