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

#include "compatmesh/compatmesh.h"
#include "interrupt.h"
#include "write_vtu.h"

#ifdef CM_HAVE_GMSH
#include <dlfcn.h>
#include <gmshc.h>
#endif

static const char *const extensions[] = {"msh", "vtk", "vtu", "inp", "bdf", "unv"};

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

static int write_with_gmsh(const char *temporary, const char *path, const volume_mesh *mesh,
                           double msh_version, cli_error *error)
{
    (void)temporary, (void)mesh, (void)msh_version;
    cli_error_set(error, "cannot write %s: this compatmesh was built without Gmsh "
                  "(libgmsh-dev, CMake option CM_WITH_GMSH); .vtu needs no Gmsh", path);
    return CLI_EXIT_INTERNAL;
}

#else

int volume_writer_available(void) { return 1; }

/* Gmsh is loaded when a volume is written, not at start: it brings about a
 * hundred shared libraries (OpenCascade, FLTK, GL) that would cost every
 * other command 0.09 s and 39 MB before any work. */
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

static int load_gmsh(const char *path, cli_error *error)
{
    if (gmsh.library) return CLI_EXIT_OK;
    void *library = dlopen(CM_GMSH_SONAME, RTLD_NOW | RTLD_LOCAL);
    if (!library) {
        cli_error_set(error, "cannot write %s: Gmsh could not be loaded (%s)", path, dlerror());
        return CLI_EXIT_INTERNAL;
    }
    struct { const char *name; void **slot; } symbols[] = {
#define GMSH_SYMBOL(name) {"gmsh" #name, (void **)&gmsh.name},
        GMSH_FUNCTIONS(GMSH_SYMBOL)
#undef GMSH_SYMBOL
    };
    for (size_t i = 0; i < sizeof symbols / sizeof symbols[0]; i++) {
        *symbols[i].slot = dlsym(library, symbols[i].name);
        if (!*symbols[i].slot) {
            cli_error_set(error, "cannot write %s: %s has no %s", path, CM_GMSH_SONAME, symbols[i].name);
            dlclose(library);
            return CLI_EXIT_INTERNAL;
        }
    }
    gmsh.library = library;
    return CLI_EXIT_OK;
}

/* Gmsh's last error, or a generic note when it recorded none. */
static void gmsh_failure(const char *path, const char *what, cli_error *error)
{
    char *message = NULL;
    int ierr = 0;
    gmsh.LoggerGetLastError(&message, &ierr);
    cli_error_set(error, "cannot write %s: Gmsh failed to %s%s%s", path, what,
                  message && message[0] ? ": " : "", message ? message : "");
    if (message) gmsh.Free(message);
}

/* Hands the boundary faces of group g to Gmsh's discrete surface g + 1
 * with physical group g + 1, named as the core names it; element tags
 * from *next_tag on. */
static int add_boundary_group(const volume_mesh *mesh, size_t g, size_t *next_tag, size_t *tags, size_t *nodes)
{
    int ierr = 0, surface = (int)g + 1;
    for (int corners = 3; corners <= 4 && !ierr; corners++) {
        size_t count = 0;
        for (size_t i = 0; i < mesh->num_faces; i++) {
            const int32_t *f = mesh->faces + 4 * i;
            if ((size_t)mesh->face_groups[i] != g || (f[3] >= 0) != (corners == 4)) continue;
            for (int c = 0; c < corners; c++) nodes[(size_t)corners * count + (size_t)c] = (size_t)f[c] + 1;
            tags[count++] = (*next_tag)++;
        }
        if (count) /* Gmsh: 3-node triangle 2, 4-node quadrangle 3 */
            gmsh.ModelMeshAddElementsByType(surface, corners == 3 ? 2 : 3, tags, count, nodes,
                                           (size_t)corners * count, &ierr);
    }
    char name[32];
    cm_sweep_boundary_group_name(g, name);
    if (!ierr) gmsh.ModelAddPhysicalGroup(2, &surface, 1, surface, &ierr);
    if (!ierr) gmsh.ModelSetPhysicalName(2, surface, name, &ierr);
    return ierr;
}

