#define _DEFAULT_SOURCE /* mkstemps */

#include "write_volume.h"

#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

#ifdef CM_HAVE_GMSH
#include <gmshc.h>

#include "interrupt.h"
#endif

static const char *const extensions[] = {"msh", "vtk", "inp", "bdf", "unv"};

static const char *extension_of(const char *path)
{
    const char *slash = strrchr(path, '/');
    const char *dot = strrchr(path, '.');
    return dot && (!slash || dot > slash + 1) ? dot + 1 : NULL;
}

int volume_extension_known(const char *path)
{
    const char *extension = extension_of(path);
    for (size_t i = 0; extension && i < sizeof extensions / sizeof extensions[0]; i++)
        if (strcasecmp(extension, extensions[i]) == 0) return 0;
    return -1;
}

#ifndef CM_HAVE_GMSH

int volume_writer_available(void) { return 0; }

int write_volume(const char *path, const volume_mesh *mesh, double msh_version,
                 cli_error *error)
{
    (void)mesh, (void)msh_version;
    cli_error_set(error, "cannot write %s: this compatmesh was built without Gmsh "
                  "(libgmsh-dev, CMake option CM_WITH_GMSH)", path);
    return CLI_EXIT_INTERNAL;
}

#else

int volume_writer_available(void) { return 1; }

/* Gmsh's last error, or a generic note when it recorded none. */
static void gmsh_failure(const char *path, const char *what, cli_error *error)
{
    char *message = NULL;
    int ierr = 0;
    gmshLoggerGetLastError(&message, &ierr);
    cli_error_set(error, "cannot write %s: Gmsh failed to %s%s%s", path, what,
                  message && message[0] ? ": " : "", message ? message : "");
    if (message) gmshFree(message);
}

/* Hands the mesh to Gmsh as one discrete volume (entity and physical group
 * 1, "sweep") with nodes and elements numbered from 1. */
static int add_mesh(const volume_mesh *mesh, cli_error *error, const char *path)
{
    int ierr = 0;
    size_t per_cell = mesh->tetrahedra ? 4 : 6;
    int element_type = mesh->tetrahedra ? 4 : 6; /* Gmsh: 4-node tet, 6-node prism */
    size_t *node_tags = malloc((mesh->num_nodes + 1) * sizeof *node_tags);
    size_t *cell_tags = malloc((mesh->num_cells + 1) * sizeof *cell_tags);
    size_t *cell_nodes = malloc((per_cell * mesh->num_cells + 1) * sizeof *cell_nodes);
    int code = CLI_EXIT_INTERNAL;
    if (!node_tags || !cell_tags || !cell_nodes) {
        cli_error_set(error, "out of memory");
        goto done;
    }
    for (size_t i = 0; i < mesh->num_nodes; i++) node_tags[i] = i + 1;
    for (size_t i = 0; i < mesh->num_cells; i++) cell_tags[i] = i + 1;
    for (size_t i = 0; i < per_cell * mesh->num_cells; i++)
        cell_nodes[i] = (size_t)mesh->cells[i] + 1;
    gmshModelAdd("compatmesh_sweep", &ierr);
    if (!ierr) gmshModelAddDiscreteEntity(3, 1, NULL, 0, &ierr);
    if (!ierr)
        gmshModelMeshAddNodes(3, 1, node_tags, mesh->num_nodes, (double *)mesh->nodes,
                              3 * mesh->num_nodes, NULL, 0, &ierr);
    if (!ierr)
        gmshModelMeshAddElementsByType(1, element_type, cell_tags, mesh->num_cells,
                                       cell_nodes, per_cell * mesh->num_cells, &ierr);
    int volume = 1;
    if (!ierr) gmshModelAddPhysicalGroup(3, &volume, 1, 1, &ierr);
    if (!ierr) gmshModelSetPhysicalName(3, 1, "sweep", &ierr);
    if (ierr) gmsh_failure(path, "take the mesh", error);
    else code = CLI_EXIT_OK;
done:
    free(node_tags);
    free(cell_tags);
    free(cell_nodes);
    return code;
}

/* "dir/name.EXT" -> "dir/.name.compatmesh-XXXXXX.ext", created empty (so
 * the name is ours) in the target's directory, so rename is atomic. */
static char *make_temporary(const char *path, cli_error *error)
{
    const char *slash = strrchr(path, '/');
    size_t dir_length = slash ? (size_t)(slash - path) + 1 : 0;
    const char *name = path + dir_length;
    const char *extension = extension_of(path);
    size_t stem_length = (size_t)(extension - 1 - name);
    size_t size = strlen(path) + 32;
    char *temporary = malloc(size);
    if (!temporary) {
        cli_error_set(error, "out of memory");
        return NULL;
    }
    int length = snprintf(temporary, size, "%.*s.%.*s.compatmesh-XXXXXX.%s",
                          (int)dir_length, path, (int)stem_length, name, extension);
    /* Gmsh knows the extensions in lower case only; the final name keeps
     * the user's spelling. */
    for (char *c = temporary + length - strlen(extension); *c; c++) *c = (char)tolower(*c);
    int fd = mkstemps(temporary, (int)strlen(extension) + 1);
    if (fd < 0) {
        cli_error_set(error, "cannot write %s: %s", path, strerror(errno));
        free(temporary);
        return NULL;
    }
    /* mkstemps makes the file private; give it the mode a new file gets. */
    mode_t mask = umask(0);
    umask(mask);
    fchmod(fd, 0666 & ~mask);
    close(fd);
    return temporary;
}

int write_volume(const char *path, const volume_mesh *mesh, double msh_version,
                 cli_error *error)
{
    writing_output = 1; /* the temporary file exists until the rename */
    char *temporary = make_temporary(path, error);
    if (!temporary) {
        writing_output = 0;
        return CLI_EXIT_INTERNAL;
    }
    int ierr = 0;
    gmshInitialize(0, NULL, 0, &ierr);
    if (ierr) {
        gmsh_failure(path, "start", error);
        unlink(temporary);
        free(temporary);
        return CLI_EXIT_INTERNAL;
    }
    catch_interrupts(); /* Gmsh may install its own handlers; ours leave no file */
    gmshOptionSetNumber("General.Terminal", 0, &ierr);
    gmshOptionSetNumber("Mesh.MshFileVersion", msh_version, &ierr);
    gmshOptionSetNumber("Mesh.Binary", 0, &ierr);
    /* Nastran: large fields (16 characters), else coordinates lose digits. */
    gmshOptionSetNumber("Mesh.BdfFieldFormat", 2, &ierr);
    int code = add_mesh(mesh, error, path);
    if (code == CLI_EXIT_OK) {
        gmshWrite(temporary, &ierr);
        if (ierr) {
            gmsh_failure(path, "write the file", error);
            code = CLI_EXIT_INTERNAL;
        }
    }
    gmshFinalize(&ierr);
    catch_interrupts();
    if (code == CLI_EXIT_OK && interrupted) {
        cli_error_set(error, "interrupted; nothing written");
        code = CLI_EXIT_INTERRUPTED;
    }
    if (code == CLI_EXIT_OK && rename(temporary, path) != 0) {
        cli_error_set(error, "cannot write %s: %s", path, strerror(errno));
        code = CLI_EXIT_INTERNAL;
    }
    if (code != CLI_EXIT_OK) unlink(temporary);
    writing_output = 0;
    free(temporary);
    return code;
}

#endif
