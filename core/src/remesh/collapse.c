/* Steiner vertex removal: collapse an interior vertex v onto a neighbour u
 * (v's triangles become a fan from u) when the fan is valid in every
 * geometry, the mesh stays a disk, and the angles allow it. The
 * construction leaves far more Steiner vertices than compatibility needs;
 * this takes most of them out. */
#include <math.h>
#include <stdlib.h>

#include "geom/predicates.h"
#include "remesh/collapse.h"
#include "remesh/criteria.h"

/* Stars larger than this are not collapsed: the test costs degree^2. */
#define CM_COLLAPSE_MAX_DEGREE 64

typedef struct { double q; long j; } option;

static int32_t link_at(const cm_kmesh *km, const cm_ibuf *star, long i)
{
    return km->tri[cm_next(star->a[i])];
}

/* Smallest angle of the fan from u = link j, over all geometries. */
static double collapse_quality(const cm_kmesh *km, const cm_ibuf *star, long j)
{
    long m = (long)star->n;
    int32_t u = link_at(km, star, j);
    double q = CM_PI;
    for (size_t g = 0; g < km->k; g++)
        for (long i = 0; i < m; i++) {
            if (i == j || i == (j + m - 1) % m) continue;
            int32_t c = star->a[i];
            q = fmin(q, cm_triangle_min_angle(cm_kmesh_pos(km, g, u), cm_kmesh_pos(km, g, km->tri[cm_next(c)]),
                                     cm_kmesh_pos(km, g, km->tri[cm_prev(c)])));
        }
    return q;
}

static int fan_valid(const cm_kmesh *km, const cm_ibuf *star, long j)
{
    long m = (long)star->n;
    int32_t u = link_at(km, star, j);
    for (size_t g = 0; g < km->k; g++)
        for (long i = 0; i < m; i++) {
            if (i == j || i == (j + m - 1) % m) continue;
            int32_t c = star->a[i];
            if (!cm_kmesh_tri_ok(km, g, u, km->tri[cm_next(c)], km->tri[cm_prev(c)])) return 0;
        }
    return 1;
}

static int by_quality_desc(const void *pa, const void *pb)
{
    const option *a = pa, *b = pb;
    if (a->q != b->q) return a->q < b->q ? 1 : -1;
    return (a->j > b->j) - (a->j < b->j);
}

/* The best acceptable collapse of v: returns its quality and the corner
 * (at v, next to u) in *corner, -1 if none, -2 out of memory. star holds
 * v's corners afterwards. */
static double best_collapse(cm_kmesh *km, int32_t v, double threshold, cm_ibuf *star,
                            int32_t *corner)
{
    long m = cm_kmesh_star(km, v, star);
    if (m == -1) return -2;
    if (m < 3 || m > CM_COLLAPSE_MAX_DEGREE) return -1;
    double old = CM_PI;
    for (long i = 0; i < m; i++) old = fmin(old, km->tkey[star->a[i] / 3]);
    double need = fmin(old, threshold);
    option opts[CM_COLLAPSE_MAX_DEGREE];
    long count = 0;
    for (long j = 0; j < m; j++) {
        double q = collapse_quality(km, star, j);
        if (q > 0 && q >= need) opts[count++] = (option){q, j};
    }
    qsort(opts, (size_t)count, sizeof *opts, by_quality_desc);
    for (long i = 0; i < count; i++)
        if (fan_valid(km, star, opts[i].j) &&
            cm_kmesh_collapse_ok_topology(km, star->a[opts[i].j], star)) {
            *corner = star->a[opts[i].j];
            return opts[i].q;
        }
    return -1;
}

int cm_collapse_try(cm_kmesh *km, int32_t c, cm_ibuf *star)
{
    int32_t v = km->tri[c];
    if (v < 0 || cm_kmesh_is_boundary(km, v)) return 0;
    long m = cm_kmesh_star(km, v, star);
    if (m == -1) return -1;
    if (m < 3 || m > CM_COLLAPSE_MAX_DEGREE) return 0;
    long j = 0;
    while (j < m && star->a[j] != c) j++;
    if (j == m || !fan_valid(km, star, j) || !cm_kmesh_collapse_ok_topology(km, c, star)) return 0;
    cm_kmesh_collapse(km, c, star);
    return 1;
}

/* Re-rates v in the heap (key: minus the quality, so the best pops first). */
static int rate(cm_kmesh *km, cm_heap *h, int32_t v, double threshold, cm_ibuf *star)
{
    int32_t corner;
    double q = best_collapse(km, v, threshold, star, &corner);
    if (q == -2) return -1;
    if (q < 0) cm_heap_remove(h, v);
    else cm_heap_set(h, v, -q);
    return 0;
}

long cm_collapse_pass(cm_kmesh *km, double threshold, long max_collapses, cm_work *touched)
{
    cm_heap h;
    cm_ibuf star = {0}, ring = {0};
    long done = 0;
    if (cm_heap_init(&h, km->nv)) goto oom;
    for (int32_t v = km->n; v < km->nv; v++)
        if (km->vc[v] >= 0 && !cm_kmesh_is_boundary(km, v) && rate(km, &h, v, threshold, &star)) goto oom;
    while (max_collapses < 0 || done < max_collapses) {
        int32_t v = cm_heap_pop(&h), corner;
        if (v < 0) break;
        double q = best_collapse(km, v, threshold, &star, &corner);
        if (q == -2) goto oom;
        if (q < 0) continue;
        int32_t top = cm_heap_top(&h);
        if (top >= 0 && -h.key[top] > q + CM_ANGLE_EPS) { /* went stale: wait its turn */
            cm_heap_set(&h, v, -q);
            continue;
        }
        ring.n = 0;
        for (size_t i = 0; i < star.n; i++)
            if (cm_ibuf_push(&ring, link_at(km, &star, (long)i))) goto oom;
        cm_kmesh_collapse(km, corner, &star);
        done++;
        for (size_t i = 0; i < ring.n; i++) {
            int32_t w = ring.a[i];
            if (touched && cm_work_push(touched, w)) goto oom;
            if (!cm_kmesh_is_boundary(km, w) && rate(km, &h, w, threshold, &star)) goto oom;
        }
    }
    cm_heap_free(&h), cm_ibuf_free(&star), cm_ibuf_free(&ring);
    return done;
oom:
    cm_heap_free(&h), cm_ibuf_free(&star), cm_ibuf_free(&ring);
    return -1;
}