/* Hands the mesh to Gmsh as one discrete volume (entity and physical group
 * 1, "sweep") with nodes and elements numbered from 1; with boundary, its
 * boundary faces as the volume's bounding surfaces, one physical group
 * each. */
static int add_mesh(const volume_mesh *mesh, int boundary, cli_error *error, const char *path)
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
    int code = CLI_EXIT_INTERNAL;
    if (!node_tags || !cell_tags || !cell_nodes || !face_tags || !face_nodes || !surfaces) {
        cli_error_set(error, "out of memory");
        goto done;
    }
    for (size_t i = 0; i < mesh->num_nodes; i++) node_tags[i] = i + 1;
    for (size_t i = 0; i < mesh->num_cells; i++) cell_tags[i] = i + 1;
    for (size_t i = 0; i < per_cell * mesh->num_cells; i++)
        cell_nodes[i] = (size_t)mesh->cells[i] + 1;
    gmsh.ModelAdd("compatmesh_sweep", &ierr);
    /* The surfaces first, to bound the volume; their faces after the
     * nodes, which the volume holds. */
    for (size_t g = 0; g < num_groups && !ierr; g++) {
        surfaces[g] = (int)g + 1;
        gmsh.ModelAddDiscreteEntity(2, surfaces[g], NULL, 0, &ierr);
    }
    if (!ierr) gmsh.ModelAddDiscreteEntity(3, 1, surfaces, num_groups, &ierr);
    if (!ierr)
        gmsh.ModelMeshAddNodes(3, 1, node_tags, mesh->num_nodes, (double *)mesh->nodes,
                              3 * mesh->num_nodes, NULL, 0, &ierr);
    if (!ierr)
        gmsh.ModelMeshAddElementsByType(1, element_type, cell_tags, mesh->num_cells,
                                       cell_nodes, per_cell * mesh->num_cells, &ierr);
    int volume = 1;
    if (!ierr) gmsh.ModelAddPhysicalGroup(3, &volume, 1, 1, &ierr);
    if (!ierr) gmsh.ModelSetPhysicalName(3, 1, "sweep", &ierr);
    size_t next_tag = mesh->num_cells + 1;
    for (size_t g = 0; g < num_groups && !ierr; g++)
        ierr = add_boundary_group(mesh, g, &next_tag, face_tags, face_nodes);
    if (ierr) gmsh_failure(path, "take the mesh", error);
    else code = CLI_EXIT_OK;
done:
    free(node_tags);
    free(cell_tags);
    free(cell_nodes);
    free(face_tags);
    free(face_nodes);
    free(surfaces);
    return code;
}

/* Writes mesh to temporary through Gmsh, the format by its extension. */
static int write_with_gmsh(const char *temporary, const char *path, const volume_mesh *mesh,
                           double msh_version, cli_error *error)
{
    if (load_gmsh(path, error) != CLI_EXIT_OK) return CLI_EXIT_INTERNAL;
    int ierr = 0;
    gmsh.Initialize(0, NULL, 0, &ierr);
    if (ierr) {
        gmsh_failure(path, "start", error);
        return CLI_EXIT_INTERNAL;
    }
    catch_interrupts(); /* Gmsh may install its own handlers; ours leave no file */
    gmsh.OptionSetNumber("General.Terminal", 0, &ierr);
    gmsh.OptionSetNumber("Mesh.MshFileVersion", msh_version, &ierr);
    gmsh.OptionSetNumber("Mesh.Binary", 0, &ierr);
    /* Nastran: large fields (16 characters), else coordinates lose digits. */
    gmsh.OptionSetNumber("Mesh.BdfFieldFormat", 2, &ierr);
    /* Only Gmsh's own format takes the boundary: Gmsh 4.8 writes surface
     * groups to Abaqus, Nastran and UNV files as shell elements (CPS3,
     * CTRIA3), which would join the analysis, and VTK has no groups. */
    int code = add_mesh(mesh, strcasecmp(extension_of(path), "msh") == 0, error, path);
    if (code == CLI_EXIT_OK) {
        gmsh.Write(temporary, &ierr);
        if (ierr) {
            gmsh_failure(path, "write the file", error);
            code = CLI_EXIT_INTERNAL;
        }
    }
    gmsh.Finalize(&ierr);
    catch_interrupts();
    return code;
}

