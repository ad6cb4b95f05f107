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

/* Numbers from 1, PER_LINE a line. */
static int write_numbers(FILE *file, const size_t *numbers, size_t count)
{
    for (size_t i = 0; i < count; i++)
        if (fprintf(file, (i + 1) % PER_LINE == 0 || i + 1 == count ? "%zu\n" : "%zu, ", numbers[i]) < 0) return -1;
    return 0;
}

/* Group g's nodes from its faces (numbers from 1, ascending) into list. */
static size_t face_nodes(const volume_mesh *mesh, size_t g, unsigned char *member, size_t *list)
{
    memset(member, 0, mesh->num_nodes);
    for (size_t i = mesh->group_offsets[g]; i < mesh->group_offsets[g + 1]; i++)
        for (int c = 0; c < 4 && mesh->faces[4 * i + c] >= 0; c++) member[mesh->faces[4 * i + c]] = 1;
    size_t count = 0;
    for (size_t v = 0; v < mesh->num_nodes; v++)
        if (member[v]) list[count++] = v + 1;
    return count;
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

int abaqus_write_sets(FILE *file, const volume_mesh *mesh, const size_t *const *nodes, const size_t *counts)
{
    unsigned char *member = nodes ? NULL : malloc(mesh->num_nodes + 1);
    size_t *list = nodes ? NULL : malloc((mesh->num_nodes + 1) * sizeof *list);
    if (!nodes && (!member || !list)) {
        free(member), free(list);
        errno = ENOMEM;
        return -1;
    }
    int failed = 0;
    for (size_t g = 0; !failed && mesh->num_faces && g < mesh->num_groups; g++) {
        size_t count = nodes ? counts[g] : face_nodes(mesh, g, member, list);
        failed = fprintf(file, "*NSET, NSET=%s\n", mesh->group_names[g]) < 0 ||
                 write_numbers(file, nodes ? nodes[g] : list, count) || (mesh->face_cells && write_surface(file, mesh, g));
    }
    free(member), free(list);
    if (failed && !errno) errno = EIO;
    return failed ? -1 : 0;
}
