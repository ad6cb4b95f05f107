#include "gmsh_volume.h"

#include <dlfcn.h>
#include <gmshc.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#define GMSH_FUNCTIONS(X)                                                                        \
    X(Initialize) X(Finalize) X(Free) X(LoggerGetLastError) X(ModelAdd) X(ModelAddDiscreteEntity)  \
    X(ModelAddPhysicalGroup) X(ModelMeshAddElementsByType) X(ModelMeshAddNodes)                   \
    X(ModelSetPhysicalName) X(OptionSetNumber) X(Write)

static struct {
    void *library;
#define GMSH_POINTER(name) __typeof__(gmsh##name) *name;
    GMSH_FUNCTIONS(GMSH_POINTER)
#undef GMSH_POINTER
} gmsh;

static int fail(char *message, size_t size, const char *format, ...)
{
    va_list args;
    va_start(args, format);
    vsnprintf(message, size, format, args);
    va_end(args);
    return -1;
}

static int load_gmsh(int deep_bind, char *message, size_t size)
{
    if (gmsh.library) return 0;
    int flags = RTLD_NOW | RTLD_LOCAL;
#ifdef RTLD_DEEPBIND
    if (deep_bind) flags |= RTLD_DEEPBIND;
#endif
    void *library = dlopen(CM_GMSH_SONAME, flags);
    if (!library) return fail(message, size, "Gmsh could not be loaded (%s)", dlerror());
    struct { const char *name; void **slot; } symbols[] = {
#define GMSH_SYMBOL(name) {"gmsh" #name, (void **)&gmsh.name},
        GMSH_FUNCTIONS(GMSH_SYMBOL)
#undef GMSH_SYMBOL
    };
    for (size_t i = 0; i < sizeof symbols / sizeof symbols[0]; i++) {
        *symbols[i].slot = dlsym(library, symbols[i].name);
        if (!*symbols[i].slot) {
            dlclose(library);
            return fail(message, size, "%s has no %s", CM_GMSH_SONAME, symbols[i].name);
        }
    }
    gmsh.library = library;
    return 0;
}

/* Gmsh's last error, or a generic note when it recorded none. */
static int gmsh_failure(const char *what, char *message, size_t size)
{
    char *last = NULL;
    int ierr = 0;
    gmsh.LoggerGetLastError(&last, &ierr);
    fail(message, size, "Gmsh failed to %s%s%s", what, last && last[0] ? ": " : "", last ? last : "");
    if (last) gmsh.Free(last);
    return -1;
}

/* Hands the boundary faces of group g to Gmsh's discrete surface g + 1
 * with physical group g + 1; element tags from *next_tag on. */
static int add_boundary_group(const volume_mesh *mesh, size_t g, size_t *next_tag, size_t *tags, size_t *nodes)
{
    int ierr = 0, surface = (int)g + 1;
    for (int corners = 3; corners <= 4 && !ierr; corners++) {
        size_t count = 0;
        for (size_t i = mesh->group_offsets[g]; i < mesh->group_offsets[g + 1]; i++) {
            const int32_t *f = mesh->faces + 4 * i;
            if ((f[3] >= 0) != (corners == 4)) continue;
            for (int c = 0; c < corners; c++) nodes[(size_t)corners * count + (size_t)c] = (size_t)f[c] + 1;
            tags[count++] = (*next_tag)++;
        }
        if (count) /* Gmsh: 3-node triangle 2, 4-node quadrangle 3 */
            gmsh.ModelMeshAddElementsByType(surface, corners == 3 ? 2 : 3, tags, count, nodes,
                                           (size_t)corners * count, &ierr);
    }
    if (!ierr) gmsh.ModelAddPhysicalGroup(2, &surface, 1, surface, &ierr);
    if (!ierr) gmsh.ModelSetPhysicalName(2, surface, mesh->group_names[g], &ierr);
    return ierr;
}

/* The mesh as Gmsh's model: one discrete volume (entity and physical group
 * 1, "sweep") with nodes and elements numbered from 1; with boundary, the
 * surfaces first (they bound the volume), their faces after the nodes,
 * which the volume holds. */
