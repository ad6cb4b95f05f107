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
