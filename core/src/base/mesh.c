#include <stdlib.h>

#include "base/mesh.h"

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