#endif

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

/* Gmsh writes Nastran bulk data without the BEGIN BULK line that readers
 * (meshio among them) look for: inserted after the leading comments. */
static int add_begin_bulk(const char *temporary, const char *path, cli_error *error)
{
    FILE *file = fopen(temporary, "rb");
    char *text = NULL;
    long size = -1;
    if (file && fseek(file, 0, SEEK_END) == 0) size = ftell(file);
    if (size >= 0 && fseek(file, 0, SEEK_SET) == 0 && (text = malloc((size_t)size + 1)) &&
        fread(text, 1, (size_t)size, file) == (size_t)size) {
        text[size] = '\0';
    } else {
        size = -1;
    }
    if (file) fclose(file);
    int code = CLI_EXIT_INTERNAL;
    if (size >= 0) {
        size_t head = 0; /* the "$" comment lines */
        while (text[head] == '$') {
            const char *end = strchr(text + head, '\n');
            head = end ? (size_t)(end - text) + 1 : (size_t)size;
        }
        file = fopen(temporary, "wb");
        if (file && fwrite(text, 1, head, file) == head && fputs("BEGIN BULK\n", file) >= 0 &&
            fwrite(text + head, 1, (size_t)size - head, file) == (size_t)size - head)
            code = CLI_EXIT_OK;
        if (file && fclose(file) != 0) code = CLI_EXIT_INTERNAL;
    }
    if (code != CLI_EXIT_OK) cli_error_set(error, "cannot write %s: %s", path, strerror(errno ? errno : EIO));
    free(text);
    return code;
}

/* Abaqus (and CalculiX) decks take boundary conditions on node sets; Gmsh
 * 4.8 writes a surface group only with its faces as shell elements, so the
 * boundary groups are appended as *NSET blocks (the nodes numbered from 1
 * as Gmsh numbers them), 16 to a line as Abaqus allows. */
static int add_node_sets(const char *temporary, const char *path, const volume_mesh *mesh, cli_error *error)
{
    unsigned char *member = malloc(mesh->num_nodes + 1);
    FILE *file = member ? fopen(temporary, "ab") : NULL;
    int ok = file != NULL;
    for (size_t g = 0; ok && g < mesh->num_groups; g++) {
        memset(member, 0, mesh->num_nodes);
        for (size_t i = 0; i < mesh->num_faces; i++)
            if ((size_t)mesh->face_groups[i] == g)
                for (int c = 0; c < 4 && mesh->faces[4 * i + c] >= 0; c++) member[mesh->faces[4 * i + c]] = 1;
        char name[32];
        cm_sweep_boundary_group_name(g, name);
        ok = fprintf(file, "*NSET, NSET=%s\n", name) > 0;
        size_t on_line = 0;
        for (size_t v = 0; ok && v < mesh->num_nodes; v++) {
            if (!member[v]) continue;
            ok = fprintf(file, on_line ? ", %zu" : "%zu", v + 1) > 0;
            if (ok && ++on_line == 16) ok = fputc('\n', file) != EOF, on_line = 0;
        }
        if (ok && on_line) ok = fputc('\n', file) != EOF;
    }
    if (file && fclose(file) != 0) ok = 0;
    free(member);
    if (!ok) cli_error_set(error, "cannot write %s: %s", path, member ? strerror(errno ? errno : EIO) : "out of memory");
    return ok ? CLI_EXIT_OK : CLI_EXIT_INTERNAL;
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
    const char *extension = extension_of(path);
    int code = strcasecmp(extension, "vtu") == 0 ? write_vtu(temporary, path, mesh, error)
                                                 : write_with_gmsh(temporary, path, mesh, msh_version, error);
    if (code == CLI_EXIT_OK && strcasecmp(extension, "bdf") == 0) code = add_begin_bulk(temporary, path, error);
    if (code == CLI_EXIT_OK && strcasecmp(extension, "inp") == 0 && mesh->num_faces)
        code = add_node_sets(temporary, path, mesh, error);
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
