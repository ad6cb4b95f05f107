/* Boundary groups for Abaqus decks (abaqus_sets.h). Gmsh 4.8 writes a
 * surface group to a deck only as shell elements, which would join the
 * analysis; these blocks name the same faces without adding elements. */
#include "abaqus_sets.h"

#include <errno.h>
#include <inttypes.h>
#include <stdlib.h>
#include <string.h>

/* Abaqus reads at most 16 entries a data line. */
#define PER_LINE 16

static int write_node_set(FILE *file, const volume_mesh *mesh, size_t g, unsigned char *member)
{
    memset(member, 0, mesh->num_nodes);
    for (size_t i = mesh->group_offsets[g]; i < mesh->group_offsets[g + 1]; i++)
        for (int c = 0; c < 4 && mesh->faces[4 * i + c] >= 0; c++) member[mesh->faces[4 * i + c]] = 1;
    if (fprintf(file, "*NSET, NSET=%s\n", mesh->group_names[g]) < 0) return -1;
    size_t on_line = 0;
    for (size_t v = 0; v < mesh->num_nodes; v++) {
        if (!member[v]) continue;
        if (fprintf(file, on_line ? ", %zu" : "%zu", v + 1) < 0) return -1;
        if (++on_line == PER_LINE && fputc('\n', file) == EOF) return -1;
        on_line %= PER_LINE;
    }
    return on_line && fputc('\n', file) == EOF ? -1 : 0;
}

/* One line per face: its element and the element's face (S1 ...). */
static int write_surface(FILE *file, const volume_mesh *mesh, size_t g)
{
    if (fprintf(file, "*SURFACE, NAME=%s, TYPE=ELEMENT\n", mesh->group_names[g]) < 0) return -1;
    for (size_t i = mesh->group_offsets[g]; i < mesh->group_offsets[g + 1]; i++)
        if (fprintf(file, "%" PRId64 ", S%" PRId64 "\n", mesh->face_cells[2 * i] + 1, mesh->face_cells[2 * i + 1] + 1) < 0)
            return -1;
    return 0;
}

int abaqus_write_sets(FILE *file, const volume_mesh *mesh)
{
    unsigned char *member = malloc(mesh->num_nodes + 1);
    if (!member) {
        errno = ENOMEM;
        return -1;
    }
    int failed = 0;
    for (size_t g = 0; !failed && mesh->num_faces && g < mesh->num_groups; g++)
        failed = write_node_set(file, mesh, g, member) || (mesh->face_cells && write_surface(file, mesh, g));
    free(member);
    if (failed && !errno) errno = EIO;
    return failed ? -1 : 0;
}
