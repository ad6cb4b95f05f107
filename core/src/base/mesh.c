#include <stdlib.h>
#include <string.h>

#include "base/mesh.h"

static int by_edge(const void *a, const void *b)
{
    const cm_edge_key *x = a, *y = b;
    if (x->lo != y->lo) return x->lo < y->lo ? -1 : 1;
    if (x->hi != y->hi) return x->hi < y->hi ? -1 : 1;
    return (x->corner > y->corner) - (x->corner < y->corner);
}

cm_edge_key *cm_mesh_edge_keys(const int32_t *tri, size_t nt)
{
    cm_edge_key *e = malloc((3 * nt + 1) * sizeof *e);
    if (!e) return NULL;
    for (size_t c = 0; c < 3 * nt; c++) {
        int32_t u = tri[c], w = tri[cm_corner_next(c)];
        e[c] = (cm_edge_key){u < w ? u : w, u < w ? w : u, (int32_t)c};
    }
    qsort(e, 3 * nt, sizeof *e, by_edge);
    return e;
}

void cm_mesh_clear(cm_mesh *mesh)
{
    if (mesh->xy)
        for (size_t g = 0; g < mesh->k; g++) free(mesh->xy[g]);
    free(mesh->xy);
    free(mesh->tri);
    mesh->xy = NULL;
    mesh->tri = NULL;
    mesh->nv = mesh->nt = 0;
}

int cm_mesh_copy(cm_mesh *dst, const cm_mesh *src)
{
    *dst = (cm_mesh){src->k, src->nv, src->nt, calloc(src->k, sizeof *dst->xy), malloc((3 * src->nt + 1) * sizeof *dst->tri),
                     src->loop_start, src->num_loops};
    int ok = dst->xy && dst->tri;
    for (size_t g = 0; ok && g < src->k; g++) ok = (dst->xy[g] = malloc((2 * src->nv + 1) * sizeof **dst->xy)) != NULL;
    if (!ok) {
        cm_mesh_clear(dst);
        return -1;
    }
    for (size_t g = 0; g < src->k; g++) memcpy(dst->xy[g], src->xy[g], 2 * src->nv * sizeof **dst->xy);
    memcpy(dst->tri, src->tri, 3 * src->nt * sizeof *dst->tri);
    return 0;
}

static size_t loop_of(const size_t *loop_start, size_t i)
{
    size_t l = 0;
    while (i >= loop_start[l + 1]) l++;
    return l;
}

size_t cm_loops_next(const size_t *loop_start, size_t n, size_t i)
{
    if (!loop_start) return (i + 1) % n;
    size_t l = loop_of(loop_start, i);
    return i + 1 == loop_start[l + 1] ? loop_start[l] : i + 1;
}

size_t cm_loops_prev(const size_t *loop_start, size_t n, size_t i)
{
    if (!loop_start) return (i + n - 1) % n;
    size_t l = loop_of(loop_start, i);
    return i == loop_start[l] ? loop_start[l + 1] - 1 : i - 1;
}
