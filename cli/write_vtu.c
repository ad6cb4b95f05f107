#include "write_vtu.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "format_double.h"

enum { VTK_TETRA = 10, VTK_WEDGE = 13 };

int write_vtu(const char *path, const char *target, const volume_mesh *mesh, cli_error *error)
{
    FILE *file = fopen(path, "w");
    if (!file) {
        cli_error_set(error, "cannot write %s: %s", target, strerror(errno));
        return CLI_EXIT_INTERNAL;
    }
    size_t per = mesh->tetrahedra ? 4 : 6;
    /* Gmsh's wedge has its bottom counter-clockwise seen from the top; VTK
     * wants the bottom's normal pointing away from the top: b and c swap. */
    static const int tet_order[4] = {0, 1, 2, 3}, wedge_order[6] = {0, 2, 1, 3, 5, 4};
    const int *order = mesh->tetrahedra ? tet_order : wedge_order;
    fprintf(file, "<?xml version=\"1.0\"?>\n"
                  "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
                  "header_type=\"UInt64\">\n"
                  "  <UnstructuredGrid>\n"
                  "    <Piece NumberOfPoints=\"%zu\" NumberOfCells=\"%zu\">\n"
                  "      <Points>\n"
                  "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n",
            mesh->num_nodes, mesh->num_cells);
    char line[16 + 3 * FORMAT_DOUBLE_SIZE] = "         "; /* the indent, 9 + 1 blanks */
    for (size_t i = 0; i < mesh->num_nodes; i++) {
        char *end = line + 9;
        for (int c = 0; c < 3; c++) {
            *end++ = ' ';
            end = format_double(end, mesh->nodes[3 * i + (size_t)c]);
        }
        *end++ = '\n';
        fwrite(line, 1, (size_t)(end - line), file);
    }
    fputs("        </DataArray>\n      </Points>\n      <Cells>\n"
          "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n", file);
    for (size_t c = 0; c < mesh->num_cells; c++) {
        fputs("         ", file);
        for (size_t k = 0; k < per; k++) fprintf(file, " %d", (int)mesh->cells[per * c + (size_t)order[k]]);
        fputc('\n', file);
    }
    fputs("        </DataArray>\n"
          "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n", file);
    for (size_t c = 0; c < mesh->num_cells; c++) fprintf(file, "%s%zu", c % 16 ? " " : "\n          ", per * (c + 1));
    fputs("\n        </DataArray>\n"
          "        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n", file);
    for (size_t c = 0; c < mesh->num_cells; c++)
        fprintf(file, "%s%d", c % 32 ? " " : "\n          ", mesh->tetrahedra ? VTK_TETRA : VTK_WEDGE);
    fputs("\n        </DataArray>\n      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n", file);
    int failed = ferror(file);
    if (fclose(file) != 0) failed = 1;
    if (failed) {
        cli_error_set(error, "cannot write %s: %s", target, strerror(errno ? errno : EIO));
        return CLI_EXIT_INTERNAL;
    }
    return CLI_EXIT_OK;
}
