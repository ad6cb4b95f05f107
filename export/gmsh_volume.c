#include "gmsh_volume.h"

#include <dlfcn.h>
#include <errno.h>
#include <gmshc.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "abaqus_sets.h"

#define GMSH_FUNCTIONS(X)                                                                        \
    X(Initialize) X(Finalize) X(Free) X(LoggerGetLastError) X(ModelAdd) X(ModelAddDiscreteEntity)  \
    X(ModelAddPhysicalGroup) X(ModelMeshAddElementsByType) X(ModelMeshAddNodes)                   \
    X(ModelMeshGetElementsByType) X(ModelMeshSetOrder) X(ModelSetPhysicalName) X(OptionSetNumber) \
    X(Write)

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

/* Hands the boundary faces of group g to Gmsh's discrete surface g + 1,
 * with physical group g + 1 if `physical`; element tags from *next_tag on. */
static int add_boundary_group(const volume_mesh *mesh, size_t g, int physical, size_t *next_tag, size_t *tags,
                              size_t *nodes)
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
    if (!ierr && physical) gmsh.ModelAddPhysicalGroup(2, &surface, 1, surface, &ierr);
    if (!ierr && physical) gmsh.ModelSetPhysicalName(2, surface, mesh->group_names[g], &ierr);
    return ierr;
}

/* The mesh as Gmsh's model: one discrete volume (entity and physical group
 * 1, "sweep") with nodes and elements numbered from 1; with boundary, the
 * surfaces first (they bound the volume), their faces after the nodes,
 * which the volume holds, each with a physical group if `physical`. */
static int add_mesh(const volume_mesh *mesh, int boundary, int physical, char *message, size_t size)
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
    for (size_t g = 0; g < num_groups && !ierr; g++)
        ierr = add_boundary_group(mesh, g, physical, &next_tag, face_tags, face_nodes);
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

/* The file's text (malloc'd, NUL-terminated; *size its length), or NULL. */
static char *read_text(const char *file, size_t *size)
{
    FILE *in = fopen(file, "rb");
    char *text = NULL;
    long length = -1;
    if (in && fseek(in, 0, SEEK_END) == 0) length = ftell(in);
    if (length >= 0 && fseek(in, 0, SEEK_SET) == 0 && (text = malloc((size_t)length + 1)) &&
        fread(text, 1, (size_t)length, in) == (size_t)length) {
        text[length] = '\0';
        *size = (size_t)length;
    } else {
        free(text);
        text = NULL;
    }
    if (in) fclose(in);
    return text;
}

/* Where at(text, size, &drop) finds a place (NOT_FOUND: none, the file
 * stays as it is), rewrites the file with text[from, from + drop) replaced
 * by insert; 0 or -1 (errno set). */
#define NOT_FOUND ((size_t)-1)
static int splice(const char *file, size_t (*at)(const char *text, size_t size, size_t *drop), const char *insert)
{
    size_t size = 0, drop = 0;
    char *text = read_text(file, &size);
    int ok = 0;
    size_t from = text ? at(text, size, &drop) : NOT_FOUND;
    if (text && from == NOT_FOUND) ok = 1;
    else if (text) {
        FILE *out = fopen(file, "wb");
        ok = out && fwrite(text, 1, from, out) == from && fputs(insert, out) >= 0 &&
             fwrite(text + from + drop, 1, size - from - drop, out) == size - from - drop;
        if (out && fclose(out) != 0) ok = 0;
    }
    free(text);
    return ok ? 0 : -1;
}

/* Nastran: after the leading "$" comment lines. */
static size_t after_comments(const char *text, size_t size, size_t *drop)
{
    size_t head = 0;
    while (head < size && text[head] == '$') {
        const char *end = strchr(text + head, '\n');
        head = end ? (size_t)(end - text) + 1 : size;
    }
    *drop = 0;
    return head;
}

/* Abaqus: the title line after *Heading (NOT_FOUND without one). */
static size_t title_line(const char *text, size_t size, size_t *drop)
{
    static const char heading[] = "*Heading\n";
    size_t from = sizeof heading - 1;
    const char *end = size >= from && strncmp(text, heading, from) == 0 ? strchr(text + from, '\n') : NULL;
    *drop = end ? (size_t)(end - text) + 1 - from : 0;
    return end ? from : NOT_FOUND;
}

static int compare_tags(const void *pa, const void *pb)
{
    size_t a = *(const size_t *)pa, b = *(const size_t *)pb;
    return (a > b) - (a < b);
}