static int add_mesh(const volume_mesh *mesh, int boundary, char *message, size_t size)
{
    int ierr = 0;
    size_t per_cell = mesh->tetrahedra ? 4 : 6;
    int element_type = mesh->tetrahedra ? 4 : 6; /* Gmsh: 4-node tet, 6-node prism */
    size_t num_faces = boundary ? mesh->num_faces : 0, num_groups = num_faces ? mesh->num_groups : 0;
    size_t *node_tags = malloc((mesh->num_nodes + 1) * sizeof *node_tags);
    size_t *cell_tags = malloc((mesh->num_cells + 1) * sizeof *cell_tags);
    size_t *cell_nodes = malloc((per_cell * mesh->num_cells + 1) * sizeof *cell_nodes);
    size_t *face_tags = malloc((num_faces + 1) * sizeof *face_tags);
    size_t *face_nodes = malloc((4 * num_faces + 1) * sizeof *face_nodes);
    int *surfaces = malloc((num_groups + 1) * sizeof *surfaces);
    int result = -1;
    if (!node_tags || !cell_tags || !cell_nodes || !face_tags || !face_nodes || !surfaces) {
        fail(message, size, "out of memory");
        goto done;
    }
    for (size_t i = 0; i < mesh->num_nodes; i++) node_tags[i] = i + 1;
    for (size_t i = 0; i < mesh->num_cells; i++) cell_tags[i] = i + 1;
    for (size_t i = 0; i < per_cell * mesh->num_cells; i++) cell_nodes[i] = (size_t)mesh->cells[i] + 1;
    gmsh.ModelAdd("compatmesh_sweep", &ierr);
    for (size_t g = 0; g < num_groups && !ierr; g++) {
        surfaces[g] = (int)g + 1;
        gmsh.ModelAddDiscreteEntity(2, surfaces[g], NULL, 0, &ierr);
    }
    if (!ierr) gmsh.ModelAddDiscreteEntity(3, 1, surfaces, num_groups, &ierr);
    if (!ierr)
        gmsh.ModelMeshAddNodes(3, 1, node_tags, mesh->num_nodes, (double *)mesh->nodes, 3 * mesh->num_nodes, NULL, 0,
                               &ierr);
    if (!ierr)
        gmsh.ModelMeshAddElementsByType(1, element_type, cell_tags, mesh->num_cells, cell_nodes,
                                        per_cell * mesh->num_cells, &ierr);
    int volume = 1;
    if (!ierr) gmsh.ModelAddPhysicalGroup(3, &volume, 1, 1, &ierr);
    if (!ierr) gmsh.ModelSetPhysicalName(3, 1, "sweep", &ierr);
    size_t next_tag = mesh->num_cells + 1;
    for (size_t g = 0; g < num_groups && !ierr; g++) ierr = add_boundary_group(mesh, g, &next_tag, face_tags, face_nodes);
    result = ierr ? gmsh_failure("take the mesh", message, size) : 0;
done:
    free(node_tags);
    free(cell_tags);
    free(cell_nodes);
    free(face_tags);
    free(face_nodes);
    free(surfaces);
    return result;
}

int gmsh_write_volume(const char *file, const volume_mesh *mesh, const gmsh_write_options *options, char *message,
                      size_t size)
{
    if (load_gmsh(options->deep_bind, message, size) != 0) return -1;
    int ierr = 0;
    gmsh.Initialize(0, NULL, 0, &ierr);
    if (ierr) return gmsh_failure("start", message, size);
    if (options->started) options->started();
    gmsh.OptionSetNumber("General.Terminal", 0, &ierr);
    gmsh.OptionSetNumber("Mesh.MshFileVersion", options->msh_version, &ierr);
    gmsh.OptionSetNumber("Mesh.Binary", 0, &ierr);
    /* Nastran: large fields (16 characters), else coordinates lose digits. */
    gmsh.OptionSetNumber("Mesh.BdfFieldFormat", 2, &ierr);
    const char *dot = strrchr(file, '.');
    int result = add_mesh(mesh, dot && strcasecmp(dot, ".msh") == 0, message, size);
    if (result == 0) {
        gmsh.Write(file, &ierr);
        if (ierr) result = gmsh_failure("write the file", message, size);
    }
    gmsh.Finalize(&ierr);
    return result;
}
