/* OFF, OBJ and PLY written here rather than by OpenMesh's IO (a dependency
 * of the adapter), for measured reasons (bench/mesh_writers_bench.cc,
 * bench/CLI_COST.md): OpenMesh 9.0's OFF/OBJ/PLY writers take every point
 * as float (BaseExporter::point), whatever the mesh's point type, the
 * precision argument or the binary option, so no file of theirs reads back
 * bit-identical; their ASCII writers take more than twice as long (a
 * 1098-triangle morph frame: 1.0 ms against 0.43 ms here; 100k triangles:
 * 52 ms against 25 ms); and linking OpenMesh would add libOpenMeshCore and
 * libstdc++ to every start of the tool (+1 ms, +100 page faults). */
#include "write_mesh.h"

#include "format_double.h"
#include "outdir.h"

#include <inttypes.h>
#include <stdlib.h>
#include <string.h>

static const char *const format_names[] = {"off", "obj", "ply"};

int mesh_format_from_name(const char *name, mesh_format *format)
{
    for (int i = 0; i < 3; i++) {
        if (strcmp(name, format_names[i]) == 0) {
            *format = (mesh_format)i;
            return 0;
        }
    }
    return -1;
}

const char *mesh_format_name(mesh_format format)
{
    return format_names[format];
}

static void write_header(FILE *file, mesh_format format, size_t vertices,
                         size_t triangles)
{
    switch (format) {
    case MESH_FORMAT_OFF:
        fprintf(file, "OFF\n%zu %zu 0\n", vertices, triangles);
        break;
    case MESH_FORMAT_OBJ:
        fprintf(file, "# compatmesh: %zu vertices, %zu triangles\n", vertices, triangles);
        break;
    case MESH_FORMAT_PLY:
        fprintf(file,
                "ply\nformat ascii 1.0\ncomment compatmesh\n"
                "element vertex %zu\n"
                "property double x\nproperty double y\nproperty double z\n"
                "element face %zu\n"
                "property list uchar int vertex_indices\nend_header\n",
                vertices, triangles);
        break;
    }
}

/* The vertices: x y 0 from xy, or x y z from xyz. */
static void write_vertices(FILE *file, mesh_format format, const double *xy, const double *xyz,
                           size_t count)
{
    const char *prefix = format == MESH_FORMAT_OBJ ? "v " : "";
    size_t prefix_length = strlen(prefix);
    char line[8 + 3 * FORMAT_DOUBLE_SIZE];
    memcpy(line, prefix, prefix_length);
    for (size_t i = 0; i < count; i++) {
        const double *p = xyz ? xyz + 3 * i : xy + 2 * i;
        char *end = format_double(line + prefix_length, p[0]);
        *end++ = ' ';
        end = format_double(end, p[1]);
        if (xyz) {
            *end++ = ' ';
            end = format_double(end, p[2]);
            *end++ = '\n';
        } else {
            memcpy(end, " 0\n", 3), end += 3;
        }
        fwrite(line, 1, (size_t)(end - line), file);
    }
}

static void write_triangles(FILE *file, mesh_format format,
                            const int32_t *triangles, size_t count)
{
    /* OBJ counts vertices from 1, OFF and PLY from 0. */
    const char *prefix = format == MESH_FORMAT_OBJ ? "f" : "3";
    int32_t base = format == MESH_FORMAT_OBJ ? 1 : 0;
    for (size_t t = 0; t < count; t++) {
        const int32_t *v = triangles + 3 * t;
        fprintf(file, "%s %" PRId32 " %" PRId32 " %" PRId32 "\n", prefix,
                v[0] + base, v[1] + base, v[2] + base);
    }
}

int write_triangle_mesh(const char *path, const double *xy, const double *xyz, size_t vertices,
                        const int32_t *triangles, size_t count, mesh_format format,
                        cli_error *error)
{
    FILE *file = output_open(path, error);
    if (!file) return CLI_EXIT_INTERNAL;
    write_header(file, format, vertices, count);
    write_vertices(file, format, xy, xyz, vertices);
    write_triangles(file, format, triangles, count);
    return output_close(file, path, error);
}

/* The next vertex of input vertex e along its loop. */
static size_t next_in_loop(const polygon_input *input, size_t e)
{
    size_t first = 0;
    for (size_t l = 0; l < input->loops; first += input->loop_sizes[l++])
        if (e < first + input->loop_sizes[l]) return e + 1 < first + input->loop_sizes[l] ? e + 1 : first;
    return e + 1 < input->count ? e + 1 : 0;
}

void mesh_in_space(const cm_result *result, size_t g, const polygon_input *input, double *xyz)
{
    const double *xy = cm_result_vertices(result, g);
    size_t nv = cm_result_num_vertices(result), n = cm_result_stats(result)->n;
    for (size_t v = 0; v < nv; v++) {
        double *p = xyz + 3 * v, t = 0;
        long e = v < n && input->spatial ? cm_result_boundary_source(result, g, v, &t) : -1;
        if (e >= 0) {
            const double *a = input->xyz + 3 * e, *b = input->xyz + 3 * next_in_loop(input, (size_t)e);
            for (int c = 0; c < 3; c++) p[c] = t == 0 ? a[c] : a[c] + t * (b[c] - a[c]);
        } else if (input->spatial) {
            section_to_space(&input->frame, xy[2 * v], xy[2 * v + 1], p);
        } else {
            p[0] = xy[2 * v], p[1] = xy[2 * v + 1], p[2] = input->z;
        }
    }
}

void section_in_space(const cm_result *result, const polygon_input *inputs, const double *frames, size_t k,
                      double t, const double *xy, double *xyz)
{
    size_t nv = cm_result_num_vertices(result);
    /* at an input's own time the section is that input's geometry, bit for bit (cm_morph_section) */
    for (size_t h = 0; h < k; h++)
        if (memcmp(xy, cm_result_vertices(result, h), 2 * nv * sizeof *xy) == 0) {
            mesh_in_space(result, h, &inputs[h], xyz);
            return;
        }
    cm_loft_section(frames, k, t, xy, nv, xyz);
    if (!inputs[0].spatial) /* planes z = constant: x and y the section's own, exactly */
        for (size_t v = 0; v < nv; v++) xyz[3 * v] = xy[2 * v], xyz[3 * v + 1] = xy[2 * v + 1];
}

int write_mesh(const char *path, const cm_result *result, size_t g, const polygon_input *input,
               mesh_format format, cli_error *error)
{
    size_t nv = cm_result_num_vertices(result);
    double *xyz = NULL;
    if (input && (input->has_z || input->spatial)) { /* else the plane z = 0 */
        if (!(xyz = malloc((3 * nv + 1) * sizeof *xyz))) {
            cli_error_set(error, "cannot write %s: out of memory", path);
            return CLI_EXIT_INTERNAL;
        }
        mesh_in_space(result, g, input, xyz);
    }
    int code = write_triangle_mesh(path, cm_result_vertices(result, g), xyz, nv, cm_result_triangles(result),
                                   cm_result_num_triangles(result), format, error);
    free(xyz);
    return code;
}