/* The node tags of each boundary group's faces as Gmsh numbers them after
 * setOrder (the mid-edge nodes too), sorted, unique: lists[g] (malloc'd),
 * counts[g]. 0, or -1. */
static int group_nodes(const volume_mesh *mesh, size_t **lists, size_t *counts)
{
    /* second-order faces: 6-node triangles (9), 8-node quadrangles (16) */
    static const int types[2] = {9, 16};
    int ierr = 0;
    for (size_t g = 0; g < mesh->num_groups && !ierr; g++) {
        size_t *all = NULL, n = 0;
        for (int i = 0; i < 2 && !ierr; i++) {
            size_t *tags = NULL, *nodes = NULL, nt = 0, nn = 0;
            gmsh.ModelMeshGetElementsByType(types[i], &tags, &nt, &nodes, &nn, (int)g + 1, 0, 1, &ierr);
            size_t *grown = ierr ? NULL : realloc(all, (n + nn + 1) * sizeof *all);
            if (grown) memcpy(grown + n, nodes, nn * sizeof *nodes), all = grown, n += nn;
            else ierr = 1;
            if (tags) gmsh.Free(tags);
            if (nodes) gmsh.Free(nodes);
        }
        if (ierr) {
            free(all);
            break;
        }
        qsort(all, n, sizeof *all, compare_tags);
        size_t unique = 0;
        for (size_t i = 0; i < n; i++)
            if (!unique || all[i] != all[unique - 1]) all[unique++] = all[i];
        lists[g] = all, counts[g] = unique;
    }
    return ierr ? -1 : 0;
}

/* What Gmsh's file lacks, added (see gmsh_volume.h); the sets of a
 * second-order deck from Gmsh's numbering (group_nodes, before Gmsh
 * finalises). 0, or -1 with the reason in message. */
static int complete_file(const char *file, const char *extension, const volume_mesh *mesh,
                         const gmsh_write_options *options, char *message, size_t size)
{
    int failed = 0;
    if (strcasecmp(extension, ".bdf") == 0) failed = splice(file, after_comments, "BEGIN BULK\n");
    if (strcasecmp(extension, ".inp") != 0) return failed ? fail(message, size, "%s", strerror(errno)) : 0;
    if (options->title) {
        size_t length = strlen(options->title);
        char *title = malloc(length + 3);
        if (title) snprintf(title, length + 3, " %s\n", options->title);
        failed = !title || splice(file, title_line, title);
        free(title);
    }
    size_t **lists = NULL, *counts = NULL;
    if (!failed && mesh->num_faces && options->order == 2) {
        lists = calloc(mesh->num_groups + 1, sizeof *lists), counts = calloc(mesh->num_groups + 1, sizeof *counts);
        failed = !lists || !counts || group_nodes(mesh, lists, counts);
    }
    FILE *out = failed || !mesh->num_faces ? NULL : fopen(file, "ab");
    if (!failed && mesh->num_faces)
        failed = !out || abaqus_write_sets(out, mesh, (const size_t *const *)lists, counts) != 0;
    if (out && fclose(out) != 0) failed = 1;
    for (size_t g = 0; lists && g < mesh->num_groups; g++) free(lists[g]);
    free(lists), free(counts);
    return failed ? fail(message, size, "%s", strerror(errno ? errno : EIO)) : 0;
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
    const char *dot = strrchr(file, '.'), *extension = dot ? dot : "";
    int msh = strcasecmp(extension, ".msh") == 0, second = options->order == 2;
    /* A second-order deck's surfaces are there for their nodes' new numbers
     * (physical only in .msh files), which its node sets need; Gmsh places
     * the new nodes on the straight edges. */
    int result = add_mesh(mesh, msh || (second && strcasecmp(extension, ".inp") == 0), msh, message, size);
    if (result == 0 && second) {
        gmsh.OptionSetNumber("Mesh.SecondOrderIncomplete", 1, &ierr);
        gmsh.OptionSetNumber("Mesh.SecondOrderLinear", 1, &ierr);
        gmsh.ModelMeshSetOrder(2, &ierr);
        if (ierr) result = gmsh_failure("make second-order cells", message, size);
    }
    if (result == 0) {
        gmsh.Write(file, &ierr);
        if (ierr) result = gmsh_failure("write the file", message, size);
    }
    if (result == 0) result = complete_file(file, extension, mesh, options, message, size);
    gmsh.Finalize(&ierr);
    return result;
}
