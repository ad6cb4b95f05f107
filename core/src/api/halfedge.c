/* The half-edge structure of a result, and the exact check that the result
 * is a valid compatible triangulation. */
#include <stdlib.h>
#include <string.h>

#include "api/halfedge.h"
#include "geom/predicates.h"

typedef struct { int32_t lo, hi; int32_t slot; } corner_edge; /* slot = 3t + i */

/* One stable counting pass of from[0..ns-1] into to by the key lo (by_lo)
 * or hi, keys below nv; count: nv + 1 of scratch. */
static void count_pass(const corner_edge *from, corner_edge *to, size_t ns, size_t nv, int by_lo, size_t *count)
{
    memset(count, 0, (nv + 1) * sizeof *count);
    for (size_t i = 0; i < ns; i++) count[(size_t)(by_lo ? from[i].lo : from[i].hi) + 1]++;
    for (size_t v = 0; v < nv; v++) count[v + 1] += count[v];
    for (size_t i = 0; i < ns; i++) to[count[by_lo ? from[i].lo : from[i].hi]++] = from[i];
}

static int32_t slot_from(const int32_t *tri, int32_t s) { return tri[s]; }
static int32_t slot_to(const int32_t *tri, int32_t s) { return tri[s - s % 3 + (s + 1) % 3]; }

/* The triangles' ns directed edges as (lo, hi, slot), sorted by lo, then
 * hi, then slot: made by ascending slot, so a stable pass by hi, then one
 * by lo, O(ns + nv) (vertices checked to be below nv). 0, or -1 out of
 * memory. */
static int sorted_corner_edges(const int32_t *tri, size_t ns, size_t nv, corner_edge *e)
{
    corner_edge *tmp = calloc(ns + 1, sizeof *tmp);
    size_t *count = malloc((nv + 1) * sizeof *count);
    if (tmp && count) {
        for (size_t s = 0; s < ns; s++) {
            int32_t a = slot_from(tri, (int32_t)s), b = slot_to(tri, (int32_t)s);
            tmp[s] = (corner_edge){a < b ? a : b, a < b ? b : a, (int32_t)s};
        }
        count_pass(tmp, e, ns, nv, 0, count);
        count_pass(e, tmp, ns, nv, 1, count);
        memcpy(e, tmp, ns * sizeof *e);
    }
    int status = tmp && count ? 0 : -1;
    free(tmp), free(count);
    return status;
}

static cm_status check_orientation(cm_result *r)
{
    const cm_mesh *m = &r->mesh;
    for (size_t t = 0; t < m->nt; t++) {
        const int32_t *v = m->tri + 3 * t;
        for (int i = 0; i < 3; i++)
            if (v[i] < 0 || (size_t)v[i] >= m->nv || v[i] == v[(i + 1) % 3])
                return cm_fail(&r->error, CM_ERR_INTERNAL, "check: triangle %zu has bad vertex indices", t);
        for (size_t g = 0; g < m->k; g++) {
            const double *xy = m->xy[g];
            if (cm_orient2d(xy + 2 * v[0], xy + 2 * v[1], xy + 2 * v[2]) <= 0)
                return cm_fail(&r->error, CM_ERR_INTERNAL,
                               "check: triangle %zu (%d %d %d) is not counter-clockwise in geometry %zu",
                               t, v[0], v[1], v[2], g);
        }
    }
    return CM_OK;
}

static int alloc_halfedges(cm_result *r, size_t nh)
{
    size_t nv = r->mesh.nv, nt = r->mesh.nt;
    r->nh = nh;
    r->he_next = malloc(nh * sizeof *r->he_next);
    r->he_to = malloc(nh * sizeof *r->he_to);
    r->he_face = malloc(nh * sizeof *r->he_face);
    r->vertex_he = malloc((nv + 1) * sizeof *r->vertex_he);
    r->face_he = malloc((nt + 1) * sizeof *r->face_he);
    return r->he_next && r->he_to && r->he_face && r->vertex_he && r->face_he ? 0 : -1;
}

/* Pairs the triangles' directed edges into edges; unpaired ones must be the
 * boundary cycle. Fills he_to, he_face, he_next (inside triangles) and
 * he_of_slot. Returns the number of edges, or -1 / -2 (memory / invalid). */
static long pair_edges(cm_result *r, const int32_t *boundary, const size_t *loop_start,
                       int32_t *he_of_slot, int32_t *boundary_he)
{
    const cm_mesh *m = &r->mesh;
    size_t ns = 3 * m->nt, n = r->n;
    corner_edge *e = malloc((ns + 1) * sizeof *e);
    if (!e) return -1;
    if (sorted_corner_edges(m->tri, ns, m->nv, e) != 0) {
        free(e);
        return -1;
    }
    size_t interior = 0, on_boundary = 0;
    for (size_t i = 0; i < ns;) {
        size_t j = i + 1;
        while (j < ns && e[j].lo == e[i].lo && e[j].hi == e[i].hi) j++;
        if (j - i == 2 && slot_from(m->tri, e[i].slot) == slot_to(m->tri, e[i + 1].slot)) interior++;
        else if (j - i == 1) on_boundary++;
        else { /* three triangles on an edge, or a fold */
            cm_fail_at(&r->error, -1, e[i].lo, e[i].hi);
            free(e);
            return -2;
        }
        i = j;
    }
    if (on_boundary != n || alloc_halfedges(r, 2 * (interior + on_boundary))) {
        free(e);
        return on_boundary != n ? -2 : -1;
    }
    long edge = 0;
    for (size_t i = 0; i < ns; edge++) {
        int single = i + 1 >= ns || e[i + 1].lo != e[i].lo || e[i + 1].hi != e[i].hi;
        for (int side = 0; side < 2; side++) {
            int32_t h = (int32_t)(2 * edge + side);
            if (side == 1 && single) {
                /* the boundary half-edge: opposite direction, no face */
                int32_t s = e[i].slot;
                r->he_to[h] = slot_from(m->tri, s);
                r->he_face[h] = -1;
                int32_t from = slot_to(m->tri, s);
                /* position of edge from->to in the boundary cycle */
                boundary_he[from] = h;
                continue;
            }
            int32_t s = e[i + (size_t)side].slot;
            r->he_to[h] = slot_to(m->tri, s);
            r->he_face[h] = s / 3;
            he_of_slot[s] = h;
        }
        i += single ? 1 : 2;
    }
    free(e);
    /* Boundary half-edges must run boundary[i+1] -> boundary[i]. */
    for (size_t i = 0; i < n; i++) {
        int32_t h = boundary_he[boundary[cm_loops_next(loop_start, n, i)]];
        if (h < 0 || r->he_to[h] != boundary[i]) {
            cm_fail_at(&r->error, -1, boundary[i], boundary[cm_loops_next(loop_start, n, i)]);
            return -2;
        }
    }
    return edge;
}

cm_status cm_halfedge_build_and_check(cm_result *r, const int32_t *boundary,
                                      const size_t *loop_start, size_t num_loops)
{
    cm_status s = check_orientation(r);
    if (s != CM_OK) return s;
    const cm_mesh *m = &r->mesh;
    size_t nv = m->nv, nt = m->nt, n = r->n;
    int32_t *he_of_slot = malloc((3 * nt + 1) * sizeof *he_of_slot);
    int32_t *boundary_he = malloc((nv + 1) * sizeof *boundary_he);
    int32_t *prev = NULL, *out_count = NULL;
    s = CM_ERR_NO_MEMORY;
    if (!he_of_slot || !boundary_he) goto done;
    for (size_t v = 0; v < nv; v++) boundary_he[v] = -1;
    long ne = pair_edges(r, boundary, loop_start, he_of_slot, boundary_he);
    if (ne == -1) goto done;
    s = CM_ERR_INTERNAL;
    if (ne < 0) {
        if (r->error.vertex >= 0)
            cm_fail(&r->error, s, "check: at edge %ld-%ld the triangles do not form a surface bounded by the input loops",
                    r->error.vertex, r->error.other);
        else
            cm_fail(&r->error, s, "check: the triangles do not form a surface bounded by the input loops");
        goto done;
    }
    size_t nh = r->nh;
    for (size_t t = 0; t < nt; t++)
        for (int i = 0; i < 3; i++) r->he_next[he_of_slot[3 * t + i]] = he_of_slot[3 * t + (i + 1) % 3];
    for (size_t i = 0; i < n; i++) {
        int32_t h = boundary_he[boundary[cm_loops_next(loop_start, n, i)]];
        r->he_next[h] = boundary_he[boundary[i]];
    }
    for (size_t t = 0; t < nt; t++) r->face_he[t] = he_of_slot[3 * t];

    /* Every vertex is used and its half-edges form one fan (manifold). */
    prev = malloc(nh * sizeof *prev);
    out_count = calloc(nv + 1, sizeof *out_count);
    if (!prev || !out_count) { s = CM_ERR_NO_MEMORY; goto done; }
    for (size_t h = 0; h < nh; h++) prev[r->he_next[h]] = (int32_t)h;
    for (size_t v = 0; v < nv; v++) r->vertex_he[v] = -1;
    for (size_t h = 0; h < nh; h++) {
        int32_t from = r->he_to[h ^ 1];
        out_count[from]++;
        if (r->vertex_he[from] < 0 || r->he_face[h] < 0) r->vertex_he[from] = (int32_t)h;
    }
    for (size_t v = 0; v < nv; v++) {
        int32_t h0 = r->vertex_he[v], h = h0, around = 0;
        if (h0 < 0 || (v < n) != (boundary_he[v] >= 0 && r->he_face[h0] < 0)) {
            cm_fail(&r->error, s, "check: vertex %zu is unused or misplaced on the boundary", v);
            goto done;
        }
        do {
            h = prev[h] ^ 1;
            around++;
        } while (h != h0 && around <= out_count[v]);
        if (around != out_count[v]) {
            cm_fail(&r->error, s, "check: the triangles around vertex %zu do not form one fan", v);
            goto done;
        }
    }
    /* Connected, manifold, bounded by the loops: Euler characteristic
     * 1 - holes says it is a disk with those holes, nothing of higher genus. */
    long euler = 2 - (long)(loop_start ? num_loops : 1);
    if ((long)nv - ne + (long)nt != euler) {
        cm_fail(&r->error, s, "check: Euler characteristic %ld, expected %ld", (long)nv - ne + (long)nt, euler);
        goto done;
    }
    s = CM_OK;
done:
    free(he_of_slot), free(boundary_he), free(prev), free(out_count);
    return s;
}
